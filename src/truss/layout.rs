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

/// Gap between the truss drawing, the reactions' force polygon and the plan, and between
/// rows (mm).
const GAP_MM: f64 = 30.0;
/// Room for a load case's name over its row (mm).
pub(super) const HEADING_MM: f64 = 8.0;

impl Layout {
    /// Every part at the origin: the dry run's layout.
    pub(super) const ORIGIN: Layout = Layout {
        truss: Point::new(0.0, 0.0),
        polygon: Point::new(0.0, 0.0),
        plan: Point::new(0.0, 0.0),
    };

    /// The parts of a case side by side in a row whose top is `row_top`, from the dry run's
    /// boxes (truss drawing, reactions' polygon, plan): the layout, and how far the next row
    /// starts below.
    pub(super) fn row(boxes: &[[f64; 4]; 3], row_top: f64) -> (Layout, f64) {
        let [tx0, ty0, tx1, ty1] = boxes[0];
        let [px0, py0, px1, py1] = boxes[1];
        let [qx0, qy0, _, qy1] = boxes[2];
        let at = Layout {
            truss: Point::new(-tx0, row_top - ty1),
            polygon: Point::new(tx1 - tx0 + GAP_MM - px0, row_top - py1),
            plan: Point::new(
                tx1 - tx0 + GAP_MM + (px1 - px0) + GAP_MM - qx0,
                row_top - qy1,
            ),
        };
        let height = (ty1 - ty0).max(py1 - py0).max(qy1 - qy0);
        (at, height + 2.0 * GAP_MM)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_puts_the_parts_side_by_side_under_its_top() {
        // Truss 100 × 40 mm, polygon 20 × 60, plan 50 × 30 (each box relative to its origin).
        let boxes = [
            [-10.0, 0.0, 90.0, 40.0],
            [0.0, -30.0, 20.0, 30.0],
            [5.0, 0.0, 55.0, 30.0],
        ];
        let (at, height) = Layout::row(&boxes, -100.0);
        assert_eq!(at.truss, Point::new(10.0, -140.0)); // its top edge at the row's top
        assert_eq!(at.polygon, Point::new(100.0 + GAP_MM, -130.0));
        assert_eq!(at.plan.x, 100.0 + GAP_MM + 20.0 + GAP_MM - 5.0);
        assert_eq!(height, 60.0 + 2.0 * GAP_MM);
    }
}
