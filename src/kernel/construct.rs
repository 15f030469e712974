//! The remaining operations of ruler, set square and compass: parallels, perpendiculars,
//! laying off a length, dividing a segment or an arc into equal parts, measuring.

use super::primitives::{Arc, Circle, Line, Point, PrimitiveError, Segment, Vector};
use parry2d_f64::query::PointQueryWithLocation;
use parry2d_f64::shape::Segment as ParrySegment;
use serde::Serialize;

/// The parallel to `line` through `p` (two set squares sliding on each other).
///
/// ```
/// use graphostatik::kernel::{construct::parallel_through, Line, Point, Vector};
/// let g = Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 1.0)).unwrap();
/// let h = parallel_through(&g, Point::new(0.0, 2.0));
/// assert_eq!(h.dir, g.dir);
/// assert!((h.signed_distance(&Point::new(0.0, 0.0)) + 2f64.sqrt()).abs() < 1e-15);
/// ```
pub fn parallel_through(line: &Line, p: Point) -> Line {
    Line {
        origin: p,
        dir: line.dir,
    }
}

/// The perpendicular to `line` through `p`, directed along the line's left normal.
pub fn perpendicular_through(line: &Line, p: Point) -> Line {
    Line {
        origin: p,
        dir: line.normal(),
    }
}

/// The foot of the perpendicular from `p` on the (infinite) line.
pub fn foot_on_line(line: &Line, p: &Point) -> Point {
    line.point_at(line.param_of(p))
}

/// Where the foot of a perpendicular falls on a segment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum FootOnSegment {
    /// Inside the segment.
    Inside(Point),
    /// Beyond an end: the nearest point of the segment is that end point (0 = `a`, 1 = `b`).
    AtEnd(Point, u8),
}

/// The foot of the perpendicular from `p` on a segment, or the end it falls beyond.
///
/// Uses parry's segment projection, which reports the location on the segment.
///
/// ```
/// use graphostatik::kernel::{construct::{foot_on_segment, FootOnSegment}, Point, Segment};
/// let s = Segment { a: Point::new(0.0, 0.0), b: Point::new(100.0, 0.0) };
/// assert_eq!(foot_on_segment(&s, &Point::new(30.0, 40.0)), FootOnSegment::Inside(Point::new(30.0, 0.0)));
/// assert_eq!(foot_on_segment(&s, &Point::new(130.0, 40.0)), FootOnSegment::AtEnd(Point::new(100.0, 0.0), 1));
/// ```
pub fn foot_on_segment(seg: &Segment, p: &Point) -> FootOnSegment {
    let ps = ParrySegment::new(seg.a, seg.b);
    let (proj, loc) = ps.project_local_point_and_get_location(p, false);
    match loc {
        parry2d_f64::shape::SegmentPointLocation::OnVertex(i) => {
            FootOnSegment::AtEnd(proj.point, i as u8)
        }
        parry2d_f64::shape::SegmentPointLocation::OnEdge(_) => FootOnSegment::Inside(proj.point),
    }
}

/// Lays off `length` mm from `origin` in the direction `dir` (need not be unit).
/// A negative length lays off backwards.
pub fn lay_off(origin: Point, dir: Vector, length: f64) -> Result<Point, PrimitiveError> {
    let n = dir.norm();
    if n == 0.0 {
        return Err(PrimitiveError::ZeroDirection);
    }
    if !length.is_finite() {
        return Err(PrimitiveError::NotFinite);
    }
    let p = origin + dir * (length / n);
    // A length beyond f64 along a tiny direction (cargo fuzz: 9.4e305 along 1.2e-130).
    if !(p.x.is_finite() && p.y.is_finite()) {
        return Err(PrimitiveError::NotFinite);
    }
    Ok(p)
}

/// Divides a segment into `n ≥ 1` equal parts: the `n + 1` division points, ends included
/// and exact (`a·(1 − k/n) + b·k/n`).
///
/// ```
/// use graphostatik::kernel::{construct::divide_segment, Point, Segment};
/// let s = Segment { a: Point::new(0.0, 0.0), b: Point::new(3.0, 0.0) };
/// let pts = divide_segment(&s, 3);
/// assert_eq!(pts.len(), 4);
/// assert_eq!(pts[3], Point::new(3.0, 0.0));
/// ```
pub fn divide_segment(seg: &Segment, n: usize) -> Vec<Point> {
    let n = n.max(1);
    (0..=n)
        .map(|k| {
            let t = k as f64 / n as f64;
            Point::new(
                seg.a.x * (1.0 - t) + seg.b.x * t,
                seg.a.y * (1.0 - t) + seg.b.y * t,
            )
        })
        .collect()
}

