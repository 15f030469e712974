//! The engine's pressures and forces as functions, independent of any construction: the
//! indicator diagrams (digitised or modelled), the piston forces of a double-acting cylinder,
//! the inertia of the reciprocating masses and the turning force, with their exact integrals.
//! The construction reads its ordinates from these, and the checks hold the construction to
//! them.

use crate::crank::closed_form as cf;
use crate::kernel::tolerance::CROSSING_DEG_EPS;

/// Technical units (LH, KG): g in m/s².
pub const G: f64 = 9.81;

/// A cylinder side's pressures over its own stroke coordinate u ∈ [0, 1], from the dead
/// centre where its working stroke begins (u = x/s on the cover side, 1 − x/s on the crank
/// side), absolute pressures in at (kg/cm²).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Indicator {
    /// Digitised points (u, p), ordered along the stroke, joined by straight lines: the working
    /// stroke (the side's volume grows) and the back stroke (it shrinks).
    Points {
        /// (u, p) of the working stroke, u rising from 0 to 1.
        working: Vec<(f64, f64)>,
        /// (u, p) of the back stroke, u rising from 0 to 1.
        back: Vec<(f64, f64)>,
    },
    /// A steam distribution (LH Abb. 40): admission to cut-off, expansion pV^n = const to
    /// release, exhaust falling straight to the back pressure at the dead centre; on the back
    /// stroke the back pressure to the start of compression, then compression pV^n = const.
    Steam(SteamModel),
}

/// The parameters of a modelled steam distribution; fractions of the stroke, absolute at.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SteamModel {
    /// Admission pressure (at abs).
    pub admission: f64,
    /// Cut-off, fraction of the stroke (0 < ε ≤ release).
    pub cutoff: f64,
    /// Exponent n of the expansion and compression lines (1 for Mariotte's law).
    pub exponent: f64,
    /// Release (Vorausströmung), fraction of the stroke (cutoff ≤ release ≤ 1).
    pub release: f64,
    /// Back pressure (at abs).
    pub back: f64,
    /// Compression begins when this fraction of the stroke is left on the back stroke.
    pub compression: f64,
    /// Clearance volume as a fraction of the swept volume (schädlicher Raum).
    pub clearance: f64,
}

impl SteamModel {
    /// Working-stroke pressure at u.
    pub fn working(&self, u: f64) -> f64 {
        let c = self.clearance;
        if u <= self.cutoff {
            self.admission
        } else if u <= self.release {
            self.admission * ((self.cutoff + c) / (u + c)).powf(self.exponent)
        } else {
            let p_rel =
                self.admission * ((self.cutoff + c) / (self.release + c)).powf(self.exponent);
            let t = (u - self.release) / (1.0 - self.release);
            p_rel + (self.back - p_rel) * t
        }
    }

    /// Back-stroke pressure at u (u falls from 1 to 0 as the side's volume shrinks).
    pub fn back_stroke(&self, u: f64) -> f64 {
        if u >= self.compression {
            self.back
        } else {
            let c = self.clearance;
            self.back * ((self.compression + c) / (u + c)).powf(self.exponent)
        }
    }

    /// The points of the stroke where the curves have a corner (cut-off, release, start of
    /// compression): where a quadrature should split.
    pub fn corners(&self) -> [f64; 3] {
        [self.cutoff, self.release, self.compression]
    }
}

/// The pressure at `u` on a curve of digitised points in order along the stroke (x never
/// decreasing, as the scene requires): the first point at or past `u` found by binary
/// search (a linear search made a cylinder of 100,000 points per curve take some ten
/// minutes).
fn interpolate(pts: &[(f64, f64)], u: f64) -> f64 {
    match pts.partition_point(|&(x, _)| x < u) {
        k if k == pts.len() => pts.last().map_or(0.0, |p| p.1),
        0 => pts[0].1,
        k => {
            let ((x0, y0), (x1, y1)) = (pts[k - 1], pts[k]);
            if x1 > x0 {
                y0 + (y1 - y0) * (u - x0) / (x1 - x0)
            } else {
                y1
            }
        }
    }
}

impl Indicator {
    /// Pressure on the working stroke at u (at abs).
    pub fn working(&self, u: f64) -> f64 {
        match self {
            Indicator::Points { working, .. } => interpolate(working, u),
            Indicator::Steam(m) => m.working(u),
        }
    }

