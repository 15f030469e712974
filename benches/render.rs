//! What `render` costs per drawn object, the whole path a user runs for one scene: the
//! scene read and constructed on a drawing board, the SVG written (every label placed), and
//! the PNG (at 150 dpi) and PDF exports, each timed on its own, for every bundled scene. The
//! cost per object is each stage's time over the objects the board drew; the spread of that
//! cost across scenes says whether the cost follows what is drawn. `cargo bench --bench
//! render` prints the table in Markdown (median of 5 runs each).

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
    println!("| scene | objects | construct ms | SVG ms | PNG ms | PDF ms | µs an object (construct / SVG / PNG / PDF) |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    let mut per: [Vec<f64>; 4] = Default::default();
    let (mut all_objects, mut all_t) = (0usize, [0.0f64; 4]);
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
        let objects = board.object_count();
        let svg = figure(&meta, &board, None);
        let t = [
            median(5, || drop(black_box(construct()))),
            median(5, || drop(black_box(figure(&meta, &board, None)))),
            median(5, || drop(black_box(export::png(&svg, 150.0).unwrap()))),
            median(5, || drop(black_box(export::pdf(&svg).unwrap()))),
        ];
        let us: Vec<f64> = t.iter().map(|s| s * 1e6 / objects.max(1) as f64).collect();
        for k in 0..4 {
            per[k].push(us[k]);
            all_t[k] += t[k];
        }
        all_objects += objects;
        println!(
            "| {name} | {objects} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} / {:.1} / {:.1} / {:.1} |",
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
            all_t[k] * 1e6 / all_objects as f64
        );
    }
}
