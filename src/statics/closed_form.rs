//! The closed forms a beam construction is checked against: equilibrium for the reactions,
//! the method of sections for M(x) and V(x). Computed independently of the construction.

use super::{Beam, UniformLoad};

/// Support reactions (A, B) from moment equilibrium about B and vertical equilibrium (kg).
///
/// ```
/// use graphostatik::statics::{closed_form::reactions, Beam, PointLoad};
/// let beam = Beam { supports: [0.0, 4.0], ends: [0.0, 4.0],
///     point_loads: vec![PointLoad { x: 1.0, p: 400.0 }], uniform_loads: vec![] };
/// assert_eq!(reactions(&beam), (300.0, 100.0));
/// ```
pub fn reactions(beam: &Beam) -> (f64, f64) {
    let [xa, xb] = beam.supports;
    let mut total = 0.0;
    let mut moment_about_b = 0.0;
    for l in &beam.point_loads {
        total += l.p;
        moment_about_b += l.p * (xb - l.x);
    }
    for u in &beam.uniform_loads {
        let q = u.resultant();
        total += q;
        moment_about_b += q * (xb - u.centre());
    }
    let a = moment_about_b / (xb - xa);
    (a, total - a)
}

/// Bending moment M(x) (kg·m), sagging positive, from the forces left of the section.
pub fn moment(beam: &Beam, x: f64) -> f64 {
    let (ra, rb) = reactions(beam);
    let mut m = 0.0;
    for (s, r) in [(beam.supports[0], ra), (beam.supports[1], rb)] {
        if s < x {
            m += r * (x - s);
        }
    }
    for l in &beam.point_loads {
        if l.x < x {
            m -= l.p * (x - l.x);
        }
    }
    for u in &beam.uniform_loads {
        if u.from < x {
            let e = x.min(u.to);
            m -= u.q * (e - u.from) * (x - 0.5 * (u.from + e));
        }
    }
    m
}

/// Shear force just right of the section x (kg): upward forces at or left of x less the
/// downward loads at or left of x. `just_left` counts only forces strictly left of x.
pub fn shear(beam: &Beam, x: f64, just_left: bool) -> f64 {
    let (ra, rb) = reactions(beam);
    let left = |s: f64| if just_left { s < x } else { s <= x };
    let mut v = 0.0;
    for (s, r) in [(beam.supports[0], ra), (beam.supports[1], rb)] {
        if left(s) {
            v += r;
        }
    }
    for l in &beam.point_loads {
        if left(l.x) {
            v -= l.p;
        }
    }
    for u in &beam.uniform_loads {
        if u.from < x {
            v -= u.q * (x.min(u.to) - u.from);
        }
    }
    v
}

/// The largest |M| over the beam and where it is (m): at a support, a point load, the end of
/// a uniform load, or inside a uniform load where the shear passes through zero.
pub fn max_abs_moment(beam: &Beam) -> (f64, f64) {
    let sec = Sections::new(beam);
    let mut xs: Vec<f64> = beam.supports.to_vec();
    xs.extend(beam.point_loads.iter().map(|l| l.x));
    for u in &beam.uniform_loads {
        xs.push(u.from);
        xs.push(u.to);
        // V is linear inside: V(from+) − q (x − from) = 0.
        if u.q != 0.0 {
            let x0 = u.from + sec.shear(u.from, false) / u.q;
            if x0 > u.from && x0 < u.to {
                xs.push(x0);
            }
        }
    }
    let mut best = (0.0f64, beam.ends[0]);
    for x in xs {
        let m = sec.moment(x);
        if m.abs() > best.0.abs() {
            best = (m, x);
        }
    }
    best
}

/// The method of sections prepared once for many sections: point loads sorted with prefix sums
/// of P and P·x, and, where there are more than [`UNIFORM_LOADS_SUMMED`] uniform loads that do
/// not overlap, those too, so that M(x) and V(x) cost O(log n) each instead of O(n) (a beam of
/// 200,000 uniform loads took minutes to check). The checks of a long beam use it; [`moment`]
/// and [`shear`] stay as the plain reference it is tested against.
#[derive(Debug, Clone)]
pub struct Sections<'a> {
    beam: &'a Beam,
    reactions: (f64, f64),
    xs: Vec<f64>,
    /// prefix[i] = (Σ P, Σ P·x) over the first i loads in x order.
    prefix: Vec<(f64, f64)>,
    /// The uniform loads summed up, where there are many and they do not overlap.
    uniform: Option<UniformSums>,
}

/// Up to this many uniform loads, a section adds them one by one (the same bits as
/// [`moment`]); above, from prefix sums, which round differently in the last digits.
pub const UNIFORM_LOADS_SUMMED: usize = 32;

