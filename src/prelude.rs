//! The names a construction in Rust needs, in one `use`:
//!
//! ```
//! use graphostatik::prelude::*;
//! ```
//!
//! Geometry ([`Point`], [`Vector`], [`Line`], [`Circle`]), the board and what is written on it
//! ([`Board`], [`Note`], [`Label`], [`Role`], [`Topic`], [`Scale`]), figure metadata, the truss
//! model with its builder, the scene of any procedure, and the SVG renderer.

pub use crate::kernel::{Branch, Circle, Line, Point, Segment, Vector};
pub use crate::protocol::{
    note, Board, Check, ConstructionError, Cut, Drawn, FigureMeta, Label, Mark, Note, Role, Scale,
    ScaleBar, Topic, H,
};
pub use crate::render::figure;
pub use crate::scene::{AnyProblem, AnyScene, Procedure};
pub use crate::truss::cremona::TrussDrawing;
pub use crate::truss::{LoadCase, Truss};
