//! The joint-equilibrium equations of a truss (LH B.2-3): at every joint ΣX = 0 and ΣY = 0,
//! 2k equations in the s member forces and the r reaction components.
//!
//! # Determinacy and stability (LH Gl. 2)
//! The books count: a truss of triangles needs s = 2k − 3 members. Counting alone is not
//! enough (a truss can have the right number of members and still be a mechanism where one
//! panel has none), so [`analyse`] also takes the rank of the 2k × (s + r) equilibrium
//! matrix A by its singular values:
//! - rank A < 2k: some load cannot be carried; the truss (with its supports) is a
//!   **mechanism**. A vector u with Aᵀu = 0 is a motion of the joints that no member resists,
//!   and the joint that moves most is named;
//! - rank A = 2k = s + r: **determinate**, one solution for every load;
//! - rank A = 2k < s + r: **over-determinate** by s + r − 2k (LH B.5).
//!
//! # Numerics
//! A singular value counts as zero below [`RANK_REL`] × the largest. A square system that
//! is clearly regular is settled by a sparse LU and inverse iteration at any size, in time
//! and memory of the order of the truss; every other system goes to the dense SVD, which
//! costs O(k³) time and O(k²) memory and is made up to [`DENSE_MAX_JOINTS`] joints. Above,
//! the pebble game ([`super::pebble`]) decides generic rigidity without linear algebra, and
//! a square system the sparse test doubts is a mechanism named by its inverse-iteration
//! motion.

use super::{LoadCase, SupportKind, Truss};
use crate::kernel::tolerance::REL_TIE_EPS_MOTION;
use nalgebra::DMatrix;
use serde::Serialize;
use std::sync::Arc;

pub use crate::kernel::tolerance::RANK_REL;

/// The dense rank test is made up to this many joints (a 2k × 2k matrix of 2 × 1500 rows is
/// 72 MB and some seconds); above it a truss that is not determinate is found by its plan
/// stalling. The solve the plan is checked against is sparse and made at every size.
pub const DENSE_MAX_JOINTS: usize = 1500;

/// What the rank test finds.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Determinacy {
    /// s + r = 2k and full rank.
    Determinate,
    /// Full rank with more unknowns than equations.
    OverDeterminate {
        /// s + r − 2k: the number of redundant members or reactions.
        redundant: usize,
    },
    /// Not decided: the truss is larger than the SVD's limit and its members are not joined
    /// in panels the pebble game can follow in time (members joined at random): its searches
    /// passed their budget of [`PEBBLE_VISITS_PER_PART`] joints per joint, member and
    /// reaction.
    Undecided {
        /// The budget the searches passed (joints visited).
        visits: u64,
    },
    /// Rank below 2k: a joint can move.
    Mechanism {
        /// The joint that moves most in a motion no member resists.
        joint: usize,
        /// 2k − rank: the number of independent motions.
        freedoms: usize,
    },
}

/// The count and the rank.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Analysis {
    /// Joints k.
    pub joints: usize,
    /// Members s.
    pub members: usize,
    /// Reaction unknowns r.
    pub reactions: usize,
    /// The books' count: s − (2k − 3) (negative: too few members, positive: too many), for
    /// trusses with three reaction unknowns.
    pub count_excess: i64,
    /// Rank of the equilibrium matrix, if the dense test was made.
    pub rank: Option<usize>,
    /// The verdict (by the rank where it was made, otherwise by counting).
    pub determinacy: Determinacy,
}

/// The equilibrium matrix A (2k × (s + r)): column m holds member m's unit forces on its two
/// joints (tension positive: it pulls each joint towards the other), then one column per
/// reaction component (a pin's x and y, a roller's direction), in the order of the supports.
pub fn equilibrium_matrix(t: &Truss) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(2 * t.joints.len(), t.members.len() + t.reaction_unknowns());
    for e in equilibrium_triplets(t) {
        a[(e.row, e.col)] += e.val;
    }
    a
}

