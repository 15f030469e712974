//! Why a construction could not be made: typed, so that a caller can match on the case.

use super::step::{StepId, Text};
use crate::fmt::num;
use crate::kernel::PrimitiveError;

/// Why a step could not be made: the geometric case that stopped it, or the input the
/// procedure does not construct, named.
///
/// ```
/// use graphostatik::prelude::*;
/// use graphostatik::protocol::CutOutcome;
/// let mut b = Board::recording();
/// let n = Note::new("two parallels", Topic::Custom("demo"));
/// let o = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
/// let p = b.point(Point::new(0.0, 5.0), Role::Given, n.clone());
/// let x = Vector::new(1.0, 0.0);
/// let l1 = b.line_dir(&o, x, Role::Given, n.clone())?;
/// let l2 = b.line_dir(&p, x, Role::Given, n.clone())?;
/// match b.meet_point(&l1, &l2, Label::NONE, n) {
///     Err(ConstructionError::NoIntersection { outcome: CutOutcome::Parallel { distance }, .. }) => {
///         assert_eq!(distance, 5.0)
///     }
///     other => panic!("{other:?}"),
/// }
/// # Ok::<(), ConstructionError>(())
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ConstructionError {
    /// A primitive could not be formed (coincident points, zero radius, non-finite value).
    #[error("step {step} ({caption}): {source}")]
    Primitive {
        /// The step number it would have had.
        step: StepId,
        /// Its caption.
        caption: Text,
        /// The cause.
        source: PrimitiveError,
    },
    /// An intersection has no point where the construction needs one.
    #[error("step {step} ({caption}): {outcome}")]
    NoIntersection {
        /// The step number it would have had.
        step: StepId,
        /// Its caption.
        caption: Text,
        /// The geometric case found instead.
        outcome: CutOutcome,
    },
    /// The input asks for a construction the procedure does not make (a point load inside a
    /// uniform load, supports in the wrong order, a pole on the force polygon).
    #[error("{reason}")]
    Unsupported {
        /// The input it is about, in the procedure's own terms (`forces[2]`, `pole`,
        /// `uniform_loads[0]`), for the scene layer to name its field.
        input: Text,
        /// What is wrong, and what to do.
        reason: String,
    },
    /// A truss that can move: its equilibrium matrix has fewer independent rows than unknowns.
    #[error("the truss is a mechanism ({freedoms} free motion(s)): joint {joint} can move")]
    Mechanism {
        /// The name of a joint that can move.
        joint: String,
        /// How many independent motions it has.
        freedoms: usize,
    },
    /// A truss with more members than its joints determine (LH B.5).
    #[error(
        "the truss is over-determinate by {redundant} (s = {members}, 2k − 3 = {needed}): the \
         Cremona plan needs a determinate truss (split it as in LH B.5)"
    )]
    OverDeterminate {
        /// Members beyond the determinate count.
        redundant: usize,
        /// Members s.
        members: usize,
        /// 2k − 3, the members a determinate truss of k joints has (Gl. 2).
        needed: i64,
    },
    /// A joint that no member connects to the rest of the truss.
    #[error("joint {joint} is not connected to the truss")]
    Disconnected {
        /// The joint's name.
        joint: String,
    },
    /// A force plan that cannot go on: no joint with two unknown member forces is left, and no
    /// section gives one (LH B.4).
    #[error("{reason}")]
    PlanStalls {
        /// The first member whose force is still unknown.
        member: String,
        /// The joints where it is stuck (at most six named).
        joints: Vec<String>,
        /// The whole sentence.
        reason: String,
    },
}

impl ConstructionError {
    /// An input the procedure does not construct: `input` names it in the procedure's own
    /// terms (`"pole"`, `"forces[2]"`).
    pub fn unsupported(input: impl Into<Text>, reason: impl Into<String>) -> ConstructionError {
        ConstructionError::Unsupported {
            input: input.into(),
            reason: reason.into(),
        }
    }
}

/// What a cut found where the construction needed a point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum CutOutcome {
    /// Two lines are parallel, `distance` mm apart on the sheet.
    Parallel {
        /// Their distance (mm).
        distance: f64,
    },
    /// Two lines coincide: the point is undetermined.
    Coincident,
    /// A circle misses a line by `gap` mm.
    Misses {
        /// The gap (mm).
        gap: f64,
    },
    /// Two circles lie `gap` mm apart.
    CirclesApart {
        /// The gap (mm).
        gap: f64,
    },
    /// One circle lies inside the other, `gap` mm clear.
    CircleInside {
        /// The clearance (mm).
        gap: f64,
    },
    /// Two circles with one centre and different radii.
    Concentric,
    /// Two circles are the same circle.
    CirclesCoincide,
}

impl std::fmt::Display for CutOutcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            CutOutcome::Parallel { distance } => write!(
                f,
                "the lines are parallel ({} mm apart) and do not meet",
                num(distance, 6)
            ),
            CutOutcome::Coincident => {
                write!(f, "the lines coincide: the intersection is undetermined")
            }
            CutOutcome::Misses { gap } => {
                write!(f, "the circle misses the line by {} mm", num(gap, 6))
            }
            CutOutcome::CirclesApart { gap } => {
                write!(f, "the circles lie {} mm apart", num(gap, 6))
            }
            CutOutcome::CircleInside { gap } => write!(
                f,
                "one circle lies inside the other, {} mm clear",
                num(gap, 6)
            ),
            CutOutcome::Concentric => write!(f, "the circles are concentric"),
            CutOutcome::CirclesCoincide => write!(f, "the circles coincide"),
        }
    }
}
