//! The crank-dynamics scene (LH II A, C-J; KG XIV B.4): an engine of one or more
//! double-acting cylinders on one shaft, its indicator diagrams digitised or modelled, and
//! what to construct from them.

use super::defaults::nice_at_least;
use super::error::SceneError;
use super::fields::{optional_positive, Fields};
use super::procedure::{Procedure, ReadContext};
use super::sweep::{one, timed_drawing, Setting};
use super::{Mechanism, Speed};
use crate::crank::Angles;
use crate::dynamics::model::{self, area_cm2, Cylinder, Indicator, Kinematics, Side, SteamModel};
use crate::dynamics::{self, DynamicsDrawing, DynamicsRequest, DynamicsResults, Engine};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// An engine's dynamics: `"procedure": "crank_dynamics"`.
    pub struct DynamicsScene {
        /// The crank drive every cylinder works on (one crank radius for the shaft).
        pub mechanism: Mechanism,
        /// How fast the shaft turns.
        pub speed: Speed,
        /// The cylinders, in the order of their cranks; the first one's crank at 0°.
        pub cylinders: Vec<CylinderSpec>,
        /// Equal divisions of the crank circle (the crank rays), 2 to 3600; or give
        /// `stroke_parts`.
        #[serde(default)]
        pub divisions: Option<usize>,
        /// Each cylinder's stroke in n equal parts (LH: 10), its crank rays by arcs with the
        /// rod length (LH C.2, Abb. 59): 2n rays a cylinder, 1 ≤ n ≤ 1800. The turning-force
        /// diagram stands on every cylinder's abscissae, each one's ordinate taken off the
        /// others' drawn curves (LH F, Abb. 67). The first cylinder's crank offset must be 0.
        #[serde(default)]
        pub stroke_parts: Option<usize>,
        /// The physical effects to include; only these are computed.
        #[serde(default)]
        pub effects: Option<DynamicsEffects>,
        /// What the flywheel must achieve.
        #[serde(default)]
        pub flywheel: Option<FlywheelSpec>,
        /// What to construct, at least one output (`DynamicsOutput` lists them); each pulls
        /// in only what it needs.
        pub outputs: DynamicsRequest,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<DynamicsDrawingSpec>,
    }
}

/// One double-acting cylinder.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CylinderSpec {
    /// Name written in the figure ("right", "HP").
    pub name: String,
    /// Bore D (mm).
    pub bore_mm: f64,
    /// Piston rod through the crank side (mm).
    #[serde(default)]
    pub rod_crank_side_mm: f64,
    /// Tail rod through the cover side (mm).
    #[serde(default)]
    pub rod_cover_side_mm: f64,
    /// The cylinder's stroke if stated (mm): it must be the mechanism's, one crank radius on
    /// one shaft.
    #[serde(default)]
    pub stroke_mm: Option<f64>,
    /// How far its crank leads the first cylinder's (degrees; 90 for a locomotive's second
    /// cylinder, 180 for a compound engine's).
    #[serde(default)]
    pub crank_offset_deg: f64,
    /// Its indicator diagrams.
    pub indicator: IndicatorSpec,
    /// The reciprocating masses; used with the effect `inertia`.
    #[serde(default)]
    pub masses: Option<MassSpec>,
    /// A double-acting pump on the same piston rod (KG Abb. 1053); used with the effect
    /// `pump`.
    #[serde(default)]
    pub pump: Option<PumpSpec>,
    /// The indicator card as the indicator drew it; used with the output `reduction`.
    #[serde(default)]
    pub card: Option<CardSpec>,
}

/// An indicator card as the indicator drew it (LH A, Abb. 42): the output `reduction`
/// divides it into 10 strips, redraws it over the drawing's stroke (at `respring_mm_per_at`
/// where given, Abb. 44) and turns it into piston forces at the force scale (Abb. 45).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CardSpec {
    /// The card's length l (mm; LH: 30).
    pub length_mm: f64,
    /// Its spring scale f: mm for 1 at (LH: 1.5).
    pub spring_mm_per_at: f64,
    /// The spring scale f′ it is redrawn at over the new length (mm for 1 at; LH Abb. 44:
    /// 2.5); absent: the card goes straight to piston forces.
    #[serde(default)]
    pub respring_mm_per_at: Option<f64>,
}

