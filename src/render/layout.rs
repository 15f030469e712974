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
//! Where a row of such parts would make one long strip (LH Aufgabe 3: the truss, its force
//! polygon and four joint polygons, 713 × 152 mm), the row is tried wrapped at widths
//! around the long side of an A-series sheet of the parts' area, a row's first two parts
//! kept side by side; a wrapped layout is taken where it fits a sheet more than
//! [`WRAP_GAIN`] smaller for a bounding box at most [`WRAP_GROWTH`] larger (391 × 284 mm).
//!
//! A free part ([`Part::free`]: a table of results, which shares no axis with anything) is
//! set last, in part order, where it grows the sheet least. First inside the sheet, where
//! its box meets no stroke, point or table of the parts set before it
//! (`ink::inner_hole`: LH Abb. 52's table of the book's values goes into the empty
//! upper left that the pole B₁ high over the crank leaves), of such places the one nearest
//! to where its own row and column would put it; else in a hole the rows and columns leave
//! (beside a short row, under a short column) where its box stands a gap clear of every
//! part and crosses no drawn line. The Diesel engine's table of T_m moves from a row of its
//! own under the turning-force diagram to the room beside it (KG Abb. 1058: 200 → 165 mm).

//! A part's extent is that of its solid drawing (points, segments, vectors, circles, arcs,
//! curves, tables; not the lines, which the figure clips to the reach of the solids) with
//! [`PART_MARGIN`] around it for the lettering.

use super::extent::extent_points;
use super::ink::{inner_hole, part_marks, Mark};
use super::style::{CLIP_REACH, LINE_OVERSHOOT};
use crate::kernel::{Point, Vector};
use crate::protocol::{Board, ConstructionError, Geom, Part, StepKind};
use std::collections::BTreeMap;

/// The gap between two rows or two columns of parts (mm of the sheet).
pub const PART_GAP: f64 = 12.0;

/// Places for a free part whose sheets differ in area by less than this share count as
/// equal, and the one nearer to its row and column is taken.
pub const SHEET_GROWTH_TIE: f64 = 0.01;

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

