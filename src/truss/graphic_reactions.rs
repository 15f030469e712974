//! The support reactions by the funicular polygon (LH C.2): a pin and a roller by the closing
//! line, three rollers by Culmann's line; each read off the force plan and checked by the
//! moment equations and the sparse solve.

use super::labels::support_label;
use super::layout::{column, grow, part_of, POLYGON, TRUSS};
use super::matrix::Solution;
use super::notes::*;
use super::{JointLoad, SupportKind, Truss};
use crate::kernel::tolerance::{REL_LAYOUT_EPS, REL_SCORE_EPS};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Role, Scale, H};
use crate::statics::funicular::polygon::{self, StringStyle};

/// The supports, as the reaction construction takes them.
#[derive(Debug, Clone, Copy)]
pub(super) enum Supports {
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
pub(super) fn support_index(t: &Truss, joint: usize) -> usize {
    t.supports
        .iter()
        .position(|s| s.joint == joint)
        .expect("a support at that joint")
}

/// The reaction supports: one pin and one roller, or three rollers.
pub(super) fn supports(t: &Truss) -> Result<Supports, ConstructionError> {
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

/// The pole for the reaction construction: off the left of the loads' resultant by about the
/// polygon's size, picked among a few candidates for the best-conditioned cuts of strings with
/// lines of action and of the last string with B's line.
pub(super) fn choose_pole(corners: &[Point], loads: &[Vector], rdir: Vector) -> Point {
    let (first, last) = (corners[0], corners[corners.len() - 1]);
    let mid = Point::from((first.coords + last.coords) * 0.5);
    let span = corners
        .iter()
        .map(|c| (c - mid).norm())
        .fold(0.0, f64::max)
        .max(10.0);
    let chord = last - first;
    // Off to the side of the closing chord; if the polygon closes, of its longest side.
    let along = if chord.norm() > REL_LAYOUT_EPS * span {
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
        if d > REL_LAYOUT_EPS * span * b.norm() {
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
        if s > best.1 * (1.0 + REL_SCORE_EPS) {
            best = (o, s);
        }
    }
    best.0
}

/// A reaction in the force plan: its support (index), tail and head.
pub(super) type PlanReaction = (usize, H<Point>, H<Point>);

/// Three rollers (Culmann): the resultant R of the loads and the lone roller's reaction
/// meet in P, the other two reaction lines in Q; R and the lone reaction together balance
/// the other two, so their sum acts along PQ. In the force plan, the parallel to the lone
/// roller through the end of the loads and the parallel to PQ through their start give the
/// lone reaction; the other two follow by resolving along their lines. Of the three rollers
/// the lone one is the one with the best-conditioned cuts. Returns (support index, tail,
/// head) of each reaction in the force plan.
pub(super) fn culmann(
    b: &mut Board,
    inp: &ReactionInput,
    first: &H<Line>,
    last_string: &H<Line>,
    fh: &[H<Point>],
    r: &[(usize, Vector); 3],
) -> Result<Vec<PlanReaction>, ConstructionError> {
    let ReactionInput { t, rlines, .. } = *inp;
    let n = fh.len() - 1;
    let rv = fh[n].g - fh[0].g;
    let span = fh
        .iter()
        .map(|f| (f.g - fh[0].g).norm())
        .fold(0.0, f64::max);
    if rv.norm() <= REL_LAYOUT_EPS * span.max(f64::MIN_POSITIVE) {
        return Err(ConstructionError::unsupported("loads", 
            "the loads form a couple (their force polygon closes): three rollers need a resultant to cut",
        ));
    }
    let on_r = b.meet_point(first, last_string, Label::quiet("R", 0), N_RESULTANT)?;
    let rl = b.line_dir(&on_r, rv, Role::Construction.named("R"), N_RESULTANT)?;
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
    let c = b.line_through(&p, &q, Role::Construction.named("c"), N_CULMANN)?;
    column(b, POLYGON);
    let (f0, last) = (fh[0], fh[n]);
    let along_k = b.parallel(&lk, &last, Role::Auxiliary, N_CULMANN_PLAN);
    let along_c = b.parallel(&c, &f0, Role::Auxiliary, N_CULMANN_PLAN);
    let x = b.meet_point(&along_k, &along_c, Label::quiet("X", 0), N_CULMANN_PLAN)?;
    let along_i = b.parallel(&li, &x, Role::Auxiliary, N_CULMANN_PLAN);
    let along_j = b.parallel(&lj, &f0, Role::Auxiliary, N_CULMANN_PLAN);
    let y = b.meet_point(&along_i, &along_j, Label::quiet("Y", 0), N_CULMANN_PLAN)?;
    Ok(vec![
        (support_index(t, r[k].0), last, x),
        (support_index(t, r[i].0), x, y),
        (support_index(t, r[j].0), y, f0),
    ])
}

/// Reads each reaction off the force plan and checks it by the moment equations of the whole
/// truss (LH C.2) and against the sparse solve: a roller's along its line, a pin's by its
/// horizontal and vertical parts.
pub(super) fn read_reactions(
    b: &mut Board,
    inp: &ReactionInput,
    segs: &[PlanSegment],
    by_moments: Option<&[Vector]>,
) -> Result<(), ConstructionError> {
    let r = Reader {
        inp,
        by_moments,
        kg: Scale::kg(inp.fs),
    };
    let mut col = 0;
    for (si, sup) in inp.t.supports.iter().enumerate() {
        let first_col = col;
        col += match sup.kind {
            SupportKind::Pinned => 2,
            SupportKind::Roller { .. } => 1,
        };
        let Some((from, to)) = segs[si] else {
            continue;
        };
        match sup.kind {
            SupportKind::Roller { dir } => r.roller(b, si, dir, (from, to), first_col),
            SupportKind::Pinned => r.pin(b, si, (from, to), first_col)?,
        }
    }
    Ok(())
}

/// Reads reactions off the force plan and checks them.
struct Reader<'a> {
    inp: &'a ReactionInput<'a>,
    by_moments: Option<&'a [Vector]>,
    kg: Scale,
}

/// The formula of the sparse solve's checks.
const BY_SOLVE: &str = "joint equilibrium, sparse LU (faer)";
/// The formula of the moment checks.
const BY_MOMENTS: &str = "moments about the other supports (LH C.2)";

impl Reader<'_> {
    /// A roller's reaction, along its line; checked by moments and by the solve (its
    /// unknown is column `col` of the solve).
    fn roller(
        &self,
        b: &mut Board,
        si: usize,
        dir: Vector,
        (from, to): (H<Point>, H<Point>),
        col: usize,
    ) {
        let reference = self.inp.maxload;
        let line = self.inp.rlines[si].expect("a roller has a line");
        let v = b.measure(&from, &to, &line, self.kg, Label::quiet("R", 0), N_REACT);
        if let Some(m) = self.by_moments {
            let what = "roller reaction by moments";
            b.check(&v, what, "kg", BY_MOMENTS, reference, || m[si].dot(&dir));
        }
        if let Some(sol) = self.inp.sol {
            let what = "roller reaction along its line";
            let scale = reference.max(sol.scale());
            b.check(&v, what, "kg", BY_SOLVE, scale, || sol.reactions[col]);
        }
    }

    /// A pin's reaction, by its horizontal and vertical parts; checked by moments and by the
    /// solve (its unknowns are columns `col` and `col + 1`).
    fn pin(
        &self,
        b: &mut Board,
        si: usize,
        (from, to): (H<Point>, H<Point>),
        col: usize,
    ) -> Result<(), ConstructionError> {
        let reference = self.inp.maxload;
        let aux = Role::Auxiliary;
        let xa = b.line_dir(&from, Vector::new(1.0, 0.0), aux, N_AXIS)?;
        let ya = b.line_dir(&from, Vector::new(0.0, 1.0), aux, N_AXIS)?;
        let ax = b.measure(&from, &to, &xa, self.kg, Label::quiet("Ax", 0), N_REACT);
        let ay = b.measure(&from, &to, &ya, self.kg, Label::quiet("Ay", 0), N_REACT);
        if let Some(m) = self.by_moments {
            let what = "pin reaction by moments, horizontal";
            b.check(&ax, what, "kg", BY_MOMENTS, reference, || m[si].x);
            let what = "pin reaction by moments, vertical";
            b.check(&ay, what, "kg", BY_MOMENTS, reference, || m[si].y);
        }
        if let Some(sol) = self.inp.sol {
            // The solve's rounding is relative to its largest force, not to the reactions.
            let scale = reference.max(sol.scale());
            let what = "pin reaction, horizontal";
            b.check(&ax, what, "kg", BY_SOLVE, scale, || sol.reactions[col]);
            let what = "pin reaction, vertical";
            b.check(&ay, what, "kg", BY_SOLVE, scale, || sol.reactions[col + 1]);
        }
        Ok(())
    }
}

/// A reaction in the force plan: its tail and head, where the construction gives one.
pub(super) type PlanSegment = Option<(H<Point>, H<Point>)>;

/// The loads' force polygon for the reactions: its corners, the pole and its rays.
struct LoadsPolygon {
    corners: Vec<H<Point>>,
    pole: H<Point>,
    rays: Vec<H<Line>>,
}

/// What the graphic reactions of one case work from: the truss and its supports, the dense
/// solve, the force scale, the largest load, the joints and reaction lines of the truss
/// drawing, the loads (in the order of their joints) and where the parts of the case go.
#[derive(Clone, Copy)]
pub(super) struct ReactionInput<'a> {
    pub(super) t: &'a Truss,
    pub(super) sup: Supports,
    pub(super) sol: Option<&'a Solution>,
    pub(super) fs: f64,
    pub(super) maxload: f64,
    pub(super) jp: &'a [H<Point>],
    pub(super) rlines: &'a [Option<H<Line>>],
    pub(super) loads: &'a [JointLoad],
}

