//! Circle ∩ circle: two compass arcs.

use crate::kernel::conditioning::Conditioning;
use crate::kernel::primitives::{Circle, Point, Vector};
use crate::kernel::tolerance::Tolerance;
use serde::Serialize;

/// The outcome of intersecting two circles.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum CircleCircle {
    /// Two points: `[right, left]` of the direction from the first centre to the second.
    Two {
        /// `[right, left]` of the centre line.
        points: [Point; 2],
        /// Meeting angle (same at both points) and error amplification.
        conditioning: Conditioning,
    },
    /// The circles touch from outside (distance of centres = r₁ + r₂).
    TangentExternal {
        /// The point of contact.
        point: Point,
    },
    /// One circle touches the other from inside (distance of centres = |r₁ − r₂|).
    TangentInternal {
        /// The point of contact.
        point: Point,
    },
    /// The circles lie apart, `gap` mm between them.
    Separate {
        /// Gap between the circles (mm).
        gap: f64,
    },
    /// One circle lies inside the other without touching, `gap` mm between them.
    Contained {
        /// Gap between the circles (mm).
        gap: f64,
    },
    /// Same centre, different radii.
    Concentric,
    /// The same circle.
    Coincident,
}

/// Intersects two circles.
///
/// With `d` the distance of the centres, the common chord lies at `a = (d² + r₁² − r₂²)/(2d)`
/// from the first centre, half chord `h = √((r₁ − a)(r₁ + a))`. The circles meet at the angle
/// between their radii to the common point, `sin θ = d·h/(r₁·r₂)`.
///
/// ```
/// use graphostatik::kernel::{intersect_circle_circle, Circle, CircleCircle, Point, Tolerance};
/// let tol = Tolerance::for_figure(10.0);
/// let a = Circle::new(Point::new(0.0, 0.0), 5.0).unwrap();
/// let b = Circle::new(Point::new(8.0, 0.0), 5.0).unwrap();
/// match intersect_circle_circle(&a, &b, &tol) {
///     CircleCircle::Two { points, .. } => {
///         assert_eq!(points, [Point::new(4.0, -3.0), Point::new(4.0, 3.0)]);
///     }
///     o => panic!("{o:?}"),
/// }
/// ```
pub fn intersect_circle_circle(c1: &Circle, c2: &Circle, tol: &Tolerance) -> CircleCircle {
    let w = c2.center - c1.center;
    let big = w.x.abs().max(w.y.abs()).max(c1.radius).max(c2.radius);
    if big > 0.0 && big.is_finite() && !(1e-150..1e150).contains(&big) {
        return scaled(c1, c2, tol, big);
    }
    in_range(c1, c2, tol)
}

/// Circles whose radii or distance lie beyond 1e±150, where r² would overflow or lose its
/// digits (cargo fuzz: radii of 4e204): cut at a power-of-two scale, which is exact, with
/// the first centre at the origin, and the results scaled back.
fn scaled(c1: &Circle, c2: &Circle, tol: &Tolerance, big: f64) -> CircleCircle {
    let e = (-big.log2().floor()).clamp(-1000.0, 1000.0) as i32;
    let (k, back) = (2f64.powi(e), 2f64.powi(-e));
    let w = c2.center - c1.center;
    let a = Circle {
        center: Point::origin(),
        radius: c1.radius * k,
    };
    let b = Circle {
        center: Point::from(w * k),
        radius: c2.radius * k,
    };
    let t = Tolerance {
        length: tol.length * k,
    };
    let at = |p: Point| c1.center + p.coords * back;
    match in_range(&a, &b, &t) {
        CircleCircle::Two {
            points,
            conditioning,
        } => CircleCircle::Two {
            points: points.map(at),
            conditioning,
        },
        CircleCircle::TangentExternal { point } => {
            CircleCircle::TangentExternal { point: at(point) }
        }
        CircleCircle::TangentInternal { point } => {
            CircleCircle::TangentInternal { point: at(point) }
        }
        CircleCircle::Separate { gap } => CircleCircle::Separate { gap: gap * back },
        CircleCircle::Contained { gap } => CircleCircle::Contained { gap: gap * back },
        other => other,
    }
}