/// The extent of every part a board draws in, in part order. Where one part is drawn
/// beside free parts only (tables, which do not widen the reach of the lines), its extent
/// is what the figure draws of it: its solid drawing and the points it constructs within
/// reach of that (12 % of its larger side, as the figure clips lines; a point farther out,
/// an intersection of nearly parallel rays, is left off the sheet). Otherwise every point
/// counts: the figure's reach is that of all its parts, and a line of one part may be
/// drawn on to a far point of its own.
pub fn part_boxes(board: &Board) -> Vec<PartBox> {
    let mut grid = (board.drawn_objects())
        .filter_map(|o| board.step(o.step))
        .filter(|s| !s.part.free)
        .map(|s| s.part);
    let first = grid.next();
    let alone = first.is_some() && grid.all(|p| Some(p) == first);
    let grow = |boxes: &mut BTreeMap<Part, [f64; 4]>, part: Part, pts: &[Point]| {
        for p in pts.iter().filter(|p| p.x.is_finite() && p.y.is_finite()) {
            let b = boxes.entry(part).or_insert([p.x, p.y, p.x, p.y]);
            *b = [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)];
        }
    };
    let constructed = |o: &crate::protocol::Object| {
        matches!(o.geom, Geom::Point { .. })
            && board
                .step(o.step)
                .is_some_and(|s| s.kind != StepKind::Given)
    };
    let mut solid: BTreeMap<Part, [f64; 4]> = BTreeMap::new();
    let mut pts = Vec::new();
    for o in board.drawn_objects() {
        if matches!(o.geom, Geom::Line { .. }) || constructed(o) {
            continue;
        }
        if let Some(step) = board.step(o.step) {
            pts.clear();
            extent_points(o, &mut pts);
            grow(&mut solid, step.part, &pts);
        }
    }
    let mut boxes = solid.clone();
    for o in board.drawn_objects().filter(|o| constructed(o)) {
        let (Some(step), Geom::Point { at }) = (board.step(o.step), &o.geom) else {
            continue;
        };
        let near = !alone
            || solid.get(&step.part).is_none_or(|b| {
                let reach = CLIP_REACH * (b[2] - b[0]).max(b[3] - b[1]) + LINE_OVERSHOOT;
                at.x >= b[0] - reach
                    && at.x <= b[2] + reach
                    && at.y >= b[1] - reach
                    && at.y <= b[3] + reach
            });
        if near {
            grow(&mut boxes, step.part, &[*at]);
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

/// Whether every part `board` draws fits within `max_mm` across on the sheet, by the extent
/// [`part_boxes`] gives it. The limits of a scene are checked on its inputs and scales, but a
/// part derived from them can reach far past them near a degenerate case (a truss joint
/// 1e-10 m off the line of its members: a force plan 250,000 km long). Every command that
/// draws asks this before it draws; a construction studied for its numbers (`check`,
/// `protocol`, a hard case in a test) does not.
///
/// # Errors
/// The widest part past `max_mm`, by the step that begins it, as
/// [`ConstructionError::Unsupported`] for the input `figure`.
pub fn parts_within(board: &Board, max_mm: f64) -> Result<(), ConstructionError> {
    let widest = (part_boxes(board).into_iter())
        .map(|b| {
            let [x0, y0, x1, y1] = b.bounds;
            ((x1 - x0).max(y1 - y0), b.part)
        })
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let Some((mm, part)) = widest.filter(|(mm, _)| *mm > max_mm) else {
        return Ok(());
    };
    let first = board.steps().iter().find(|s| s.part == part);
    Err(ConstructionError::Unsupported {
        input: "figure".into(),
        reason: format!(
            "its part begun by step {} ({}) would be {} m across on the sheet, more than the {} \
             m a figure may take: an input is near a degenerate case (a joint nearly on the \
             line of its members, a support's direction nearly along the load, forces nearly \
             in balance, a speed far beyond the scene's own) and drives it that far; move it \
             off (graphostatik check takes the scene: it draws nothing)",
            first.map_or(0, |s| s.id.0),
            crate::fmt::clip(first.map_or("", |s| &s.caption), 80),
            if mm < 1e9 {
                crate::fmt::num(mm / 1000.0, 3)
            } else {
                crate::fmt::sci(mm / 1000.0)
            },
            crate::fmt::num(max_mm / 1000.0, 3)
        ),
    })
}

/// Whether two boxes `[min_x, min_y, max_x, max_y]` overlap (touching edges do not).
fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// How many pairs of `boxes` overlap (what the sheet layout is to leave none of).
pub fn overlapping_pairs(boxes: &[PartBox]) -> usize {
    (boxes.iter().enumerate())
        .map(|(i, a)| {
            (boxes[i + 1..].iter())
                .filter(|b| overlap(&a.bounds, &b.bounds))
                .count()
        })
        .sum()
}

/// How many pairs of parts overlap on the board as it is laid out: two boxes that overlap
/// where neither part is free, else a free part (a table) whose box meets a mark of the
/// other part (it may stand inside a large part's box where that is empty).
pub fn part_overlaps(board: &Board) -> usize {
    overlapping_parts(board).len()
}

/// The pairs of parts that overlap on the board as it is laid out, as [`part_overlaps`]
/// counts them, each pair in part order. A drag keeps the layout it started with while no
/// pair overlaps that did not then ([`crate::render::Layout`]).
pub fn overlapping_parts(board: &Board) -> Vec<(Part, Part)> {
    let boxes = part_boxes(board);
    let marks = std::cell::OnceCell::new();
    let touch = |free: &PartBox, other: Part| {
        let marks: &BTreeMap<Part, Vec<Mark>> = marks.get_or_init(|| part_marks(board));
        (marks.get(&other)).is_some_and(|ms| ms.iter().any(|m| m.meets(free.bounds)))
    };
    let mut out = Vec::new();
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            let met = overlap(&a.bounds, &b.bounds)
                && match (a.part.free, b.part.free) {
                    (false, false) => true,
                    (true, false) => touch(a, b.part),
                    (false, true) => touch(b, a.part),
                    (true, true) => touch(a, b.part) || touch(b, a.part),
                };
            if met {
                out.push((a.part, b.part));
            }
        }
    }
    out
}

