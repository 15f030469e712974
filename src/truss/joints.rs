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

use super::labels::member_label;
use super::layout::{grow, EMPTY};
use super::plan::{check_member, check_reference, plan_result, CaseResult, PlanContext};
use crate::kernel::{Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Cut, Label, Note, Role, Scale, Topic, H};

const N_START: Note = note(
    "start of the joint polygon",
    Some("Knotenpunktpolygon"),
    "LH B.4, Abb. 17a",
    Topic::Cremona,
);
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

/// Draws the joint polygons of one case from `at` to the right; returns the result and the
/// bounding box of the polygons relative to `at`.
///
/// # Errors
/// When no joint with at most two unknown members (not parallel) is left.
pub(crate) fn joint_polygons(
    b: &mut Board,
    ctx: &PlanContext,
) -> Result<(CaseResult, [f64; 4]), ConstructionError> {
    let PlanContext {
        t,
        case,
        ext,
        sol,
        dr,
        at,
        mline,
        maxload,
    } = *ctx;
    let fs = dr.force_scale;
    let kg = Scale::kg(fs);
    let k = t.joints.len();
    let mut members_at: Vec<Vec<usize>> = vec![Vec::new(); k];
    for (m, mem) in t.members.iter().enumerate() {
        members_at[mem.ends[0]].push(m);
        members_at[mem.ends[1]].push(m);
    }
    let mut ext_at: Vec<Vec<Vector>> = vec![Vec::new(); k];
    for &(j, f) in &ext.forces {
        ext_at[j].push(f);
    }
    let reference = check_reference(maxload, ext);
    let dir_from = |v: usize, m: usize| {
        let [a, c] = t.members[m].ends;
        let o = if a == v { c } else { a };
        (t.joints[o].at - t.joints[v].at).normalize()
    };
    let mut force: Vec<Option<f64>> = vec![None; t.members.len()];
    let mut plan_mm = vec![0.0; t.members.len()];
    let mut bx = EMPTY;
    let mut cursor = at.x;
    let mut queue: std::collections::VecDeque<usize> = (0..k).collect();
    let mut queued = vec![true; k];
    let mut stalled = 0;
    while let Some(v) = queue.pop_front() {
        queued[v] = false;
        let unknown: Vec<usize> = members_at[v]
            .iter()
            .copied()
            .filter(|&m| force[m].is_none())
            .collect();
        let solvable = match unknown.len() {
            1 => true,
            2 => {
                let (d1, d2) = (dir_from(v, unknown[0]), dir_from(v, unknown[1]));
                (d1.x * d2.y - d1.y * d2.x).abs() > 1e-9
            }
            _ => false,
        };
        if !solvable {
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
        // Clockwise from the first known force after the unknowns (Regel 2).
        let mut items: Vec<Item> = ext_at[v]
            .iter()
            .map(|&f| Item {
                angle: f.y.atan2(f.x),
                force: f,
                member: None,
            })
            .chain(members_at[v].iter().map(|&m| {
                let d = dir_from(v, m);
                Item {
                    angle: d.y.atan2(d.x),
                    force: d * force[m].unwrap_or(0.0),
                    member: Some(m),
                }
            }))
            .collect();
        items.sort_by(|a, c| c.angle.total_cmp(&a.angle).then(a.member.cmp(&c.member)));
        let known: Vec<&Item> = items
            .iter()
            .filter(|i| i.member.is_none_or(|m| force[m].is_some()) && i.force.norm() > 0.0)
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
        let start = b.point(
            Point::new(cursor - lo, at.y),
            Label::NONE,
            Role::Given,
            N_START,
        );
        let mut cur = start;
        for i in &known {
            let along = b.line_dir(&cur, i.force, Label::NONE, Role::Auxiliary, N_KNOWN)?;
            cur = b.lay_off(
                &cur,
                &along,
                i.force.norm() / fs,
                Label::NONE,
                Role::Force,
                N_KNOWN,
            )?;
            grow(&mut bx, cur.g, at);
        }
        grow(&mut bx, start.g, at);
        // The unknowns, in clockwise order after the knowns.
        let order: Vec<usize> = items
            .iter()
            .filter_map(|i| i.member)
            .filter(|m| unknown.contains(m))
            .collect();
        let read = |b: &mut Board, from: &H<Point>, to: &H<Point>, m: usize| {
            b.segment(from, to, member_label(t, m), Role::Result, N_FORCE);
            // The side from..to acts on v; read along the member from v outwards.
            let on_v = t.members[m].ends[0] == v;
            let (p, q) = if on_v { (from, to) } else { (to, from) };
            b.measure(p, q, &mline[m], kg, member_label(t, m), N_FORCE)
        };
        let mut found: Vec<(usize, H<f64>, f64)> = Vec::new();
        if order.len() == 1 {
            let m = order[0];
            let h = read(b, &cur, &start, m);
            found.push((m, h, close.norm()));
        } else {
            let (m1, m2) = (order[0], order[1]);
            let l1 = b.parallel(&mline[m1], &cur, Label::NONE, Role::Construction, N_PAR);
            let l2 = b.parallel(&mline[m2], &start, Label::NONE, Role::Construction, N_PAR);
            let mid = match b.meet(&l1, &l2, Label::NONE, N_CLOSE) {
                Cut::Point(p, _) => p,
                _ => continue,
            };
            grow(&mut bx, mid.g, at);
            let h1 = read(b, &cur, &mid, m1);
            let h2 = read(b, &mid, &start, m2);
            found.push((m1, h1, (mid.g - cur.g).norm()));
            found.push((m2, h2, (start.g - mid.g).norm()));
        }
        for (m, h, mm) in found {
            check_member(b, &h, m, sol, reference);
            force[m] = Some(h.g);
            plan_mm[m] = mm;
            for &e in &t.members[m].ends {
                if !queued[e] {
                    queued[e] = true;
                    queue.push_back(e);
                }
            }
        }
        cursor = at.x + bx[2] + 12.0;
    }
    b.set_context(|| case.name.clone());
    if let Some(m) = force.iter().position(|f| f.is_none()) {
        return Err(ConstructionError::PlanStalls {
            member: t.members[m].name.clone(),
            joints: Vec::new(),
            reason: format!(
                "the joint polygons stall before member {}: every joint left has three or more unknown member forces (or two in line)",
                t.members[m].name
            ),
        });
    }
    let result = plan_result(t, case, ext, &force, &plan_mm, sol, dr);
    if !bx[0].is_finite() {
        bx = [0.0; 4];
    }
    Ok((result, bx))
}