    /// Pressure on the back stroke at u (at abs).
    pub fn back(&self, u: f64) -> f64 {
        match self {
            Indicator::Points { back, .. } => interpolate(back, u),
            Indicator::Steam(m) => m.back_stroke(u),
        }
    }

    /// Where the pressure curves have corners (u): the digitised points, or the model's
    /// cut-off, release and compression.
    pub fn corners(&self) -> Vec<f64> {
        match self {
            Indicator::Points { working, back } => {
                working.iter().chain(back).map(|p| p.0).collect()
            }
            Indicator::Steam(m) => m.corners().to_vec(),
        }
    }

    /// The mean pressure p_m of the diagram, ∫ (working − back) du, exactly (adaptive
    /// quadrature split at the corners).
    pub fn mean_pressure(&self) -> f64 {
        integrate_split(
            |u| self.working(u) - self.back(u),
            0.0,
            1.0,
            &self.corners(),
        )
    }
}

/// An ordinate `a` (mm) drawn with the spring scale `f` (mm per at), redrawn with the spring
/// scale `f_new`: `a' = a · f'/f` (LH Gl. 15; 13.5 · 2.5/1.5 = 22.5 mm).
pub fn respring(a: f64, f: f64, f_new: f64) -> f64 {
    a * f_new / f
}

/// The reduction factor `R = F_w/(f · k)` turning an indicator ordinate (mm at the spring
/// scale f, mm per at) into a piston-force ordinate at the force scale k (kg per mm)
/// (LH Gl. 18-19).
///
/// ```
/// use graphostatik::dynamics::model::{area_cm2, reduction_factor};
/// // LH A: the locomotive's crank side, D = 540, rod 90 mm, f = 1.5 mm/at, k = 900 kg/mm.
/// let r_k = reduction_factor(area_cm2(540.0, 90.0), 1.5, 900.0);
/// assert!((r_k - 1.65).abs() < 0.005);
/// ```
pub fn reduction_factor(area_cm2: f64, f: f64, k: f64) -> f64 {
    area_cm2 / (f * k)
}

/// The effective piston area `π/4 (D² − d²)` (cm²) for a bore and a rod through the side (mm).
pub fn area_cm2(bore_mm: f64, rod_mm: f64) -> f64 {
    std::f64::consts::PI / 4.0 * ((bore_mm / 10.0).powi(2) - (rod_mm / 10.0).powi(2))
}

/// Revolutions per minute of a crank of radius `r_mm` whose pin runs at `v` m/s:
/// n = 60·v/(2πr) (LH H).
pub fn revolutions_per_minute(v: f64, r_mm: f64) -> f64 {
    60.0 * v / (2.0 * std::f64::consts::PI * r_mm / 1000.0)
}

/// Indicated power of a double-acting cylinder (PS, LH Gl. 68):
/// `(F_D p_m^D + F_K p_m^K) · s · n / (75 · 60)`, areas in cm², p_m in at, s in m, n per min.
pub fn indicated_power(sides: [(f64, f64); 2], s_m: f64, n: f64) -> f64 {
    let work: f64 = sides.iter().map(|(f, p)| f * p).sum();
    work * s_m * n / (75.0 * 60.0)
}

/// Power from the mean turning force (PS, LH Gl. 69): `T_m · v / 75`.
pub fn power_from_turning(t_m: f64, v: f64) -> f64 {
    t_m * v / 75.0
}

/// One side of a double-acting cylinder.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Side {
    /// Effective piston area F_w (cm²): the bore less a rod passing through this side.
    pub area_cm2: f64,
    /// Its pressures.
    pub indicator: Indicator,
}

/// A cylinder of the engine: both sides, the reciprocating mass and the crank offset.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Cylinder {
    /// Name in the figure ("HP", "left").
    pub name: String,
    /// Cover side (Deckelseite), working on the outstroke.
    pub cover: Side,
    /// Crank side (Kurbelseite), working on the return stroke.
    pub crank: Side,
    /// Reciprocating mass M = G/g (kg·s²/m); 0 without the effect `inertia`.
    pub mass: f64,
    /// How far this crank leads the first one (degrees).
    pub offset_deg: f64,
    /// A double-acting pump on the same piston rod (KG Abb. 1053, 1065-1067), with the
    /// effect `pump`.
    pub pump: Option<Pump>,
    /// The indicator card as the indicator drew it, where its reduction is to be drawn
    /// (LH A, Abb. 42-45).
    pub card: Option<IndicatorCard>,
}

