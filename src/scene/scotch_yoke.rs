//! The scotch-yoke scene (`"procedure": "scotch_yoke"`, KG XIV, Abb. 1069).

use super::error::SceneError;
use super::fields::Fields;
use super::procedure::{Procedure, ReadContext};
use super::slider_crank::{check_crank, crank_radius};
use super::sweep::{mean_over_divisions, timed_drawing, MeanOf, Setting};
use super::types::{AngleSpec, Rod, Speed};
use crate::crank::{Angles, Drawing};
use crate::mechanisms::scotch_yoke::{self, Yoke, YokeRequest, YokeResults};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
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
        pub outputs: YokeRequest,
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
        crank_radius((self.crank.crank_radius_mm, self.crank.stroke_mm))
    }

    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let r = check_crank(
            f,
            "crank",
            (self.crank.crank_radius_mm, self.crank.stroke_mm),
        )?;
        self.speed.check(f)?;
        self.angles.check_divisions_or_degrees(f)?;
        self.check_rod(f, r)?;
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

    /// The rod of the comparison: asked for with `slider_crank`, longer than the crank
    /// (`r`) as a slider-crank's rod must be.
    fn check_rod(&self, f: Fields, r: f64) -> Result<(), SceneError> {
        let wants = self.outputs.slider_crank;
        match (wants, self.compare_rod) {
            (true, None) => Err(f.bad("compare_rod", "the slider_crank output draws a slider-crank beside the yoke: give its rod, e.g. {\"l_over_r\": 5}".into())),
            (false, Some(_)) => Err(f.bad("compare_rod", "is drawn only with the slider_crank output: add it, or leave the rod out".into())),
            (true, Some(rod)) => rod.check(f, "compare_rod", r),
            (false, None) => Ok(()),
        }
    }

    /// The problem the scene describes, with the scales chosen where none are given: the
    /// crank circle about 100 mm across, v about 30 mm, v²/R about 30 mm.
    fn to_problem(&self) -> YokeProblem {
        let r = self.radius();
        let v = self.speed.crank_pin_speed(r);
        let d = self.drawing.unwrap_or(YokeDrawingSpec {
            length_scale: None,
            velocity_scale_m_s_per_mm: None,
            acceleration_scale_m_s2_per_mm: None,
        });
        let nice = super::defaults::nice_at_least;
        let yoke = Yoke {
            crank_radius: r,
            crank_pin_speed: v,
            compare_rod: self.compare_rod.map(|rod| rod.length(r)),
        };
        YokeProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            yoke,
            drawing: Drawing {
                length_scale: d.length_scale.unwrap_or_else(|| nice(2.0 * r / 100.0)),
                force_scale: 1.0,
                velocity_scale: d
                    .velocity_scale_m_s_per_mm
                    .unwrap_or_else(|| nice(v / 30.0)),
                acceleration_scale: d
                    .acceleration_scale_m_s2_per_mm
                    .unwrap_or_else(|| nice(yoke.v2_over_r() / 30.0)),
            },
            angles: self.angles.angles(),
            request: self.outputs,
        }
    }
}

impl super::Procedure for YokeScene {
    const NAME: &'static str = "scotch_yoke";
    const SIZED_BY: &'static str = "angles (crank positions) or outputs";
    const ABOUT: &'static str = "the scotch yoke (Kurbelschleife): path, velocity and acceleration over the stroke, beside the slider-crank of the same stroke (KG XIV, Abb. 1069)";
    const OUTPUTS: &'static [&'static str] = YokeRequest::NAMES;
    const GEOMETRY_FIELD: &'static str = "crank";

    fn sheet_extent(p: &YokeProblem) -> (f64, &'static str) {
        let d = &p.drawing;
        let y = &p.yoke;
        let length = 4.0 * y.crank_radius / d.length_scale;
        let speed = 4.0 * y.crank_pin_speed / d.velocity_scale;
        let accel = 4.0 * y.v2_over_r() / d.acceleration_scale;
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
                    y.v2_over_r() / d.acceleration_scale,
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

    fn problem(&self, ctx: &ReadContext) -> Result<YokeProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &YokeProblem,
        config: BoardConfig,
    ) -> Result<(Board, YokeResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = scotch_yoke::construct(
            &mut board,
            &problem.yoke,
            &problem.drawing,
            &problem.angles,
            problem.request,
        )?;
        Ok((board, r))
    }
    fn sweeps(p: &YokeProblem) -> Vec<Setting<'_>> {
        yoke_divisions(p)
    }
    fn figure_meta(problem: &YokeProblem) -> FigureMeta {
        let d = &problem.drawing;
        let mut scales = vec![ScaleBar::length(d.length_scale, "m")];
        if problem.request.velocity {
            scales.push(ScaleBar::velocity(d.velocity_scale));
        }
        if problem.request.acceleration {
            scales.push(ScaleBar::acceleration(d.acceleration_scale));
        }
        FigureMeta {
            title: problem.title.clone(),
            source: problem.source.clone(),
            scales,
            plate: Vec::new(),
        }
    }
}

/// A scotch yoke's crank angles swept, against its mean speed 2v/π (velocity asked for):
/// |c′| = v·|sin φ| has kinks at the dead centres, so the mean of the divisions converges as
/// n⁻², as the slider-crank's does.
fn yoke_divisions(y: &YokeProblem) -> Vec<Setting<'_>> {
    if !y.request.velocity {
        return Vec::new();
    }
    let what = MeanOf {
        quantity: "mean yoke speed (of the divisions)",
        unit: "m/s",
        exact: 2.0 * y.yoke.crank_pin_speed / std::f64::consts::PI,
    };
    mean_over_divisions(what, move |n| {
        let mut q = y.clone();
        q.angles = Angles::Divisions(n);
        let (r, secs) = timed_drawing(&format_args!("{n} crank divisions"), |c| {
            YokeScene::construct(&q, c)
        });
        Ok((r?.1.rows.iter().filter_map(|r| r.c).collect(), secs))
    })
}
