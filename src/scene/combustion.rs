//! The combustion-engine scene (`"procedure": "combustion_engine"`, KG XIV B.4, Abb.
//! 1056-1060).

use super::error::SceneError;
use super::fields::Fields;
use super::procedure::{Procedure, ReadContext};
use super::sweep::{one, timed_drawing, Setting};
use super::types::{Mechanism, Speed};
use crate::dynamics::combustion::{
    self, Combustion, GasCycle, GasCylinder, GasDrawing, GasEngine, GasResults, Strokes,
};
use crate::dynamics::model::{area_cm2, Kinematics, G};
use crate::kernel::tolerance::MAX_DIVISIONS;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A single-acting combustion engine: `"procedure": "combustion_engine"`.
    pub struct CombustionScene {
        /// The crank (`crank_radius_mm` or `stroke_mm`) and the rod.
        pub mechanism: Mechanism,
        /// The crank's speed.
        pub speed: Speed,
        /// `four` (a cycle of 720°) or `two` (360°).
        pub strokes: Strokes,
        /// The cylinders on the shaft.
        pub cylinders: GasCylindersSpec,
        /// The gas cycle every cylinder runs.
        pub gas: GasSpec,
        /// The effects: `inertia` (with `cylinders.reciprocating_kg`).
        #[serde(default)]
        pub effects: Option<GasEffects>,
        /// Equal shaft angles over the cycle.
        pub divisions: usize,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<GasDrawingSpec>,
    }
}

/// The cylinders: how many, their bore, their firing order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GasCylindersSpec {
    /// Bore D (mm).
    pub bore_mm: f64,
    /// The firing order, cylinders numbered from 1 (e.g. `[1, 3, 4, 2]`); one cylinder: `[1]`.
    /// They fire evenly spaced over the cycle.
    pub firing_order: Vec<usize>,
    /// Weight of each cylinder's reciprocating parts (kg); with the effect `inertia`.
    #[serde(default)]
    pub reciprocating_kg: Option<f64>,
}

/// The gas cycle: pressures absolute in at, fractions of the stroke.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GasSpec {
    /// `"constant_volume"` (Otto) or `{"constant_pressure": {"cutoff": 0.08}}` (Diesel).
    pub combustion: Combustion,
    /// Compression ratio ε = (V_s + V_c)/V_c, more than 1.
    pub compression_ratio: f64,
    /// Pressure of the charge when compression starts (at abs).
    pub charge_at: f64,
    /// Peak pressure (at abs), at least the compression's end pressure.
    pub peak_at: f64,
    /// Polytropic exponent of compression (1 to 1.67).
    pub n_compression: f64,
    /// Polytropic exponent of expansion (1 to 1.67).
    pub n_expansion: f64,
    /// The exhaust opens at this fraction of the working stroke.
    pub release: f64,
    /// Exhaust back pressure (at abs, four-stroke; default 1.1).
    #[serde(default)]
    pub exhaust_at: Option<f64>,
}

/// The effects a combustion-engine scene can name.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GasEffects {
    /// Inertia of the reciprocating masses (KG Abb. 1058 b-b).
    #[serde(default)]
    pub inertia: bool,
}

/// Scales of a combustion-engine scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct GasDrawingSpec {
    /// Length scale 1 : n of the crank figures.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm.
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
    /// Sheet mm per degree of the developed cycle.
    #[serde(default)]
    pub mm_per_deg: Option<f64>,
}

/// A validated combustion-engine scene.
#[derive(Debug, Clone, PartialEq)]
pub struct CombustionProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The engine.
    pub engine: GasEngine,
    /// Scales.
    pub drawing: GasDrawing,
    /// Shaft angles over the cycle.
    pub divisions: usize,
}