/// The point dividing a segment in the ratio `t : (1 − t)` from `a` (t = 0 gives `a`, 1 gives
/// `b`): the drafter's division of a line by a ratio (parallels through a divided ray).
///
/// ```
/// use graphostatik::kernel::{construct::point_at_ratio, Point, Segment};
/// let s = Segment { a: Point::new(0.0, 0.0), b: Point::new(4.0, 2.0) };
/// assert_eq!(point_at_ratio(&s, 0.25), Point::new(1.0, 0.5));
/// ```
pub fn point_at_ratio(seg: &Segment, t: f64) -> Point {
    // a + t (b − a) would not return b exactly at t = 1; the weighted form does at both ends.
    Point::new(
        seg.a.x * (1.0 - t) + seg.b.x * t,
        seg.a.y * (1.0 - t) + seg.b.y * t,
    )
}

/// Divides an arc into `n ≥ 1` equal parts: the `n + 1` division points, ends included.
pub fn divide_arc(arc: &Arc, n: usize) -> Vec<Point> {
    let n = n.max(1);
    (0..=n)
        .map(|k| arc.point_at_fraction(k as f64 / n as f64))
        .collect()
}

/// Divides a whole circle into `n ≥ 1` equal parts starting at `start_deg`, counter-clockwise
/// (`clockwise = false`) or clockwise: `n` points, exact wherever a division falls on a
/// quadrant angle.
pub fn divide_circle(circle: &Circle, start_deg: f64, n: usize, clockwise: bool) -> Vec<Point> {
    let n = n.max(1);
    let sign = if clockwise { -1.0 } else { 1.0 };
    (0..n)
        .map(|k| circle.point_at_deg(start_deg + sign * 360.0 * k as f64 / n as f64))
        .collect()
}

/// The parameters (0 at `a`, 1 at `b`) between which the segment a–b lies in the rectangle
/// `[x0, y0, x1, y1]` (Liang–Barsky); `None` where it misses it.
///
/// ```
/// use graphostatik::kernel::{construct::clip_to_rect, Point};
/// let t = clip_to_rect(Point::new(-1.0, 0.5), Point::new(3.0, 0.5), [0.0, 0.0, 1.0, 1.0]);
/// assert_eq!(t, Some((0.25, 0.5)));
/// assert_eq!(clip_to_rect(Point::new(-1.0, 2.0), Point::new(3.0, 2.0), [0.0, 0.0, 1.0, 1.0]), None);
/// ```
pub fn clip_to_rect(a: Point, b: Point, rect: [f64; 4]) -> Option<(f64, f64)> {
    let [x0, y0, x1, y1] = rect;
    let d = b - a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d.x, a.x - x0),
        (d.x, x1 - a.x),
        (-d.y, a.y - y0),
        (d.y, y1 - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

/// The signed ordinate of `p` measured along `axis` from the axis origin (mm on the sheet):
/// the drafter's "cut off on the vertical centre line".
pub fn ordinate(axis: &Line, p: &Point) -> f64 {
    axis.param_of(p)
}

/// The most hatch lines [`hatch`] draws in one area: past it the lines are set wider apart,
/// so that a hatching costs at most this many segments whatever the area's size.
pub const MAX_HATCH_LINES: usize = 2000;

/// The hatching of the area inside `outline` (a closed polygon, its last vertex joined to its
/// first): segments parallel to `dir`, `spacing` apart (or wider, at most
/// [`MAX_HATCH_LINES`]), each from where it enters the area to where it leaves it (the
/// even-odd rule, so a polygon that winds back on itself is hatched where it is crossed an
/// odd number of times). The draftsman's Schraffur of an area a figure names (LH J's excess
/// areas of the turning force over its mean). Empty for fewer than three vertices, a spacing
/// that is not positive, a direction of no length or coordinates that are not finite.
///
/// ```
/// use graphostatik::kernel::{construct::hatch, Point, Vector};
/// let square = [Point::new(0.0, 0.0), Point::new(4.0, 0.0), Point::new(4.0, 4.0), Point::new(0.0, 4.0)];
/// let lines = hatch(&square, Vector::new(0.0, 1.0), 1.0);
/// // x = 1, 2, 3 inside (x = 0 and x = 4 only touch the outline's sides), whole.
/// assert_eq!(lines.len(), 3);
/// assert!(lines.iter().all(|s| (s.b.y - s.a.y - 4.0).abs() < 1e-12));
/// ```
pub fn hatch(outline: &[Point], dir: Vector, spacing: f64) -> Vec<Segment> {
    let len = dir.norm();
    let finite = outline.iter().all(|p| p.x.is_finite() && p.y.is_finite());
    let positive = |v: f64| v > 0.0 && v.is_finite();
    if outline.len() < 3 || !finite || !positive(spacing) || !positive(len) {
        return Vec::new();
    }
    let d = dir / len;
    let n = Vector::new(-d.y, d.x);
    // Measured from the first vertex, so that the lines' count follows the area's size and
    // not how far from the origin it lies.
    let o = outline[0];
    let across = |p: &Point| n.dot(&(p - o));
    let (lo, hi) = (outline.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(across(p)), hi.max(across(p)))
    });
    let spacing = spacing.max((hi - lo) / MAX_HATCH_LINES as f64);
    let (first, last) = (
        (lo / spacing).floor() as i64 + 1,
        (hi / spacing).ceil() as i64 - 1,
    );
    let mut out = Vec::new();
    let mut cuts: Vec<Point> = Vec::new();
    for k in first..=last {
        let s = k as f64 * spacing;
        cuts.clear();
        for (i, a) in outline.iter().enumerate() {
            let b = &outline[(i + 1) % outline.len()];
            let (fa, fb) = (across(a) - s, across(b) - s);
            if (fa > 0.0) != (fb > 0.0) {
                cuts.push(a + (b - a) * (fa / (fa - fb)));
            }
        }
        cuts.sort_by(|p, q| d.dot(&p.coords).total_cmp(&d.dot(&q.coords)));
        out.extend(cuts.chunks_exact(2).map(|w| Segment { a: w[0], b: w[1] }));
    }
    out
}

