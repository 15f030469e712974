//! The beam scene: a beam on two supports with point and uniform loads (LH C.4-6, Aufgabe 6).

use super::defaults::nice_at_least;
use super::error::SceneError;
use super::fields::{optional_positive, Fields};
use super::procedure::{Procedure, ReadContext};
use super::sweep::{one, timed_drawing, Setting, Sweep};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use crate::statics::{self, Beam, BeamDrawing, BeamRequest, PointLoad, UniformLoad};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A beam scene: `"procedure": "beam"`.
    pub struct BeamScene {
        /// The beam and its supports.
        pub beam: BeamSpec,
        /// Point loads.
        #[serde(default)]
        pub point_loads: Vec<PointLoadSpec>,
        /// Uniformly distributed loads.
        #[serde(default)]
        pub uniform_loads: Vec<UniformLoadSpec>,
        /// Panel points (m) of stringers that carry the loads to the beam (indirect loading,
        /// LH Abb. 35); absent for loads acting on the beam directly.
        #[serde(default)]
        pub stringers_m: Option<Vec<f64>>,
        /// What to construct besides the reactions: `moment_area`, `shear_diagram`.
        #[serde(default)]
        pub outputs: BeamRequest,
        /// Scales and the pole; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<BeamDrawingSpec>,
    }
}

/// The beam: its supports and, if it overhangs them, its ends.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BeamSpec {
    /// Positions of the supports A and B along the beam (m).
    pub supports_m: [f64; 2],
    /// Ends of the beam (m); default: the supports. Loads beyond a support need an overhang
    /// declared here.
    #[serde(default)]
    pub ends_m: Option<[f64; 2]>,
}

/// A point load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PointLoadSpec {
    /// Position (m).
    pub x_m: f64,
    /// Load (kg), positive downwards.
    pub kg: f64,
}

/// A uniformly distributed load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct UniformLoadSpec {
    /// Start (m).
    pub from_m: f64,
    /// End (m).
    pub to_m: f64,
    /// Intensity (kg/m), positive downwards.
    pub kg_per_m: f64,
}

/// Scales and the pole.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BeamDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm of sheet.
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
    /// Pole distance H (kg): the moment is M = y·H.
    #[serde(default)]
    pub pole_distance_kg: Option<f64>,
    /// Equal parts each tangent of a uniform load's parabola is divided into (2 to 64, default 8).
    #[serde(default)]
    pub parabola_divisions: Option<usize>,
}

/// A validated beam scene, ready to construct.
#[derive(Debug, Clone, PartialEq)]
pub struct BeamProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The beam.
    pub beam: Beam,
    /// Scales.
    pub drawing: BeamDrawing,
    /// What to construct.
    pub request: BeamRequest,
    /// Panel points of stringers (empty: direct loading).
    pub stringers: Vec<f64>,
}

/// Most loads a beam scene drawn as a figure may carry: the figure stays readable.
pub const MAX_LOADS: usize = 2000;

/// Most loads a beam scene may carry where only its checks are kept (`check`:
/// [`ReadContext::checks`]): time and memory are linear in the loads.
pub const MAX_LOADS_CHECKED: usize = 1_000_000;

/// Construction steps a beam takes per load, all diagrams drawn (measured: 1,800,053 for
/// 100,000 loads).
const STEPS_PER_LOAD: usize = 18;

/// The most loads (or panel points) a beam scene read now may have.
fn max_loads(ctx: &ReadContext) -> usize {
    if ctx.checks_only {
        MAX_LOADS_CHECKED
    } else {
        MAX_LOADS
    }
}

