//! What `graphostatik check` costs, the whole path in process: the scene's text parsed and
//! validated (the rank test included), the construction with every check, and the check
//! table written. Trusses (Warren girders, a load at every bottom joint) of 10 to 100,000
//! joints and beams of 10 to 1,000,000 point loads, on two boards:
//!
//! - figure: the board `render` and `steps` use, every step, object and caption recorded
//!   (scenes larger than a figure may hold are refused: "-");
//! - checks only: the board `check` and `forces` use, which keeps the checks and their
//!   bounds and not the drawing (`Setup::checks_only`): the same table, byte for byte.
//!
//! Peak memory is the largest number of heap bytes live during a run (a counting
//! allocator), less what was live before it (the scene's text). `cargo bench --bench check`
//! prints the tables in Markdown.

use graphostatik::protocol::BoardConfig;
use graphostatik::render::check_table_text;
use graphostatik::scene::{AnyScene, ReadContext};
use std::hint::black_box;
use std::time::Instant;

#[path = "support/counting.rs"]
mod counting;

#[global_allocator]
static A: counting::Counting = counting::Counting;

/// A Warren girder of about `joints` joints as scene text.
fn warren(joints: usize) -> String {
    let n = (joints.max(5) - 1) / 2;
    let mut js = Vec::new();
    for i in 0..=n {
        js.push(format!(r#"{{"name":"B{i}","at_m":[{},0]}}"#, 2 * i));
    }
    for i in 0..n {
        js.push(format!(r#"{{"name":"T{i}","at_m":[{},2]}}"#, 2 * i + 1));
    }
    let mut ms = Vec::new();
    let mut add = |a: String, b: String| {
        ms.push(format!(
            r#"{{"name":"{}","joints":["{a}","{b}"]}}"#,
            ms.len() + 1
        ))
    };
    for i in 0..n {
        add(format!("B{i}"), format!("B{}", i + 1));
        add(format!("B{i}"), format!("T{i}"));
        add(format!("T{i}"), format!("B{}", i + 1));
        if i + 1 < n {
            add(format!("T{i}"), format!("T{}", i + 1));
        }
    }
    let loads: Vec<String> = (1..n)
        .map(|i| format!(r#"{{"joint":"B{i}","kg":{}}}"#, 1000 + 100 * (i % 7)))
        .collect();
    format!(
        r#"{{"procedure":"truss","title":"Warren girder","joints":[{}],"members":[{}],
        "supports":[{{"joint":"B0","kind":"pinned"}},{{"joint":"B{n}","kind":"roller","direction_deg":90}}],
        "load_cases":[{{"name":"P","loads":[{}]}}]}}"#,
        js.join(","),
        ms.join(","),
        loads.join(",")
    )
}

/// A beam on two supports 8 m apart under `n` point loads, every diagram asked for.
fn beam(n: usize) -> String {
    let loads: Vec<String> = (0..n)
        .map(|i| {
            let x = 0.1 + 7.8 * (i as f64 + 0.5) / n as f64;
            format!(r#"{{"x_m":{x},"kg":{}}}"#, 100 + 10 * (i % 7))
        })
        .collect();
    format!(
        r#"{{"procedure":"beam","title":"many loads","beam":{{"supports_m":[0,8]}},
        "point_loads":[{}],"outputs":["reactions","moment_area","shear_diagram"]}}"#,
        loads.join(",")
    )
}

/// The whole check in process: parse, validate, construct, table. `None` if the scene is
/// refused on this board.
fn check(text: &str, checks_only: bool) -> Option<usize> {
    let (ctx, config) = if checks_only {
        (
            ReadContext::checks("bench.json", graphostatik::io::available_memory()),
            BoardConfig::CHECKS,
        )
    } else {
        (ReadContext::figure("bench.json"), BoardConfig::DRAWING)
    };
    let scene = AnyScene::read(text, &ctx).ok()?;
    let board = scene.problem().construct(config).ok()?;
    assert!(board.all_passed());
    Some(black_box(check_table_text(&board)).len())
}

/// Median wall time (ms) and peak heap (MB) of the whole check, over `reps` runs.
fn measure(text: &str, checks_only: bool, reps: usize) -> Option<(f64, f64)> {
    let mut times = Vec::new();
    let mut peak = 0;
    for _ in 0..reps {
        let base = counting::start();
        // Every run from the start: each reads its own truss, whose LU and rank test are
        // made afresh (they travel with the truss, not from one run to the next).
        let t = Instant::now();
        check(text, checks_only)?;
        times.push(t.elapsed().as_secs_f64() * 1e3);
        peak = peak.max(counting::peak_above(base));
    }
    times.sort_by(f64::total_cmp);
    Some((times[reps / 2], peak as f64 / 1e6))
}

fn row(label: String, text: &str, reps: usize) {
    let cell = |m: Option<(f64, f64)>| match m {
        Some((t, p)) => format!("{t:.2} ms | {p:.1} MB"),
        None => "- | -".to_string(),
    };
    println!(
        "| {label} | {:.1} MB | {} | {} |",
        text.len() as f64 / 1e6,
        cell(measure(text, false, reps)),
        cell(measure(text, true, reps)),
    );
}

fn main() {
    println!("| truss | scene text | figure board | peak | checks only | peak |");
    println!("|---|---:|---:|---:|---:|---:|");
    for joints in [11usize, 101, 1001, 10_001, 99_999] {
        let reps = if joints > 10_000 { 3 } else { 7 };
        row(format!("{joints} joints"), &warren(joints), reps);
    }
    println!();
    println!("| beam | scene text | figure board | peak | checks only | peak |");
    println!("|---|---:|---:|---:|---:|---:|");
    for n in [10usize, 1000, 100_000, 1_000_000] {
        let reps = if n > 10_000 { 3 } else { 7 };
        row(format!("{n} loads"), &beam(n), reps);
    }
}
