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
    let mut xs: Vec<f64> = beam.supports.to_vec();
    xs.extend(beam.point_loads.iter().map(|l| l.x));
    for u in &beam.uniform_loads {
        xs.push(u.from);
        xs.push(u.to);
        // V is linear inside: V(from+) − q (x − from) = 0.
        if u.q != 0.0 {
            let x0 = u.from + shear(beam, u.from, false) / u.q;
            if x0 > u.from && x0 < u.to {
                xs.push(x0);
            }
        }
    }
    let mut best = (0.0f64, beam.ends[0]);
    for x in xs {
        let m = moment(beam, x);
        if m.abs() > best.0.abs() {
            best = (m, x);
        }
    }
    best
}
