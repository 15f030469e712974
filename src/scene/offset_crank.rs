//! The offset slider-crank scene (`"procedure": "offset_crank"`, KG XIV, Abb. 1046).

use super::error::SceneError;
use super::fields::Fields;
use super::procedure::ReadContext;
use super::types::{AngleSpec, Rod, Speed};
use crate::mechanisms::offset_crank::{
    self, OffsetCrank, OffsetRequest, OffsetResults, OffsetScales,
};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// An offset (geschränkt) slider-crank: `"procedure": "offset_crank"`.
    pub struct OffsetScene {
        /// Crank radius R in mm.
        pub crank_radius_mm: f64,
        /// The rod: `length_mm` or `l_over_r`.
        pub rod: Rod,
        /// The offset a of the line of the stroke from the shaft (mm; positive on the side
        /// the pin passes on the outstroke). |a| < L − R.
        pub offset_mm: f64,
        /// The crank's speed.
        pub speed: Speed,
        /// Crank angles (`divisions` or `degrees`), counter-clockwise from the line through
        /// O parallel to the stroke, towards the crosshead.
        pub angles: AngleSpec,
        /// What to draw besides the path and the dead centres: `velocity`, `forces` (needs
        /// `piston_force_kg`).
        #[serde(default)]
        pub outputs: OffsetRequest,
        /// The driving piston force P (kg), pushing the piston the way it moves.
        #[serde(default)]
        pub piston_force_kg: Option<f64>,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<OffsetDrawingSpec>,
    }
}

/// Scales of an offset-crank scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct OffsetDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Velocity scale, m/s per mm of sheet.
    #[serde(default)]
    pub velocity_scale_m_s_per_mm: Option<f64>,
    /// Force scale, kg per mm of sheet.
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
}

/// A validated offset-crank scene.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The mechanism.
    pub crank: OffsetCrank,
    /// Scales.
    pub scales: OffsetScales,
    /// Crank angles (degrees).
    pub thetas: Vec<f64>,
    /// What to draw.
    pub request: OffsetRequest,
}

impl OffsetScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let r = self.crank_radius_mm;
        f.positive("crank_radius_mm", r)?;
        self.rod.check(f, "rod", r)?;
        let l = self.rod.length(r);
        f.finite("offset_mm", self.offset_mm)?;
        if self.offset_mm.abs() >= l - r {
            return Err(f.bad("offset_mm", format!(
                "|a| must be less than L − R = {} mm so that the crank turns round (the arc L − R about O must cut the line of the stroke), got {}",
                crate::fmt::num(l - r, 6), crate::fmt::num(self.offset_mm, 6))));
        }
        self.speed.check(f)?;
        self.angles.check_divisions_or_degrees(f)?;
        let wants = self.outputs.forces;
        match (wants, self.piston_force_kg) {
            (true, None) => {
                return Err(f.bad(
                    "piston_force_kg",
                    "missing: the forces output needs the piston force".into(),
                ))
            }
            (false, Some(_)) => {
                return Err(f.bad(
                    "piston_force_kg",
                    "is used only by the forces output: add it, or leave the force out".into(),
                ))
            }
            (true, Some(p)) => f.finite("piston_force_kg", p)?,
            (false, None) => {}
        }
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                (
                    "drawing.velocity_scale_m_s_per_mm",
                    d.velocity_scale_m_s_per_mm,
                ),
                ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
            ] {
                if let Some(v) = v {
                    f.positive(name, v)?;
                }
            }
        }
        Ok(())
    }

    /// The problem, with the scales chosen where none are given: the crank circle about 60 mm
    /// across, v about 30 mm, P about 40 mm.
    fn to_problem(&self) -> OffsetProblem {
        let r = self.crank_radius_mm;
        let v = self.speed.crank_pin_speed(r);
        let crank = OffsetCrank {
            crank_radius: r,
            rod_length: self.rod.length(r),
            offset: self.offset_mm,
            crank_pin_speed: v,
            piston_force: self.piston_force_kg,
        };
        let d = self.drawing.unwrap_or(OffsetDrawingSpec {
            length_scale: None,
            velocity_scale_m_s_per_mm: None,
            force_scale_kg_per_mm: None,
        });
        let nice = super::defaults::nice_at_least;
        let p = self
            .piston_force_kg
            .unwrap_or(1.0)
            .abs()
            .max(f64::MIN_POSITIVE);
        let thetas = self.angles.degrees();
        OffsetProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            crank,
            scales: OffsetScales {
                length: d.length_scale.unwrap_or_else(|| nice(2.0 * r / 60.0)),
                velocity: d
                    .velocity_scale_m_s_per_mm
                    .unwrap_or_else(|| nice(v / 30.0)),
                force: d.force_scale_kg_per_mm.unwrap_or_else(|| nice(p / 40.0)),
            },
            thetas,
            request: self.outputs,
        }
    }
}

