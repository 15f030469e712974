//! The sheet layout: the parts of a figure ([`Part`]) set out in rows and columns.
//!
//! A procedure draws each part where it is convenient to construct it and names its row and
//! column; the layout then moves every row as a whole so that it stands [`PART_GAP`] under
//! the row above, and every column as a whole so that it stands [`PART_GAP`] right of the
//! column before. Moving whole rows and columns keeps what a row or a column shares: the base
//! line of a diagram through the centre of the crank beside it, the crank angle's axis under
//! diagrams stacked in one column. Two parts in different rows or columns cannot overlap, and
//! no gap between them is wider than the gap, so the sheet has no large empty regions of the
//! layout's making. Parts in one cell keep the positions they were constructed at.
//!
//! A part that is set out in its row alone ([`Part::packed`]: a truss's drawing, force
//! polygon and plan, of another size in every load case) belongs to no column: its top is
//! set level with its row's, and it stands a gap right of the part before it in the row.
//!
//! A part's extent is that of its solid drawing (points, segments, vectors, circles, arcs,
//! curves, tables; not the lines, which the figure clips to the reach of the solids) with
//! [`PART_MARGIN`] around it for the lettering.

use super::extent::extent_points;
use crate::kernel::Vector;
use crate::protocol::{Board, Geom, Part};
use std::collections::BTreeMap;

/// The gap between two rows or two columns of parts (mm of the sheet).
pub const PART_GAP: f64 = 12.0;

/// Room for the lettering around a part's solid drawing (mm).
pub const PART_MARGIN: f64 = 6.0;

/// One part of a figure and its extent on the sheet, `[min_x, min_y, max_x, max_y]` (mm, y
/// up), lettering room included.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartBox {
    /// Which part.
    pub part: Part,
    /// Its extent.
    pub bounds: [f64; 4],
}

/// The extent of every part a board draws in, in part order.
pub fn part_boxes(board: &Board) -> Vec<PartBox> {
    let mut boxes: BTreeMap<Part, [f64; 4]> = BTreeMap::new();
    let mut pts = Vec::new();
    for o in board.objects() {
        if matches!(o.geom, Geom::Line { .. }) {
            continue;
        }
        let Some(step) = board.step(o.step) else {
            continue;
        };
        pts.clear();
        extent_points(o, &mut pts);
        for p in pts.iter().filter(|p| p.x.is_finite() && p.y.is_finite()) {
            let b = boxes.entry(step.part).or_insert([p.x, p.y, p.x, p.y]);
            *b = [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)];
        }
    }
    (boxes.into_iter())
        .map(|(part, [x0, y0, x1, y1])| PartBox {
            part,
            bounds: [
                x0 - PART_MARGIN,
                y0 - PART_MARGIN,
                x1 + PART_MARGIN,
                y1 + PART_MARGIN,
            ],
        })
        .collect()
}

/// How many pairs of `boxes` overlap (what the sheet layout is to leave none of).
pub fn overlapping_pairs(boxes: &[PartBox]) -> usize {
    let overlap =
        |a: &[f64; 4], b: &[f64; 4]| a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
    (boxes.iter().enumerate())
        .map(|(i, a)| {
            (boxes[i + 1..].iter())
                .filter(|b| overlap(&a.bounds, &b.bounds))
                .count()
        })
        .sum()
}

/// How far each part set out in its row alone ([`Part::packed`]) is moved: up or down to
/// the highest top of its row's parts, and across to a gap right of the part before it in
/// the row (the first at the sheet's left edge); `boxes` moved with them.
fn packed(boxes: &mut [PartBox]) -> BTreeMap<Part, Vector> {
    let left = boxes
        .iter()
        .map(|b| b.bounds[0])
        .fold(f64::INFINITY, f64::min);
    let mut tops: BTreeMap<u16, f64> = BTreeMap::new();
    for b in boxes.iter() {
        let top = tops.entry(b.part.row).or_insert(b.bounds[3]);
        *top = top.max(b.bounds[3]);
    }
    let mut shift = BTreeMap::new();
    let mut right: BTreeMap<u16, f64> = BTreeMap::new();
    // Boxes are in part order: by row, then column.
    for b in boxes.iter_mut().filter(|b| b.part.packed) {
        let cursor = right.get(&b.part.row).map_or(left, |r| r + PART_GAP);
        let d = Vector::new(cursor - b.bounds[0], tops[&b.part.row] - b.bounds[3]);
        b.bounds = [
            b.bounds[0] + d.x,
            b.bounds[1] + d.y,
            b.bounds[2] + d.x,
            b.bounds[3] + d.y,
        ];
        right.insert(b.part.row, b.bounds[2]);
        shift.insert(b.part, d);
    }
    shift
}

