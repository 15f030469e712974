//! What a figure's parts put on the sheet, as marks a free part (a table) is set clear of:
//! the strokes of lines, segments, curves, arcs and circles, and the patches of points
//! (with room for their letter) and tables. A part's box ([`super::layout::PartBox`]) holds
//! all of them; a large part leaves room inside its box (LH Abb. 52: the velocity curve
//! over the stroke and the pole B₁ high above the crank leave the sheet's upper left
//! empty), and [`inner_hole`] finds it.

use super::extent::{compass_arc_half_angle, line_ends, table_blocks, table_size};
use crate::kernel::construct::clip_to_rect;
use crate::kernel::{Point, Vector};
use crate::protocol::{Board, Geom, Object, Part};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BinaryHeap};

/// Room kept around a point for its dot and its letter (mm each way).
pub const POINT_ROOM: f64 = 4.0;

/// Sides of the polygon a full circle is marked by.
const CIRCLE_SIDES: usize = 48;

/// The most cells a side of [`inner_hole`]'s raster has; a sheet longer than 1 m gets
/// coarser cells.
const MAX_SIDE: f64 = 500.0;

/// How many of the raster's empty places [`inner_hole`] tests exactly.
const MAX_TRIES: usize = 64;

/// The finest cell of [`inner_hole`]'s raster (mm).
const CELL: f64 = 2.0;

/// One mark on the sheet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mark {
    /// A straight stroke from one point to another.
    Stroke(Point, Point),
    /// A rectangle `[min_x, min_y, max_x, max_y]`.
    Patch([f64; 4]),
}

impl Mark {
    /// The mark moved by `d`.
    pub fn moved(self, d: Vector) -> Mark {
        match self {
            Mark::Stroke(a, b) => Mark::Stroke(a + d, b + d),
            Mark::Patch([x0, y0, x1, y1]) => Mark::Patch([x0 + d.x, y0 + d.y, x1 + d.x, y1 + d.y]),
        }
    }

    /// The part of the mark within the rectangle `r`, if any.
    pub fn clipped(self, r: [f64; 4]) -> Option<Mark> {
        match self {
            Mark::Stroke(a, b) => {
                let (t0, t1) = clip_to_rect(a, b, r)?;
                Some(Mark::Stroke(a + (b - a) * t0, a + (b - a) * t1))
            }
            Mark::Patch(p) => self.meets(r).then_some(Mark::Patch([
                p[0].max(r[0]),
                p[1].max(r[1]),
                p[2].min(r[2]),
                p[3].min(r[3]),
            ])),
        }
    }

    /// Whether the mark touches the rectangle `r`.
    pub fn meets(&self, r: [f64; 4]) -> bool {
        match *self {
            Mark::Stroke(a, b) => clip_to_rect(a, b, r).is_some_and(|(t0, t1)| t0 <= t1),
            Mark::Patch(p) => p[0] < r[2] && r[0] < p[2] && p[1] < r[3] && r[1] < p[3],
        }
    }
}

/// The strokes between consecutive points.
fn polyline(pts: &[Point], out: &mut Vec<Mark>) {
    out.extend(pts.windows(2).map(|w| Mark::Stroke(w[0], w[1])));
}

/// The marks one object puts on the sheet.
fn object_marks(o: &Object, out: &mut Vec<Mark>) {
    match &o.geom {
        Geom::Point { at } => {
            let r = POINT_ROOM;
            out.push(Mark::Patch([at.x - r, at.y - r, at.x + r, at.y + r]));
        }
        Geom::Line { .. } => {
            if let Some((a, b)) = line_ends(o) {
                out.push(Mark::Stroke(a, b));
            }
        }
        Geom::Segment { segment } | Geom::Vector { segment } => {
            out.push(Mark::Stroke(segment.a, segment.b))
        }
        Geom::Circle {
            circle,
            full,
            marks,
        } => {
            if *full {
                let pts: Vec<Point> = (0..=CIRCLE_SIDES)
                    .map(|k| circle.point_at_deg(360.0 * k as f64 / CIRCLE_SIDES as f64))
                    .collect();
                polyline(&pts, out);
            } else {
                let h = compass_arc_half_angle(circle.radius).to_degrees();
                for m in marks {
                    let pts: Vec<Point> = [-h, 0.0, h]
                        .iter()
                        .map(|d| circle.point_at_deg(m + d))
                        .collect();
                    polyline(&pts, out);
                }
            }
        }
        Geom::Arc { arc } => {
            let pts: Vec<Point> = (0..=16)
                .map(|k| arc.point_at_fraction(k as f64 / 16.0))
                .collect();
            polyline(&pts, out);
        }
        Geom::Curve { points, .. } => polyline(points, out),
        Geom::Table { at, rows } => {
            for (block, corner) in table_blocks(*at, rows) {
                let (w, h) = table_size(&block);
                out.push(Mark::Patch([
                    corner.x,
                    corner.y - h,
                    corner.x + w,
                    corner.y,
                ]));
            }
        }
        Geom::Scalar { .. } => {}
    }
}

