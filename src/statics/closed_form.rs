//! The closed forms a beam construction is checked against: equilibrium for the reactions,
//! the method of sections for M(x) and V(x). Computed independently of the construction.

use super::{Beam, UniformLoad};
use std::cell::Cell;

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
    Sections::new(beam).max_abs_moment()
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
    /// Where the last section fell among `xs`: sections are mostly asked for in x order, so
    /// the next falls there or one further, found without a search.
    hint: Cell<usize>,
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
            hint: Cell::new(0),
        }
    }

    /// [`max_abs_moment`] from the loads sorted and summed already (the same bits).
    pub fn max_abs_moment(&self) -> (f64, f64) {
        let mut xs: Vec<f64> = self.beam.supports.to_vec();
        xs.extend(self.beam.point_loads.iter().map(|l| l.x));
        for u in &self.beam.uniform_loads {
            xs.push(u.from);
            xs.push(u.to);
            // V is linear inside: V(from+) − q (x − from) = 0.
            if u.q != 0.0 {
                let x0 = u.from + self.shear(u.from, false) / u.q;
                if x0 > u.from && x0 < u.to {
                    xs.push(x0);
                }
            }
        }
        let mut best = (0.0f64, self.beam.ends[0]);
        for x in xs {
            let m = self.moment(x);
            if m.abs() > best.0.abs() {
                best = (m, x);
            }
        }
        best
    }

    /// How many loads lie left of `x` (`at_too`: or at it): `partition_point` over the sorted
    /// `xs`, whose answer is the one place where the loads before lie left and the rest not.
    /// That place is tried at the last section's and the next before a binary search, so a
    /// sweep in x order costs O(1) a section; the answer is the same either way.
    fn loads_left_of(&self, x: f64, at_too: bool) -> usize {
        let xs = &self.xs;
        let left = |v: f64| if at_too { v <= x } else { v < x };
        let fits = |i: usize| (i == 0 || left(xs[i - 1])) && (i == xs.len() || !left(xs[i]));
        let h = self.hint.get();
        let i = if h <= xs.len() && fits(h) {
            h
        } else if h < xs.len() && fits(h + 1) {
            h + 1
        } else {
            xs.partition_point(|&v| left(v))
        };
        self.hint.set(i);
        i
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
        let (sp, spx) = self.prefix[self.loads_left_of(x, false)];
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
        v -= self.prefix[self.loads_left_of(x, !just_left)].0;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statics::PointLoad;

    /// The place found from the last section's is `partition_point`'s, whatever the order
    /// the sections come in: sorted, reversed, jumping, on a load, between two loads at one x.
    #[test]
    fn the_hinted_place_among_the_loads_is_the_searched_one() {
        let at = [0.5, 1.0, 1.0, 1.0, 2.5, 3.0, 7.0, 7.0, 9.5];
        let beam = Beam {
            supports: [0.0, 10.0],
            ends: [0.0, 10.0],
            point_loads: (at.iter().rev())
                .map(|&x| PointLoad { x, p: 100.0 })
                .collect(),
            uniform_loads: vec![],
        };
        let sec = Sections::new(&beam);
        let mut probes: Vec<f64> = (0..=44).map(|i| -0.5 + 0.25 * i as f64).collect();
        probes.extend(at);
        let mut orders = vec![probes.clone()];
        probes.sort_by(f64::total_cmp);
        orders.push(probes.clone());
        orders.push(probes.iter().rev().copied().collect());
        orders.push(
            (0..probes.len())
                .map(|i| probes[(i * 17) % probes.len()])
                .collect(),
        );
        for order in orders {
            for &x in &order {
                for at_too in [false, true] {
                    let searched = sec
                        .xs
                        .partition_point(|&v| if at_too { v <= x } else { v < x });
                    assert_eq!(sec.loads_left_of(x, at_too), searched, "x = {x}, {at_too}");
                }
            }
        }
    }
}