/// An indicator card as the indicator drew it (LH A, Abb. 42): its length and its spring
/// scale, and the spring scale it is redrawn at over the new length before the piston forces
/// (Abb. 44), where the book redraws it so.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct IndicatorCard {
    /// The card's length l (mm): the stroke as the indicator's reducing gear drew it.
    pub length_mm: f64,
    /// Its spring scale f (mm per at): p = a/f (LH Gl. 14).
    pub spring_mm_per_at: f64,
    /// The spring scale f′ it is redrawn at (mm per at): a′ = a·f′/f (LH Gl. 15).
    pub respring_mm_per_at: Option<f64>,
}

/// A double-acting plunger pump driven directly by the cylinder's piston rod (KG Abb. 1053):
/// its force is a rectangle over the stroke, P_p1 = F_p(p_s + p_a) − f_s·p_a on the
/// outstroke and P_p2 = F_p(p_s + p_a) − f_s·p_s on the return, resisting the motion; the
/// steam side's force is reduced by the efficiency η before the pump's is laid over it
/// (KG Abb. 1065).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Pump {
    /// Plunger area F_p (cm²).
    pub plunger_cm2: f64,
    /// Area f_s of the rod at the plunger's front end (cm²).
    pub rod_cm2: f64,
    /// Suction: the underpressure p_s below the atmosphere (at).
    pub suction_at: f64,
    /// Delivery pressure p_a (at, gauge).
    pub delivery_at: f64,
    /// Efficiency η by which the steam force is reduced (KG: 0.85-0.92).
    pub efficiency: f64,
}

impl Pump {
    /// The pump's resisting force on the outstroke (P_p1) and on the return (P_p2), kg.
    ///
    /// ```
    /// use graphostatik::dynamics::model::{area_cm2, Pump};
    /// // KG, Tafel I: d = 28.5 cm, rod 7.5 cm, p_s = 0.45 at, p_a = 5.4 at.
    /// let p = Pump { plunger_cm2: area_cm2(285.0, 0.0), rod_cm2: area_cm2(75.0, 0.0), suction_at: 0.45, delivery_at: 5.4, efficiency: 0.9 };
    /// let (p1, p2) = p.forces();
    /// assert_eq!((p1.round(), p2.round()), (3493.0, 3712.0)); // KG prints 3490 and 3710
    /// ```
    pub fn forces(&self) -> (f64, f64) {
        let both = self.plunger_cm2 * (self.suction_at + self.delivery_at);
        (
            both - self.rod_cm2 * self.delivery_at,
            both - self.rod_cm2 * self.suction_at,
        )
    }

    /// The pump's force on the given stroke (kg, resisting).
    pub fn force(&self, stroke: cf::Stroke) -> f64 {
        let (p1, p2) = self.forces();
        match stroke {
            cf::Stroke::Out => p1,
            cf::Stroke::Return => p2,
        }
    }

    /// The larger of its two forces (kg): the scale its rectangle is drawn and judged at.
    pub fn largest_force(&self) -> f64 {
        let (p1, p2) = self.forces();
        p1.abs().max(p2.abs())
    }

    /// The pump's mean resistance at the crank pin over a revolution (kg, KG Abb. 1067):
    /// its work 2r·(P_p1 + P_p2) spread over the crank circle 2πr, (P_p1 + P_p2)/π.
    ///
    /// ```
    /// use graphostatik::dynamics::model::{area_cm2, Pump};
    /// let p = Pump { plunger_cm2: area_cm2(285.0, 0.0), rod_cm2: area_cm2(75.0, 0.0), suction_at: 0.45, delivery_at: 5.4, efficiency: 0.9 };
    /// assert!((p.mean_resistance() - 2293.6).abs() < 0.05); // (3493.4 + 3712.1)/π
    /// ```
    pub fn mean_resistance(&self) -> f64 {
        let (p1, p2) = self.forces();
        (p1 + p2) / std::f64::consts::PI
    }
}

