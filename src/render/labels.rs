//! Where a figure's lettering goes: every label placed so that it never overprints another
//! label, a point's dot, a table, a heavy line or the sheet's edge.
//!
//! The cartographers' model of point labels: each label tries a list of candidate positions
//! around its point, the one the figure has always used first (up and to the right of the
//! point, or radially outward on a whole circle), then sixteen around it at two distances.
//! The drawn strokes are weighed as the plates do: no letter stands on a given, result or
//! force line (drawn with the medium or heavy pen); a thin construction line, an axis or a
//! transfer may run through a label only where no place within reach is free of every
//! stroke. So the candidates are tried in two passes, the first allowing no stroke under the
//! label, the second thin ones; in each, the places near the point come first, then (for a
//! line's name, a member's number) places along its line, then rings farther out, joined to
//! the point by a short leader. Of the places a pass allows, the one crossing the fewest
//! strokes is taken (the first of equals).
//! Where none is free the label is left out (the crowd rule: the books, too, letter only
//! some of a crowd of crank positions or load positions), and the figure says how many it
//! left out. Labels are placed in the order their objects were made, so that the
//! construction's early letters keep their places and the later ones of a crowd give way.
//!
//! What is placed is kept in bounding-volume hierarchies (parry2d's [`Bvh`]): each candidate
//! is a query, so a figure of thousands of labels is placed in time n log n.

use super::style::{DOT, LABEL_OFFSET};
use crate::kernel::construct::clip_to_rect;
use crate::kernel::tolerance::{MIN_DRAWN_MM, SAME_LINE_MM};
use crate::kernel::{Circle, Point, Vector};
use crate::protocol::{Board, Geom, Label, ObjId, Part};
use parry2d_f64::bounding_volume::{Aabb, BoundingVolume};
use parry2d_f64::math::Point as PPoint;
use parry2d_f64::partitioning::Bvh;
use std::collections::HashMap;

/// Advance of one letter of a label (mm): 0.62 em of the labels' 3.5 mm italic serif, the
/// width of the DejaVu Serif the exports set (Times, which browsers may use, is narrower).
const CHAR: f64 = 2.17;
/// The letters set wider than [`CHAR`] (DejaVu Serif Italic's m is 0.92 em, its W 1.0 em),
/// and how many of `CHAR` each counts for.
const WIDE: &str = "mwMWΦΨΩ";
const WIDE_CHAR: f64 = 1.5;
/// Advance of one figure of a label's subscript (mm): 0.64 em of its 2.4 mm.
const INDEX_CHAR: f64 = 1.54;
/// The space between a letter and its subscript (mm): the subscript is set right after its
/// letter, on one line with it; the italic capital leans over the subscript's start by
/// less than this (0.2 mm as usvg lays out "A₃" in DejaVu Serif).
const INDEX_GAP: f64 = 0.2;
/// How far the italic's last letter leans out past its advance at the top (mm): the
/// capitals' 2.5 mm at DejaVu Serif Italic's slant of some 11°, as usvg inks K beside O.
const OVERHANG: f64 = 0.45;
/// Height of a label above its baseline (mm): the capitals of 3.5 mm type.
const ASCENT: f64 = 2.5;
/// Depth below the baseline (mm): descenders, or a subscript set 0.9 mm lower.
const DESCENT: f64 = 0.9;
const INDEX_DESCENT: f64 = 1.4;
/// Clear space kept around a label's box (mm).
const PAD: f64 = 0.15;
/// How far inside the sheet's edge a label stays (mm).
const EDGE: f64 = 1.0;
/// The largest sheet coordinate (mm) the placer works at: 1,000 km of paper. A figure beyond
/// it (a scene of absurd values that still constructs) keeps its labels where they first
/// stand: the hierarchy's binning is not made for coordinates near f64's range.
const MAX_SHEET_COORD: f64 = 1e9;
/// The grid (mm) the hierarchy's boxes are rounded out to: boxes whose centres differ by
/// less than a subnormal would make its binning divide by their spread.
const GRID: f64 = 1e-6;
/// Rings of candidates farther out, in multiples of the label's offset (up to 14 mm), each
/// drawn with a leader: where a label's point is the centre of a star of heavy lines (a
/// polar diagram's O), the free gaps between the rays open only some way out.
const RINGS: [f64; 4] = [2.5, 4.0, 6.0, 9.0];
/// Where along its drawn length a line's name goes when none of the places beside its middle
/// is free, in this order (fractions of the length): a member's number slides along its
/// member, as the plates write the numbers of crossed diagonals off their crossing (LH Abb.
/// 19), before it takes a leader.
const SLIDE: [f64; 4] = [1.0 / 3.0, 2.0 / 3.0, 0.25, 0.75];

/// A stroke drawn on the sheet, for the lettering to keep clear of: heavy where it is drawn
/// with a medium or heavy pen ([`is_heavy`]), which no letter may lie on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stroke {
    pub a: Point,
    pub b: Point,
    pub heavy: bool,
}

/// Whether a line of `role` is one no letter may lie on: a given, result, force, velocity,
/// guide or reduced line, drawn with the medium or heavy pen. A thin construction line, an
/// axis or a transfer may be crossed by a letter where no free place is within reach, as
/// the plates do.
pub(crate) fn is_heavy(role: crate::protocol::Role) -> bool {
    use crate::protocol::Role;
    !matches!(role, Role::Construction | Role::Auxiliary | Role::Axis)
}

/// A placed label: its text's baseline-left point on the sheet (mm), and the leader from its
/// point where it had to move away.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Placed {
    /// Baseline-left of the text.
    pub at: Point,
    /// A leader from the labelled point to the label's box, where it stands off.
    pub leader: Option<(Point, Point)>,
}

/// The labels of a figure, by the object they letter.
#[derive(Debug, Default)]
pub(crate) struct Placement {
    placed: HashMap<ObjId, Placed>,
    /// How many labels were to be written: every point's, line's and curve's, and the names
    /// of lines and forces of the parts that had room for all of theirs.
    pub labels: usize,
    /// How many found no free place and were left out.
    pub crowded: usize,
    /// Names of segments and forces (S₃, P₂) not written because their part had no room
    /// for all of them: a plan is lettered in full or not at all.
    pub withheld: usize,
    /// The names written after an object's own, of the segments drawn on its line ("S₁, S₂"
    /// where two members of a plan carry the same force).
    joined: HashMap<ObjId, Vec<Label>>,
}

