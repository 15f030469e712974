//! The slider-crank scene (LH II, KG XIV B): its validation, its problem in machine units and
//! the figure's metadata.

use super::defaults;
use super::error::SceneError;
use super::fields::Fields;
use super::procedure::Procedure;
use super::procedure::ReadContext;
use super::sweep::{mean_over_divisions, timed_drawing, MeanOf, Setting};
use super::types::*;
use crate::crank::{self, Angles, CrankDrive, CrankResults, Drawing, PistonForce, Request};
use crate::kernel::tolerance::MAX_DIVISIONS;
use crate::kernel::tolerance::MIN_ROD_EXCESS;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};

/// A validated scene, ready to construct.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderCrankProblem {
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

impl SliderCrankScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let r = self.mechanism.check(f)?;
        self.mechanism.check_rod(f, r)?;
        self.speed.check(f)?;
        let n_angles = self.angles.check(f)?;
        self.check_outputs_and_force(f, n_angles)?;
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
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

    /// At least one output; the piston force where a force is asked for, finite, and one per
    /// angle where given per angle.
    fn check_outputs_and_force(&self, f: Fields, n_angles: usize) -> Result<(), SceneError> {
        if self.outputs.is_empty() {
            return Err(f.bad("outputs", "ask for at least one output".into()));
        }
        let needs_force = self.outputs.iter().any(|o| o.is_force());
        match (&self.piston_force, needs_force) {
            (None, true) => {
                return Err(f.bad(
                    "piston_force",
                    "missing: the outputs ask for forces, so the piston force is needed".into(),
                ))
            }
            (Some(PistonForceSpec::Kg(p)), _) => {
                if !p.is_finite() {
                    return Err(f.bad("piston_force.kg", "must be a finite number".into()));
                }
            }
            (Some(PistonForceSpec::Pressure(p)), _) => {
                f.positive("piston_force.pressure.bore_mm", p.bore_mm)?;
                if !p.at.is_finite() {
                    return Err(f.bad("piston_force.pressure.at", "must be a finite number".into()));
                }
                if !(p.rod_diameter_mm.is_finite()
                    && p.rod_diameter_mm >= 0.0
                    && p.rod_diameter_mm < p.bore_mm)
                {
                    return Err(f.bad(
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
                    return Err(f.bad(
                        "piston_force.per_angle_kg",
                        format!("{} forces for {n_angles} crank angles", v.len()),
                    ));
                }
                if let Some(k) = v.iter().position(|x| !x.is_finite()) {
                    return Err(f.bad(
                        &format!("piston_force.per_angle_kg[{k}]"),
                        "must be a finite number".into(),
                    ));
                }
            }
            (None, false) => {}
        }
        Ok(())
    }

    /// The crank radius in mm.
    pub fn crank_radius(&self) -> f64 {
        self.mechanism.radius()
    }

    /// Maps the validated scene to the problem the crank procedures solve.
    fn to_problem(&self) -> SliderCrankProblem {
        let r = self.crank_radius();
        let l = self.mechanism.rod_length();
        let v = self.speed.crank_pin_speed(r);
        let angles = self.angles.angles();
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
                CrankOutput::PistonPath => {
                    let methods = self
                        .piston_path_methods
                        .clone()
                        .unwrap_or_else(|| vec![PistonPathMethod::RodArc]);
                    for m in methods {
                        match m {
                            PistonPathMethod::RodArc => request.piston_path = true,
                            PistonPathMethod::FixedArc => request.piston_path_fixed_arc = true,
                        }
                    }
                }
                CrankOutput::Velocity => {
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
                CrankOutput::RodForce => request.rod_force = true,
                CrankOutput::GuideForce => request.guide_force = true,
                CrankOutput::TangentialForce => request.tangential_force = true,
                CrankOutput::RadialForce => request.radial_force = true,
                CrankOutput::Acceleration => request.acceleration = true,
                CrankOutput::MaxVelocity => request.max_velocity = true,
                CrankOutput::PolarDiagrams => {
                    request.tangential_force = true;
                    request.polar_diagrams = true;
                }
            }
        }
        let drawing = defaults::drawing(self.drawing.as_ref(), &drive);
        SliderCrankProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            drive,
            drawing,
            angles,
            request,
        }
    }
}

