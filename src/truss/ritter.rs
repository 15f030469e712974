//! Ritter's section (LH B.4, Aufgabe 5): where no joint with two unknown members is left,
//! three members cut from a known outer space to another give the third by moments.

use super::faces::PlaneGraph;
use super::labels::*;
use super::notes::*;
use super::plan::*;
use super::Truss;
use crate::kernel::tolerance::{JOINT_CUT_SIN_EPS, REL_LAYOUT_EPS};
use crate::kernel::{Point, Vector};
use crate::protocol::{Board, Label, Role, H};

/// Ritter's method of sections where the plan stalls (LH B.4; Aufgabe 5, Tafel I, 5): a cut
/// through three members m₁, m₂, m₃ that runs from a known space outside the truss through
/// two unknown spaces to another known space outside, and parts the truss in two. The
/// moment equation of one part about the meeting point of two of the cut members gives the
/// force of the third (about a point at infinity, if the two are parallel, the equation of
/// forces across them). That force fixes the space beyond it, and the plan goes on.
/// Returns the space fixed, or `None` if no such cut exists.
pub(super) fn ritter(
    b: &mut Board,
    ctx: &PlanContext,
    g: &PlaneGraph,
    sp: &Spaces,
    pt: &mut [Option<H<Point>>],
) -> Option<usize> {
    let sec = find_section(ctx, g, sp, pt)?;
    let PlanContext {
        t, case, mline, dr, ..
    } = *ctx;
    let cut = sec.cut;
    b.set_context(|| {
        format!(
            "{}: Ritter section through {}, {}, {}",
            case.name, t.members[cut[0]].name, t.members[cut[1]].name, t.members[cut[2]].name
        )
    });
    // The moment point: two members' lines cut in the truss drawing.
    super::layout::in_column(b, super::layout::TRUSS, |b| {
        b.meet(
            &mline[sec.i],
            &mline[sec.j],
            Label::quiet("R", 0),
            N_RITTER_CUT,
        )
    });
    let m = cut[sec.k];
    let px = pt[sec.known].expect("known space");
    let par = b.parallel(&mline[m], &px, Role::Construction, N_RITTER_PAR);
    // P[right of a→b] − P[left of a→b] = t·(a→b).
    let sign = if sp.of_half[2 * m] == sec.known {
        1.0
    } else {
        -1.0
    };
    let len = sign * sec.force / dr.force_scale;
    let label = space_label(sec.unknown);
    let con = Role::Construction;
    let p = b
        .lay_off(&px, &par, len, con.labelled(label), N_RITTER_FORCE)
        .ok()?;
    pt[sec.unknown] = Some(p);
    Some(sec.unknown)
}

/// A section that gives a member's force: the three members cut, which of them (`k`, 0 or
/// 2) is found, the known outer space next to it and the unknown inner one, the other two
/// members (whose lines meet in the moment point), and the force.
struct Section {
    cut: [usize; 3],
    k: usize,
    known: usize,
    unknown: usize,
    i: usize,
    j: usize,
    force: f64,
}

/// The first section from a known outer space across two unknown inner spaces to another
/// known outer space whose moments (or forces across) give a member's force.
fn find_section(
    ctx: &PlanContext,
    g: &PlaneGraph,
    sp: &Spaces,
    pt: &[Option<H<Point>>],
) -> Option<Section> {
    let known_outside = |s: usize| s < sp.n_ext && pt[s].is_some();
    let unknown_inside = |s: usize| s >= sp.n_ext && pt[s].is_none();
    for s1 in (sp.n_ext..pt.len()).filter(|&s| pt[s].is_none()) {
        let f1 = &g.faces[sp.face_of[s1]];
        for &h1 in f1 {
            let x0 = sp.of_half[h1 ^ 1];
            if !known_outside(x0) {
                continue;
            }
            for &h2 in f1 {
                let s2 = sp.of_half[h2 ^ 1];
                if h2 == h1 || s2 == s1 || !unknown_inside(s2) {
                    continue;
                }
                for &h3 in &g.faces[sp.face_of[s2]] {
                    let x3 = sp.of_half[h3 ^ 1];
                    if h3 / 2 == h2 / 2 || !known_outside(x3) {
                        continue;
                    }
                    let cut = [h1 / 2, h2 / 2, h3 / 2];
                    if let Some(sec) = section_through(ctx, cut, (x0, s1), (x3, s2)) {
                        return Some(sec);
                    }
                }
            }
        }
    }
    None
}

/// The section through `cut`, if it separates the truss and gives the member next to the
/// outside at either end: `(known, unknown)` spaces at the first and at the last member.
fn section_through(
    ctx: &PlanContext,
    cut: [usize; 3],
    first: (usize, usize),
    last: (usize, usize),
) -> Option<Section> {
    let side = part(ctx.t, &cut)?;
    for (k, (known, unknown)) in [(0, first), (2, last)] {
        let (i, j) = match k {
            0 => (cut[1], cut[2]),
            _ => (cut[0], cut[1]),
        };
        if let Some(force) = section_force(ctx.t, &side, ctx.ext, cut[k], i, j) {
            return Some(Section {
                cut,
                k,
                known,
                unknown,
                i,
                j,
                force,
            });
        }
    }
    None
}

/// The joints on one side of a cut through `cut`, if removing those members parts the truss
/// in exactly two pieces with every cut member joining them.
pub(super) fn part(t: &Truss, cut: &[usize; 3]) -> Option<Vec<bool>> {
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
pub(super) fn section_force(
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
    if cross(di, dj).abs() > JOINT_CUT_SIN_EPS {
        // The meeting point R of the lines of i and j.
        let pi = t.joints[t.members[i].ends[0]].at;
        let pj = t.joints[t.members[j].ends[0]].at;
        let s = cross(pj - pi, dj) / cross(di, dj);
        let r = pi + di * s;
        let arm = cross(t.joints[a].at - r, dir);
        if arm.abs() <= REL_LAYOUT_EPS * scale {
            return None;
        }
        let moment: f64 = forces.map(|(jt, f)| cross(t.joints[*jt].at - r, *f)).sum();
        Some(-moment / arm)
    } else {
        let n = Vector::new(-di.y, di.x);
        let across = dir.dot(&n);
        if across.abs() <= JOINT_CUT_SIN_EPS {
            return None;
        }
        let sum: f64 = forces.map(|(_, f)| f.dot(&n)).sum();
        Some(-sum / across)
    }
}