impl Placement {
    /// Where the label of `id` goes.
    pub fn get(&self, id: ObjId) -> Option<&Placed> {
        self.placed.get(&id)
    }

    /// The names written after `id`'s own, on one line with it: those of the segments drawn
    /// on the same line.
    pub fn joined(&self, id: ObjId) -> &[Label] {
        self.joined.get(&id).map_or(&[], Vec::as_slice)
    }
}

/// A label to place: its object, the point it letters, where it has always stood, the size of
/// its text ([`extent`], reckoned once for all its candidates).
#[derive(Clone, Copy)]
struct Request {
    id: ObjId,
    anchor: Point,
    first: Point,
    size: (f64, f64),
    /// A line's drawn ends, where its name may slide along it ([`SLIDE`]) before it takes a
    /// leader; `None` for a point's, a curve's or a segment's.
    slide: Option<(Point, Point)>,
}

/// The names of the segments and forces of one part of the sheet (a force plan's S₁ … S₇),
/// placed together or not at all. Segments of one kind drawn on one line share a request:
/// `ends` are each request's segment and kind, `joined` the names written after its own (each
/// with the request it makes alone).
struct Group {
    requests: Vec<Request>,
    ends: Vec<(Point, Point, Kind)>,
    joined: Vec<Vec<(Request, Label)>>,
    /// The requests by the cells ([`cell`]) of both ends of their segments: a segment's twin
    /// is looked for among its neighbours only, so a part's names are grouped in a time
    /// linear in their number.
    cells: HashMap<(i64, i64), Vec<usize>>,
}

/// The cell, `SAME_LINE_MM` wide, that holds `p`: two points nearer than that lie in the
/// same cell or in neighbouring ones.
fn cell(p: Point) -> (i64, i64) {
    // Sheet coordinates are at most metres in millimetres: far inside i64 after the division.
    (
        (p.x / SAME_LINE_MM).floor() as i64,
        (p.y / SAME_LINE_MM).floor() as i64,
    )
}

impl Group {
    /// Adds the name of the segment `a`–`b`: to the request of a segment of its kind drawn
    /// on the same line, if there is one (its text then reads "S₁, S₂"), else as a request of
    /// its own. A load drawn along a member keeps its own name.
    fn add(&mut self, r: Request, (a, b): (Point, Point), kind: Kind, label: &Label) {
        match self.twin(a, b, kind) {
            Some(i) => self.joined[i].push((r, label.clone())),
            None => {
                let i = self.requests.len();
                self.requests.push(r);
                self.ends.push((a, b, kind));
                self.joined.push(Vec::new());
                self.cells.entry(cell(a)).or_default().push(i);
                if cell(b) != cell(a) {
                    self.cells.entry(cell(b)).or_default().push(i);
                }
            }
        }
    }

    /// The first request whose segment is `a`–`b` (either way round, ends within
    /// `SAME_LINE_MM`) and of `kind`: among those with an end in `a`'s cell or its eight
    /// neighbours.
    fn twin(&self, a: Point, b: Point, kind: Kind) -> Option<usize> {
        let near = |u: Point, v: Point| (u - v).norm() < SAME_LINE_MM;
        let same = |i: usize| {
            let (p, q, k) = self.ends[i];
            k == kind && ((near(p, a) && near(q, b)) || (near(p, b) && near(q, a)))
        };
        let (x, y) = cell(a);
        (x - 1..=x + 1)
            .flat_map(|cx| (y - 1..=y + 1).map(move |cy| (cx, cy)))
            .filter_map(|c| self.cells.get(&c))
            .flat_map(|ids| ids.iter().copied().filter(|&i| same(i)))
            .min()
    }
}

/// What a named segment is: a force (an arrow) or not, and its role on the sheet.
type Kind = (bool, crate::protocol::Role);

/// The width (mm) of the ", " between names written on one line: a comma and a space of the
/// serif face, about 0.64 em, taken as one average character and a fifth.
const JOIN_SEPARATOR: f64 = 1.2 * CHAR;

/// The size of a label's text (width, depth below the baseline).
fn extent(label: &Label) -> (f64, f64) {
    let text = crate::fmt::subscripts(&label.base);
    let small = text
        .chars()
        .filter(|c| crate::fmt::is_subscript(*c))
        .count() as f64;
    let wide = text.chars().filter(|c| WIDE.contains(*c)).count() as f64;
    let letters =
        text.chars().count() as f64 - small + small * INDEX_CHAR / CHAR + wide * (WIDE_CHAR - 1.0);
    match label.index {
        Some(i) => (
            letters * CHAR + INDEX_GAP + i.to_string().len() as f64 * INDEX_CHAR + OVERHANG,
            INDEX_DESCENT,
        ),
        None => (letters * CHAR + OVERHANG, DESCENT),
    }
}

/// The box of a label of `size` ([`extent`]) whose baseline starts at `at`.
fn text_box(at: Point, (w, depth): (f64, f64)) -> Aabb {
    Aabb::new(
        PPoint::new(at.x - PAD, at.y - depth - PAD),
        PPoint::new(at.x + w + PAD, at.y + ASCENT + PAD),
    )
}

/// The box of `label` written with its baseline starting at `at` (`[x0, y0, x1, y1]`, mm).
pub(crate) fn label_box(label: &Label, at: Point) -> [f64; 4] {
    let b = text_box(at, extent(label));
    [b.mins.x, b.mins.y, b.maxs.x, b.maxs.y]
}

/// The baseline-left points of the eight positions around `p` at distance `d` (mm) of a
/// label of `size` ([`extent`]), the first position given first: NE, NW, SE, SW, E, W, N, S.
fn around(p: Point, d: f64, (w, depth): (f64, f64)) -> [Point; 8] {
    let up = p.y + d + depth;
    let down = p.y - d - ASCENT;
    let mid = p.y - (ASCENT - depth) / 2.0;
    let right = p.x + d;
    let left = p.x - d - w;
    let centre = p.x - w / 2.0;
    [
        Point::new(right, up),
        Point::new(left, up),
        Point::new(right, down),
        Point::new(left, down),
        Point::new(right + DOT, mid),
        Point::new(left - DOT, mid),
        Point::new(centre, up + DOT),
        Point::new(centre, down - DOT),
    ]
}