impl Mechanism {
    /// The crank: its radius or its stroke, one of them, positive: the radius (mm).
    pub(super) fn check(&self, f: Fields) -> Result<f64, SceneError> {
        check_crank(f, "mechanism", (self.crank_radius_mm, self.stroke_mm))
    }

    /// The rod: positive and longer than the crank radius `r`.
    pub(super) fn check_rod(&self, f: Fields, r: f64) -> Result<(), SceneError> {
        self.rod.check(f, "mechanism.rod", r)
    }

    /// The crank radius R (mm): given, or half the stroke.
    pub fn radius(&self) -> f64 {
        crank_radius((self.crank_radius_mm, self.stroke_mm))
    }

    /// The rod length L (mm).
    pub fn rod_length(&self) -> f64 {
        self.rod.length(self.radius())
    }
}

/// The crank radius (mm) of a crank given by its radius or its stroke.
pub(super) fn crank_radius((radius, stroke): (Option<f64>, Option<f64>)) -> f64 {
    radius.unwrap_or_else(|| stroke.unwrap_or(0.0) / 2.0)
}

/// A crank given by its radius or its stroke (the fields `crank_radius_mm`, `stroke_mm` under
/// `at`), one of them, positive: the radius (mm). Shared by every scene with a crank.
pub(super) fn check_crank(
    f: Fields,
    at: &str,
    (radius, stroke): (Option<f64>, Option<f64>),
) -> Result<f64, SceneError> {
    match (radius, stroke) {
        (Some(r), None) => {
            f.positive(&format!("{at}.crank_radius_mm"), r)?;
            Ok(r)
        }
        (None, Some(s)) => {
            f.positive(&format!("{at}.stroke_mm"), s)?;
            Ok(s / 2.0)
        }
        (Some(_), Some(_)) => Err(f.bad(
            at,
            "give either crank_radius_mm or stroke_mm, not both".into(),
        )),
        (None, None) => Err(f.bad(
            at,
            "missing field `crank_radius_mm` (or `stroke_mm`)".into(),
        )),
    }
}

impl Rod {
    /// The rod length L (mm) beside a crank of radius `r`.
    pub fn length(&self, r: f64) -> f64 {
        match *self {
            Rod::LengthMm(l) => l,
            Rod::LOverR(k) => k * r,
        }
    }

    /// The rod (the field `at`): positive and longer than the crank radius `r` by more
    /// than [`MIN_ROD_EXCESS`] of it. Shared by every scene with a rod.
    pub(super) fn check(&self, f: Fields, at: &str, r: f64) -> Result<(), SceneError> {
        let field = |name: &str| format!("{at}.{name}");
        match *self {
            Rod::LengthMm(l) => {
                f.positive(&field("length_mm"), l)?;
                if l <= r {
                    return Err(f.bad(
                        &field("length_mm"),
                        format!(
                            "the rod (L = {l} mm) must be longer than the crank (R = {r} mm): \
                             otherwise the mechanism locks where the crank stands perpendicular \
                             to the piston line"
                        ),
                    ));
                }
            }
            Rod::LOverR(k) => {
                f.positive(&field("l_over_r"), k)?;
                if k <= 1.0 {
                    return Err(f.bad(
                        &field("l_over_r"),
                        format!(
                            "L/R = {k}: the rod must be longer than the crank (L/R > 1), \
                             otherwise the mechanism locks"
                        ),
                    ));
                }
            }
        }
        // Nearer to locking, the rod's arc cuts the piston line at 90° so glancingly that the
        // forces lose more digits than their checks allow (at L/R = 1 + 1e-9 they were 0.35 kg
        // off against a 0.022 kg tolerance): refused, with the reason.
        let (l, name) = match *self {
            Rod::LengthMm(l) => (l, "length_mm"),
            Rod::LOverR(k) => (k * r, "l_over_r"),
        };
        if l <= r * (1.0 + MIN_ROD_EXCESS) {
            return Err(f.bad(
                &field(name),
                format!(
                    "the rod is only {} of the crank longer than the crank: the construction \
                     near 90° needs at least {}",
                    crate::fmt::sci((l - r) / r),
                    crate::fmt::sci(MIN_ROD_EXCESS)
                ),
            ));
        }
        Ok(())
    }
}

