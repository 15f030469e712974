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
    pub fn glancing(&self) -> bool {
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
