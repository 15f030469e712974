//! The force-system scene: forces in the plane, their resultant by the funicular polygon (or,
//! on one line of action, as their algebraic sum), and resolutions along two lines (LH A.1-4,
//! C.2, Aufgabe 2).

use super::defaults::nice_at_least;
use super::error::SceneError;
use super::fields::{optional_positive, Fields};
use super::procedure::ReadContext;
use crate::kernel::tolerance::PARALLEL_DEG_EPS;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use crate::statics::funicular::{self, Force, Resolution, SystemDrawing};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A force-system scene: `"procedure": "force_system"`.
    pub struct ForceSystemScene {
        /// The forces, in the order they are laid off.
        pub forces: Vec<ForceSpec>,
        /// Forces to resolve along two given directions.
        #[serde(default)]
        pub resolve: Vec<ResolveSpec>,
        /// Draw the resultant of two parallel forces by two equal and opposite auxiliary forces of
        /// this size (kg) instead of the funicular polygon (LH C.1, Abb. 21).
        #[serde(default)]
        pub auxiliary_force_kg: Option<f64>,
        /// Scales and the pole; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<ForceDrawingSpec>,
    }
}

/// A force: where it acts, and either its components or its magnitude and direction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ForceSpec {
    /// Point of application [x, y] (m).
    pub at_m: [f64; 2],
    /// Components [Fx, Fy] (kg), x to the right, y up.
    #[serde(default)]
    pub kg_xy: Option<[f64; 2]>,
    /// Magnitude (kg), with `angle_deg`.
    #[serde(default)]
    pub kg: Option<f64>,
    /// Direction, degrees counter-clockwise from +x (270 points down), with `kg`.
    #[serde(default)]
    pub angle_deg: Option<f64>,
}

impl ForceSpec {
    /// The force's components (kg): `kg_xy`, or `kg` along `angle_deg`; `None` unless exactly
    /// one of the two forms is given.
    pub fn vector(&self) -> Option<[f64; 2]> {
        match (self.kg_xy, self.kg, self.angle_deg) {
            (Some(xy), None, None) => Some(xy),
            (None, Some(k), Some(a)) => {
                let (s, c) = crate::kernel::angle::sin_cos_deg(a);
                Some([k * c, k * s])
            }
            _ => None,
        }
    }
}

/// A resolution of one force along two directions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ResolveSpec {
    /// Number of the force, from 1.
    pub force: usize,
    /// The two directions, degrees counter-clockwise from +x.
    pub along_deg: [f64; 2],
    /// Resolve the force that holds it in balance (rope tensions, support forces) instead.
    #[serde(default)]
    pub equilibrant: bool,
}

/// Scales and the pole.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ForceDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm of sheet.
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
    /// The pole relative to the start of the force polygon [x, y] (kg). Forces on one line
    /// of action are summed without one (LH Abb. 2), and it is not used.
    #[serde(default)]
    pub pole_kg: Option<[f64; 2]>,
}

/// A validated force-system scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceSystemProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The forces.
    pub forces: Vec<Force>,
    /// The resolutions.
    pub resolutions: Vec<Resolution>,
    /// Scales and pole.
    pub drawing: SystemDrawing,
    /// The auxiliary force of LH Abb. 21, if that construction is asked for.
    pub auxiliary_force: Option<f64>,
}