/// A double-acting plunger pump driven by the piston rod (KG Abb. 1053, 1065).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PumpSpec {
    /// Plunger diameter d (mm).
    pub plunger_mm: f64,
    /// Diameter of the rod at the plunger's front end (mm).
    #[serde(default)]
    pub rod_mm: f64,
    /// Suction: the underpressure p_s below the atmosphere (at; at most 1, absolute zero).
    pub suction_at: f64,
    /// Delivery pressure p_a (at, gauge).
    pub delivery_at: f64,
}

/// The indicator diagrams of a cylinder: digitised per side, or a steam distribution for
/// both sides.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum IndicatorSpec {
    /// Digitised diagrams.
    #[serde(rename = "points")]
    Points(PointsSpec),
    /// A modelled steam distribution, the same on both sides.
    #[serde(rename = "steam")]
    Steam(SteamSpec),
}

/// Digitised diagrams of both sides.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PointsSpec {
    /// Cover side (Deckelseite).
    pub cover: SidePoints,
    /// Crank side (Kurbelseite).
    pub crank: SidePoints,
    /// Pressures are gauge (at über), not absolute: 1 at is added (LH A: 1 at abs = 0 at übd).
    #[serde(default)]
    pub gauge: bool,
}

/// One side's diagram as points [x_mm, p_at], x from the dead centre where this side's working
/// stroke begins, rising to the stroke.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SidePoints {
    /// The working stroke (the side's volume grows).
    pub working: Vec<[f64; 2]>,
    /// The back stroke (its volume shrinks).
    pub back: Vec<[f64; 2]>,
}

/// A steam distribution (LH Abb. 40).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SteamSpec {
    /// Admission pressure (at).
    pub admission_at: f64,
    /// Cut-off as a fraction of the stroke.
    pub cutoff: f64,
    /// Release as a fraction of the stroke (default 0.95).
    #[serde(default)]
    pub release: Option<f64>,
    /// Exponent n of pV^n = const (default 1, Mariotte).
    #[serde(default)]
    pub exponent: Option<f64>,
    /// Back pressure (at).
    pub back_at: f64,
    /// Compression begins when this fraction of the stroke is left (default 0).
    #[serde(default)]
    pub compression: Option<f64>,
    /// Clearance volume as a fraction of the swept volume (default 0.05).
    #[serde(default)]
    pub clearance: Option<f64>,
    /// Pressures are gauge (at über): 1 at is added.
    #[serde(default)]
    pub gauge: bool,
}

/// The reciprocating masses.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum MassSpec {
    /// Part weights (kg): G = piston + piston rod + crosshead + others + the share of the
    /// connecting rod (`effects.rod_mass_share`).
    #[serde(rename = "weights_kg")]
    Weights(Weights),
    /// Radinger's specific weight q (kg per cm² of piston area; LH B.4: 0.28 without, 0.33
    /// with condensation, 0.41 for combustion engines), on the area of `bore_mm` (default the
    /// cylinder's own; a compound engine takes the low-pressure cylinder's).
    #[serde(rename = "radinger")]
    Radinger {
        /// q (kg/cm²).
        q_kg_per_cm2: f64,
        /// The bore whose area q refers to (mm).
        #[serde(default)]
        bore_mm: Option<f64>,
    },
}

/// Part weights in kg.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Weights {
    /// Piston.
    pub piston: f64,
    /// Piston rod.
    pub piston_rod: f64,
    /// Crosshead.
    pub crosshead: f64,
    /// Connecting rod (its share counts as reciprocating).
    pub connecting_rod: f64,
    /// Anything else moving with the piston (a pump plunger).
    #[serde(default)]
    pub other: f64,
}

