//! Line ∩ circle: the ruler's line cut by a compass arc.

use crate::kernel::conditioning::Conditioning;
use crate::kernel::primitives::{Circle, Line, Point};
use crate::kernel::tolerance::Tolerance;
use serde::Serialize;

/// The outcome of intersecting a line and a circle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum LineCircle {
    /// Two points, ordered along the line's direction.
    Two {
        /// `[first, second]` along the line direction.
        points: [Point; 2],
        /// Meeting angle (the same at both points) and error amplification.
        conditioning: Conditioning,
    },
    /// The line touches the circle (within the figure tolerance): one double point.
    Tangent {
        /// The point of contact (foot of the perpendicular from the centre).
        point: Point,
    },
    /// The line passes the circle by `gap` mm.
    Disjoint {
        /// Distance from the circle to the line (mm, > 0).
        gap: f64,
    },
}

/// Intersects a line with a circle.
///
/// With `h` the distance of the centre from the line and `f` the foot of the perpendicular,
/// the points are `f ± s·dir` with the half chord `s = √((r − h)(r + h))` (the factored form
/// keeps its digits when `h ≈ r`). The curves meet at the angle `atan2(s, h)` between the line
/// and the circle's tangent: 90° through the centre, 0° at tangency.
///
/// ```
/// use graphostatik::kernel::{intersect_line_circle, Circle, Line, LineCircle, Point, Tolerance, Vector};
/// let tol = Tolerance::for_figure(10.0);
/// let axis = Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 0.0)).unwrap();
/// let c = Circle::new(Point::new(0.0, 3.0), 5.0).unwrap();
/// match intersect_line_circle(&axis, &c, &tol) {
///     LineCircle::Two { points, .. } => {
///         assert_eq!(points[0], Point::new(-4.0, 0.0));
///         assert_eq!(points[1], Point::new(4.0, 0.0));
///     }
///     o => panic!("{o:?}"),
/// }
/// ```
pub fn intersect_line_circle(line: &Line, circle: &Circle, tol: &Tolerance) -> LineCircle {
    let t_foot = line.param_of(&circle.center);
    let foot = line.point_at(t_foot);
    let h = line.signed_distance(&circle.center).abs();
    let r = circle.radius;
    if (h - r).abs() <= tol.length {
        return LineCircle::Tangent { point: foot };
    }
    if h > r {
        return LineCircle::Disjoint { gap: h - r };
    }
    // (r − h)(r + h) overflows for r near 1e154 and loses digits below 1e-154 (subnormal):
    // there the square roots are taken apart.
    let p = (r - h) * (r + h);
    let s = if p.is_normal() || p == 0.0 {
        p.sqrt()
    } else {
        (r - h).sqrt() * (r + h).sqrt()
    };
    LineCircle::Two {
        points: [line.point_at(t_foot - s), line.point_at(t_foot + s)],
        conditioning: Conditioning::from_sin_cos(s, h),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Vector;

    fn tol() -> Tolerance {
        Tolerance::for_figure(10.0)
    }
    fn x_axis() -> Line {
        Line::new(Point::new(0.0, 0.0), Vector::new(1.0, 0.0)).unwrap()
    }

    #[test]
    fn secant_through_centre_meets_at_right_angles() {
        let c = Circle::new(Point::new(2.0, 0.0), 1.0).unwrap();
        match intersect_line_circle(&x_axis(), &c, &tol()) {
            LineCircle::Two {
                points,
                conditioning,
            } => {
                assert_eq!(points, [Point::new(1.0, 0.0), Point::new(3.0, 0.0)]);
                assert_eq!(conditioning.amplification(), 1.0);
            }
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn tangent_is_a_typed_case() {
        let c = Circle::new(Point::new(2.0, 1.0), 1.0).unwrap();
        assert_eq!(
            intersect_line_circle(&x_axis(), &c, &tol()),
            LineCircle::Tangent {
                point: Point::new(2.0, 0.0)
            }
        );
    }

    #[test]
    fn disjoint_reports_the_gap() {
        let c = Circle::new(Point::new(2.0, 3.0), 1.0).unwrap();
        assert_eq!(
            intersect_line_circle(&x_axis(), &c, &tol()),
            LineCircle::Disjoint { gap: 2.0 }
        );
    }

    #[test]
    fn nearly_tangent_is_glancing_and_accurate() {
        let c = Circle::new(Point::new(0.0, 1.0 - 1e-6), 1.0).unwrap();
        match intersect_line_circle(&x_axis(), &c, &tol()) {
            LineCircle::Two {
                points,
                conditioning,
            } => {
                for p in points {
                    assert_eq!(p.y, 0.0);
                    assert!(((p - c.center).norm() - 1.0).abs() < 1e-15);
                }
                assert!((points[1].x - 2e-6f64.sqrt()).abs() < 1e-9);
                assert!(conditioning.glancing());
            }
            o => panic!("{o:?}"),
        }
    }
}