/// The baseline-left points of eight more positions around `p`, between those of
/// [`around`]: each box's centre out along the directions 22.5°, 67.5° … from `p`, far
/// enough that the box keeps `d` (mm) from it.
fn between(p: Point, d: f64, (w, depth): (f64, f64)) -> impl Iterator<Item = Point> {
    let h = ASCENT + depth;
    [22.5f64, 157.5, -22.5, -157.5, 67.5, 112.5, -67.5, -112.5]
        .into_iter()
        .map(move |deg| {
            let u = Vector::new(deg.to_radians().cos(), deg.to_radians().sin());
            let c = p + u * (d + u.x.abs() * w / 2.0 + u.y.abs() * h / 2.0);
            Point::new(c.x - w / 2.0, c.y - (ASCENT - depth) / 2.0)
        })
}

/// The sixteen positions around `p` at distance `d`: [`around`]'s eight, then
/// [`between`]'s.
fn all_around(p: Point, d: f64, size: (f64, f64)) -> impl Iterator<Item = Point> {
    around(p, d, size).into_iter().chain(between(p, d, size))
}

/// The hierarchy's box of a stroke from `a` to `b`.
fn stroke_box(a: Point, b: Point) -> Aabb {
    gridded(&Aabb::new(
        PPoint::new(a.x.min(b.x), a.y.min(b.y)),
        PPoint::new(a.x.max(b.x), a.y.max(b.y)),
    ))
}

/// What is on the sheet already: the boxes placed and the strokes drawn, each in a
/// hierarchy for the queries.
struct Taken {
    bvh: Bvh,
    boxes: Vec<Aabb>,
    sheet: Aabb,
    stroke_bvh: Bvh,
    strokes: Vec<Stroke>,
}

/// A box rounded out to the [`GRID`]: what the hierarchy keeps (the exact box is tested
/// after it).
fn gridded(b: &Aabb) -> Aabb {
    let down = |v: f64| (v / GRID).floor() * GRID;
    let up = |v: f64| (v / GRID).ceil() * GRID;
    Aabb::new(
        PPoint::new(down(b.mins.x), down(b.mins.y)),
        PPoint::new(up(b.maxs.x), up(b.maxs.y)),
    )
}

impl Taken {
    fn add(&mut self, b: Aabb) {
        self.bvh.insert(gridded(&b), self.boxes.len() as u32);
        self.boxes.push(b);
    }

    /// Takes back every box added since there were `len`: the hierarchy keeps their leaves,
    /// but an empty box meets nothing.
    fn retract(&mut self, len: usize) {
        for b in &mut self.boxes[len..] {
            *b = Aabb::new_invalid();
        }
    }

    /// Whether `b` lies on the sheet and clear of every label and dot placed.
    fn free(&self, b: &Aabb) -> bool {
        self.sheet.contains(b)
            && !self
                .bvh
                .intersect_aabb(b)
                .any(|i| self.boxes[i as usize].intersects(b))
    }

    /// How many strokes pass through `b`: (heavy, thin).
    fn crossings(&self, b: &Aabb) -> (usize, usize) {
        let mut n = (0, 0);
        for i in self.stroke_bvh.intersect_aabb(b) {
            let s = self.strokes[i as usize];
            if clip_to_rect(s.a, s.b, rect(b)).is_some() {
                match s.heavy {
                    true => n.0 += 1,
                    false => n.1 += 1,
                }
            }
        }
        n
    }
}

/// Every label at its first position: for a sheet too large to place on.
fn unplaced(board: &Board) -> Placement {
    let circles = full_circles(board);
    let mut out = Placement::default();
    for o in board.drawn_objects() {
        if let Some((_, first)) = where_first(o, &circles) {
            out.placed.insert(
                o.id,
                Placed {
                    at: first,
                    leader: None,
                },
            );
        }
    }
    out.labels = out.placed.len();
    out
}

/// The point a label letters and where it has always stood: a point's, radially outward on
/// a whole circle or up and to the right; a line's or a segment's, beside its middle; a
/// curve's, over its highest point. `None` for an object without a drawn label.
fn where_first(o: &crate::protocol::Object, circles: &[Circle]) -> Option<(Point, Point)> {
    if o.label.is_empty() {
        return None;
    }
    match &o.geom {
        // A mark on an axis (a crank angle under a developed diagram) is lettered under it,
        // centred, as a scale is.
        Geom::Point { at } if o.role == crate::protocol::Role::Axis => {
            let w = extent(&o.label).0;
            Some((*at, at + Vector::new(-w / 2.0, -(LABEL_OFFSET + ASCENT))))
        }
        Geom::Point { at } => Some((*at, first_position(circles, at))),
        // A line is lettered beside the middle of its drawn length: a member between its
        // joints (LH Abb. 17's numbers), a funicular's closing line s.
        Geom::Line { line, extent } => {
            let mid = line.point_at(0.5 * (extent[0] + extent[1]));
            Some((
                mid,
                mid + Vector::new(LABEL_OFFSET * 0.6, LABEL_OFFSET * 0.6),
            ))
        }
        Geom::Curve { points, .. } => (points.iter())
            .max_by(|a, b| a.y.total_cmp(&b.y))
            .map(|top| (*top, top + Vector::new(1.0, 1.5))),
        // An angle's arc is lettered inside the angle, beside the arc's middle.
        Geom::Arc { arc } => {
            let mid = arc.point_at_fraction(0.5);
            let out = (mid - arc.circle.center) / arc.circle.radius;
            let (w, depth) = extent(&o.label);
            let centre = mid + out * (0.6 * LABEL_OFFSET + 0.5 * w.max(ASCENT));
            Some((mid, centre - Vector::new(0.5 * w, 0.5 * (ASCENT - depth))))
        }
        // A segment or a force is lettered beside its middle: a member force S₃ in the force
        // plan, a reaction A, a resultant R.
        Geom::Segment { segment } | Geom::Vector { segment } => {
            let mid = Point::from((segment.a.coords + segment.b.coords) * 0.5);
            Some((
                mid,
                mid + Vector::new(LABEL_OFFSET * 0.6, LABEL_OFFSET * 0.6),
            ))
        }
        _ => None,
    }
}

