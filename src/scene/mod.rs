//! The scene format: what a user writes to get a figure.
//!
//! A scene is JSON (unknown fields are rejected) naming the mechanism, its speed and piston
//! force, the crank angles, the physical **effects** to include and the **outputs** wanted.
//! Only the constructions the outputs depend on are made ("simulate only what the scene calls
//! for"). `graphostatik schema` prints the JSON Schema of this format.
//!
//! ```
//! let scene = graphostatik::scene::Scene::from_json(r#"{
//!   "title": "KG Tafel I",
//!   "mechanism": { "crank_radius_mm": 400, "rod": { "length_mm": 2000 } },
//!   "speed": { "rpm": 50 },
//!   "angles": { "divisions": 12 },
//!   "outputs": ["piston_path"]
//! }"#, "inline").unwrap();
//! let problem = scene.problem();
//! assert_eq!(problem.drive.lambda(), 0.2);
//! assert!(problem.request.piston_path && !problem.request.tangential_force);
//! ```

mod beam;
mod centroid;
mod defaults;
mod error;
mod force_system;
mod shaft;
mod truss;
mod types;

pub use beam::{
    BeamDrawingSpec, BeamOutput, BeamProblem, BeamScene, BeamSpec, PointLoadSpec, UniformLoadSpec,
    MAX_LOADS,
};
pub use centroid::{CentroidDrawingSpec, CentroidProblem, CentroidScene};
pub use error::SceneError;
pub use force_system::{
    ForceDrawingSpec, ForceSpec, ForceSystemProblem, ForceSystemScene, ResolveSpec,
};
pub use shaft::{ShaftProblem, ShaftScene, TorqueSpec};
pub use truss::{TrussProblem, TrussScene};
pub use types::*;

use crate::crank::{self, Angles, CrankDrive, CrankResults, Drawing, PistonForce, Request};
use crate::kernel::tolerance::MAX_DIVISIONS;
use crate::protocol::{Board, ConstructionError};

/// A validated scene, ready to construct.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Title written on the figure.
    pub title: String,
    /// Book reference written under the title.
    pub source: String,
    /// The mechanism in machine units.
    pub drive: CrankDrive,
    /// The scales of the drawing (given or chosen).
    pub drawing: Drawing,
    /// Crank angles.
    pub angles: Angles,
    /// What to construct.
    pub request: Request,
}

impl Scene {
    /// Parses and validates a scene; `origin` (a file name) prefixes every error message.
    pub fn from_json(text: &str, origin: &str) -> Result<Scene, SceneError> {
        let de = &mut serde_json::Deserializer::from_str(text);
        let scene: Scene =
            serde_path_to_error::deserialize(de).map_err(|e| json_error(e, origin))?;
        scene.validate(origin)?;
        Ok(scene)
    }

    /// Reads, parses and validates a scene file.
    pub fn load(path: &std::path::Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|e| SceneError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        Scene::from_json(&text, &path.display().to_string())
    }