/// Counts, and tests the rank when the truss has at most [`DENSE_MAX_JOINTS`] joints.
///
/// ```
/// use graphostatik::truss::{matrix::*, *};
/// use graphostatik::kernel::{Point, Vector};
/// // A triangle on a pin and a roller: s = 3 = 2·3 − 3.
/// let j = |n: &str, x, y| Joint { name: n.into(), at: Point::new(x, y) };
/// let m = |n: &str, a, b| Member { name: n.into(), ends: [a, b] };
/// let mut t = Truss::new(
///     vec![j("I", 0.0, 0.0), j("II", 2.0, 0.0), j("III", 1.0, 1.0)],
///     vec![m("1", 0, 1), m("2", 1, 2), m("3", 2, 0)],
///     vec![
///         Support::pinned(0, "A"),
///         Support::roller(1, Vector::new(0.0, 1.0), "B"),
///     ],
/// );
/// assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
/// // Without member 2, joint III can swing about I.
/// t.members.remove(1);
/// assert!(matches!(analyse(&t).determinacy, Determinacy::Mechanism { joint: 2, .. }));
/// ```
pub fn analyse(t: &Truss) -> Analysis {
    if let Some(a) = memo(t, |m| m.analysis.clone()) {
        return a;
    }
    let a = analyse_afresh(t);
    memo(t, |m| m.analysis = Some(a.clone()));
    a
}

fn analyse_afresh(t: &Truss) -> Analysis {
    let k = t.joints.len();
    let s = t.members.len();
    let r = t.reaction_unknowns();
    let mut out = Analysis {
        joints: k,
        members: s,
        reactions: r,
        count_excess: s as i64 - (2 * k as i64 - 3),
        rank: None,
        determinacy: by_count(k, s, r),
    };
    if k == 0 {
        return out;
    }
    if decided_by_counting(t, &mut out) {
        return out;
    }
    // The usual case, a square system that is clearly regular, is settled by the sparse LU
    // at any size; anything doubtful goes to the SVD, which names the joint that can move.
    let sparse = (s + r == 2 * k).then(|| sparse_test(t));
    if sparse == Some(Sparse::Regular) {
        out.rank = Some(2 * k);
        out.determinacy = Determinacy::Determinate;
        return out;
    }
    if k > DENSE_MAX_JOINTS {
        // Too large for the SVD: the pebble game decides generic rigidity, and a square system
        // that the sparse test doubts is a mechanism named by its inverse-iteration motion.
        out.determinacy = without_svd(t, sparse);
        return out;
    }
    let a = equilibrium_matrix(t);
    // An SVD of a matrix with a non-finite entry never converges: such a truss (joints too
    // far apart or too close for f64) keeps the count's answer and no rank.
    if !a.iter().all(|x| x.is_finite()) {
        return out;
    }
    // Padded to at least 2k columns so that the SVD's U spans the whole joint space, and the
    // motions Aᵀu = 0 show as left singular vectors of zero singular values.
    let n = a.ncols().max(2 * k);
    let mut sq = DMatrix::zeros(2 * k, n);
    sq.columns_mut(0, a.ncols()).copy_from(&a);
    let svd = sq.svd(true, false);
    let sv = &svd.singular_values;
    let smax = sv.iter().cloned().fold(0.0, f64::max);
    let rank = sv.iter().filter(|&&x| x > RANK_REL * smax).count();
    out.rank = Some(rank);
    out.determinacy = if rank < 2 * k {
        let u = svd.u.as_ref().expect("U was asked for");
        Determinacy::Mechanism {
            joint: moving_joint(u, sv, k),
            freedoms: 2 * k - rank,
        }
    } else if s + r > 2 * k {
        Determinacy::OverDeterminate {
            redundant: s + r - 2 * k,
        }
    } else {
        Determinacy::Determinate
    };
    out
}

/// Above the SVD's limit, a truss that is a mechanism whatever its geometry is found by
/// counting (the pebble game) before any factorisation: the LU of a truss of random members
/// fills in (a 50,000-joint one took 57 s and 7.7 GB to be called a mechanism), and the game
/// itself is held to a budget. True if that decided, the verdict in `out`.
fn decided_by_counting(t: &Truss, out: &mut Analysis) -> bool {
    if out.joints <= DENSE_MAX_JOINTS {
        return false;
    }
    let budget = PEBBLE_VISITS_PER_PART * (out.joints + out.members + out.reactions + 3) as u64;
    match super::pebble::generic_within(t, budget) {
        None => out.determinacy = Determinacy::Undecided { visits: budget },
        Some(g) if g.freedoms > 0 => {
            out.determinacy = Determinacy::Mechanism {
                joint: g.loose_joint.unwrap_or(0),
                freedoms: g.freedoms,
            }
        }
        Some(_) => return false,
    }
    true
}