/// The corners of a box as `[x0, y0, x1, y1]`.
fn rect(b: &Aabb) -> [f64; 4] {
    [b.mins.x, b.mins.y, b.maxs.x, b.maxs.y]
}

/// The part of the segment p–q within the box, if any (finite points only).
fn clipped(b: &Aabb, p: Point, q: Point) -> Option<(Point, Point)> {
    let finite = p.x.is_finite() && p.y.is_finite() && q.x.is_finite() && q.y.is_finite();
    let (t0, t1) = clip_to_rect(p, q, rect(b)).filter(|_| finite)?;
    let d = q - p;
    Some((p + d * t0, p + d * t1))
}

/// The labels of `board`'s drawn points and curves placed on a sheet whose drawable region
/// is `sheet` (`[x0, y0, x1, y1]`, mm), clear of the `strokes` drawn where they can be;
/// `drawn(p)` tells whether a point is drawn at all.
pub(crate) fn place(
    board: &Board,
    sheet: [f64; 4],
    strokes: Vec<Stroke>,
    drawn: &dyn Fn(&Point) -> bool,
) -> Placement {
    let [x0, y0, x1, y1] = sheet;
    if !sheet.iter().all(|v| v.abs() <= MAX_SHEET_COORD) {
        return unplaced(board);
    }
    let region = Aabb::new(PPoint::new(x0, y0), PPoint::new(x1, y1));
    let strokes: Vec<Stroke> = strokes
        .into_iter()
        .filter_map(|s| clipped(&region, s.a, s.b).map(|(a, b)| Stroke { a, b, ..s }))
        .collect();
    let stroke_boxes: Vec<Aabb> = strokes.iter().map(|s| stroke_box(s.a, s.b)).collect();
    let mut taken = Taken {
        bvh: Bvh::new(),
        boxes: Vec::new(),
        sheet: Aabb::new(
            PPoint::new(x0 + EDGE, y0 + EDGE),
            PPoint::new(x1 - EDGE, y1 - EDGE),
        ),
        stroke_bvh: Bvh::from_leaves(Default::default(), &stroke_boxes),
        strokes,
    };
    let (requests, groups) = requests(board, &region, drawn, &mut taken);
    let mut out = Placement {
        labels: requests.len(),
        ..Placement::default()
    };
    for r in requests {
        // The crowd rule: a label with no free place is left out, so that the lettering
        // that is written can be read (the books letter only some of a crowd of positions).
        let Some(placed) = place_one(&mut taken, &r) else {
            out.crowded += 1;
            continue;
        };
        taken.add(text_box(placed.at, r.size));
        out.placed.insert(r.id, placed);
    }
    for g in groups {
        place_group(&mut taken, g, &mut out);
    }
    out
}

/// A part's names of segments and forces, after every other label: all of them where each
/// finds a free place, else none (the books letter a plan in full or leave it to its
/// letters; a plan named in part would leave the reader guessing which line is which).
///
/// The names of segments on one line are written together ("S₁, S₂"); where the part has
/// no room for that, each on its own.
fn place_group(taken: &mut Taken, g: Group, out: &mut Placement) {
    let names = g.requests.len() + g.joined.iter().map(Vec::len).sum::<usize>();
    let together = g.joined.iter().any(|j| !j.is_empty());
    let placed = (together.then(|| try_group(taken, &g, true)).flatten())
        .or_else(|| try_group(taken, &g, false));
    let Some((placed, joins)) = placed else {
        out.withheld += names;
        return;
    };
    out.labels += names;
    out.placed.extend(placed);
    for (i, joined) in g.joined.into_iter().enumerate() {
        if joins.binary_search(&i).is_ok() {
            out.joined.insert(
                g.requests[i].id,
                joined.into_iter().map(|(_, l)| l).collect(),
            );
        }
    }
}

/// Every name of a group placed, those on one line `together` or each alone: the places and
/// which requests were written together (ascending); `None`, with nothing taken, where one has
/// no room.
#[allow(clippy::type_complexity)]
fn try_group(
    taken: &mut Taken,
    g: &Group,
    together: bool,
) -> Option<(Vec<(ObjId, Placed)>, Vec<usize>)> {
    let before = taken.boxes.len();
    let mut placed = Vec::with_capacity(g.requests.len());
    let mut joins = Vec::new();
    for (i, (r, joined)) in g.requests.iter().zip(&g.joined).enumerate() {
        let ok = if together && !joined.is_empty() {
            let size = joined.iter().fold(r.size, |(w, d), (q, _)| {
                (w + JOIN_SEPARATOR + q.size.0, d.max(q.size.1))
            });
            joins.push(i);
            take_place(taken, &Request { size, ..*r }, &mut placed)
        } else {
            let mut alone = std::iter::once(r).chain(joined.iter().map(|(q, _)| q));
            alone.all(|q| take_place(taken, q, &mut placed))
        };
        if !ok {
            taken.retract(before);
            return None;
        }
    }
    Some((placed, joins))
}

/// Places `r` where [`place_one`] finds room and takes that room; false where there is none.
fn take_place(taken: &mut Taken, r: &Request, placed: &mut Vec<(ObjId, Placed)>) -> bool {
    let Some(p) = place_one(taken, r) else {
        return false;
    };
    taken.add(text_box(p.at, r.size));
    placed.push((r.id, p));
    true
}