    fn validate(&self, origin: &str) -> Result<(), SceneError> {
        let bad = |field: &str, message: String| SceneError::Invalid {
            origin: origin.to_string(),
            field: field.to_string(),
            message,
        };
        if let Some(p) = &self.procedure {
            if p != "slider_crank" {
                return Err(bad("procedure", format!("unknown procedure `{p}`")));
            }
        }
        let positive = |field: &str, x: f64| {
            if x.is_finite() && x > 0.0 {
                Ok(())
            } else {
                Err(bad(
                    field,
                    format!("must be a positive length or number, got {x}"),
                ))
            }
        };
        let m = &self.mechanism;
        let r = match (m.crank_radius_mm, m.stroke_mm) {
            (Some(r), None) => {
                positive("mechanism.crank_radius_mm", r)?;
                r
            }
            (None, Some(s)) => {
                positive("mechanism.stroke_mm", s)?;
                s / 2.0
            }
            (Some(_), Some(_)) => {
                return Err(bad(
                    "mechanism",
                    "give either crank_radius_mm or stroke_mm, not both".into(),
                ))
            }
            (None, None) => {
                return Err(bad(
                    "mechanism",
                    "missing field `crank_radius_mm` (or `stroke_mm`)".into(),
                ))
            }
        };
        match m.rod {
            Rod::LengthMm(l) => {
                positive("mechanism.rod.length_mm", l)?;
                if l <= r {
                    return Err(bad(
                        "mechanism.rod.length_mm",
                        format!(
                            "the rod (L = {l} mm) must be longer than the crank (R = {r} mm): \
                             otherwise the mechanism locks where the crank stands perpendicular \
                             to the piston line"
                        ),
                    ));
                }
            }
            Rod::LOverR(k) => {
                positive("mechanism.rod.l_over_r", k)?;
                if k <= 1.0 {
                    return Err(bad(
                        "mechanism.rod.l_over_r",
                        format!(
                            "L/R = {k}: the rod must be longer than the crank (L/R > 1), \
                             otherwise the mechanism locks"
                        ),
                    ));
                }
            }
        }
        match &self.speed {
            Speed::Rpm(n) => positive("speed.rpm", *n)?,
            Speed::CrankPinMS(v) => positive("speed.crank_pin_m_s", *v)?,
            Speed::Train {
                km_h,
                wheel_diameter_mm,
            } => {
                positive("speed.train.km_h", *km_h)?;
                positive("speed.train.wheel_diameter_mm", *wheel_diameter_mm)?;
            }
        }
        let n_angles = match &self.angles {
            AngleSpec::Divisions(n) => {
                if *n < 2 || *n > MAX_DIVISIONS {
                    return Err(bad(
                        "angles.divisions",
                        format!("{n} divisions: give between 2 and {MAX_DIVISIONS}"),
                    ));
                }
                *n
            }
            AngleSpec::Degrees(v) => {
                if v.is_empty() || v.len() > MAX_DIVISIONS {
                    return Err(bad(
                        "angles.degrees",
                        format!("{} angles: give between 1 and {MAX_DIVISIONS}", v.len()),
                    ));
                }
                for (k, a) in v.iter().enumerate() {
                    if !(a.is_finite() && (0.0..360.0).contains(a)) {
                        return Err(bad(
                            &format!("angles.degrees[{k}]"),
                            format!("crank angle {a}° is out of range: give 0 ≤ θ < 360"),
                        ));
                    }
                }
                v.len()
            }
        };
        if self.outputs.is_empty() {
            return Err(bad("outputs", "ask for at least one output".into()));
        }
        let needs_force = self.outputs.iter().any(|o| o.is_force());
        match (&self.piston_force, needs_force) {
            (None, true) => {
                return Err(bad(
                    "piston_force",
                    "missing: the outputs ask for forces, so the piston force is needed".into(),
                ))
            }
            (Some(PistonForceSpec::Kg(p)), _) => {
                if !p.is_finite() {
                    return Err(bad("piston_force.kg", "must be a finite number".into()));
                }
            }
            (Some(PistonForceSpec::Pressure(p)), _) => {
                positive("piston_force.pressure.bore_mm", p.bore_mm)?;
                if !p.at.is_finite() {
                    return Err(bad(
                        "piston_force.pressure.at",
                        "must be a finite number".into(),
                    ));
                }
                if !(p.rod_diameter_mm.is_finite()
                    && p.rod_diameter_mm >= 0.0
                    && p.rod_diameter_mm < p.bore_mm)
                {
                    return Err(bad(
                        "piston_force.pressure.rod_diameter_mm",
                        format!(
                            "must lie in [0, bore) = [0, {}), got {}",
                            p.bore_mm, p.rod_diameter_mm
                        ),
                    ));
                }
            }
            (Some(PistonForceSpec::PerAngleKg(v)), _) => {
                if v.len() != n_angles {
                    return Err(bad(
                        "piston_force.per_angle_kg",
                        format!("{} forces for {n_angles} crank angles", v.len()),
                    ));
                }
                if let Some(k) = v.iter().position(|x| !x.is_finite()) {
                    return Err(bad(
                        &format!("piston_force.per_angle_kg[{k}]"),
                        "must be a finite number".into(),
                    ));
                }
            }
            (None, false) => {}
        }
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                (
                    "drawing.velocity_scale_m_s_per_mm",
                    d.velocity_scale_m_s_per_mm,
                ),
            ] {
                if let Some(v) = v {
                    positive(name, v)?;
                }
            }
        }
        Ok(())
    }

    /// The crank radius in mm.
    pub fn crank_radius(&self) -> f64 {
        self.mechanism
            .crank_radius_mm
            .unwrap_or_else(|| self.mechanism.stroke_mm.unwrap_or(0.0) / 2.0)
    }

    /// Maps the validated scene to the problem the crank procedures solve.
    pub fn problem(&self) -> Problem {
        let r = self.crank_radius();
        let l = match self.mechanism.rod {
            Rod::LengthMm(l) => l,
            Rod::LOverR(k) => k * r,
        };
        let v = match &self.speed {
            Speed::Rpm(n) => 2.0 * std::f64::consts::PI * (r / 1000.0) * n / 60.0,
            Speed::CrankPinMS(v) => *v,
            // LH: v = v₁ · s / D₁ (crank pin against the wheel rim, same angular speed).
            Speed::Train {
                km_h,
                wheel_diameter_mm,
            } => km_h / 3.6 * (2.0 * r) / wheel_diameter_mm,
        };
        let angles = match &self.angles {
            AngleSpec::Divisions(n) => Angles::Divisions(*n),
            AngleSpec::Degrees(v) => Angles::Degrees(v.clone()),
        };
        let piston_force = match &self.piston_force {
            None => PistonForce::Constant(0.0),
            Some(PistonForceSpec::Kg(p)) => PistonForce::Constant(*p),
            Some(PistonForceSpec::Pressure(p)) => PistonForce::Constant(p.force_kg()),
            Some(PistonForceSpec::PerAngleKg(v)) => PistonForce::PerAngle(v.clone()),
        };
        let effects = self.effects.unwrap_or_default();
        let drive = CrankDrive {
            crank_radius: r,
            rod_length: l,
            finite_rod: effects.finite_rod,
            crank_pin_speed: v,
            piston_force,
        };
        let mut request = Request::default();
        for o in &self.outputs {
            match o {
                Output::PistonPath => request.piston_path = true,
                Output::Velocity => {
                    let methods = self
                        .velocity_methods
                        .clone()
                        .unwrap_or_else(|| vec![VelocityMethod::Parallel]);
                    for m in methods {
                        match m {
                            VelocityMethod::Parallel => request.velocity_parallel = true,
                            VelocityMethod::InstantCentre => request.velocity_instant_centre = true,
                        }
                    }
                }
                Output::RodForce => request.rod_force = true,
                Output::GuideForce => request.guide_force = true,
                Output::TangentialForce => request.tangential_force = true,
                Output::RadialForce => request.radial_force = true,
            }
        }
        let drawing = defaults::drawing(self.drawing.as_ref(), &drive);
        Problem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            drive,
            drawing,
            angles,
            request,
        }
    }
}