/// Why a truss whose rank test was not decided is refused: one text for the scene's error
/// and the construction's.
pub fn undecided_reason(t: &Truss) -> String {
    format!(
        "the rank test of these {} members could not be decided in time: they are not joined \
         in panels (the pebble game visits at most 6 joints per joint, member and reaction of \
         a girder; on this truss it passed {}); draw the truss as panels, or split it",
        t.members.len(),
        PEBBLE_VISITS_PER_PART
    )
}

/// The pebble game's budget: joints its searches may visit per joint, member and reaction.
/// Girders of 200 to 100,000 joints (Warren, Pratt, Howe) take at most 6; members joined at
/// random take hundreds to thousands, and the game's time grows as the square of the truss:
/// the budget holds a 100,000-joint truss to about a second.
pub const PEBBLE_VISITS_PER_PART: u64 = 100;

/// How far above [`RANK_REL`] the estimated smallest singular value must lie for the sparse
/// test to call the matrix regular without the SVD: the estimate comes from a few steps of
/// inverse iteration, and only a clear answer is taken from it.
const SPARSE_RANK_MARGIN: f64 = 1e3;

/// Most inverse iteration steps of the sparse test.
const SPARSE_RANK_STEPS: usize = 8;

/// Fewest inverse iteration steps before the sparse test may stop early.
const SPARSE_RANK_MIN_STEPS: usize = 3;

/// The sparse test stops once its estimate of σ_min, clear of the threshold, falls by less
/// than this fraction in a step: it has settled on σ_min (the estimates fall monotonically
/// towards it, by the square of σ_min/σ₂ a step), and more steps would not change the
/// verdict. A Warren or Pratt girder of 1,000 to 100,000 joints settles in 3 to 4 steps of 8.
const SPARSE_RANK_SETTLED: f64 = 1e-3;

/// What the sparse test finds of a square equilibrium matrix.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Sparse {
    /// Regular beyond doubt.
    Regular,
    /// Singular or doubtful; the joint that moves most in the motion inverse iteration found
    /// (none if the LU itself failed).
    Doubtful(Option<usize>),
}

/// Whether the square equilibrium matrix is regular beyond doubt: a sparse LU, σ_max bounded
/// from above by √(‖A‖₁‖A‖∞), and σ_min estimated by inverse iteration on AAᵀ (each step a
/// pair of sparse solves). The estimate 1/‖A⁻¹u‖ never lies below σ_min and falls to it within
/// a few steps where σ_min is far below the next singular value, which is where a truss is a
/// mechanism; so a matrix is called regular only if the estimate stays
/// [`SPARSE_RANK_MARGIN`] above [`RANK_REL`] × σ_max at every step, up to
/// [`SPARSE_RANK_STEPS`] or until it has settled ([`SPARSE_RANK_SETTLED`]). Where it does
/// not, u is (nearly) the motion Aᵀu ≈ 0 no member resists, and the joint it moves most is
/// named. O(fill) time and memory.
fn sparse_test(t: &Truss) -> Sparse {
    let n = 2 * t.joints.len();
    let triplets = equilibrium_triplets(t);
    let floor = sparse_floor(n, &triplets);
    let Some(lu) = factorised(t, || triplets) else {
        return Sparse::Doubtful(None);
    };
    match inverse_iteration(&lu, n, floor, true) {
        None => Sparse::Doubtful(None),
        Some((true, _, _)) => Sparse::Regular,
        Some((false, motion, _)) => Sparse::Doubtful(most_moved(&motion, t.joints.len())),
    }
}