impl Cylinder {
    /// The net piston force from the pressures alone (KG 296-297, LH Gl. 40-42) at the full
    /// crank angle θ of this cylinder and the piston position x (fraction of the stroke from
    /// the inner dead centre), positive when it drives the piston the way it moves. With a
    /// pump: η times the steam force, less the pump's rectangle (KG Abb. 1065); at a dead
    /// centre during compression the drive carries the sum of both.
    pub fn pressure_force(&self, theta_deg: f64, x: f64) -> f64 {
        let (stroke, _) = cf::book_angle(theta_deg);
        let steam = self.steam_force(stroke, x);
        match &self.pump {
            Some(p) => p.efficiency * steam - p.force(stroke),
            None => steam,
        }
    }

    /// The share of the steam force the net-pressure diagram draws: the efficiency η where a
    /// pump on the rod is laid against the steam force reduced by it (KG Abb. 1065), 1
    /// otherwise.
    pub fn drawn_steam_share(&self) -> f64 {
        self.pump.map_or(1.0, |p| p.efficiency)
    }

    /// The mean of the two sides' effective areas, F = (F′+F″)/2 (cm², KG 297).
    pub fn mean_area_cm2(&self) -> f64 {
        0.5 * (self.cover.area_cm2 + self.crank.area_cm2)
    }

    /// The net steam force alone (kg) on the given stroke at x.
    pub fn steam_force(&self, stroke: cf::Stroke, x: f64) -> f64 {
        let ((work, u_work), (back, u_back)) = self.sides(stroke, x);
        work.area_cm2 * work.indicator.working(u_work) - back.area_cm2 * back.indicator.back(u_back)
    }

    /// The side working on `stroke` (the cover side on the outstroke) and the side behind
    /// the piston, each with the piston's position along its own side's stroke, x being the
    /// position from the inner dead centre.
    pub fn sides(&self, stroke: cf::Stroke, x: f64) -> ((&Side, f64), (&Side, f64)) {
        match stroke {
            cf::Stroke::Out => ((&self.cover, x), (&self.crank, 1.0 - x)),
            cf::Stroke::Return => ((&self.crank, 1.0 - x), (&self.cover, x)),
        }
    }
}

/// The crank geometry and speed the dynamics need.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Kinematics {
    /// Crank radius R (mm).
    pub r: f64,
    /// R/L, 0 for the infinitely long rod.
    pub lambda: f64,
    /// Crank-pin speed v (m/s).
    pub v: f64,
}

impl Kinematics {
    /// v²/R (m/s²).
    pub fn a(&self) -> f64 {
        self.v * self.v / (self.r / 1000.0)
    }

    /// The rod, `None` for the infinitely long rod.
    pub fn rod(&self) -> Option<f64> {
        (self.lambda > 0.0).then(|| self.r / self.lambda)
    }

    /// Piston position as a fraction of the stroke from the inner dead centre (exact, KG 285).
    pub fn x_frac(&self, theta_deg: f64) -> f64 {
        cf::piston_position(self.r, self.rod(), theta_deg) / (2.0 * self.r)
    }

    /// The inertia force M·b of the book (KG 298, LH Gl. 35 with Gl. 29), in the direction of
    /// motion: the force the piston force spends accelerating the masses.
    pub fn inertia(&self, mass: f64, theta_deg: f64) -> f64 {
        let (stroke, _) = cf::book_angle(theta_deg);
        mass * stroke.sign() * cf::acceleration_approx(self.a(), self.lambda, theta_deg)
    }

    /// The resulting driving force P − M·b (LH C.1, Abb. 58) of a cylinder at its crank angle.
    pub fn resulting_force(&self, c: &Cylinder, theta_deg: f64) -> f64 {
        c.pressure_force(theta_deg, self.x_frac(theta_deg)) - self.inertia(c.mass, theta_deg)
    }

    /// The tangential force T = P sin(φ ± ψ)/cos ψ of a cylinder at its crank angle (KG 303).
    pub fn tangential(&self, c: &Cylinder, theta_deg: f64) -> f64 {
        cf::tangential_force(self.resulting_force(c, theta_deg), self.lambda, theta_deg)
    }
}

/// The turning force on the shaft at shaft angle θ: every cylinder at θ + its offset, summed,
/// times the efficiency η (KG Abb. 1062, 1064; LH F).
pub fn turning_force(k: &Kinematics, cyls: &[Cylinder], eta: f64, theta_deg: f64) -> f64 {
    eta * cyls
        .iter()
        .map(|c| k.tangential(c, (theta_deg + c.offset_deg).rem_euclid(360.0)))
        .sum::<f64>()
}

