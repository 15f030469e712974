//! What the beam construction costs, and what accuracy costs:
//!
//! 1. Funicular polygon, reactions, moment area and shear diagram for 10, 1,000 and 100,000
//!    point loads: ns per load (must be linear).
//! 2. A uniform load q over the span replaced by n equal point loads at the centres of n equal
//!    strips (n = 2 … 1,024), against the parabola drawn by its tangents: error of max M
//!    against q·l²/8 and the time it takes.
//!
//! `cargo bench --bench statics` runs criterion, then prints both tables in Markdown.

use criterion::{criterion_group, BenchmarkId, Criterion, Throughput};
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use graphostatik::statics::*;
use std::hint::black_box;
use std::time::Instant;

const ALL: BeamRequest = BeamRequest {
    reactions: true,
    moment_area: true,
    shear_diagram: true,
};

fn drawing() -> BeamDrawing {
    BeamDrawing {
        length_scale: 50.0,
        force_scale: 40.0,
        pole_distance: 5000.0,
        parabola_divisions: 8,
        origin: graphostatik::kernel::Point::origin(),
    }
}

fn loads(n: usize) -> Beam {
    let l = 10.0;
    Beam {
        supports: [0.0, l],
        ends: [0.0, l],
        point_loads: (0..n)
            .map(|i| PointLoad {
                x: l * (i as f64 + 0.5) / n as f64,
                p: 100.0 + (i % 13) as f64,
            })
            .collect(),
        uniform_loads: vec![],
    }
}

fn strips(n: usize, q: f64, l: f64) -> Beam {
    Beam {
        supports: [0.0, l],
        ends: [0.0, l],
        point_loads: (0..n)
            .map(|i| PointLoad {
                x: l * (i as f64 + 0.5) / n as f64,
                p: q * l / n as f64,
            })
            .collect(),
        uniform_loads: vec![],
    }
}

fn parabola(q: f64, l: f64, m: usize) -> (Beam, BeamDrawing) {
    let mut d = drawing();
    d.parabola_divisions = m;
    (
        Beam {
            supports: [0.0, l],
            ends: [0.0, l],
            point_loads: vec![],
            uniform_loads: vec![UniformLoad {
                from: 0.0,
                to: l,
                q,
            }],
        },
        d,
    )
}

fn solve(beam: &Beam, d: &BeamDrawing, recording: bool) -> f64 {
    let mut b = Board::new(BoardConfig::recording(recording)).with_figure_size(300.0);
    construct_beam(&mut b, beam, d, &ALL)
        .unwrap()
        .max_moment
        .unwrap()
        .moment
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("beam");
    g.sample_size(10);
    for n in [10usize, 1000, 100_000] {
        let beam = loads(n);
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::new("construction", n), &beam, |b, beam| {
            b.iter(|| solve(black_box(beam), &drawing(), false))
        });
        if n <= 1000 {
            g.bench_with_input(BenchmarkId::new("recorded_checked", n), &beam, |b, beam| {
                b.iter(|| solve(black_box(beam), &drawing(), true))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);

/// Median wall time of `f` in ns over a few repetitions.
fn time_ns(f: &dyn Fn()) -> f64 {
    let reps = 7;
    let mut v = Vec::new();
    for _ in 0..reps {
        let t = Instant::now();
        f();
        v.push(t.elapsed().as_nanos() as f64);
    }
    v.sort_by(f64::total_cmp);
    v[reps / 2]
}

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();

    println!();
    println!("| loads | construction | ns per load | recorded + checked | ns per load |");
    println!("|---:|---:|---:|---:|---:|");
    for n in [10usize, 1000, 100_000] {
        let beam = loads(n);
        let t = time_ns(&|| {
            black_box(solve(&beam, &drawing(), false));
        });
        let (tr, per) = if n <= 10_000 {
            let tr = time_ns(&|| {
                black_box(solve(&beam, &drawing(), true));
            });
            (
                format!("{:.1} µs", tr / 1e3),
                format!("{:.0}", tr / n as f64),
            )
        } else {
            ("-".to_string(), "-".to_string())
        };
        println!(
            "| {n} | {:.1} µs | {:.0} | {tr} | {per} |",
            t / 1e3,
            t / n as f64
        );
    }

    let (q, l) = (500.0, 6.0);
    let exact = q * l * l / 8.0;
    println!();
    println!("| uniform load as | max M (kg·m) | error of max M | largest error of the moment line | time, constructed | time, recorded + checked |");
    println!("|---|---:|---:|---:|---:|---:|");
    let parabola_m = |x: f64| q * x * (l - x) / 2.0;
    let mut n = 2;
    while n <= 1024 {
        let beam = strips(n, q, l);
        let m = solve(&beam, &drawing(), false);
        // The polygon's corners against the exact parabola under them.
        let mut board = Board::new(BoardConfig::recording(false)).with_figure_size(300.0);
        let r = construct_beam(&mut board, &beam, &drawing(), &ALL).unwrap();
        let line_err = r
            .sections
            .iter()
            .map(|s| (s.moment - parabola_m(s.x)).abs())
            .fold(0.0, f64::max)
            / exact;
        let t = time_ns(&|| {
            black_box(solve(&beam, &drawing(), false));
        });
        let tr = time_ns(&|| {
            black_box(solve(&beam, &drawing(), true));
        });
        println!(
            "| {n} point loads | {m:.6} | {:.1e} | {line_err:.2e} | {:.1} µs | {:.1} µs |",
            (m - exact).abs() / exact,
            t / 1e3,
            tr / 1e3
        );
        n *= 2;
    }
    for m in [2usize, 8, 64] {
        let (beam, d) = parabola(q, l, m);
        let mm = solve(&beam, &d, false);
        let mut board = Board::new(BoardConfig::recording(false)).with_figure_size(300.0);
        let r = construct_beam(&mut board, &beam, &d, &ALL).unwrap();
        let line_err = r
            .sections
            .iter()
            .map(|s| (s.moment - parabola_m(s.x)).abs())
            .fold(0.0, f64::max)
            / exact;
        let t = time_ns(&|| {
            black_box(solve(&beam, &d, false));
        });
        let tr = time_ns(&|| {
            black_box(solve(&beam, &d, true));
        });
        println!(
            "| parabola by tangents, {m} parts | {mm:.6} | {:.1e} | {line_err:.2e} | {:.1} µs | {:.1} µs |",
            (mm - exact).abs() / exact,
            t / 1e3,
            tr / 1e3
        );
    }
}
