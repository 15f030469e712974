//! What the Cremona plan costs against the joint-equilibrium solve it is checked with, in
//! time and peak memory, on Warren girders of about 100, 1,000 and 10,000 joints with a load
//! at every bottom joint.
//!
//! - plan: the Cremona plan alone (reactions by the funicular polygon, every space of Bow's
//!   notation), on a board that does not record;
//! - recorded: the same, recorded step by step (what `render` draws), without the checks;
//! - sparse LU: faer's sparse LU solve of the 2k × 2k equilibrium matrix, the check every
//!   plan is compared with at every size;
//! - checked: the whole path of `check` after the scene is read: the rank test (a dense SVD,
//!   up to 1,500 joints), the plan recorded, the sparse solve and every check.
//!
//! `cargo bench --bench truss` prints the table in Markdown. Peak memory is counted by a
//! global allocator that records the largest number of bytes live during one run.

use graphostatik::kernel::Vector;
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use graphostatik::truss::cremona::{construct_plan, construct_truss, TrussDrawing};
use graphostatik::truss::generate::{parallel_chord, Web};
use graphostatik::truss::matrix;
use graphostatik::truss::{JointLoad, LoadCase, Truss};
use std::hint::black_box;
use std::time::Instant;

#[path = "support/counting.rs"]
mod counting;

#[global_allocator]
static A: counting::Counting = counting::Counting;

const D: TrussDrawing = TrussDrawing {
    length_scale: 100.0,
    force_scale: 50.0,
};

fn girder(joints: usize) -> (Truss, Vec<LoadCase>) {
    // Warren: k = 2n + 1.
    let n = (joints - 1) / 2;
    let t = parallel_chord(Web::Warren, n, 2.0, 2.0);
    let loads = (1..n)
        .map(|i| JointLoad {
            joint: i,
            force: Vector::new(0.0, -(1000.0 + (i % 7) as f64 * 100.0)),
        })
        .collect();
    (
        t,
        vec![LoadCase {
            name: "P".into(),
            loads,
            force_scale: None,
            drawn: true,
            book_name: None,
        }],
    )
}

/// Median wall time (ns) and the peak of live heap bytes above the start, over `reps` runs.
fn measure(reps: usize, f: &dyn Fn()) -> (f64, usize) {
    let mut times = Vec::new();
    let mut peak = 0;
    for _ in 0..reps {
        let base = counting::start();
        let t = Instant::now();
        f();
        times.push(t.elapsed().as_nanos() as f64);
        peak = peak.max(counting::peak_above(base));
    }
    times.sort_by(f64::total_cmp);
    (times[reps / 2], peak)
}

fn mb(bytes: usize) -> String {
    format!("{:.2} MB", bytes as f64 / 1e6)
}

fn main() {
    println!(
        "| joints | members | plan | ns per joint | peak | recorded | peak | sparse LU | peak | checked | peak |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for joints in [101usize, 1001, 10_001] {
        let (t, cases) = girder(joints);
        let k = t.joints.len();
        let (tp, mp) = measure(7, &|| {
            let mut b = Board::new(BoardConfig::recording(false)).with_figure_size(1000.0);
            black_box(construct_plan(&mut b, &t, &cases, &D).unwrap());
        });
        let (tr, mr) = measure(5, &|| {
            let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
            black_box(construct_plan(&mut b, &t, &cases, &D).unwrap());
        });
        let (ts, ms) = measure(5, &|| {
            t.forget_matrix();
            black_box(matrix::solve(&t, &cases[0]).unwrap());
        });
        let (tc, mc) = measure(3, &|| {
            // The rank test made afresh in every run (not taken from the run before).
            t.forget_matrix();
            let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
            black_box(construct_truss(&mut b, &t, &cases, &D).unwrap());
            assert!(b.all_passed());
        });
        println!(
            "| {k} | {} | {:.2} ms | {:.0} | {} | {:.2} ms | {} | {:.2} ms | {} | {:.2} ms | {} |",
            t.members.len(),
            tp / 1e6,
            tp / k as f64,
            mb(mp),
            tr / 1e6,
            mb(mr),
            ts / 1e6,
            mb(ms),
            tc / 1e6,
            mb(mc),
        );
    }
}
