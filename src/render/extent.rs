//! What a figure's objects take up on the sheet: the drawn ends of a line, the compass
//! arcs of a circle, the blocks of a table. The figure draws by it and the sheet layout
//! measures its parts by it.

use super::style::*;
use crate::kernel::{Point, Vector};
use crate::protocol::{Geom, Object, TABLE_BLOCK_ROWS};

pub(super) fn line_ends(obj: &Object) -> Option<(Point, Point)> {
    match &obj.geom {
        Geom::Line { line, extent } => {
            let (a, b) = if extent[1] - extent[0] > 0.0 {
                (extent[0] - LINE_OVERSHOOT, extent[1] + LINE_OVERSHOOT)
            } else {
                (
                    extent[0] - 2.0 * LINE_OVERSHOOT,
                    extent[1] + 2.0 * LINE_OVERSHOOT,
                )
            };
            Some((line.point_at(a), line.point_at(b)))
        }
        _ => None,
    }
}

pub(super) fn compass_arc_half_angle(radius: f64) -> f64 {
    (0.5 * COMPASS_ARC / radius).min(20f64.to_radians())
}

/// The points that bound an object's drawing.
pub(super) fn extent_points(obj: &Object, out: &mut Vec<Point>) {
    match &obj.geom {
        Geom::Point { at } => out.push(*at),
        Geom::Line { .. } => {
            if let Some((a, b)) = line_ends(obj) {
                out.push(a);
                out.push(b);
            }
        }
        Geom::Segment { segment } | Geom::Vector { segment } => {
            out.push(segment.a);
            out.push(segment.b);
        }
        Geom::Circle {
            circle,
            full,
            marks,
        } => {
            if *full {
                let r = Vector::new(circle.radius, circle.radius);
                out.push(circle.center - r);
                out.push(circle.center + r);
            } else {
                let h = compass_arc_half_angle(circle.radius).to_degrees();
                for m in marks {
                    for d in [-h, 0.0, h] {
                        out.push(circle.point_at_deg(m + d));
                    }
                }
            }
        }
        Geom::Arc { arc } => {
            for k in 0..=8 {
                out.push(arc.point_at_fraction(k as f64 / 8.0));
            }
        }
        Geom::Curve { points, .. } => out.extend(points.iter().copied()),
        Geom::Table { at, rows } => {
            for (block, corner) in table_blocks(*at, rows) {
                let (w, h) = table_size(&block);
                out.push(corner);
                out.push(corner + Vector::new(w, -h));
            }
        }
        Geom::Scalar { .. } => {}
    }
}

/// Column widths of a table (mm), estimated from the character counts.
pub(super) fn table_columns(rows: &[Vec<String>]) -> Vec<f64> {
    let n = rows.iter().map(|r| r.len()).max().unwrap_or(0);
    (0..n)
        .map(|c| {
            rows.iter()
                .filter_map(|r| r.get(c))
                .map(|s| s.chars().count())
                .max()
                .unwrap_or(0) as f64
                * TABLE_CHAR
                + TABLE_GAP
        })
        .collect()
}

/// A table cut into blocks of at most [`TABLE_BLOCK_ROWS`] body rows, each with the header,
/// side by side from `at`.
pub(super) fn table_blocks(at: Point, rows: &[Vec<String>]) -> Vec<(Vec<Vec<String>>, Point)> {
    let Some((head, body)) = rows.split_first() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mut x = at.x;
    for chunk in body.chunks(TABLE_BLOCK_ROWS.max(1)) {
        let mut block = vec![head.clone()];
        block.extend(chunk.iter().cloned());
        let (w, _) = table_size(&block);
        out.push((block, Point::new(x, at.y)));
        x += w + 3.0 * TABLE_GAP;
    }
    if body.is_empty() {
        out.push((vec![head.clone()], at));
    }
    out
}

/// Whether a table is a heading: one row of one cell (a load case's name over its row),
/// set larger and without a rule.
pub(super) fn is_heading(rows: &[Vec<String>]) -> bool {
    rows.len() == 1 && rows[0].len() == 1
}

/// Width and height of a table (mm).
pub(super) fn table_size(rows: &[Vec<String>]) -> (f64, f64) {
    if is_heading(rows) {
        let n = rows[0][0].chars().count() as f64;
        return (n * HEADING_CHAR, HEADING_ROW);
    }
    (
        table_columns(rows).iter().sum(),
        rows.len() as f64 * TABLE_ROW,
    )
}
