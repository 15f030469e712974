//! Combustion engines (KG XIV B.4, Abb. 1056-1060): the pressure in a
//! single-acting cylinder over its cycle from polytropic models, four-stroke over 720° of the
//! shaft or two-stroke over 360°, with combustion at constant volume (Verpuffung, Otto) or at
//! constant pressure (Selbstzündung, Diesel). The piston force is the gas pressure above the
//! atmosphere on the piston (the crank side stands open); with the inertia of the
//! reciprocating masses it gives the resulting force (KG Abb. 1058, 1060, curves a-a and b-b),
//! and the slider-crank turns it into the tangential force. Several cylinders fire evenly
//! spaced over the cycle in their firing order.
//!
//! The cycle angle α counts from the firing dead centre (the cover-side dead centre where the
//! working stroke begins): the working stroke takes α ∈ [0°, 180°); a four-stroke then
//! exhausts, draws in and compresses, a two-stroke compresses at once.

use super::model::{integrate_split, Kinematics};
use crate::crank::closed_form as cf;

mod construction;
mod indicator;
pub use construction::{construct, GasDrawing, GasEngine, GasResults, GasRow};

/// Four-stroke (a cycle of two turns) or two-stroke (one turn).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Strokes {
    /// Working, exhaust, intake and compression strokes: 720°.
    Four,
    /// Working and compression strokes, scavenged by a pump: 360°.
    Two,
}

impl Strokes {
    /// The cycle in shaft degrees.
    pub fn cycle_deg(self) -> f64 {
        match self {
            Strokes::Four => 720.0,
            Strokes::Two => 360.0,
        }
    }
}

/// How the charge burns at the firing dead centre.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Combustion {
    /// At constant volume: the pressure jumps to the peak at the dead centre (KG Abb. 1056,
    /// "Verpuffung"; peaks of about 25 at).
    ConstantVolume,
    /// At constant pressure: the peak held while fuel is injected, to this fraction of the
    /// stroke (KG Abb. 1057, 1059, "Selbstzündung"; 30-35 at).
    ConstantPressure {
        /// End of injection, fraction of the stroke (0 < cut-off < release).
        cutoff: f64,
    },
}

/// The gas cycle of one cylinder; pressures absolute (at), fractions of the stroke.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct GasCycle {
    /// Four- or two-stroke.
    pub strokes: Strokes,
    /// Constant volume or constant pressure.
    pub combustion: Combustion,
    /// Compression ratio ε = (V_s + V_c)/V_c (> 1).
    pub compression_ratio: f64,
    /// Pressure at the start of compression: the intake's (four-stroke) or the scavenging
    /// air's (two-stroke), at abs.
    pub charge_at: f64,
    /// Peak pressure after combustion (at abs), not below the compression's end pressure.
    pub peak_at: f64,
    /// Polytropic exponent of compression.
    pub n_compression: f64,
    /// Polytropic exponent of expansion.
    pub n_expansion: f64,
    /// The exhaust opens at this fraction of the working stroke; the pressure falls
    /// straight to the exhaust's (two-stroke: the charge's) at the outer dead centre.
    pub release: f64,
    /// Exhaust back pressure (four-stroke, at abs).
    pub exhaust_at: f64,
}

/// The atmosphere on the open crank side (at).
pub const ATMOSPHERE_AT: f64 = 1.0;

impl GasCycle {
    /// V/V_s at the piston position u (fraction of the stroke from the cover-side dead centre).
    fn volume(&self, u: f64) -> f64 {
        1.0 / (self.compression_ratio - 1.0) + u
    }

    /// The compression's end pressure p_c = p_charge·ε^n₁ (at abs).
    pub fn compression_end(&self) -> f64 {
        self.charge_at * self.compression_ratio.powf(self.n_compression)
    }

    /// The pressure while compressing, at u.
    fn compressing(&self, u: f64) -> f64 {
        self.charge_at * (self.volume(1.0) / self.volume(u)).powf(self.n_compression)
    }

    /// The volume where expansion starts (V/V_s) and the pressure there.
    fn expansion_start(&self) -> (f64, f64) {
        let start = match self.combustion {
            Combustion::ConstantVolume => 0.0,
            Combustion::ConstantPressure { cutoff } => cutoff,
        };
        (self.volume(start), self.peak_at)
    }

    /// The pressure on the working stroke at u: peak, expansion, release.
    pub fn working(&self, u: f64) -> f64 {
        if let Combustion::ConstantPressure { cutoff } = self.combustion {
            if u <= cutoff {
                return self.peak_at;
            }
        }
        let (v0, p0) = self.expansion_start();
        let expand = |u: f64| p0 * (v0 / self.volume(u)).powf(self.n_expansion);
        if u <= self.release {
            expand(u)
        } else {
            let end = self.after_release();
            let t = (u - self.release) / (1.0 - self.release);
            expand(self.release) + t * (end - expand(self.release))
        }
    }

    /// Where the release line ends at the outer dead centre.
    fn after_release(&self) -> f64 {
        match self.strokes {
            Strokes::Four => self.exhaust_at,
            Strokes::Two => self.charge_at,
        }
    }

    /// The absolute pressure at the cycle angle α (degrees from the firing dead centre), with
    /// u the piston position there.
    pub fn pressure(&self, alpha: f64, u: f64) -> f64 {
        let a = alpha.rem_euclid(self.strokes.cycle_deg());
        match (self.strokes, (a / 180.0) as u32) {
            (_, 0) => self.working(u),
            (Strokes::Four, 1) => self.exhaust_at,
            (Strokes::Four, 2) => self.charge_at,
            _ => self.compressing(u),
        }
    }

