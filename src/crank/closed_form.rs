//! The closed forms of the slider-crank, written as the books write them: the crank angle φ
//! counted from the dead centre where the stroke begins, and the double sign ± for outstroke
//! (*Hingang*, +) and return stroke (*Rückgang*, −). They are computed independently of the
//! construction, so a check compares two different routes to one number.
//!
//! Conventions of the engine (see [`super`]): the full crank angle θ ∈ [0°, 360°) counts from
//! the inner dead centre; θ < 180° is the outstroke with φ = θ, θ ≥ 180° the return stroke with
//! φ = θ − 180°. `lambda` is R/L, 0 for an infinitely long rod.

use serde::Serialize;

/// Outstroke or return stroke.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stroke {
    /// *Hingang*: from the inner to the outer dead centre, the upper sign.
    Out,
    /// *Rückgang*: back to the inner dead centre, the lower sign.
    Return,
}

impl Stroke {
    /// The double sign ±: +1 for the outstroke, −1 for the return stroke.
    pub fn sign(self) -> f64 {
        match self {
            Stroke::Out => 1.0,
            Stroke::Return => -1.0,
        }
    }
}

/// Splits the full crank angle θ (degrees) into the book's stroke and φ (degrees).
///
/// ```
/// use graphostatik::crank::closed_form::{book_angle, Stroke};
/// assert_eq!(book_angle(30.0), (Stroke::Out, 30.0));
/// assert_eq!(book_angle(210.0), (Stroke::Return, 30.0));
/// ```
pub fn book_angle(theta_deg: f64) -> (Stroke, f64) {
    let t = crate::kernel::angle::wrap_360(theta_deg);
    if t < 180.0 {
        (Stroke::Out, t)
    } else {
        (Stroke::Return, t - 180.0)
    }
}

fn sc(phi_deg: f64) -> (f64, f64) {
    crate::kernel::angle::sin_cos_deg(phi_deg)
}

/// sin ψ and cos ψ of the rod's inclination: `L sin ψ = R sin φ` (KG, LH Abb. 46).
pub fn rod_angle(lambda: f64, phi_deg: f64) -> (f64, f64) {
    let s = lambda * sc(phi_deg).0;
    (s, ((1.0 - s) * (1.0 + s)).sqrt())
}

/// Piston path from the dead centre where the stroke began (mm, in the unit of `r`):
/// `x = R(1 − cos φ) ± L(1 − √(1 − (R/L · sin φ)²))` (KG 285, LH Gl. 20; Gl. 23 for L = ∞).
/// `l = None` is the infinitely long rod.
///
/// ```
/// use graphostatik::crank::closed_form::{piston_path_book, Stroke};
/// // LH: the difference of outstroke and return stroke at φ = 90° is 2·L(1 − cos ψ) ≈ 2·u.
/// let out = piston_path_book(300.0, Some(1500.0), 90.0, Stroke::Out);
/// let ret = piston_path_book(300.0, Some(1500.0), 90.0, Stroke::Return);
/// assert!((out - ret - 2.0 * 1500.0 * (1.0 - (1.0f64 - 0.04).sqrt())).abs() < 1e-9);
/// ```
pub fn piston_path_book(r: f64, l: Option<f64>, phi_deg: f64, stroke: Stroke) -> f64 {
    let (_, c) = sc(phi_deg);
    let base = r * (1.0 - c);
    match l {
        None => base,
        Some(l) => {
            let (_, cos_psi) = rod_angle(r / l, phi_deg);
            base + stroke.sign() * l * (1.0 - cos_psi)
        }
    }
}

/// Piston position measured from the inner dead centre for the full angle θ (the engine's
/// single coordinate): the outstroke path, or the stroke `2R` less the return-stroke path.
pub fn piston_position(r: f64, l: Option<f64>, theta_deg: f64) -> f64 {
    match book_angle(theta_deg) {
        (Stroke::Out, phi) => piston_path_book(r, l, phi, Stroke::Out),
        (Stroke::Return, phi) => 2.0 * r - piston_path_book(r, l, phi, Stroke::Return),
    }
}

/// The difference u of the outstroke's and the return's piston paths at 90° from their dead
/// centres (LH B.1, Gl. 22): exactly `2L(1 − √(1 − λ²))`, written `2L·λ²/(1 + √(1 − λ²))`
/// so that a long rod loses no digits; LH's `u = L·λ²` keeps the series' first term
/// (60 mm for R = 300, L = 1500 mm, where this gives 60.61).
pub fn path_difference(r: f64, l: f64) -> f64 {
    let lam2 = (r / l) * (r / l);
    2.0 * l * lam2 / (1.0 + (1.0 - lam2).sqrt())
}

