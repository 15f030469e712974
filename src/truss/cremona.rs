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

use super::bow::*;
use super::faces::{self, PlaneGraph};
use super::graphic_reactions::*;
use super::labels::*;
use super::layout::*;
use super::matrix::{self, Solution};
use super::notes::*;
use super::plan::*;
use super::{JointLoad, LoadCase, SupportKind, Truss};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Role, H, TABLE_BLOCK_ROWS};
use crate::statics::funicular::polygon::{self, StringStyle};

pub use super::plan::{CaseResult, ReactionForce, TrussDrawing, ZERO_FORCE_REL};

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
