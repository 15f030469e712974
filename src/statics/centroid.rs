//! The centroid of a polygon by two funicular polygons (LH C.3, Abb. 23): split the polygon
//! into triangles, find each triangle's centroid where two medians cross, let the areas act
//! as parallel forces at these centroids, and find their resultant twice — once for vertical
//! forces, once with the forces turned through 90° (the book turns the figure). The two lines
//! of action cross at the centroid.
//!
//! The split is a fan from one vertex (the book's diagonal BD is the fan from B). For a
//! non-convex polygon some fan triangles run the other way round: their areas count negative,
//! forces of the opposite sense, which the force polygon takes in its stride.

use super::funicular::{construct_system, Force, SystemDrawing};
use crate::kernel::tolerance::REL_AREA_EPS;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{note, Board, ConstructionError, Label, Note, Role, Scale, Topic, Trace, H};
use serde::Serialize;

const N_VERTEX: Note = note(
    "vertex of the polygon",
    Some("Eckpunkt"),
    "LH Abb. 23",
    Topic::Loads,
);
const N_OUTLINE: Note = note("the polygon", Some("Fläche F"), "LH Abb. 23", Topic::Loads);
const N_DIAGONAL: Note = note(
    "diagonal splitting off a triangle",
    Some("Diagonale"),
    "LH Abb. 23",
    Topic::Loads,
);
const N_MIDPOINT: Note = note(
    "halve a side",
    Some("Seitenmitte"),
    "LH Abb. 23",
    Topic::Loads,
);
const N_MEDIAN: Note = note("median", Some("Mittellinie"), "LH Abb. 23", Topic::Loads);
const N_TRIANGLE_CENTROID: Note = note(
    "two medians cross: centroid of the triangle",
    Some("Dreiecksschwerpunkt"),
    "LH Abb. 23",
    Topic::Loads,
);
const N_ORIGIN: Note = note(
    "origin of the coordinates",
    Some("Ursprung"),
    "LH Abb. 23",
    Topic::Funicular,
);
const N_AXIS: Note = note(
    "coordinate axis",
    Some("Achse"),
    "LH Abb. 23",
    Topic::Funicular,
);
const N_CENTROID: Note = note(
    "the two centroidal lines cross: centroid S",
    Some("Schwerpunkt"),
    "LH C.3, Abb. 23",
    Topic::Funicular,
);
const N_COORD: Note = note(
    "coordinate of the centroid",
    Some("Schwerpunktsabstand"),
    "LH C.3",
    Topic::Funicular,
);

/// Scales of a centroid drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CentroidDrawing {
    /// Length scale 1 : n.
    pub length_scale: f64,
    /// Area scale: m² per mm of sheet in the force polygons.
    pub area_scale: f64,
    /// The vertex the fan of triangles starts from.
    pub fan_from: usize,
}

/// Results of [`construct_centroid`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CentroidResults {
    /// The centroid (m).
    pub centroid: Point,
    /// The area (m²).
    pub area: f64,
}

/// The closed form: area and centroid by the shoelace formula; `None` for zero area.
///
/// ```
/// use graphostatik::statics::centroid::polygon_centroid;
/// use graphostatik::kernel::Point;
/// let square = [(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (0.0, 2.0)].map(|(x, y)| Point::new(x, y));
/// let (a, c) = polygon_centroid(&square).unwrap();
/// assert_eq!((a, c), (8.0, Point::new(2.0, 1.0)));
/// ```
pub fn polygon_centroid(pts: &[Point]) -> Option<(f64, Point)> {
    let n = pts.len();
    // Measured from the first vertex: the shoelace's products x·y at absolute coordinates
    // would cancel the offset's digits (a unit square at 1e8 m came out of zero area).
    let o = pts.first().copied().unwrap_or(Point::origin());
    let (mut a2, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let (x0, y0) = (pts[i].x - o.x, pts[i].y - o.y);
        let (x1, y1) = (pts[(i + 1) % n].x - o.x, pts[(i + 1) % n].y - o.y);
        let c = x0 * y1 - x1 * y0;
        a2 += c;
        cx += (x0 + x1) * c;
        cy += (y0 + y1) * c;
    }
    if a2 == 0.0 {
        return None;
    }
    Some((
        0.5 * a2.abs(),
        Point::new(o.x + cx / (3.0 * a2), o.y + cy / (3.0 * a2)),
    ))
}

fn orient(a: Point, b: Point, c: Point) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

fn on_segment(a: Point, b: Point, p: Point) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

fn segments_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (o1, o2, o3, o4) = (
        orient(a, b, c),
        orient(a, b, d),
        orient(c, d, a),
        orient(c, d, b),
    );
    if ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
        && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0))
    {
        return true;
    }
    (o1 == 0.0 && on_segment(a, b, c))
        || (o2 == 0.0 && on_segment(a, b, d))
        || (o3 == 0.0 && on_segment(c, d, a))
        || (o4 == 0.0 && on_segment(c, d, b))
}

