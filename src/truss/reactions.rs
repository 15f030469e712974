//! The support reactions by the moment equations (LH C.2: "ΣM = 0 um den Auflagerpunkt"),
//! the check the books make on the graphic reactions: independent of the closing line and of
//! the sparse solve, and O(loads), so it runs on trusses of any size.
//!
//! - One pin P and one roller R with the reaction direction d: moments about P give the
//!   roller's reaction r·d with r = −Σ (pᵢ − P) × Fᵢ / ((R − P) × d); the pin takes the
//!   rest of the force sum.
//! - Three rollers: moments about the meeting point Q of two reaction lines give the third,
//!   r_k = −Σ (pᵢ − Q) × Fᵢ / ((p_k − Q) × d_k). If those two lines are parallel, the
//!   forces across them give it instead: r_k (d_k · n) = −Σ Fᵢ · n with n normal to them.
//!
//! # Numerics
//! The divisors are the lever arm of a reaction (a length times a unit vector) and the
//! cross product of two reaction directions. Both are zero exactly when the supports make
//! a mechanism, which scene validation refuses (the rank test); a divisor below
//! [`LEVER_REL`] of the truss size is reported as `None` rather than divided by.

use super::{JointLoad, SupportKind, Truss};
use crate::kernel::{cross, Point, Vector};

pub use crate::kernel::tolerance::LEVER_REL;

/// The reaction of every support (in the order of the supports) from the moment and force
/// equations of the whole truss under `loads`; `None` if the supports are not one pin and one
/// roller, or three rollers, or cannot be resolved (a mechanism).
///
/// ```
/// use graphostatik::kernel::{Point, Vector};
/// use graphostatik::truss::{Joint, JointLoad, Member, Support, SupportKind, Truss};
/// use graphostatik::truss::reactions::by_moments;
/// let joint = |n: &str, x: f64, y: f64| Joint { name: n.into(), at: Point::new(x, y) };
/// let t = Truss::new(
///     vec![joint("I", 0.0, 0.0), joint("II", 6.0, 0.0), joint("III", 2.0, 2.0)],
///     vec![],
///     vec![
///         Support::pinned(0, "A"),
///         Support::roller(1, Vector::new(0.0, 1.0), "B"),
///     ],
/// );
/// // 600 kg at a third of the span: B takes a third, A two thirds.
/// let r = by_moments(&t, &[JointLoad { joint: 2, force: Vector::new(0.0, -600.0) }]).unwrap();
/// assert!((r[1].y - 200.0).abs() < 1e-12 && (r[0].y - 400.0).abs() < 1e-12);
/// ```
pub fn by_moments(t: &Truss, loads: &[JointLoad]) -> Option<Vec<Vector>> {
    let at = |j: usize| t.joints[j].at;
    let sum: Vector = loads.iter().map(|l| l.force).sum();
    let moment_about = |q: Point| -> f64 {
        loads
            .iter()
            .map(|l| cross(&(at(l.joint) - q), &l.force))
            .sum()
    };
    let small = LEVER_REL * t.size();
    let pins: Vec<usize> = (0..t.supports.len())
        .filter(|&s| t.supports[s].kind == SupportKind::Pinned)
        .collect();
    let dir = |s: usize| match t.supports[s].kind {
        SupportKind::Roller { dir } => Some(dir),
        SupportKind::Pinned => None,
    };
    let mut out = vec![Vector::zeros(); t.supports.len()];
    match (pins.len(), t.supports.len()) {
        (1, 2) => {
            let (p, r) = (pins[0], 1 - pins[0]);
            let d = dir(r)?;
            let pp = at(t.supports[p].joint);
            let lever = cross(&(at(t.supports[r].joint) - pp), &d);
            if lever.abs() <= small {
                return None;
            }
            out[r] = d * (-moment_about(pp) / lever);
            out[p] = -sum - out[r];
        }
        (0, 3) => {
            for (k, slot) in out.iter_mut().enumerate() {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let (di, dj, dk) = (dir(i)?, dir(j)?, dir(k)?);
                let (pi, pj, pk) = (
                    at(t.supports[i].joint),
                    at(t.supports[j].joint),
                    at(t.supports[k].joint),
                );
                let sine = cross(&di, &dj);
                let r = if sine.abs() <= LEVER_REL {
                    // Parallel lines i and j: the forces across them.
                    let n = Vector::new(-di.y, di.x);
                    let across = dk.dot(&n);
                    if across.abs() <= LEVER_REL {
                        return None;
                    }
                    -sum.dot(&n) / across
                } else {
                    // Q = pi + s·di on line j: (pi + s·di − pj) × dj = 0.
                    let s = cross(&(pj - pi), &dj) / sine;
                    let q = pi + di * s;
                    let lever = cross(&(pk - q), &dk);
                    if lever.abs() <= small {
                        return None;
                    }
                    -moment_about(q) / lever
                };
                *slot = dk * r;
            }
        }
        _ => return None,
    }
    Some(out)
}