/// The floor the sparse test's estimate of σ_min must stay above: [`SPARSE_RANK_MARGIN`] ×
/// [`RANK_REL`] × σ_max, σ_max bounded from above by √(‖A‖₁‖A‖∞) of the n × n matrix given
/// by its `triplets`.
fn sparse_floor(n: usize, triplets: &[Triplet]) -> f64 {
    let (mut col1, mut row1) = (vec![0.0f64; n], vec![0.0f64; n]);
    for e in triplets {
        col1[e.col] += e.val.abs();
        row1[e.row] += e.val.abs();
    }
    let norm1 = col1.iter().cloned().fold(0.0, f64::max);
    let norm_inf = row1.iter().cloned().fold(0.0, f64::max);
    SPARSE_RANK_MARGIN * RANK_REL * (norm1 * norm_inf).sqrt()
}

/// Inverse iteration on AAᵀ with A's LU: whether every estimate 1/‖A⁻¹u‖ of σ_min stays
/// above `floor`, the last u (the motion where it does not), and the steps taken. With
/// `settle`, a regular matrix's iteration stops where the estimate has settled
/// ([`SPARSE_RANK_SETTLED`]); `None` where a solve is not finite.
fn inverse_iteration(
    lu: &Lu,
    n: usize,
    floor: f64,
    settle: bool,
) -> Option<(bool, Vec<f64>, usize)> {
    use faer::prelude::Solve;
    // A start with every component non-zero and no symmetry of the girder's numbering.
    let mut u = faer::Col::<f64>::from_fn(n, |i| 1.0 + ((i * 7919) % 613) as f64 / 613.0);
    let mut regular = true;
    let mut last = f64::INFINITY;
    let mut steps = 0;
    while steps < SPARSE_RANK_STEPS {
        let un = u.norm_l2();
        if !(un.is_finite() && un > 0.0) {
            return None;
        }
        u /= un;
        let w = lu.solve(&u);
        let wn = w.norm_l2();
        if !wn.is_finite() {
            return None;
        }
        let estimate = 1.0 / wn;
        regular &= estimate > floor;
        steps += 1;
        if settle
            && regular
            && steps >= SPARSE_RANK_MIN_STEPS
            && estimate > last * (1.0 - SPARSE_RANK_SETTLED)
        {
            break;
        }
        last = estimate;
        u = lu.solve_transpose(&w);
    }
    Some((regular, u.iter().copied().collect(), steps))
}

/// The joint with the largest displacement in a motion (x and y interleaved); ties go to the
/// first joint. `None` if the motion is not finite or zero.
fn most_moved(motion: &[f64], k: usize) -> Option<usize> {
    let mut best = (None, 0.0);
    for j in 0..k {
        let m = motion[2 * j].hypot(motion[2 * j + 1]);
        if !m.is_finite() {
            return None;
        }
        if m > best.1 * (1.0 + REL_TIE_EPS_MOTION) {
            best = (Some(j), m);
        }
    }
    best.0
}

/// The verdict without the SVD, once the pebble game found the truss generically rigid
/// ([`decided_by_counting`]): a square system the sparse test doubts is a mechanism all the
/// same (joints in line, parallel bars), named by its motion.
fn without_svd(t: &Truss, sparse: Option<Sparse>) -> Determinacy {
    let (k, s, r) = (t.joints.len(), t.members.len(), t.reaction_unknowns());
    match sparse {
        Some(Sparse::Doubtful(j)) => Determinacy::Mechanism {
            joint: j.unwrap_or(0),
            freedoms: 1,
        },
        _ if s + r > 2 * k => Determinacy::OverDeterminate {
            redundant: s + r - 2 * k,
        },
        _ => Determinacy::Determinate,
    }
}

/// Determinacy by the count alone (LH Gl. 2: s + r against 2k); a mechanism by count names
/// no joint (the first).
fn by_count(k: usize, s: usize, r: usize) -> Determinacy {
    if s + r == 2 * k {
        Determinacy::Determinate
    } else if s + r > 2 * k {
        Determinacy::OverDeterminate {
            redundant: s + r - 2 * k,
        }
    } else {
        Determinacy::Mechanism {
            joint: 0,
            freedoms: 2 * k - s - r,
        }
    }
}