impl BeamScene {
    fn check_values(&self, ctx: &ReadContext) -> Result<(), SceneError> {
        let origin = ctx.origin;
        let f = Fields { origin };
        let ends = self.check_supports(f)?;
        self.check_point_loads(f, ctx, ends)?;
        self.check_uniform_loads(f, ends)?;
        self.check_stringers(f, ctx, ends)?;
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                    ("drawing.pole_distance_kg", d.pole_distance_kg),
                ],
            )?;
            if let Some(m) = d.parabola_divisions {
                if !(2..=64).contains(&m) {
                    return Err(f.bad("drawing.parabola_divisions", format!("{m}: give 2 to 64")));
                }
            }
        }
        Ok(())
    }

    /// The supports, A left of B, finite; the ends of the beam over both: the ends (m).
    fn check_supports(&self, f: Fields) -> Result<[f64; 2], SceneError> {
        let [a, b] = self.beam.supports_m;
        f.finite("beam.supports_m[0]", a)?;
        f.finite("beam.supports_m[1]", b)?;
        if a == b {
            return Err(f.bad(
                "beam.supports_m",
                format!(
                    "both supports at one point ({a} m): the beam is not supported against turning"
                ),
            ));
        }
        if a > b {
            return Err(f.bad(
                "beam.supports_m",
                format!("support A ({a} m) must lie left of support B ({b} m)"),
            ));
        }
        let [e0, e1] = self.beam.ends_m.unwrap_or([a, b]);
        f.finite("beam.ends_m[0]", e0)?;
        f.finite("beam.ends_m[1]", e1)?;
        if e0 > a || e1 < b {
            return Err(f.bad(
                "beam.ends_m",
                format!("the beam [{e0}, {e1}] m must reach over both supports [{a}, {b}] m"),
            ));
        }
        Ok([e0, e1])
    }

    /// At most MAX_LOADS loads; point loads finite and on the beam.
    fn check_point_loads(
        &self,
        f: Fields,
        ctx: &ReadContext,
        ends: [f64; 2],
    ) -> Result<(), SceneError> {
        let max = max_loads(ctx);
        let loads = self.point_loads.len() + self.uniform_loads.len();
        if loads > max {
            return Err(f.bad("point_loads", format!("more than {max} loads")));
        }
        if ctx.checks_only {
            let steps = loads.saturating_mul(STEPS_PER_LOAD) + 60;
            super::fields::check_fits_memory(f.origin, "point_loads", steps, ctx.free_memory)?;
        }
        for (i, l) in self.point_loads.iter().enumerate() {
            // The field's name is written only for a load that is refused.
            if l.x_m.is_finite() && l.kg.is_finite() && l.x_m >= ends[0] && l.x_m <= ends[1] {
                continue;
            }
            f.finite(&format!("point_loads[{i}].x_m"), l.x_m)?;
            f.finite(&format!("point_loads[{i}].kg"), l.kg)?;
            on_beam(f, &format!("point_loads[{i}].x_m"), l.x_m, ends)?;
        }
        Ok(())
    }

    /// Uniform loads finite, on the beam, ending after they start, straddling no support,
    /// holding no point load, overlapping no other: each load alone, then the loads in the
    /// order of their starts (n log n: a million loads are checked in a fraction of a second,
    /// where comparing every pair took minutes).
    fn check_uniform_loads(&self, f: Fields, ends: [f64; 2]) -> Result<(), SceneError> {
        let [a, b] = self.beam.supports_m;
        for (i, u) in self.uniform_loads.iter().enumerate() {
            let at = |n: &str| format!("uniform_loads[{i}].{n}");
            f.finite(&at("from_m"), u.from_m)?;
            f.finite(&at("to_m"), u.to_m)?;
            f.finite(&at("kg_per_m"), u.kg_per_m)?;
            if u.to_m <= u.from_m {
                return Err(f.bad(
                    &at("to_m"),
                    format!(
                        "the load must end ({} m) after it starts ({} m)",
                        u.to_m, u.from_m
                    ),
                ));
            }
            on_beam(f, &at("from_m"), u.from_m, ends)?;
            on_beam(f, &at("to_m"), u.to_m, ends)?;
            for (s, x) in [("A", a), ("B", b)] {
                if x > u.from_m && x < u.to_m {
                    return Err(f.bad(&at("to_m"), format!("the load straddles support {s} at {x} m: split it there into two uniform loads (the result is the same)")));
                }
            }
        }
        self.check_point_loads_outside_uniform(f)?;
        self.check_uniform_overlaps(f)
    }

    /// No point load strictly inside a uniform load (the first such uniform load named, with
    /// the first point load inside it by position).
    fn check_point_loads_outside_uniform(&self, f: Fields) -> Result<(), SceneError> {
        let xs: Vec<f64> = self.point_loads.iter().map(|l| l.x_m).collect();
        match crate::statics::beam::point_inside_span(&self.spans(), &xs) {
            Some((i, k)) => Err(f.bad(&format!("point_loads[{k}].x_m"), format!("the point load lies inside uniform load {i}: split the uniform load there (the result is the same)"))),
            None => Ok(()),
        }
    }

    /// No two uniform loads overlap (touching is allowed).
    fn check_uniform_overlaps(&self, f: Fields) -> Result<(), SceneError> {
        match crate::statics::beam::overlapping_spans(&self.spans()) {
            Some((first, second)) => Err(f.bad(
                &format!("uniform_loads[{second}]"),
                format!("overlaps uniform load {first}: add their intensities instead"),
            )),
            None => Ok(()),
        }
    }

    /// The uniform loads' spans (from, to), m.
    fn spans(&self) -> Vec<(f64, f64)> {
        self.uniform_loads
            .iter()
            .map(|u| (u.from_m, u.to_m))
            .collect()
    }

    /// Panel points of the stringers: 2 to MAX_LOADS, increasing, on the beam, covering the
    /// loads.
    fn check_stringers(
        &self,
        f: Fields,
        ctx: &ReadContext,
        ends: [f64; 2],
    ) -> Result<(), SceneError> {
        if let Some(st) = &self.stringers_m {
            let max = max_loads(ctx);
            if st.len() < 2 || st.len() > max {
                return Err(f.bad(
                    "stringers_m",
                    format!("{} panel points: give 2 to {max}", st.len()),
                ));
            }
            for (i, x) in st.iter().enumerate() {
                if !(x.is_finite() && *x >= ends[0] && *x <= ends[1]) {
                    f.finite(&format!("stringers_m[{i}]"), *x)?;
                    on_beam(f, &format!("stringers_m[{i}]"), *x, ends)?;
                }
                if i > 0 && *x <= st[i - 1] {
                    return Err(f.bad(
                        &format!("stringers_m[{i}]"),
                        "panel points must increase".into(),
                    ));
                }
            }
            let (first, last) = (st[0], st[st.len() - 1]);
            for (i, l) in self.point_loads.iter().enumerate() {
                if l.x_m < first || l.x_m > last {
                    return Err(f.bad(
                        &format!("point_loads[{i}].x_m"),
                        format!(
                            "x = {} m lies outside the stringers [{first}, {last}] m",
                            l.x_m
                        ),
                    ));
                }
            }
            for (i, u) in self.uniform_loads.iter().enumerate() {
                if u.from_m < first || u.to_m > last {
                    return Err(f.bad(
                        &format!("uniform_loads[{i}]"),
                        format!("the load reaches outside the stringers [{first}, {last}] m"),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Maps the validated scene to the beam problem.
    fn to_problem(&self) -> BeamProblem {
        let [a, b] = self.beam.supports_m;
        let beam = Beam {
            supports: [a, b],
            ends: self.beam.ends_m.unwrap_or([a, b]),
            point_loads: self
                .point_loads
                .iter()
                .map(|l| PointLoad { x: l.x_m, p: l.kg })
                .collect(),
            uniform_loads: self
                .uniform_loads
                .iter()
                .map(|u| UniformLoad {
                    from: u.from_m,
                    to: u.to_m,
                    q: u.kg_per_m,
                })
                .collect(),
        };
        let total: f64 = beam.point_loads.iter().map(|l| l.p.abs()).sum::<f64>()
            + beam
                .uniform_loads
                .iter()
                .map(|u| u.resultant().abs())
                .sum::<f64>();
        let d = self.drawing.unwrap_or(BeamDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
            pole_distance_kg: None,
            parabola_divisions: None,
        });
        let span = beam.ends[1] - beam.ends[0];
        let drawing = BeamDrawing {
            length_scale: d
                .length_scale
                .unwrap_or_else(|| nice_at_least(span * 1000.0 / 160.0)),
            force_scale: d
                .force_scale_kg_per_mm
                .unwrap_or_else(|| nice_at_least(total / 80.0)),
            pole_distance: d
                .pole_distance_kg
                .unwrap_or_else(|| nice_at_least(total / 2.0)),
            parabola_divisions: d.parabola_divisions.unwrap_or(8),
            origin: crate::kernel::Point::origin(),
        };
        BeamProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            beam,
            drawing,
            request: self.outputs,
            stringers: self.stringers_m.clone().unwrap_or_default(),
        }
    }
}

impl super::Procedure for BeamScene {
    const NAME: &'static str = "beam";
    const ABOUT: &'static str = "a beam on two supports: reactions by the closing line, moment area, shear, parabola by tangents (LH I C.4-6)";
    const OUTPUTS: &'static [&'static str] = BeamRequest::NAMES;
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("supports", "beam.supports_m"),
        ("stringers", "stringers_m"),
        ("pole", "drawing.pole_distance_kg"),
    ];
    const GEOMETRY_FIELD: &'static str = "drawing";

    fn sheet_extent(p: &BeamProblem) -> (f64, &'static str) {
        let (b, d) = (&p.beam, &p.drawing);
        let span = (b.ends[1] - b.ends[0]) * 1000.0 / d.length_scale;
        let loads: f64 = b.point_loads.iter().map(|l| l.p.abs()).sum::<f64>()
            + b.uniform_loads
                .iter()
                .map(|u| u.resultant().abs())
                .sum::<f64>();
        // The pole stands H from the load line, and the polygon hangs M/H deep: a pole
        // distance typed wrong (1e12 kg, 1e-9 kg) makes one of them absurd.
        let pole = d.pole_distance / d.force_scale;
        let m = statics::closed_form::max_abs_moment(b).0.abs();
        let depth = m / (d.length_scale / 1000.0 * d.pole_distance);
        let by_scale = super::fields::larger(span, loads / d.force_scale);
        if pole.max(depth) > by_scale.0 || pole.is_nan() || depth.is_nan() {
            (pole.max(depth), "drawing.pole_distance_kg")
        } else {
            by_scale
        }
    }
    type Problem = BeamProblem;
    type Results = statics::BeamResults;

    fn problem(&self, ctx: &ReadContext) -> Result<BeamProblem, SceneError> {
        self.check_values(ctx)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &BeamProblem,
        config: BoardConfig,
    ) -> Result<(Board, statics::BeamResults), ConstructionError> {
        let span =
            (problem.beam.ends[1] - problem.beam.ends[0]) * 1000.0 / problem.drawing.length_scale;
        let mut board = Board::new(config).with_figure_size(span.max(1.0) * 3.0);
        let r = if problem.stringers.is_empty() {
            statics::construct_beam(
                &mut board,
                &problem.beam,
                &problem.drawing,
                &problem.request,
            )?
        } else {
            statics::construct_beam_indirect(
                &mut board,
                &problem.beam,
                &problem.stringers,
                &problem.drawing,
                &problem.request,
            )?
        };
        Ok((board, r))
    }
    fn sweeps(p: &BeamProblem) -> Vec<Setting<'_>> {
        beam_loads(p)
    }
    fn figure_meta(problem: &BeamProblem) -> FigureMeta {
        use crate::fmt::num;
        let d = &problem.drawing;
        FigureMeta {
            title: problem.title.clone(),
            source: super::fields::source_line(
                &problem.source,
                &format!("pole distance H = {} kg", num(d.pole_distance, 6)),
            ),
            scales: vec![
                ScaleBar::length(d.length_scale, "m"),
                ScaleBar::force(d.force_scale),
                ScaleBar::moment(d.length_scale / 1000.0 * d.pole_distance),
            ],
            plate: Vec::new(),
        }
    }
}