impl ForceSystemScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        self.check_forces(f)?;
        self.check_resolutions(f)?;
        self.check_auxiliary(f)?;
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                ],
            )?;
        }
        Ok(())
    }

    /// One to MAX_LOADS forces, each at a finite point with finite, non-zero components.
    fn check_forces(&self, fields: Fields) -> Result<(), SceneError> {
        if self.forces.is_empty() {
            return Err(fields.bad("forces", "give at least one force".into()));
        }
        if self.forces.len() > super::MAX_LOADS {
            return Err(fields.bad("forces", format!("more than {} forces", super::MAX_LOADS)));
        }
        for (i, force) in self.forces.iter().enumerate() {
            let at = |n: &str| format!("forces[{i}].{n}");
            if !force.at_m.iter().all(|v| v.is_finite()) {
                return Err(fields.bad(&at("at_m"), "must be finite numbers".into()));
            }
            let Some(v) = force.vector() else {
                return Err(fields.bad(
                    &format!("forces[{i}]"),
                    "give either kg_xy, or kg with angle_deg".into(),
                ));
            };
            if !v.iter().all(|x| x.is_finite()) {
                return Err(fields.bad(&format!("forces[{i}]"), "must be finite numbers".into()));
            }
            if v[0] == 0.0 && v[1] == 0.0 {
                return Err(fields.bad(
                    &format!("forces[{i}]"),
                    "a zero force has no line of action: leave it out".into(),
                ));
            }
        }
        Ok(())
    }

    /// Each resolution names a force and two directions that are not parallel.
    fn check_resolutions(&self, f: Fields) -> Result<(), SceneError> {
        for (j, r) in self.resolve.iter().enumerate() {
            if r.force == 0 || r.force > self.forces.len() {
                return Err(f.bad(
                    &format!("resolve[{j}].force"),
                    format!(
                        "names force {}, but there are {}",
                        r.force,
                        self.forces.len()
                    ),
                ));
            }
            let [a, b] = r.along_deg;
            // Parallel when the difference is within the tolerance of 0° or of 180° (either side).
            let d = (a - b).rem_euclid(180.0);
            if !(a.is_finite() && b.is_finite()) || d.min(180.0 - d) < PARALLEL_DEG_EPS {
                return Err(f.bad(
                    &format!("resolve[{j}].along_deg"),
                    "two different, non-parallel directions are needed".into(),
                ));
            }
        }
        Ok(())
    }

    /// The auxiliary forces of Abb. 21: positive, with exactly two forces and no resolutions.
    fn check_auxiliary(&self, f: Fields) -> Result<(), SceneError> {
        if let Some(aux) = self.auxiliary_force_kg {
            if !(aux.is_finite() && aux > 0.0) {
                return Err(f.bad("auxiliary_force_kg", format!("must be positive, got {aux}")));
            }
            if self.forces.len() != 2 || !self.resolve.is_empty() {
                return Err(f.bad("auxiliary_force_kg", "the auxiliary-force construction takes exactly two parallel forces and no resolutions".into()));
            }
            self.check_auxiliary_pair(f, aux)?;
        }
        Ok(())
    }

    /// The pair of Abb. 21 can be constructed: parallel forces at two points off their common
    /// line of action, whose partial resultants with the auxiliary forces meet at an angle
    /// the board can cut (a pair nearly equal and opposite is a couple to the drawing's
    /// precision: its partial resultants run parallel).
    fn check_auxiliary_pair(&self, f: Fields, aux: f64) -> Result<(), SceneError> {
        use crate::kernel::tolerance::PARALLEL_SIN_EPS;
        use crate::kernel::{cross, Vector};
        let (Some(a), Some(b)) = (self.forces[0].vector(), self.forces[1].vector()) else {
            return Ok(());
        };
        let (v1, v2) = (Vector::new(a[0], a[1]), Vector::new(b[0], b[1]));
        if cross(&v1, &v2).abs() > PARALLEL_SIN_EPS * v1.norm() * v2.norm() {
            return Err(f.bad("forces[1]", "is not parallel to forces[0]: the auxiliary-force construction takes two parallel forces".into()));
        }
        let (p, q) = (self.forces[0].at_m, self.forces[1].at_m);
        let join = Vector::new(q[0] - p[0], q[1] - p[1]);
        if cross(&join, &(v1 / v1.norm())).abs() <= PARALLEL_SIN_EPS * join.norm() {
            return Err(f.bad("forces[1].at_m", "lies on the line of action of forces[0]: the resultant acts on that line, and the auxiliary forces have no line to act along".into()));
        }
        let across = join / join.norm() * aux;
        let (d1, d2) = (v1 + across, v2 - across);
        let sin = cross(&d1, &d2).abs() / (d1.norm() * d2.norm());
        // Ten times the board's parallel limit, so that the constructed lines (whose sine
        // rounds differently) are never judged parallel after this passed.
        if sin.is_nan() || sin <= 10.0 * PARALLEL_SIN_EPS {
            let sum = v1 + v2;
            return Err(f.bad(
                "forces[1]",
                format!(
                    "and forces[0] sum to {} kg, nearly equal and opposite: their partial resultants with the auxiliary forces meet at {sin:.1e} rad, parallel on the board (a couple to the drawing's precision); leave out auxiliary_force_kg to draw the pair by the funicular polygon",
                    crate::fmt::sci(sum.norm())
                ),
            ));
        }
        Ok(())
    }

    /// The problem the scene describes.
    fn to_problem(&self) -> ForceSystemProblem {
        let forces: Vec<Force> = self
            .forces
            .iter()
            .map(|f| {
                // Validated: one of the two forms is given.
                let [fx, fy] = f.vector().unwrap_or([0.0, 0.0]);
                Force::new((f.at_m[0], f.at_m[1]), (fx, fy))
            })
            .collect();
        let (fmax, reach) = funicular::extent(&forces);
        let d = self.drawing.unwrap_or(ForceDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
            pole_kg: None,
        });
        ForceSystemProblem {
            auxiliary_force: self.auxiliary_force_kg,
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            resolutions: self
                .resolve
                .iter()
                .map(|r| Resolution {
                    force: r.force - 1,
                    along: r.along_deg,
                    equilibrant: r.equilibrant,
                })
                .collect(),
            drawing: SystemDrawing {
                length_scale: d
                    .length_scale
                    .unwrap_or_else(|| nice_at_least(reach * 1000.0 / 60.0)),
                force_scale: d
                    .force_scale_kg_per_mm
                    .unwrap_or_else(|| nice_at_least(fmax / 40.0)),
                pole: d.pole_kg.map(|[x, y]| crate::kernel::Vector::new(x, y)),
                plan_at: None,
                unit: "kg",
            },
            forces,
        }
    }
}

