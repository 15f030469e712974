//! What `render` costs per drawn object, the whole path a user runs for one scene: the
//! scene read and constructed on a drawing board, the SVG written (every label placed), and
//! the PNG (at 150 dpi) and PDF exports, each timed on its own, for every bundled scene. The
//! cost per object is each stage's time over the objects it handles (the construction every
//! object made, the SVG and the exports the objects drawn); the spread of that cost across
//! scenes says whether the cost follows what is drawn. `cargo bench --bench render` prints
//! the table in Markdown (median of 5 runs each).
//!
//! Then the batch: `graphostatik render scenes --out DIR` as a user runs it (the process, its
//! files written and synced), on one core and on two, SVG alone and with PNG and PDF, and the
//! speed-up two cores give (median of 5 runs; CPU time beside the wall time, since the
//! machine is shared).

use graphostatik::protocol::BoardConfig;
use graphostatik::render::{export, figure};
use graphostatik::scene::{AnyScene, ReadContext};
use std::hint::black_box;
use std::time::Instant;

/// The median wall time of `runs` calls (seconds).
fn median(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn main() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    println!("| scene | objects made / drawn | construct ms | SVG ms | PNG ms | PDF ms | µs an object (construct / SVG / PNG / PDF) |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    let mut per: [Vec<f64>; 4] = Default::default();
    let (mut all_objects, mut all_t) = ([0usize; 2], [0.0f64; 4]);
    for path in &paths {
        let text = std::fs::read_to_string(path).unwrap();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let construct = || {
            let scene = AnyScene::read(&text, &ReadContext::figure(&name)).unwrap();
            let p = scene.problem();
            let b = p.construct(BoardConfig::DRAWING).unwrap();
            (p.figure_meta(), b)
        };
        let (meta, board) = construct();
        // Constructing costs every object made; drawing and the exports those drawn (a part
        // constructed and checked but not drawn is left out of the figure).
        let objects = [board.object_count(), board.drawn_objects().count()];
        let svg = figure(&meta, &board, None);
        let t = [
            median(5, || drop(black_box(construct()))),
            median(5, || drop(black_box(figure(&meta, &board, None)))),
            median(5, || drop(black_box(export::png(&svg, 150.0).unwrap()))),
            median(5, || drop(black_box(export::pdf(&svg).unwrap()))),
        ];
        let per_object = |k: usize| objects[usize::from(k > 0)].max(1) as f64;
        let us: Vec<f64> = (0..4).map(|k| t[k] * 1e6 / per_object(k)).collect();
        for k in 0..4 {
            per[k].push(us[k]);
            all_t[k] += t[k];
        }
        all_objects[0] += objects[0];
        all_objects[1] += objects[1];
        println!(
            "| {name} | {} / {} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} / {:.1} / {:.1} / {:.1} |",
            objects[0],
            objects[1],
            t[0] * 1e3,
            t[1] * 1e3,
            t[2] * 1e3,
            t[3] * 1e3,
            us[0],
            us[1],
            us[2],
            us[3]
        );
    }
    let stat = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        (v[0], v[v.len() / 2], v[v.len() - 1])
    };
    println!();
    println!("| stage | µs an object, all scenes | median scene | fewest / most |");
    println!("|---|---:|---:|---|");
    for (k, stage) in ["construct", "SVG", "PNG (150 dpi)", "PDF"]
        .iter()
        .enumerate()
    {
        let (lo, mid, hi) = stat(&mut per[k]);
        println!(
            "| {stage} | {:.1} | {mid:.1} | {lo:.1} / {hi:.1} |",
            all_t[k] * 1e6 / all_objects[usize::from(k > 0)] as f64
        );
    }
    batch_on_cores(dir);
}

/// The wall and CPU time (user + system, of the process and its threads) of one run of the
/// command line.
fn run_once(args: &[&str]) -> (f64, f64) {
    let cpu = || {
        // The waited-for children's CPU time: cutime + cstime of /proc/self/stat, in ticks
        // of 1/100 s (Linux; NaN elsewhere).
        std::fs::read_to_string("/proc/self/stat")
            .ok()
            .and_then(|s| {
                let f: Vec<f64> = s
                    .rsplit(')')
                    .next()?
                    .split_whitespace()
                    .filter_map(|x| x.parse().ok())
                    .collect();
                // cutime and cstime: fields 16 and 17 of stat, 12 and 13 of the numbers after
                // the name (the state, field 3, is a letter).
                Some((f.get(12)? + f.get(13)?) / 100.0)
            })
            .unwrap_or(f64::NAN)
    };
    let (c0, s) = (cpu(), Instant::now());
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_graphostatik"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (s.elapsed().as_secs_f64(), cpu() - c0)
}

/// `render` of the bundled scenes on one and on two cores.
fn batch_on_cores(dir: &str) {
    let out = std::env::temp_dir().join(format!("gs-bench-render-{}", std::process::id()));
    let out_s = out.to_string_lossy().to_string();
    println!();
    println!("| render {dir} | 1 core: wall s (CPU s) | 2 cores: wall s (CPU s) | speed-up |");
    println!("|---|---:|---:|---:|");
    for formats in ["svg", "svg,png,pdf"] {
        let time = |jobs: &str| {
            let mut runs: Vec<(f64, f64)> = (0..5)
                .map(|_| {
                    let args = ["-q", "render", dir, "--out", &out_s, "--jobs", jobs];
                    run_once(&[&args[..], &["--format", formats]].concat())
                })
                .collect();
            runs.sort_by(|a, b| a.0.total_cmp(&b.0));
            runs[2]
        };
        let (one, two) = (time("1"), time("2"));
        println!(
            "| --format {formats} | {:.3} ({:.2}) | {:.3} ({:.2}) | {:.2}x |",
            one.0,
            one.1,
            two.0,
            two.1,
            one.0 / two.0
        );
    }
    let _ = std::fs::remove_dir_all(&out);
}