/// The pumps' resistance on the shaft at shaft angle θ (kg, KG Abb. 1067): each pump's
/// rectangle P_p1, P_p2 carried through the crank as T_p = P_p·sin(φ ± ψ)/cos ψ, summed over
/// the cylinders that drive one; positive where it resists. The rectangles give curves like
/// sine lines ("Sinuslinien ähnliche Kurven").
pub fn pump_resistance(k: &Kinematics, cyls: &[Cylinder], theta_deg: f64) -> f64 {
    (cyls.iter())
        .filter_map(|c| c.pump.map(|p| (c, p)))
        .map(|(c, p)| {
            let t = (theta_deg + c.offset_deg).rem_euclid(360.0);
            cf::tangential_force(p.force(cf::book_angle(t).0), k.lambda, t)
        })
        .sum()
}

/// The power engine's own turning force at shaft angle θ (kg, KG Abb. 1067), which the
/// pumps' resistance line is compared with: every cylinder's steam force (reduced by the
/// pump's η where it drives one) less its inertia force, carried through the crank, summed
/// and times the engine's η.
pub fn steam_turning_force(k: &Kinematics, cyls: &[Cylinder], eta: f64, theta_deg: f64) -> f64 {
    eta * (cyls.iter())
        .map(|c| {
            let t = (theta_deg + c.offset_deg).rem_euclid(360.0);
            let (stroke, _) = cf::book_angle(t);
            let steam = c.drawn_steam_share() * c.steam_force(stroke, k.x_frac(t));
            cf::tangential_force(steam - k.inertia(c.mass, t), k.lambda, t)
        })
        .sum::<f64>()
}

/// The shaft angles (degrees in [0, 360)) where some cylinder passes a corner of its
/// pressure curves or a dead centre: the turning force has a kink there.
pub fn turning_corners(k: &Kinematics, cyls: &[Cylinder]) -> Vec<f64> {
    let mut out = Vec::new();
    for c in cyls {
        let mut xs: Vec<f64> = c.cover.indicator.corners();
        xs.extend(c.crank.indicator.corners().iter().map(|u| 1.0 - u));
        for x in xs.into_iter().filter(|x| (0.0..=1.0).contains(x)) {
            for theta in crank_angles_at(k, x) {
                out.push((theta - c.offset_deg).rem_euclid(360.0));
            }
        }
        for dead in [0.0, 180.0] {
            out.push((dead - c.offset_deg).rem_euclid(360.0));
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    out
}

/// The two crank angles (out and return) where the piston stands at fraction x of the stroke
/// ([`cf::crank_angle_at`], the half-angle formula).
pub fn crank_angles_at(k: &Kinematics, x: f64) -> [f64; 2] {
    let t = cf::crank_angle_at(k.r, k.rod(), x * 2.0 * k.r);
    [t, 360.0 - t]
}

/// ∫ f over [a, b], split at the interior `corners` (where f has a kink), each smooth piece
/// by 8-point Gauss-Legendre, halved until the halves agree with the whole to 1e-11 of ∫|f|
/// over the range (shared out by width, so that a sliver at a dead centre is not refined
/// below the rounding of the values around it). The net piston force is a difference of two
/// large forces, so its values carry rounding of some 1e-13 of their size: a tighter target
/// would chase that noise. At most [`QUADRATURE_BUDGET`] evaluations per call.
pub fn integrate_split(f: impl Fn(f64) -> f64, a: f64, b: f64, corners: &[f64]) -> f64 {
    let mut cuts: Vec<f64> = corners
        .iter()
        .copied()
        .filter(|c| *c > a && *c < b)
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut edges = vec![a];
    edges.extend(cuts);
    edges.push(b);
    // Each piece's rule and the rule of |f| from the same 16 values: a diagram of many
    // digitised points has millions of pieces, each evaluated once here.
    let (wholes, abs): (Vec<f64>, Vec<f64>) = edges
        .windows(2)
        .map(|w| gauss_with_abs(&f, w[0], w[1]))
        .unzip();
    let scale = abs.iter().sum::<f64>();
    drop(abs);
    let per_width = 1e-11 * scale.max(f64::MIN_POSITIVE) / (b - a);
    let budget = std::cell::Cell::new(QUADRATURE_BUDGET);
    edges
        .windows(2)
        .zip(wholes)
        .map(|(w, whole)| refine(&f, (w[0], w[1]), whole, per_width * (w[1] - w[0]), &budget))
        .sum()
}

/// The most evaluations [`integrate_split`] spends refining: a bound on its time whatever f.
pub const QUADRATURE_BUDGET: usize = 200_000;

/// 8-point Gauss-Legendre nodes (positive half) and weights on [−1, 1].
const GAUSS8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// [`gauss`] of f and of |f| over [a, b], from one evaluation of f at each node (the same
/// bits as the two rules taken apart: the terms are summed in the same order).
fn gauss_with_abs(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut sum, mut sum_abs) = (-0.0, -0.0);
    for &(x, w) in &GAUSS8 {
        let (lo, hi) = (f(m - h * x), f(m + h * x));
        sum += w * (lo + hi);
        sum_abs += w * (lo.abs() + hi.abs());
    }
    (h * sum, h * sum_abs)
}

fn gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
    h * GAUSS8
        .iter()
        .map(|&(x, w)| w * (f(m - h * x) + f(m + h * x)))
        .sum::<f64>()
}