impl CombustionScene {
    fn cycle(&self) -> GasCycle {
        let g = &self.gas;
        GasCycle {
            strokes: self.strokes,
            combustion: g.combustion,
            compression_ratio: g.compression_ratio,
            charge_at: g.charge_at,
            peak_at: g.peak_at,
            n_compression: g.n_compression,
            n_expansion: g.n_expansion,
            release: g.release,
            exhaust_at: g.exhaust_at.unwrap_or(1.1),
        }
    }

    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let r = self.mechanism.check(f)?;
        self.mechanism.check_rod(f, r)?;
        self.speed.check(f)?;
        self.check_cylinders(f)?;
        self.check_gas(f)?;
        if !(8..=MAX_DIVISIONS).contains(&self.divisions) {
            return Err(f.bad(
                "divisions",
                format!(
                    "{}: give between 8 and {MAX_DIVISIONS} shaft angles over the cycle",
                    self.divisions
                ),
            ));
        }
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                ("drawing.mm_per_deg", d.mm_per_deg),
            ] {
                if let Some(v) = v {
                    f.positive(name, v)?;
                }
            }
        }
        Ok(())
    }

    /// The bore, a firing order that names every cylinder once (1 to 12), the masses with
    /// the effect `inertia`.
    fn check_cylinders(&self, f: Fields) -> Result<(), SceneError> {
        let c = &self.cylinders;
        f.positive("cylinders.bore_mm", c.bore_mm)?;
        let n = c.firing_order.len();
        let mut seen = c.firing_order.clone();
        seen.sort_unstable();
        if !(1..=12).contains(&n) || seen != (1..=n).collect::<Vec<_>>() {
            return Err(f.bad("cylinders.firing_order", format!("{:?}: name each of 1 to 12 cylinders once, numbered from 1 (e.g. [1, 3, 4, 2])", c.firing_order)));
        }
        let inertia = self.effects.unwrap_or_default().inertia;
        match (inertia, c.reciprocating_kg) {
            (true, None) => Err(f.bad(
                "cylinders.reciprocating_kg",
                "missing: the effect inertia needs the reciprocating weight".into(),
            )),
            (false, Some(_)) => Err(f.bad(
                "cylinders.reciprocating_kg",
                "is used only with the effect inertia: add it, or leave the weight out".into(),
            )),
            (true, Some(w)) => f.positive("cylinders.reciprocating_kg", w),
            (false, None) => Ok(()),
        }
    }

    /// ε > 1, absolute pressures above zero, a peak not below the compression's end, the
    /// exponents in [1, 1.67], 0 < cut-off < release ≤ 1.
    fn check_gas(&self, f: Fields) -> Result<(), SceneError> {
        let g = &self.gas;
        if !(g.compression_ratio.is_finite() && g.compression_ratio > 1.0) {
            return Err(f.bad(
                "gas.compression_ratio",
                format!(
                    "{}: the compression ratio (V_s + V_c)/V_c must exceed 1",
                    g.compression_ratio
                ),
            ));
        }
        for (name, p) in [
            ("gas.charge_at", Some(g.charge_at)),
            ("gas.peak_at", Some(g.peak_at)),
            ("gas.exhaust_at", g.exhaust_at),
        ] {
            if let Some(p) = p {
                if !(p.is_finite() && p > 0.0) {
                    return Err(f.bad(
                        name,
                        format!("{p}: absolute pressures lie above zero (at abs)"),
                    ));
                }
            }
        }
        for (name, x) in [
            ("gas.n_compression", g.n_compression),
            ("gas.n_expansion", g.n_expansion),
        ] {
            if !(x.is_finite() && (1.0..=1.67).contains(&x)) {
                return Err(f.bad(
                    name,
                    format!("{x}: give a polytropic exponent between 1 (isothermal) and 1.67"),
                ));
            }
        }
        let cutoff = match g.combustion {
            Combustion::ConstantPressure { cutoff } => cutoff,
            Combustion::ConstantVolume => 0.0,
        };
        if !(g.release.is_finite() && g.release > cutoff && g.release <= 1.0) {
            return Err(f.bad("gas.release", format!("{}: the exhaust opens after the injection ends ({cutoff}) and by the dead centre (1)", g.release)));
        }
        if let Combustion::ConstantPressure { cutoff } = g.combustion {
            if !(cutoff.is_finite() && cutoff > 0.0) {
                return Err(f.bad(
                    "gas.combustion.constant_pressure.cutoff",
                    format!(
                        "{cutoff}: give the end of injection as a fraction of the stroke, above 0"
                    ),
                ));
            }
        }
        let end = self.cycle().compression_end();
        if g.peak_at < end {
            return Err(f.bad("gas.peak_at", format!("{} at is below the compression's end pressure {} at (p_charge·ε^n): raise it or lower the compression", g.peak_at, crate::fmt::num(end, 4))));
        }
        Ok(())
    }

    /// The problem, with the scales chosen where none are given.
    fn to_problem(&self) -> CombustionProblem {
        let r = self.mechanism.radius();
        let kinematics = Kinematics {
            r,
            lambda: r / self.mechanism.rod_length(),
            v: self.speed.crank_pin_speed(r),
        };
        let c = &self.cylinders;
        let cycle = self.cycle();
        let n = c.firing_order.len();
        let inertia = self.effects.unwrap_or_default().inertia;
        let cylinders: Vec<GasCylinder> = (1..=n)
            .map(|i| {
                let k = c.firing_order.iter().position(|&x| x == i).unwrap_or(0);
                GasCylinder {
                    name: format!("{i}"),
                    area_cm2: area_cm2(c.bore_mm, 0.0),
                    cycle,
                    mass: if inertia {
                        c.reciprocating_kg.unwrap_or(0.0) / G
                    } else {
                        0.0
                    },
                    fires_at: self.strokes.cycle_deg() * k as f64 / n as f64,
                }
            })
            .collect();
        let d = self.drawing.unwrap_or(GasDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
            mm_per_deg: None,
        });
        let nice = super::defaults::nice_at_least;
        let peak = cylinders
            .first()
            .map_or(0.0, |c| largest_force(&kinematics, c));
        CombustionProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            engine: GasEngine {
                kinematics,
                cylinders,
                cycle_deg: self.strokes.cycle_deg(),
            },
            drawing: GasDrawing {
                length_scale: d.length_scale.unwrap_or_else(|| nice(2.0 * r / 60.0)),
                force_scale: d.force_scale_kg_per_mm.unwrap_or_else(|| nice(peak / 60.0)),
                mm_per_deg: d.mm_per_deg.unwrap_or(180.0 / self.strokes.cycle_deg()),
            },
            divisions: self.divisions,
        }
    }
}