fn in_range(c1: &Circle, c2: &Circle, tol: &Tolerance) -> CircleCircle {
    let w = c2.center - c1.center;
    let d = w.norm();
    let (r1, r2) = (c1.radius, c2.radius);
    if d <= tol.length {
        return if (r1 - r2).abs() <= tol.length {
            CircleCircle::Coincident
        } else {
            CircleCircle::Concentric
        };
    }
    let e = w / d;
    if (d - (r1 + r2)).abs() <= tol.length {
        return CircleCircle::TangentExternal {
            point: c1.center + e * r1,
        };
    }
    if (d - (r1 - r2).abs()).abs() <= tol.length {
        // Contact on the side of the smaller circle, away from the larger one's centre.
        let point = if r1 >= r2 {
            c1.center + e * r1
        } else {
            c1.center - e * r1
        };
        return CircleCircle::TangentInternal { point };
    }
    if d > r1 + r2 {
        return CircleCircle::Separate { gap: d - r1 - r2 };
    }
    if d < (r1 - r2).abs() {
        return CircleCircle::Contained {
            gap: (r1 - r2).abs() - d,
        };
    }
    // The foot of the common chord, measured from the smaller circle's centre towards the
    // other: a_s = (d² − r_L² + r_s²) / 2d, with d² − r_L² = (d − r_L)(d + r_L), exact where
    // d is near r_L. Measured from the larger circle instead, (r_L − a)(r_L + a) would cancel
    // log10(r_L/r_s) digits (r = 1000 and 1e-4 meeting at 90° lost four).
    let (small_first, rs, rl) = if r1 <= r2 {
        (true, r1, r2)
    } else {
        (false, r2, r1)
    };
    let a_s = ((d - rl) * (d + rl) + rs * rs) / (2.0 * d);
    let h = ((rs - a_s) * (rs + a_s)).max(0.0).sqrt();
    let (m, a) = if small_first {
        (c1.center + e * a_s, a_s)
    } else {
        (c2.center - e * a_s, d - a_s)
    };
    if h == 0.0 {
        // The chord has shrunk to a point: the circles touch (outside the tolerance's band).
        return if d < rl {
            CircleCircle::TangentInternal { point: m }
        } else {
            CircleCircle::TangentExternal { point: m }
        };
    }
    let n = Vector::new(-e.y, e.x);
    // The radii to the common point are (a, h) and (a − d, h) in the frame of the centre
    // line: their cross product is d·h, their dot product a(a − d) + h². The angle between
    // them may be obtuse; the curves' meeting angle is its acute fold.
    CircleCircle::Two {
        points: [m - n * h, m + n * h],
        conditioning: Conditioning::from_sin_cos(d * h, a * (a - d) + h * h),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_large_and_a_small_circle_meeting_at_right_angles_keep_their_digits_either_way() {
        use super::*;
        // A hard case: r = 1000 and 1e-4, centres √(r1² + r2²) apart: they meet at 90°,
        // at y = ±r1·r2/d from the centre line, whichever circle comes first.
        let (r1, r2) = (1000.0f64, 1e-4f64);
        let d = r1.hypot(r2);
        let y = r1 * r2 / d;
        let tol = Tolerance::for_figure(1000.0);
        let big = Circle::new(Point::new(0.0, 0.0), r1).unwrap();
        let small = Circle::new(Point::new(d, 0.0), r2).unwrap();
        for (a, b) in [(&big, &small), (&small, &big)] {
            match intersect_circle_circle(a, b, &tol) {
                CircleCircle::Two {
                    points,
                    conditioning,
                } => {
                    for p in points {
                        assert!((p.y.abs() - y).abs() <= 1e-12 * y, "{p:?} against ±{y}");
                    }
                    assert!((conditioning.angle_deg() - 90.0).abs() < 1e-6);
                }
                o => panic!("{o:?}"),
            }
        }
    }

    use super::*;

    fn tol() -> Tolerance {
        Tolerance::for_figure(10.0)
    }
    fn c(x: f64, y: f64, r: f64) -> Circle {
        Circle::new(Point::new(x, y), r).unwrap()
    }

    #[test]
    fn orthogonal_circles_meet_at_right_angles() {
        match intersect_circle_circle(&c(0.0, 0.0, 3.0), &c(5.0, 0.0, 4.0), &tol()) {
            CircleCircle::Two {
                points,
                conditioning,
            } => {
                assert!((points[1] - Point::new(1.8, 2.4)).norm() < 1e-15);
                assert!((conditioning.angle_deg() - 90.0).abs() < 1e-9);
            }
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn every_degenerate_case_is_typed() {
        let t = tol();
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 1.0), &c(2.0, 0.0, 1.0), &t),
            CircleCircle::TangentExternal {
                point: Point::new(1.0, 0.0)
            }
        );
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 2.0), &c(1.0, 0.0, 1.0), &t),
            CircleCircle::TangentInternal {
                point: Point::new(2.0, 0.0)
            }
        );
        assert_eq!(
            intersect_circle_circle(&c(1.0, 0.0, 1.0), &c(0.0, 0.0, 2.0), &t),
            CircleCircle::TangentInternal {
                point: Point::new(2.0, 0.0)
            }
        );
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 1.0), &c(5.0, 0.0, 1.0), &t),
            CircleCircle::Separate { gap: 3.0 }
        );
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 5.0), &c(1.0, 0.0, 1.0), &t),
            CircleCircle::Contained { gap: 3.0 }
        );
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 5.0), &c(0.0, 0.0, 1.0), &t),
            CircleCircle::Concentric
        );
        assert_eq!(
            intersect_circle_circle(&c(0.0, 0.0, 5.0), &c(0.0, 0.0, 5.0), &t),
            CircleCircle::Coincident
        );
    }

    #[test]
    fn nearly_tangent_circles_are_glancing() {
        match intersect_circle_circle(&c(0.0, 0.0, 1.0), &c(2.0 - 1e-8, 0.0, 1.0), &tol()) {
            CircleCircle::Two { conditioning, .. } => assert!(conditioning.glancing()),
            o => panic!("{o:?}"),
        }
    }
}

#[cfg(test)]
mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Random crossings: two distinct points with a finite amplification, or a typed case.
        #[test]
        fn crossings_are_two_distinct_points_or_a_named_case(
            r1 in 1e-4f64..1e3, r2 in 1e-4f64..1e3, t in 0.0f64..1.0, phi in 0.0f64..6.3,
        ) {
            let d = (r1 - r2).abs() + t * (r1 + r2 - (r1 - r2).abs());
            let tol = Tolerance::for_figure(r1.max(r2) * 2.0);
            let a = Circle::new(Point::new(0.0, 0.0), r1).unwrap();
            let b = Circle::new(Point::new(d * phi.cos(), d * phi.sin()), r2).unwrap();
            if let CircleCircle::Two { points, conditioning } = intersect_circle_circle(&a, &b, &tol) {
                prop_assert!(points[0] != points[1]);
                prop_assert!(conditioning.amplification().is_finite());
                for p in points {
                    prop_assert!(p.x.is_finite() && p.y.is_finite());
                }
            }
        }
    }
}
