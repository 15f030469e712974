//! Times the recorded crank construction at growing angle counts (a scaling probe).
use graphostatik::crank::*;
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use std::time::Instant;
fn main() {
    let d = CrankDrive {
        crank_radius: 315.0,
        rod_length: 1890.0,
        finite_rod: true,
        crank_pin_speed: 7.0,
        piston_force: PistonForce::Constant(8700.0),
    };
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
    for n in [36usize, 360, 1000, 3600] {
        for rec in [false, true] {
            let t = Instant::now();
            let reps = 20000 / n + 1;
            for _ in 0..reps {
                let mut b = Board::new(BoardConfig::recording(rec)).with_figure_size(300.0);
                construct(&mut b, &d, &dr, &Angles::Divisions(n), &rq).unwrap();
                std::hint::black_box(&b);
            }
            println!(
                "n={n} rec={rec}: {:.0} ns/angle",
                t.elapsed().as_nanos() as f64 / (reps * n) as f64
            );
        }
    }
}