impl Problem {
    /// What the sheet writes besides the construction: title, source and the scale bars.
    pub fn figure_meta(&self) -> crate::render::FigureMeta {
        let d = &self.drawing;
        let r = &self.request;
        let mut scales = vec![bars::length(d.length_scale, "mm")];
        if r.velocity_parallel || r.velocity_instant_centre {
            scales.push(bars::velocity(d.velocity_scale));
        }
        if r.rod_force || r.guide_force || r.tangential_force || r.radial_force {
            scales.push(bars::force(d.force_scale));
        }
        let rod = if self.drive.finite_rod {
            format!(
                "R = {} mm, L = {} mm (R/L = 1/{})",
                crate::fmt::num(self.drive.crank_radius, 3),
                crate::fmt::num(self.drive.rod_length, 3),
                crate::fmt::num(self.drive.rod_length / self.drive.crank_radius, 3)
            )
        } else {
            format!(
                "R = {} mm, infinitely long rod",
                crate::fmt::num(self.drive.crank_radius, 3)
            )
        };
        let source = if self.source.is_empty() {
            rod
        } else {
            format!(
                "{} — {rod}, v = {} m/s",
                self.source,
                crate::fmt::num(self.drive.crank_pin_speed, 4)
            )
        };
        crate::render::FigureMeta {
            title: self.title.clone(),
            source,
            scales,
        }
    }

    /// The size of the figure on the sheet (mm), for the tolerance.
    pub fn figure_size(&self) -> f64 {
        let d = &self.drawing;
        let pmax = self.drive.piston_force.max_abs();
        (2.0 * self.drive.crank_radius + self.drive.rod_length) / d.length_scale
            + 3.0 * pmax / d.force_scale
            + self.drive.crank_pin_speed / d.velocity_scale
    }

    /// Constructs the problem on a fresh board (`recording`: keep steps and checks).
    pub fn construct(&self, recording: bool) -> Result<(Board, CrankResults), ConstructionError> {
        let mut board = Board::new(self.figure_size(), recording);
        let res = crank::construct(
            &mut board,
            &self.drive,
            &self.drawing,
            &self.angles,
            &self.request,
        )?;
        Ok((board, res))
    }
}

/// serde_json appends " at line L column C" to its messages; the error reports those apart.
fn strip_position(msg: &str) -> String {
    match msg.rfind(" at line ") {
        Some(k) => msg[..k].to_string(),
        None => msg.to_string(),
    }
}