/// The effects a dynamics scene can include.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct DynamicsEffects {
    /// Inertia of the reciprocating masses (each cylinder's `masses`).
    #[serde(default)]
    pub inertia: bool,
    /// The share of the connecting rod's weight that reciprocates (default 2/3, LH B.4; KG
    /// gives 1/2 to 2/3).
    #[serde(default)]
    pub rod_mass_share: Option<f64>,
    /// Mechanical efficiency η scaling the turning force (default 1; KG: 0.85-0.92).
    #[serde(default)]
    pub efficiency: Option<f64>,
    /// Finite rod length (default true).
    #[serde(default)]
    pub finite_rod: Option<bool>,
    /// The cylinders' pumps (each cylinder's `pump`): their force rectangles laid against
    /// the steam force, which the efficiency then reduces instead of the turning force
    /// (KG Abb. 1065).
    #[serde(default)]
    pub pump: bool,
}

/// The flywheel's task.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct FlywheelSpec {
    /// Degree of irregularity δ = (ω_max − ω_min)/ω_m (e.g. 1/50).
    pub irregularity: f64,
}

/// Scales of a dynamics drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct DynamicsDrawingSpec {
    /// Length scale 1 : n for the stroke and the crank circle.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm (LH: 900).
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
}

/// A validated dynamics scene.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The engine.
    pub engine: Engine,
    /// Scales.
    pub drawing: DynamicsDrawing,
    /// Crank rays.
    pub rays: crate::crank::Angles,
    /// What to construct.
    pub request: DynamicsRequest,
}

mod validate;

impl DynamicsScene {
    /// The problem the (validated) scene describes.
    fn to_problem(&self) -> DynamicsProblem {
        let r = self.mechanism.radius();
        let eff = self.effects.unwrap_or_default();
        let finite = eff.finite_rod.unwrap_or(true);
        let kinematics = Kinematics {
            r,
            lambda: if finite {
                r / self.mechanism.rod_length()
            } else {
                0.0
            },
            v: self.speed.crank_pin_speed(r),
        };
        let share = eff.rod_mass_share.unwrap_or(2.0 / 3.0);
        let cylinders = self
            .cylinders
            .iter()
            .map(|c| cylinder(c, (eff.inertia, share), 2.0 * r, pump_eta(&eff)))
            .collect();
        let engine = Engine {
            kinematics,
            cylinders,
            // With pumps, η reduces the steam force before the pump's is laid over it.
            efficiency: if eff.pump {
                1.0
            } else {
                eff.efficiency.unwrap_or(1.0)
            },
            irregularity: self.flywheel.map(|f| f.irregularity),
        };
        let d = self.drawing.unwrap_or(DynamicsDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
        });
        let fmax = engine
            .cylinders
            .iter()
            .map(|c| largest_force(&engine.kinematics, c))
            .fold(0.0, f64::max);
        // The force scale follows the forces at any size (a floor of 1 kg once laid a
        // diagram of micro-engine forces out at a scale for kilograms); an engine that draws no
        // force at all takes 1 kg.
        let fmax = if fmax > 0.0 { fmax } else { 1.0 };
        let drawing = DynamicsDrawing {
            length_scale: d
                .length_scale
                .unwrap_or_else(|| nice_at_least(2.0 * r / 60.0)),
            force_scale: d
                .force_scale_kg_per_mm
                .unwrap_or_else(|| nice_at_least(fmax / 25.0)),
        };
        DynamicsProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            engine,
            drawing,
            rays: match (self.divisions, self.stroke_parts) {
                (_, Some(n)) => crate::crank::Angles::StrokeParts(n),
                (n, None) => crate::crank::Angles::Divisions(n.unwrap_or(2)),
            },
            request: self.outputs,
        }
    }
}

/// The largest force a cylinder's diagrams draw (kg): pressure or inertia.
fn largest_force(k: &Kinematics, c: &Cylinder) -> f64 {
    let p = c.cover.area_cm2.max(c.crank.area_cm2)
        * peak(&c.cover.indicator).max(peak(&c.crank.indicator));
    // The pump's rectangle is drawn at the same scale (at 5,400 at delivery it made a sheet
    // of 35 m, at 4.3e9 at the construction never ended).
    let pump = c.pump.map_or(0.0, |p| p.largest_force());
    p.max(c.mass * k.a() * (1.0 + k.lambda)).max(pump)
}

