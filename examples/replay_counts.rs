//! The drags of a slider or a point as the browser engine replays them (`web::replay_into`
//! with the construction kept, then `web::figure_patch_read` against the figure shown, read once as the page's engine
//! keeps it), for
//! counting instructions where a browser's wall time is too noisy:
//!
//! ```sh
//! cargo build --release --example replay_counts
//! valgrind --tool=callgrind target/release/examples/replay_counts \
//!     scenes/lh_j_compound_engine.json /speed/rpm 150 151 152 153
//! ```
//!
//! The scene is opened as the page opens it (the lines, the last page shown); each value
//! after the JSON pointer is then set in turn and replayed as a drag. Prints each drag's
//! wall time and the patch's length (for orientation).
use graphostatik::web::{figure_patch_read, replay_into, Ask, FigureLines};
use serde_json::Value;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [path, field, values @ ..] = args.as_slice() else {
        eprintln!("usage: replay_counts SCENE.json /json/pointer VALUE...");
        std::process::exit(2);
    };
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| {
        eprintln!("{path}: {e}");
        std::process::exit(2);
    });
    let mut scene: Value = serde_json::from_str(&text).expect("the scene is JSON");
    let mut kept = None;
    let (first, svg) = replay_into(&mut kept, &text, path, Ask::Lines);
    let answer: Value = serde_json::from_str(&first).expect("the answer is JSON");
    let page = answer["page_count"].as_u64().unwrap_or(1).saturating_sub(1) as usize;
    let mut shown = svg.unwrap_or_default();
    let mut shown_read = FigureLines::of(&shown);
    for v in values {
        let value: Value = serde_json::from_str(v).expect("each value is JSON");
        let Some(slot) = scene.pointer_mut(field) else {
            eprintln!("{field}: no such field in {path}");
            std::process::exit(2);
        };
        *slot = value;
        let t = Instant::now();
        let (json, svg) = replay_into(&mut kept, &scene.to_string(), path, Ask::Page(page));
        let read = svg.as_deref().map(FigureLines::of);
        let patch = svg.as_deref().zip(read.as_ref());
        let patch = patch.and_then(|(new, r)| figure_patch_read(&shown, &shown_read, new, r));
        let js = patch.map(|p| p.to_json()).unwrap_or_default();
        if let Ok(f) = std::env::var("PATCH_DUMP") {
            std::fs::write(format!("{f}.{v}.json"), &js).unwrap();
        }
        let bytes = js.len();
        println!(
            "{v}: {:.2} ms, answer {} bytes, patch {bytes} bytes",
            t.elapsed().as_secs_f64() * 1e3,
            json.len()
        );
        if let (Some(svg), Some(read)) = (svg, read) {
            (shown, shown_read) = (svg, read);
        }
    }
}
