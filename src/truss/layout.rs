//! The two-pass layout of a case: a dry run measures the truss drawing, the reactions' force
//! polygon and the plan; the real run draws them side by side in a row.

use super::plan::*;
use crate::kernel::Point;

#[derive(Clone, Copy)]
pub(super) struct Layout {
    pub(super) truss: Point,
    pub(super) polygon: Point,
    pub(super) plan: Point,
}

pub(super) struct CaseOut {
    pub(super) result: CaseResult,
    /// Bounding boxes [x0, y0, x1, y1] of the truss drawing, the reactions' force polygon,
    /// and the Cremona plan, relative to their origins.
    pub(super) boxes: [[f64; 4]; 3],
}

pub(crate) fn grow(bx: &mut [f64; 4], p: Point, o: Point) {
    let (x, y) = (p.x - o.x, p.y - o.y);
    bx[0] = bx[0].min(x);
    bx[1] = bx[1].min(y);
    bx[2] = bx[2].max(x);
    bx[3] = bx[3].max(y);
}

pub(crate) const EMPTY: [f64; 4] = [
    f64::INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NEG_INFINITY,
];