impl AngleSpec {
    /// The crank angles: 2 to MAX_DIVISIONS divisions, or 1 to MAX_DIVISIONS angles in
    /// [0°, 360°): their number.
    pub(super) fn check(&self, f: Fields) -> Result<usize, SceneError> {
        Ok(match self {
            AngleSpec::Divisions(n) => {
                if *n < 2 || *n > MAX_DIVISIONS {
                    return Err(f.bad(
                        "angles.divisions",
                        format!("{n} divisions: give between 2 and {MAX_DIVISIONS}"),
                    ));
                }
                *n
            }
            AngleSpec::Degrees(v) => {
                if v.is_empty() || v.len() > MAX_DIVISIONS {
                    return Err(f.bad(
                        "angles.degrees",
                        format!("{} angles: give between 1 and {MAX_DIVISIONS}", v.len()),
                    ));
                }
                for (k, a) in v.iter().enumerate() {
                    if !(a.is_finite() && (0.0..360.0).contains(a)) {
                        return Err(f.bad(
                            &format!("angles.degrees[{k}]"),
                            format!("crank angle {a}° is out of range: give 0 ≤ θ < 360"),
                        ));
                    }
                }
                v.len()
            }
            AngleSpec::StrokeParts(n) => {
                if *n < 1 || 2 * n > MAX_DIVISIONS {
                    return Err(f.bad(
                        "angles.stroke_parts",
                        format!("{n} parts: give between 1 and {}", MAX_DIVISIONS / 2),
                    ));
                }
                2 * n
            }
        })
    }

    /// [`AngleSpec::check`] for a mechanism other than the slider-crank, which has no rod
    /// arcs to divide the stroke by: `stroke_parts` is refused.
    pub(super) fn check_divisions_or_degrees(&self, f: Fields) -> Result<usize, SceneError> {
        if let AngleSpec::StrokeParts(_) = self {
            return Err(f.bad(
                "angles.stroke_parts",
                "the stroke divided by rod arcs is the straight slider-crank's construction: \
                 give divisions or degrees"
                    .into(),
            ));
        }
        self.check(f)
    }

    /// The angles in degrees: n divisions of the circle from 0°, or the degrees given (none
    /// for stroke parts, which [`AngleSpec::check_divisions_or_degrees`] refuses).
    pub(super) fn degrees(&self) -> Vec<f64> {
        match self {
            AngleSpec::Divisions(n) => (0..*n).map(|k| 360.0 * k as f64 / *n as f64).collect(),
            AngleSpec::Degrees(v) => v.clone(),
            AngleSpec::StrokeParts(_) => Vec::new(),
        }
    }

    /// The angles in machine terms.
    pub(super) fn angles(&self) -> Angles {
        match self {
            AngleSpec::Divisions(n) => Angles::Divisions(*n),
            AngleSpec::Degrees(v) => Angles::Degrees(v.clone()),
            AngleSpec::StrokeParts(n) => Angles::StrokeParts(*n),
        }
    }
}

impl Speed {
    /// The speed: positive numbers.
    pub(super) fn check(&self, f: Fields) -> Result<(), SceneError> {
        match self {
            Speed::Rpm(n) => f.positive("speed.rpm", *n)?,
            Speed::CrankPinMS(v) => f.positive("speed.crank_pin_m_s", *v)?,
            Speed::Train {
                km_h,
                wheel_diameter_mm,
            } => {
                f.positive("speed.train.km_h", *km_h)?;
                f.positive("speed.train.wheel_diameter_mm", *wheel_diameter_mm)?;
            }
        }
        Ok(())
    }