impl super::Procedure for OffsetScene {
    const NAME: &'static str = "offset_crank";
    const SIZED_BY: &'static str = "angles (crank positions) or outputs";
    const ABOUT: &'static str = "the offset (geschränkt) slider-crank: dead centres by the arcs L ± R, the unequal strokes’ crank angles 180° ± δ, path, velocity and forces (KG XIV, Abb. 1046)";
    const OUTPUTS: &'static [&'static str] = OffsetRequest::NAMES;
    const GEOMETRY_FIELD: &'static str = "offset_mm";
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("offset", "offset_mm"),
        ("rod_length", "rod"),
        ("crank_radius", "crank_radius_mm"),
        ("crank_pin_speed", "speed"),
    ];
    type Problem = OffsetProblem;
    type Results = OffsetResults;

    fn sheet_extent(p: &OffsetProblem) -> (f64, &'static str) {
        let k = &p.crank;
        let s = &p.scales;
        let length = 2.0 * (k.rod_length + k.crank_radius) / s.length;
        let force = (
            p.request.forces,
            4.0 * k.piston_force.unwrap_or(0.0).abs() / s.force,
        );
        let speed = (p.request.velocity, 4.0 * k.crank_pin_speed / s.velocity);
        let parts = [
            (force, "drawing.force_scale_kg_per_mm"),
            (speed, "drawing.velocity_scale_m_s_per_mm"),
        ];
        let drawn = parts.into_iter().filter(|((on, _), _)| *on);
        super::fields::largest(length, drawn.map(|((_, mm), field)| (mm, field)))
    }
    fn smallest_part(p: &OffsetProblem) -> Option<(f64, &'static str)> {
        let (k, s, rq) = (&p.crank, &p.scales, &p.request);
        let parts = [
            Some((k.crank_radius / s.length, "drawing.length_scale")),
            rq.velocity.then(|| {
                (
                    k.crank_pin_speed / s.velocity,
                    "drawing.velocity_scale_m_s_per_mm",
                )
            }),
            (rq.forces && k.piston_force.is_some_and(|f| f != 0.0)).then(|| {
                (
                    k.piston_force.unwrap_or(0.0).abs() / s.force,
                    "drawing.force_scale_kg_per_mm",
                )
            }),
        ];
        parts
            .into_iter()
            .flatten()
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }
    fn problem(&self, ctx: &ReadContext) -> Result<OffsetProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        p: &OffsetProblem,
        config: BoardConfig,
    ) -> Result<(Board, OffsetResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = offset_crank::construct(&mut board, &p.crank, p.scales, &p.thetas, p.request)?;
        Ok((board, r))
    }
    fn figure_meta(p: &OffsetProblem) -> FigureMeta {
        let mut scales = vec![ScaleBar::length(p.scales.length, "m")];
        if p.request.velocity {
            scales.push(ScaleBar::velocity(p.scales.velocity));
        }
        if p.request.forces {
            scales.push(ScaleBar::force(p.scales.force));
        }
        FigureMeta {
            title: p.title.clone(),
            source: p.source.clone(),
            scales,
            plate: Vec::new(),
        }
    }
}
