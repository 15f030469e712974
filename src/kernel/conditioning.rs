//! How well an intersection is conditioned: the drafter's *schleifender Schnitt*.
//!
//! Two curves that meet at the angle θ locate their common point with an error
//! `δ / sin θ` when either curve is off by `δ` across its direction. `1 / sin θ` is the
//! error amplification. Below [`GLANCING_ANGLE`](super::tolerance::GLANCING_ANGLE) the
//! intersection is flagged as glancing.

use super::tolerance::GLANCING_ANGLE;
use serde::Serialize;

/// The conditioning of one intersection.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Conditioning {
    /// Angle at which the two curves meet, radians, in [0, π/2].
    pub angle: f64,
    /// Error amplification `1 / sin(angle)` (∞ for a tangency, serialised as null).
    pub amplification: f64,
    /// True for a glancing intersection (angle below the named threshold).
    pub glancing: bool,
}

impl Conditioning {
    /// From the meeting angle in radians; folded into [0, π/2].
    ///
    /// ```
    /// use graphostatik::kernel::Conditioning;
    /// let c = Conditioning::from_angle(std::f64::consts::FRAC_PI_2);
    /// assert_eq!(c.amplification, 1.0);
    /// assert!(!c.glancing);
    /// assert!(Conditioning::from_angle(0.01).glancing);
    /// ```
    pub fn from_angle(angle: f64) -> Conditioning {
        let mut a = angle.abs() % std::f64::consts::PI;
        if a > std::f64::consts::FRAC_PI_2 {
            a = std::f64::consts::PI - a;
        }
        let s = a.sin();
        Conditioning {
            angle: a,
            amplification: if s > 0.0 { 1.0 / s } else { f64::INFINITY },
            glancing: a < GLANCING_ANGLE,
        }
    }

    /// The meeting angle in degrees.
    pub fn angle_deg(&self) -> f64 {
        self.angle.to_degrees()
    }
}