/// The largest pressure of a diagram (at), for choosing a scale.
fn peak(ind: &Indicator) -> f64 {
    (0..=20)
        .map(|k| ind.working(k as f64 / 20.0).max(ind.back(k as f64 / 20.0)))
        .fold(0.0, f64::max)
}

/// The steam side's efficiency with the effect `pump` (None without it).
fn pump_eta(eff: &DynamicsEffects) -> Option<f64> {
    eff.pump.then(|| eff.efficiency.unwrap_or(1.0))
}

/// A cylinder in machine units: areas (cm²), absolute pressures, mass (kg·s²/m), and its
/// pump with the effect (`eta` the steam side's efficiency).
fn cylinder(
    c: &CylinderSpec,
    (inertia, share): (bool, f64),
    stroke: f64,
    eta: Option<f64>,
) -> Cylinder {
    let (cover, crank) = match &c.indicator {
        IndicatorSpec::Steam(s) => {
            let m = Indicator::Steam(steam(s));
            (m.clone(), m)
        }
        IndicatorSpec::Points(p) => (
            points(&p.cover, p.gauge, stroke),
            points(&p.crank, p.gauge, stroke),
        ),
    };
    let mass = if inertia {
        match c.masses {
            Some(MassSpec::Weights(w)) => {
                (w.piston + w.piston_rod + w.crosshead + w.other + share * w.connecting_rod)
                    / model::G
            }
            Some(MassSpec::Radinger {
                q_kg_per_cm2,
                bore_mm,
            }) => q_kg_per_cm2 * area_cm2(bore_mm.unwrap_or(c.bore_mm), 0.0) / model::G,
            None => 0.0,
        }
    } else {
        0.0
    };
    Cylinder {
        name: c.name.clone(),
        cover: Side {
            area_cm2: area_cm2(c.bore_mm, c.rod_cover_side_mm),
            indicator: cover,
        },
        crank: Side {
            area_cm2: area_cm2(c.bore_mm, c.rod_crank_side_mm),
            indicator: crank,
        },
        mass,
        offset_deg: c.crank_offset_deg,
        card: c.card.map(|k| model::IndicatorCard {
            length_mm: k.length_mm,
            spring_mm_per_at: k.spring_mm_per_at,
            respring_mm_per_at: k.respring_mm_per_at,
        }),
        pump: eta.and_then(|efficiency| {
            c.pump.map(|p| model::Pump {
                plunger_cm2: area_cm2(p.plunger_mm, 0.0),
                rod_cm2: area_cm2(p.rod_mm, 0.0),
                suction_at: p.suction_at,
                delivery_at: p.delivery_at,
                efficiency,
            })
        }),
    }
}

fn steam(s: &SteamSpec) -> SteamModel {
    let add = if s.gauge { 1.0 } else { 0.0 };
    SteamModel {
        admission: s.admission_at + add,
        cutoff: s.cutoff,
        exponent: s.exponent.unwrap_or(1.0),
        release: s.release.unwrap_or(0.95),
        back: s.back_at + add,
        compression: s.compression.unwrap_or(0.0),
        clearance: s.clearance.unwrap_or(0.05),
    }
}

fn points(s: &SidePoints, gauge: bool, stroke: f64) -> Indicator {
    let add = if gauge { 1.0 } else { 0.0 };
    let conv = |v: &Vec<[f64; 2]>| v.iter().map(|p| (p[0] / stroke, p[1] + add)).collect();
    Indicator::Points {
        working: conv(&s.working),
        back: conv(&s.back),
    }
}

