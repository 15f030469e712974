//! Angles given in degrees, with exact sines and cosines at the quadrant angles.
//!
//! `f64::sin(PI)` is 1.2e-16, not 0: a crank at its dead centre would leave the piston line by
//! a hair, and T = 0 at the dead centre would become T = 1e-13 kg. Reducing the angle to its
//! quadrant first makes 0°, 90°, 180°, 270° exact and makes sin(180° − φ) bit-identical to
//! sin φ, so outstroke and return stroke are exact mirror images.

/// Sine and cosine of an angle in degrees, exact at multiples of 90°.
///
/// ```
/// use graphostatik::kernel::angle::sin_cos_deg;
/// assert_eq!(sin_cos_deg(180.0), (0.0, -1.0));
/// assert_eq!(sin_cos_deg(270.0), (-1.0, 0.0));
/// let (s, c) = sin_cos_deg(30.0);
/// assert!((s - 0.5).abs() < 1e-15 && (c - 0.75f64.sqrt()).abs() < 1e-15);
/// assert_eq!(sin_cos_deg(150.0).0, sin_cos_deg(30.0).0);
/// ```
#[inline]
pub fn sin_cos_deg(deg: f64) -> (f64, f64) {
    let r = wrap_360(deg);
    let quadrant = (r / 90.0).floor();
    let rem = r - 90.0 * quadrant;
    // Within the quadrant, fold to [0, 45°] so that complementary angles are symmetric.
    let (s, c) = if rem == 0.0 {
        (0.0, 1.0)
    } else if rem <= 45.0 {
        rem.to_radians().sin_cos()
    } else {
        let (s2, c2) = (90.0 - rem).to_radians().sin_cos();
        (c2, s2)
    };
    match quadrant as i32 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// A direction by its sine and cosine: for an angle better known by those than by its degrees
/// (180° − θ for a tiny θ, where forming 180 − θ would round θ away).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SinCos {
    /// The sine.
    pub sin: f64,
    /// The cosine.
    pub cos: f64,
}

impl SinCos {
    /// The sine and cosine of `deg` degrees, exact at the quadrants ([`sin_cos_deg`]).
    pub fn of_deg(deg: f64) -> SinCos {
        let (sin, cos) = sin_cos_deg(deg);
        SinCos { sin, cos }
    }
}

/// The angle in [0°, 360°): `deg.rem_euclid(360.0)`, without the division where the angle is
/// in range already (as nearly every angle of a construction is: `fmod` was 2 % of the crank
/// construction's instructions), and never 360° itself, which `rem_euclid` gives for a tiny
/// negative angle (−1e-15° rounds to 360°, and the quadrant reduction of [`sin_cos_deg`]
/// then read it as 270°).
///
/// ```
/// use graphostatik::kernel::angle::{sin_cos_deg, wrap_360};
/// assert_eq!(wrap_360(-1e-15), 0.0);
/// assert_eq!(wrap_360(-90.0), 270.0);
/// let (s, c) = sin_cos_deg(-1e-15);
/// assert!(s.abs() < 1e-16 && c == 1.0);
/// ```
#[inline]
pub fn wrap_360(deg: f64) -> f64 {
    if (0.0..360.0).contains(&deg) {
        deg
    } else {
        let r = deg.rem_euclid(360.0);
        if r < 360.0 {
            r
        } else {
            0.0
        }
    }
}

/// The angle (radians, in [0, π]) of a triangle opposite its side `c`, the other two sides
/// `a` and `b`: Kahan's half-angle form, free of the cancellation of the law of cosines.
/// `acos((a² + b² − c²)/2ab)` loses half of f64's digits near 0 and π (a needle of a
/// triangle, a linkage at its change point: 1e-6° from it, arccos gives 0, the truth is
/// 7.7e-7°); here each difference is of two given sides, so the angle is as good as they
/// are. Sides that break the triangle inequality by rounding give 0 or π.
///
/// ```
/// use graphostatik::kernel::angle::triangle_angle;
/// // 3-4-5: the right angle opposite 5.
/// assert!((triangle_angle(5.0, 3.0, 4.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// // A needle: sides 1, 1 and 1e-10 enclose 1e-10 rad (arccos gives 0).
/// let tiny = triangle_angle(1e-10, 1.0, 1.0);
/// assert!((tiny / 1e-10 - 1.0).abs() < 1e-12, "{tiny}");
/// assert_eq!(triangle_angle(2.0, 1.0, 1.0), std::f64::consts::PI);
/// ```
pub fn triangle_angle(c: f64, a: f64, b: f64) -> f64 {
    let (a, b) = if a >= b { (a, b) } else { (b, a) };
    // Kahan: with a ≥ b, m = c − (a − b) when b ≥ c, else b − (a − c); both are the
    // triangle's excess c + b − a, formed where it does not cancel.
    let m = if b >= c { c - (a - b) } else { b - (a - c) };
    let num = ((a - b) + c) * m;
    let den = (a + (b + c)) * ((a - c) + b);
    if num <= 0.0 {
        return 0.0;
    }
    if den <= 0.0 {
        return std::f64::consts::PI;
    }
    2.0 * (num / den).sqrt().atan()
}
