//! What accuracy and bookkeeping cost: the crank diagram (piston path, piston velocity by the
//! parallel of KG Abb. 1049, tangential force by LH Abb. 65) at 36 and 3,600 crank angles,
//! (a) as the bare closed form, (b) as the kernel construction on a board that does not
//! record, (c) on a recording board with every analytic check (the board a figure is drawn
//! from), (d) with every check and bound on the board `check` uses, which keeps the checks
//! and not the drawing.
//!
//! The closed form comes twice: as the crate's `crank::closed_form` functions (each reckons
//! the book's stroke, its angle and its own sines), and lean, (a'), the same sum in one
//! `sin_cos` and one square root per angle: the least a program needs for these numbers.
//!
//! `cargo bench --bench crank` runs criterion, then prints a Markdown table of ns per angle
//! (median of repeated runs) and the ratios to (a) and to (a'), the targets being (b) ≤ 5x
//! and (c) ≤ 40x the lean closed form.

use criterion::{criterion_group, BenchmarkId, Criterion, Throughput};
use graphostatik::crank::closed_form as cf;
use graphostatik::crank::*;
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use std::hint::black_box;
use std::time::Instant;

fn drive() -> CrankDrive {
    CrankDrive {
        crank_radius: 315.0,
        rod_length: 1890.0,
        finite_rod: true,
        crank_pin_speed: 7.0,
        piston_force: PistonForce::Constant(8700.0),
    }
}

const DRAWING: Drawing = Drawing {
    length_scale: 10.0,
    force_scale: 200.0,
    velocity_scale: 0.25,
    acceleration_scale: 10.0,
};

const REQUEST: Request = Request {
    piston_path: true,
    velocity_parallel: true,
    velocity_instant_centre: false,
    rod_force: false,
    guide_force: false,
    tangential_force: true,
    radial_force: false,
    acceleration: false,
    max_velocity: false,
    polar_diagrams: false,
    piston_path_fixed_arc: false,
};

fn closed_form(n: usize) -> f64 {
    let d = drive();
    let (lam, rod) = (d.lambda(), d.rod());
    let mut acc = 0.0;
    for k in 0..n {
        let th = 360.0 * k as f64 / n as f64;
        acc += cf::piston_position(d.crank_radius, rod, th)
            + cf::piston_velocity(d.crank_pin_speed, lam, th)
            + cf::tangential_force(8700.0, lam, th);
    }
    acc
}

#[path = "support/lean_crank.rs"]
mod lean_crank;

/// (a'): the same sum as [`closed_form`], as lean as it goes ([`lean_crank::sum`]).
fn lean_closed_form(n: usize) -> f64 {
    let d = drive();
    lean_crank::sum(d.crank_radius, d.rod_length, d.crank_pin_speed, 8700.0, n)
}

fn constructed(n: usize, recording: bool) -> usize {
    let mut b = Board::new(BoardConfig::recording(recording)).with_figure_size(300.0);
    let r = construct(&mut b, &drive(), &DRAWING, &Angles::Divisions(n), &REQUEST).unwrap();
    r.rows.len() + b.steps().len()
}

/// (d): what `check` makes, every check and bound without the drawing.
fn checked(n: usize) -> usize {
    let mut b = Board::new(BoardConfig::CHECKS).with_figure_size(300.0);
    let r = construct(&mut b, &drive(), &DRAWING, &Angles::Divisions(n), &REQUEST).unwrap();
    r.rows.len() + b.step_count() + usize::from(b.all_passed())
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("crank_diagram");
    for n in [36usize, 3600] {
        let (a, lean) = (closed_form(n), lean_closed_form(n));
        assert!((a - lean).abs() <= 1e-9 * a.abs(), "{a} {lean}");
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::new("a_lean_closed_form", n), &n, |b, &n| {
            b.iter(|| lean_closed_form(black_box(n)))
        });
        g.bench_with_input(BenchmarkId::new("a_closed_form", n), &n, |b, &n| {
            b.iter(|| closed_form(black_box(n)))
        });
        g.bench_with_input(BenchmarkId::new("b_construction", n), &n, |b, &n| {
            b.iter(|| constructed(black_box(n), false))
        });
        g.bench_with_input(BenchmarkId::new("c_recorded_checked", n), &n, |b, &n| {
            b.iter(|| constructed(black_box(n), true))
        });
        g.bench_with_input(BenchmarkId::new("d_checks_only", n), &n, |b, &n| {
            b.iter(|| checked(black_box(n)))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);

/// Median ns per angle over repeated runs of `f(n)`.
fn ns_per_angle(n: usize, f: &dyn Fn(usize)) -> f64 {
    let reps = (200_000 / n).max(3);
    let mut samples = Vec::new();
    for _ in 0..15 {
        let t = Instant::now();
        for _ in 0..reps {
            f(black_box(n));
        }
        samples.push(t.elapsed().as_nanos() as f64 / (reps * n) as f64);
    }
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    println!();
    println!("| angles | (a) closed form | (a') lean | (b) construction | (c) recorded + checked | (d) checks only | (b)/(a) | (c)/(a) | (d)/(a) | (b)/(a') | (c)/(a') | (d)/(a') |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in [36usize, 3600] {
        let a = ns_per_angle(n, &|n| {
            black_box(closed_form(n));
        });
        let lean = ns_per_angle(n, &|n| {
            black_box(lean_closed_form(n));
        });
        let b = ns_per_angle(n, &|n| {
            black_box(constructed(n, false));
        });
        let c = ns_per_angle(n, &|n| {
            black_box(constructed(n, true));
        });
        let d = ns_per_angle(n, &|n| {
            black_box(checked(n));
        });
        println!(
            "| {n} | {a:.0} ns | {lean:.0} ns | {b:.0} ns | {c:.0} ns | {d:.0} ns | {:.2}x | {:.1}x | {:.1}x | {:.1}x | {:.0}x | {:.0}x |",
            b / a,
            c / a,
            d / a,
            b / lean,
            c / lean,
            d / lean
        );
    }
}