impl super::Procedure for ForceSystemScene {
    const NAME: &'static str = "force_system";
    const ABOUT: &'static str = "forces in the plane: force and funicular polygons, resultant, couple, resolution along two lines, forces on one line (LH I A, C.1-2)";
    const OUTPUTS: &'static [&'static str] = &[];
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("resolutions", "resolve"),
        (".along", ".along_deg"),
        ("pole", "drawing.pole_kg"),
    ];
    const GEOMETRY_FIELD: &'static str = "forces";

    fn sheet_extent(p: &ForceSystemProblem) -> (f64, &'static str) {
        let (_, reach) = funicular::extent(&p.forces);
        let o = p
            .forces
            .first()
            .map_or(crate::kernel::Point::origin(), |f| f.at);
        let spread = p
            .forces
            .iter()
            .map(|f| (f.at - o).norm())
            .fold(0.0, f64::max);
        // Far from the origin the system is drawn in its own frame (statics::funicular):
        // then its spread, not its distance from the origin, sets the figure.
        let far = reach > crate::kernel::tolerance::REL_LOCAL_FRAME * spread;
        let length = if far { spread } else { reach };
        let total: f64 = p.forces.iter().map(|f| f.f.x.hypot(f.f.y)).sum();
        let d = &p.drawing;
        super::fields::larger(length * 1000.0 / d.length_scale, total / d.force_scale)
    }
    type Problem = ForceSystemProblem;
    type Results = Option<funicular::SystemResults>;

    fn problem(&self, ctx: &ReadContext) -> Result<ForceSystemProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &ForceSystemProblem,
        config: BoardConfig,
    ) -> Result<(Board, Option<funicular::SystemResults>), ConstructionError> {
        let mut board = Board::new(config);
        if let Some(aux) = problem.auxiliary_force {
            funicular::parallel_pair_by_auxiliary_forces(
                &mut board,
                problem.forces[0],
                problem.forces[1],
                aux,
                &problem.drawing,
            )?;
            return Ok((board, None));
        }
        let r = funicular::construct_system(
            &mut board,
            &problem.forces,
            &problem.drawing,
            &problem.resolutions,
        )?;
        Ok((board, Some(r)))
    }
    fn figure_meta(problem: &ForceSystemProblem) -> FigureMeta {
        let d = &problem.drawing;
        FigureMeta {
            title: problem.title.clone(),
            source: problem.source.clone(),
            scales: vec![
                ScaleBar::length(d.length_scale, "m"),
                ScaleBar::force(d.force_scale),
            ],
            plate: Vec::new(),
        }
    }
}