/// The outstroke crank angle θ (degrees) at which the piston stands `x` from the inner dead
/// centre (0 ≤ x ≤ 2R): the angle at O of the triangle of crank R, rod L and the distance
/// d = L + R − x from O to the crosshead, by the half-angle formula
/// `tg(θ/2) = √(x (2L − x) / ((2R + 2L − x)(2R − x)))`, whose factors carry no cancellation
/// (acos of the law of cosines would lose half the digits near the dead centres); for the
/// infinite rod `sin(θ/2) = √(x/2R)`.
///
/// ```
/// use graphostatik::crank::closed_form::{crank_angle_at, piston_position};
/// let t = crank_angle_at(300.0, Some(1500.0), 250.0);
/// assert!((piston_position(300.0, Some(1500.0), t) - 250.0).abs() < 1e-9);
/// assert_eq!(crank_angle_at(300.0, Some(1500.0), 600.0), 180.0);
/// ```
pub fn crank_angle_at(r: f64, l: Option<f64>, x: f64) -> f64 {
    let x = x.clamp(0.0, 2.0 * r);
    let half = match l {
        None => (x / (2.0 * r)).sqrt().clamp(0.0, 1.0).asin(),
        Some(l) => {
            let num = x * (2.0 * l - x);
            let den = (2.0 * r + 2.0 * l - x) * (2.0 * r - x);
            num.sqrt().atan2(den.sqrt())
        }
    };
    2.0 * half.to_degrees()
}

/// The factor `sin(φ ± ψ)/cos ψ` of KG (288, 303), LH Gl. 48 (Zusammenstellung 112, lower row).
pub fn sin_factor(lambda: f64, phi_deg: f64, stroke: Stroke) -> f64 {
    let (s, c) = sc(phi_deg);
    let (sp, cp) = rod_angle(lambda, phi_deg);
    // sin(φ ± ψ) = sin φ cos ψ ± cos φ sin ψ
    (s * cp + stroke.sign() * c * sp) / cp
}

/// The factor `cos(φ ± ψ)/cos ψ` of KG (302), LH Gl. 49.
pub fn cos_factor(lambda: f64, phi_deg: f64, stroke: Stroke) -> f64 {
    let (s, c) = sc(phi_deg);
    let (sp, cp) = rod_angle(lambda, phi_deg);
    (c * cp - stroke.sign() * s * sp) / cp
}

/// The acceleration factor `cos φ ± R/L cos 2φ` of KG (291), LH Gl. 29
/// (Zusammenstellung 112, upper row). Approximate: it neglects cos ψ ≈ 1, as the book says.
pub fn accel_factor(lambda: f64, phi_deg: f64, stroke: Stroke) -> f64 {
    sc(phi_deg).1 + stroke.sign() * lambda * sc(2.0 * phi_deg).1
}

/// Piston velocity, signed in the direction of the outstroke:
/// `c = ± v sin(φ ± ψ)/cos ψ` (KG 288, LH Abb. 53 / Gl. 28).
pub fn piston_velocity(v: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (stroke, phi) = book_angle(theta_deg);
    stroke.sign() * v * sin_factor(lambda, phi, stroke)
}

/// Rod force `S = P / cos ψ` (KG 300, LH Gl. 43), positive in compression. `p` is the driving
/// piston force (positive when it pushes the piston the way it moves); on the return stroke a
/// driving force pulls the rod, so S is negative (tension) there.
pub fn rod_force(p: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (stroke, phi) = book_angle(theta_deg);
    stroke.sign() * p / rod_angle(lambda, phi).1
}

/// Guide force `N = P tg ψ` (KG 301, LH Gl. 44): the guide's reaction on the crosshead,
/// positive when the crosshead bears on the lower guide (the book's sense of rotation).
pub fn guide_force(p: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (_, phi) = book_angle(theta_deg);
    let (s, c) = rod_angle(lambda, phi);
    p * s / c
}

/// Tangential force `T = P sin(φ ± ψ)/cos ψ` (KG 303, LH Gl. 48), positive when it drives.
pub fn tangential_force(p: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (stroke, phi) = book_angle(theta_deg);
    p * sin_factor(lambda, phi, stroke)
}

/// Radial crank-pin force `K = P cos(φ ± ψ)/cos ψ` (KG 302 "D'", LH Gl. 49), positive
/// towards the shaft.
pub fn radial_force(p: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (stroke, phi) = book_angle(theta_deg);
    p * cos_factor(lambda, phi, stroke)
}