/// The largest force a cylinder's diagrams draw (kg): the gas at its peak, or the inertia
/// of its masses at the inner dead centre, whichever is larger (a small fast engine's
/// inertia dwarfs its gas forces, and a scale chosen for the gas alone once drew it kilometres
/// long).
fn largest_force(k: &Kinematics, c: &GasCylinder) -> f64 {
    (c.area_cm2 * c.cycle.peak_at).max(c.mass * k.a() * (1.0 + k.lambda))
}

impl super::Procedure for CombustionScene {
    const NAME: &'static str = "combustion_engine";
    const SIZED_BY: &'static str = "divisions, cylinders or outputs";
    const ABOUT: &'static str = "single-acting combustion engines, four- and two-stroke, constant volume or constant pressure: piston force with and without inertia over the cycle, tangential force, turning force of several cylinders in their firing order and its mean (KG XIV B.4, Abb. 1056-1060)";
    const GEOMETRY_FIELD: &'static str = "mechanism";
    type Problem = CombustionProblem;
    type Results = GasResults;

    fn sheet_extent(p: &CombustionProblem) -> (f64, &'static str) {
        let d = &p.drawing;
        let n = p.engine.cylinders.len() as f64;
        let peak = p
            .engine
            .cylinders
            .first()
            .map_or(0.0, |c| largest_force(&p.engine.kinematics, c));
        let force = (n + 2.0) * peak / d.force_scale;
        let across = p.engine.cycle_deg * d.mm_per_deg;
        let length =
            4.0 * (p.engine.kinematics.r / p.engine.kinematics.lambda.max(1e-300)) / d.length_scale;
        super::fields::largest(
            length,
            [
                (force, "drawing.force_scale_kg_per_mm"),
                (across, "drawing.mm_per_deg"),
            ],
        )
    }
    fn smallest_part(p: &CombustionProblem) -> Option<(f64, &'static str)> {
        let d = &p.drawing;
        let c = p.engine.cylinders.first()?;
        let atm = c.area_cm2 * combustion::ATMOSPHERE_AT / d.force_scale;
        let crank = p.engine.kinematics.r / d.length_scale;
        Some(if atm < crank {
            (atm, "drawing.force_scale_kg_per_mm")
        } else {
            (crank, "drawing.length_scale")
        })
    }
    fn spread(p: &CombustionProblem) -> Option<super::procedure::Spread> {
        let c = p.engine.cylinders.first()?;
        let k = &p.engine.kinematics;
        let atm = c.area_cm2 * combustion::ATMOSPHERE_AT;
        let inertia = c.mass * k.a() * (1.0 + k.lambda);
        Some(if inertia > c.area_cm2 * c.cycle.peak_at {
            super::procedure::Spread {
                ratio: inertia / atm,
                between: "the masses' inertia force and the atmosphere's force on the piston",
                field: "cylinders.reciprocating_kg",
            }
        } else {
            super::procedure::Spread {
                ratio: c.cycle.peak_at / combustion::ATMOSPHERE_AT,
                between: "the peak pressure and the atmosphere",
                field: "gas.peak_at",
            }
        })
    }
    fn problem(&self, ctx: &ReadContext) -> Result<CombustionProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        p: &CombustionProblem,
        config: BoardConfig,
    ) -> Result<(Board, GasResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = combustion::construct(&mut board, &p.engine, &p.drawing, p.divisions)?;
        Ok((board, r))
    }
    fn sweeps(p: &CombustionProblem) -> Vec<Setting<'_>> {
        gas_divisions(p)
    }
    fn figure_meta(p: &CombustionProblem) -> FigureMeta {
        FigureMeta {
            title: p.title.clone(),
            source: p.source.clone(),
            scales: vec![
                ScaleBar::length(p.drawing.length_scale, "m"),
                ScaleBar::force(p.drawing.force_scale),
            ],
            plate: Vec::new(),
        }
    }
}

/// A combustion engine's shaft angles over the cycle swept, the mean of the drawn turning
/// force against the exact integral: the gas force jumps at the firing dead centre and at
/// the cut-off's corner, so the mean converges as n⁻¹ until the ordinates resolve the peak.
fn gas_divisions(g: &CombustionProblem) -> Vec<Setting<'_>> {
    [8, 12, 24, 48, 96, 180, 360, 720, 1440, 3600]
        .into_iter()
        .map(|n| -> Setting<'_> {
            Box::new(move || {
                let mut q = g.clone();
                q.divisions = n;
                let (r, secs) = timed_drawing(&format_args!("{n} shaft divisions"), |c| {
                    CombustionScene::construct(&q, c)
                });
                let res = r?.1;
                Ok(vec![one(
                    "shaft divisions over the cycle",
                    "mean turning force T_m (of the ordinates)",
                    "kg",
                    Some(res.t_m_exact),
                    n.to_string(),
                    res.t_m,
                    secs,
                )])
            })
        })
        .collect()
}
