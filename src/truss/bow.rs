//! The Cremona plan in Bow's notation (LH B.4, Abb. 17): the external forces clockwise round
//! the outline, then every joint with two unknown members, Ritter's section where none is
//! left.

use super::faces::{self, dest, origin, PlaneGraph};
use super::labels::*;
use super::layout::*;
use super::notes::*;
use super::plan::*;
use super::ritter::*;
use super::Truss;
use crate::kernel::Point;
use crate::protocol::{Board, ConstructionError, Cut, Label, Role, Scale, H};

/// The forces at a joint (not placed yet) whose line of action leaves into the sector of
/// angular width `span` clockwise from `back`, in clockwise order. The line of action is
/// drawn on the outside: the arrow coming in towards the joint (−f) if that side is outside,
/// else going out (+f).
fn in_sector(
    ext: &External,
    at_v: &[usize],
    placed: &[bool],
    back: f64,
    span: f64,
) -> impl Iterator<Item = usize> {
    let inside = |a: f64| {
        let c = faces::cw(back, a);
        c > 0.0 && c < span
    };
    let mut here: Vec<(f64, usize)> = Vec::new();
    for &fi in at_v.iter().filter(|&&fi| !placed[fi]) {
        let f = ext.forces[fi].1;
        let (a_in, a_out) = ((-f.y).atan2(-f.x), f.y.atan2(f.x));
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
    here.into_iter().map(|(_, fi)| fi)
}

/// The external forces in clockwise order round the outline, and the space left of every
/// half-edge (outer half-edges only; the rest `usize::MAX`).
pub(super) type Outline = (Vec<usize>, Vec<usize>);

/// Assigns every external force to its place on the outline, clockwise, and every outer
/// half-edge to the space on its left.
pub(super) fn outline(
    t: &Truss,
    g: &PlaneGraph,
    ext: &External,
) -> Result<Outline, ConstructionError> {
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
    // The forces at each joint, in their order (one list for all joints, not one each).
    let at_joint = faces::Lists::grouped(
        t.joints.len(),
        (ext.forces.iter().enumerate()).map(|(fi, &(j, _))| (j, fi)),
    );
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
        for fi in in_sector(ext, &at_joint[v], &placed, back, span) {
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

pub(super) fn cremona_plan(
    b: &mut Board,
    ctx: &PlanContext,
    g: &PlaneGraph,
    round: Outline,
) -> Result<(CaseResult, [f64; 4]), ConstructionError> {
    let PlanContext { t, case, at, .. } = *ctx;
    let sm = SpaceMap::new(g, round);
    let mut bx = EMPTY;
    let mut pt: Vec<Option<H<Point>>> = vec![None; sm.n_spaces];
    external_polygon(b, ctx, &sm.order, &mut pt, &mut bx)?;
    let joints_of_space = sm.joints_of_space(t);
    let mut found = Found::new(ctx, &sm.space_of_half);
    let mut queue: std::collections::VecDeque<usize> = (0..t.joints.len()).collect();
    let mut queued = vec![true; t.joints.len()];
    // Members on the outline are known from the external polygon already.
    found.settle(b, &pt, &mut (0..t.members.len()));
    let spaces = Spaces {
        of_half: &sm.space_of_half,
        face_of: &sm.face_of_space,
        n_ext: sm.n_ext,
    };
    loop {
        let fixed = match queue.pop_front() {
            Some(v) => {
                queued[v] = false;
                joint_polygon(b, ctx, g, v, &spaces, &mut pt)
            }
            None if pt.iter().all(|p| p.is_some()) => break,
            // No joint with two unknown members is left: Ritter's section.
            None => match ritter(b, ctx, g, &spaces, &mut pt) {
                Some(u) => Some(u),
                None => break,
            },
        };
        let Some(u) = fixed else {
            continue;
        };
        grow(&mut bx, pt[u].expect("just fixed").g, at);
        found.settle(
            b,
            &pt,
            &mut g.faces[sm.face_of_space[u]].iter().map(|h| h / 2),
        );
        for &j in &joints_of_space[u] {
            if !queued[j] {
                queued[j] = true;
                queue.push_back(j);
            }
        }
    }
    b.set_context(|| case.name.clone());
    if let Some(m) = found.forces.iter().position(|f| f.is_none()) {
        return Err(stalls(t, g, &found.forces, m));
    }
    let result = plan_result(b, ctx, (&found.forces, &found.ids), &found.plan_mm);
    Ok((result, bx))
}

/// The spaces of Bow's notation: the external forces in clockwise order round the outline,
/// the space left of every half-edge, and the face of every space (inner faces numbered
/// after the outer spaces).
struct SpaceMap {
    order: Vec<usize>,
    space_of_half: Vec<usize>,
    face_of_space: Vec<usize>,
    n_ext: usize,
    n_spaces: usize,
}

impl SpaceMap {
    fn new(g: &PlaneGraph, (order, mut space_of_half): Outline) -> SpaceMap {
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
        SpaceMap {
            order,
            space_of_half,
            face_of_space,
            n_ext,
            n_spaces,
        }
    }

    /// The joints touching each space, to revisit when it becomes known.
    fn joints_of_space(&self, t: &Truss) -> faces::Lists {
        let of_half = self.space_of_half.iter().enumerate();
        let mut all =
            faces::Lists::grouped(self.n_spaces, of_half.map(|(h, &s)| (s, origin(t, h))));
        let mut out = faces::Lists::with_capacity(self.space_of_half.len());
        for s in 0..all.len() {
            all[s].sort_unstable();
            let js = &all[s];
            out.push(
                (0..js.len())
                    .filter(|&i| i == 0 || js[i] != js[i - 1])
                    .map(|i| js[i]),
            );
        }
        out
    }
}

/// The external force polygon, clockwise round the truss (Regel 2): its corners are the
/// points of the outer spaces.
fn external_polygon(
    b: &mut Board,
    ctx: &PlanContext,
    order: &[usize],
    pt: &mut [Option<H<Point>>],
    bx: &mut [f64; 4],
) -> Result<(), ConstructionError> {
    let (at, fs) = (ctx.at, ctx.dr.force_scale);
    let start = b.point(at, Role::Given.labelled(space_label(0)), N_START);
    grow(bx, at, at);
    pt[0] = Some(start);
    let mut cur = start;
    let (t, case) = (ctx.t, &ctx.case.name);
    for (i, &fi) in order.iter().enumerate() {
        let (j, f) = ctx.ext.forces[fi];
        b.set_context_within(Some(case), || {
            format!("external force at joint {}", t.joints[j].name)
        });
        let along = b.line_dir(&cur, f, Role::Auxiliary, N_EXT_DIR)?;
        let last = i + 1 == order.len();
        let lab = if last {
            Label::NONE
        } else {
            space_label(i + 1)
        };
        let next = b.lay_off(
            &cur,
            &along,
            f.norm() / fs,
            Role::Force.labelled(lab),
            N_EXT,
        )?;
        grow(bx, next.g, at);
        if !last {
            pt[i + 1] = Some(next);
        }
        cur = next;
    }
    b.set_context(|| case.clone());
    Ok(())
}

/// The member forces found so far, and their lengths in the plan.
struct Found<'a> {
    ctx: &'a PlanContext<'a>,
    space_of_half: &'a [usize],
    reference: f64,
    forces: Vec<Option<f64>>,
    /// The objects the forces were read as (their error bounds follow into the balance).
    ids: Vec<crate::protocol::ObjId>,
    plan_mm: Vec<f64>,
}

impl<'a> Found<'a> {
    fn new(ctx: &'a PlanContext<'a>, space_of_half: &'a [usize]) -> Self {
        let n = ctx.t.members.len();
        Found {
            ctx,
            space_of_half,
            reference: member_check_reference(ctx),
            forces: vec![None; n],
            ids: vec![crate::protocol::ObjId::NONE; n],
            plan_mm: vec![0.0; n],
        }
    }

    /// Draws every member whose two spaces are known and that is not drawn yet: the segment
    /// between their points, read off and checked.
    fn settle(
        &mut self,
        b: &mut Board,
        pt: &[Option<H<Point>>],
        members: &mut dyn Iterator<Item = usize>,
    ) {
        let PlanContext { t, sol, mline, .. } = *self.ctx;
        let kg = Scale::kg(self.ctx.dr.force_scale);
        for m in members {
            if self.forces[m].is_some() {
                continue;
            }
            let (l, r) = (self.space_of_half[2 * m], self.space_of_half[2 * m + 1]);
            if let (Some(pl), Some(pr)) = (pt[l], pt[r]) {
                let v = b.naming(write_member(t, m), |b| {
                    let name = Role::Result.labelled(member_label(b, t, m));
                    b.segment(&pl, &pr, name, N_SIDE);
                    b.measure(&pl, &pr, &mline[m], kg, member_label(b, t, m), N_FORCE)
                });
                check_member(b, t, &v, m, sol, self.reference);
                self.forces[m] = Some(v.g);
                self.ids[m] = v.id;
                self.plan_mm[m] = (pr.g - pl.g).norm();
            }
        }
    }
}

/// The plan stalls before member `m`: the joints where it is stuck named (at most six).
fn stalls(t: &Truss, g: &PlaneGraph, forces: &[Option<f64>], m: usize) -> ConstructionError {
    let stuck: Vec<String> = (0..t.joints.len())
        .filter(|&v| g.around[v].iter().any(|&h| forces[h / 2].is_none()))
        .map(|v| t.joints[v].name.to_string())
        .take(6)
        .collect();
    ConstructionError::PlanStalls {
        member: t.members[m].name.to_string(),
        reason: format!(
            "the Cremona plan stalls before member {}: at joints {} three or more member forces are unknown, and no section through three members with two unknown spaces between them gives one of them (Ritter, LH B.4)",
            t.members[m].name,
            stuck.join(", ")
        ),
        joints: stuck,
    }
}

/// The polygon of joint `v` if only one space round it is unknown: the parallels to the two
/// members bounding that space, through the points of the spaces beyond them, meet in its
/// point (Regel 2). Returns the space fixed.
pub(super) fn joint_polygon(
    b: &mut Board,
    ctx: &PlanContext,
    g: &PlaneGraph,
    v: usize,
    sp: &Spaces,
    pt: &mut [Option<H<Point>>],
) -> Option<usize> {
    let PlanContext { t, case, mline, .. } = *ctx;
    let around = &g.around[v];
    let d = around.len();
    if d < 2 {
        return None;
    }
    // Exactly one half-edge round the joint with its space unknown.
    let mut unknown = (0..d).filter(|&i| pt[sp.of_half[around[i]]].is_none());
    let (Some(i), None) = (unknown.next(), unknown.next()) else {
        return None;
    };
    let (ha, hb) = (around[i], around[(i + 1) % d]);
    let u = sp.of_half[ha];
    let (px, py) = (pt[sp.of_half[ha ^ 1]]?, pt[sp.of_half[hb]]?);
    let name = &t.joints[v].name;
    let member = |h: usize| &t.members[h / 2].name;
    // Each parallel names its member on a board that keeps its drawing (no check is made in
    // them); the joint's checks below keep the joint's context.
    let within = Some(case.name.as_str());
    b.set_context_within(within, || format!("joint {name}, member {}", member(ha)));
    let la = b.parallel(&mline[ha / 2], &px, Role::Construction, N_PAR);
    b.set_context_within(within, || format!("joint {name}, member {}", member(hb)));
    let lb = b.parallel(&mline[hb / 2], &py, Role::Construction, N_PAR);
    b.set_context(|| [case.name.as_str(), ": joint ", name.as_str()].concat());
    match b.meet(&la, &lb, space_label(u), N_SPACE) {
        Cut::Point(p, _) => {
            pt[u] = Some(p);
            Some(u)
        }
        // Two members in line at this joint: another joint has to fix the space.
        _ => None,
    }
}