#[cfg(test)]
mod hatch_tests {
    use super::*;

    #[test]
    fn a_triangle_is_hatched_inside_and_whole() {
        let t = [
            Point::new(0.0, 0.0),
            Point::new(10.0, 0.0),
            Point::new(0.0, 10.0),
        ];
        let lines = hatch(&t, Vector::new(1.0, 1.0), 1.0);
        assert!(!lines.is_empty());
        for s in &lines {
            for p in [s.a, s.b] {
                assert!(
                    p.x >= -1e-9 && p.y >= -1e-9 && p.x + p.y <= 10.0 + 1e-9,
                    "{p:?}"
                );
            }
            let d = s.b - s.a;
            assert!((d.x - d.y).abs() < 1e-9, "parallel to (1, 1): {d:?}");
        }
    }

    #[test]
    fn far_from_the_origin_or_huge_or_degenerate_stays_bounded() {
        let far = [
            Point::new(1e300, 0.0),
            Point::new(1e300 + 1e290, 0.0),
            Point::new(1e300, 1e290),
        ];
        assert!(hatch(&far, Vector::new(0.0, 1.0), 1.0).len() <= MAX_HATCH_LINES);
        let huge = [
            Point::new(0.0, 0.0),
            Point::new(1e12, 0.0),
            Point::new(0.0, 1e12),
        ];
        assert!(hatch(&huge, Vector::new(1.0, 1.0), 0.5).len() <= MAX_HATCH_LINES);
        let flat = [
            Point::new(0.0, 0.0),
            Point::new(5.0, 0.0),
            Point::new(10.0, 0.0),
        ];
        assert!(hatch(&flat, Vector::new(1.0, 0.0), 1.0).is_empty());
        let nan = [
            Point::new(f64::NAN, 0.0),
            Point::new(1.0, 0.0),
            Point::new(0.0, 1.0),
        ];
        assert!(hatch(&nan, Vector::new(1.0, 1.0), 1.0).is_empty());
        assert!(hatch(&flat[..2], Vector::new(1.0, 1.0), 1.0).is_empty());
        assert!(hatch(&far, Vector::zeros(), 1.0).is_empty());
    }
}
