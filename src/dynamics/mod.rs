//! The crank drive's dynamics (LH II A, C-J; KG XIV B.4): indicator diagrams reduced to piston
//! forces, the net pressure of a double-acting cylinder, the inertia of the reciprocating
//! masses by Tolle's parabola at force scale, the resulting net-pressure curve, the tangential
//! force on every crank ray, the turning-force diagram of several cylinders on one shaft, its
//! mean height by the books' rules, the indicated power both ways, and the flywheel.
//!
//! # What is constructed and what is reckoned
//! Every ordinate the books draw is drawn: the net pressure by laying off the working side's
//! force and the back side's against it (LH Abb. 58), the inertia force on Tolle's parabola,
//! the resulting force by transferring the inertia ordinate, the tangential force by the polar
//! construction of [`crate::crank`], and the turning force by adding the cylinders' ordinates
//! over the developed crank circle. Each is checked against [`model`]. The mean heights are
//! the books' rules applied to the drawn ordinates; the exact integrals of [`model`] are what
//! they are measured against.
//!
//! ```
//! use graphostatik::dynamics::{model::*, *};
//! // One cylinder with a constant net pressure: the work over a revolution is the same
//! // whether read from the indicator (P_m) or from the turning force (T_m): P_m/T_m = π/2
//! // (LH Gl. 70).
//! let side = |p| Side { area_cm2: 100.0, indicator: Indicator::Points {
//!     working: vec![(0.0, p), (1.0, p)], back: vec![(0.0, 1.0), (1.0, 1.0)] } };
//! let cyl = Cylinder { name: "1".into(), cover: side(5.0), crank: side(5.0), mass: 0.0,
//!     offset_deg: 0.0, pump: None, card: None };
//! let k = Kinematics { r: 300.0, lambda: 0.2, v: 5.0 };
//! let t_m = mean_turning_force(&k, &[cyl], 1.0);
//! let p_m = 100.0 * (5.0 - 1.0);
//! assert!((p_m / t_m - std::f64::consts::PI / 2.0).abs() < 1e-9);
//! ```

pub mod combustion;
mod construction;
pub mod model;
pub mod rules;

pub use construction::construct;

/// The crank angle written under a developed diagram's base line every `every` degrees up to
/// `until` (0° excluded: the diagram's start is lettered of its own), at `mm_per_deg` from
/// `start` to the right: the scale of crank angles the plates write under their abscissa.
pub(crate) fn angle_marks(
    b: &mut crate::protocol::Board,
    start: crate::kernel::Point,
    (mm_per_deg, every, until): (f64, f64, f64),
    note: crate::protocol::Note,
) {
    if !b.is_recording() || every <= 0.0 {
        return;
    }
    let count = (until / every).floor() as usize;
    for k in 1..=count.min(24) {
        let deg = every * k as f64;
        let at = crate::kernel::Point::new(start.x + deg * mm_per_deg, start.y);
        let name = crate::protocol::Label::named(format!("{}°", crate::fmt::num(deg, 3)));
        b.point(at, crate::protocol::Role::Axis.labelled(name), note.clone());
    }
}
use model::{Cylinder, Kinematics};
use serde::Serialize;

/// An engine: the crank drive, its cylinders on one shaft, efficiency and flywheel data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Engine {
    /// Crank radius, rod ratio and crank-pin speed.
    pub kinematics: Kinematics,
    /// The cylinders, the first one's crank at offset 0.
    pub cylinders: Vec<Cylinder>,
    /// Mechanical efficiency η scaling the turning force (KG Abb. 1062); 1 without the effect.
    pub efficiency: f64,
    /// Degree of irregularity δ = (ω_max − ω_min)/ω_m asked of the flywheel.
    pub irregularity: Option<f64>,
}

/// Scales of the drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DynamicsDrawing {
    /// Machine mm per mm of sheet for the stroke and the crank circle.
    pub length_scale: f64,
    /// kg per mm of sheet (LH: 1 mm = 900 kg).
    pub force_scale: f64,
}

crate::protocol::request_set! {
    /// What a dynamics scene constructs (its `outputs`); each pulls in only what it needs.
    pub struct DynamicsRequest as "DynamicsOutput" {
        /// Each cylinder's indicator card reduced: 11 ordinates, the new length, the new
        /// spring scale, the piston forces by the reduction factor (LH A, Abb. 42-45).
        reduction,
        /// Net pressure, inertia and resulting curves (LH Abb. 58; KG Abb. 1055).
        net_pressure,
        /// The net piston force by the mean piston area F = (F′+F″)/2 on every ray, beside
        /// the net pressure's own, and the effective areas read back (KG 296-297, Abb. 1054).
        mean_area,
        /// Tangential force on every ray and the turning-force diagram (LH Abb. 67; KG Abb. 1064).
        turning_force,
        /// Mean height of the turning-force diagram by every rule (LH G).
        mean_height,
        /// Indicated power from the mean pressures and from T_m (LH H).
        power,
        /// The flywheel (LH J; KG Abb. 1062).
        flywheel,
        /// With the effect `pump`: the pumps' resistance line T_p, their rectangles carried
        /// through a crank figure of their own, beside the steam engine's turning force
        /// T_s = T + T_p over the developed crank circle (KG Abb. 1067).
        resistance_line,
    }
}

