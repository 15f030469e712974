//! Sizing from the moment area (LH Aufgabe 7): the shaft diameter from M = W·k_b with
//! W = 0.1·d³ (round section), the arm height from W = b·H²/6 (rectangular section). With the
//! moment read as an ordinate y of a moment area drawn at pole distance h (mm), force scale
//! 1 mm = m kg and length scale 1 : l, M = y·h·m·l/10 kg·cm, so d = const·∛y and H = const·√y.

/// Shaft diameter (cm) for a bending (or ideal) moment M (kg·cm) at the allowed stress
/// k_b (kg/cm²): d = ∛(M / (0.1·k_b)).
///
/// ```
/// use graphostatik::statics::sizing::shaft_diameter_cm;
/// assert!((shaft_diameter_cm(100.0, 1000.0) - 1.0).abs() < 1e-12);
/// ```
pub fn shaft_diameter_cm(m_kgcm: f64, kb: f64) -> f64 {
    (m_kgcm.abs() / (0.1 * kb)).cbrt()
}

/// Height H (cm) of a rectangular arm of width b (cm) for a moment M (kg·cm) at k_b (kg/cm²):
/// H = √(6·M / (b·k_b)).
pub fn arm_height_cm(m_kgcm: f64, b_cm: f64, kb: f64) -> f64 {
    (6.0 * m_kgcm.abs() / (b_cm * kb)).sqrt()
}

/// The moment (kg·cm) an ordinate y (mm) stands for: y·h·m·l/10 (LH Aufgabe 7).
pub fn ordinate_moment_kgcm(y_mm: f64, h_mm: f64, m_kg_per_mm: f64, l: f64) -> f64 {
    y_mm * h_mm * m_kg_per_mm * l / 10.0
}

/// The constant of d = const·∛y (d in cm, y in mm).
pub fn diameter_constant(h_mm: f64, m_kg_per_mm: f64, l: f64, kb: f64) -> f64 {
    (h_mm * m_kg_per_mm * l / (10.0 * 0.1 * kb)).cbrt()
}

/// The constant of H = const·√y (H in cm, y in mm) for arm width b (cm).
pub fn height_constant(h_mm: f64, m_kg_per_mm: f64, l: f64, b_cm: f64, kb: f64) -> f64 {
    (6.0 * h_mm * m_kg_per_mm * l / (10.0 * b_cm * kb)).sqrt()
}