    /// The speed against the crank radius `r` (mm): a crank-pin speed or revolutions per
    /// minute beyond what a number holds (a wheel of 1e-300 mm) are refused, naming the
    /// field, so that no power or force reckoned from them overflows.
    pub(super) fn check_revolutions(&self, f: Fields, r: f64) -> Result<(), SceneError> {
        let v = self.crank_pin_speed(r);
        let n = crate::dynamics::model::revolutions_per_minute(v, r);
        if v.is_finite() && n.is_finite() {
            return Ok(());
        }
        let field = match self {
            Speed::Rpm(_) => "speed.rpm",
            Speed::CrankPinMS(_) => "speed.crank_pin_m_s",
            Speed::Train { .. } => "speed.train.wheel_diameter_mm",
        };
        Err(f.bad(
            field,
            "gives a crank speed beyond the numbers the engine can hold: give a realistic speed"
                .into(),
        ))
    }

    /// The crank-pin speed v (m/s) for the crank radius `r` (mm).
    pub fn crank_pin_speed(&self, r: f64) -> f64 {
        match self {
            Speed::Rpm(n) => 2.0 * std::f64::consts::PI * (r / 1000.0) * n / 60.0,
            Speed::CrankPinMS(v) => *v,
            // LH: v = v₁ · s / D₁ (crank pin against the wheel rim, same angular speed).
            Speed::Train {
                km_h,
                wheel_diameter_mm,
            } => km_h / 3.6 * (2.0 * r) / wheel_diameter_mm,
        }
    }
}

impl SliderCrankProblem {
    /// The size of the figure on the sheet (mm), for the tolerance.
    pub fn figure_size(&self) -> f64 {
        let d = &self.drawing;
        let pmax = self.drive.piston_force.max_abs();
        (2.0 * self.drive.crank_radius + self.drive.rod_length) / d.length_scale
            + 3.0 * pmax / d.force_scale
            + self.drive.crank_pin_speed / d.velocity_scale
            + if self.request.acceleration {
                2.0 * self.drive.v2_over_r() / d.acceleration_scale
            } else {
                0.0
            }
    }
}