/// The reactions by the funicular polygon, one vector per support (LH C.2): the loads' force
/// polygon, a pole by [`choose_pole`], the strings from the pin (or the first roller), then
/// the closing line for a pin and a roller, Culmann's line for three rollers; each reaction
/// drawn, read off and checked.
pub(super) fn draw_reactions(
    b: &mut Board,
    inp: &ReactionInput,
    truss_box: &mut [f64; 4],
) -> Result<Vec<Vector>, ConstructionError> {
    let ReactionInput {
        t,
        sup,
        fs,
        jp,
        loads,
        ..
    } = *inp;
    let mut reactions = vec![Vector::zeros(); t.supports.len()];
    if loads.is_empty() {
        return Ok(reactions);
    }
    let LoadsPolygon {
        corners: fh,
        pole,
        rays,
    } = loads_polygon(b, inp)?;
    // The first string starts at the pin, or at the first roller.
    let start = match sup {
        Supports::PinRoller { pin, .. } => pin,
        Supports::Rollers(r) => r[0].0,
    };
    column(b, TRUSS);
    let strings = polygon::strings(
        b,
        &rays,
        &jp[start],
        false,
        StringStyle::CONSTRUCTION,
        |b, j| {
            let l = &loads[j];
            b.line_dir(&jp[l.joint], l.force, Role::Auxiliary, N_LOA)
        },
    )?;
    for c in &strings.corners {
        grow(truss_box, c.g, Point::origin());
    }
    let (first, s) = (strings.strings[0], strings.strings[loads.len()]);
    let segs = match sup {
        Supports::PinRoller { pin, roller, .. } => {
            pin_and_roller(b, inp, (pin, roller), &s, &fh, &pole, truss_box)?
        }
        Supports::Rollers(r) => {
            let mut segs = vec![None; t.supports.len()];
            for (si, from, to) in culmann(b, inp, &first, &s, &fh, &r)? {
                segs[si] = Some((from, to));
            }
            segs
        }
    };
    // Each reaction drawn, read off and checked: a roller's along its line, a pin's by its
    // horizontal and vertical parts.
    for (si, seg) in segs.iter().enumerate() {
        if let Some((from, to)) = seg {
            b.segment(
                from,
                to,
                Role::Force.labelled(support_label(t, si)),
                N_REACT,
            );
            reactions[si] = (to.g - from.g) * fs;
        }
    }
    let by_moments = super::reactions::by_moments(t, loads);
    read_reactions(b, inp, &segs, by_moments.as_deref())?;
    Ok(reactions)
}

