//! The joint polygons one by one (LH B.4, Abb. 17a): where the combined Cremona plan cannot
//! be drawn — members that cross in the drawing, or a load at a joint inside the outline,
//! which Bow's notation cannot name — every joint gets a force polygon of its own.
//!
//! Joints are taken in an order where at most two member forces are unknown. The known
//! forces at the joint (its loads and reactions, and the members already found, acting on
//! it) are laid head to tail clockwise (Regel 2); the parallels to the two unknown members,
//! through the end and through the start, close the polygon. A member acts on the joint as
//! its side of the polygon: pointing away from the joint it pulls (tension, Regel 1).
//! Every member is found once, so it is drawn in one joint polygon and read there.

use super::labels::{member_label, write_member};
use super::layout::{grow, EMPTY};
use super::plan::{check_member, member_check_reference, plan_result, CaseResult, PlanContext};
use crate::kernel::tolerance::JOINT_CUT_SIN_EPS;
use crate::kernel::{Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Cut, Label, Note, Role, Scale, Topic, H};

const N_START: Note = note(
    "start of the joint polygon",
    Some("Knotenpunktpolygon"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
const N_NAME: Note = note(
    "the joint’s name over its polygon",
    Some("Knotenpunkt"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
/// Height of the joint's name over its polygon, the gap under it included (mm): a heading
/// of the sheet is set 5 mm high.
const NAME_MM: f64 = 7.0;
const N_KNOWN: Note = note(
    "known force at the joint laid on, clockwise",
    Some("bekannte Kraft"),
    "LH B.4, Regel 2",
    Topic::Cremona,
);
const N_PAR: Note = note(
    "parallel to an unknown member",
    Some("Parallele zum Stab"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
const N_CLOSE: Note = note(
    "the two parallels close the joint polygon",
    Some("Knotenpunktpolygon"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
const N_SIDE: Note = note(
    "member force drawn: the side of the joint polygon along the member",
    Some("Stabkraft"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
const N_FORCE: Note = note(
    "member force: tension if it points away from the joint (Regel 1)",
    Some("Stabkraft"),
    "LH B.4, Regel 1",
    Topic::Cremona,
);

/// A force on the joint in the polygon: its vector (kg) and, for a member, which one.
struct Item {
    angle: f64,
    force: Vector,
    member: Option<usize>,
}

/// A member found at a joint: its index, its measured force, its length in the plan (mm).
type Found = (usize, H<f64>, f64);

/// The state of the joint polygons of one case: which members meet at each joint, the
/// external forces at each, the member forces found so far, and where the next polygon goes.
struct Polygons<'a> {
    ctx: &'a PlanContext<'a>,
    members_at: Vec<Vec<usize>>,
    ext_at: Vec<Vec<Vector>>,
    reference: f64,
    force: Vec<Option<f64>>,
    /// The objects the forces were read as (their error bounds follow into the balance).
    ids: Vec<crate::protocol::ObjId>,
    plan_mm: Vec<f64>,
    bx: [f64; 4],
    cursor: f64,
}

/// Draws the joint polygons of one case from `at` to the right; returns the result and the
/// bounding box of the polygons relative to `at`.
///
/// # Errors
/// When no joint with at most two unknown members (not parallel) is left.
pub(crate) fn joint_polygons(
    b: &mut Board,
    ctx: &PlanContext,
) -> Result<(CaseResult, [f64; 4]), ConstructionError> {
    let PlanContext { t, case, sol, .. } = *ctx;
    let mut p = Polygons::new(ctx);
    let k = t.joints.len();
    let mut queue: std::collections::VecDeque<usize> = (0..k).collect();
    let mut queued = vec![true; k];
    let mut stalled = 0;
    while let Some(v) = queue.pop_front() {
        queued[v] = false;
        let unknown = p.unknown_at(v);
        if !p.solvable(v, &unknown) {
            // Revisit later; give up when a whole round finds nothing.
            if !unknown.is_empty() {
                stalled += 1;
                if stalled > queue.len() + 1 {
                    break;
                }
                queued[v] = true;
                queue.push_back(v);
            }
            continue;
        }
        stalled = 0;
        let Some(found) = p.draw(b, v, &unknown)? else {
            continue;
        };
        for (m, h, mm) in found {
            check_member(b, t, &h, m, sol, p.reference);
            p.force[m] = Some(h.g);
            p.ids[m] = h.id;
            p.plan_mm[m] = mm;
            for &e in &t.members[m].ends {
                if !queued[e] {
                    queued[e] = true;
                    queue.push_back(e);
                }
            }
        }
        p.cursor = ctx.at.x + p.bx[2] + 12.0;
    }
    b.set_context(|| case.name.clone());
    if let Some(m) = p.force.iter().position(|f| f.is_none()) {
        return Err(ConstructionError::PlanStalls {
            member: t.members[m].name.to_string(),
            joints: Vec::new(),
            reason: format!(
                "the joint polygons stall before member {}: every joint left has three or more unknown member forces (or two in line)",
                t.members[m].name
            ),
        });
    }
    let result = plan_result(b, ctx, (&p.force, &p.ids), &p.plan_mm);
    let bx = if p.bx[0].is_finite() { p.bx } else { [0.0; 4] };
    Ok((result, bx))
}

impl<'a> Polygons<'a> {
    fn new(ctx: &'a PlanContext<'a>) -> Self {
        let t = ctx.t;
        let k = t.joints.len();
        let mut members_at: Vec<Vec<usize>> = vec![Vec::new(); k];
        for (m, mem) in t.members.iter().enumerate() {
            members_at[mem.ends[0]].push(m);
            members_at[mem.ends[1]].push(m);
        }
        let mut ext_at: Vec<Vec<Vector>> = vec![Vec::new(); k];
        for &(j, f) in &ctx.ext.forces {
            ext_at[j].push(f);
        }
        Polygons {
            ctx,
            members_at,
            ext_at,
            reference: member_check_reference(ctx),
            force: vec![None; t.members.len()],
            ids: vec![crate::protocol::ObjId::NONE; t.members.len()],
            plan_mm: vec![0.0; t.members.len()],
            bx: EMPTY,
            cursor: ctx.at.x,
        }
    }

    /// The unit direction of member `m` from joint `v` to its other end.
    fn dir_from(&self, v: usize, m: usize) -> Vector {
        let t = self.ctx.t;
        let [a, c] = t.members[m].ends;
        let o = if a == v { c } else { a };
        (t.joints[o].at - t.joints[v].at).normalize()
    }

    /// The members at `v` whose force is still unknown.
    fn unknown_at(&self, v: usize) -> Vec<usize> {
        self.members_at[v]
            .iter()
            .copied()
            .filter(|&m| self.force[m].is_none())
            .collect()
    }

    /// One unknown member, or two that are not in line, close a joint polygon.
    fn solvable(&self, v: usize, unknown: &[usize]) -> bool {
        match unknown.len() {
            1 => true,
            2 => {
                let (d1, d2) = (self.dir_from(v, unknown[0]), self.dir_from(v, unknown[1]));
                (d1.x * d2.y - d1.y * d2.x).abs() > JOINT_CUT_SIN_EPS
            }
            _ => false,
        }
    }

    /// The forces at `v`, clockwise (Regel 2): external forces and members, by angle.
    fn items(&self, v: usize) -> Vec<Item> {
        let mut items: Vec<Item> = self.ext_at[v]
            .iter()
            .map(|&f| Item {
                angle: f.y.atan2(f.x),
                force: f,
                member: None,
            })
            .chain(self.members_at[v].iter().map(|&m| {
                let d = self.dir_from(v, m);
                Item {
                    angle: d.y.atan2(d.x),
                    force: d * self.force[m].unwrap_or(0.0),
                    member: Some(m),
                }
            }))
            .collect();
        items.sort_by(|a, c| c.angle.total_cmp(&a.angle).then(a.member.cmp(&c.member)));
        items
    }

    /// The polygon of joint `v`: the known forces laid head to tail clockwise, then the
    /// unknown members' parallels close it. Returns each member found with its measured
    /// force and its length in the plan; `None` if the two parallels do not meet.
    fn draw(
        &mut self,
        b: &mut Board,
        v: usize,
        unknown: &[usize],
    ) -> Result<Option<Vec<Found>>, ConstructionError> {
        let PlanContext {
            t, case, dr, at, ..
        } = *self.ctx;
        let fs = dr.force_scale;
        let items = self.items(v);
        let known: Vec<&Item> = items
            .iter()
            .filter(|i| i.member.is_none_or(|m| self.force[m].is_some()) && i.force.norm() > 0.0)
            .collect();
        // The numbers first, to place the polygon.
        let mut corners = vec![Vector::zeros()];
        for i in &known {
            corners.push(corners[corners.len() - 1] + i.force / fs);
        }
        let close = -corners[corners.len() - 1];
        let lo = corners
            .iter()
            .fold(f64::INFINITY, |a, c| a.min(c.x))
            .min(0.0);
        let name = &t.joints[v].name;
        b.set_context(|| format!("{}: joint polygon {name}", case.name));
        let at_start = Point::new(self.cursor - lo, at.y);
        let start = b.point(at_start, Role::Given, N_START);
        let mut own = EMPTY;
        let mut cur = start;
        for i in &known {
            let along = b.line_dir(&cur, i.force, Role::Auxiliary, N_KNOWN)?;
            let len = i.force.norm() / fs;
            cur = b.lay_off(&cur, &along, len, Role::Force, N_KNOWN)?;
            grow(&mut own, cur.g, at);
        }
        grow(&mut own, start.g, at);
        // The unknowns, in clockwise order after the knowns.
        let order: Vec<usize> = items
            .iter()
            .filter_map(|i| i.member)
            .filter(|m| unknown.contains(m))
            .collect();
        if let [m] = order[..] {
            let h = self.read(b, v, &cur, &start, m);
            self.name(b, v, own);
            return Ok(Some(vec![(m, h, close.norm())]));
        }
        let (m1, m2) = (order[0], order[1]);
        let mline = self.ctx.mline;
        let con = Role::Construction;
        let l1 = b.parallel(&mline[m1], &cur, con, N_PAR);
        let l2 = b.parallel(&mline[m2], &start, con, N_PAR);
        let Cut::Point(mid, _) = b.meet(&l1, &l2, Label::NONE, N_CLOSE) else {
            self.name(b, v, own);
            return Ok(None);
        };
        grow(&mut own, mid.g, at);
        let h1 = self.read(b, v, &cur, &mid, m1);
        let h2 = self.read(b, v, &mid, &start, m2);
        self.name(b, v, own);
        Ok(Some(vec![
            (m1, h1, (mid.g - cur.g).norm()),
            (m2, h2, (start.g - mid.g).norm()),
        ]))
    }

    /// The name of joint `v` over its polygon, whose box (from the plan's corner) is `own`,
    /// as LH Abb. 17a names each polygon by its joint; the plan's box takes in both.
    fn name(&mut self, b: &mut Board, v: usize, own: [f64; 4]) {
        let at = self.ctx.at;
        let top = Point::new(at.x + own[0], at.y + own[3] + NAME_MM);
        let name = match Label::from_name(&self.ctx.t.joints[v].name) {
            Label {
                base,
                index: Some(i),
                ..
            } => format!("{base}_{i}"),
            l => l.base.into_owned(),
        };
        b.table(top, vec![vec![name]], &[], N_NAME);
        for p in [Point::new(at.x + own[0], at.y + own[1]), top] {
            grow(&mut self.bx, p, at);
        }
        grow(&mut self.bx, Point::new(at.x + own[2], at.y + own[3]), at);
    }

    /// Member `m` drawn as the side `from → to` of the polygon of joint `v`, and its force
    /// read along the member from `v` outwards (tension if the side points away, Regel 1).
    fn read(&self, b: &mut Board, v: usize, from: &H<Point>, to: &H<Point>, m: usize) -> H<f64> {
        let t = self.ctx.t;
        let kg = Scale::kg(self.ctx.dr.force_scale);
        let on_v = t.members[m].ends[0] == v;
        let (p, q) = if on_v { (from, to) } else { (to, from) };
        b.naming(write_member(t, m), |b| {
            let name = Role::Result.labelled(member_label(b, t, m));
            b.segment(from, to, name, N_SIDE);
            b.measure(p, q, &self.ctx.mline[m], kg, member_label(b, t, m), N_FORCE)
        })
    }
}