/// The labels to place, in the order their objects were made, and apart from them the names
/// of segments and forces by part, in the order of their parts' first; every drawn point's
/// dot is put on the sheet as it is met.
fn requests(
    board: &Board,
    region: &Aabb,
    drawn: &dyn Fn(&Point) -> bool,
    taken: &mut Taken,
) -> (Vec<Request>, Vec<Group>) {
    let circles = full_circles(board);
    let inside = |p: &Point| region.contains_local_point(&PPoint::new(p.x, p.y));
    let mut requests = Vec::new();
    // A segment's or a force's name (S₃ in a force plan, a load P₂) comes after every
    // point's, line's and curve's: it only takes room they leave (Bow's letters keep theirs
    // in a crowded plan).
    let mut groups: Vec<Group> = Vec::new();
    let mut by_part: HashMap<Part, usize> = HashMap::new();
    for o in board.drawn_objects() {
        // A table's lettering (a heading, an area's sign, an evaluation) is no place for a
        // label either.
        if let Geom::Table { at, rows } = &o.geom {
            for (block, p) in super::extent::table_blocks(*at, rows) {
                let (w, h) = super::extent::table_size(&block);
                taken.add(Aabb::new(
                    PPoint::new(p.x, p.y - h),
                    PPoint::new(p.x + w, p.y),
                ));
            }
        }
        if let Geom::Point { at } = &o.geom {
            if !(drawn(at) && inside(at)) {
                continue;
            }
            taken.add(Aabb::new(
                PPoint::new(at.x - DOT - PAD, at.y - DOT - PAD),
                PPoint::new(at.x + DOT + PAD, at.y + DOT + PAD),
            ));
        }
        if let Some((anchor, first)) = where_first(o, &circles).filter(|(a, _)| inside(a)) {
            let slide = match &o.geom {
                Geom::Line { line, extent } => {
                    Some((line.point_at(extent[0]), line.point_at(extent[1])))
                }
                _ => None,
            };
            let r = Request {
                id: o.id,
                anchor,
                first,
                size: extent(&o.label),
                slide,
            };
            match o.geom {
                // A segment too short to be drawn (a zero force) has no line to name.
                Geom::Segment { segment } | Geom::Vector { segment }
                    if (segment.b - segment.a).norm() <= MIN_DRAWN_MM => {}
                Geom::Segment { segment } | Geom::Vector { segment } => {
                    let part = (board.step(o.step)).map_or(Part::default(), |s| s.part);
                    let i = *by_part.entry(part).or_insert_with(|| {
                        groups.push(Group {
                            requests: Vec::new(),
                            ends: Vec::new(),
                            joined: Vec::new(),
                            cells: HashMap::new(),
                        });
                        groups.len() - 1
                    });
                    let kind = (matches!(o.geom, Geom::Vector { .. }), o.role);
                    groups[i].add(r, (segment.a, segment.b), kind, &o.label);
                }
                _ => requests.push(r),
            }
        }
    }
    (requests, groups)
}

/// How much a candidate place of a label may cross: the passes of [`place_one`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Crossing {
    /// No stroke at all.
    Nothing,
    /// Thin construction lines, axes and transfers, no heavy line.
    Thin,
}

/// The distances (in multiples of the label's offset) of the places close enough to their
/// point to need no leader: beside it, and one step out.
const NEAR: [f64; 2] = [0.6, 1.2];

/// The best free position of a label, in passes that allow more and more under it
/// ([`Crossing`]): first a place on no stroke at all, near its point (where it has always
/// stood, then the places around it), along its line for a line's name, then on the rings
/// farther out with a leader; then the same allowing thin construction lines. Of the places
/// a pass allows, the one that crosses the fewest strokes is taken (the first of equals). A
/// label never stands on a given, result or force line: where no place within reach is
/// free of them, it is left out ([`Placement::crowded`]).
fn place_one(taken: &mut Taken, r: &Request) -> Option<Placed> {
    [Crossing::Nothing, Crossing::Thin]
        .into_iter()
        .find_map(|allow| place_pass(taken, r, allow))
}

/// One pass of [`place_one`]: the best place near, along the line, then on the rings, whose
/// box crosses no more than `allow`.
fn place_pass(taken: &Taken, r: &Request, allow: Crossing) -> Option<Placed> {
    let near = std::iter::once(r.first).chain(
        NEAR.iter()
            .flat_map(|k| all_around(r.anchor, k * LABEL_OFFSET, r.size)),
    );
    if let Some(at) = least_crossed(taken, r.size, near, allow) {
        return Some(Placed { at, leader: None });
    }
    if let Some((a, b)) = r.slide {
        let along = SLIDE
            .iter()
            .flat_map(|t| around(a + (b - a) * *t, 0.6 * LABEL_OFFSET, r.size));
        if let Some(at) = least_crossed(taken, r.size, along, allow) {
            return Some(Placed { at, leader: None });
        }
    }
    RINGS.iter().find_map(|k| {
        let ring = all_around(r.anchor, k * LABEL_OFFSET, r.size);
        let at = least_crossed(taken, r.size, ring, allow)?;
        let end = nearest_on(&text_box(at, r.size), r.anchor);
        Some(Placed {
            at,
            leader: Some((r.anchor, end)),
        })
    })
}

/// Of the candidates whose box is free and crosses no more than `allow`, the first that
/// crosses the fewest strokes (heavy ones first, then thin).
fn least_crossed(
    taken: &Taken,
    size: (f64, f64),
    candidates: impl Iterator<Item = Point>,
    allow: Crossing,
) -> Option<Point> {
    let mut best: Option<((usize, usize), Point)> = None;
    for at in candidates {
        let b = text_box(at, size);
        if !taken.free(&b) {
            continue;
        }
        let n = taken.crossings(&b);
        let allowed = match allow {
            Crossing::Nothing => n == (0, 0),
            Crossing::Thin => n.0 == 0,
        };
        if allowed && best.is_none_or(|(m, _)| n < m) {
            best = Some((n, at));
            if n == (0, 0) {
                break;
            }
        }
    }
    best.map(|(_, at)| at)
}

/// The point of a box nearest to `p` (where a leader from `p` ends).
fn nearest_on(b: &Aabb, p: Point) -> Point {
    Point::new(
        p.x.clamp(b.mins.x + PAD, b.maxs.x - PAD),
        p.y.clamp(b.mins.y + PAD, b.maxs.y - PAD),
    )
}

/// The whole circles of the figure, for the radial first position.
fn full_circles(board: &Board) -> Vec<Circle> {
    board
        .drawn_objects()
        .filter_map(|o| match &o.geom {
            Geom::Circle {
                circle, full: true, ..
            } => Some(*circle),
            _ => None,
        })
        .collect()
}