    /// The mean indicated pressure over the swept volume (at): the cycle's work per cm² of
    /// piston and m... per unit of stroke, by the closed integrals of the polytropes (the
    /// atmosphere on the crank side does no net work).
    pub fn mean_indicated(&self) -> f64 {
        let (v0, p0) = self.expansion_start();
        let poly = |p: f64, v: f64, n: f64, a: f64, b: f64| {
            // ∫ p (v/V)^n dV from V = a to b.
            if (n - 1.0).abs() < 1e-12 {
                p * v * (b / a).ln()
            } else {
                p * v.powf(n) * (b.powf(1.0 - n) - a.powf(1.0 - n)) / (1.0 - n)
            }
        };
        let vr = self.volume(self.release);
        let mut work = poly(p0, v0, self.n_expansion, v0, vr);
        let pr = self.working(self.release);
        work += 0.5 * (pr + self.after_release()) * (1.0 - self.release);
        if let Combustion::ConstantPressure { cutoff } = self.combustion {
            work += self.peak_at * cutoff;
        }
        let (vc, vb) = (self.volume(0.0), self.volume(1.0));
        work -= poly(self.charge_at, vb, self.n_compression, vc, vb);
        if self.strokes == Strokes::Four {
            work -= self.exhaust_at - self.charge_at;
        }
        work
    }

    /// The fractions of the stroke where the working-stroke curve has a corner.
    pub fn corners(&self) -> Vec<f64> {
        let mut out = vec![self.release];
        if let Combustion::ConstantPressure { cutoff } = self.combustion {
            out.push(cutoff);
        }
        out
    }
}

/// One single-acting cylinder of a combustion engine.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GasCylinder {
    /// Its name in the figure.
    pub name: String,
    /// Piston area (cm²).
    pub area_cm2: f64,
    /// Its gas cycle.
    pub cycle: GasCycle,
    /// Reciprocating mass M = G/g (kg·s²/m); 0 without the effect `inertia`.
    pub mass: f64,
    /// The shaft angle at which it fires (degrees in [0, cycle)).
    pub fires_at: f64,
}

impl GasCylinder {
    /// Its cycle angle and crank angle (from its cover-side dead centre) at the shaft angle.
    pub fn angles(&self, shaft: f64) -> (f64, f64) {
        let alpha = (shaft - self.fires_at).rem_euclid(self.cycle.strokes.cycle_deg());
        (alpha, alpha.rem_euclid(360.0))
    }

    /// The driving piston force from the gas (kg): the pressure above the atmosphere on the
    /// piston, positive when it pushes the piston the way it moves (KG Abb. 1058 a-a).
    pub fn gas_force(&self, k: &Kinematics, shaft: f64) -> f64 {
        let (alpha, theta) = self.angles(shaft);
        let u = k.x_frac(theta);
        let push = self.area_cm2 * (self.cycle.pressure(alpha, u) - ATMOSPHERE_AT);
        let (stroke, _) = cf::book_angle(theta);
        stroke.sign() * push
    }

    /// The resulting force with the masses' inertia (KG Abb. 1058 b-b).
    pub fn resulting(&self, k: &Kinematics, shaft: f64) -> f64 {
        let (_, theta) = self.angles(shaft);
        self.gas_force(k, shaft) - k.inertia(self.mass, theta)
    }

    /// The tangential force at the shaft angle (KG 303).
    pub fn tangential(&self, k: &Kinematics, shaft: f64) -> f64 {
        let (_, theta) = self.angles(shaft);
        cf::tangential_force(self.resulting(k, shaft), k.lambda, theta)
    }

    /// The shaft angles where its force has a corner or a jump (dead centres, cut-off,
    /// release).
    fn kinks(&self, k: &Kinematics) -> Vec<f64> {
        let cycle = self.cycle.strokes.cycle_deg();
        let mut out: Vec<f64> = (0..(cycle / 180.0) as u32)
            .map(|i| 180.0 * i as f64)
            .collect();
        for u in self.cycle.corners() {
            out.push(cf::crank_angle_at(k.r, k.rod(), u * 2.0 * k.r));
        }
        out.into_iter()
            .map(|a| (a + self.fires_at).rem_euclid(cycle))
            .collect()
    }
}

/// The turning force of all cylinders at the shaft angle (kg).
pub fn turning_force(k: &Kinematics, cyls: &[GasCylinder], shaft: f64) -> f64 {
    cyls.iter().map(|c| c.tangential(k, shaft)).sum()
}

/// The exact mean turning force over the cycle (kg), split at every kink.
pub fn mean_turning_force(k: &Kinematics, cyls: &[GasCylinder], cycle: f64) -> f64 {
    let mut corners: Vec<f64> = cyls.iter().flat_map(|c| c.kinks(k)).collect();
    corners.sort_by(f64::total_cmp);
    corners.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    integrate_split(|t| turning_force(k, cyls, t), 0.0, cycle, &corners) / cycle
}

/// The mean turning force the indicated work calls for: Σ p_mi·F·s over the cycle's path of
/// the crank pin (2πR per turn); the masses do no net work.
pub fn mean_from_work(k: &Kinematics, cyls: &[GasCylinder], cycle: f64) -> f64 {
    let turns = cycle / 360.0;
    let work: f64 = cyls
        .iter()
        .map(|c| c.cycle.mean_indicated() * c.area_cm2 * 2.0 * k.r)
        .sum();
    work / (turns * 2.0 * std::f64::consts::PI * k.r)
}
