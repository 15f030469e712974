//! The crank diagram's closed form as lean as it goes, shared by `benches/crank.rs` and
//! `examples/crank_counts.rs` (`#[path = "support/lean_crank.rs"] mod lean_crank;`): the
//! floor the construction's targets are stated against.

/// The sum over `n` equally spaced crank angles of the piston position, its velocity and
/// the tangential force, in one `sin_cos` and one square root per angle. With s, c the sine
/// and cosine of θ and cos ψ = √(1 − λ²s²) (λ = R/L): the piston at R(1 − c) + L(1 − cos ψ)
/// from the inner dead centre, its velocity v·s·(1 + λc/cos ψ) and the tangential force
/// ±P·s·(1 + λc/cos ψ), + on the outstroke (KG 285, 303; LH Gl. 20, 48).
pub fn sum(r: f64, l: f64, v: f64, p: f64, n: usize) -> f64 {
    let lam = r / l;
    let step = std::f64::consts::TAU / n as f64;
    let mut acc = 0.0;
    for k in 0..n {
        let (s, c) = (step * k as f64).sin_cos();
        let sp = lam * s;
        let cp = ((1.0 - sp) * (1.0 + sp)).sqrt();
        let factor = s + s * lam * c / cp;
        let force = if 2 * k < n { p } else { -p };
        acc += r * (1.0 - c) + l * (1.0 - cp) + (v + force) * factor;
    }
    acc
}