/// Uniform loads that do not overlap, in the order of their starts, with prefix sums of their
/// resultants q·L and moments q·L·c about the origin.
#[derive(Debug, Clone)]
struct UniformSums {
    /// (from, to, q) in the order of `from`.
    loads: Vec<(f64, f64, f64)>,
    /// prefix[i] = (Σ q·L, Σ q·L·c) over the first i loads.
    prefix: Vec<(f64, f64)>,
}

impl UniformSums {
    /// The loads sorted and summed, if there are more than [`UNIFORM_LOADS_SUMMED`], each ends
    /// after it starts, and none overlaps the next (touching is allowed).
    fn new(loads: &[UniformLoad]) -> Option<UniformSums> {
        if loads.len() <= UNIFORM_LOADS_SUMMED
            || loads
                .iter()
                .any(|u| u.to.partial_cmp(&u.from).is_none_or(|o| o.is_lt()))
        {
            return None;
        }
        let mut l: Vec<(f64, f64, f64)> = loads.iter().map(|u| (u.from, u.to, u.q)).collect();
        l.sort_by(|a, b| a.0.total_cmp(&b.0));
        if l.windows(2).any(|w| w[1].0 < w[0].1) {
            return None;
        }
        let mut prefix = Vec::with_capacity(l.len() + 1);
        let (mut sq, mut sqc) = (0.0, 0.0);
        prefix.push((0.0, 0.0));
        for &(a, b, q) in &l {
            let r = q * (b - a);
            sq += r;
            sqc += r * 0.5 * (a + b);
            prefix.push((sq, sqc));
        }
        Some(UniformSums { loads: l, prefix })
    }

    /// The loads that start left of `x`: how many lie wholly left of it, and the one `x` cuts,
    /// if any.
    fn left_of(&self, x: f64) -> (usize, Option<(f64, f64, f64)>) {
        let k = self.loads.partition_point(|u| u.0 < x);
        match k.checked_sub(1).map(|i| self.loads[i]) {
            Some(u) if u.1 > x => (k - 1, Some(u)),
            _ => (k, None),
        }
    }

    /// The uniform loads' share of M(x).
    fn moment(&self, x: f64) -> f64 {
        let (whole, cut) = self.left_of(x);
        let (sq, sqc) = self.prefix[whole];
        let cut = cut.map_or(0.0, |(a, _, q)| q * (x - a) * (x - 0.5 * (a + x)));
        sq * x - sqc + cut
    }

    /// The uniform loads' share of V(x).
    fn shear(&self, x: f64) -> f64 {
        let (whole, cut) = self.left_of(x);
        self.prefix[whole].0 + cut.map_or(0.0, |(a, _, q)| q * (x - a))
    }
}

impl<'a> Sections<'a> {
    /// Sorts the loads and sums them up.
    pub fn new(beam: &'a Beam) -> Sections<'a> {
        let mut loads: Vec<(f64, f64)> = beam.point_loads.iter().map(|l| (l.x, l.p)).collect();
        loads.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut prefix = Vec::with_capacity(loads.len() + 1);
        let (mut sp, mut spx) = (0.0, 0.0);
        prefix.push((0.0, 0.0));
        for &(x, p) in &loads {
            sp += p;
            spx += p * x;
            prefix.push((sp, spx));
        }
        Sections {
            beam,
            reactions: reactions(beam),
            xs: loads.iter().map(|l| l.0).collect(),
            prefix,
            uniform: UniformSums::new(&beam.uniform_loads),
        }
    }

    /// M(x) (kg·m), as [`moment`].
    pub fn moment(&self, x: f64) -> f64 {
        let (ra, rb) = self.reactions;
        let mut m = 0.0;
        for (s, r) in [(self.beam.supports[0], ra), (self.beam.supports[1], rb)] {
            if s < x {
                m += r * (x - s);
            }
        }
        let (sp, spx) = self.prefix[self.xs.partition_point(|&v| v < x)];
        m -= sp * x - spx;
        if let Some(u) = &self.uniform {
            return m - u.moment(x);
        }
        for u in &self.beam.uniform_loads {
            if u.from < x {
                let e = x.min(u.to);
                m -= u.q * (e - u.from) * (x - 0.5 * (u.from + e));
            }
        }
        m
    }

    /// V(x) (kg), as [`shear`].
    pub fn shear(&self, x: f64, just_left: bool) -> f64 {
        let (ra, rb) = self.reactions;
        let left = |s: f64| if just_left { s < x } else { s <= x };
        let mut v = 0.0;
        for (s, r) in [(self.beam.supports[0], ra), (self.beam.supports[1], rb)] {
            if left(s) {
                v += r;
            }
        }
        let i = if just_left {
            self.xs.partition_point(|&v| v < x)
        } else {
            self.xs.partition_point(|&v| v <= x)
        };
        v -= self.prefix[i].0;
        if let Some(u) = &self.uniform {
            return v - u.shear(x);
        }
        for u in &self.beam.uniform_loads {
            if u.from < x {
                v -= u.q * (x.min(u.to) - u.from);
            }
        }
        v
    }
}