/// The loads laid off head to tail in the order of their joints, the pole, and its rays:
/// the corners, and (pole, rays).
fn loads_polygon(b: &mut Board, inp: &ReactionInput) -> Result<LoadsPolygon, ConstructionError> {
    let ReactionInput { sup, fs, loads, .. } = *inp;
    column(b, POLYGON);
    let mut corners = vec![Point::origin()];
    for l in loads {
        let c = *corners.last().expect("starts with one corner") + l.force / fs;
        corners.push(c);
    }
    let dirs: Vec<Vector> = loads.iter().map(|l| l.force).collect();
    let last_dir = match sup {
        Supports::PinRoller { dir, .. } => dir,
        Supports::Rollers(r) => r[0].1,
    };
    let pole = choose_pole(&corners, &dirs, last_dir);
    let f0 = b.point(
        corners[0],
        Role::Given.labelled(Label::indexed("F", 0)),
        N_FP,
    );
    let mut fh = vec![f0];
    for (i, l) in loads.iter().enumerate() {
        let along = b.line_dir(&fh[i], l.force, Role::Auxiliary, N_FP)?;
        let len = l.force.norm() / fs;
        fh.push(b.lay_off(&fh[i], &along, len, Role::Force, N_FP)?);
    }
    let polygon::Rays { pole: o, rays } = polygon::pole_and_rays(b, pole, &fh)?;
    Ok(LoadsPolygon {
        corners: fh,
        pole: o,
        rays,
    })
}