/// Where a point's label has always stood: radially outward if the point lies on a whole
/// circle drawn in the figure, otherwise up and to the right.
fn first_position(circles: &[Circle], p: &Point) -> Point {
    for circle in circles {
        let v = p - circle.center;
        let d = v.norm();
        let eps = crate::kernel::tolerance::REL_LAYOUT_EPS * circle.radius;
        if d > 0.0 && (d - circle.radius).abs() <= eps {
            return p + v * ((LABEL_OFFSET + 1.2) / d) + Vector::new(-1.0, -1.2);
        }
    }
    p + Vector::new(LABEL_OFFSET * 0.6, LABEL_OFFSET * 0.6)
}

/// What a figure's lettering overprints, measured on the boxes the placer works with
/// (without their clear space).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Overprints {
    /// Pairs of labels whose boxes overlap.
    pub pairs: usize,
    /// Labels over a point's dot.
    pub on_dots: usize,
    /// Labels that cross the edge of `sheet` (where one was given).
    pub off_sheet: usize,
}

impl Overprints {
    #[cfg(test)]
    fn pairs_and_dots(&self) -> (usize, usize) {
        (self.pairs, self.on_dots)
    }
}

/// The overprints of labels standing where `at` says (`None`: not written), on a figure
/// whose lettering may use `sheet` (`[x0, y0, x1, y1]`, mm). The pairs are found by a
/// bounding-volume hierarchy, in time n log n.
pub(crate) fn overprints(
    board: &Board,
    at: &dyn Fn(&crate::protocol::Object) -> Option<Point>,
    sheet: Option<[f64; 4]>,
) -> Overprints {
    let tight = |b: Aabb| Aabb::new(b.mins + Vector::repeat(PAD), b.maxs - Vector::repeat(PAD));
    let mut boxes = Vec::new();
    let mut dots = Vec::new();
    for o in board.drawn_objects() {
        if let Geom::Point { at: p } = &o.geom {
            let inside = sheet
                .is_none_or(|[x0, y0, x1, y1]| p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1);
            if inside && p.x.is_finite() && p.y.is_finite() {
                dots.push(gridded(&Aabb::new(
                    PPoint::new(p.x - DOT, p.y - DOT),
                    PPoint::new(p.x + DOT, p.y + DOT),
                )));
            }
        }
        if let Some(p) = at(o) {
            boxes.push(tight(text_box(p, extent(&o.label))));
        }
    }
    // Beyond the placer's largest sheet the hierarchy's binning is not to be trusted: every
    // pair is tested instead (only absurd scenes come here).
    let huge = (boxes.iter().chain(&dots)).any(|b| {
        !(b.mins.coords.amax() <= MAX_SHEET_COORD && b.maxs.coords.amax() <= MAX_SHEET_COORD)
    });
    let leaves: Vec<Aabb> = boxes.iter().map(gridded).collect();
    let (bvh, dot_bvh) = match huge {
        true => (Bvh::new(), Bvh::new()),
        false => (
            Bvh::from_leaves(Default::default(), &leaves),
            Bvh::from_leaves(Default::default(), &dots),
        ),
    };
    let near = |tree: &Bvh, n: usize, i: usize| -> Vec<usize> {
        match huge {
            true => (0..n).collect(),
            false => tree
                .intersect_aabb(&leaves[i])
                .map(|j| j as usize)
                .collect(),
        }
    };
    let mut out = Overprints::default();
    for (i, b) in boxes.iter().enumerate() {
        out.pairs += (near(&bvh, boxes.len(), i).into_iter())
            .filter(|&j| j > i && boxes[j].intersects(b))
            .count();
        if (near(&dot_bvh, dots.len(), i).into_iter()).any(|j| dots[j].intersects(b)) {
            out.on_dots += 1;
        }
        if let Some([x0, y0, x1, y1]) = sheet {
            let within = b.mins.x >= x0 && b.mins.y >= y0 && b.maxs.x <= x1 && b.maxs.y <= y1;
            out.off_sheet += usize::from(!within);
        }
    }
    out
}

