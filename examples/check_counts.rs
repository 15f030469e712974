//! One `check` of a scene file, the whole path in process (read, parse, validation with the
//! rank test, the construction with every check on a board that keeps only its checks, the
//! table), for counting instructions where wall time is too noisy:
//!
//! ```sh
//! cargo build --release --example check_counts
//! valgrind --tool=callgrind target/release/examples/check_counts girder.json
//! ```
//!
//! Prints the table's length and the phases' instruction-free wall times (for orientation).
use graphostatik::protocol::BoardConfig;
use std::time::Instant;

fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: check_counts SCENE.json");
        std::process::exit(2);
    };
    let t0 = Instant::now();
    let scene = match graphostatik::scene::AnyScene::load_for_checks(
        std::path::Path::new(&path),
        graphostatik::io::available_memory(),
    ) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let problem = scene.problem();
    let t1 = Instant::now();
    let board = problem
        .construct(BoardConfig::CHECKS)
        .expect("the scene constructs");
    let t2 = Instant::now();
    let table = graphostatik::render::check_table_text(&board);
    let t3 = Instant::now();
    let ms = |a: Instant, b: Instant| (b - a).as_secs_f64() * 1e3;
    println!(
        "read {:.2} ms, construct {:.2} ms, table {:.2} ms ({} bytes, {} checks)",
        ms(t0, t1),
        ms(t1, t2),
        ms(t2, t3),
        table.len(),
        board.checks().count()
    );
}