/// A pin and a roller: the last string cuts the roller's line in b′; the closing line from
/// the pin to b′, carried through the pole, cuts the parallel to the roller's reaction
/// through the end of the loads in X, which divides the closing side into B and A.
fn pin_and_roller(
    b: &mut Board,
    inp: &ReactionInput,
    (pin, roller): (usize, usize),
    last_string: &H<Line>,
    fh: &[H<Point>],
    pole: &H<Point>,
    truss_box: &mut [f64; 4],
) -> Result<Vec<PlanSegment>, ConstructionError> {
    let ReactionInput { t, jp, rlines, .. } = *inp;
    let mut segs = vec![None; t.supports.len()];
    let last = fh[fh.len() - 1];
    let ri = support_index(t, roller);
    let rline = rlines[ri].expect("a roller has a line");
    let bcut = b.meet_point(last_string, &rline, Label::quiet("b", 0), N_B_CUT)?;
    grow(truss_box, bcut.g, Point::origin());
    let con = Role::Construction;
    // The closing line in the truss drawing, its parallel through the pole in the polygon.
    let ray_part = part_of(b, POLYGON);
    let closing = polygon::closing_across(b, (&jp[pin], &bcut), pole, con, ray_part)?;
    let bl = b.parallel(&rline, &last, Role::Auxiliary, N_B_DIR);
    let x = b.meet_point(&closing.ray, &bl, Label::quiet("X", 0), N_SPLIT)?;
    segs[ri] = Some((last, x));
    segs[support_index(t, pin)] = Some((x, fh[0]));
    Ok(segs)
}
