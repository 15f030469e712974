//! Scales chosen for a scene that leaves them out.

use super::types::DrawingSpec;
use crate::crank::{CrankDrive, Drawing};

/// Mechanism length (2R + L) on the sheet when the length scale is chosen (mm).
const TARGET_MECHANISM_MM: f64 = 150.0;
/// Largest piston force on the sheet when the force scale is chosen (mm).
const TARGET_FORCE_MM: f64 = 40.0;
/// The crank-pin speed on the sheet as a fraction of the drawn crank radius (LH chose v = r).
const TARGET_VELOCITY_OF_RADIUS: f64 = 1.0;

pub use crate::protocol::nice_at_least;

/// The drawing scales: the scene's, or chosen.
pub fn drawing(spec: Option<&DrawingSpec>, d: &CrankDrive) -> Drawing {
    let spec = spec.copied().unwrap_or(DrawingSpec {
        length_scale: None,
        force_scale_kg_per_mm: None,
        velocity_scale_m_s_per_mm: None,
        acceleration_scale_m_s2_per_mm: None,
    });
    let length_scale = spec.length_scale.unwrap_or_else(|| {
        nice_at_least((2.0 * d.crank_radius + d.rod_length) / TARGET_MECHANISM_MM)
    });
    let pmax = d.piston_force.max_abs();
    let force_scale = spec
        .force_scale_kg_per_mm
        .unwrap_or_else(|| nice_at_least(pmax / TARGET_FORCE_MM));
    let r_mm = d.crank_radius / length_scale;
    let velocity_scale = spec
        .velocity_scale_m_s_per_mm
        .unwrap_or_else(|| nice_at_least(d.crank_pin_speed / (TARGET_VELOCITY_OF_RADIUS * r_mm)));
    // v²/R drawn about as long as the crank radius, as LH Abb. 55 draws 155.5 m/s² as 10.4 mm
    // under a stroke of 37.5 mm.
    let acceleration_scale = spec
        .acceleration_scale_m_s2_per_mm
        .unwrap_or_else(|| nice_at_least(d.v2_over_r() / r_mm));
    Drawing {
        length_scale,
        force_scale,
        velocity_scale,
        acceleration_scale,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn nice_scales() {
        assert_eq!(nice_at_least(7.0), 10.0);
        assert_eq!(nice_at_least(200.0), 200.0);
        assert_eq!(nice_at_least(217.0), 250.0);
        assert_eq!(nice_at_least(0.03), 0.05);
    }
}
