//! The closed forms a beam construction is checked against: equilibrium for the reactions,
//! the method of sections for M(x) and V(x). Computed independently of the construction.

use super::Beam;

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
/// of P and P·x, so that M(x) and V(x) cost O(log n + number of uniform loads) each instead of
/// O(n). The checks of a long beam use it; [`moment`] and [`shear`] stay as the plain reference
/// it is tested against.
#[derive(Debug, Clone)]
pub struct Sections<'a> {
    beam: &'a Beam,
    reactions: (f64, f64),
    xs: Vec<f64>,
    /// prefix[i] = (Σ P, Σ P·x) over the first i loads in x order.
    prefix: Vec<(f64, f64)>,
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
        for u in &self.beam.uniform_loads {
            if u.from < x {
                v -= u.q * (x.min(u.to) - u.from);
            }
        }
        v
    }
}
