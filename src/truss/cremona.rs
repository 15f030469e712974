//! The Cremona force plan (LH B.4, Abb. 17, Regel 1 and 2), with the support reactions by the
//! funicular polygon and its closing line (LH C.2).
//!
//! # Reactions
//! With a pin at A and a roller at B: the force polygon of the loads, a pole O and its rays;
//! the first string through A (the only point of A's reaction known), each further string from
//! the cut of the previous one with the next load's line of action, the last one cut with
//! B's reaction line in b′. The closing line A b′, carried parallel through O, cuts the
//! parallel to B's reaction through the end of the force polygon: that point divides the
//! closing side of the force polygon into B and A. This works for any directions, loads
//! parallel or not.
//!
//! # The plan in Bow's notation
//! Every space of the truss drawing gets a point of the plan: the spaces between the external
//! forces (loads and reactions, taken clockwise round the outline) are the corners of the
//! external force polygon; each triangle of the truss is found where the parallels to two of
//! its members through the points of the neighbouring spaces meet. That is the joint
//! polygon of a joint where only the space between two members is unknown, so two unknown
//! member forces (Regel 2: clockwise round every joint, kept for the whole plan). Every member
//! then appears once, as the segment between the points of the two spaces it separates.
//!
//! Going clockwise round joint a across member m from the space L on its left (seen from a
//! towards b) to the space R, the member acts on a as the plan vector from L to R. If that
//! vector points from a towards b the member pulls at the joint: tension (+); towards a,
//! it pushes: compression (−) (Regel 1).

use super::faces::{self, dest, origin, PlaneGraph};
use super::matrix::{self, Solution};
use super::{JointLoad, LoadCase, MemberForce, SupportKind, Truss};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{
    note, Board, ConstructionError, Cut, Label, Note, Role, Scale, Topic, H, TABLE_BLOCK_ROWS,
};
use crate::statics::funicular::polygon::{self, StringStyle};
use serde::Serialize;

