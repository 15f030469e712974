//! The scotch-yoke scene (`"procedure": "scotch_yoke"`, KG XIV, Abb. 1069).

use super::error::SceneError;
use super::fields::Fields;
use super::types::{AngleSpec, Rod, Speed};
use crate::crank::{Angles, Drawing};
use crate::kernel::tolerance::{MAX_DIVISIONS, MIN_ROD_EXCESS};
use crate::mechanisms::scotch_yoke::{self, Yoke, YokeRequest, YokeResults};
use crate::protocol::{Board, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A scotch-yoke scene: `"procedure": "scotch_yoke"`.
    pub struct YokeScene {
        /// The crank: its radius or its stroke.
        pub crank: YokeCrank,
        /// The crank's speed.
        pub speed: Speed,
        /// Crank positions: `divisions` or `degrees` (from the dead centre).
        pub angles: AngleSpec,
        /// What to draw besides the yoke's path: `velocity`, `acceleration`, and
        /// `slider_crank`, the slider-crank of the same stroke beside it (needs `compare_rod`).
        #[serde(default)]
        pub outputs: Vec<YokeOutput>,
        /// The rod of the slider-crank drawn beside the yoke for comparison.
        #[serde(default)]
        pub compare_rod: Option<Rod>,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<YokeDrawingSpec>,
    }
}

/// The crank of a scotch yoke.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct YokeCrank {
    /// Crank radius R in mm (give this or `stroke_mm`).
    #[serde(default)]
    pub crank_radius_mm: Option<f64>,
    /// Stroke s = 2R in mm.
    #[serde(default)]
    pub stroke_mm: Option<f64>,
}

/// What a scotch-yoke scene can ask for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum YokeOutput {
    /// The velocity c′ over the stroke.
    Velocity,
    /// The acceleration b′ over the stroke.
    Acceleration,
    /// The slider-crank of the same stroke, drawn beside and laid into the diagrams.
    SliderCrank,
}

/// Scales of a scotch-yoke scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct YokeDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Velocity scale, m/s per mm of sheet.
    #[serde(default)]
    pub velocity_scale_m_s_per_mm: Option<f64>,
    /// Acceleration scale, m/s² per mm of sheet.
    #[serde(default)]
    pub acceleration_scale_m_s2_per_mm: Option<f64>,
}

/// A validated scotch-yoke scene.
#[derive(Debug, Clone, PartialEq)]
pub struct YokeProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The yoke.
    pub yoke: Yoke,
    /// Scales (the force scale unused).
    pub drawing: Drawing,
    /// Crank angles.
    pub angles: Angles,
    /// What to draw.
    pub request: YokeRequest,
}

impl YokeScene {
    fn radius(&self) -> f64 {
        self.crank
            .crank_radius_mm
            .unwrap_or_else(|| self.crank.stroke_mm.unwrap_or(0.0) / 2.0)
    }

    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        match (self.crank.crank_radius_mm, self.crank.stroke_mm) {
            (Some(r), None) => f.positive("crank.crank_radius_mm", r)?,
            (None, Some(s)) => f.positive("crank.stroke_mm", s)?,
            _ => {
                return Err(f.bad(
                    "crank",
                    "give crank_radius_mm or stroke_mm, one of them".into(),
                ))
            }
        }
        self.speed.check(f)?;
        match &self.angles {
            AngleSpec::Divisions(n) if !(2..=MAX_DIVISIONS).contains(n) => {
                return Err(f.bad(
                    "angles.divisions",
                    format!("{n}: give 2 to {MAX_DIVISIONS}"),
                ));
            }
            AngleSpec::Degrees(v)
                if v.is_empty()
                    || v.len() > MAX_DIVISIONS
                    || v.iter()
                        .any(|a| !(a.is_finite() && (0.0..360.0).contains(a))) =>
            {
                return Err(f.bad(
                    "angles.degrees",
                    format!("give 1 to {MAX_DIVISIONS} angles, each 0 ≤ θ < 360"),
                ));
            }
            AngleSpec::StrokeParts(_) => {
                return Err(f.bad("angles.stroke_parts", "the stroke divided by rod arcs is the slider-crank's construction: give divisions or degrees".into()));
            }
            _ => {}
        }
        self.check_rod(f)?;
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                (
                    "drawing.velocity_scale_m_s_per_mm",
                    d.velocity_scale_m_s_per_mm,
                ),
                (
                    "drawing.acceleration_scale_m_s2_per_mm",
                    d.acceleration_scale_m_s2_per_mm,
                ),
            ] {
                if let Some(v) = v {
                    f.positive(name, v)?;
                }
            }
        }
        Ok(())
    }

    /// The rod of the comparison: asked for with `slider_crank`, longer than the crank.
    fn check_rod(&self, f: Fields) -> Result<(), SceneError> {
        let wants = self.outputs.contains(&YokeOutput::SliderCrank);
        match (wants, self.compare_rod) {
            (true, None) => Err(f.bad("compare_rod", "the slider_crank output draws a slider-crank beside the yoke: give its rod, e.g. {\"l_over_r\": 5}".into())),
            (false, Some(_)) => Err(f.bad("compare_rod", "is drawn only with the slider_crank output: add it, or leave the rod out".into())),
            (_, Some(rod)) => {
                let r = self.radius();
                let (l, field) = match rod {
                    Rod::LengthMm(l) => (l, "compare_rod.length_mm"),
                    Rod::LOverR(k) => (k * r, "compare_rod.l_over_r"),
                };
                if !(l.is_finite() && l > r * (1.0 + MIN_ROD_EXCESS)) {
                    return Err(f.bad(field, format!("the rod ({}) must be longer than the crank (R = {r} mm) by more than {MIN_ROD_EXCESS} of it", crate::fmt::num(l, 6))));
                }
                Ok(())
            }
            (false, None) => Ok(()),
        }
    }

    /// The problem the scene describes, with the scales chosen where none are given: the
    /// crank circle about 100 mm across, v about 30 mm, v²/R about 30 mm.
    pub fn problem(&self) -> YokeProblem {
        let r = self.radius();
        let v = self.speed.crank_pin_speed(r);
        let d = self.drawing.unwrap_or(YokeDrawingSpec {
            length_scale: None,
            velocity_scale_m_s_per_mm: None,
            acceleration_scale_m_s2_per_mm: None,
        });
        let nice = super::defaults::nice_at_least;
        YokeProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            yoke: Yoke {
                crank_radius: r,
                crank_pin_speed: v,
                compare_rod: self.compare_rod.map(|rod| match rod {
                    Rod::LengthMm(l) => l,
                    Rod::LOverR(k) => k * r,
                }),
            },
            drawing: Drawing {
                length_scale: d.length_scale.unwrap_or_else(|| nice(2.0 * r / 100.0)),
                force_scale: 1.0,
                velocity_scale: d
                    .velocity_scale_m_s_per_mm
                    .unwrap_or_else(|| nice(v / 30.0)),
                acceleration_scale: d
                    .acceleration_scale_m_s2_per_mm
                    .unwrap_or_else(|| nice(v * v / (r / 1000.0) / 30.0)),
            },
            angles: match &self.angles {
                AngleSpec::Divisions(n) => Angles::Divisions(*n),
                AngleSpec::Degrees(v) => Angles::Degrees(v.clone()),
                AngleSpec::StrokeParts(n) => Angles::StrokeParts(*n),
            },
            request: YokeRequest {
                velocity: self.outputs.contains(&YokeOutput::Velocity),
                acceleration: self.outputs.contains(&YokeOutput::Acceleration),
            },
        }
    }
}