fn refine(
    f: &impl Fn(f64) -> f64,
    (a, b): (f64, f64),
    whole: f64,
    tol: f64,
    budget: &std::cell::Cell<usize>,
) -> f64 {
    let m = 0.5 * (a + b);
    let (left, right) = (gauss(f, a, m), gauss(f, m, b));
    budget.set(budget.get().saturating_sub(16));
    let diff = left + right - whole;
    // Below the rounding of the sum itself no split can help; a non-finite value cannot
    // converge; a spent budget stops: never split 2^depth times.
    let floor = 64.0 * f64::EPSILON * (left.abs() + right.abs());
    if budget.get() == 0 || diff.abs() <= tol.max(floor) || !diff.is_finite() || m <= a || m >= b {
        return left + right;
    }
    refine(f, (a, m), left, tol / 2.0, budget) + refine(f, (m, b), right, tol / 2.0, budget)
}

/// The exact mean turning force over one revolution (kg): ∫ T dθ / 2π, split at every kink.
pub fn mean_turning_force(k: &Kinematics, cyls: &[Cylinder], eta: f64) -> f64 {
    turning_integral(k, cyls, eta, 0.0, 360.0, &cylinder_corners(k, cyls)) / 360.0
}

/// Each cylinder's kinks apart ([`turning_corners`] of that cylinder alone).
fn cylinder_corners(k: &Kinematics, cyls: &[Cylinder]) -> Vec<Vec<f64>> {
    cyls.iter()
        .map(|c| turning_corners(k, std::slice::from_ref(c)))
        .collect()
}

/// ∫ T dθ over [a, b] (kg·degrees), the sum of each cylinder's own integral, each split at
/// its own kinks: the sum of the engine's turning forces has the kinks of every cylinder, so
/// integrating it whole would evaluate every cylinder on every piece of every other (an
/// engine of 8 digitised cylinders, 64 times the work of one, not 8).
fn turning_integral(
    k: &Kinematics,
    cyls: &[Cylinder],
    eta: f64,
    a: f64,
    b: f64,
    corners: &[Vec<f64>],
) -> f64 {
    let each = cyls.iter().zip(corners).map(|(c, kinks)| {
        let t = |theta: f64| k.tangential(c, (theta + c.offset_deg).rem_euclid(360.0));
        integrate_split(t, a, b, kinks)
    });
    eta * each.sum::<f64>()
}