/// The widths a row of packed parts is tried at before it goes on in a line under it (mm):
/// around the long side of a sheet in the A series' proportion (√2 : 1, landscape) whose
/// area is that of all the parts' boxes.
fn wrap_widths(boxes: &[PartBox]) -> [f64; 4] {
    let area: f64 = (boxes.iter())
        .map(|b| (b.bounds[2] - b.bounds[0]) * (b.bounds[3] - b.bounds[1]))
        .sum();
    let w = (std::f64::consts::SQRT_2 * area).sqrt();
    [1.5 * w, 1.25 * w, w, 0.8 * w]
}

/// The shorter side of the smallest sheet in the A series' proportion, either way round,
/// that holds `bounds` (mm): what a layout is judged by.
fn a_side(bounds: [f64; 4]) -> f64 {
    let (w, h) = (bounds[2] - bounds[0], bounds[3] - bounds[1]);
    let r = std::f64::consts::SQRT_2;
    (w / r).max(h).min(w.max(h / r))
}

/// A wrapped layout is taken only where its sheet (the shorter side of the A-series sheet
/// that holds it) is smaller than the unwrapped one's by more than this share, and its
/// parts' bounding box larger by no more than [`WRAP_GROWTH`]: a row of plans stays one
/// strip unless wrapping it fits a smaller sheet without leaving a hole beside the shorter
/// line.
pub const WRAP_GAIN: f64 = 0.1;

/// How much larger a wrapped layout's bounding box may be than the strip's ([`WRAP_GAIN`]).
pub const WRAP_GROWTH: f64 = 0.1;