/// How many written labels have a line through their letters (their box without its clear
/// space): `(heavy, thin)`, a label counted once, as heavy where any heavy line crosses it.
/// `at` says where each label stands (`None`: not written).
pub(crate) fn lines_through(
    board: &Board,
    at: &dyn Fn(&crate::protocol::Object) -> Option<Point>,
    strokes: &[Stroke],
) -> (usize, usize) {
    let finite = |p: &Point| p.x.abs() <= MAX_SHEET_COORD && p.y.abs() <= MAX_SHEET_COORD;
    let strokes: Vec<Stroke> = (strokes.iter().copied())
        .filter(|s| finite(&s.a) && finite(&s.b))
        .collect();
    let leaves: Vec<Aabb> = strokes.iter().map(|s| stroke_box(s.a, s.b)).collect();
    let bvh = Bvh::from_leaves(Default::default(), &leaves);
    let mut out = (0, 0);
    for o in board.drawn_objects() {
        let Some(p) = at(o).filter(finite) else {
            continue;
        };
        let b = text_box(p, extent(&o.label));
        let tight = Aabb::new(b.mins + Vector::repeat(PAD), b.maxs - Vector::repeat(PAD));
        let (mut heavy, mut thin) = (false, false);
        for i in bvh.intersect_aabb(&gridded(&tight)) {
            let s = strokes[i as usize];
            if clip_to_rect(s.a, s.b, rect(&tight)).is_some() {
                heavy |= s.heavy;
                thin |= !s.heavy;
            }
        }
        if heavy {
            out.0 += 1;
        } else if thin {
            out.1 += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::protocol::BoardConfig;

    /// A figure's name, its overprints before and after (pairs, on dots), its labels left out
    /// and its labels.
    type Report = (String, (usize, usize), (usize, usize), usize, usize);

    /// Every bundled figure, its labels as the figure places them and as they stood before
    /// the placer (each at its first position): overlapping pairs and labels on a dot.
    fn bundled() -> Vec<Report> {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
        let mut paths: Vec<_> = (std::fs::read_dir(dir).unwrap())
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        paths.sort();
        let mut out = Vec::new();
        for p in &paths {
            let scene = crate::scene::AnyScene::load(p).unwrap();
            let problem = scene.problem();
            let board = problem.construct(BoardConfig::DRAWING).unwrap();
            let board = crate::render::layout::laid_out(&board).unwrap_or(board);
            let circles = full_circles(&board);
            let first = |o: &crate::protocol::Object| match &o.geom {
                Geom::Point { at } if !o.label.is_empty() => Some(first_position(&circles, at)),
                _ => None,
            };
            let placed = crate::render::figure::placement(&problem.figure_meta(), &board);
            let now = |o: &crate::protocol::Object| placed.get(o.id).map(|p| p.at);
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            out.push((
                name,
                overprints(&board, &first, None).pairs_and_dots(),
                overprints(&board, &now, None).pairs_and_dots(),
                placed.crowded,
                placed.labels,
            ));
        }
        out
    }

    /// No label of a bundled figure overprints another label or a point's dot; where a
    /// figure has more labels than room (the crane bridge's nineteen crane positions over one
    /// girder), the crowd rule leaves the labels without room out, and fewer than one in ten.
    #[test]
    fn no_label_overprints_another_or_a_dot() {
        for (name, before, after, crowded, labels) in bundled() {
            assert_eq!(
                after,
                (0, 0),
                "{name}: {after:?} overprints (was {before:?})"
            );
            assert!(
                crowded * 10 < labels.max(1),
                "{name}: {crowded} of {labels} left out"
            );
        }
    }

    /// A part's names of lines are written all or none: thirty names crowded on a sheet of
    /// 10 mm are withheld together (taking back those that found room), and one in another
    /// part takes the room they left.
    #[test]
    fn a_part_without_room_for_all_its_names_of_lines_gets_none() {
        use crate::protocol::{Note, Role, Topic};
        let n = Note::new("s", Topic::Custom("t"));
        let mut b = Board::recording();
        let seg = |b: &mut Board, x: f64, name: String| {
            let p = b.point(Point::new(x, 0.0), Role::Given, n.clone());
            let q = b.point(Point::new(x + 1.0, 0.0), Role::Given, n.clone());
            b.segment(
                &p,
                &q,
                Role::Force.labelled(Label::from_name(&name)),
                n.clone(),
            )
        };
        b.set_part(Part::at(0, 0));
        for k in 0..30 {
            let y = f64::from(k) * 0.1;
            let p = b.point(Point::new(-3.0, y), Role::Given, n.clone());
            let q = b.point(Point::new(-2.0, y), Role::Given, n.clone());
            let name = Label::from_name(&format!("S{k}"));
            b.segment(&p, &q, Role::Force.labelled(name), n.clone());
        }
        b.set_part(Part::at(1, 0));
        let alone = seg(&mut b, 2.0, "R".into());
        let placed = place(&b, [-5.0, -5.0, 5.0, 5.0], Vec::new(), &|_| true);
        assert_eq!((placed.withheld, placed.labels, placed.crowded), (30, 1, 0));
        assert!(placed.get(alone.id).is_some());
        let written = (b.objects().iter()).filter(|o| placed.get(o.id).is_some());
        assert_eq!(written.count(), 1);
    }

    /// Members of equal force drawn on one line of a plan share one name, "S₁, S₂"; a force
    /// of another kind on that line (a load along a member) keeps its own, and a segment too
    /// short to be drawn (a zero force) is not named.
    #[test]
    fn segments_on_one_line_share_a_name_and_zero_ones_get_none() {
        use crate::protocol::{Note, Role, Topic};
        let n = Note::new("s", Topic::Custom("t"));
        let mut b = Board::recording();
        let p = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        let q = b.point(Point::new(30.0, 0.0), Role::Given, n.clone());
        let q2 = b.point(Point::new(30.0, 0.01), Role::Given, n.clone());
        let name = |s: &str| Role::Result.labelled(Label::from_name(s));
        let s1 = b.segment(&p, &q, name("S1"), n.clone());
        let s2 = b.segment(&q2, &p, name("S2"), n.clone());
        let load = b.segment(
            &p,
            &q,
            Role::Force.labelled(Label::from_name("P1")),
            n.clone(),
        );
        let zero = b.segment(&p, &p, name("S3"), n.clone());
        let placed = place(&b, [-50.0, -50.0, 50.0, 50.0], Vec::new(), &|_| true);
        assert!(placed.get(s1.id).is_some() && placed.get(s2.id).is_none());
        let joined: Vec<String> = (placed.joined(s1.id).iter())
            .map(|l| l.to_string())
            .collect();
        assert_eq!(joined, ["S2"]);
        assert!(placed.get(load.id).is_some() && placed.joined(load.id).is_empty());
        assert!(placed.get(zero.id).is_none());
        assert_eq!((placed.labels, placed.withheld, placed.crowded), (3, 0, 0));
    }

    /// A line's name whose places beside the middle are all taken (a table over the middle
    /// of the line) slides along the line, a third of the way, and needs no leader.
    #[test]
    fn a_line_name_slides_along_its_line_before_it_takes_a_leader() {
        use crate::protocol::{Note, Role, Topic};
        let n = Note::new("s", Topic::Custom("t"));
        let mut b = Board::recording();
        let rows = vec![vec!["XXXXXXXXXX".to_string()]; 4];
        let (w, h) = super::super::extent::table_size(&rows);
        assert!(w > 18.0 && h > 10.0, "the table covers the middle's places");
        b.table(Point::new(30.0 - w / 2.0, h / 2.0), rows, &[], n.clone());
        let p = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        let q = b.point(Point::new(60.0, 0.0), Role::Given, n.clone());
        let member = b.line_through(
            &p,
            &q,
            Role::Given.labelled(Label::from_name("7")),
            n.clone(),
        );
        let member = member.expect("two points apart");
        let placed = place(&b, [-50.0, -50.0, 110.0, 50.0], Vec::new(), &|_| true);
        let at = *placed.get(member.id).expect("placed");
        assert!(at.leader.is_none(), "slid, no leader: {at:?}");
        assert!((at.at.x - 20.0).abs() < 6.0, "a third of the way: {at:?}");
    }

    /// A point at the centre of a star of eight heavy rays (a polar diagram's O) is lettered
    /// in a gap between two rays, on none of them; with the rays thin, the label stays near
    /// its point, across a ray rather than on a leader, only where nothing near is free.
    #[test]
    fn a_label_keeps_off_heavy_lines_and_crosses_thin_ones_only_where_it_must() {
        use crate::protocol::{Note, Role, Topic};
        let n = Note::new("s", Topic::Custom("t"));
        let mut b = Board::recording();
        let o = b.point(Point::origin(), Role::Given.named("O"), n.clone());
        let star = |heavy: bool, k: u32| {
            let t = f64::from(k) * std::f64::consts::FRAC_PI_4;
            let a = Point::origin();
            let b = Point::new(30.0 * t.cos(), 30.0 * t.sin());
            Stroke { a, b, heavy }
        };
        let sheet = [-50.0, -50.0, 50.0, 50.0];
        for heavy in [true, false] {
            let strokes: Vec<Stroke> = (0..8).map(|k| star(heavy, k)).collect();
            let placed = place(&b, sheet, strokes.clone(), &|_| true);
            let at = placed.get(o.id).expect("O is lettered");
            let on = |p: &crate::protocol::Object| (p.id == o.id).then_some(at.at);
            let (on_heavy, on_thin) = lines_through(&b, &on, &strokes);
            assert_eq!((on_heavy, on_thin), (0, 0), "heavy {heavy}: {at:?}");
        }
        // On a sheet too small for a gap between the rays (10 mm square inside its edge), thin rays
        // are crossed, heavy ones never: the label is left out.
        for heavy in [true, false] {
            let strokes: Vec<Stroke> = (0..8).map(|k| star(heavy, k)).collect();
            let placed = place(&b, [-6.0, -6.0, 6.0, 6.0], strokes.clone(), &|_| true);
            let at = placed.get(o.id).map(|p| p.at);
            let on = |p: &crate::protocol::Object| at.filter(|_| p.id == o.id);
            let (on_heavy, on_thin) = lines_through(&b, &on, &strokes);
            assert_eq!((on_heavy, on_thin), (0, usize::from(!heavy)), "{at:?}");
            assert_eq!(placed.crowded, usize::from(heavy));
        }
    }

    #[test]
    fn degenerate_and_absurd_sheets_are_placed_without_a_panic() {
        use crate::protocol::{Note, Role, Topic};
        let n = Note::new("p", Topic::Custom("t"));
        let mut b = Board::recording();
        let mut strokes = Vec::new();
        let stroke = |a: Point, b: Point| Stroke { a, b, heavy: true };
        for k in 0..12 {
            let at = Point::new(k as f64 * 1e-310, 0.0);
            b.point(at, Role::Given.named("P"), n.clone());
            strokes.push(stroke(at, Point::new(at.x, 1e-310)));
        }
        let placed = place(&b, [-50.0, -50.0, 50.0, 50.0], strokes.clone(), &|_| true);
        assert_eq!(
            b.objects()
                .iter()
                .filter(|o| placed.get(o.id).is_some())
                .count(),
            12
        );
        strokes.push(stroke(
            Point::new(f64::NAN, 0.0),
            Point::new(1e308, f64::INFINITY),
        ));
        place(&b, [-50.0, -50.0, 50.0, 50.0], strokes.clone(), &|_| true);
        let huge = place(&b, [-1e300, -1e300, 1e300, 1e300], strokes, &|_| true);
        assert_eq!(huge.crowded, 0);
        assert!(b.objects().iter().all(|o| huge.get(o.id).is_some()));
    }

    /// The placer's cost per label, on the bundled figure with the most labels (the crane
    /// bridge's 953): its placement timed alone, the best of five.
    #[test]
    #[ignore = "a report: cargo test --release --lib labels -- --ignored --nocapture"]
    fn report_the_cost_per_label() {
        let dir = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenes/lh_aufgabe5_crane_bridge.json"
        );
        let scene = crate::scene::AnyScene::load(std::path::Path::new(dir)).unwrap();
        let problem = scene.problem();
        let board = problem.construct(BoardConfig::DRAWING).unwrap();
        let meta = problem.figure_meta();
        let mut best = f64::MAX;
        let mut labels = 0;
        for _ in 0..5 {
            let t = std::time::Instant::now();
            let placed = crate::render::figure::placement(&meta, &board);
            best = best.min(t.elapsed().as_secs_f64());
            labels = placed.labels;
        }
        println!(
            "{labels} labels placed in {:.1} ms: {:.1} µs a label",
            best * 1e3,
            best * 1e6 / labels as f64
        );
    }

    /// The cost per name of one part with many segments (a generated truss's plan drawn on
    /// one sheet): every second segment lies on its predecessor's line, so half the names
    /// are joined. Grouping them looks among neighbouring cells only, so the cost per name
    /// stays flat as the part grows tenfold.
    #[test]
    #[ignore = "a report: cargo test --release --lib labels -- --ignored --nocapture"]
    fn report_the_cost_per_name_of_a_large_plan() {
        use crate::protocol::{Note, Role, Topic};
        for n in [2_000_u32, 20_000] {
            let note = Note::new("s", Topic::Custom("t"));
            let mut b = Board::recording();
            b.set_part(Part::at(0, 0));
            let side = f64::from(n).sqrt().ceil() as u32;
            for k in 0..n {
                let (i, j) = (f64::from((k / 2) % side), f64::from((k / 2) / side));
                let p = b.point(Point::new(40.0 * i, 12.0 * j), Role::Given, note.clone());
                let q = b.point(
                    Point::new(40.0 * i + 30.0, 12.0 * j),
                    Role::Given,
                    note.clone(),
                );
                let name = Role::Force.labelled(Label::from_name(&format!("S{k}")));
                b.segment(&p, &q, name, note.clone());
            }
            let edge = 40.0 * f64::from(side) + 40.0;
            let t = std::time::Instant::now();
            let placed = place(&b, [-10.0, -10.0, edge, edge], Vec::new(), &|_| true);
            let secs = t.elapsed().as_secs_f64();
            println!(
                "{n:6} names in one part: {:.1} ms, {:.2} µs a name ({} written, {} withheld)",
                secs * 1e3,
                secs * 1e6 / f64::from(n),
                placed.labels,
                placed.withheld
            );
        }
    }

    #[test]
    #[ignore = "a report: cargo test --lib labels -- --ignored --nocapture"]
    fn report_overprints_of_the_bundled_figures() {
        for (name, (b0, d0), (b1, d1), crowded, labels) in bundled() {
            println!(
                "{name:45} before {b0:5} pairs {d0:4} on dots; after {b1:5} pairs {d1:4} on dots, \
                 {crowded} of {labels} left out"
            );
        }
    }
}
