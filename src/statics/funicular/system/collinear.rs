//! Forces on one line of action (LH A.2, Abb. 2): they are laid off head to tail along that
//! line, and their resultant is their algebraic sum, acting on the same line. No pole and no
//! funicular polygon are wanted: every string would pass through one point of the line.
//!
//! On the sheet the chain is staggered, as the books draw such sums: each force on its own
//! parallel a few mm under the last, its tail squared down from the head before it, and R on a
//! parallel under them all, between the start and the end of the chain squared down.

use super::{Plan, Polygon, System, SystemResults, ARROW_MM, GAP_MM};
use crate::kernel::tolerance::{PARALLEL_SIN_EPS, REL_CLOSURE_EPS, REL_POSITION_EPS};
use crate::kernel::{cross, Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Label, Note, Role, Topic, H};
use crate::statics::funicular::{Resolution, Resultant};

/// How far each force's parallel lies under the last one's (mm).
const STAGGER_MM: f64 = 5.0;
/// R's arrow in the position plan (as long as the forces' arrows, [`ARROW_MM`]): its gap past
/// the last point of application (mm).
const ARROW_GAP_MM: f64 = 16.0;

const N_START_ONE_LINE: Note = note(
    "start of the chain of forces",
    Some("Kräftezug"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_R_PLAN: Note = note(
    "R in the position plan: on the same line of action, in the sense of the sum",
    Some("Resultierende"),
    "LH A.2, Abb. 2",
    Topic::Loads,
);
const N_TRACK: Note = note(
    "the common line of action carried over through the start",
    Some("Aktionslinie"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_ACROSS: Note = note(
    "perpendicular through the start: the forces are laid off one under the other",
    Some("Lot"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_STAGGER: Note = note(
    "a parallel a little lower for the next force",
    Some("Parallele"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_CARRY: Note = note(
    "the head of the last force squared down: the next force starts under it",
    Some("Lot"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_LAY_OFF: Note = note(
    "lay off the force at the force scale, in its own sense (right positive)",
    Some("Kräftemaßstab"),
    "LH A.1-2, Abb. 2",
    Topic::ForcePlan,
);
const N_ENDS: Note = note(
    "start and end of the chain squared down onto the resultant’s parallel",
    Some("Resultierende"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);
const N_SUM: Note = note(
    "the resultant R = P₁ + P₂ + …, the algebraic sum, read off along the line",
    Some("Resultierende, algebraische Summe"),
    "LH A.2, Abb. 2",
    Topic::ForcePlan,
);

impl System<'_, '_> {
    /// The forces' common line of action, as a unit vector pointing right (or up where the
    /// line is vertical), if there are two or more forces and they all act on one line: every
    /// direction parallel to the first, every point of application on its line (both to
    /// rounding, the points relative to their own spread).
    pub(super) fn common_line(&self) -> Option<Vector> {
        let first = self.forces.first()?;
        if self.forces.len() < 2 {
            return None;
        }
        let u0 = first.f / first.f.norm();
        let spread = (self.forces.iter())
            .map(|f| (f.at - first.at).norm())
            .fold(0.0, f64::max);
        let on_line = self.forces.iter().all(|f| {
            let u = f.f / f.f.norm();
            cross(&u0, &u).abs() <= PARALLEL_SIN_EPS
                && cross(&(f.at - first.at), &u0).abs() <= REL_POSITION_EPS * spread
        });
        let right = u0.x > 0.0 || (u0.x == 0.0 && u0.y > 0.0);
        on_line.then_some(if right { u0 } else { -u0 })
    }

    /// The construction for forces on one line: the staggered chain, R as their algebraic sum
    /// on their common line (or equilibrium), and the resolutions asked for.
    pub(super) fn on_one_line(
        &mut self,
        (_, apps, xmax): &Plan,
        u: Vector,
        resolutions: &[Resolution],
    ) -> Result<SystemResults, ConstructionError> {
        // Room for R's arrow beyond the last point of application.
        let xmax = xmax + (ARROW_GAP_MM + ARROW_MM) * u.x.max(0.0);
        let poly = self.chain(xmax, u)?;
        let tol = self.b.tolerance().length;
        let closed = poly.r_len <= tol.max(REL_CLOSURE_EPS * poly.sides_mm);
        let outcome = if closed {
            self.no_moment(&poly, &apps[0], N_SUM);
            (Resultant::Equilibrium, None)
        } else {
            let (r, line) = self.resultant_force(&poly, &apps[0], Role::Construction)?;
            self.plan_arrow(apps, u, poly.r)?;
            (r, Some(line))
        };
        self.resolved(outcome, &poly, resolutions)
    }

    /// R's arrow in the position plan, on the common line beyond the last arrow: the plan
    /// shows place and sense only, so it is as long as the forces' arrows.
    fn plan_arrow(
        &mut self,
        apps: &[H<Point>],
        u: Vector,
        r: Vector,
    ) -> Result<(), ConstructionError> {
        let far = (apps.iter())
            .max_by(|p, q| p.g.coords.dot(&u).total_cmp(&q.g.coords.dot(&u)))
            .expect("two or more forces");
        let sense = r.dot(&u).signum();
        let b = &mut *self.b;
        let line = b.line_dir(far, u, Role::Construction, N_R_PLAN)?;
        let (near, away) = (ARROW_GAP_MM, ARROW_GAP_MM + ARROW_MM);
        let (from, to) = if sense > 0.0 {
            (near, away)
        } else {
            (away, near)
        };
        let tail = b.lay_off(far, &line, from, Role::Construction.named("R"), N_R_PLAN)?;
        let head = b.lay_off(far, &line, to, Role::Construction, N_R_PLAN)?;
        b.segment(&tail, &head, Role::Force, N_R_PLAN);
        Ok(())
    }

    /// The forces laid off head to tail along `u`, each on its own parallel, and R read off
    /// on the parallel under them all and checked against the algebraic sum.
    fn chain(&mut self, xmax: f64, u: Vector) -> Result<Polygon, ConstructionError> {
        let fs = self.dr.force_scale;
        let lens: Vec<f64> = self.forces.iter().map(|f| f.f.dot(&u) / fs).collect();
        let origin = self.dr.plan_at.unwrap_or_else(|| {
            // The chain's leftmost point a gap right of the plan.
            let (mut sum, mut left) = (0.0_f64, 0.0_f64);
            for l in &lens {
                sum += l;
                left = left.min(sum * u.x);
            }
            Point::new(xmax + GAP_MM - left, 0.0)
        });
        let b = &mut *self.b;
        let p0 = b.point(origin, Role::Given.named("0"), N_START_ONE_LINE);
        let track0 = b.line_dir(&p0, u, Role::Auxiliary, N_TRACK)?;
        let across = b.perpendicular(&track0, &p0, Role::Auxiliary, N_ACROSS);
        // Downwards: the chain grows under its start.
        let down = -across.g.dir.dot(&Vector::new(-u.y, u.x)).signum();
        let parallel_at = |b: &mut Board, k: usize| {
            let at = b.lay_off(
                &p0,
                &across,
                down * k as f64 * STAGGER_MM,
                Role::Auxiliary,
                N_STAGGER,
            )?;
            Ok::<_, ConstructionError>(b.parallel(&track0, &at, Role::Auxiliary, N_STAGGER))
        };
        let mut sides: Vec<(H<Point>, H<Point>)> = Vec::with_capacity(lens.len());
        let mut tail = p0;
        for (i, &len) in lens.iter().enumerate() {
            let track = if i == 0 { track0 } else { parallel_at(b, i)? };
            if i > 0 {
                tail = b.foot(&track, &sides[i - 1].1, Role::Construction, N_CARRY);
            }
            let label = Label::indexed("", i as u32 + 1);
            let head = b.lay_off(&tail, &track, len, Role::Force.labelled(label), N_LAY_OFF)?;
            sides.push((tail, head));
        }
        let r_track = parallel_at(b, lens.len())?;
        let first = b.foot(&r_track, &p0, Role::Construction.named("R"), N_ENDS);
        let last = b.foot(
            &r_track,
            &sides[lens.len() - 1].1,
            Role::Construction,
            N_ENDS,
        );
        let r_len = (last.g - first.g).norm();
        if r_len > b.tolerance().length {
            b.segment(&first, &last, Role::Force.named("R"), N_SUM);
        }
        let r = b.measure(
            &first,
            &last,
            &r_track,
            self.kg,
            Label::quiet("R", 0),
            N_SUM,
        );
        let (unit, fmax, r_cf) = (self.dr.unit, self.fmax, self.r_cf);
        let what = "resultant along the common line of action (algebraic sum)";
        let sum = if u.x > 0.0 {
            "ΣP, right positive"
        } else {
            "ΣP, up positive"
        };
        b.check(&r, what, unit, sum, fmax, || r_cf.dot(&u));
        Ok(Polygon {
            pts: Vec::new(),
            sides,
            first,
            last,
            sides_mm: lens.iter().map(|l| l.abs()).sum(),
            axis_x: track0,
            r_len,
            r: u * r.g,
        })
    }
}