/// Where g changes sign between a < b (g(a) and g(b) given, of opposite signs; a zero
/// counts as positive), to within half of [`CROSSING_DEG_EPS`]: the ITP method (Oliveira and
/// Takahashi, 2020; interpolate, truncate, project), regula falsi pulled towards the midpoint
/// and kept within the bisection's worst case. A smooth crossing takes some 8 evaluations
/// of g, where bisection down to the last bit takes 60; a kink or a flat crossing (a
/// digitised indicator diagram's corner, a cubic touch) by the method's bound no more than
/// bisection to the same width and one (34 for a half-degree bracket), and two more at most
/// where rounding keeps the bracket from closing.
fn crossing(g: &impl Fn(f64) -> f64, (a, fa): (f64, f64), (b, fb): (f64, f64)) -> f64 {
    debug_assert!(a < b, "{a} {b}");
    // Oriented so that h < 0 at a and h > 0 at b.
    let s = if fa < 0.0 { 1.0 } else { -1.0 };
    let h = |x: f64| s * g(x);
    let (mut a, mut ya, mut b, mut yb) = (a, s * fa, b, s * fb);
    if ya == 0.0 {
        return a;
    }
    if yb == 0.0 {
        return b;
    }
    let eps = 0.5 * CROSSING_DEG_EPS;
    let k1 = 0.2 / (b - a);
    let n_max = ((b - a) / (2.0 * eps)).log2().ceil().max(0.0) as i32 + 1;
    let mut j = 0;
    while b - a > 2.0 * eps && j <= n_max + 1 {
        let mid = 0.5 * (a + b);
        let r = (eps * 2f64.powi(n_max - j) - 0.5 * (b - a)).max(0.0);
        let delta = k1 * (b - a) * (b - a);
        let falsi = (yb * a - ya * b) / (yb - ya);
        let truncated = if delta <= (mid - falsi).abs() && falsi.is_finite() {
            falsi + (mid - falsi).signum() * delta
        } else {
            mid
        };
        let x = if (truncated - mid).abs() <= r {
            truncated
        } else {
            mid - (mid - truncated).signum() * r
        };
        let y = h(x);
        if y > 0.0 {
            (b, yb) = (x, y);
        } else if y < 0.0 {
            (a, ya) = (x, y);
        } else {
            return x;
        }
        j += 1;
    }
    0.5 * (a + b)
}

