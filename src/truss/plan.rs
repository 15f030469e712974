//! The plan context shared by Bow's notation, the joint polygons and Ritter's sections: the
//! drawing's scales, the external forces, the result of a case and the check of a member.

use super::labels::write_member;
use super::matrix::{self, Solution};
use super::{JointLoad, LoadCase, MemberForce, SupportKind, Truss};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, H};
use serde::Serialize;

pub use crate::kernel::tolerance::ZERO_FORCE_REL;

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
    pub force: Vector,
    /// Its length in the force plan (mm), |force| over the force scale.
    pub plan_mm: f64,
}

impl ReactionForce {
    /// The magnitude (kg).
    pub fn magnitude(&self) -> f64 {
        self.force.x.hypot(self.force.y)
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
    /// The same for the sparse solve, where it was made.
    pub matrix_residual: Option<f64>,
}

/// Everything the truss drawing needs per case, computed without a board.
pub(crate) struct External {
    /// (joint, force) of every external force, loads first, then reactions.
    pub(crate) forces: Vec<(usize, Vector)>,
    /// Reaction vectors per support.
    pub(crate) reactions: Vec<Vector>,
}

pub(super) fn ext_max(ext: &External) -> f64 {
    ext.forces.iter().map(|(_, f)| f.norm()).fold(0.0, f64::max)
}

/// The result of a plan, either way it was drawn: the forces found, the sparse solve beside
/// them, and the balance of both at every joint. The plan's balance is recorded as a check of
/// its own (see [`check_balance`]).
pub(crate) fn plan_result(
    b: &mut Board,
    ctx: &PlanContext,
    (forces, ids): (&[Option<f64>], &[crate::protocol::ObjId]),
    plan_mm: &[f64],
) -> CaseResult {
    let PlanContext {
        t,
        case,
        ext,
        sol,
        dr,
        ..
    } = *ctx;
    let members: Vec<f64> = forces.iter().map(|f| f.unwrap_or(0.0)).collect();
    let matrix: Vec<Option<f64>> = (0..members.len())
        .map(|m| sol.map(|s| s.members[m]))
        .collect();
    // The plan's balance, reckoned once: its largest residual is the result's, its joint
    // the check's.
    let rc = reaction_components(t, &ext.reactions);
    let worst = matrix::worst_joint(t, case, &members, &rc);
    let plan_residual = worst.map_or(0.0, |(_, r)| r);
    let forces = CaseForces {
        members: &members,
        plan_mm,
        matrix: &matrix,
        reactions: &ext.reactions,
    };
    let mut result = case_result_with(t, case, forces, dr, plan_residual);
    result.matrix_residual = sol.map(|s| matrix::max_residual(t, case, &s.members, &s.reactions));
    if let Some(worst) = worst {
        check_balance(b, ctx, &members, ids, worst);
    }
    result
}

/// The balance of every joint under the forces the plan found and the reactions: a check at
/// every size, that names the joint that balances worst. It is
/// judged against the largest force of the case (a load, a reaction or a member force: the
/// chord of a long girder carries many times its largest load, and its rounding with it).
fn check_balance(
    b: &mut Board,
    ctx: &PlanContext,
    members: &[f64],
    ids: &[crate::protocol::ObjId],
    (joint, residual): (usize, f64),
) {
    if !b.is_recording() {
        return;
    }
    let t = ctx.t;
    let largest = members.iter().fold(0.0, |a: f64, f| a.max(f.abs()));
    let reference = check_reference(ctx.maxload, ctx.ext).max(largest);
    // Reckoned from the forces of the joint's members, whose bounds it carries.
    let at_joint: Vec<_> = (0..t.members.len())
        .filter(|&m| t.members[m].ends.contains(&joint))
        .map(|m| ids[m])
        .filter(|id| *id != crate::protocol::ObjId::NONE)
        .collect();
    let v = b.tally(
        residual,
        "kg",
        crate::protocol::Label::NONE,
        &at_joint,
        super::notes::N_BALANCE,
    );
    let name = &t.joints[joint].name;
    b.check(
        &v,
        format!("joint balance |ΣF|, worst at joint {name}"),
        "kg",
        "ΣX = ΣY = 0 at every joint (LH B.3)",
        reference,
        || 0.0,
    );
}

/// Reaction components in the order of [`matrix::equilibrium_matrix`]'s columns.
fn reaction_components(t: &Truss, reactions: &[Vector]) -> Vec<f64> {
    let mut rc = Vec::new();
    for (sup, r) in t.supports.iter().zip(reactions) {
        match sup.kind {
            SupportKind::Pinned => rc.extend([r.x, r.y]),
            SupportKind::Roller { dir } => rc.push(r.dot(&dir)),
        }
    }
    rc
}

/// The scale of the checks: the largest load or reaction of the case (kg).
pub(crate) fn check_reference(maxload: f64, ext: &External) -> f64 {
    maxload.max(ext_max(ext))
}

/// The scale a member force checked against the sparse solve is judged at: the larger of the
/// case's scale and the solve's own (its largest force). Computed once per case.
pub(crate) fn member_check_reference(ctx: &PlanContext) -> f64 {
    let case = check_reference(ctx.maxload, ctx.ext);
    ctx.sol.map_or(case, |s| case.max(s.scale()))
}

/// Checks a member force read off a plan against the sparse solve, if it was made, at
/// `reference` ([`member_check_reference`]).
pub(crate) fn check_member(
    b: &mut Board,
    t: &Truss,
    value: &H<f64>,
    m: usize,
    sol: Option<&Solution>,
    reference: f64,
) {
    if let Some(sol) = sol {
        b.checking(write_member(t, m), |b| {
            b.check(
                value,
                "member force (tension +)",
                "kg",
                "joint equilibrium, sparse LU (faer)",
                reference,
                || sol.members[m],
            )
        });
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
    let rc = reaction_components(t, reactions);
    let plan_residual = matrix::max_residual(t, case, forces, &rc);
    let forces = CaseForces {
        members: forces,
        plan_mm,
        matrix,
        reactions,
    };
    case_result_with(t, case, forces, dr, plan_residual)
}

/// What a case's result is made of: member forces (kg) and their lengths in the plan (mm),
/// the sparse solve's forces where it was made, and the reaction of every support.
struct CaseForces<'a> {
    members: &'a [f64],
    plan_mm: &'a [f64],
    matrix: &'a [Option<f64>],
    reactions: &'a [Vector],
}

/// [`case_result`] with the largest out-of-balance force already reckoned.
fn case_result_with(
    t: &Truss,
    case: &LoadCase,
    f: CaseForces,
    dr: &TrussDrawing,
    plan_residual: f64,
) -> CaseResult {
    CaseResult {
        case: case.name.clone(),
        reactions: t
            .supports
            .iter()
            .zip(f.reactions)
            .map(|(sup, r)| ReactionForce {
                support: sup.name.clone(),
                joint: t.joints[sup.joint].name.as_str().to_owned(),
                force: *r,
                plan_mm: r.norm() / dr.force_scale,
            })
            .collect(),
        members: t
            .members
            .iter()
            .enumerate()
            .map(|(m, mem)| MemberForce {
                member: mem.name.clone(),
                plan_mm: f.plan_mm[m],
                force: f.members[m],
                matrix: f.matrix[m],
            })
            .collect(),
        plan_residual,
        matrix_residual: None,
    }
}

/// The spaces of Bow's notation.
pub(super) struct Spaces<'a> {
    /// The space left of every half-edge.
    pub(super) of_half: &'a [usize],
    /// The face of every inner space (the outer face for outer spaces).
    pub(super) face_of: &'a [usize],
    /// Spaces below this index are outside the truss.
    pub(super) n_ext: usize,
}

