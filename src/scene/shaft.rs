//! The shaft scene: loads in two planes and a torque (LH C.7-8, Abb. 26-29).

use super::beam::BeamDrawingSpec;
use super::defaults::nice_at_least;
use super::error::SceneError;
use super::fields::{optional_positive, Fields};
use super::procedure::ReadContext;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use crate::statics::shaft::{self, Shaft, ShaftRow, Torque};
use crate::statics::{BeamDrawing, PointLoad};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A shaft scene: `"procedure": "shaft"`.
    pub struct ShaftScene {
        /// Supports and ends, as for a beam.
        pub shaft: super::BeamSpec,
        /// Loads in the first plane.
        #[serde(default)]
        pub plane_1_loads: Vec<super::PointLoadSpec>,
        /// Loads in the second plane.
        #[serde(default)]
        pub plane_2_loads: Vec<super::PointLoadSpec>,
        /// Angle between the two load planes (degrees, 0 < α ≤ 180), default 90.
        #[serde(default)]
        pub angle_between_planes_deg: Option<f64>,
        /// A torque acting over a stretch of the shaft.
        #[serde(default)]
        pub torque: Option<TorqueSpec>,
        /// Bach's ratio α0 weighting the torque in the ideal moment (default 1).
        #[serde(default)]
        pub alpha0: Option<f64>,
        /// Allowed bending stress k_b (kg/cm²): each section then reports the diameter it needs.
        #[serde(default)]
        pub kb_kg_per_cm2: Option<f64>,
        /// Scales and the pole distance, as for a beam.
        #[serde(default)]
        pub drawing: Option<BeamDrawingSpec>,
    }
}

/// A torque over a stretch of the shaft.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct TorqueSpec {
    /// Start of the stretch (m).
    pub from_m: f64,
    /// End of the stretch (m).
    pub to_m: f64,
    /// Torque M_d (kg·m).
    pub kg_m: f64,
    /// Radius r (m) of the pulley or crank on which the twisting force P = M_d / r acts; with
    /// it the torque ordinate is constructed in the pole triangle (LH Gl. 12).
    #[serde(default)]
    pub radius_m: Option<f64>,
}

/// A validated shaft scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The shaft.
    pub shaft: Shaft,
    /// Scales.
    pub drawing: BeamDrawing,
    /// Where x = 0 of [`ShaftProblem::shaft`] lies in the scene (m): support A for a shaft
    /// farther from the scene's origin than
    /// [`REL_LOCAL_FRAME`](crate::kernel::tolerance::REL_LOCAL_FRAME) times its length, which
    /// is then built in its own frame; 0 otherwise.
    pub offset: f64,
}

