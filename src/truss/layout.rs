//! Where a case's parts are constructed: each in its own frame, at the origin, as a part of
//! the sheet ([`Part`]): the truss drawing (Bauplan) with its loads and funicular polygon,
//! the reactions' force polygon, and the Cremona plan with its table, side by side in the
//! case's row. The sheet layout sets the rows and columns out afterwards, so no case is
//! constructed twice to measure where it will go, and the checks' error bounds follow the
//! construction's own coordinates, not where a part stands on the sheet.

use super::plan::*;
use crate::kernel::Point;
use crate::protocol::{Board, Part};

/// The column of the truss drawing, its loads, the funicular polygon and the closing line.
pub(super) const TRUSS: u16 = 0;
/// The column of the reactions' force polygon.
pub(super) const POLYGON: u16 = 1;
/// The column of the Cremona plan (or the joint polygons) and its table.
pub(super) const PLAN: u16 = 2;

/// The part of column `col` in the row the board is drawing in, set out in its row alone
/// ([`Part::packed`]).
pub(super) fn part_of(b: &Board, col: u16) -> Part {
    Part::packed(b.part().row, col)
}

/// Where the next steps draw: column `col` of the row the board is drawing in.
pub(super) fn column(b: &mut Board, col: u16) {
    b.set_part(part_of(b, col));
}

/// Runs `f` drawing in column `col` of the current row, then draws where it drew before: an
/// object of one part constructed among the steps of another (Ritter's cut of two members in
/// the truss drawing, found while the plan is drawn).
pub(super) fn in_column<R>(b: &mut Board, col: u16, f: impl FnOnce(&mut Board) -> R) -> R {
    let before = b.part();
    column(b, col);
    let r = f(b);
    b.set_part(before);
    r
}

pub(super) struct CaseOut {
    pub(super) result: CaseResult,
    /// The bounding box [x0, y0, x1, y1] of the truss drawing (its loads and funicular
    /// polygon included), in its own frame: where the case's name goes.
    pub(super) truss_box: [f64; 4],
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

/// Room between a load case's name and the top of its truss drawing (mm).
pub(super) const HEADING_MM: f64 = 6.0;

/// Room the names of the top joints take above them (mm): a label's offset and its letters'
/// height. A case's name stands above them where no load rises higher (LH Abb. 19's dead
/// load hangs from the bottom chord).
pub(super) const JOINT_NAMES_MM: f64 = 4.5;