impl External {
    /// The external forces at their joints: the loads, then the reactions (those not zero
    /// to rounding against the largest force).
    pub(super) fn of(
        t: &Truss,
        loads: &[JointLoad],
        reactions: Vec<Vector>,
        maxload: f64,
    ) -> External {
        let mut forces: Vec<(usize, Vector)> = loads.iter().map(|l| (l.joint, l.force)).collect();
        let tiny = crate::kernel::tolerance::REL_ZERO_REACTION
            * reactions.iter().map(|r| r.norm()).fold(maxload, f64::max);
        for (si, r) in reactions.iter().enumerate() {
            if r.norm() > tiny {
                forces.push((t.supports[si].joint, *r));
            }
        }
        External { forces, reactions }
    }
}

/// What every way of drawing the plan of one case works from: the truss, the case and its
/// external forces, the sparse solve to check against, the scales, where the plan starts on
/// the sheet, the members' lines in the truss drawing, and the largest load (the reference
/// of the checks).
#[derive(Clone, Copy)]
pub(super) struct PlanContext<'a> {
    pub(super) t: &'a Truss,
    pub(super) case: &'a LoadCase,
    pub(super) ext: &'a External,
    pub(super) sol: Option<&'a Solution>,
    pub(super) dr: &'a TrussDrawing,
    pub(super) at: Point,
    pub(super) mline: &'a [H<Line>],
    pub(super) maxload: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn external_forces_leave_out_an_unloaded_support() {
        let t = Truss::triangle(2.0, 1.0);
        let loads = [JointLoad {
            joint: 2,
            force: Vector::new(-100.0, 0.0),
        }];
        // A horizontal load at the apex: the roller takes 50 kg up, the pin 100 kg across and
        // 50 kg down; a reaction of 1e-14 kg is rounding, not a force.
        let reactions = vec![Vector::new(100.0, -50.0), Vector::new(1e-14, 50.0)];
        let e = External::of(&t, &loads, reactions.clone(), 100.0);
        assert_eq!(e.forces.len(), 3);
        let zero = vec![Vector::new(100.0, 0.0), Vector::new(0.0, 1e-13)];
        let e = External::of(&t, &loads, zero, 100.0);
        assert_eq!(e.forces.len(), 2, "the roller's 1e-13 kg is no force");
        assert_eq!(e.reactions.len(), 2);
    }
}