/// How far each row (down) and each column (across) is moved: `(row offsets in y, column
/// offsets in x)`, the first row and column left where they are.
fn offsets(boxes: &[PartBox]) -> (BTreeMap<u16, f64>, BTreeMap<u16, f64>) {
    let mut rows: BTreeMap<u16, [f64; 2]> = BTreeMap::new();
    let mut cols: BTreeMap<u16, [f64; 2]> = BTreeMap::new();
    for b in boxes {
        let [x0, y0, x1, y1] = b.bounds;
        let r = rows.entry(b.part.row).or_insert([y0, y1]);
        *r = [r[0].min(y0), r[1].max(y1)];
        // A part set out in its row alone is in no column.
        if !b.part.packed {
            let c = cols.entry(b.part.col).or_insert([x0, x1]);
            *c = [c[0].min(x0), c[1].max(x1)];
        }
    }
    let mut dy = BTreeMap::new();
    let mut bottom: Option<f64> = None;
    for (row, [y0, y1]) in rows {
        let d = bottom.map_or(0.0, |b| b - PART_GAP - y1);
        dy.insert(row, d);
        bottom = Some(y0 + d);
    }
    let mut dx = BTreeMap::new();
    let mut right: Option<f64> = None;
    for (col, [x0, x1]) in cols {
        let d = right.map_or(0.0, |r| r + PART_GAP - x0);
        dx.insert(col, d);
        right = Some(x1 + d);
    }
    (dy, dx)
}

/// The board with its parts set out, or `None` where it draws in one part only (then it is
/// drawn as constructed).
pub fn laid_out(board: &Board) -> Option<Board> {
    let mut boxes = part_boxes(board);
    if boxes.len() < 2 {
        return None;
    }
    let own = packed(&mut boxes);
    let (dy, dx) = offsets(&boxes);
    let mut moved = board.clone();
    moved.move_parts(|p| {
        let row = Vector::new(0.0, dy.get(&p.row).copied().unwrap_or(0.0));
        match own.get(&p) {
            Some(v) => v + row,
            None => Vector::new(dx.get(&p.col).copied().unwrap_or(0.0), 0.0) + row,
        }
    });
    Some(moved)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::protocol::{Note, Role, Topic};

    #[test]
    fn rows_and_columns_are_set_a_gap_apart_and_keep_their_alignment() {
        let n = Note::new("p", Topic::Custom("layout"));
        let mut b = Board::recording();
        // Two rows that overlap, and a column 300 mm away from the first.
        for (row, y) in [(0u16, 0.0), (1, 10.0)] {
            b.set_part(Part::at(row, 0));
            b.point(Point::new(0.0, y), Role::Given, n.clone());
            b.point(Point::new(40.0, y + 20.0), Role::Given, n.clone());
            b.set_part(Part::at(row, 1));
            b.point(Point::new(340.0, y), Role::Given, n.clone());
        }
        let moved = laid_out(&b).expect("four parts");
        assert!(
            overlapping_pairs(&part_boxes(&b)) > 0,
            "the rows overlap as drawn"
        );
        let boxes = part_boxes(&moved);
        assert_eq!(overlapping_pairs(&boxes), 0, "{boxes:?}");
        let at = |k: usize| match moved.objects()[k].geom {
            Geom::Point { at } => at,
            _ => unreachable!(),
        };
        // The first part stays; the second column comes within the gap of the first.
        assert_eq!(at(0), Point::new(0.0, 0.0));
        let gap = (at(2).x - PART_MARGIN) - (40.0 + PART_MARGIN);
        assert!((gap - PART_GAP).abs() < 1e-9, "{gap}");
        // The second row stands a gap under the first, its two columns level with each other.
        assert!((at(3).y - at(5).y).abs() < 1e-9);
        let gap = (0.0 - PART_MARGIN) - (at(4).y + PART_MARGIN);
        assert!((gap - PART_GAP).abs() < 1e-9, "{gap}");
    }

    #[test]
    fn packed_parts_stand_in_their_own_row_tops_level_a_gap_apart() {
        let n = Note::new("p", Topic::Custom("layout"));
        let mut b = Board::recording();
        // Two rows of three parts, each constructed at the origin: the first row's parts wide,
        // the second's narrow; tops at different heights.
        for (row, w) in [(0u16, 200.0), (1, 20.0)] {
            for col in 0..3 {
                b.set_part(Part::packed(row, col));
                b.point(
                    Point::new(0.0, -10.0 * f64::from(col)),
                    Role::Given,
                    n.clone(),
                );
                b.point(Point::new(w, -40.0), Role::Given, n.clone());
            }
        }
        let moved = laid_out(&b).expect("six parts");
        let boxes = part_boxes(&moved);
        assert_eq!(overlapping_pairs(&boxes), 0, "{boxes:?}");
        for row in boxes.chunks(3) {
            // Tops level, and each part a gap right of the one before, in every row alone.
            assert!(row
                .iter()
                .all(|b| (b.bounds[3] - row[0].bounds[3]).abs() < 1e-9));
            for pair in row.windows(2) {
                let gap = pair[1].bounds[0] - pair[0].bounds[2];
                assert!((gap - PART_GAP).abs() < 1e-9, "{gap}");
            }
        }
        // The narrow row is not spread to the wide row's columns.
        assert!(boxes[5].bounds[2] < boxes[1].bounds[2], "{boxes:?}");
    }

    #[test]
    fn a_figure_of_one_part_is_drawn_as_constructed() {
        let n = Note::new("p", Topic::Custom("layout"));
        let mut b = Board::recording();
        b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        b.point(Point::new(500.0, 0.0), Role::Given, n);
        assert!(laid_out(&b).is_none());
    }
}
