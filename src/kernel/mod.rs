//! The geometric kernel: ruler-and-compass geometry in f64, no drawing, no mechanics.
//!
//! - [`primitives`]: points, lines, segments, circles, arcs;
//! - [`intersect`]: line∩line, line∩circle, circle∩circle, each a typed outcome with its
//!   [`Conditioning`];
//! - [`construct`]: parallels, perpendiculars, laying off, equal division, measuring;
//! - [`angle`]: degrees with exact quadrant values;
//! - [`tolerance`]: every tolerance, named.

pub mod angle;
pub mod conditioning;
pub mod construct;
pub mod intersect;
pub mod primitives;
pub mod tolerance;

pub use conditioning::Conditioning;
pub use intersect::{
    intersect_circle_circle, intersect_line_circle, intersect_line_line, Branch, CircleCircle,
    LineCircle, LineLine,
};
pub use primitives::{cross, Arc, Circle, Line, Point, PrimitiveError, Segment, Vector};
pub use tolerance::Tolerance;