/// The JSON Schema of the scene format, pretty-printed: one of the procedures' scenes.
pub fn schema_json() -> String {
    let schema = schemars::schema_for!(AnySceneSchema);
    serde_json::to_string_pretty(&schema).expect("a schema is plain JSON")
}

/// The scene format as a whole: a slider-crank scene (`"procedure": "slider_crank"`, the
/// default), a beam scene (`"procedure": "beam"`), a force system
/// (`"procedure": "force_system"`), a centroid (`"procedure": "centroid"`), a shaft
/// (`"procedure": "shaft"`) or a truss (`"procedure": "truss"`).
#[derive(schemars::JsonSchema)]
#[serde(untagged)]
#[allow(dead_code)]
enum AnySceneSchema {
    /// A slider-crank scene.
    SliderCrank(Scene),
    /// A beam scene.
    Beam(BeamScene),
    /// A force-system scene.
    ForceSystem(ForceSystemScene),
    /// A centroid scene.
    Centroid(CentroidScene),
    /// A shaft scene.
    Shaft(ShaftScene),
    /// A truss scene.
    Truss(TrussScene),
}

/// A scene of any procedure, validated.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyScene {
    /// Slider-crank (LH II, KG XIV B).
    SliderCrank(Scene),
    /// Beam (LH I C).
    Beam(BeamScene),
    /// Forces in the plane (LH I A, C.2).
    ForceSystem(ForceSystemScene),
    /// Centroid of a polygon (LH I C.3).
    Centroid(CentroidScene),
    /// Shaft with loads in two planes and a torque (LH I C.7-8).
    Shaft(ShaftScene),
    /// Truss with load cases (LH I B).
    Truss(TrussScene),
}

/// A constructible problem of any procedure.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyProblem {
    /// Slider-crank.
    SliderCrank(Problem),
    /// Beam.
    Beam(BeamProblem),
    /// Forces in the plane.
    ForceSystem(ForceSystemProblem),
    /// Centroid of a polygon.
    Centroid(CentroidProblem),
    /// Shaft.
    Shaft(ShaftProblem),
    /// Truss.
    Truss(TrussProblem),
}

#[derive(serde::Deserialize)]
struct ProcedureProbe {
    #[serde(default)]
    procedure: Option<String>,
}

impl AnyScene {
    /// Parses and validates a scene of any procedure, by its `procedure` field.
    pub fn from_json(text: &str, origin: &str) -> Result<AnyScene, SceneError> {
        // A first look for the procedure only; the real parse keeps line and column.
        let probe: Option<ProcedureProbe> = serde_json::from_str(text).ok();
        match probe.and_then(|p| p.procedure).as_deref() {
            Some("beam") => parse_as::<BeamScene>(text, origin).map(AnyScene::Beam),
            Some("force_system") => {
                parse_as::<ForceSystemScene>(text, origin).map(AnyScene::ForceSystem)
            }
            Some("centroid") => parse_as::<CentroidScene>(text, origin).map(AnyScene::Centroid),
            Some("shaft") => parse_as::<ShaftScene>(text, origin).map(AnyScene::Shaft),
            Some("truss") => parse_as::<TrussScene>(text, origin).map(AnyScene::Truss),
            _ => Scene::from_json(text, origin).map(AnyScene::SliderCrank),
        }
    }

    /// Reads, parses and validates a scene file of any procedure.
    pub fn load(path: &std::path::Path) -> Result<AnyScene, SceneError> {
        let text = std::fs::read_to_string(path).map_err(|e| SceneError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        AnyScene::from_json(&text, &path.display().to_string())
    }

    /// The problem the scene describes.
    pub fn problem(&self) -> AnyProblem {
        match self {
            AnyScene::SliderCrank(s) => AnyProblem::SliderCrank(s.problem()),
            AnyScene::Beam(s) => AnyProblem::Beam(s.problem()),
            AnyScene::ForceSystem(s) => AnyProblem::ForceSystem(s.problem()),
            AnyScene::Centroid(s) => AnyProblem::Centroid(s.problem()),
            AnyScene::Shaft(s) => AnyProblem::Shaft(s.problem()),
            AnyScene::Truss(s) => AnyProblem::Truss(s.problem()),
        }
    }
}

impl AnyProblem {
    /// Constructs the problem on a fresh board (the results are in the protocol).
    pub fn construct(&self, recording: bool) -> Result<Board, ConstructionError> {
        match self {
            AnyProblem::SliderCrank(p) => p.construct(recording).map(|(b, _)| b),
            AnyProblem::Beam(p) => p.construct(recording).map(|(b, _)| b),
            AnyProblem::ForceSystem(p) => p.construct(recording).map(|(b, _)| b),
            AnyProblem::Centroid(p) => p.construct(recording).map(|(b, _)| b),
            AnyProblem::Shaft(p) => p.construct(recording).map(|(b, _)| b),
            AnyProblem::Truss(p) => p.construct(recording).map(|(b, _)| b),
        }
    }