/// `x` must lie on the beam between its `ends`.
fn on_beam(f: Fields, field: &str, x: f64, [e0, e1]: [f64; 2]) -> Result<(), SceneError> {
    if x < e0 || x > e1 {
        Err(f.bad(
            field,
            format!(
                "x = {x} m lies outside the beam [{e0}, {e1}] m: declare the overhang with beam.ends_m"
            ),
        ))
    } else {
        Ok(())
    }
}

const POINT_LOADS: [usize; 8] = [1, 2, 4, 8, 16, 32, 64, 128];
const TANGENT_PARTS: [usize; 5] = [2, 4, 8, 16, 64];

/// A beam's uniform loads as n point loads (strip centres), and the parabola by d tangent
/// parts: the largest moment error at the sections, against the uniform loads' exact moment.
fn beam_loads(b: &BeamProblem) -> Vec<Setting<'_>> {
    if b.beam.uniform_loads.is_empty() || !b.request.moment_area {
        return Vec::new();
    }
    let mut out: Vec<Setting<'_>> = Vec::new();
    for &n in &POINT_LOADS {
        out.push(Box::new(move || {
            let mut q = b.clone();
            q.beam = as_point_loads(&b.beam, n);
            let s = moment_error(b, &q, "n point loads for each uniform load", n)?;
            Ok(vec![s])
        }));
    }
    for &d in &TANGENT_PARTS {
        out.push(Box::new(move || {
            let mut q = b.clone();
            q.drawing.parabola_divisions = d;
            Ok(vec![moment_error(
                b,
                &q,
                "parabola by its tangents, d parts",
                d,
            )?])
        }));
    }
    out
}