/// Every mark the board's drawn objects put on the sheet, by the part they belong to.
pub fn part_marks(board: &Board) -> BTreeMap<Part, Vec<Mark>> {
    let mut out: BTreeMap<Part, Vec<Mark>> = BTreeMap::new();
    for o in board.drawn_objects() {
        if let Some(step) = board.step(o.step) {
            object_marks(o, out.entry(step.part).or_default());
        }
    }
    out
}

/// The sheet `sheet` rasterised on square cells, a cell set where a mark touches it.
struct Raster {
    origin: Point,
    cell: f64,
    nx: usize,
    ny: usize,
    /// Prefix sums of the set cells: `sums[j * (nx + 1) + i]` counts those left of column
    /// `i` and below row `j`.
    sums: Vec<u32>,
}

impl Raster {
    fn of(sheet: [f64; 4], marks: &[Mark]) -> Option<Raster> {
        let (w, h) = (sheet[2] - sheet[0], sheet[3] - sheet[1]);
        if !(w.is_finite() && h.is_finite() && w > 0.0 && h > 0.0) {
            return None;
        }
        let cell = CELL.max(w.max(h) / MAX_SIDE);
        let (nx, ny) = ((w / cell).ceil() as usize, (h / cell).ceil() as usize);
        if !cell.is_finite() || nx == 0 || ny == 0 {
            return None;
        }
        let origin = Point::new(sheet[0], sheet[1]);
        let mut set = vec![false; nx * ny];
        // `floor(v / cell)` clamped to the raster: the saturating cast truncates, which for
        // a quotient at or above zero is its floor, and takes anything below (and NaN) to 0,
        // as the clamp did; no call to `floor` (a library call on x86-64 without SSE4.1).
        let index = |v: f64, n: usize| ((v / cell) as usize).min(n - 1);
        let fill = |set: &mut [bool], r: [f64; 4]| {
            let (i0, i1) = (index(r[0] - origin.x, nx), index(r[2] - origin.x, nx));
            let (j0, j1) = (index(r[1] - origin.y, ny), index(r[3] - origin.y, ny));
            for j in j0..=j1 {
                set[j * nx + i0..=j * nx + i1].fill(true);
            }
        };
        let dot = |set: &mut [bool], p: Point| {
            let (i, j) = (index(p.x - origin.x, nx), index(p.y - origin.y, ny));
            set[j * nx + i] = true;
        };
        for m in marks {
            match *m {
                // A patch off the sheet (a far point's) marks nothing, not the edge cells.
                Mark::Patch(p) if m.meets(sheet) => fill(&mut set, p),
                Mark::Patch(_) => {}
                Mark::Stroke(a, b) => {
                    // Only the stroke's part on the sheet, in steps of half a cell.
                    let Some((t0, t1)) = clip_to_rect(a, b, sheet) else {
                        continue;
                    };
                    let (a, b) = (a + (b - a) * t0, a + (b - a) * t1);
                    let n = ((b - a).norm() / (0.5 * cell)).ceil().min(4.0 * MAX_SIDE);
                    let n = if n.is_finite() { n as usize } else { 0 };
                    for k in 0..=n {
                        dot(&mut set, a + (b - a) * (k as f64 / n.max(1) as f64));
                    }
                }
            }
        }
        // Each row's running count added to the row below's sums.
        let mut sums = vec![0u32; (nx + 1) * (ny + 1)];
        for j in 0..ny {
            let (below, row) = sums.split_at_mut((j + 1) * (nx + 1));
            let below = &below[j * (nx + 1)..];
            let mut run = 0;
            for i in 0..nx {
                run += u32::from(set[j * nx + i]);
                row[i + 1] = below[i + 1] + run;
            }
        }
        Some(Raster {
            origin,
            cell,
            nx,
            ny,
            sums,
        })
    }
}

/// A place for a box and the square of its centre's distance from where it is wanted,
/// ordered by that distance, then from the bottom, then from the left: a total order, so
/// that the place taken is the same on every platform.
#[derive(Debug, Clone, Copy)]
struct Place(f64, [f64; 4]);

impl Place {
    fn key(&self) -> [f64; 3] {
        [self.0, self.1[1], self.1[0]]
    }
}

