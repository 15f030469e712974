//! Intersections, one file per pair of curve types: `line_line.rs`, `line_circle.rs`,
//! `circle_circle.rs` (the naming rule of dimforge/parry's `query/<op>/<op>_<a>_<b>.rs`).
//!
//! Each returns an enum that names the geometric case (a point, two points, tangent,
//! parallel, coincident, none) and, where there is a point, the [`Conditioning`] of the cut.
//! No case is ever represented by NaN. Where there are two points, [`Branch`] picks one, and
//! the construction step records which.

mod circle_circle;
mod line_circle;
mod line_line;

pub use circle_circle::{intersect_circle_circle, CircleCircle};
pub use line_circle::{intersect_line_circle, LineCircle};
pub use line_line::{intersect_line_line, LineLine};

use super::primitives::Point;
use serde::Serialize;

#[allow(unused_imports)]
use super::conditioning::Conditioning;

/// Which of two intersection points to take (tkz-euclide's `near`, GeoGebra's
/// `AlgoIntersectSingle` reference point).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Branch {
    /// The point nearer to the given point.
    Near(Point),
    /// The point farther from the given point.
    Far(Point),
    /// The first point along the line's direction (line–circle only).
    First,
    /// The second point along the line's direction (line–circle only).
    Second,
}

impl Branch {
    /// Picks one of two points `[first, second]`. Ties (equal distances) take the first,
    /// so the choice is deterministic.
    pub fn pick(&self, pts: [Point; 2]) -> (Point, usize) {
        let idx = match *self {
            Branch::First => 0,
            Branch::Second => 1,
            Branch::Near(q) => {
                if (pts[1] - q).norm_squared() < (pts[0] - q).norm_squared() {
                    1
                } else {
                    0
                }
            }
            Branch::Far(q) => {
                if (pts[1] - q).norm_squared() > (pts[0] - q).norm_squared() {
                    1
                } else {
                    0
                }
            }
        };
        (pts[idx], idx)
    }

    /// A short description for the protocol ("near (x, y)").
    pub fn describe(&self) -> String {
        match self {
            Branch::Near(q) => format!("near ({}, {})", fmt3(q.x), fmt3(q.y)),
            Branch::Far(q) => format!("far from ({}, {})", fmt3(q.x), fmt3(q.y)),
            Branch::First => "first along the line".to_string(),
            Branch::Second => "second along the line".to_string(),
        }
    }
}

fn fmt3(x: f64) -> String {
    crate::fmt::num(x, 3)
}
