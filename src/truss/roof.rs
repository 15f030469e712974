//! Roof loads on the joints of a truss (LH B.3, Gl. 3-10): dead load of the cover and the
//! truss, snow by the roof pitch, and wind normal to the roof, each panel's load shared
//! half and half by the joints at its ends (so the eave and ridge joints of a slope get
//! half a panel, LH Abb. 15-16).
//!
//! Per panel of horizontal projection λ (m) and pitch α, with bay spacing a (m):
//! - dead load: (g / cos α + g₂)·a·λ, the cover weight g per m² of roof surface (Gl. 5)
//!   plus the truss weight g₂ per m² of ground (Gl. 6-7), vertical (Gl. 9-10);
//! - snow: s(α)·a·λ, vertical, with s = 75 kg/m² of ground up to 40°, 38 kg/m² up to 50°,
//!   and 0 above (LH B.3 and Aufgabe 4);
//! - wind: N = k·sin²(α + 10°) per m² of roof surface (Gl. 3), W = N·a·λ / cos α (Gl. 4),
//!   normal to the roof, pressing on it, on the slopes that face the wind.

use super::{JointLoad, LoadCase, Truss};
use crate::kernel::Vector;
use serde::Serialize;

/// One slope of the roof: its joints from the eave to the ridge (or any order along it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Slope {
    /// The joints along the slope (indices).
    pub joints: Vec<usize>,
    /// Weight of the cover, kg per m² of roof surface.
    pub cover: f64,
}

/// The roof.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Roof {
    /// Spacing of the trusses a (m).
    pub bay: f64,
    /// Weight of the truss, kg per m² of ground.
    pub truss_weight: f64,
    /// Wind pressure k, kg per m² normal to the wind (120-240, LH B.3).
    pub wind_k: f64,
    /// The slopes.
    pub slopes: Vec<Slope>,
}

/// Snow, kg per m² of ground, by the pitch (degrees): LH B.3 and Aufgabe 4.
pub fn snow_per_m2(pitch_deg: f64) -> f64 {
    if pitch_deg <= 40.0 {
        75.0
    } else if pitch_deg <= 50.0 {
        38.0
    } else {
        0.0
    }
}

/// Gl. 3: the wind's normal pressure on the roof, kg per m² of roof surface.
pub fn wind_normal_per_m2(k: f64, pitch_deg: f64) -> f64 {
    let s = (pitch_deg + 10.0).to_radians().sin();
    k * s * s
}

fn add(loads: &mut Vec<JointLoad>, joint: usize, force: Vector) {
    match loads.iter_mut().find(|l| l.joint == joint) {
        Some(l) => l.force += force,
        None => loads.push(JointLoad { joint, force }),
    }
}

/// The load cases "dead load", "snow", "wind left" and "wind right" (those with loads).
///
/// ```
/// use graphostatik::truss::roof::*;
/// // LH Aufgabe 4, wind from the left on the 60° glass side: W = 150·3·1.5·sin²70°/cos 60°.
/// let w = wind_normal_per_m2(150.0, 60.0) * 3.0 * 1.5 / 0.5;
/// assert!((w - 1192.0).abs() < 1.0); // the book: 1200 kg
/// ```
pub fn load_cases(t: &Truss, roof: &Roof) -> Vec<LoadCase> {
    let mut dead = Vec::new();
    let mut snow = Vec::new();
    let mut wind = [Vec::new(), Vec::new()];
    for slope in &roof.slopes {
        for w in slope.joints.windows(2) {
            let (p, q) = (t.joints[w[0]].at, t.joints[w[1]].at);
            let d = q - p;
            let lambda = d.x.abs();
            if lambda == 0.0 {
                continue;
            }
            let cos = lambda / d.norm();
            let pitch = (d.y.abs() / lambda).atan().to_degrees();
            let area = roof.bay * lambda;
            let g = (slope.cover / cos + roof.truss_weight) * area;
            let s = snow_per_m2(pitch) * area;
            let wn = wind_normal_per_m2(roof.wind_k, pitch) * area / cos;
            // The roof surface faces up: its outward normal has a positive y component.
            let mut n = Vector::new(-d.y, d.x) / d.norm();
            if n.y < 0.0 {
                n = -n;
            }
            // A surface facing left (n.x < 0) takes the wind from the left.
            let side = if n.x < 0.0 { 0 } else { 1 };
            for &j in w {
                add(&mut dead, j, Vector::new(0.0, -0.5 * g));
                if s > 0.0 {
                    add(&mut snow, j, Vector::new(0.0, -0.5 * s));
                }
                if wn > 0.0 && n.x != 0.0 {
                    add(&mut wind[side], j, -n * (0.5 * wn));
                }
            }
        }
    }
    let mut out = Vec::new();
    for (name, loads) in [
        ("dead load", dead),
        ("wind left", std::mem::take(&mut wind[0])),
        ("wind right", std::mem::take(&mut wind[1])),
        ("snow", snow),
    ] {
        if !loads.is_empty() {
            let mut loads = loads;
            loads.sort_by_key(|l| l.joint);
            out.push(LoadCase {
                name: name.into(),
                loads,
                force_scale: None,
                drawn: true,
                book_name: None,
            });
        }
    }
    out
}