impl PartialEq for Place {
    fn eq(&self, other: &Place) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Place {}

impl PartialOrd for Place {
    fn partial_cmp(&self, other: &Place) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Place {
    fn cmp(&self, other: &Place) -> Ordering {
        let (a, b) = (self.key(), other.key());
        (a[0].total_cmp(&b[0]))
            .then(a[1].total_cmp(&b[1]))
            .then(a[2].total_cmp(&b[2]))
    }
}

/// A place for a box of `size` (mm) inside `sheet` that meets none of `marks`, of such
/// places the one whose centre is nearest to `wanted`: the sheet rasterised on cells of
/// [`CELL`] (coarser past [`MAX_SIDE`] a side), every cell-aligned place of the box with no
/// mark in its cells tried in order of that distance, and the first that meets no mark
/// exactly taken. `None` where the sheet has no such room.
pub fn inner_hole(
    sheet: [f64; 4],
    marks: &[Mark],
    size: (f64, f64),
    wanted: Point,
) -> Option<[f64; 4]> {
    let r = Raster::of(sheet, marks)?;
    let (w, h) = size;
    let (wc, hc) = ((w / r.cell).ceil() as usize, (h / r.cell).ceil() as usize);
    if wc == 0 || hc == 0 || wc > r.nx || hc > r.ny {
        return None;
    }
    let place = |i: usize, j: usize| {
        let (x, y) = (
            r.origin.x + i as f64 * r.cell,
            r.origin.y + j as f64 * r.cell,
        );
        [x, y, x + w, y + h]
    };
    let distance = |c: &[f64; 4]| {
        (Point::new(0.5 * (c[0] + c[2]), 0.5 * (c[1] + c[3])) - wanted).norm_squared()
    };
    // The nearest empty places, kept in a heap of at most MAX_TRIES (the farthest on top).
    let mut nearest: BinaryHeap<Place> = BinaryHeap::with_capacity(MAX_TRIES + 1);
    // Per row of places, the set cells of its `hc` rows left of each column: a place's
    // count is the difference of two.
    let mut left = vec![0u32; r.nx + 1];
    for j in 0..=r.ny - hc {
        let (lo, hi) = (&r.sums[j * (r.nx + 1)..], &r.sums[(j + hc) * (r.nx + 1)..]);
        for (l, (h, o)) in left.iter_mut().zip(hi.iter().zip(lo)) {
            *l = h - o;
        }
        for i in 0..=r.nx - wc {
            if left[i + wc] != left[i] {
                continue;
            }
            let c = place(i, j);
            let p = Place(distance(&c), c);
            if nearest.len() < MAX_TRIES {
                nearest.push(p);
            } else if nearest.peek().is_some_and(|far| p < *far) {
                nearest.pop();
                nearest.push(p);
            }
        }
    }
    // The raster marks every cell a mark crosses but for a corner it may clip between two
    // steps; the exact test settles those, within a few tries of the nearest places.
    (nearest.into_sorted_vec().into_iter())
        .map(|p| p.1)
        .find(|c| c[2] <= sheet[2] && c[3] <= sheet[3] && !marks.iter().any(|m| m.meets(*c)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Strokes and a patch in a 100 mm square leave two rooms, 60 × 50 mm at the upper
    /// right and 100 × 50 mm under the middle stroke; a box goes into the one nearest to
    /// where it is wanted, and a box larger than both finds none.
    #[test]
    fn a_box_goes_where_no_mark_is() {
        let marks = [
            Mark::Stroke(Point::new(0.0, 0.0), Point::new(100.0, 0.0)),
            Mark::Stroke(Point::new(0.0, 0.0), Point::new(0.0, 100.0)),
            Mark::Stroke(Point::new(0.0, 50.0), Point::new(100.0, 50.0)),
            Mark::Patch([0.0, 50.0, 40.0, 100.0]),
        ];
        let sheet = [0.0, 0.0, 100.0, 100.0];
        let c = inner_hole(sheet, &marks, (30.0, 30.0), Point::new(0.0, 100.0)).unwrap();
        assert!(
            c[0] >= 40.0 && c[1] > 50.0 && c[2] <= 100.0 && c[3] <= 100.0,
            "{c:?}"
        );
        assert!(!marks.iter().any(|m| m.meets(c)));
        // Nearest to the wanted corner: against the patch's right side, at the top.
        assert!(c[0] - 40.0 <= CELL && 100.0 - c[3] <= CELL, "{c:?}");
        assert_eq!(
            inner_hole(sheet, &marks, (70.0, 60.0), Point::origin()),
            None
        );
        // Below the middle stroke the whole width is free.
        let low = inner_hole(sheet, &marks, (90.0, 40.0), Point::origin()).unwrap();
        assert!(low[3] < 50.0 && low[1] > 0.0 && low[0] > 0.0, "{low:?}");
        // A patch off the sheet (a far point's) takes no room at its edge.
        let mut far = marks.to_vec();
        far.push(Mark::Patch([150.0, 150.0, 160.0, 160.0]));
        let corner = Point::new(100.0, 100.0);
        let at = inner_hole(sheet, &far, (30.0, 30.0), corner).unwrap();
        assert_eq!(at, inner_hole(sheet, &marks, (30.0, 30.0), corner).unwrap());
        assert!(at[2] == 100.0 && at[3] == 100.0, "{at:?}");
    }
}