/// The flywheel's energy curve E(θ) = ∫₀^θ (T − T_m) r dθ (m·kg, r in m) for the turning
/// force of the engine, exactly: its extremes lie where T crosses T_m, found by sampling every
/// half degree and closing in on each sign change by the ITP method, and E there by
/// [`integrate_split`]. Returns (ΔE = E_max − E_min, shaft angle of the largest speed, of the
/// smallest). A crossing pair closer than half a degree is not seen (its excess area is
/// below 1e-5 of the diagram's).
pub fn energy_extremes(k: &Kinematics, cyls: &[Cylinder], eta: f64, t_m: f64) -> (f64, f64, f64) {
    let g = |t: f64| turning_force(k, cyls, eta, t) - t_m;
    let mut roots = Vec::new();
    let n = 720;
    let mut prev = g(0.0);
    for i in 1..=n {
        let t1 = 360.0 * i as f64 / n as f64;
        let v = g(t1);
        if (prev < 0.0) != (v < 0.0) {
            roots.push(crossing(&g, (t1 - 360.0 / n as f64, prev), (t1, v)));
        }
        prev = v;
    }
    let corners = cylinder_corners(k, cyls);
    let r_m = k.r / 1000.0;
    let (mut e, mut from) = (0.0, 0.0);
    let (mut emax, mut emin, mut fast, mut slow) = (0.0f64, 0.0f64, 0.0, 0.0);
    for &t in &roots {
        let excess = turning_integral(k, cyls, eta, from, t, &corners) - t_m * (t - from);
        e += excess * r_m * std::f64::consts::PI / 180.0;
        from = t;
        if e > emax {
            emax = e;
            fast = t;
        }
        if e < emin {
            emin = e;
            slow = t;
        }
    }
    (emax - emin, fast, slow)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A digitised diagram: a working curve falling from `p` with a kink, a flat back curve.
    fn cylinder(name: &str, p: f64, offset_deg: f64, mass: f64) -> Cylinder {
        let n = 40;
        let working: Vec<(f64, f64)> = (0..=n)
            .map(|i| {
                let u = f64::from(i) / f64::from(n);
                (u, if u < 0.3 { p } else { p * 0.3 / u })
            })
            .collect();
        let side = |a: f64| Side {
            area_cm2: a,
            indicator: Indicator::Points {
                working: working.clone(),
                back: vec![(0.0, 1.2), (0.5, 1.0), (1.0, 1.1)],
            },
        };
        Cylinder {
            name: name.into(),
            cover: side(700.0),
            crank: side(650.0),
            mass,
            offset_deg,
            pump: None,
            card: None,
        }
    }

    #[test]
    fn cylinders_integrated_apart_sum_to_the_engine_integrated_whole() {
        let k = Kinematics {
            r: 300.0,
            lambda: 0.2,
            v: 4.0,
        };
        let cyls = [
            cylinder("1", 9.0, 0.0, 0.8),
            cylinder("2", 7.0, 90.0, 0.8),
            cylinder("3", 8.0, 233.0, 0.5),
        ];
        let eta = 0.85;
        let whole = |a: f64, b: f64| {
            let f = |t: f64| turning_force(&k, &cyls, eta, t);
            integrate_split(f, a, b, &turning_corners(&k, &cyls))
        };
        let t_m = mean_turning_force(&k, &cyls, eta);
        let reference = whole(0.0, 360.0) / 360.0;
        assert!(
            (t_m - reference).abs() <= 1e-11 * reference.abs(),
            "{t_m} {reference}"
        );
        // The flywheel's energy between the crossings, the same way.
        let corners = cylinder_corners(&k, &cyls);
        for (a, b) in [(0.0, 47.5), (47.5, 180.0), (12.25, 359.0)] {
            let apart = turning_integral(&k, &cyls, eta, a, b, &corners);
            let together = whole(a, b);
            assert!(
                (apart - together).abs() <= 1e-11 * 360.0 * t_m.abs(),
                "{apart} {together}"
            );
        }
        let (de, fast, slow) = energy_extremes(&k, &cyls, eta, t_m);
        assert!(de > 0.0 && (0.0..=360.0).contains(&fast) && (0.0..=360.0).contains(&slow));
    }

    /// The crossing is found where bisection to the last bit finds it, in few evaluations,
    /// for the hard shapes: a kink at the root, a root at an end, a flat root (cubic), a
    /// steep jump beside a flat run, values twenty orders of magnitude apart; never more
    /// than bisection to the same width and two.
    #[test]
    fn the_crossing_closes_in_where_bisection_does() {
        type Case<'a> = (&'a dyn Fn(f64) -> f64, f64, f64);
        let cases: [Case; 7] = [
            (&|x| (x - 0.3).sin(), 0.0, 0.5),
            (
                &|x| {
                    if x < 0.31 {
                        5.0 * (x - 0.31)
                    } else {
                        1e-3 * (x - 0.31)
                    }
                },
                0.0,
                0.5,
            ),
            (&|x| (x - 0.2).powi(3), 0.0, 0.5),
            (&|x| 1e10 * (x - 0.1).max(0.0) - 1e-10, 0.0, 0.5),
            (&|x| (x - 0.5).tanh(), 0.0, 0.5),
            (&|x| -(x - 359.75), 359.5, 360.0),
            (&|x| if x < 0.25 { -1e-300 } else { 7.0 }, 0.0, 0.5),
        ];
        for (g, a, b) in cases {
            let (fa, fb) = (g(a), g(b));
            let (mut lo, mut hi) = (a, b);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if (g(mid) < 0.0) == (fa < 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let calls = std::cell::Cell::new(0);
            let counted = |x: f64| {
                calls.set(calls.get() + 1);
                g(x)
            };
            let c = crossing(&counted, (a, fa), (b, fb));
            assert!((c - lo).abs() <= 0.5 * CROSSING_DEG_EPS, "{c} {lo}");
            assert!(calls.get() <= 36, "{} evaluations", calls.get());
        }
        // A smooth crossing takes a handful of evaluations, not bisection's 60.
        let calls = std::cell::Cell::new(0);
        let g = |x: f64| {
            calls.set(calls.get() + 1);
            (x - 0.3).sin() + 0.1 * (x - 0.3).powi(2)
        };
        crossing(&g, (0.0, g(0.0)), (0.5, g(0.5)));
        assert!(calls.get() <= 12, "{} evaluations", calls.get() - 2);
    }

    #[test]
    fn one_pass_gives_the_bits_of_both_rules() {
        let fs: [&dyn Fn(f64) -> f64; 5] = [
            &|x| x.sin() * 1e4 - 3.0,
            &|x| (x - 0.3).abs(),
            &|_| -0.0,
            &|x| if x < 0.5 { -1e-300 } else { 7.0 },
            &|x| 1.0 / (x + 1e-3),
        ];
        for f in fs {
            for (a, b) in [(0.0, 1.0), (0.25, 0.2500001), (-3.0, 360.0)] {
                let (whole, abs) = gauss_with_abs(&f, a, b);
                assert_eq!(whole.to_bits(), gauss(&f, a, b).to_bits());
                assert_eq!(abs.to_bits(), gauss(&|x| f(x).abs(), a, b).to_bits());
            }
        }
    }
}