/// One crank ray of one cylinder.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RayRow {
    /// Shaft angle θ (degrees).
    pub shaft_deg: f64,
    /// The cylinder's crank angle θ + offset (degrees).
    pub crank_deg: f64,
    /// Net pressure force P from the indicator diagrams (kg), driving positive.
    pub pressure_force: f64,
    /// Inertia force M·b (kg), in the direction of motion.
    pub inertia: f64,
    /// Resulting force P − M·b (kg).
    pub resulting: f64,
    /// Tangential force T (kg), where constructed.
    pub tangential: Option<f64>,
}

/// A mean height by one rule, as T_m (kg), against the exact mean.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeanHeight {
    /// The rule ("trapezoid", "Simpson", …).
    pub rule: String,
    /// T_m by the rule (kg).
    pub t_m: f64,
    /// Its error against the exact mean (kg).
    pub error: f64,
}

/// KG (297) against (296) for one cylinder: the net piston force by the mean piston area.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeanArea {
    /// The cover side's effective area F′ (cm²).
    pub cover_cm2: f64,
    /// The crank side's effective area F″ (cm²).
    pub crank_cm2: f64,
    /// Their mean F = (F′+F″)/2 (cm²).
    pub mean_cm2: f64,
    /// The largest F·p_ü − P over the drawn rays (kg), P the steam's force by (296).
    pub difference: f64,
    /// The crank angle where it is largest (degrees).
    pub at_deg: f64,
    /// That difference over the largest |P| of the rays.
    pub relative: f64,
}

/// The indicated power.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Power {
    /// Per cylinder from its mean pressures (PS, LH Gl. 68), times η.
    pub from_pressures: Vec<f64>,
    /// The whole engine from the exact T_m (PS, LH Gl. 69).
    pub from_t_m: f64,
    /// From T_m by the trapezoid rule over the drawn ordinates (PS).
    pub from_drawn_t_m: f64,
}

/// The flywheel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Flywheel {
    /// Mean resistance T_m (kg) at the crank pin.
    pub resistance: f64,
    /// The largest fluctuation of energy ΔE (m·kg), from the drawn ordinates.
    pub delta_e: f64,
    /// ΔE of the exact turning force's continuous energy curve (m·kg): what the ordinates
    /// approach as the divisions grow.
    pub delta_e_exact: f64,
    /// Shaft angle of the largest speed (degrees).
    pub fastest_deg: f64,
    /// Shaft angle of the smallest speed (degrees).
    pub slowest_deg: f64,
    /// The flywheel's moment of inertia J = ΔE/(δ ω²) (kg·m·s²), where δ is given.
    pub moment_of_inertia: Option<f64>,
}

/// The results of [`construct`].
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct DynamicsResults {
    /// Per cylinder, per ray.
    pub rays: Vec<Vec<RayRow>>,
    /// The turning force at each shaft angle (kg).
    pub turning: Vec<(f64, f64)>,
    /// The ordinates of the turning force as read on the board, in the order of `turning`:
    /// the mean heights are reckoned from them, their error bounds with them.
    #[serde(skip)]
    pub turning_ids: Vec<crate::protocol::ObjId>,
    /// Per cylinder, KG (297) against (296), where asked for.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub mean_area: Vec<MeanArea>,
    /// The exact mean turning force (kg).
    pub t_m_exact: Option<f64>,
    /// Mean heights by rule.
    pub mean_heights: Vec<MeanHeight>,
    /// Power.
    pub power: Option<Power>,
    /// Flywheel.
    pub flywheel: Option<Flywheel>,
    /// The pumps' resistance line and the steam engine's turning force (KG Abb. 1067).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resistance: Option<Resistance>,
}

/// The pumps' resistance line beside the power engine's own turning force (KG Abb. 1067).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Resistance {
    /// Per shaft angle θ (degrees): the pumps' resistance T_p and the steam engine's
    /// turning force T_s = T + T_p (kg), as read off the diagram.
    pub ordinates: Vec<(f64, f64, f64)>,
    /// The mean resistance by the trapezoid rule over the drawn ordinates (kg).
    pub mean: f64,
    /// The exact mean resistance, Σ (P_p1 + P_p2)/π (kg).
    pub mean_exact: f64,
}

/// PS in m·kg/s (LH Gl. 63).
pub const PS: f64 = 75.0;

impl Engine {
    /// The exact mean turning force (kg).
    pub fn t_m(&self) -> f64 {
        model::mean_turning_force(&self.kinematics, &self.cylinders, self.efficiency)
    }

    /// The stroke s (m) and the revolutions per minute n = 60·v/(2πr).
    pub fn stroke_and_rpm(&self) -> (f64, f64) {
        let k = &self.kinematics;
        (2.0 * k.r / 1000.0, model::revolutions_per_minute(k.v, k.r))
    }

    /// Indicated power of each cylinder from its exact mean pressures (LH Gl. 68), times η:
    /// (F_D p_m^D + F_K p_m^K) s n / (75 · 60).
    pub fn power_from_pressures(&self) -> Vec<f64> {
        let (s, n) = self.stroke_and_rpm();
        self.cylinders
            .iter()
            .map(|c| {
                let sides = [
                    (c.cover.area_cm2, c.cover.indicator.mean_pressure()),
                    (c.crank.area_cm2, c.crank.indicator.mean_pressure()),
                ];
                self.efficiency * model::indicated_power(sides, s, n)
            })
            .collect()
    }
}