impl YokeProblem {
    /// Constructs the yoke (and the slider-crank beside it) on a fresh board.
    pub fn construct(&self, recording: bool) -> Result<(Board, YokeResults), ConstructionError> {
        let mut board = Board::for_construction(recording);
        let r = scotch_yoke::construct(
            &mut board,
            &self.yoke,
            &self.drawing,
            &self.angles,
            self.request,
        )?;
        Ok((board, r))
    }

    /// Title, source and scale bars.
    pub fn figure_meta(&self) -> FigureMeta {
        let d = &self.drawing;
        let mut scales = vec![ScaleBar::length(d.length_scale, "m")];
        if self.request.velocity {
            scales.push(ScaleBar::velocity(d.velocity_scale));
        }
        if self.request.acceleration {
            scales.push(ScaleBar::acceleration(d.acceleration_scale));
        }
        FigureMeta {
            title: self.title.clone(),
            source: self.source.clone(),
            scales,
        }
    }
}

impl super::Procedure for YokeScene {
    const NAME: &'static str = "scotch_yoke";
    const ABOUT: &'static str = "the scotch yoke (Kurbelschleife): path, velocity and acceleration over the stroke, beside the slider-crank of the same stroke (KG XIV, Abb. 1069)";
    const OUTPUTS: &'static [&'static str] = &["velocity", "acceleration", "slider_crank"];
    const GEOMETRY_FIELD: &'static str = "crank";

    fn sheet_extent(p: &YokeProblem) -> (f64, &'static str) {
        let d = &p.drawing;
        let y = &p.yoke;
        let length = 4.0 * y.crank_radius / d.length_scale;
        let speed = 4.0 * y.crank_pin_speed / d.velocity_scale;
        let accel =
            4.0 * y.crank_pin_speed.powi(2) / (y.crank_radius / 1000.0) / d.acceleration_scale;
        if accel > length.max(speed) && p.request.acceleration {
            (accel, "drawing.acceleration_scale_m_s2_per_mm")
        } else if speed > length && p.request.velocity {
            (speed, "drawing.velocity_scale_m_s_per_mm")
        } else {
            (length, "drawing.length_scale")
        }
    }
    fn smallest_part(p: &YokeProblem) -> Option<(f64, &'static str)> {
        let (d, y, rq) = (&p.drawing, &p.yoke, &p.request);
        let parts = [
            rq.velocity.then(|| {
                (
                    y.crank_pin_speed / d.velocity_scale,
                    "drawing.velocity_scale_m_s_per_mm",
                )
            }),
            rq.acceleration.then(|| {
                (
                    y.crank_pin_speed.powi(2) / (y.crank_radius / 1000.0) / d.acceleration_scale,
                    "drawing.acceleration_scale_m_s2_per_mm",
                )
            }),
        ];
        parts
            .into_iter()
            .flatten()
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }
    type Problem = YokeProblem;
    type Results = YokeResults;

    fn validate(&self, origin: &str) -> Result<(), SceneError> {
        self.check_values(origin)
    }
    fn problem(&self) -> YokeProblem {
        YokeScene::problem(self)
    }
    fn construct(
        problem: &YokeProblem,
        recording: bool,
    ) -> Result<(Board, YokeResults), ConstructionError> {
        problem.construct(recording)
    }
    fn figure_meta(problem: &YokeProblem) -> FigureMeta {
        problem.figure_meta()
    }
}