/// The joint that moves most in the free motion of the smallest singular value (ties go to
/// the first joint, so that the name does not depend on rounding).
fn moving_joint(u: &DMatrix<f64>, sv: &nalgebra::DVector<f64>, k: usize) -> usize {
    let (imin, _) =
        sv.iter().enumerate().fold(
            (0, f64::INFINITY),
            |(bi, bv), (i, &v)| {
                if v < bv {
                    (i, v)
                } else {
                    (bi, bv)
                }
            },
        );
    let col: Vec<f64> = u.column(imin).iter().copied().collect();
    most_moved(&col, k).unwrap_or(0)
}

/// Member forces and reaction components of a determinate truss under one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Solution {
    /// Member forces (kg), tension +, in the order of the members.
    pub members: Vec<f64>,
    /// Reaction components (kg) in the order of [`equilibrium_matrix`]'s columns.
    pub reactions: Vec<f64>,
}

impl Solution {
    /// The largest force of the solution (kg), member or reaction: the scale its rounding
    /// error is relative to (a sparse LU's backward error is a multiple of ε times the largest
    /// unknown), so the scale a value checked against the solve is judged at.
    pub fn scale(&self) -> f64 {
        self.members
            .iter()
            .chain(&self.reactions)
            .fold(0.0, |a: f64, f| a.max(f.abs()))
    }
}

/// Solves A f = −p by a sparse LU decomposition (faer): the independent solve every Cremona
/// plan is checked against, at every size. `None` if A is not square, is singular, or gives
/// a force that is not finite.
pub fn solve(t: &Truss, case: &LoadCase) -> Option<Solution> {
    solve_all(t, std::slice::from_ref(case)).pop().flatten()
}

/// [`solve`] for every load case of one truss: A is factorised once (a truss's equations
/// have at most five entries per column, and the fill of a girder numbered along its span
/// stays small), and each case costs one pair of sparse triangular solves.
pub fn solve_all(t: &Truss, cases: &[LoadCase]) -> Vec<Option<Solution>> {
    let none = || vec![None; cases.len()];
    let k = t.joints.len();
    let s = t.members.len();
    let n = 2 * k;
    if s + t.reaction_unknowns() != n || n == 0 {
        return none();
    }
    let Some(lu) = factorised(t, || equilibrium_triplets(t)) else {
        return none();
    };
    cases
        .iter()
        .map(|case| {
            let mut p = faer::Col::<f64>::zeros(n);
            for l in &case.loads {
                p[2 * l.joint] -= l.force.x;
                p[2 * l.joint + 1] -= l.force.y;
            }
            let f = faer::prelude::Solve::solve(&*lu, &p);
            let f: Vec<f64> = f.iter().copied().collect();
            if f.iter().any(|x| !x.is_finite()) {
                return None;
            }
            Some(Solution {
                members: f[..s].to_vec(),
                reactions: f[s..].to_vec(),
            })
        })
        .collect()
}

type Lu = faer::sparse::linalg::solvers::Lu<usize, f64>;

/// What is known of one truss's matrix, kept in the truss's analysis cache. The truss is
/// recognised by its geometry bit for bit (joint coordinates, member ends, supports), never
/// by a hash.
#[derive(Default)]
struct Memo {
    key: Vec<u64>,
    /// The sparse LU of the square system: not yet made, or made (`None` if it failed).
    lu: Option<Option<Arc<Lu>>>,
    analysis: Option<Analysis>,
}

/// The geometry a truss's equilibrium matrix is made of, bit for bit.
fn memo_key(t: &Truss) -> Vec<u64> {
    let mut key =
        Vec::with_capacity(3 + 2 * t.joints.len() + t.members.len() + 3 * t.supports.len());
    key.extend([t.joints.len(), t.members.len(), t.supports.len()].map(|n| n as u64));
    key.extend(
        t.joints
            .iter()
            .flat_map(|j| [j.at.x.to_bits(), j.at.y.to_bits()]),
    );
    key.extend(
        t.members
            .iter()
            .map(|m| (m.ends[0] as u64) << 32 | m.ends[1] as u64),
    );
    for sup in &t.supports {
        key.extend(match sup.kind {
            SupportKind::Pinned => [sup.joint as u64, 0, 0],
            SupportKind::Roller { dir } => {
                [sup.joint as u64 | 1 << 63, dir.x.to_bits(), dir.y.to_bits()]
            }
        });
    }
    key
}

