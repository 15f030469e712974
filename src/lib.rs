//! # graphostatik
//!
//! Digital *Graphostatik*: the ruler-and-compass procedures of classic German engineering
//! textbooks, replayed on a geometric kernel, recorded step by step, drawn as SVG layers and
//! checked against the closed form each step stands for.
//!
//! A truss built in code by the books' names, its Cremona plan drawn and every member checked
//! against the joint equations (LH I B.4, Abb. 17; `examples/truss_in_code.rs`):
//!
//! ```
//! use graphostatik::prelude::*;
//! let truss = Truss::builder()
//!     .joint("I", (0.0, 0.0)).joint("II", (4.0, 0.0)).joint("III", (8.0, 0.0))
//!     .joint("IV", (2.0, 1.0)).joint("V", (4.0, 2.0)).joint("VI", (6.0, 1.0))
//!     .member("1", "I", "IV").member("2", "IV", "V").member("3", "V", "VI")
//!     .member("4", "VI", "III").member("5", "I", "II").member("6", "II", "III")
//!     .member("7", "IV", "II").member("8", "V", "II").member("9", "VI", "II")
//!     .pin("I").roller("III", (0.0, 1.0))
//!     .build()?;
//! let p = (0.0, -1000.0);
//! let case = truss.load_case("dead load", &[("IV", p), ("V", p), ("VI", p)])?;
//! let mut board = Board::recording();
//! let results = truss.cremona(&mut board, &[case])?;
//! assert!(board.all_passed());
//! assert!((results[0].members[4].force - 3000.0).abs() < 1e-9); // the tie I–II: +3000 kg
//! let svg = figure(&FigureMeta::titled("A roof truss"), &board, None);
//! assert!(svg.contains("inkscape:groupmode=\"layer\""));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! A construction of one's own (`examples/bisector.rs`) uses the same [`protocol::Board`]
//! with its own captions ([`protocol::Note::new`]) and topic ([`protocol::Topic::Custom`]).
//!
//! Layers, each using only the ones before it:
//!
//! 1. [`kernel`]: geometry (points, lines, circles, intersections with conditioning, every
//!    tolerance);
//! 2. [`protocol`]: the board on which every kernel operation is recorded as a step, the
//!    typed construction errors, the figure metadata and scale bars;
//! 3. the procedures: [`crank`], the slider-crank (LH II, KG XIV B); [`statics`], force
//!    and funicular polygons, beams, centroids, shafts (LH I A, C); [`truss`], determinacy,
//!    reactions, Cremona plans, Ritter sections, counter-diagonals, envelopes (LH I B);
//!    [`dynamics`], an engine's net pressure, turning force and flywheel (LH II, KG XIV B.4);
//!    [`mechanisms`], the other mechanisms of KG XIV (scotch yoke, slotted link, offset
//!    crank, four-bar);
//! 4. [`scene`]: the JSON scene format, the [`scene::Procedure`] trait and its registry;
//! 5. [`render`]: textbook-style SVG, one layer per step, the walk-through page, the check
//!    table, the tables of member forces, and PNG, PDF and TikZ exports (feature `export`);
//! 6. [`web`], the engine as a browser page calls it (scene JSON in, page JSON out; the
//!    crate `graphostatik-wasm` compiles it to WebAssembly), [`site`], the static site
//!    around it, `serve`, the live preview, and the `graphostatik` command line (feature
//!    `cli`, on by default).
//!
//! [`prelude`] gathers what a construction in Rust needs; [`fmt`], [`io`] and [`jobs`] are
//! helpers (fixed number formatting, atomic writes, jobs on every core).
#![warn(missing_docs)]

pub mod crank;
pub mod dynamics;
pub mod fmt;
pub mod io;
pub mod jobs;
pub mod kernel;
pub mod mechanisms;
pub mod prelude;
pub mod protocol;
pub mod render;
pub mod scene;
#[cfg(feature = "cli")]
pub mod serve;
pub mod site;
pub mod statics;
pub mod truss;
pub mod web;