/// How far each part set out in its row alone ([`Part::packed`]) is moved: up or down to
/// the highest top of its row's parts, and across to a gap right of the part before it in
/// the row (the first at the sheet's left edge); where that would reach `wrap` (mm) past the
/// left edge, to the left edge a gap under the line before, except a row's second part (a
/// truss drawing's force polygon stays beside it). `boxes` moved with them.
fn packed(boxes: &mut [PartBox], wrap: f64) -> BTreeMap<Part, Vector> {
    let left = boxes
        .iter()
        .map(|b| b.bounds[0])
        .fold(f64::INFINITY, f64::min);
    let wrap = left + wrap;
    let mut tops: BTreeMap<u16, f64> = BTreeMap::new();
    for b in boxes.iter() {
        let top = tops.entry(b.part.row).or_insert(b.bounds[3]);
        *top = top.max(b.bounds[3]);
    }
    let mut shift = BTreeMap::new();
    // Per row, the line being set: its right end (none before its first part), its top,
    // the row's bottom so far, and how many of the row's parts are set.
    struct Line {
        right: Option<f64>,
        top: f64,
        bottom: f64,
        parts: usize,
    }
    let mut lines: BTreeMap<u16, Line> = BTreeMap::new();
    // Boxes are in part order: by row, then column.
    for b in boxes.iter_mut().filter(|b| b.part.packed) {
        let top = tops[&b.part.row];
        let (w, h) = (b.bounds[2] - b.bounds[0], b.bounds[3] - b.bounds[1]);
        let line = (lines.entry(b.part.row)).or_insert(Line {
            right: None,
            top,
            bottom: top,
            parts: 0,
        });
        if line.parts >= 2 && line.right.is_some_and(|r| r + PART_GAP + w > wrap) {
            (line.right, line.top) = (None, line.bottom - PART_GAP);
        }
        let (x, y) = (line.right.map_or(left, |r| r + PART_GAP), line.top);
        let d = Vector::new(x - b.bounds[0], y - b.bounds[3]);
        b.bounds = moved(b.bounds, d);
        (line.right, line.bottom) = (Some(x + w), line.bottom.min(y - h));
        line.parts += 1;
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

/// How far each part that is not free is moved by the rows and columns: [`packed`] parts
/// in their rows alone, the others with their row (down) and column (across).
fn grid_shifts(boxes: &[PartBox], wrap: f64) -> BTreeMap<Part, Vector> {
    let mut boxes = boxes.to_vec();
    let mut shift = packed(&mut boxes, wrap);
    let (dy, dx) = offsets(&boxes);
    for b in &boxes {
        let row = Vector::new(0.0, dy.get(&b.part.row).copied().unwrap_or(0.0));
        let own = shift.get(&b.part).copied();
        let across = Vector::new(dx.get(&b.part.col).copied().unwrap_or(0.0), 0.0);
        shift.insert(b.part, own.unwrap_or(across) + row);
    }
    shift
}

/// The bounding box of the boxes `a` and `b`.
fn union(a: [f64; 4], b: &[f64; 4]) -> [f64; 4] {
    [
        a[0].min(b[0]),
        a[1].min(b[1]),
        a[2].max(b[2]),
        a[3].max(b[3]),
    ]
}

/// `bounds` moved by `d`.
fn moved(bounds: [f64; 4], d: Vector) -> [f64; 4] {
    [
        bounds[0] + d.x,
        bounds[1] + d.y,
        bounds[2] + d.x,
        bounds[3] + d.y,
    ]
}

/// Whether the boxes `a` and `b` come closer than [`PART_GAP`].
fn too_near(a: &[f64; 4], b: &[f64; 4]) -> bool {
    let g = PART_GAP - 1e-9;
    a[0] < b[2] + g && b[0] < a[2] + g && a[1] < b[3] + g && b[1] < a[3] + g
}

/// Where the free part `free` goes beside the boxes `placed`: a gap clear of every placed
/// box and off every line, where it grows the sheet (the boxes' bounding box) least, and of
/// such places (within [`SHEET_GROWTH_TIE`]) the one nearest to `wanted`, where the rows and
/// columns would put it. The places tried are `wanted` and those that set the box's edges a
/// gap from a placed box's edges or on the sheet's; `None` where none is clear.
fn hole(placed: &[[f64; 4]], marks: &[Mark], free: [f64; 4], wanted: [f64; 4]) -> Option<Vector> {
    let sheet = placed.iter().fold(*placed.first()?, union);
    let (w, h) = (free[2] - free[0], free[3] - free[1]);
    let mut xs = vec![sheet[0], sheet[2] - w];
    let mut ys = vec![sheet[1], sheet[3] - h];
    for b in placed {
        xs.extend([b[2] + PART_GAP, b[0] - PART_GAP - w]);
        ys.extend([b[3] + PART_GAP, b[1] - PART_GAP - h]);
    }
    let area = |c: &[f64; 4]| {
        let u = union(sheet, c);
        (u[2] - u[0]) * (u[3] - u[1])
    };
    let centre = |c: &[f64; 4]| Point::new(0.5 * (c[0] + c[2]), 0.5 * (c[1] + c[3]));
    let places: Vec<[f64; 4]> = std::iter::once(wanted)
        .chain(
            xs.iter()
                .flat_map(|&x| ys.iter().map(move |&y| [x, y, x + w, y + h])),
        )
        .filter(|c| !placed.iter().any(|b| too_near(c, b)))
        .collect();
    let least = places.iter().map(area).fold(f64::INFINITY, f64::min);
    let mut near: Vec<(f64, [f64; 4])> = (places.into_iter())
        .filter(|c| area(c) <= least * (1.0 + SHEET_GROWTH_TIE))
        .map(|c| ((centre(&c) - centre(&wanted)).norm(), c))
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let clear = |c: &[f64; 4]| !marks.iter().any(|m| m.meets(*c));
    let (_, c) = near.into_iter().find(|(_, c)| clear(c))?;
    Some(Vector::new(c[0] - free[0], c[1] - free[1]))
}

/// What [`room`] was asked, as far as its answer depends on it: the parts set before the
/// free part (those of the rows and columns in their order, with how far each moved; the
/// number of them; then the free parts already set, with theirs), the free part, and where
/// it is wanted (bits: a key compared exactly).
type Asked = (Vec<(Part, [u64; 2])>, usize, Part, [u64; 4]);

/// The rooms found for free parts, by what was asked: the layouts tried at the wrap widths
/// ([`laid_out`]) often set the same rows and columns, and each search rasterises the sheet
/// (the crane bridge of LH Aufgabe 5: ten searches, some five million instructions each).
#[derive(Default)]
struct Rooms(Vec<(Asked, Option<Vector>)>);

fn bits(d: Vector) -> [u64; 2] {
    [d.x.to_bits(), d.y.to_bits()]
}

/// The marks of part `p`, moved by `d`, added to `drawn`.
fn add_moved(drawn: &mut Vec<Mark>, marks: &BTreeMap<Part, Vec<Mark>>, p: &Part, d: Vector) {
    let own = marks.get(p).map_or(&[][..], |ms| &ms[..]);
    drawn.extend(own.iter().map(|m| m.moved(d)));
}

/// How far each part is moved: the rows and columns set out, then each free part
/// ([`Part::free`]) in part order into room the sheet has: inside it where its box meets
/// no mark of the parts set before it ([`inner_hole`]), else in a hole the boxes leave
/// ([`hole`]). A free part that neither takes joins the rows and columns, and the room is
/// sought again. A room found before for the same parts set the same way is taken from
/// `rooms`.
fn shifts(
    boxes: &[PartBox],
    marks: &BTreeMap<Part, Vec<Mark>>,
    wrap: f64,
    rooms: &mut Rooms,
) -> BTreeMap<Part, Vector> {
    let everything = grid_shifts(boxes, wrap);
    let (mut grid, mut free): (Vec<PartBox>, Vec<PartBox>) =
        boxes.iter().partition(|b| !b.part.free);
    loop {
        if grid.is_empty() || free.is_empty() {
            return everything;
        }
        let mut shift = grid_shifts(&grid, wrap);
        let mut placed: Vec<[f64; 4]> = (grid.iter())
            .map(|b| moved(b.bounds, shift[&b.part]))
            .collect();
        let mut set: Vec<(Part, [u64; 2])> = (grid.iter())
            .map(|b| (b.part, bits(shift[&b.part])))
            .collect();
        // The marks of the rows and columns, moved and clipped, then those of the free parts
        // set: made only where a room is sought.
        let rows_and_columns = shift.clone();
        let mut drawn: Option<Vec<Mark>> = None;
        let reach = within_reach(&placed);
        let misfit = free.iter().position(|f| {
            let wanted = moved(f.bounds, everything[&f.part]);
            let asked: Asked = (set.clone(), grid.len(), f.part, wanted.map(f64::to_bits));
            let known = rooms.0.iter().find(|(a, _)| *a == asked).map(|(_, d)| *d);
            let found = known.unwrap_or_else(|| {
                let drawn = drawn.get_or_insert_with(|| {
                    let mut drawn: Vec<Mark> = (marks.iter())
                        .filter_map(|(p, ms)| Some((*rows_and_columns.get(p)?, ms)))
                        .flat_map(|(d, ms)| {
                            ms.iter().filter_map(move |m| m.moved(d).clipped(reach))
                        })
                        .collect();
                    for (p, d) in &set[grid.len()..] {
                        let d = Vector::new(f64::from_bits(d[0]), f64::from_bits(d[1]));
                        add_moved(&mut drawn, marks, p, d);
                    }
                    drawn
                });
                let d = room(&placed, drawn, f.bounds, wanted);
                rooms.0.push((asked, d));
                d
            });
            let Some(d) = found else {
                return true;
            };
            shift.insert(f.part, d);
            placed.push(moved(f.bounds, d));
            set.push((f.part, bits(d)));
            if let Some(drawn) = drawn.as_mut() {
                add_moved(drawn, marks, &f.part, d);
            }
            false
        });
        match misfit {
            None => return shift,
            Some(k) => grid.push(free.remove(k)),
        }
    }
}

/// The region the figure draws lines in, for boxes `placed` (the parts that are not free):
/// their extent (without [`PART_MARGIN`]) and [`CLIP_REACH`] of its larger side around it,
/// as the figure clips its lines; a free part is set clear of the lines there, and does not
/// widen the region.
fn within_reach(placed: &[[f64; 4]]) -> [f64; 4] {
    let Some(first) = placed.first() else {
        return [0.0; 4];
    };
    let [x0, y0, x1, y1] = placed.iter().fold(*first, union);
    let side = (x1 - x0).max(y1 - y0) - 2.0 * PART_MARGIN;
    let reach = CLIP_REACH * side.max(0.0) + LINE_OVERSHOOT;
    let m = reach - PART_MARGIN;
    [x0 - m, y0 - m, x1 + m, y1 + m]
}

/// How far the free part of box `free` moves: into the sheet the boxes `placed` span where
/// it meets none of `marks` ([`inner_hole`]), else into a hole beside them ([`hole`]).
fn room(placed: &[[f64; 4]], marks: &[Mark], free: [f64; 4], wanted: [f64; 4]) -> Option<Vector> {
    let sheet = placed.iter().fold(*placed.first()?, union);
    let size = (free[2] - free[0], free[3] - free[1]);
    let centre = Point::new(0.5 * (wanted[0] + wanted[2]), 0.5 * (wanted[1] + wanted[3]));
    match inner_hole(sheet, marks, size, centre) {
        Some(c) => Some(Vector::new(c[0] - free[0], c[1] - free[1])),
        None => hole(placed, marks, free, wanted),
    }
}

/// The board with its parts set out, or `None` where it draws in one part only (then it is
/// drawn as constructed).
pub fn laid_out(board: &Board) -> Option<Board> {
    Some(moved_by(board, &part_shifts(board)?))
}

/// The board with each part moved by its shift (a part not named stays).
pub(crate) fn moved_by(board: &Board, shifts: &BTreeMap<Part, Vector>) -> Board {
    let mut moved = board.clone();
    moved.move_parts(|p| shifts.get(&p).copied().unwrap_or_else(Vector::zeros));
    moved
}

/// How far [`laid_out`] moves each part of `board` (mm on the sheet); `None` where the
/// board has fewer than two parts and is drawn as constructed. The figure draws each step
/// in its part's own coordinates and moves its layer by this (an SVG transform), so that a
/// part the layout moves is one attribute changed, not every mark of it.
pub fn part_shifts(board: &Board) -> Option<BTreeMap<Part, Vector>> {
    let boxes = part_boxes(board);
    if boxes.len() < 2 {
        return None;
    }
    let marks = part_marks(board);
    let sheet = |shift: &BTreeMap<Part, Vector>| {
        let b = (boxes.iter())
            .map(|b| moved(b.bounds, shift[&b.part]))
            .reduce(|s, b| union(s, &b))
            .unwrap_or_default();
        (a_side(b), (b[2] - b[0]) * (b[3] - b[1]))
    };
    let mut rooms = Rooms::default();
    let strip = shifts(&boxes, &marks, f64::INFINITY, &mut rooms);
    let rows_wrap = boxes.iter().any(|b| b.part.packed);
    let wraps = wrap_widths(&boxes).into_iter().filter(|_| rows_wrap);
    let (side, area) = sheet(&strip);
    let least = (wraps.map(|w| shifts(&boxes, &marks, w, &mut rooms)))
        .map(|s| (sheet(&s), s))
        .filter(|((_, a), _)| *a <= (1.0 + WRAP_GROWTH) * area)
        .min_by(|a, b| a.0 .0.total_cmp(&b.0 .0));
    Some(match least {
        Some(((s, _), wrapped)) if s < (1.0 - WRAP_GAIN) * side => wrapped,
        _ => strip,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::construct::clip_to_rect;
    use crate::kernel::Point;
    use crate::protocol::{Note, Role, Topic};
    use crate::render::extent::line_ends;

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
        // Unwrapped (wide rows wrap where that saves paper: the next test).
        let mut boxes = part_boxes(&b);
        packed(&mut boxes, f64::INFINITY);
        let (dy, _) = offsets(&boxes);
        for b in &mut boxes {
            b.bounds = moved(b.bounds, Vector::new(0.0, dy[&b.part.row]));
        }
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

    /// A board of two rows: a wide part (row 0) over a narrow one (row 1, left), and a
    /// free table of three rows constructed far away; where `ruled`, the narrow part draws
    /// a line level with its foot out to a point of the wide part, through the hole beside
    /// it.
    fn with_a_table(ruled: bool) -> Board {
        let n = Note::new("p", Topic::Custom("layout"));
        let mut b = Board::recording();
        b.set_part(Part::at(0, 0));
        b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        b.point(Point::new(300.0, 60.0), Role::Given, n.clone());
        let r = b.point(Point::new(300.0, 0.0), Role::Given, n.clone());
        b.set_part(Part::at(1, 0));
        let p = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        b.point(Point::new(100.0, 40.0), Role::Given, n.clone());
        if ruled {
            b.line_through(&p, &r, Role::Construction, n.clone())
                .expect("two points");
        }
        b.set_part(Part::free(2, 0));
        let rows = vec![vec!["T_m".to_string(), "1234.5".to_string()]; 3];
        b.table(Point::new(-500.0, -500.0), rows, &[], n);
        b
    }

    /// `with_a_table(ruled)` laid out: its parts overlap nowhere; the table's box, the
    /// boxes of the parts that are not free, and the board.
    fn table_set_out(ruled: bool) -> ([f64; 4], Vec<[f64; 4]>, Board) {
        let moved = laid_out(&with_a_table(ruled)).expect("three parts");
        assert_eq!(part_overlaps(&moved), 0);
        let boxes = part_boxes(&moved);
        let table = boxes.iter().find(|b| b.part.free).expect("the table");
        let rest = (boxes.iter().filter(|b| !b.part.free)).map(|b| b.bounds);
        (table.bounds, rest.collect(), moved)
    }

    #[test]
    fn a_free_part_takes_room_in_the_sheet_instead_of_a_row_of_its_own() {
        // Within the sheet the other parts span: the empty inside of the wide part's box,
        // or the hole beside the narrow part.
        for ruled in [false, true] {
            let (t, rest, moved) = table_set_out(ruled);
            let sheet = rest.iter().fold(rest[0], union);
            assert!(
                t[0] >= sheet[0] && t[1] >= sheet[1] && t[2] <= sheet[2] && t[3] <= sheet[3],
                "{t:?} {sheet:?}"
            );
            // Clear of every mark of the others: their points and the line.
            let table = (moved.steps().iter().find(|s| s.part.free)).map(|s| s.id);
            let others = (moved.drawn_objects()).filter(|o| Some(o.step) != table);
            for o in others {
                if let Some((a, b)) = line_ends(o) {
                    assert!(clip_to_rect(a, b, t).is_none(), "{t:?} {a:?} {b:?}");
                }
                if let Geom::Point { at } = o.geom {
                    assert!(!(at.x > t[0] && at.x < t[2] && at.y > t[1] && at.y < t[3]));
                }
            }
        }
        // The boxes alone overlap: the table stands inside the wide part's empty box.
        let (t, rest, _) = table_set_out(false);
        let inside = |b: &[f64; 4]| t[0] >= b[0] && t[2] <= b[2] && t[1] >= b[1] && t[3] <= b[3];
        assert!(rest.iter().any(inside), "{t:?} {rest:?}");
    }

    #[test]
    fn a_long_row_of_small_plans_wraps_and_a_short_one_does_not() {
        let n = Note::new("p", Topic::Custom("layout"));
        // A truss drawing, its force polygon, then `k` small joint polygons, in one row.
        let row = |k: u16| {
            let mut b = Board::recording();
            let sizes = [(200.0, 100.0), (50.0, 100.0)];
            let small = std::iter::repeat_n((50.0, 50.0), usize::from(k));
            for (col, (w, h)) in sizes.into_iter().chain(small).enumerate() {
                b.set_part(Part::packed(0, col as u16));
                b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
                b.point(Point::new(w, h), Role::Given, n.clone());
            }
            let moved = laid_out(&b).expect("parts");
            part_boxes(&moved)
        };
        let long = row(8);
        assert_eq!(overlapping_pairs(&long), 0, "{long:?}");
        // The force polygon beside the drawing, the last polygon on a line under them.
        assert!((long[1].bounds[3] - long[0].bounds[3]).abs() < 1e-9);
        assert!(long[9].bounds[3] < long[0].bounds[1], "{long:?}");
        let side =
            |bs: &[PartBox]| a_side(bs.iter().fold(bs[0].bounds, |s, b| union(s, &b.bounds)));
        // Set out in one strip it would need a sheet more than a tenth larger.
        let width: f64 =
            long.iter().map(|b| b.bounds[2] - b.bounds[0]).sum::<f64>() + PART_GAP * 9.0;
        let strip_side = a_side([0.0, 0.0, width, long[0].bounds[3] - long[0].bounds[1]]);
        assert!(side(&long) < (1.0 - WRAP_GAIN) * strip_side, "{long:?}");
        // One small polygon: one line, as constructed.
        let short = row(1);
        let tops: Vec<f64> = short.iter().map(|b| b.bounds[3]).collect();
        assert!(tops.iter().all(|t| (t - tops[0]).abs() < 1e-9), "{short:?}");
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