/// `f` on what is known of `t`, forgetting what was known if `t` has changed since.
fn memo<R>(t: &Truss, f: impl FnOnce(&mut Memo) -> R) -> R {
    let key = memo_key(t);
    t.memo.with(|m: &mut Memo| {
        if m.key != key {
            *m = Memo {
                key,
                ..Memo::default()
            };
        }
        f(m)
    })
}

/// The sparse LU of the square equilibrium matrix, made once per truss ([`Memo`]) from
/// its entries (asked for only where it is made).
fn factorised(t: &Truss, triplets: impl FnOnce() -> Vec<Triplet>) -> Option<Arc<Lu>> {
    if let Some(lu) = memo(t, |m| m.lu.clone()) {
        return lu;
    }
    let lu = sparse_lu(t, &triplets()).map(Arc::new);
    memo(t, |m| m.lu = Some(lu.clone()));
    lu
}

/// The sparse LU of the square equilibrium matrix given by its `triplets`; `None` if an
/// entry is not finite or the factorisation fails.
fn sparse_lu(
    t: &Truss,
    triplets: &[Triplet],
) -> Option<faer::sparse::linalg::solvers::Lu<usize, f64>> {
    let n = 2 * t.joints.len();
    if !triplets.iter().all(|e| e.val.is_finite()) {
        return None;
    }
    let a = match in_column_order(n, triplets) {
        Some(a) => a,
        None => faer::sparse::SparseColMat::try_new_from_triplets(n, n, triplets).ok()?,
    };
    a.sp_lu().ok()
}

/// The n × n matrix of `triplets` given column by column, as [`equilibrium_triplets`] gives
/// them, without faer's sort of every entry: each column's few entries sorted by row, the
/// same matrix (values as given, zeros kept). `None` where they are not in column order,
/// repeat a place or lie outside.
fn in_column_order(
    n: usize,
    triplets: &[Triplet],
) -> Option<faer::sparse::SparseColMat<usize, f64>> {
    let mut col_ptr = Vec::with_capacity(n + 1);
    let (mut rows, mut vals) = (
        Vec::with_capacity(triplets.len()),
        Vec::with_capacity(triplets.len()),
    );
    col_ptr.push(0);
    let mut k = 0;
    for c in 0..n {
        let start = rows.len();
        while let Some(e) = triplets.get(k).filter(|e| e.col == c) {
            if e.row >= n {
                return None;
            }
            // Insertion into the column's sorted rows (at most five).
            let at = start + rows[start..].partition_point(|&r| r < e.row);
            if rows.get(at) == Some(&e.row) {
                return None;
            }
            rows.insert(at, e.row);
            vals.insert(at, e.val);
            k += 1;
        }
        col_ptr.push(rows.len());
    }
    if k != triplets.len() {
        return None;
    }
    let symbolic = faer::sparse::SymbolicSparseColMat::new_checked(n, n, col_ptr, None, rows);
    Some(faer::sparse::SparseColMat::new(symbolic, vals))
}

type Triplet = faer::sparse::Triplet<usize, usize, f64>;

/// The non-zero entries of [`equilibrium_matrix`] (row, column, value), without forming it.
fn equilibrium_triplets(t: &Truss) -> Vec<Triplet> {
    let mut e = Vec::with_capacity(4 * t.members.len() + 2 * t.supports.len());
    for_each_entry(t, |row, col, val| e.push(Triplet::new(row, col, val)));
    e
}

/// Each non-zero entry of [`equilibrium_matrix`] (row, column, value), member by member
/// and then support by support: the one order every use of the entries sums in.
fn for_each_entry(t: &Truss, mut f: impl FnMut(usize, usize, f64)) {
    let s = t.members.len();
    for (m, mem) in t.members.iter().enumerate() {
        let (d, _) = t.member_dir(m);
        let [i, j] = mem.ends;
        f(2 * i, m, d.x);
        f(2 * i + 1, m, d.y);
        f(2 * j, m, -d.x);
        f(2 * j + 1, m, -d.y);
    }
    let mut c = s;
    for sup in &t.supports {
        let j = sup.joint;
        match sup.kind {
            SupportKind::Pinned => {
                f(2 * j, c, 1.0);
                f(2 * j + 1, c + 1, 1.0);
                c += 2;
            }
            SupportKind::Roller { dir } => {
                f(2 * j, c, dir.x);
                f(2 * j + 1, c, dir.y);
                c += 1;
            }
        }
    }
}