/// The beam with every uniform load replaced by `n` equal point loads at its strips' centres.
fn as_point_loads(beam: &Beam, n: usize) -> Beam {
    let mut out = beam.clone();
    out.uniform_loads.clear();
    for u in &beam.uniform_loads {
        let w = (u.to - u.from) / n as f64;
        out.point_loads.extend((0..n).map(|k| PointLoad {
            x: u.from + w * (k as f64 + 0.5),
            p: u.q * w,
        }));
    }
    out.point_loads.sort_by(|a, c| a.x.total_cmp(&c.x));
    out
}

/// The largest |M| error over the constructed sections, against the original beam's moment.
fn moment_error(
    orig: &BeamProblem,
    q: &BeamProblem,
    knob: &str,
    setting: usize,
) -> Result<Sweep, ConstructionError> {
    let (r, secs) = timed_drawing(&format_args!("{knob} {setting}"), |c| {
        BeamScene::construct(q, c)
    });
    let res = r?.1;
    let cf = crate::statics::closed_form::Sections::new(&orig.beam);
    let err = res
        .sections
        .iter()
        .map(|s| (s.moment - cf.moment(s.x)).abs())
        .fold(0.0, f64::max);
    // No single exact value: the setting's value is its error.
    let mut s = one(
        knob,
        "largest moment error at the sections",
        "kg·m",
        None,
        setting.to_string(),
        err,
        secs,
    );
    s.scale = cf.max_abs_moment().0.abs();
    Ok(s)
}