/// The first pair of edges (i, j) that cross or touch, if the polygon is not simple. Edge i
/// runs from vertex i to vertex i + 1.
pub fn self_intersection(pts: &[Point]) -> Option<(usize, usize)> {
    let n = pts.len();
    for i in 0..n {
        for j in i + 1..n {
            // Neighbouring edges share a vertex; they may only meet there.
            if j == i + 1 || (i == 0 && j == n - 1) {
                continue;
            }
            if segments_cross(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]) {
                return Some((i, j));
            }
        }
    }
    None
}

/// Constructs the centroid of a simple polygon (vertices in m, in order) by two funicular
/// polygons, and checks it against the shoelace formula.
///
/// # Errors
/// [`ConstructionError::Unsupported`] for fewer than three vertices, a self-intersecting
/// polygon or one of zero area.
///
/// ```
/// use graphostatik::statics::centroid::*;
/// use graphostatik::protocol::Board;
/// // The trapezoid of LH Abb. 23, split along the diagonal BD (the fan from B).
/// use graphostatik::kernel::Point;
/// let trapezoid = [(0.0, 0.0), (4.0, 0.0), (3.0, 2.0), (1.0, 2.0)].map(|(x, y)| Point::new(x, y));
/// let d = CentroidDrawing { length_scale: 25.0, area_scale: 0.1, fan_from: 1 };
/// let mut b = Board::recording();
/// let r = construct_centroid(&mut b, &trapezoid, &d).unwrap();
/// assert!((r.centroid.x - 2.0).abs() < 1e-9 && (r.centroid.y - 8.0 / 9.0).abs() < 1e-9);
/// assert!(b.all_passed());
/// ```
pub fn construct_centroid(
    b: &mut Board,
    pts: &[Point],
    dr: &CentroidDrawing,
) -> Result<CentroidResults, ConstructionError> {
    // A polygon farther from the origin than REL_LOCAL_FRAME times its size is constructed
    // from its first vertex, and its centroid given back at the scene's coordinates.
    let size0 = pts
        .iter()
        .flat_map(|p| pts.iter().map(move |q| (p - q).norm()))
        .fold(0.0, f64::max);
    let reach = pts
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    if reach > crate::kernel::tolerance::REL_LOCAL_FRAME * size0 && !pts.is_empty() {
        let o = pts[0];
        let local: Vec<Point> = pts.iter().map(|p| Point::from(p - o)).collect();
        let r = construct_centroid(b, &local, dr)?;
        return Ok(CentroidResults {
            centroid: Point::new(r.centroid.x + o.x, r.centroid.y + o.y),
            area: r.area,
        });
    }
    let (area, exact) = check_polygon(pts)?;
    let k = 1000.0 / dr.length_scale;
    let size = pts
        .iter()
        .flat_map(|p| pts.iter().map(move |q| (p.x - q.x).hypot(p.y - q.y)))
        .fold(0.0, f64::max);
    let vs = draw_polygon(b, pts, k);
    let parts = triangle_centroids(b, &vs, dr.fan_from, k, size)?;
    if parts.is_empty() {
        return Err(ConstructionError::unsupported(
            "polygon",
            "every triangle of the fan is a sliver (area below 1e-12 of the size squared): the polygon has next to no area",
        ));
    }
    let (l1, l2) = two_funiculars(b, &vs, &parts, dr)?;
    let s = b.meet_point(&l1, &l2, Label::plain("S"), N_CENTROID)?;
    let o = b.point(Point::origin(), Role::Given, N_ORIGIN);
    let ax = b.line_dir(&o, Vector::new(1.0, 0.0), Role::Axis, N_AXIS)?;
    let ay = b.line_dir(&o, Vector::new(0.0, 1.0), Role::Axis, N_AXIS)?;
    let m = Scale::new(1.0 / k, "m");
    let xs = b.measure(&o, &s, &ax, m, Label::quiet("x", 0), N_COORD);
    b.check(&xs, "centroid x", "m", "shoelace formula", size, || {
        exact[0]
    });
    let ys = b.measure(&o, &s, &ay, m, Label::quiet("y", 0), N_COORD);
    b.check(&ys, "centroid y", "m", "shoelace formula", size, || {
        exact[1]
    });
    Ok(CentroidResults {
        centroid: Point::new(xs.g, ys.g),
        area,
    })
}