/// The largest out-of-balance force (kg) at any joint for the given member forces and
/// reaction components: O(s + k), usable at any size.
pub fn max_residual(t: &Truss, case: &LoadCase, members: &[f64], reactions: &[f64]) -> f64 {
    worst_joint(t, case, members, reactions).map_or(0.0, |(_, r)| r)
}

/// The joint with the largest out-of-balance force and that force (kg), for the given member
/// forces and reaction components (ties go to the first joint); `None` for a truss without
/// joints. O(s + k).
pub fn worst_joint(
    t: &Truss,
    case: &LoadCase,
    members: &[f64],
    reactions: &[f64],
) -> Option<(usize, f64)> {
    let r = joint_residuals(t, case, members, reactions);
    (0..t.joints.len())
        .map(|j| (j, r[2 * j].hypot(r[2 * j + 1])))
        .fold(None, |best, (j, v)| match best {
            // A NaN is the worst of all: it is never hidden behind a finite residual.
            Some((_, bv)) if bv.is_nan() || v <= bv => best,
            _ => Some((j, v)),
        })
}

/// The out-of-balance force at every joint: x and y interleaved.
fn joint_residuals(t: &Truss, case: &LoadCase, members: &[f64], reactions: &[f64]) -> Vec<f64> {
    let mut r = vec![0.0; 2 * t.joints.len()];
    for l in &case.loads {
        r[2 * l.joint] += l.force.x;
        r[2 * l.joint + 1] += l.force.y;
    }
    let s = members.len();
    for_each_entry(t, |row, col, val| {
        let x = if col < s {
            members[col]
        } else {
            reactions[col - s]
        };
        r[row] += x * val;
    });
    r
}

#[cfg(test)]
mod memo_tests {
    use super::*;
    use crate::kernel::Vector;
    use crate::truss::generate::{parallel_chord, Web};
    use crate::truss::JointLoad;

    fn case(n: usize) -> LoadCase {
        LoadCase {
            name: "P".into(),
            loads: (1..n)
                .map(|i| JointLoad {
                    joint: i,
                    force: Vector::new(0.0, -1000.0),
                })
                .collect(),
            force_scale: None,
            drawn: true,
            book_name: None,
        }
    }

    #[test]
    fn what_is_known_of_one_truss_is_never_taken_for_another() {
        let mut t = parallel_chord(Web::Warren, 6, 2.0, 2.0);
        let c = case(6);
        assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
        let before = solve(&t, &c).unwrap();
        // The same truss again: the same answers (from the memo).
        assert_eq!(solve(&t, &c).unwrap(), before);
        // A joint moved by one ulp is another truss.
        let j = t.joints.len() - 1;
        t.joints[j].at.y = f64::from_bits(t.joints[j].at.y.to_bits() + 1);
        let moved = solve(&t, &c).unwrap();
        assert_ne!(moved, before);
        t.forget_matrix();
        assert_eq!(solve(&t, &c).unwrap(), moved);
        // A member taken out: a mechanism, not the determinate truss known before.
        t.members.remove(2);
        assert!(matches!(
            analyse(&t).determinacy,
            Determinacy::Mechanism { .. }
        ));
        assert_eq!(solve(&t, &c), None);
    }

    /// The sparse test's floor and the LU of `t`'s square equilibrium matrix.
    fn floor_and_lu(t: &Truss) -> (f64, usize, Arc<Lu>) {
        let triplets = equilibrium_triplets(t);
        let n = 2 * t.joints.len();
        let floor = sparse_floor(n, &triplets);
        let lu = factorised(t, || triplets).expect("a square matrix the LU takes");
        (floor, n, lu)
    }