/// The approximate piston path of LH Gl. 21, from the inner dead centre for the full angle θ:
/// `x = R(1 − cos θ) + R/L · R/2 · sin²θ` (the root of Gl. 20 expanded to first order in R/L).
/// Tolle's parabola draws the acceleration over this abscissa (see [`tolle_bound`]).
pub fn piston_path_approx(r: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (s, c) = sc(theta_deg);
    r * (1.0 - c) + lambda * r / 2.0 * s * s
}

/// The piston acceleration of the books, signed along the outstroke (+x):
/// `b = v²/R (cos θ + R/L cos 2θ)` (KG 291, LH Gl. 29; Gl. 34 with R/L = 0), with v²/R given
/// as `a` (m/s²). The book's value "in the direction of motion" is [`Stroke::sign`] times it.
pub fn acceleration_approx(a: f64, lambda: f64, theta_deg: f64) -> f64 {
    a * (sc(theta_deg).1 + lambda * sc(2.0 * theta_deg).1)
}

/// The exact piston acceleration of the finite rod, signed along +x, with v²/R given as `a`:
/// `ẍ = v²/R (cos θ + λ cos 2θ / cos ψ + λ³ sin² 2θ / (4 cos³ ψ))`, KG (285) differentiated
/// twice at constant ω.
///
/// ```
/// use graphostatik::crank::closed_form::{acceleration_exact, acceleration_approx};
/// // At the dead centres ψ = 0 and the book's (1 ± λ) v²/R is exact (LH Gl. 30, 31).
/// assert!((acceleration_exact(155.5, 1.0 / 6.0, 0.0) - 155.5 * 7.0 / 6.0).abs() < 1e-12);
/// assert!((acceleration_exact(155.5, 1.0 / 6.0, 180.0) + 155.5 * 5.0 / 6.0).abs() < 1e-12);
/// ```
pub fn acceleration_exact(a: f64, lambda: f64, theta_deg: f64) -> f64 {
    let (_, c) = sc(theta_deg);
    let (s2, c2) = sc(2.0 * theta_deg);
    let (_, cp) = rod_angle(lambda, theta_deg);
    a * (c + lambda * c2 / cp + lambda.powi(3) * s2 * s2 / (4.0 * cp.powi(3)))
}

/// A bound of |exact − approximate| acceleration over v²/R for every crank angle:
/// `1.25 λ³ / (1 − λ²)^{3/2}`. From the exact form, `λ cos 2θ (1/cos ψ − 1)` is at most
/// `λ³ / cos ψ` (as `1/cos ψ − 1 ≤ sin²ψ / cos ψ`) and the last term at most `λ³/(4 cos³ ψ)`,
/// with `cos ψ ≥ √(1 − λ²)`. At λ = 1/6 it is 0.0059 (0.6 % of v²/R); at 1/5, 0.0107.
pub fn tolle_bound(lambda: f64) -> f64 {
    let c = ((1.0 - lambda) * (1.0 + lambda)).sqrt();
    1.25 * lambda.powi(3) / (c * c * c)
}

/// A bound of |exact − approximate| acceleration over v²/R at the crank angle θ: the two
/// terms [`acceleration_exact`] adds to the book's cos θ + λ cos 2θ, each taken at its
/// size, `λ|cos 2θ|(1/cos ψ − 1) + λ³ sin² 2θ/(4 cos³ ψ)`. It is at most
/// [`tolle_bound`], which holds for every angle and grows without limit as λ → 1 (2.6e9 at
/// λ = 1 − 1e-6, where the gap at one angle is some thousand times v²/R): a check held to
/// the bound of its own angle fails on a wrong value there.
///
/// ```
/// use graphostatik::crank::closed_form::{acceleration_approx, acceleration_exact, tolle_bound, tolle_bound_at};
/// for theta in [0.0, 37.0, 90.0, 133.0, 180.0, 271.0] {
///     let gap = (acceleration_exact(1.0, 0.2, theta) - acceleration_approx(1.0, 0.2, theta)).abs();
///     let at = tolle_bound_at(0.2, theta);
///     assert!(gap <= at * (1.0 + 1e-12) && at <= tolle_bound(0.2));
/// }
/// ```
pub fn tolle_bound_at(lambda: f64, theta_deg: f64) -> f64 {
    let (s2, c2) = sc(2.0 * theta_deg);
    let (_, cp) = rod_angle(lambda, theta_deg);
    lambda * c2.abs() * (1.0 / cp - 1.0) + lambda.powi(3) * s2 * s2 / (4.0 * cp.powi(3))
}

