//! Forces in the plane (LH A.2-4, C.2): the force polygon with its resultant and equilibrant,
//! the funicular polygon that places the resultant's line of action, the couple when the
//! force polygon closes but the funicular polygon does not, and the resolution of a force
//! along two given lines (the parallelogram of forces).
//!
//! # The construction (LH Abb. 22)
//! The forces are laid off head to tail: the closing side from the start to the end of the
//! chain is the resultant R (reversed, the equilibrant). From a pole O, rays run to the
//! corners of the chain; the strings of the funicular polygon run parallel to them between the
//! lines of action: string k between force k and force k + 1, string 0 before the first, string
//! n after the last. The first and the last string meet on the resultant's line of action. If
//! R = 0 they are parallel: a couple of moment |ray 0| × their distance, or, if they coincide,
//! equilibrium (force polygon and funicular polygon both closed).

mod auxiliary;
mod notes;
pub mod polygon;
mod system;

pub use auxiliary::parallel_pair_by_auxiliary_forces;
pub use system::{construct_system, FORCE_LETTER};

use crate::kernel::{Line, Point, Vector};
use crate::protocol::H;
use serde::Serialize;

/// A force: point of application (m) and components (kg), x to the right, y up.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Force {
    /// Point of application (m).
    pub at: Point,
    /// Components (kg).
    pub f: Vector,
}

impl Force {
    /// A force of components `f` (kg) at `at` (m).
    pub fn new(at: (f64, f64), f: (f64, f64)) -> Force {
        Force {
            at: Point::new(at.0, at.1),
            f: Vector::new(f.0, f.1),
        }
    }
}

/// The outcome of the funicular polygon.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Resultant {
    /// A single force R through the point `through` (m), and its moment about the origin.
    Force {
        /// Components of R (kg).
        r: Vector,
        /// A point of its line of action (m).
        through: Point,
        /// Moment of R about the origin (kg·m, counter-clockwise positive).
        moment: f64,
    },
    /// The force polygon closes but the funicular polygon does not: a couple (kg·m).
    Couple {
        /// Its moment (kg·m, counter-clockwise positive).
        moment: f64,
    },
    /// Force polygon and funicular polygon both close.
    Equilibrium,
}

/// Drawing choices.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SystemDrawing {
    /// Length scale 1 : n.
    pub length_scale: f64,
    /// kg per mm of sheet.
    pub force_scale: f64,
    /// The pole relative to the start of the force polygon (kg, x and y); `None` chooses one.
    pub pole: Option<Vector>,
    /// Where the force polygon starts on the sheet (mm); `None` puts it right of the forces.
    pub plan_at: Option<Point>,
    /// The unit of the "forces" ("kg"; "m²" when areas stand for weights, LH C.3).
    pub unit: &'static str,
}

/// A force to resolve along two directions (degrees from +x).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Resolution {
    /// Index of the force.
    pub force: usize,
    /// The two directions (degrees).
    pub along: [f64; 2],
    /// Resolve the equilibrant −F instead: the two forces that hold F in balance (the rope
    /// tensions of LH Aufgabe 2).
    pub equilibrant: bool,
}

/// Results of [`construct_system`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SystemResults {
    /// What the system reduces to.
    pub resultant: Resultant,
    /// The resultant's line of action on the board, where there is one.
    #[serde(skip)]
    pub resultant_line: Option<H<Line>>,
    /// Components of the resolved forces along their two directions (kg).
    pub components: Vec<Components>,
}

/// A force resolved along two directions: its component along each (kg, positive in the
/// direction's sense).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Components {
    /// Along the first direction.
    pub first: f64,
    /// Along the second direction.
    pub second: f64,
}

/// Closed forms: the vector sum and the moment about the origin.
pub fn sum_and_moment(forces: &[Force]) -> (Vector, f64) {
    let mut r = Vector::zeros();
    let mut m = 0.0;
    for f in forces {
        r.x += f.f.x;
        r.y += f.f.y;
        m += f.at.x * f.f.y - f.at.y * f.f.x;
    }
    (r, m)
}

/// The largest force (kg) and the farthest point of application from the origin (m, at least
/// 1): the magnitudes a force system's tolerances and default scales are relative to.
pub fn extent(forces: &[Force]) -> (f64, f64) {
    let fmax = forces
        .iter()
        .map(|f| f.f.x.hypot(f.f.y))
        .fold(0.0, f64::max);
    let reach = forces
        .iter()
        .map(|f| f.at.x.hypot(f.at.y))
        .fold(0.0, f64::max)
        .max(1.0);
    (fmax, reach)
}

/// Closed form of the resolution of `f` along unit directions `d1`, `d2`: the 2×2 solve.
pub fn resolve(f: Vector, d1: Vector, d2: Vector) -> Option<Components> {
    let det = d1.x * d2.y - d1.y * d2.x;
    if det.abs() < crate::kernel::tolerance::PARALLEL_SIN_EPS {
        return None;
    }
    Some(Components {
        first: (f.x * d2.y - f.y * d2.x) / det,
        second: (d1.x * f.y - d1.y * f.x) / det,
    })
}
