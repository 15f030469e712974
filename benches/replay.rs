//! What one replay of a drag costs natively: `web::replay_page` (read the scene, construct
//! it on a drawing board, draw the figure with its labels placed, the current step's item,
//! the checks and handles, the answer as JSON), the call the browser engine makes on every
//! pointer move, for every bundled scene. `cargo bench --bench replay` prints the table in
//! Markdown (median of 15 replays after 3 to warm up; the answer's size in bytes);
//! `cargo bench --bench replay -- otto` only the scenes whose name holds `otto`.

use std::hint::black_box;
use std::time::Instant;

fn main() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    // `cargo bench` passes `--bench` to the binary: the first other argument is the filter.
    let only = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .filter(|p| {
            only.as_ref()
                .is_none_or(|o| p.to_string_lossy().contains(o.as_str()))
        })
        .collect();
    paths.sort();
    println!("| scene | answer bytes | replay median ms | worst ms |");
    println!("|---|---:|---:|---:|");
    let mut total = 0.0;
    for path in &paths {
        let text = std::fs::read_to_string(path).unwrap();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let origin = format!("{name}.json");
        let replay = || graphostatik::web::replay_page(&text, &origin, Some(0));
        let bytes = replay().len();
        for _ in 0..3 {
            black_box(replay());
        }
        let mut t: Vec<f64> = (0..15)
            .map(|_| {
                let s = Instant::now();
                black_box(replay());
                s.elapsed().as_secs_f64() * 1e3
            })
            .collect();
        t.sort_by(f64::total_cmp);
        total += t[t.len() / 2];
        println!(
            "| {name} | {bytes} | {:.2} | {:.2} |",
            t[t.len() / 2],
            t[t.len() - 1]
        );
    }
    println!(
        "\nsum of the medians: {total:.1} ms over {} scenes",
        paths.len()
    );
}