/// The crank angle φ (degrees, outstroke) of the largest piston velocity, exactly: the zero of
/// [`acceleration_exact`] in (0°, 90°], found by bisection to the last bit.
///
/// ```
/// use graphostatik::crank::closed_form::max_velocity_angle;
/// // R/L = 1/5: 79.100°, between Esselborn's rod-perpendicular 78.690° and LH's 79°16'.
/// assert!((max_velocity_angle(0.2) - 79.1001).abs() < 1e-4);
/// ```
pub fn max_velocity_angle(lambda: f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 90.0f64);
    // acceleration_exact > 0 at 0° and ≤ 0 at 90° for 0 ≤ λ < 1.
    while hi - lo > f64::EPSILON * 90.0 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if acceleration_exact(1.0, lambda, mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The crank angle φ (degrees) where the rod stands perpendicular to the crank:
/// `tg φ = L/R` (Esselborn, LH Abb. 52); 90° for the infinitely long rod.
pub fn rod_perpendicular_angle(lambda: f64) -> f64 {
    1.0f64.atan2(lambda).to_degrees()
}

/// The crank angle φ (degrees) where the book's approximate acceleration (KG 291, LH Gl. 29)
/// vanishes: `cos φ = 2λ / (1 + √(1 + 8λ²))`, LH's 79°16' for R/L = 1/5.
pub fn approx_zero_acceleration_angle(lambda: f64) -> f64 {
    (2.0 * lambda / (1.0 + (1.0 + 8.0 * lambda * lambda).sqrt()))
        .acos()
        .to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn forces_satisfy_their_vector_identities() {
        // T² + K² = S² and S² = P² + N²: the two parallelograms of LH Abb. 61.
        for &lambda in &[0.0, 1.0 / 6.0, 0.2, 0.5, 0.99] {
            for k in 0..72 {
                let th = k as f64 * 5.0;
                let p = 1000.0;
                let (s, n, t, kk) = (
                    rod_force(p, lambda, th),
                    guide_force(p, lambda, th),
                    tangential_force(p, lambda, th),
                    radial_force(p, lambda, th),
                );
                assert!((t * t + kk * kk - s * s).abs() < 1e-6 * s * s);
                assert!((p * p + n * n - s * s).abs() < 1e-6 * s * s);
            }
        }
    }

    #[test]
    fn velocity_is_the_derivative_of_the_position() {
        let (r, l) = (0.4, 2.0);
        let v = 1.0; // ω = v / r
        for k in 1..71 {
            let th = k as f64 * 5.0 + 0.5;
            let h = 1e-4;
            let dx = (piston_position(r, Some(l), th + h) - piston_position(r, Some(l), th - h))
                / (2.0 * h.to_radians());
            let c = piston_velocity(v, r / l, th);
            assert!(
                (dx * v / r - c).abs() < 1e-7,
                "θ={th}: {} vs {c}",
                dx * v / r
            );
        }
    }

    #[test]
    fn acceleration_is_the_derivative_of_the_velocity_and_tolle_bounds_the_book() {
        for &lambda in &[0.0, 0.1, 1.0 / 6.0, 0.2, 0.25, 0.5, 0.9, 0.99] {
            let mut worst: f64 = 0.0;
            for k in 0..720 {
                let th = k as f64 * 0.5 + 0.25;
                let h = 1e-4;
                let dc = (piston_velocity(1.0, lambda, th + h)
                    - piston_velocity(1.0, lambda, th - h))
                    / (2.0 * h.to_radians());
                let b = acceleration_exact(1.0, lambda, th);
                assert!(
                    (dc - b).abs() < 1e-6 * (1.0 + b.abs()),
                    "λ={lambda} θ={th}: {dc} vs {b}"
                );
                worst = worst.max((b - acceleration_approx(1.0, lambda, th)).abs());
            }
            assert!(
                worst <= tolle_bound(lambda) + 1e-15,
                "λ={lambda}: {worst} > bound"
            );
            // The bound is not loose by orders of magnitude (it is what the check table uses).
            // (For the usual rods, λ ≤ 1/2; near locking it grows loose.)
            assert!(
                lambda == 0.0 || lambda > 0.5 || worst > 0.2 * tolle_bound(lambda),
                "λ={lambda}: {worst}"
            );
        }
    }

    #[test]
    fn the_three_angles_of_the_largest_velocity() {
        // R/L = 1/5: LH's 79°16' is the zero of the approximate Gl. 29; the exact maximum is
        // 79°06'; Esselborn's rod-perpendicular position 78°41'.
        let (ex, es, ap) = (
            max_velocity_angle(0.2),
            rod_perpendicular_angle(0.2),
            approx_zero_acceleration_angle(0.2),
        );
        assert!((ap - (79.0 + 16.0 / 60.0)).abs() < 0.5 / 60.0, "{ap}");
        assert!((es - 78.690_067_5).abs() < 1e-6 && (ex - 79.100_1).abs() < 1e-4);
        assert_eq!(max_velocity_angle(0.0), 90.0);
    }
}
