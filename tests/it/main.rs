//! The integration tests, one crate: each module was a test binary of its own, and each
//! linked the whole library (29 links after every change to it). Run one module with
//! `cargo test --test it truss::`, one test by its name.

mod accuracy;
mod architecture;
mod bad_input;
mod beams;
mod book_values;
mod browser;
mod centroid;
mod checks_only;
mod combustion;
mod crank_closed_form;
mod dynamics;
mod export;
mod figures;
mod force_system;
mod fuzz_scenes;
mod injection;
mod inkscape;
mod kernel_fuzz;
mod lazy_evaluation;
mod local_frame;
mod mechanisms;
mod paper;
mod properties;
mod pump;
mod scale_free;
mod schema;
mod serve_load;
mod shaft;
mod snapshots;
mod support;
mod truss;
