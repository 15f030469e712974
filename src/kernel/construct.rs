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
