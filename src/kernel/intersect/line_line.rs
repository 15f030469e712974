//! Line ∩ line: the ruler's intersection.

use crate::kernel::conditioning::Conditioning;
use crate::kernel::primitives::{cross, Line, Point};
use crate::kernel::tolerance::{Tolerance, PARALLEL_SIN_EPS};
use serde::Serialize;

/// The outcome of intersecting two lines.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum LineLine {
    /// One common point.
    Point {
        /// The intersection.
        point: Point,
        /// Its parameter on the first line.
        t_a: f64,
        /// Its parameter on the second line.
        t_b: f64,
        /// The meeting angle and error amplification.
        conditioning: Conditioning,
    },
    /// Parallel lines, `distance` mm apart: they meet at infinity.
    Parallel {
        /// Distance between the lines (mm).
        distance: f64,
    },
    /// The same line.
    Coincident,
}

/// Intersects two lines.
///
/// The directions are unit vectors, so `sin θ = a.dir × b.dir`; below
/// [`PARALLEL_SIN_EPS`] the lines are parallel, and coincident when their distance is within
/// the figure tolerance. The point is computed on the first line, `a.origin + t·a.dir`, so a
/// coordinate in which `a` does not move (a horizontal `a` keeps `y` exactly) stays exact.
///
/// ```
/// use graphostatik::kernel::{intersect_line_line, Line, LineLine, Point, Tolerance, Vector};
/// let tol = Tolerance::for_figure(100.0);
/// let a = Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 0.0)).unwrap();
/// let b = Line::new(Point::new(3.0, -5.0), Vector::new(0.0, 1.0)).unwrap();
/// match intersect_line_line(&a, &b, &tol) {
///     LineLine::Point { point, conditioning, .. } => {
///         assert_eq!(point, Point::new(3.0, 0.0));
///         assert_eq!(conditioning.amplification(), 1.0);
///     }
///     other => panic!("{other:?}"),
/// }
/// let c = Line::new(Point::new(0.0, 2.0), Vector::new(-4.0, 0.0)).unwrap();
/// assert_eq!(intersect_line_line(&a, &c, &tol), LineLine::Parallel { distance: 2.0 });
/// ```
pub fn intersect_line_line(a: &Line, b: &Line, tol: &Tolerance) -> LineLine {
    let s = cross(&a.dir, &b.dir);
    let w = b.origin - a.origin;
    if s.abs() <= PARALLEL_SIN_EPS {
        let distance = cross(&a.dir, &w).abs();
        return if distance <= tol.length {
            LineLine::Coincident
        } else {
            LineLine::Parallel { distance }
        };
    }
    let t_a = cross(&w, &b.dir) / s;
    let t_b = cross(&w, &a.dir) / s;
    let point = a.point_at(t_a);
    if !(point.x.is_finite() && point.y.is_finite() && t_b.is_finite()) {
        // They meet beyond the range of f64 (origins near 1e300, or a cut so glancing that
        // the point overflows): for every drawing that is at infinity, typed as such.
        let distance = cross(&a.dir, &w).abs();
        return LineLine::Parallel {
            distance: if distance.is_finite() {
                distance
            } else {
                f64::MAX
            },
        };
    }
    LineLine::Point {
        point,
        t_a,
        t_b,
        // atan2 of sine and cosine keeps its digits near 90°, where asin would not.
        conditioning: Conditioning::from_sin_cos(s, a.dir.dot(&b.dir)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Vector;

    #[test]
    fn lines_meeting_beyond_f64_are_parallel_not_nan() {
        // A hard case: origins near 1e300.
        let tol = Tolerance::for_figure(1.0);
        let a = Line::new(Point::new(1e300, 0.0), Vector::new(1.0, 1e-10)).unwrap();
        let b = Line::new(Point::new(-1e300, 1e300), Vector::new(1.0, -1e-10)).unwrap();
        match intersect_line_line(&a, &b, &tol) {
            LineLine::Parallel { distance } => assert!(distance.is_finite()),
            LineLine::Point { point, .. } => {
                assert!(point.x.is_finite() && point.y.is_finite(), "{point:?}")
            }
            LineLine::Coincident => {}
        }
    }

    fn tol() -> Tolerance {
        Tolerance::for_figure(100.0)
    }

    #[test]
    fn perpendicular_lines_meet_exactly() {
        let a = Line::new(Point::new(1.0, 1.0), Vector::new(1.0, 1.0)).unwrap();
        let b = Line::new(Point::new(0.0, 2.0), Vector::new(1.0, -1.0)).unwrap();
        match intersect_line_line(&a, &b, &tol()) {
            LineLine::Point {
                point,
                conditioning,
                ..
            } => {
                assert!((point - Point::new(1.0, 1.0)).norm() < 1e-15);
                assert!((conditioning.angle_deg() - 90.0).abs() < 1e-12);
                assert!(!conditioning.glancing());
            }
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn parallel_lines_are_a_typed_case_with_their_distance() {
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(2.0, 1.0)).unwrap();
        let b = Line::new(Point::new(0.0, 5.0), Vector::new(-4.0, -2.0)).unwrap();
        match intersect_line_line(&a, &b, &tol()) {
            LineLine::Parallel { distance } => {
                assert!((distance - 5.0 * 2.0 / 5f64.sqrt()).abs() < 1e-12)
            }
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn coincident_lines_are_a_typed_case() {
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(3.0, 4.0)).unwrap();
        let b = Line::new(Point::new(6.0, 8.0), Vector::new(3.0, 4.0)).unwrap();
        assert_eq!(intersect_line_line(&a, &b, &tol()), LineLine::Coincident);
    }

    #[test]
    fn glancing_cut_is_flagged_but_exact() {
        // Two lines meeting at 1° at (10, 0).
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 0.0)).unwrap();
        let d = 1f64.to_radians();
        let b = Line::new(Point::new(10.0, 0.0), Vector::new(d.cos(), d.sin())).unwrap();
        match intersect_line_line(&a, &b, &tol()) {
            LineLine::Point {
                point,
                conditioning,
                ..
            } => {
                assert!((point.x - 10.0).abs() < 1e-12 && point.y == 0.0);
                assert!(conditioning.glancing());
                assert!((conditioning.amplification() - 1.0 / d.sin()).abs() < 1e-9);
            }
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn nearly_parallel_but_not_parallel_still_meets_far_away() {
        let a = Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 0.0)).unwrap();
        let b = Line::new(Point::new(0.0, 1.0), Vector::new(1.0, -1e-9)).unwrap();
        match intersect_line_line(&a, &b, &tol()) {
            LineLine::Point {
                point,
                conditioning,
                ..
            } => {
                assert!((point.x - 1e9).abs() / 1e9 < 1e-6);
                assert!(conditioning.glancing() && conditioning.amplification() > 1e8);
            }
            o => panic!("{o:?}"),
        }
    }
}
