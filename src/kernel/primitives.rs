//! The primitives of ruler and compass: points, lines, rays, segments, circles and arcs.
//!
//! All coordinates are millimetres on the drawing sheet, y pointing up (the renderer flips).

use nalgebra::{Point2, Vector2};
use serde::Serialize;

/// A point on the sheet (mm).
pub type Point = Point2<f64>;
/// A displacement on the sheet (mm).
pub type Vector = Vector2<f64>;

/// The 2-D cross product `a × b = a.x·b.y − a.y·b.x` (the sine of the angle between unit vectors).
#[inline]
pub fn cross(a: &Vector, b: &Vector) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Why a primitive could not be formed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PrimitiveError {
    /// A coordinate or length is NaN or infinite.
    #[error("a coordinate or length is not a finite number")]
    NotFinite,
    /// A line through two points that coincide (within the figure tolerance).
    #[error("the two points that should define a line coincide")]
    CoincidentPoints,
    /// A direction of zero length.
    #[error("a direction has zero length")]
    ZeroDirection,
    /// A circle or arc of zero or negative radius.
    #[error("a circle needs a positive radius, got {0}")]
    BadRadius(f64),
}

fn finite(p: &Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// An infinite straight line: a point on it and a unit direction.
///
/// The direction fixes an orientation, used for parameters (`point_at`), for ordering two
/// intersection points and for the sign of `signed_distance` (positive on the left).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Line {
    /// A point of the line (its parameter origin).
    pub origin: Point,
    /// Unit direction.
    pub dir: Vector,
}

impl Line {
    /// The line through `origin` with direction `dir` (normalised here).
    pub fn new(origin: Point, dir: Vector) -> Result<Line, PrimitiveError> {
        if !finite(&origin) || !dir.x.is_finite() || !dir.y.is_finite() {
            return Err(PrimitiveError::NotFinite);
        }
        // x² + y² loses digits below 1e-154 (subnormal) and overflows above 1e154: such a
        // direction is first scaled by an exact power of two into the range where the norm
        // keeps every bit (a subnormal norm has lost some: cargo fuzz found a unit vector
        // 2.7e-12 too long), and a direction that is zero in f64 is refused, not made of NaN.
        let big = dir.x.abs().max(dir.y.abs());
        if big == 0.0 {
            return Err(PrimitiveError::ZeroDirection);
        }
        let dir = if (1e-150..1e150).contains(&big) {
            dir
        } else {
            // 2^-⌊log₂ big⌋ brings the larger component to [1, 2): exact, as any power of two.
            let e = (-big.log2().floor()).clamp(-1000.0, 1000.0) as i32;
            dir * 2f64.powi(e)
        };
        let n = dir.norm();
        if n == 0.0 || !n.is_finite() {
            return Err(PrimitiveError::ZeroDirection);
        }
        let unit = dir / n;
        if !(unit.x.is_finite() && unit.y.is_finite()) {
            return Err(PrimitiveError::ZeroDirection);
        }
        Ok(Line { origin, dir: unit })
    }

    /// The line from `a` through `b`; `eps` is the figure's length tolerance.
    ///
    /// ```
    /// use graphostatik::kernel::{Line, Point};
    /// let l = Line::through(Point::new(0.0, 0.0), Point::new(2.0, 0.0), 1e-12).unwrap();
    /// assert_eq!(l.dir.x, 1.0);
    /// assert!(Line::through(Point::new(1.0, 1.0), Point::new(1.0, 1.0), 1e-12).is_err());
    /// ```
    pub fn through(a: Point, b: Point, eps: f64) -> Result<Line, PrimitiveError> {
        if !finite(&a) || !finite(&b) {
            return Err(PrimitiveError::NotFinite);
        }
        if (b - a).norm() <= eps {
            return Err(PrimitiveError::CoincidentPoints);
        }
        Line::new(a, b - a)
    }

    /// The point at parameter `t` (mm from the origin along the direction).
    #[inline]
    pub fn point_at(&self, t: f64) -> Point {
        self.origin + self.dir * t
    }

    /// The parameter of the orthogonal projection of `p` on the line.
    #[inline]
    pub fn param_of(&self, p: &Point) -> f64 {
        (p - self.origin).dot(&self.dir)
    }

    /// Signed distance of `p` from the line, positive to the left of the direction.
    #[inline]
    pub fn signed_distance(&self, p: &Point) -> f64 {
        cross(&self.dir, &(p - self.origin))
    }

    /// The unit normal, the direction turned 90° counter-clockwise.
    #[inline]
    pub fn normal(&self) -> Vector {
        Vector::new(-self.dir.y, self.dir.x)
    }
}

/// A segment between two points.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Segment {
    /// Start point.
    pub a: Point,
    /// End point.
    pub b: Point,
}

impl Segment {
    /// Length in mm.
    pub fn length(&self) -> f64 {
        (self.b - self.a).norm()
    }
}

/// A circle, the compass drawn about `center` with radius `radius`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Circle {
    /// Centre (the compass needle).
    pub center: Point,
    /// Radius in mm (> 0).
    pub radius: f64,
}

impl Circle {
    /// A circle with a positive, finite radius.
    pub fn new(center: Point, radius: f64) -> Result<Circle, PrimitiveError> {
        if !finite(&center) || !radius.is_finite() {
            return Err(PrimitiveError::NotFinite);
        }
        if radius <= 0.0 {
            return Err(PrimitiveError::BadRadius(radius));
        }
        Ok(Circle { center, radius })
    }

    /// The circle about `center` through `p` (compass set to the distance `center`–`p`).
    pub fn through(center: Point, p: Point) -> Result<Circle, PrimitiveError> {
        Circle::new(center, (p - center).norm())
    }

    /// The point at the angle `deg` (degrees, counter-clockwise from +x), exact at quadrants.
    pub fn point_at_deg(&self, deg: f64) -> Point {
        let (s, c) = crate::kernel::angle::sin_cos_deg(deg);
        Point::new(
            self.center.x + self.radius * c,
            self.center.y + self.radius * s,
        )
    }
}

/// A circular arc: from `start_deg`, sweeping `sweep_deg` (counter-clockwise if positive).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Arc {
    /// The carrying circle.
    pub circle: Circle,
    /// Start angle in degrees from +x.
    pub start_deg: f64,
    /// Signed sweep in degrees.
    pub sweep_deg: f64,
}

impl Arc {
    /// The point at fraction `f` ∈ [0, 1] of the sweep.
    pub fn point_at_fraction(&self, f: f64) -> Point {
        self.circle
            .point_at_deg(self.start_deg + self.sweep_deg * f)
    }
}
