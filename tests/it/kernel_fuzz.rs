//! The kernel's entry points under any finite input, from 1e-300 to 1e300 and back: no panic,
//! and every outcome either typed or made of finite numbers. A point is
//! finite, a distance or gap is finite and not negative, a conditioning is a number.

use graphostatik::kernel::{
    intersect_circle_circle, intersect_line_circle, intersect_line_line, Circle, CircleCircle,
    Line, LineCircle, LineLine, Point, Tolerance, Vector,
};
use proptest::prelude::*;

/// A coordinate or length of any magnitude f64 holds comfortably, either sign.
fn magnitude() -> impl Strategy<Value = f64> {
    (-300i32..300, 1.0f64..10.0, any::<bool>()).prop_map(|(e, m, neg)| {
        let v = m * 10f64.powi(e);
        if neg {
            -v
        } else {
            v
        }
    })
}

fn point() -> impl Strategy<Value = Point> {
    (magnitude(), magnitude()).prop_map(|(x, y)| Point::new(x, y))
}

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn lines_meet_in_a_finite_point_or_a_typed_case(
        a in point(), b in point(), da in point(), db in point(), size in magnitude(),
    ) {
        let tol = Tolerance::for_figure(size.abs());
        let (Ok(la), Ok(lb)) = (
            Line::new(a, Vector::new(da.x, da.y)),
            Line::new(b, Vector::new(db.x, db.y)),
        ) else {
            return Ok(());
        };
        prop_assert!((la.dir.norm() - 1.0).abs() < 1e-12);
        match intersect_line_line(&la, &lb, &tol) {
            LineLine::Point { point, t_a, t_b, conditioning } => {
                prop_assert!(finite(&point) && t_a.is_finite() && t_b.is_finite());
                prop_assert!(!conditioning.angle_deg().is_nan());
            }
            LineLine::Parallel { distance } => prop_assert!(distance.is_finite() && distance >= 0.0),
            LineLine::Coincident => {}
        }
    }

    #[test]
    fn a_line_and_a_circle_meet_finitely_or_say_why_not(
        a in point(), d in point(), c in point(), r in magnitude(), size in magnitude(),
    ) {
        let tol = Tolerance::for_figure(size.abs());
        let (Ok(l), Ok(k)) = (Line::new(a, Vector::new(d.x, d.y)), Circle::new(c, r.abs())) else {
            return Ok(());
        };
        match intersect_line_circle(&l, &k, &tol) {
            LineCircle::Two { points, conditioning } => {
                prop_assert!(points.iter().all(finite));
                prop_assert!(!conditioning.angle_deg().is_nan());
            }
            LineCircle::Tangent { point } => prop_assert!(finite(&point)),
            LineCircle::Disjoint { gap } => prop_assert!(!gap.is_nan() && gap >= 0.0),
        }
    }

    #[test]
    fn two_circles_meet_finitely_or_say_why_not(
        c1 in point(), c2 in point(), r1 in magnitude(), r2 in magnitude(), size in magnitude(),
    ) {
        let tol = Tolerance::for_figure(size.abs());
        let (Ok(a), Ok(b)) = (Circle::new(c1, r1.abs()), Circle::new(c2, r2.abs())) else {
            return Ok(());
        };
        match intersect_circle_circle(&a, &b, &tol) {
            CircleCircle::Two { points, conditioning } => {
                prop_assert!(points.iter().all(finite));
                prop_assert!(!conditioning.angle_deg().is_nan());
            }
            CircleCircle::TangentExternal { point } | CircleCircle::TangentInternal { point } => {
                prop_assert!(finite(&point))
            }
            CircleCircle::Separate { gap } | CircleCircle::Contained { gap } => {
                prop_assert!(!gap.is_nan())
            }
            _ => {}
        }
    }
}