const N_JOINT: Note = note(
    "joint",
    Some("Knotenpunkt"),
    "LH B.4, Abb. 17",
    Topic::Truss,
);
const N_MEMBER: Note = note("member", Some("Stab"), "LH B.4, Abb. 17", Topic::Truss);
const N_SUPPORT: Note = note(
    "support reaction line",
    Some("Auflager"),
    "LH B.3",
    Topic::Truss,
);
const N_LOAD: Note = note("joint load", Some("Knotenlast"), "LH B.3", Topic::Loads);
const N_FP: Note = note(
    "loads laid off head to tail",
    Some("Krafteck"),
    "LH C.2",
    Topic::ForcePlan,
);
const N_LOA: Note = note(
    "line of action of the load",
    Some("Wirkungslinie"),
    "LH C.2",
    Topic::Funicular,
);
const N_B_CUT: Note = note(
    "last string cuts the reaction line of B",
    Some("Seileck"),
    "LH C.2",
    Topic::Reactions,
);
const N_B_DIR: Note = note(
    "direction of B through the end of the loads",
    Some("Auflagerdruck B"),
    "LH C.2",
    Topic::Reactions,
);
const N_SPLIT: Note = note(
    "the closing side divided into B and A",
    Some("Auflagerdrücke"),
    "LH C.2",
    Topic::Reactions,
);
const N_REACT: Note = note(
    "support reaction read off",
    Some("Auflagerdruck"),
    "LH B.3, C.2",
    Topic::Reactions,
);
const N_AXIS: Note = note(
    "reading direction",
    Some("Achse"),
    "LH B.3",
    Topic::Reactions,
);
const N_EXT: Note = note(
    "external force laid on, clockwise round the truss",
    Some("Krafteck der äußeren Kräfte"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);
const N_START: Note = note(
    "first space of the plan",
    Some("Kräfteplan"),
    "LH B.4",
    Topic::Cremona,
);
const N_PAR: Note = note(
    "parallel to a member through the point of the space beyond it",
    Some("Parallele zum Stab"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
const N_SPACE: Note = note(
    "joint polygon closed: the two unknown member forces meet",
    Some("Knotenpunktpolygon"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);
const N_FORCE: Note = note(
    "member force: tension if it points away from the joint (Regel 1)",
    Some("Stabkraft"),
    "LH B.4, Regel 1",
    Topic::Cremona,
);

/// A member force at most this fraction of the largest external force is a zero-force
/// member (Nullstab): the plan is exact to about 1e-12 of the loads, so 1e-9 separates
/// rounding from a real force with room on both sides.
pub const ZERO_FORCE_REL: f64 = 1e-9;

const N_TABLE: Note = note(
    "table of member forces read off the plan",
    Some("Auswertung"),
    "LH B.4",
    Topic::Cremona,
);
const N_SLACK: Note = note(
    "counter-diagonal out of action in this case (flat bar, would be compressed)",
    Some("Gegendiagonale"),
    "LH B.5",
    Topic::Truss,
);
const N_ZERO: Note = note(
    "zero-force member",
    Some("Nullstab"),
    "LH B.4, Aufgabe 5",
    Topic::Truss,
);

fn ext_max(ext: &External) -> f64 {
    ext.forces.iter().map(|(_, f)| f.norm()).fold(0.0, f64::max)
}

/// Scales and where the figure's blocks go.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrussDrawing {
    /// Length scale 1 : n of the truss drawing.
    pub length_scale: f64,
    /// Force scale, kg per mm.
    pub force_scale: f64,
}

/// A support reaction as read off the force plan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReactionForce {
    /// The support's name ("A", "B", or the scene's own).
    pub support: String,
    /// The joint it holds.
    pub joint: String,
    /// The force on the truss (kg), x to the right, y up.
    pub force: [f64; 2],
    /// Its length in the force plan (mm), |force| over the force scale.
    pub plan_mm: f64,
}

impl ReactionForce {
    /// The magnitude (kg).
    pub fn magnitude(&self) -> f64 {
        self.force[0].hypot(self.force[1])
    }
}

/// The result of one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseResult {
    /// Load case name.
    pub case: String,
    /// Reaction forces, one per support in the order of the supports.
    pub reactions: Vec<ReactionForce>,
    /// Member forces in the order of the members.
    pub members: Vec<MemberForce>,
    /// Largest out-of-balance force at any joint for the plan's forces (kg).
    pub plan_residual: f64,
    /// The same for the dense solve, where it was made.
    pub matrix_residual: Option<f64>,
}

/// Letters of the spaces in Bow's notation; further spaces are r₂₇, r₂₈, ….
const SPACE_NAMES: [&str; 26] = [
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q", "r", "s",
    "t", "u", "v", "w", "x", "y", "z",
];

fn space_label(i: usize) -> Label {
    if i < SPACE_NAMES.len() {
        Label::plain(SPACE_NAMES[i])
    } else {
        Label::indexed("r", i as u32 + 1)
    }
}

/// A member's label: `S` with its number where the scene numbers its members as the books do
/// (`"7"` is S₇), else the scene's own name (`"U1"` is U₁, see [`Label::from_name`]).
pub(crate) fn member_label(t: &Truss, m: usize) -> Label {
    let name = &t.members[m].name;
    match name.parse::<u32>() {
        Ok(n) => Label::indexed("S", n),
        Err(_) => Label::from_name(name),
    }
}

/// A joint's label: the scene's name for it (the books' Roman numerals, or any other; see
/// [`Label::from_name`]).
fn joint_label(t: &Truss, j: usize) -> Label {
    Label::from_name(&t.joints[j].name)
}

/// A support's label: the scene's name for its reaction (A, B, … by default).
fn support_label(t: &Truss, si: usize) -> Label {
    Label::from_name(&t.supports[si].name)
}

/// Everything the truss drawing needs per case, computed without a board.
pub(crate) struct External {
    /// (joint, force) of every external force, loads first, then reactions.
    pub(crate) forces: Vec<(usize, Vector)>,
    /// Reaction vectors per support.
    pub(crate) reactions: Vec<Vector>,
}

/// The supports, as the reaction construction takes them.
#[derive(Debug, Clone, Copy)]
enum Supports {
    /// A pin and a roller: the closing line of the funicular polygon (LH C.2).
    PinRoller {
        pin: usize,
        roller: usize,
        dir: Vector,
    },
    /// Three rollers: Culmann's line (the resultant with one reaction balances the other
    /// two, so both pairs act along the line through their meeting points).
    Rollers([(usize, Vector); 3]),
}

/// Index of support `s` in [`Truss::supports`] by joint.
fn support_index(t: &Truss, joint: usize) -> usize {
    t.supports
        .iter()
        .position(|s| s.joint == joint)
        .expect("a support at that joint")
}

/// The reaction supports: one pin and one roller, or three rollers.
fn supports(t: &Truss) -> Result<Supports, ConstructionError> {
    let pins: Vec<_> = t
        .supports
        .iter()
        .filter(|s| s.kind == SupportKind::Pinned)
        .collect();
    let rollers: Vec<_> = t
        .supports
        .iter()
        .filter_map(|s| match s.kind {
            SupportKind::Roller { dir } => Some((s.joint, dir)),
            _ => None,
        })
        .collect();
    match (pins.len(), rollers.len()) {
        (1, 1) => Ok(Supports::PinRoller {
            pin: pins[0].joint,
            roller: rollers[0].0,
            dir: rollers[0].1,
        }),
        (0, 3) => Ok(Supports::Rollers([rollers[0], rollers[1], rollers[2]])),
        _ => Err(ConstructionError::unsupported("supports", format!(
            "the graphic reactions need one pin and one roller, or three rollers; the truss has {} pin(s) and {} roller(s)",
            pins.len(),
            rollers.len()
        ))),
    }
}

/// Constructs the truss drawing and, per load case, the reactions and the Cremona plan,
/// each checked member by member against the dense solve of the joint equations
/// (up to [`matrix::DENSE_MAX_JOINTS`] joints).
///
/// # Errors
/// A truss that is not determinate, not a plane drawing, or whose plan stalls (three unknown
/// members at every remaining joint: Ritter's section would be needed), and loads at joints
/// off the outline.
///
/// ```
/// use graphostatik::truss::{cremona::*, *};
/// use graphostatik::kernel::{Point, Vector};
/// use graphostatik::protocol::Board;
/// // A triangle, span 2 m, height 1 m, 1000 kg at the apex: each rafter −707 kg, the tie +500.
/// let j = |n: &str, x, y| Joint { name: n.into(), at: Point::new(x, y) };
/// let m = |n: &str, a, b| Member { name: n.into(), ends: [a, b] };
/// let t = Truss {
///     joints: vec![j("I", 0.0, 0.0), j("II", 2.0, 0.0), j("III", 1.0, 1.0)],
///     members: vec![m("1", 0, 2), m("2", 2, 1), m("3", 0, 1)],
///     supports: vec![
///         Support::pinned(0, "A"),
///         Support::roller(1, Vector::new(0.0, 1.0), "B"),
///     ],
/// };
/// let case = LoadCase { name: "P".into(),
///     loads: vec![JointLoad { joint: 2, force: Vector::new(0.0, -1000.0) }] };
/// let mut b = Board::new(400.0, true);
/// let r = construct_truss(&mut b, &t, &[case],
///     &TrussDrawing { length_scale: 20.0, force_scale: 20.0 }).unwrap();
/// let s: Vec<f64> = r[0].members.iter().map(|m| m.force).collect();
/// assert!((s[0] + 707.1068).abs() < 1e-3 && (s[2] - 500.0).abs() < 1e-9);
/// assert!(b.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
/// ```
pub fn construct_truss(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
) -> Result<Vec<CaseResult>, ConstructionError> {
    let mut row = 0.0;
    construct(
        b,
        t,
        cases,
        dr,
        t.joints.len() <= matrix::DENSE_MAX_JOINTS,
        &mut row,
        &[],
    )
}

/// As [`construct_truss`], drawing the cases' rows from `row_top` (mm) downwards and moving
/// it below them: for figures that draw several trusses (sub-trusses, counter-diagonals
/// switched per case) one under the other. `slack` are joint pairs of members left out of
/// this truss but drawn dashed in its drawing (counter-diagonals out of action).
///
/// # Errors
/// As [`construct_truss`].
pub fn construct_truss_rows(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
    row_top: &mut f64,
    slack: &[[usize; 2]],
) -> Result<Vec<CaseResult>, ConstructionError> {
    construct(
        b,
        t,
        cases,
        dr,
        t.joints.len() <= matrix::DENSE_MAX_JOINTS,
        row_top,
        slack,
    )
}

/// The plan alone, without the rank test and the dense solve: what a drafter does, and what
/// the benchmark times against the dense solve. The plan still refuses a truss it cannot
/// resolve (it stalls, or two members meet in line where a space must be fixed), and
/// [`CaseResult::plan_residual`] still reports the balance at every joint.
///
/// # Errors
/// As [`construct_truss`].
pub fn construct_plan(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
) -> Result<Vec<CaseResult>, ConstructionError> {
    let mut row = 0.0;
    construct(b, t, cases, dr, false, &mut row, &[])
}

fn construct(
    b: &mut Board,
    t: &Truss,
    cases: &[LoadCase],
    dr: &TrussDrawing,
    dense: bool,
    row_top: &mut f64,
    slack: &[[usize; 2]],
) -> Result<Vec<CaseResult>, ConstructionError> {
    // The rank test goes with the dense solve; the plan alone finds out by stalling.
    if dense {
        match matrix::analyse(t).determinacy {
            matrix::Determinacy::Determinate => {}
            matrix::Determinacy::Mechanism { joint, freedoms } => {
                return Err(ConstructionError::Mechanism {
                    joint: t.joints[joint].name.clone(),
                    freedoms,
                })
            }
            matrix::Determinacy::OverDeterminate { redundant } => {
                return Err(ConstructionError::OverDeterminate {
                    redundant,
                    members: t.members.len(),
                    needed: 2 * t.joints.len() as i64 - 3,
                })
            }
        }
    }
    // Members that cross leave no plane drawing for Bow's notation: the joint polygons are
    // drawn one by one instead.
    let g = match faces::plane_graph(t) {
        Ok(g) => Some(g),
        Err(faces::GraphError::Crossing) => None,
        Err(faces::GraphError::Disconnected { joint }) => {
            return Err(ConstructionError::Disconnected {
                joint: t.joints[joint].name.clone(),
            })
        }
    };
    let sup = supports(t)?;
    let mut out = Vec::with_capacity(cases.len());
    let sols = if dense {
        matrix::solve_all(t, cases)
    } else {
        vec![None; cases.len()]
    };
    for (case, sol) in cases.iter().zip(sols) {
        // A scratch run fixes where the blocks go; the real run draws them there.
        let mut scratch = Board::new(b.tolerance().length * 1e6, false);
        let dry = construct_case(
            &mut scratch,
            t,
            g.as_ref(),
            case,
            sol.as_ref(),
            dr,
            Layout {
                truss: Point::origin(),
                polygon: Point::origin(),
                plan: Point::origin(),
            },
            sup,
            slack,
        )?;
        let gap = 30.0;
        let [tx0, ty0, tx1, ty1] = dry.boxes[0];
        let [px0, py0, px1, py1] = dry.boxes[1];
        let [qx0, qy0, _, qy1] = dry.boxes[2];
        let truss = Point::new(-tx0, *row_top - ty1);
        let polygon = Point::new(tx1 - tx0 + gap - px0, *row_top - py1);
        let plan = Point::new(tx1 - tx0 + gap + (px1 - px0) + gap - qx0, *row_top - qy1);
        b.set_context(|| case.name.clone());
        let r = construct_case(
            b,
            t,
            g.as_ref(),
            case,
            sol.as_ref(),
            dr,
            Layout {
                truss,
                polygon,
                plan,
            },
            sup,
            slack,
        )?;
        b.clear_context();
        let height = (ty1 - ty0).max(py1 - py0).max(qy1 - qy0);
        *row_top -= height + 2.0 * gap;
        out.push(r.result);
    }
    Ok(out)
}

#[derive(Clone, Copy)]
struct Layout {
    truss: Point,
    polygon: Point,
    plan: Point,
}

struct CaseOut {
    result: CaseResult,
    /// Bounding boxes [x0, y0, x1, y1] of the truss drawing, the reactions' force polygon,
    /// and the Cremona plan, relative to their origins.
    boxes: [[f64; 4]; 3],
}

pub(crate) fn grow(bx: &mut [f64; 4], p: Point, o: Point) {
    let (x, y) = (p.x - o.x, p.y - o.y);
    bx[0] = bx[0].min(x);
    bx[1] = bx[1].min(y);
    bx[2] = bx[2].max(x);
    bx[3] = bx[3].max(y);
}

pub(crate) const EMPTY: [f64; 4] = [
    f64::INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NEG_INFINITY,
];

/// The pole for the reaction construction: off the left of the loads' resultant by about the
/// polygon's size, picked among a few candidates for the best-conditioned cuts of strings with
/// lines of action and of the last string with B's line.
fn choose_pole(corners: &[Point], loads: &[Vector], rdir: Vector) -> Point {
    let (first, last) = (corners[0], corners[corners.len() - 1]);
    let mid = Point::from((first.coords + last.coords) * 0.5);
    let span = corners
        .iter()
        .map(|c| (c - mid).norm())
        .fold(0.0, f64::max)
        .max(10.0);
    let chord = last - first;
    // Off to the side of the closing chord; if the polygon closes, of its longest side.
    let along = if chord.norm() > 1e-9 * span {
        chord
    } else {
        loads
            .iter()
            .copied()
            .max_by(|a, b| a.norm().total_cmp(&b.norm()))
            .unwrap_or(Vector::new(0.0, 1.0))
    };
    let n = Vector::new(-along.y, along.x).normalize();
    // A pole on a corner or on a ray parallel to the next line of action scores 0.
    let sin = |a: Vector, b: Vector| {
        let d = a.norm() * b.norm();
        if d > 1e-9 * span * b.norm() {
            (a.x * b.y - a.y * b.x).abs() / d
        } else {
            0.0
        }
    };
    let score = |o: Point| -> f64 {
        let mut worst = f64::INFINITY;
        for (i, l) in loads.iter().enumerate() {
            worst = worst.min(sin(corners[i] - o, *l));
        }
        worst.min(sin(last - o, rdir))
    };
    let mut best = (mid + n * span, -1.0);
    for (f, turn) in [
        (1.0, 0.0),
        (1.0, 0.5),
        (1.0, -0.5),
        (1.6, 0.0),
        (0.7, 0.3),
        (1.3, -0.8),
        (2.0, 1.0),
    ] {
        let o = mid + n * (f * span) + along.normalize() * (turn * span);
        let s = score(o);
        if s > best.1 * (1.0 + 1e-9) {
            best = (o, s);
        }
    }
    best.0
}

#[allow(clippy::too_many_arguments)]
fn construct_case(
    b: &mut Board,
    t: &Truss,
    g: Option<&PlaneGraph>,
    case: &LoadCase,
    sol: Option<&Solution>,
    dr: &TrussDrawing,
    at: Layout,
    sup: Supports,
    slack: &[[usize; 2]],
) -> Result<CaseOut, ConstructionError> {
    let k = 1000.0 / dr.length_scale;
    let fs = dr.force_scale;
    let maxload = case
        .loads
        .iter()
        .map(|l| l.force.norm())
        .fold(0.0, f64::max);
    let mut boxes = [EMPTY; 3];
    // The truss drawing (Bauplan).
    let jp: Vec<H<Point>> = t
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            let p = at.truss + j.at.coords * k;
            grow(&mut boxes[0], p, at.truss);
            b.point(p, joint_label(t, i), Role::Given, N_JOINT)
        })
        .collect();
    // Each member drawn as the line through its joints over their distance: the line (a → b)
    // that the plan's parallels and readings refer to.
    let mut mline = Vec::with_capacity(t.members.len());
    for (m, mem) in t.members.iter().enumerate() {
        let [i, j] = mem.ends;
        mline.push(b.line_through(&jp[i], &jp[j], member_label(t, m), Role::Given, N_MEMBER)?);
    }
    // Members out of action in this case, dashed.
    for &[i, j] in slack {
        b.segment(&jp[i], &jp[j], Label::NONE, Role::Auxiliary, N_SLACK);
    }
    // Each support's reaction line (a roller's) or point (a pin's).
    let mut rlines: Vec<Option<H<Line>>> = vec![None; t.supports.len()];
    for (si, s) in t.supports.iter().enumerate() {
        match s.kind {
            SupportKind::Roller { dir } => {
                rlines[si] = Some(b.line_dir(
                    &jp[s.joint],
                    dir,
                    support_label(t, si),
                    Role::Guide,
                    N_SUPPORT,
                )?);
            }
            SupportKind::Pinned => {
                b.point(jp[s.joint].g, support_label(t, si), Role::Guide, N_SUPPORT);
            }
        }
    }
    // Loads, drawn as arrows ending at their joints, in the order of their joints.
    let mut loads: Vec<JointLoad> = case
        .loads
        .iter()
        .copied()
        .filter(|l| l.force.norm() > 0.0)
        .collect();
    loads.sort_by(|a, c| {
        let (pa, pc) = (t.joints[a.joint].at, t.joints[c.joint].at);
        pa.x.total_cmp(&pc.x).then(pa.y.total_cmp(&pc.y))
    });
    for l in &loads {
        let head = jp[l.joint];
        let tail = b.point(head.g - l.force / fs, Label::NONE, Role::Given, N_LOAD);
        grow(&mut boxes[0], tail.g, at.truss);
        b.segment(&tail, &head, Label::indexed("P", 0), Role::Force, N_LOAD);
    }
    // Reactions by the funicular polygon, one vector per support.
    let mut reactions = vec![Vector::zeros(); t.supports.len()];
    if !loads.is_empty() {
        let mut corners = vec![at.polygon];
        for l in &loads {
            let c = *corners.last().expect("starts with one corner") + l.force / fs;
            corners.push(c);
        }
        let dirs: Vec<Vector> = loads.iter().map(|l| l.force).collect();
        // The first string starts at the pin, or at the first roller.
        let (start, last_dir) = match sup {
            Supports::PinRoller { pin, dir, .. } => (pin, dir),
            Supports::Rollers(r) => (r[0].0, r[0].1),
        };
        let pole = choose_pole(&corners, &dirs, last_dir);
        let f0 = b.point(corners[0], Label::indexed("F", 0), Role::Given, N_FP);
        let mut fh = vec![f0];
        for (i, l) in loads.iter().enumerate() {
            let along = b.line_dir(&fh[i], l.force, Label::NONE, Role::Auxiliary, N_FP)?;
            let p = b.lay_off(
                &fh[i],
                &along,
                l.force.norm() / fs,
                Label::NONE,
                Role::Force,
                N_FP,
            )?;
            fh.push(p);
        }
        let polygon::Rays { pole: o, rays } = polygon::pole_and_rays(b, pole, &fh)?;
        for p in fh.iter().map(|h| h.g).chain([pole]) {
            grow(&mut boxes[1], p, at.polygon);
        }
        let strings = polygon::strings(
            b,
            &rays,
            &jp[start],
            false,
            StringStyle::CONSTRUCTION,
            |b, j| {
                let l = &loads[j];
                b.line_dir(&jp[l.joint], l.force, Label::NONE, Role::Auxiliary, N_LOA)
            },
        )?;
        for c in &strings.corners {
            grow(&mut boxes[0], c.g, at.truss);
        }
        let (first, s) = (strings.strings[0], strings.strings[loads.len()]);
        let last = fh[loads.len()];
        let mut segs: Vec<Option<(H<Point>, H<Point>)>> = vec![None; t.supports.len()];
        match sup {
            Supports::PinRoller { pin, roller, .. } => {
                let ri = support_index(t, roller);
                let rline = rlines[ri].expect("a roller has a line");
                let bcut = b.meet_point(&s, &rline, Label::quiet("b", 0), N_B_CUT)?;
                grow(&mut boxes[0], bcut.g, at.truss);
                let through_o = polygon::closing(
                    b,
                    &jp[pin],
                    &bcut,
                    &o,
                    Label::NONE,
                    Role::Construction,
                    Role::Construction,
                )?
                .ray;
                let bl = b.parallel(&rline, &last, Label::NONE, Role::Auxiliary, N_B_DIR);
                let x = b.meet_point(&through_o, &bl, Label::quiet("X", 0), N_SPLIT)?;
                grow(&mut boxes[1], x.g, at.polygon);
                let pi = support_index(t, pin);
                segs[ri] = Some((last, x));
                segs[pi] = Some((x, fh[0]));
            }
            Supports::Rollers(r) => {
                for (si, from, to) in culmann(b, t, &rlines, &first, &s, &fh, &r)? {
                    grow(&mut boxes[1], to.g, at.polygon);
                    segs[si] = Some((from, to));
                }
            }
        }
        // Each reaction drawn, read off and checked: a roller's along its line, a pin's by
        // its horizontal and vertical parts.
        for (si, seg) in segs.iter().enumerate() {
            if let Some((from, to)) = seg {
                b.segment(from, to, support_label(t, si), Role::Force, N_REACT);
                reactions[si] = (to.g - from.g) * fs;
            }
        }
        let by_moments = super::reactions::by_moments(t, &loads);
        read_reactions(
            b,
            t,
            &segs,
            &rlines,
            sol,
            by_moments.as_deref(),
            maxload,
            fs,
        )?;
    }
    // The external forces at their joints: loads, then the reactions.
    let mut ext: Vec<(usize, Vector)> = loads.iter().map(|l| (l.joint, l.force)).collect();
    let tiny = 1e-12 * reactions.iter().map(|r| r.norm()).fold(maxload, f64::max);
    for (si, r) in reactions.iter().enumerate() {
        if r.norm() > tiny {
            ext.push((t.supports[si].joint, *r));
        }
    }
    let external = External {
        forces: ext,
        reactions: reactions.clone(),
    };
    // Bow's notation needs a plane drawing and every external force on the outline;
    // otherwise the joint polygons are drawn one by one (LH Abb. 17a).
    let (result, plan_box) = match g.filter(|g| outline(t, g, &external).is_ok()) {
        Some(g) => cremona_plan(b, t, g, case, &external, sol, dr, at.plan, &mline, maxload)?,
        None => {
            super::joints::joint_polygons(b, t, case, &external, sol, dr, at.plan, &mline, maxload)?
        }
    };
    // The evaluation of the plan written beside it (LH B.4, "Auswertung").
    let zero_kg = ZERO_FORCE_REL * check_reference(maxload, &external);
    let mut rows = vec![vec![
        "Stab".to_string(),
        "Strecke mm".to_string(),
        "Stabkraft kg".to_string(),
        "Art".to_string(),
    ]];
    for mf in &result.members {
        let (force, kind) = if mf.force.abs() <= zero_kg {
            ("0".to_string(), "Nullstab")
        } else if mf.force > 0.0 {
            (format!("+{}", crate::fmt::num(mf.force, 0)), "Zug")
        } else {
            (format!("−{}", crate::fmt::num(-mf.force, 0)), "Druck")
        };
        rows.push(vec![
            mf.member.clone(),
            crate::fmt::num(mf.plan_mm, 1),
            force,
            kind.to_string(),
        ]);
    }
    // The reactions below the members, by magnitude (the book's "G" and "A" of Aufgabe 3).
    for r in &result.reactions {
        let f = r.magnitude();
        rows.push(vec![
            r.support.clone(),
            crate::fmt::num(r.plan_mm, 1),
            if f <= zero_kg {
                "0".to_string()
            } else {
                crate::fmt::num(f, 0)
            },
            "Auflager".to_string(),
        ]);
    }
    let n = rows.len() - 1;
    let corner = at.plan + Vector::new(plan_box[2] + 12.0, plan_box[3]);
    b.table(corner, rows, &[], N_TABLE);
    let mut plan_box = plan_box;
    // Room for the table: blocks of at most TABLE_BLOCK_ROWS rows side by side, each about
    // 75 mm wide, 3.6 mm per row.
    let blocks = n.div_ceil(TABLE_BLOCK_ROWS).max(1);
    plan_box[2] += 12.0 + 75.0 * blocks as f64;
    plan_box[1] = plan_box[1].min(plan_box[3] - 3.6 * (n.min(TABLE_BLOCK_ROWS) as f64 + 1.0));
    boxes[2] = plan_box;
    // Zero-force members (Nullstäbe) marked in the truss drawing.
    for (m, f) in result.members.iter().enumerate() {
        if f.force.abs() <= zero_kg {
            let [i, j] = t.members[m].ends;
            b.segment(&jp[i], &jp[j], Label::plain("0"), Role::Auxiliary, N_ZERO);
        }
    }
    for bx in &mut boxes {
        if !bx[0].is_finite() {
            *bx = [0.0; 4];
        }
    }
    Ok(CaseOut { result, boxes })
}