    /// Title, source and scale bars of the figure.
    pub fn figure_meta(&self) -> crate::render::FigureMeta {
        match self {
            AnyProblem::SliderCrank(p) => p.figure_meta(),
            AnyProblem::Beam(p) => p.figure_meta(),
            AnyProblem::ForceSystem(p) => p.figure_meta(),
            AnyProblem::Centroid(p) => p.figure_meta(),
            AnyProblem::Shaft(p) => p.figure_meta(),
            AnyProblem::Truss(p) => p.figure_meta(),
        }
    }
}

/// The line under a figure's title: the book reference, then what the figure is drawn with.
fn source_line(source: &str, detail: &str) -> String {
    if source.is_empty() {
        detail.to_string()
    } else {
        format!("{source} — {detail}")
    }
}

/// Checks that every scale or pole given (`Some`) is a positive, finite number.
fn optional_positive(origin: &str, fields: &[(&str, Option<f64>)]) -> Result<(), SceneError> {
    for &(name, v) in fields {
        if let Some(v) = v {
            if !(v.is_finite() && v > 0.0) {
                return Err(SceneError::Invalid {
                    origin: origin.to_string(),
                    field: name.to_string(),
                    message: format!("must be positive, got {v}"),
                });
            }
        }
    }
    Ok(())
}

/// The scale bars a sheet writes: length 1 : n (machine unit per mm shown in m or mm), force,
/// moment, area, velocity. German names as the books write them.
mod bars {
    use crate::fmt::num;
    use crate::render::ScaleBar;

    /// Längenmaßstab 1 : n, the bar in `unit` ("m" or "mm").
    pub fn length(n: f64, unit: &str) -> ScaleBar {
        let per_mm = if unit == "m" { n / 1000.0 } else { n };
        ScaleBar {
            name: format!("Längenmaßstab 1 : {}", num(n, 6)),
            per_mm,
            unit: unit.into(),
        }
    }
    /// Kräftemaßstab 1 mm = f kg.
    pub fn force(f: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Kräftemaßstab 1 mm = {} kg", num(f, 6)),
            per_mm: f,
            unit: "kg".into(),
        }
    }
    /// Momentenmaßstab 1 mm = m kg·m.
    pub fn moment(m: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Momentenmaßstab 1 mm = {} kg·m", num(m, 6)),
            per_mm: m,
            unit: "kg·m".into(),
        }
    }
    /// Flächenmaßstab 1 mm = a m².
    pub fn area(a: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Flächenmaßstab 1 mm = {} m²", num(a, 6)),
            per_mm: a,
            unit: "m²".into(),
        }
    }
    /// Geschwindigkeitsmaßstab 1 mm = v m/s.
    pub fn velocity(v: f64) -> ScaleBar {
        ScaleBar {
            name: format!("Geschwindigkeitsmaßstab 1 mm = {} m/s", num(v, 6)),
            per_mm: v,
            unit: "m/s".into(),
        }
    }
}

/// A scene type that checks its own values after parsing.
trait Validate {
    fn validate(&self, origin: &str) -> Result<(), SceneError>;
}

macro_rules! validate_by_method {
    ($($t:ty),*) => {$(
        impl Validate for $t {
            fn validate(&self, origin: &str) -> Result<(), SceneError> {
                <$t>::validate(self, origin)
            }
        }
    )*};
}
validate_by_method!(
    BeamScene,
    ForceSystemScene,
    CentroidScene,
    ShaftScene,
    TrussScene
);

/// Parses a scene of one procedure, keeping field path, line and column, then validates it.
fn parse_as<T: serde::de::DeserializeOwned + Validate>(
    text: &str,
    origin: &str,
) -> Result<T, SceneError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    let scene: T = serde_path_to_error::deserialize(de).map_err(|e| json_error(e, origin))?;
    scene.validate(origin)?;
    Ok(scene)
}

fn json_error(e: serde_path_to_error::Error<serde_json::Error>, origin: &str) -> SceneError {
    let field = e.path().to_string();
    let inner = e.into_inner();
    SceneError::Json {
        origin: origin.to_string(),
        line: inner.line(),
        column: inner.column(),
        field: if field == "." { String::new() } else { field },
        message: strip_position(&inner.to_string()),
    }
}
