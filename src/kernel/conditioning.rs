//! How well an intersection is conditioned: the drafter's *schleifender Schnitt*.
//!
//! Two curves that meet at the angle θ locate their common point with an error
//! `δ / sin θ` when either curve is off by `δ` across its direction. `1 / sin θ` is the
//! error amplification. Below [`GLANCING_ANGLE`] the
//! intersection is flagged as glancing.
//!
//! The intersection routines have the sine and cosine of the meeting angle at hand; they are
//! stored as they are, and the angle (one `atan2`) is computed only when asked for, so a
//! construction that does not record pays no trigonometry for its conditioning.

use super::tolerance::GLANCING_ANGLE;
use serde::{Serialize, Serializer};

/// tan 15° = 2 − √3, the tangent of [`GLANCING_ANGLE`].
const GLANCING_TAN: f64 = 0.267_949_192_431_122_7;

/// The conditioning of one intersection: the meeting angle, folded into [0, π/2].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditioning {
    /// |sin| of the meeting angle, up to a common positive factor with `cos`.
    sin: f64,
    /// |cos| of the meeting angle, up to the same factor.
    cos: f64,
}

impl Conditioning {
    /// From the meeting angle in radians; folded into [0, π/2].
    ///
    /// ```
    /// use graphostatik::kernel::Conditioning;
    /// let c = Conditioning::from_angle(std::f64::consts::FRAC_PI_2);
    /// assert_eq!(c.amplification(), 1.0);
    /// assert!(!c.glancing());
    /// assert!(Conditioning::from_angle(0.01).glancing());
    /// assert!((Conditioning::from_angle(3.0).angle() - (std::f64::consts::PI - 3.0)).abs() < 1e-15);
    /// ```
    pub fn from_angle(angle: f64) -> Conditioning {
        let (s, c) = angle.sin_cos();
        Conditioning::from_sin_cos(s, c)
    }

    /// From the sine and cosine of the meeting angle (any signs, any common positive factor).
    #[inline]
    pub fn from_sin_cos(sin: f64, cos: f64) -> Conditioning {
        Conditioning {
            sin: sin.abs(),
            cos: cos.abs(),
        }
    }

    /// The meeting angle in radians, in [0, π/2] (90° for perpendicular curves, 0 for tangency).
    pub fn angle(&self) -> f64 {
        self.sin.atan2(self.cos)
    }

    /// The meeting angle in degrees.
    pub fn angle_deg(&self) -> f64 {
        self.angle().to_degrees()
    }

    /// Error amplification `1 / sin(angle)`: ∞ for a tangency.
    pub fn amplification(&self) -> f64 {
        if self.sin > 0.0 {
            self.sin.hypot(self.cos) / self.sin
        } else {
            f64::INFINITY
        }
    }

    /// Whether the cut is glancing (a *schleifender Schnitt*): the angle is below
    /// [`GLANCING_ANGLE`].
    ///
    /// Decided without trigonometry away from the threshold: `sin < tan 15° · cos` there
    /// gives the same answer as the angle. The margin, 1e-9 relative, is some four million
    /// times the rounding of either side (a few ulps). Only within it, or for a cosine
    /// outside the normal range, is the `atan2` taken. A check table asks this of every
    /// check.
    pub fn glancing(&self) -> bool {
        if self.cos > 1e-290 && self.cos < 1e290 {
            let edge = GLANCING_TAN * self.cos;
            if self.sin < edge * (1.0 - 1e-9) {
                return true;
            }
            if self.sin > edge * (1.0 + 1e-9) {
                return false;
            }
        }
        self.angle() < GLANCING_ANGLE
    }
}

impl Serialize for Conditioning {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("Conditioning", 3)?;
        st.serialize_field("angle_deg", &self.angle_deg())?;
        let amp = self.amplification();
        st.serialize_field("amplification", &amp.is_finite().then_some(amp))?;
        st.serialize_field("glancing", &self.glancing())?;
        st.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tangent_is_that_of_the_glancing_angle() {
        assert!((GLANCING_TAN - GLANCING_ANGLE.tan()).abs() <= 2.0 * f64::EPSILON * GLANCING_TAN);
    }

    #[test]
    fn glancing_without_trigonometry_answers_as_the_angle_does() {
        let by_angle = |c: &Conditioning| c.angle() < GLANCING_ANGLE;
        let mut cases = Vec::new();
        // Angles around the threshold, down to the neighbouring floats of its sine and
        // cosine, at scales from subnormal to huge.
        let (s0, c0) = GLANCING_ANGLE.sin_cos();
        for scale in [1.0, 1e-300, 5e-324 / s0, 1e-200, 3.7, 1e200, 1e300, 1e308] {
            for k in -40i32..=40 {
                let d = f64::EPSILON * f64::from(k);
                cases.push((s0 * (1.0 + d) * scale, c0 * scale));
                cases.push((s0 * scale, c0 * (1.0 + d) * scale));
            }
            for deg in (0..=900).map(|t| f64::from(t) * 0.1) {
                let (s, c) = deg.to_radians().sin_cos();
                cases.push((s * scale, c * scale));
            }
        }
        let odd = [
            0.0,
            f64::MIN_POSITIVE,
            1.0,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ];
        for &a in &odd {
            for &b in &odd {
                cases.push((a, b));
            }
        }
        for (s, c) in cases {
            let k = Conditioning::from_sin_cos(s, c);
            assert_eq!(k.glancing(), by_angle(&k), "sin {s:e}, cos {c:e}");
        }
    }
}