impl ShaftScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let ends = self.check_ends(f)?;
        self.check_loads(f, ends)?;
        self.check_numbers(f)?;
        self.check_torque(f, ends)?;
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                    ("drawing.pole_distance_kg", d.pole_distance_kg),
                ],
            )?;
        }
        Ok(())
    }

    /// A left of B, the shaft over both: its ends (m).
    fn check_ends(&self, f: Fields) -> Result<[f64; 2], SceneError> {
        let [a, b] = self.shaft.supports_m;
        if !(a.is_finite() && b.is_finite()) || a >= b {
            return Err(f.bad(
                "shaft.supports_m",
                format!("support A ({a} m) must lie left of support B ({b} m)"),
            ));
        }
        let [e0, e1] = self.shaft.ends_m.unwrap_or([a, b]);
        if !(e0 <= a && e1 >= b) {
            return Err(f.bad(
                "shaft.ends_m",
                "the shaft must reach over both supports".into(),
            ));
        }
        Ok([e0, e1])
    }

    /// The loads of both planes: finite, on the shaft, at most MAX_LOADS each.
    fn check_loads(&self, f: Fields, [e0, e1]: [f64; 2]) -> Result<(), SceneError> {
        for (plane, loads) in [
            ("plane_1_loads", &self.plane_1_loads),
            ("plane_2_loads", &self.plane_2_loads),
        ] {
            if loads.len() > super::MAX_LOADS {
                return Err(f.bad(plane, format!("more than {} loads", super::MAX_LOADS)));
            }
            for (i, l) in loads.iter().enumerate() {
                if !(l.x_m.is_finite() && l.kg.is_finite()) {
                    return Err(f.bad(&format!("{plane}[{i}]"), "must be finite numbers".into()));
                }
                if l.x_m < e0 || l.x_m > e1 {
                    return Err(f.bad(&format!("{plane}[{i}].x_m"), format!("x = {} m lies off the shaft [{e0}, {e1}] m: declare the overhang with shaft.ends_m", l.x_m)));
                }
            }
        }
        Ok(())
    }

    /// The angle between the planes, α₀ and the allowed stress: positive where given.
    fn check_numbers(&self, f: Fields) -> Result<(), SceneError> {
        if let Some(al) = self.angle_between_planes_deg {
            if !(al.is_finite() && al > 0.0 && al <= 180.0) {
                return Err(f.bad(
                    "angle_between_planes_deg",
                    format!("{al}: give 0 < α ≤ 180"),
                ));
            }
        }
        if let Some(a0) = self.alpha0 {
            if !(a0.is_finite() && a0 > 0.0) {
                return Err(f.bad("alpha0", format!("must be positive, got {a0}")));
            }
        }
        if let Some(kb) = self.kb_kg_per_cm2 {
            if !(kb.is_finite() && kb > 0.0) {
                return Err(f.bad("kb_kg_per_cm2", format!("must be positive, got {kb}")));
            }
        }
        Ok(())
    }

    /// The torque: a finite stretch on the shaft, a positive radius where given.
    fn check_torque(&self, f: Fields, [e0, e1]: [f64; 2]) -> Result<(), SceneError> {
        if let Some(t) = &self.torque {
            if !(t.from_m.is_finite() && t.to_m.is_finite() && t.kg_m.is_finite())
                || t.from_m >= t.to_m
            {
                return Err(f.bad("torque", "give finite from_m < to_m and kg_m".into()));
            }
            if let Some(r) = t.radius_m {
                if !(r.is_finite() && r > 0.0) {
                    return Err(f.bad("torque.radius_m", format!("must be positive, got {r}")));
                }
            }
            if t.from_m < e0 || t.to_m > e1 {
                return Err(f.bad("torque", "the twisted stretch must lie on the shaft".into()));
            }
        }
        Ok(())
    }

    /// The problem the scene describes.
    fn to_problem(&self) -> ShaftProblem {
        let [a, b] = self.shaft.supports_m;
        let ends = self.shaft.ends_m.unwrap_or([a, b]);
        let reach = ends[0].abs().max(ends[1].abs());
        let far = reach > crate::kernel::tolerance::REL_LOCAL_FRAME * (ends[1] - ends[0]);
        let o = if far { a } else { 0.0 };
        let (a, b, ends) = (a - o, b - o, [ends[0] - o, ends[1] - o]);
        let loads = |v: &[super::PointLoadSpec]| {
            v.iter()
                .map(|l| PointLoad {
                    x: l.x_m - o,
                    p: l.kg,
                })
                .collect::<Vec<_>>()
        };
        let shaft = Shaft {
            supports: [a, b],
            ends,
            plane_1: loads(&self.plane_1_loads),
            plane_2: loads(&self.plane_2_loads),
            angle_deg: self.angle_between_planes_deg.unwrap_or(90.0),
            torque: self.torque.map(|t| Torque {
                from: t.from_m - o,
                to: t.to_m - o,
                md: t.kg_m,
                radius: t.radius_m,
            }),
            alpha0: self.alpha0.unwrap_or(1.0),
            kb: self.kb_kg_per_cm2,
        };
        let total = shaft
            .plane_1
            .iter()
            .chain(&shaft.plane_2)
            .map(|l| l.p.abs())
            .fold(0.0, f64::max);
        let d = self.drawing.unwrap_or(BeamDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
            pole_distance_kg: None,
            parabola_divisions: None,
        });
        ShaftProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            drawing: BeamDrawing {
                length_scale: d
                    .length_scale
                    .unwrap_or_else(|| nice_at_least((ends[1] - ends[0]) * 1000.0 / 160.0)),
                force_scale: d
                    .force_scale_kg_per_mm
                    .unwrap_or_else(|| nice_at_least(total / 40.0)),
                pole_distance: d.pole_distance_kg.unwrap_or_else(|| nice_at_least(total)),
                parabola_divisions: 8,
                origin: crate::kernel::Point::origin(),
            },
            shaft,
            offset: o,
        }
    }
}

impl super::Procedure for ShaftScene {
    const NAME: &'static str = "shaft";
    const ABOUT: &'static str =
        "a shaft: moments in two planes, torque, ideal moment and diameter (LH I C.7-8)";
    const OUTPUTS: &'static [&'static str] = &[];
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("supports", "shaft.supports_m"),
        ("point_loads", "plane_1_loads"),
        ("pole", "drawing.pole_distance_kg"),
    ];
    const GEOMETRY_FIELD: &'static str = "drawing";

    fn sheet_extent(p: &ShaftProblem) -> (f64, &'static str) {
        let s = &p.shaft;
        let span = (s.ends[1] - s.ends[0]) * 1000.0 / p.drawing.length_scale;
        let loads: f64 = s.plane_1.iter().chain(&s.plane_2).map(|l| l.p.abs()).sum();
        super::fields::larger(span, loads / p.drawing.force_scale)
    }
    type Problem = ShaftProblem;
    type Results = Vec<ShaftRow>;

    fn problem(&self, ctx: &ReadContext) -> Result<ShaftProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &ShaftProblem,
        config: BoardConfig,
    ) -> Result<(Board, Vec<ShaftRow>), ConstructionError> {
        let mut board = Board::new(config);
        let mut r = shaft::construct_shaft(&mut board, &problem.shaft, &problem.drawing)?;
        r.iter_mut().for_each(|row| row.x += problem.offset);
        Ok((board, r))
    }
    fn figure_meta(problem: &ShaftProblem) -> FigureMeta {
        use crate::fmt::num;
        let d = &problem.drawing;
        let ms = d.length_scale / 1000.0 * d.pole_distance;
        FigureMeta {
            title: problem.title.clone(),
            source: super::fields::source_line(
                &problem.source,
                &format!(
                    "planes at {}°, α0 = {}, pole distance H = {} kg",
                    num(problem.shaft.angle_deg, 3),
                    num(problem.shaft.alpha0, 3),
                    num(d.pole_distance, 6)
                ),
            ),
            scales: vec![
                ScaleBar::length(d.length_scale, "m"),
                ScaleBar::force(d.force_scale),
                ScaleBar::moment(ms),
            ],
            plate: Vec::new(),
        }
    }
}