/// At least three vertices, not crossing itself, of some area: the area and the centroid by
/// the shoelace formula.
fn check_polygon(pts: &[Point]) -> Result<(f64, Point), ConstructionError> {
    let n = pts.len();
    if n < 3 {
        return Err(ConstructionError::unsupported(
            "polygon",
            "a polygon needs at least three vertices",
        ));
    }
    if let Some((i, j)) = self_intersection(pts) {
        return Err(ConstructionError::unsupported("polygon", format!(
            "the polygon is not simple: edge {i} (vertex {i} to {}) meets edge {j} (vertex {j} to {})",
            (i + 1) % n,
            (j + 1) % n
        )));
    }
    polygon_centroid(pts)
        .ok_or_else(|| ConstructionError::unsupported("polygon", "the polygon has zero area"))
}

/// The vertices (lettered A, B, … up to 26, else P with its number) and the outline.
fn draw_polygon(b: &mut Board, pts: &[Point], k: f64) -> Vec<H<Point>> {
    const NAMES: [&str; 26] = [
        "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M", "N", "O", "P", "Q", "R",
        "S", "T", "U", "V", "W", "X", "Y", "Z",
    ];
    let n = pts.len();
    let vs: Vec<H<Point>> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let label = if n <= 26 {
                Label::plain(NAMES[i])
            } else {
                Label::indexed("P", i as u32)
            };
            b.point(
                Point::new(p.x * k, p.y * k),
                Role::Given.labelled(label),
                N_VERTEX,
            )
        })
        .collect();
    let mut outline = vs.clone();
    outline.push(vs[0]);
    b.curve(&outline, Trace::Polygon, Role::Result, N_OUTLINE);
    vs
}

/// The fan of triangles from vertex `fan_from`, each centroid where two medians cross: the
/// centroids (m) with their signed areas (m²). A sliver of no area contributes nothing and
/// has no centroid to construct.
fn triangle_centroids(
    b: &mut Board,
    vs: &[H<Point>],
    fan_from: usize,
    k: f64,
    size: f64,
) -> Result<Vec<(Point, f64)>, ConstructionError> {
    let n = vs.len();
    let apex_i = fan_from % n;
    let apex = vs[apex_i];
    let mut parts = Vec::new();
    for t in 1..n - 1 {
        let (v1, v2) = (vs[(apex_i + t) % n], vs[(apex_i + t + 1) % n]);
        let signed = 0.5 * crate::kernel::cross(&(v1.g - apex.g), &(v2.g - apex.g)) / (k * k);
        if signed.abs() <= REL_AREA_EPS * size * size {
            continue;
        }
        if t + 1 < n - 1 {
            b.segment(&apex, &v2, Role::Construction, N_DIAGONAL);
        }
        let m1 = b.divide_segment(&v1, &v2, 2, "m", N_MIDPOINT)[1];
        let m2 = b.divide_segment(&apex, &v1, 2, "m", N_MIDPOINT)[1];
        let med1 = b.line_through(&apex, &m1, Role::Auxiliary, N_MEDIAN)?;
        let med2 = b.line_through(&v2, &m2, Role::Auxiliary, N_MEDIAN)?;
        let label = Label::indexed("S", t as u32);
        let g = b.meet_point(&med1, &med2, label, N_TRIANGLE_CENTROID)?;
        parts.push((g.g / k, signed));
    }
    Ok(parts)
}

/// Two funicular polygons (LH C.3, Abb. 23): the areas as vertical forces at the triangles'
/// centroids, then the same turned through 90°; the two resultants' lines.
fn two_funiculars(
    b: &mut Board,
    vs: &[H<Point>],
    parts: &[(Point, f64)],
    dr: &CentroidDrawing,
) -> Result<(H<Line>, H<Line>), ConstructionError> {
    let xmax = vs.iter().map(|v| v.g.x).fold(f64::MIN, f64::max);
    let ymax = vs.iter().map(|v| v.g.y).fold(f64::MIN, f64::max);
    let total_mm = parts.iter().map(|f| f.1.abs()).sum::<f64>() / dr.area_scale;
    let as_forces = |turn: bool| -> Vec<Force> {
        parts
            .iter()
            .map(|(g, a)| Force {
                at: *g,
                f: if turn {
                    Vector::new(*a, 0.0)
                } else {
                    Vector::new(0.0, -a)
                },
            })
            .collect()
    };
    let mut sd = SystemDrawing {
        length_scale: dr.length_scale,
        force_scale: dr.area_scale,
        pole: None,
        plan_at: Some(Point::new(xmax + 30.0, ymax)),
        unit: "m²",
    };
    let r1 = construct_system(b, &as_forces(false), &sd, &[])?;
    sd.plan_at = Some(Point::new(
        xmax + 30.0 + 0.6 * total_mm + 20.0,
        ymax + 0.5 * total_mm,
    ));
    let r2 = construct_system(b, &as_forces(true), &sd, &[])?;
    match (r1.resultant_line, r2.resultant_line) {
        (Some(l1), Some(l2)) => Ok((l1, l2)),
        _ => Err(ConstructionError::unsupported(
            "polygon",
            "the polygon has zero area",
        )),
    }
}