impl Procedure for SliderCrankScene {
    const NAME: &'static str = "slider_crank";
    const SIZED_BY: &'static str = "angles (crank positions) or outputs";
    const ABOUT: &'static str = "the slider-crank: piston path, piston velocity, rod, guide, radial and tangential forces (LH II, KG XIV B)";
    const OUTPUTS: &'static [&'static str] = CrankOutput::NAMES;
    const GEOMETRY_FIELD: &'static str = "mechanism";

    fn sheet_extent(p: &SliderCrankProblem) -> (f64, &'static str) {
        let d = &p.drawing;
        let length = (2.0 * p.drive.crank_radius + p.drive.rod_length) / d.length_scale;
        let force = 3.0 * p.drive.piston_force.max_abs() / d.force_scale;
        let speed = p.drive.crank_pin_speed / d.velocity_scale;
        let accel = if p.request.acceleration {
            2.0 * p.drive.v2_over_r() / d.acceleration_scale
        } else {
            0.0
        };
        if accel > length.max(force).max(speed) {
            (accel, "drawing.acceleration_scale_m_s2_per_mm")
        } else if speed > length.max(force) {
            (speed, "drawing.velocity_scale_m_s_per_mm")
        } else {
            super::fields::larger(length, force)
        }
    }
    fn smallest_part(p: &SliderCrankProblem) -> Option<(f64, &'static str)> {
        let (d, r) = (&p.drawing, &p.request);
        let forces = r.rod_force || r.guide_force || r.tangential_force || r.radial_force;
        let parts = [
            (r.velocity_parallel || r.velocity_instant_centre || r.max_velocity).then(|| {
                (
                    p.drive.crank_pin_speed / d.velocity_scale,
                    "drawing.velocity_scale_m_s_per_mm",
                )
            }),
            // The largest acceleration is (1 + λ)·v²/r, at least v²/r.
            r.acceleration.then(|| {
                (
                    p.drive.v2_over_r() / d.acceleration_scale,
                    "drawing.acceleration_scale_m_s2_per_mm",
                )
            }),
            (forces && p.drive.piston_force.max_abs() > 0.0).then(|| {
                (
                    p.drive.piston_force.max_abs() / d.force_scale,
                    "drawing.force_scale_kg_per_mm",
                )
            }),
        ];
        parts
            .into_iter()
            .flatten()
            .min_by(|a, b| a.0.total_cmp(&b.0))
    }
    type Problem = SliderCrankProblem;
    type Results = CrankResults;

    fn problem(&self, ctx: &ReadContext) -> Result<SliderCrankProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &SliderCrankProblem,
        config: BoardConfig,
    ) -> Result<(Board, CrankResults), ConstructionError> {
        let mut board = Board::new(config).with_figure_size(problem.figure_size());
        let res = crank::construct(
            &mut board,
            &problem.drive,
            &problem.drawing,
            &problem.angles,
            &problem.request,
        )?;
        Ok((board, res))
    }
    fn sweeps(p: &SliderCrankProblem) -> Vec<Setting<'_>> {
        crank_divisions(p)
    }
    fn figure_meta(problem: &SliderCrankProblem) -> FigureMeta {
        let d = &problem.drawing;
        let r = &problem.request;
        let mut scales = vec![ScaleBar::length(d.length_scale, "mm")];
        if r.velocity_parallel || r.velocity_instant_centre || r.max_velocity {
            scales.push(ScaleBar::velocity(d.velocity_scale));
        }
        if r.acceleration {
            scales.push(ScaleBar::acceleration(d.acceleration_scale));
        }
        if r.rod_force || r.guide_force || r.tangential_force || r.radial_force {
            scales.push(ScaleBar::force(d.force_scale));
        }
        let rod = if problem.drive.finite_rod {
            format!(
                "R = {} mm, L = {} mm (R/L = 1 : {})",
                crate::fmt::num(problem.drive.crank_radius, 3),
                crate::fmt::num(problem.drive.rod_length, 3),
                crate::fmt::book_number(problem.drive.rod_length / problem.drive.crank_radius, 2)
            )
        } else {
            format!(
                "R = {} mm, infinitely long rod",
                crate::fmt::num(problem.drive.crank_radius, 3)
            )
        };
        let source = if problem.source.is_empty() {
            rod
        } else {
            format!(
                "{} — {rod}, v = {} m/s",
                problem.source,
                crate::fmt::num(problem.drive.crank_pin_speed, 4)
            )
        };
        FigureMeta {
            title: problem.title.clone(),
            source,
            scales,
            plate: Vec::new(),
        }
    }
}

/// Crank angles swept, against 2P/π (constant piston force, tangential force asked for) or
/// 2v/π (the mean piston speed, velocity asked for).
fn crank_divisions(c: &SliderCrankProblem) -> Vec<Setting<'_>> {
    let by_t =
        c.request.tangential_force && matches!(c.drive.piston_force, PistonForce::Constant(_));
    let what = if by_t {
        MeanOf {
            quantity: "mean tangential force T_m (of the divisions)",
            unit: "kg",
            exact: 2.0 * c.drive.piston_force.max_abs() / std::f64::consts::PI,
        }
    } else if c.request.velocity_parallel || c.request.velocity_instant_centre {
        MeanOf {
            quantity: "mean piston speed (of the divisions)",
            unit: "m/s",
            exact: 2.0 * c.drive.crank_pin_speed / std::f64::consts::PI,
        }
    } else {
        return Vec::new();
    };
    mean_over_divisions(what, move |n| {
        let mut q = c.clone();
        q.angles = Angles::Divisions(n);
        let (r, secs) = timed_drawing(&format_args!("{n} crank divisions"), |c| {
            SliderCrankScene::construct(&q, c)
        });
        let rows = r?.1.rows;
        let sample = rows.iter().filter_map(|r| {
            if by_t {
                r.tangential_force
            } else {
                r.c_parallel.or(r.c_instant_centre)
            }
        });
        Ok((sample.collect(), secs))
    })
}