impl super::Procedure for DynamicsScene {
    const NAME: &'static str = "crank_dynamics";
    const SIZED_BY: &'static str = "divisions, cylinders, outputs or digitised points";
    const ABOUT: &'static str = "an engine's dynamics: net pressure, inertia, turning force, mean heights, power, flywheel (LH II A, C-J; KG XIV B.4)";
    const OUTPUTS: &'static [&'static str] = DynamicsRequest::NAMES;
    const GEOMETRY_FIELD: &'static str = "mechanism";

    fn sheet_extent(p: &DynamicsProblem) -> (f64, &'static str) {
        let k = &p.engine.kinematics;
        let l = k.rod().unwrap_or(5.0 * k.r);
        let length = (4.0 * k.r + l) / p.drawing.length_scale * 2.0;
        let force = p
            .engine
            .cylinders
            .iter()
            .map(|c| 3.0 * largest_force(k, c))
            .sum::<f64>()
            / p.drawing.force_scale;
        super::fields::larger(length, force)
    }
    fn smallest_part(p: &DynamicsProblem) -> Option<(f64, &'static str)> {
        let k = &p.engine.kinematics;
        let force = p
            .engine
            .cylinders
            .iter()
            .map(|c| largest_force(k, c))
            .fold(0.0, f64::max);
        (force > 0.0).then(|| {
            (
                force / p.drawing.force_scale,
                "drawing.force_scale_kg_per_mm",
            )
        })
    }
    type Problem = DynamicsProblem;
    type Results = DynamicsResults;

    fn problem(&self, ctx: &ReadContext) -> Result<DynamicsProblem, SceneError> {
        let origin = ctx.origin;
        let f = Fields { origin };
        self.check(f)?;
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                ],
            )?;
        }
        Ok(self.to_problem())
    }
    fn construct(
        problem: &DynamicsProblem,
        config: BoardConfig,
    ) -> Result<(Board, DynamicsResults), ConstructionError> {
        let mut board = Board::new(config);
        let res = dynamics::construct(
            &mut board,
            &problem.engine,
            &problem.drawing,
            &problem.rays,
            &problem.request,
        )?;
        Ok((board, res))
    }
    fn sweeps(p: &DynamicsProblem) -> Vec<Setting<'_>> {
        dynamics_divisions(p)
    }
    fn figure_meta(problem: &DynamicsProblem) -> FigureMeta {
        use crate::fmt::num;
        let k = &problem.engine.kinematics;
        FigureMeta {
            title: problem.title.clone(),
            source: super::fields::source_line(
                &problem.source,
                &format!(
                    "R = {} mm, R/L = 1 : {}, v = {} m/s, {}",
                    num(k.r, 3),
                    crate::fmt::book_number(1.0 / k.lambda, 2),
                    num(k.v, 4),
                    match problem.engine.cylinders.len() {
                        1 => "1 cylinder".to_string(),
                        n => format!("{n} cylinders"),
                    }
                ),
            ),
            scales: vec![
                ScaleBar::length(problem.drawing.length_scale, "mm"),
                ScaleBar::force(problem.drawing.force_scale),
            ],
            plate: Vec::new(),
        }
    }
}

const DYNAMICS_DIVISIONS: [usize; 6] = [12, 24, 60, 120, 360, 1200];

/// The engine's divisions swept; each rule of the mean turning force its own curve.
fn dynamics_divisions(d: &DynamicsProblem) -> Vec<Setting<'_>> {
    if !d.request.mean_height {
        return Vec::new();
    }
    DYNAMICS_DIVISIONS
        .iter()
        .map(|&n| -> Setting<'_> {
            Box::new(move || {
                let mut q = d.clone();
                q.rays = Angles::Divisions(n);
                let (r, secs) = timed_drawing(&format_args!("{n} divisions"), |c| {
                    DynamicsScene::construct(&q, c)
                });
                let res = r?.1;
                let exact = res.t_m_exact;
                Ok(res
                    .mean_heights
                    .iter()
                    .map(|m| {
                        // m.error is m.t_m − exact: the error `one` finds.
                        one(
                            &format!("divisions, {}", m.rule),
                            "mean turning force T_m",
                            "kg",
                            exact,
                            n.to_string(),
                            m.t_m,
                            secs,
                        )
                    })
                    .collect())
            })
        })
        .collect()
}