    #[test]
    fn the_sparse_test_stops_early_only_where_all_its_steps_agree() {
        let mut trusses = Vec::new();
        for (web, n) in [(Web::Warren, 10), (Web::Pratt, 500), (Web::Warren, 5000)] {
            trusses.push(parallel_chord(web, n, 2.0, 2.0));
        }
        // The middle top joint lowered towards the bottom chord's line: a mechanism at 0.
        for h in [1e-3, 1e-6, 1e-9, 1e-12, 1e-14, 0.0] {
            let mut g = parallel_chord(Web::Warren, 20, 1.0, 1.0);
            let top = g.joints.len() - 10;
            g.joints[top].at.y = h;
            trusses.push(g);
        }
        let mut early = 0;
        for t in &trusses {
            let (floor, n, lu) = floor_and_lu(t);
            let all = inverse_iteration(&lu, n, floor, false);
            let settled = inverse_iteration(&lu, n, floor, true);
            let (Some(all), Some(settled)) = (all, settled) else {
                assert!(!matches!(analyse(t).determinacy, Determinacy::Determinate));
                continue;
            };
            assert_eq!(all.0, settled.0, "the same verdict");
            assert_eq!(all.2, SPARSE_RANK_STEPS);
            if settled.0 {
                assert!(settled.2 <= 4, "settled in {} steps", settled.2);
                early += 1;
            } else {
                assert_eq!(settled.1, all.1, "the same motion named");
            }
        }
        assert!(early >= 5, "{early} regular trusses stopped early");
    }

    #[test]
    fn the_matrix_built_column_by_column_is_faers_from_triplets() {
        let mut trusses = vec![
            parallel_chord(Web::Warren, 7, 2.0, 2.0),
            parallel_chord(Web::Pratt, 12, 1.5, 3.0),
        ];
        // Members numbered from their second joint, a roller at a slant.
        let mut t = parallel_chord(Web::Howe, 5, 2.0, 1.0);
        t.members.iter_mut().for_each(|m| m.ends.reverse());
        t.supports[1].kind = SupportKind::Roller {
            dir: Vector::new(0.6, 0.8),
        };
        trusses.push(t);
        for t in &trusses {
            let n = 2 * t.joints.len();
            let e = equilibrium_triplets(t);
            let ours = in_column_order(n, &e).expect("in column order");
            let faers = faer::sparse::SparseColMat::try_new_from_triplets(n, n, &e).unwrap();
            let (a, b) = (ours.symbolic(), faers.symbolic());
            assert_eq!(a.col_ptr(), b.col_ptr());
            assert_eq!(a.row_idx(), b.row_idx());
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(ours.val()), bits(faers.val()));
        }
        // Out of column order, or twice at one place: left to faer.
        let e = [Triplet::new(0, 1, 1.0), Triplet::new(1, 0, 1.0)];
        assert!(in_column_order(2, &e).is_none());
        let e = [Triplet::new(0, 0, 1.0), Triplet::new(0, 0, 1.0)];
        assert!(in_column_order(2, &e).is_none());
    }

    #[test]
    fn what_is_known_travels_with_the_truss_and_its_clones() {
        let t = parallel_chord(Web::Warren, 6, 2.0, 2.0);
        let known = |t: &Truss| {
            t.memo
                .with(|m: &mut Memo| (m.analysis.is_some(), m.lu.is_some()))
        };
        assert_eq!(known(&t), (false, false));
        analyse(&t);
        solve(&t, &case(6)).unwrap();
        assert_eq!(known(&t), (true, true));
        let c = t.clone();
        assert_eq!(known(&c), (true, true), "a clone shares what is known");
        // Another truss knows nothing of it: no state outside the value.
        assert_eq!(
            known(&parallel_chord(Web::Warren, 6, 2.0, 2.0)),
            (false, false)
        );
        t.forget_matrix();
        assert_eq!(known(&c), (false, false));
    }

    #[test]
    fn a_scene_read_hands_its_analysis_to_the_construction() {
        use crate::scene::{Procedure, TrussScene};
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenes/lh_aufgabe4_shed_roof.json"
        ))
        .unwrap();
        let (_, p) = TrussScene::read(&text, "roof.json").unwrap();
        let kept = p.truss.memo.with(|m: &mut Memo| m.analysis.is_some());
        assert!(kept, "validation's rank test kept");
    }
}
