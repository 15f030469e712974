//! Every kernel entry point on any numbers up to 1e300 (subnormals, zeros, NaN included): a
//! finite point or a typed case, never a NaN, an infinity or a panic.
#![no_main]

use graphostatik::kernel::construct::{divide_segment, foot_on_line, lay_off, point_at_ratio};
use graphostatik::kernel::{
    intersect_circle_circle, intersect_line_circle, intersect_line_line, Circle, CircleCircle,
    Line, LineCircle, LineLine, Point, Segment, Tolerance, Vector,
};
use libfuzzer_sys::fuzz_target;

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

fuzz_target!(|v: [f64; 12]| {
    // The kernel's promise covers magnitudes up to 1e300 (a sheet is at most 10 m); beyond,
    // a dot product of two coordinates may overflow, and no scene gets there.
    if v.iter().any(|x| x.abs() > 1e300) {
        return;
    }
    let p = |i: usize| Point::new(v[i], v[i + 1]);
    let tol = Tolerance::for_figure(v[11].abs());
    let (Ok(a), Ok(b)) = (
        Line::new(p(0), Vector::new(v[2], v[3])),
        Line::new(p(4), Vector::new(v[6], v[7])),
    ) else {
        return;
    };
    assert!(a.dir.x.is_finite() && (a.dir.norm() - 1.0).abs() < 1e-12);
    if let LineLine::Point {
        point,
        conditioning,
        ..
    } = intersect_line_line(&a, &b, &tol)
    {
        assert!(finite(&point) && conditioning.angle().is_finite());
    }
    if let Ok(c) = Circle::new(p(4), v[8]) {
        match intersect_line_circle(&a, &c, &tol) {
            LineCircle::Two { points, .. } => assert!(points.iter().all(finite)),
            LineCircle::Tangent { point } => assert!(finite(&point)),
            LineCircle::Disjoint { gap } => assert!(gap.is_finite()),
        }
        if let Ok(d) = Circle::new(p(0), v[9]) {
            match intersect_circle_circle(&c, &d, &tol) {
                CircleCircle::Two { points, .. } => assert!(points.iter().all(finite)),
                CircleCircle::TangentExternal { point }
                | CircleCircle::TangentInternal { point } => {
                    assert!(finite(&point))
                }
                _ => {}
            }
        }
    }
    if finite(&p(0)) && finite(&p(4)) {
        let f = foot_on_line(&b, &p(0));
        assert!(finite(&f) || !finite(&b.origin));
        let s = Segment { a: p(0), b: p(4) };
        let t = v[10];
        if t.is_finite() && t.abs() <= 1.0 {
            assert!(
                finite(&point_at_ratio(&s, t))
                    || !(s.a - s.b).x.is_finite()
                    || !(s.a - s.b).y.is_finite()
            );
        }
        let _ = divide_segment(&s, (v[10].abs() as usize) % 64);
    }
    if let Ok(q) = lay_off(p(0), Vector::new(v[2], v[3]), v[10]) {
        assert!(finite(&q), "lay_off gave {q:?}");
    }
});
