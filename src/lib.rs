//! # graphostatik
//!
//! Digital *Graphostatik*: the ruler-and-compass procedures of classic German engineering
//! textbooks, replayed on a geometric kernel, recorded step by step, drawn as SVG layers and
//! checked against the closed form each step stands for.
//!
//! Layers, each using only the ones before it:
//!
//! 1. [`kernel`] — geometry (points, lines, circles, intersections with conditioning);
//! 2. [`protocol`] — the board on which every kernel operation is recorded as a step;
//! 3. the procedures: [`crank`] — the slider-crank (LH II, KG XIV B); [`statics`] — force
//!    and funicular polygons, beams, centroids, shafts (LH I A, C); [`truss`] — determinacy,
//!    reactions, Cremona plans, Ritter sections, counter-diagonals, envelopes (LH I B);
//! 4. [`scene`] — the JSON scene format, its validation and its mapping to procedures;
//! 5. [`render`] — textbook-style SVG, one layer per step, walk-through pages, the check
//!    table and the tables of member forces;
//! 6. the `graphostatik` command line.
#![warn(missing_docs)]

pub mod crank;
pub mod fmt;
pub mod io;
pub mod kernel;
pub mod prelude;
pub mod protocol;
pub mod render;
pub mod scene;
pub mod statics;
pub mod truss;