const N_RESULTANT: Note = note(
    "the first and last strings meet on the resultant of the loads",
    Some("Resultierende"),
    "LH C.2",
    Topic::Reactions,
);
const N_CULMANN_P: Note = note(
    "the resultant meets the lone roller's line",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);
const N_CULMANN_Q: Note = note(
    "the other two reaction lines meet",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);
const N_CULMANN: Note = note(
    "Culmann's line through both points",
    Some("Culmannsche Gerade"),
    "LH C.2",
    Topic::Reactions,
);
const N_CULMANN_PLAN: Note = note(
    "in the force plan: the lone reaction, then the two along Culmann's line resolved",
    Some("Zerlegung"),
    "LH A.3, C.2",
    Topic::Reactions,
);

/// A reaction in the force plan: its support (index), tail and head.
type PlanReaction = (usize, H<Point>, H<Point>);

/// Three rollers (Culmann): the resultant R of the loads and the lone roller's reaction
/// meet in P, the other two reaction lines in Q; R and the lone reaction together balance
/// the other two, so their sum acts along PQ. In the force plan, the parallel to the lone
/// roller through the end of the loads and the parallel to PQ through their start give the
/// lone reaction; the other two follow by resolving along their lines. Of the three rollers
/// the lone one is the one with the best-conditioned cuts. Returns (support index, tail,
/// head) of each reaction in the force plan.
#[allow(clippy::too_many_arguments)]
fn culmann(
    b: &mut Board,
    t: &Truss,
    rlines: &[Option<H<Line>>],
    first: &H<Line>,
    last_string: &H<Line>,
    fh: &[H<Point>],
    r: &[(usize, Vector); 3],
) -> Result<Vec<PlanReaction>, ConstructionError> {
    let n = fh.len() - 1;
    let rv = fh[n].g - fh[0].g;
    let span = fh
        .iter()
        .map(|f| (f.g - fh[0].g).norm())
        .fold(0.0, f64::max);
    if rv.norm() <= 1e-9 * span.max(f64::MIN_POSITIVE) {
        return Err(ConstructionError::unsupported("loads", 
            "the loads form a couple (their force polygon closes): three rollers need a resultant to cut",
        ));
    }
    let on_r = b.meet_point(first, last_string, Label::quiet("R", 0), N_RESULTANT)?;
    let rl = b.line_dir(
        &on_r,
        rv,
        Label::plain("R"),
        Role::Construction,
        N_RESULTANT,
    )?;
    let sin = |a: Vector, c: Vector| (a.x * c.y - a.y * c.x).abs() / (a.norm() * c.norm());
    let mut best = (0, -1.0);
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let score = sin(rv, r[k].1).min(sin(r[i].1, r[j].1));
        if score > best.1 {
            best = (k, score);
        }
    }
    let k = best.0;
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let line = |s: usize| rlines[support_index(t, r[s].0)].expect("a roller has a line");
    let (lk, li, lj) = (line(k), line(i), line(j));
    let p = b.meet_point(&rl, &lk, Label::quiet("P", 0), N_CULMANN_P)?;
    let q = b.meet_point(&li, &lj, Label::quiet("Q", 0), N_CULMANN_Q)?;
    let c = b.line_through(&p, &q, Label::plain("c"), Role::Construction, N_CULMANN)?;
    let (f0, last) = (fh[0], fh[n]);
    let along_k = b.parallel(&lk, &last, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let along_c = b.parallel(&c, &f0, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let x = b.meet_point(&along_k, &along_c, Label::quiet("X", 0), N_CULMANN_PLAN)?;
    let along_i = b.parallel(&li, &x, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let along_j = b.parallel(&lj, &f0, Label::NONE, Role::Auxiliary, N_CULMANN_PLAN);
    let y = b.meet_point(&along_i, &along_j, Label::quiet("Y", 0), N_CULMANN_PLAN)?;
    Ok(vec![
        (support_index(t, r[k].0), last, x),
        (support_index(t, r[i].0), x, y),
        (support_index(t, r[j].0), y, f0),
    ])
}

/// Reads each reaction off the force plan and checks it by the moment equations of the whole
/// truss (LH C.2) and against the dense solve: a roller's along its line, a pin's by its
/// horizontal and vertical parts.
#[allow(clippy::too_many_arguments)]
fn read_reactions(
    b: &mut Board,
    t: &Truss,
    segs: &[Option<(H<Point>, H<Point>)>],
    rlines: &[Option<H<Line>>],
    sol: Option<&Solution>,
    by_moments: Option<&[Vector]>,
    reference: f64,
    fs: f64,
) -> Result<(), ConstructionError> {
    let kg = Scale::kg(fs);
    let f = "joint equilibrium, dense LU (nalgebra)";
    let fm = "moments about the other supports (LH C.2)";
    let mut col = 0;
    for (si, sup) in t.supports.iter().enumerate() {
        let first_col = col;
        col += match sup.kind {
            SupportKind::Pinned => 2,
            SupportKind::Roller { .. } => 1,
        };
        let Some((from, to)) = segs[si] else {
            continue;
        };
        match sup.kind {
            SupportKind::Roller { dir } => {
                let line = rlines[si].expect("a roller has a line");
                let v = b.measure(&from, &to, &line, kg, Label::quiet("R", 0), N_REACT);
                if let Some(m) = by_moments {
                    b.check(
                        &v,
                        "roller reaction by moments",
                        "kg",
                        fm,
                        reference,
                        || m[si].dot(&dir),
                    );
                }
                if let Some(sol) = sol {
                    b.check(
                        &v,
                        "roller reaction along its line",
                        "kg",
                        f,
                        reference,
                        || sol.reactions[first_col],
                    );
                }
            }
            SupportKind::Pinned => {
                let xa = b.line_dir(
                    &from,
                    Vector::new(1.0, 0.0),
                    Label::NONE,
                    Role::Auxiliary,
                    N_AXIS,
                )?;
                let ya = b.line_dir(
                    &from,
                    Vector::new(0.0, 1.0),
                    Label::NONE,
                    Role::Auxiliary,
                    N_AXIS,
                )?;
                let ax = b.measure(&from, &to, &xa, kg, Label::quiet("Ax", 0), N_REACT);
                let ay = b.measure(&from, &to, &ya, kg, Label::quiet("Ay", 0), N_REACT);
                if let Some(m) = by_moments {
                    b.check(
                        &ax,
                        "pin reaction by moments, horizontal",
                        "kg",
                        fm,
                        reference,
                        || m[si].x,
                    );
                    b.check(
                        &ay,
                        "pin reaction by moments, vertical",
                        "kg",
                        fm,
                        reference,
                        || m[si].y,
                    );
                }
                if let Some(sol) = sol {
                    b.check(&ax, "pin reaction, horizontal", "kg", f, reference, || {
                        sol.reactions[first_col]
                    });
                    b.check(&ay, "pin reaction, vertical", "kg", f, reference, || {
                        sol.reactions[first_col + 1]
                    });
                }
            }
        }
    }
    Ok(())
}

/// Assigns every external force to its place on the outline, clockwise, and every outer
/// half-edge to the space on its left.
fn outline(
    t: &Truss,
    g: &PlaneGraph,
    ext: &External,
) -> Result<(Vec<usize>, Vec<usize>), ConstructionError> {
    let nh = g.next.len();
    let mut space_of_half = vec![usize::MAX; nh];
    let mut order = Vec::with_capacity(ext.forces.len());
    let mut placed = vec![false; ext.forces.len()];
    let outer = &g.faces[g.outer];
    if outer.is_empty() {
        return Err(ConstructionError::unsupported(
            "members",
            "a truss needs members",
        ));
    }
    let mut at_joint: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
    for (fi, &(j, _)) in ext.forces.iter().enumerate() {
        at_joint.entry(j).or_default().push(fi);
    }
    // The outline's half-edges in order: h_in = u → v, then h_out = v → w.
    let mut space = 0;
    for (idx, &h_in) in outer.iter().enumerate() {
        space_of_half[h_in] = space;
        let h_out = outer[(idx + 1) % outer.len()];
        let v = dest(t, h_in);
        let back = g.angle[h_in ^ 1];
        let span = if h_out == h_in ^ 1 {
            std::f64::consts::TAU
        } else {
            faces::cw(back, g.angle[h_out])
        };
        // Forces at v whose line of action leaves into this sector, clockwise.
        let mut here: Vec<(f64, usize)> = Vec::new();
        for &fi in at_joint.get(&v).map_or(&[][..], |v| v.as_slice()) {
            let f = ext.forces[fi].1;
            if placed[fi] {
                continue;
            }
            // The line of action drawn on the outside: the arrow coming in towards the joint
            // (−f) if that side is outside, else going out (+f).
            let a_in = (-f.y).atan2(-f.x);
            let a_out = f.y.atan2(f.x);
            let inside = |a: f64| {
                let c = faces::cw(back, a);
                c > 0.0 && c < span
            };
            let a = if inside(a_in) {
                a_in
            } else if inside(a_out) {
                a_out
            } else {
                continue;
            };
            here.push((faces::cw(back, a), fi));
        }
        here.sort_by(|a, c| a.0.total_cmp(&c.0).then(a.1.cmp(&c.1)));
        for (_, fi) in here {
            placed[fi] = true;
            order.push(fi);
            space += 1;
        }
    }
    if let Some(fi) = placed.iter().position(|p| !p) {
        let j = ext.forces[fi].0;
        return Err(ConstructionError::unsupported("loads", format!(
            "joint {} carries an external force but its line of action does not leave the truss on the outside: Bow's notation needs external forces at outer joints",
            t.joints[j].name
        )));
    }
    // The space after the last force is the first one again.
    let n = order.len().max(1);
    for s in &mut space_of_half {
        if *s != usize::MAX {
            *s %= n;
        }
    }
    Ok((order, space_of_half))
}

#[allow(clippy::too_many_arguments)]
fn cremona_plan(
    b: &mut Board,
    t: &Truss,
    g: &PlaneGraph,
    case: &LoadCase,
    ext: &External,
    sol: Option<&Solution>,
    dr: &TrussDrawing,
    at: Point,
    mline: &[H<Line>],
    maxload: f64,
) -> Result<(CaseResult, [f64; 4]), ConstructionError> {
    let fs = dr.force_scale;
    let kg = Scale::kg(fs);
    let mut bx = EMPTY;
    let (order, mut space_of_half) = outline(t, g, ext)?;
    let n_ext = order.len().max(1);
    // Inner faces become spaces after the outer ones.
    let mut space_of_face = vec![usize::MAX; g.faces.len()];
    let mut n_spaces = n_ext;
    for (f, sp) in space_of_face.iter_mut().enumerate() {
        if f != g.outer {
            *sp = n_spaces;
            n_spaces += 1;
        }
    }
    let mut face_of_space = vec![g.outer; n_spaces];
    for (f, &sp) in space_of_face.iter().enumerate() {
        if sp != usize::MAX {
            face_of_space[sp] = f;
        }
    }
    for h in 0..space_of_half.len() {
        if g.face_of[h] != g.outer {
            space_of_half[h] = space_of_face[g.face_of[h]];
        }
    }
    let mut pt: Vec<Option<H<Point>>> = vec![None; n_spaces];
    // The external force polygon, clockwise round the truss.
    let start = b.point(at, space_label(0), Role::Given, N_START);
    grow(&mut bx, at, at);
    pt[0] = Some(start);
    let mut cur = start;
    for (i, &fi) in order.iter().enumerate() {
        let f = ext.forces[fi].1;
        let along = b.line_dir(&cur, f, Label::NONE, Role::Auxiliary, N_EXT)?;
        let lab = if i + 1 < order.len() {
            space_label(i + 1)
        } else {
            Label::NONE
        };
        let next = b.lay_off(&cur, &along, f.norm() / fs, lab, Role::Force, N_EXT)?;
        grow(&mut bx, next.g, at);
        if i + 1 < order.len() {
            pt[i + 1] = Some(next);
        }
        cur = next;
    }
    // Joints touching each space, to revisit when it becomes known.
    let mut joints_of_space: Vec<Vec<usize>> = vec![Vec::new(); n_spaces];
    for (h, &s) in space_of_half.iter().enumerate() {
        joints_of_space[s].push(origin(t, h));
    }
    for js in &mut joints_of_space {
        js.sort_unstable();
        js.dedup();
    }
    let mut forces: Vec<Option<f64>> = vec![None; t.members.len()];
    let mut plan_mm = vec![0.0; t.members.len()];
    let mut queue: std::collections::VecDeque<usize> = (0..t.joints.len()).collect();
    let mut queued = vec![true; t.joints.len()];
    let reference = check_reference(maxload, ext);
    // Draws every member whose two spaces are known and that is not drawn yet.
    let settle = |b: &mut Board,
                  pt: &[Option<H<Point>>],
                  forces: &mut Vec<Option<f64>>,
                  plan_mm: &mut Vec<f64>,
                  members: &mut dyn Iterator<Item = usize>| {
        for m in members {
            if forces[m].is_some() {
                continue;
            }
            let (l, r) = (space_of_half[2 * m], space_of_half[2 * m + 1]);
            if let (Some(pl), Some(pr)) = (pt[l], pt[r]) {
                b.segment(&pl, &pr, member_label(t, m), Role::Result, N_FORCE);
                let v = b.measure(&pl, &pr, &mline[m], kg, member_label(t, m), N_FORCE);
                check_member(b, &v, m, sol, reference);
                forces[m] = Some(v.g);
                plan_mm[m] = (pr.g - pl.g).norm();
            }
        }
    };
    // Members on the outline are known from the external polygon already.
    settle(b, &pt, &mut forces, &mut plan_mm, &mut (0..t.members.len()));
    let spaces = Spaces {
        of_half: &space_of_half,
        face_of: &face_of_space,
        n_ext,
    };
    loop {
        let fixed = match queue.pop_front() {
            Some(v) => {
                queued[v] = false;
                joint_polygon(b, t, g, v, &spaces, &mut pt, mline, case)
            }
            None if pt.iter().all(|p| p.is_some()) => break,
            // No joint with two unknown members is left: Ritter's section.
            None => match ritter(b, t, g, &spaces, &mut pt, ext, mline, case, fs) {
                Some(u) => Some(u),
                None => break,
            },
        };
        let Some(u) = fixed else {
            continue;
        };
        grow(&mut bx, pt[u].expect("just fixed").g, at);
        settle(
            b,
            &pt,
            &mut forces,
            &mut plan_mm,
            &mut g.faces[face_of_space[u]].iter().map(|h| h / 2),
        );
        for &j in &joints_of_space[u] {
            if !queued[j] {
                queued[j] = true;
                queue.push_back(j);
            }
        }
    }
    b.set_context(|| case.name.clone());
    if let Some(m) = forces.iter().position(|f| f.is_none()) {
        let stuck: Vec<String> = (0..t.joints.len())
            .filter(|&v| g.around[v].iter().any(|&h| forces[h / 2].is_none()))
            .map(|v| t.joints[v].name.clone())
            .take(6)
            .collect();
        return Err(ConstructionError::PlanStalls {
            member: t.members[m].name.clone(),
            reason: format!(
                "the Cremona plan stalls before member {}: at joints {} three or more member forces are unknown, and no section through three members with two unknown spaces between them gives one of them (Ritter, LH B.4)",
                t.members[m].name,
                stuck.join(", ")
            ),
            joints: stuck,
        });
    }
    Ok((plan_result(t, case, ext, &forces, &plan_mm, sol, dr), bx))
}

/// The result of a plan, either way it was drawn: the forces found, the dense solve beside
/// them, and the balance of both at every joint.
pub(crate) fn plan_result(
    t: &Truss,
    case: &LoadCase,
    ext: &External,
    forces: &[Option<f64>],
    plan_mm: &[f64],
    sol: Option<&Solution>,
    dr: &TrussDrawing,
) -> CaseResult {
    let members: Vec<f64> = forces.iter().map(|f| f.unwrap_or(0.0)).collect();
    let matrix: Vec<Option<f64>> = (0..members.len())
        .map(|m| sol.map(|s| s.members[m]))
        .collect();
    let mut result = case_result(t, case, &members, plan_mm, &matrix, &ext.reactions, dr);
    result.matrix_residual = sol.map(|s| matrix::max_residual(t, case, &s.members, &s.reactions));
    result
}

/// The scale of the checks: the largest load or reaction of the case (kg).
pub(crate) fn check_reference(maxload: f64, ext: &External) -> f64 {
    maxload.max(ext_max(ext))
}

/// Checks a member force read off a plan against the dense solve, if it was made.
pub(crate) fn check_member(
    b: &mut Board,
    value: &H<f64>,
    m: usize,
    sol: Option<&Solution>,
    reference: f64,
) {
    if let Some(sol) = sol {
        b.check(
            value,
            "member force (tension +)",
            "kg",
            "joint equilibrium, dense LU (nalgebra)",
            reference,
            || sol.members[m],
        );
    }
}

/// The result of a case from its member forces and reactions (one per support), with the balance
/// of every joint of `t` under them.
pub(crate) fn case_result(
    t: &Truss,
    case: &LoadCase,
    forces: &[f64],
    plan_mm: &[f64],
    matrix: &[Option<f64>],
    reactions: &[Vector],
    dr: &TrussDrawing,
) -> CaseResult {
    // Reaction components in the solve's order.
    let mut rc = Vec::new();
    for (sup, r) in t.supports.iter().zip(reactions) {
        match sup.kind {
            SupportKind::Pinned => rc.extend([r.x, r.y]),
            SupportKind::Roller { dir } => rc.push(r.dot(&dir)),
        }
    }
    CaseResult {
        case: case.name.clone(),
        reactions: t
            .supports
            .iter()
            .zip(reactions)
            .map(|(sup, r)| ReactionForce {
                support: sup.name.clone(),
                joint: t.joints[sup.joint].name.clone(),
                force: [r.x, r.y],
                plan_mm: r.norm() / dr.force_scale,
            })
            .collect(),
        members: t
            .members
            .iter()
            .enumerate()
            .map(|(m, mem)| MemberForce {
                member: mem.name.clone(),
                plan_mm: plan_mm[m],
                force: forces[m],
                matrix: matrix[m],
            })
            .collect(),
        plan_residual: matrix::max_residual(t, case, forces, &rc),
        matrix_residual: None,
    }
}

/// The polygon of joint `v` if only one space round it is unknown: the parallels to the two
/// members bounding that space, through the points of the spaces beyond them, meet in its
/// point (Regel 2). Returns the space fixed.
#[allow(clippy::too_many_arguments)]
fn joint_polygon(
    b: &mut Board,
    t: &Truss,
    g: &PlaneGraph,
    v: usize,
    sp: &Spaces,
    pt: &mut [Option<H<Point>>],
    mline: &[H<Line>],
    case: &LoadCase,
) -> Option<usize> {
    let around = &g.around[v];
    let d = around.len();
    if d < 2 {
        return None;
    }
    let unknown: Vec<usize> = (0..d)
        .filter(|&i| pt[sp.of_half[around[i]]].is_none())
        .collect();
    let mut spaces: Vec<usize> = unknown.iter().map(|&i| sp.of_half[around[i]]).collect();
    spaces.dedup();
    if spaces.len() != 1 || unknown.len() != 1 {
        return None;
    }
    let i = unknown[0];
    let (ha, hb) = (around[i], around[(i + 1) % d]);
    let u = sp.of_half[ha];
    let (px, py) = (pt[sp.of_half[ha ^ 1]]?, pt[sp.of_half[hb]]?);
    let name = &t.joints[v].name;
    b.set_context(|| format!("{}: joint {name}", case.name));
    let la = b.parallel(&mline[ha / 2], &px, Label::NONE, Role::Construction, N_PAR);
    let lb = b.parallel(&mline[hb / 2], &py, Label::NONE, Role::Construction, N_PAR);
    match b.meet(&la, &lb, space_label(u), N_SPACE) {
        Cut::Point(p, _) => {
            pt[u] = Some(p);
            Some(u)
        }
        // Two members in line at this joint: another joint has to fix the space.
        _ => None,
    }
}

/// The spaces of Bow's notation.
struct Spaces<'a> {
    /// The space left of every half-edge.
    of_half: &'a [usize],
    /// The face of every inner space (the outer face for outer spaces).
    face_of: &'a [usize],
    /// Spaces below this index are outside the truss.
    n_ext: usize,
}

const N_RITTER_CUT: Note = note(
    "Ritter section: the lines of two cut members meet in the moment point",
    Some("Rittersches Verfahren, Drehpunkt"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);
const N_RITTER_PAR: Note = note(
    "the third cut member carried into the plan",
    Some("Rittersches Verfahren"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);
const N_RITTER_FORCE: Note = note(
    "its force from the moment equation of the cut-off part, laid off at the force scale",
    Some("Momentengleichung"),
    "LH B.4, Aufgabe 5",
    Topic::Cremona,
);

/// Ritter's method of sections where the plan stalls (LH B.4; Aufgabe 5, Tafel I, 5): a cut
/// through three members m₁, m₂, m₃ that runs from a known space outside the truss through
/// two unknown spaces to another known space outside, and parts the truss in two. The
/// moment equation of one part about the meeting point of two of the cut members gives the
/// force of the third (about a point at infinity, if the two are parallel, the equation of
/// forces across them). That force fixes the space beyond it, and the plan goes on.
/// Returns the space fixed, or `None` if no such cut exists.
#[allow(clippy::too_many_arguments)]
fn ritter(
    b: &mut Board,
    t: &Truss,
    g: &PlaneGraph,
    sp: &Spaces,
    pt: &mut [Option<H<Point>>],
    ext: &External,
    mline: &[H<Line>],
    case: &LoadCase,
    fs: f64,
) -> Option<usize> {
    let known_outside = |s: usize, pt: &[Option<H<Point>>]| s < sp.n_ext && pt[s].is_some();
    let unknown_inside = |s: usize, pt: &[Option<H<Point>>]| s >= sp.n_ext && pt[s].is_none();
    for s1 in sp.n_ext..pt.len() {
        if pt[s1].is_some() {
            continue;
        }
        let f1 = &g.faces[sp.face_of[s1]];
        for &h1 in f1 {
            let x0 = sp.of_half[h1 ^ 1];
            if !known_outside(x0, pt) {
                continue;
            }
            for &h2 in f1 {
                let s2 = sp.of_half[h2 ^ 1];
                if h2 == h1 || s2 == s1 || !unknown_inside(s2, pt) {
                    continue;
                }
                for &h3 in &g.faces[sp.face_of[s2]] {
                    let x3 = sp.of_half[h3 ^ 1];
                    if h3 / 2 == h2 / 2 || !known_outside(x3, pt) {
                        continue;
                    }
                    let cut = [h1 / 2, h2 / 2, h3 / 2];
                    let Some(side) = part(t, &cut) else {
                        continue;
                    };
                    // Try the member next to the outside at either end of the cut.
                    for (k, known, unknown) in [(0, x0, s1), (2, x3, s2)] {
                        let (i, j) = match k {
                            0 => (cut[1], cut[2]),
                            _ => (cut[0], cut[1]),
                        };
                        let Some(tk) = section_force(t, &side, ext, cut[k], i, j) else {
                            continue;
                        };
                        b.set_context(|| {
                            format!(
                                "{}: Ritter section through {}, {}, {}",
                                case.name,
                                t.members[cut[0]].name,
                                t.members[cut[1]].name,
                                t.members[cut[2]].name
                            )
                        });
                        b.meet(&mline[i], &mline[j], Label::quiet("R", 0), N_RITTER_CUT);
                        let m = cut[k];
                        let px = pt[known].expect("known space");
                        let par = b.parallel(
                            &mline[m],
                            &px,
                            Label::NONE,
                            Role::Construction,
                            N_RITTER_PAR,
                        );
                        // P[right of a→b] − P[left of a→b] = t·(a→b).
                        let sign = if sp.of_half[2 * m] == known {
                            1.0
                        } else {
                            -1.0
                        };
                        let p = b
                            .lay_off(
                                &px,
                                &par,
                                sign * tk / fs,
                                space_label(unknown),
                                Role::Construction,
                                N_RITTER_FORCE,
                            )
                            .ok()?;
                        pt[unknown] = Some(p);
                        return Some(unknown);
                    }
                }
            }
        }
    }
    None
}

/// The joints on one side of a cut through `cut`, if removing those members parts the truss
/// in exactly two pieces with every cut member joining them.
fn part(t: &Truss, cut: &[usize; 3]) -> Option<Vec<bool>> {
    let k = t.joints.len();
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); k];
    for (m, mem) in t.members.iter().enumerate() {
        if !cut.contains(&m) {
            adj[mem.ends[0]].push(mem.ends[1]);
            adj[mem.ends[1]].push(mem.ends[0]);
        }
    }
    let start = t.members[cut[0]].ends[0];
    let mut side = vec![false; k];
    side[start] = true;
    let mut stack = vec![start];
    while let Some(v) = stack.pop() {
        for &w in &adj[v] {
            if !side[w] {
                side[w] = true;
                stack.push(w);
            }
        }
    }
    // Every cut member must join the two parts, and the other part must hang together.
    if cut
        .iter()
        .any(|&m| side[t.members[m].ends[0]] == side[t.members[m].ends[1]])
    {
        return None;
    }
    let other = (0..k).find(|&v| !side[v])?;
    let mut seen = side.iter().map(|s| !s).collect::<Vec<bool>>();
    let mut count = 0;
    let mut stack = vec![other];
    seen[other] = false;
    while let Some(v) = stack.pop() {
        count += 1;
        for &w in &adj[v] {
            if seen[w] {
                seen[w] = false;
                stack.push(w);
            }
        }
    }
    (count == side.iter().filter(|s| !**s).count()).then_some(side)
}

/// The tension in member `m` from the part `side` of the truss: moments about the meeting
/// point of members `i` and `j`, or, if they are parallel, forces across them. `None` if the
/// equation does not hold `m` (its line passes through the point, or runs parallel too).
fn section_force(
    t: &Truss,
    side: &[bool],
    ext: &External,
    m: usize,
    i: usize,
    j: usize,
) -> Option<f64> {
    let end_on_side = |mm: usize| {
        let [a, bb] = t.members[mm].ends;
        if side[a] {
            (a, bb)
        } else {
            (bb, a)
        }
    };
    let (a, other) = end_on_side(m);
    let dir = (t.joints[other].at - t.joints[a].at).normalize();
    let (di, _) = t.member_dir(i);
    let (dj, _) = t.member_dir(j);
    let cross = |u: Vector, v: Vector| u.x * v.y - u.y * v.x;
    let forces = ext.forces.iter().filter(|(jt, _)| side[*jt]);
    let scale = t.size();
    if cross(di, dj).abs() > 1e-9 {
        // The meeting point R of the lines of i and j.
        let pi = t.joints[t.members[i].ends[0]].at;
        let pj = t.joints[t.members[j].ends[0]].at;
        let s = cross(pj - pi, dj) / cross(di, dj);
        let r = pi + di * s;
        let arm = cross(t.joints[a].at - r, dir);
        if arm.abs() <= 1e-9 * scale {
            return None;
        }
        let moment: f64 = forces.map(|(jt, f)| cross(t.joints[*jt].at - r, *f)).sum();
        Some(-moment / arm)
    } else {
        let n = Vector::new(-di.y, di.x);
        let across = dir.dot(&n);
        if across.abs() <= 1e-9 {
            return None;
        }
        let sum: f64 = forces.map(|(_, f)| f.dot(&n)).sum();
        Some(-sum / across)
    }
}
