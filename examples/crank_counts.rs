//! One run of the crank diagram of `benches/crank.rs` (piston path, velocity by the parallel,
//! tangential force), for counting instructions where wall time is too noisy:
//!
//! ```sh
//! cargo build --release --example crank_counts
//! valgrind --tool=callgrind target/release/examples/crank_counts recorded 3600
//! ```
//!
//! The first argument is `closed` (the bare closed form), `lean` (the same sum in one
//! `sin_cos` and one square root per angle, as `benches/crank.rs` has it), `built` (the construction on a board
//! that does not record), `recorded` (recorded with every check, the board a figure is drawn
//! from) or `checked` (every check and bound on the board `check` uses, which keeps the checks
//! and not the drawing); the second the number of crank angles.
use graphostatik::crank::closed_form as cf;
use graphostatik::crank::*;
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;

#[path = "../benches/support/lean_crank.rs"]
mod lean_crank;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("recorded", String::as_str);
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(36);
    let d = CrankDrive {
        crank_radius: 315.0,
        rod_length: 1890.0,
        finite_rod: true,
        crank_pin_speed: 7.0,
        piston_force: PistonForce::Constant(8700.0),
    };
    let out = match mode {
        "closed" => {
            let (lam, rod) = (d.lambda(), d.rod());
            (0..n)
                .map(|k| {
                    let th = 360.0 * k as f64 / n as f64;
                    cf::piston_position(d.crank_radius, rod, th)
                        + cf::piston_velocity(d.crank_pin_speed, lam, th)
                        + cf::tangential_force(8700.0, lam, th)
                })
                .sum::<f64>()
        }
        "lean" => lean_crank::sum(d.crank_radius, d.rod_length, d.crank_pin_speed, 8700.0, n),
        "built" | "recorded" | "checked" => {
            let dr = Drawing {
                length_scale: 10.0,
                force_scale: 200.0,
                velocity_scale: 0.25,
                acceleration_scale: 10.0,
            };
            let rq = Request {
                piston_path: true,
                velocity_parallel: true,
                tangential_force: true,
                ..Request::default()
            };
            let config = match mode {
                "built" => BoardConfig::SILENT,
                "checked" => BoardConfig::CHECKS,
                _ => BoardConfig::DRAWING,
            };
            let mut b = Board::new(config).with_figure_size(300.0);
            construct(&mut b, &d, &dr, &Angles::Divisions(n), &rq).expect("the bench drive");
            b.step_count() as f64
        }
        other => panic!("closed, lean, built, recorded or checked, not {other}"),
    };
    println!("{mode} {n}: {out}");
}
