//! One SVG figure of a recorded construction.

use super::extent::*;
use super::labels::{self, Placement};
use super::style::class as class_of;
use super::style::*;
use super::xml::{escaped, El, Num, Written};
use crate::fmt::{num, subscripts};
use crate::kernel::construct::clip_to_rect;
use crate::kernel::tolerance::{MIN_DRAWN_MM, NICE_SCALE_SLACK};
use crate::kernel::{Point, Vector};
use crate::protocol::{Board, FigureMeta, Geom, Label, Object, Part, Role, ScaleBar, Step, StepId};
use std::borrow::Cow;

/// Sheet coordinates (mm, y up) to SVG user units (mm, y down), and the drawn region.
struct Frame {
    min_x: f64,
    min_y: f64,
    max_y: f64,
    width: f64,
    height: f64,
    /// The region of the sheet that is drawn: `[min_x, min_y, max_x, max_y]`. Construction
    /// lines are clipped to it and points outside it (an instantaneous centre far away) are
    /// left undrawn, as a drafter leaves a point that falls off the sheet.
    clip: [f64; 4],
    /// The title's lines: one, unless the title is wider than the figure would be without
    /// it (then it is wrapped at spaces rather than widening the sheet past the drawing).
    title: Vec<String>,
    /// The source line's lines, wrapped as the title is (where it is wider than the
    /// drawing, its scale rows and the title's two lines, at most [`TITLE_MIN_WIDTH`]).
    source: Vec<String>,
}

/// How much a title line beyond the first adds to the title block (mm).
const TITLE_LINE: f64 = 7.5;
/// How much a source line beyond the first adds to the title block (mm): its 3.5 px text
/// and a third of that between lines.
const SOURCE_LINE: f64 = 4.7;
/// The narrowest width (mm) a long title is wrapped to: a sheet this wide takes any title on
/// a few lines. A shorter title is wrapped to no less than two lines need, so that a small
/// drawing is not set on a sheet its title alone makes wide.
const TITLE_MIN_WIDTH: f64 = 160.0;
/// Characters a title's two lines are allowed beyond half its length (a word that would
/// overhang the middle).
const TITLE_HALF_SLACK: f64 = 8.0;

impl Frame {
    /// The height of the title block: title lines, source line and the space under them.
    fn title_block(&self) -> f64 {
        TITLE_BLOCK
            + TITLE_LINE * self.title.len().saturating_sub(1) as f64
            + SOURCE_LINE * self.source.len().saturating_sub(1) as f64
    }
    /// Where `p` stands in the figure's user units (the root's own coordinates, in which
    /// the page draws its handles): x as on the sheet, y turned down, the view box set
    /// around the drawing ([`Frame::origin`]).
    fn at(&self, p: &Point) -> [f64; 2] {
        [p.x, -p.y]
    }
    /// The user units of the sheet's top-left corner: the view box starts there, so that a
    /// drawing that grows or shrinks at its edge (a support at the sheet's edge dragged)
    /// changes the root's view box and the sheet's layer, not every mark and text.
    fn origin(&self) -> [f64; 2] {
        [
            self.min_x - MARGIN,
            -(self.max_y + MARGIN + self.title_block()),
        ]
    }
    /// What draws the objects of a part moved `shift` by the layout, in that part's own
    /// coordinates: its layer is moved into place by a `translate` of the shift.
    fn pen(&self, shift: Vector) -> Pen {
        Pen {
            shift,
            clip: self.clip,
        }
    }
    fn contains(&self, p: &Point) -> bool {
        inside(self.clip, p)
    }
    /// Clips the segment a–b to the drawn region; `None` if it lies outside.
    fn clip_segment(&self, a: Point, b: Point) -> Option<(Point, Point)> {
        clipped(self.clip, a, b)
    }
}

/// `p` lies in the region `[min_x, min_y, max_x, max_y]`.
fn inside(clip: [f64; 4], p: &Point) -> bool {
    let [x0, y0, x1, y1] = clip;
    p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1
}

/// The segment a–b clipped to the region `clip`; `None` if it lies outside.
fn clipped(clip: [f64; 4], a: Point, b: Point) -> Option<(Point, Point)> {
    let (t0, t1) = clip_to_rect(a, b, clip)?;
    let d = b - a;
    Some((a + d * t0, a + d * t1))
}

/// Writes the objects of one layer: sheet coordinates (mm, y up) less the shift the layout
/// gave the layer's part, y turned down, inside the layer's `translate` of that shift. A
/// part that moves on the sheet (a plan that grows as a joint is dragged, a table set where
/// there is room) then changes one attribute of each of its layers, not every mark and text
/// in them.
#[derive(Debug, Clone, Copy)]
struct Pen {
    shift: Vector,
    /// The drawn region, as [`Frame`]'s (sheet coordinates, the shift included).
    clip: [f64; 4],
}

impl Pen {
    fn x(&self, p: &Point) -> Num {
        Num(p.x - self.shift.x, 3)
    }
    fn y(&self, p: &Point) -> Num {
        Num(self.shift.y - p.y, 3)
    }
    fn xy(&self, p: &Point) -> String {
        let mut s = String::with_capacity(24);
        self.xy_into(&mut s, p);
        s
    }
    /// `x,y` of p in the layer, at the end of `out` (a path's data written without a string
    /// for each point).
    fn xy_into(&self, out: &mut String, p: &Point) {
        crate::fmt::num_into(out, self.x(p).0, 3);
        out.push(',');
        crate::fmt::num_into(out, self.y(p).0, 3);
    }
    fn contains(&self, p: &Point) -> bool {
        inside(self.clip, p)
    }
    fn clip_segment(&self, a: Point, b: Point) -> Option<(Point, Point)> {
        clipped(self.clip, a, b)
    }
}

fn bounds(pts: &[Point]) -> [f64; 4] {
    let (mut min_x, mut max_x, mut min_y, mut max_y) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in pts {
        min_x = min_x.min(p.x);
        max_x = max_x.max(p.x);
        min_y = min_y.min(p.y);
        max_y = max_y.max(p.y);
    }
    [min_x, min_y, max_x, max_y]
}

/// The labels of a figure placed on its frame.
fn placed(board: &Board, f: &Frame) -> Placement {
    labels::place(board, label_region(f), strokes(board, f), &|p| {
        f.contains(p)
    })
}

/// A board made ready to draw: its parts set out ([`super::layout`]), its frame and its
/// lettering placed. What [`figure`] draws and [`inspect`] measures.
struct Sheet<'a> {
    board: Cow<'a, Board>,
    frame: Frame,
    labels: Placement,
    /// How far the layout moved each part ([`super::layout::part_shifts`]); empty where
    /// the board is drawn as constructed.
    shifts: PartShifts,
}

impl Sheet<'_> {
    fn of<'a>(meta: &FigureMeta, board: &'a Board) -> Sheet<'a> {
        let shifts = anchored(board, super::layout::part_shifts(board).unwrap_or_default());
        Sheet::laid(meta, moved(board, &shifts), shifts)
    }

    /// The sheet of `board` moved by `shifts` (the layout's, or a layout held).
    fn laid<'a>(meta: &FigureMeta, board: Cow<'a, Board>, shifts: PartShifts) -> Sheet<'a> {
        let frame = frame_of(&board, meta);
        let labels = placed(&board, &frame);
        Sheet {
            board,
            frame,
            labels,
            shifts,
        }
    }

    /// The sheet of `board` with the layout `held` where it still holds ([`Layout`]), else
    /// laid out afresh as [`Sheet::of`] does; with the layout it was drawn with.
    fn held<'a>(meta: &FigureMeta, board: &'a Board, held: Option<&Layout>) -> (Sheet<'a>, Layout) {
        let parts = drawn_parts(board);
        if let Some(h) = held.filter(|h| h.parts == parts) {
            let board = moved(board, &h.shifts);
            let overlaps = super::layout::overlapping_parts(&board);
            if overlaps.iter().all(|p| h.overlaps.contains(p)) {
                let layout = Layout {
                    fresh: false,
                    ..h.clone()
                };
                return (Sheet::laid(meta, board, h.shifts.clone()), layout);
            }
        }
        let sheet = Sheet::of(meta, board);
        let layout = Layout {
            shifts: sheet.shifts.clone(),
            parts,
            overlaps: super::layout::overlapping_parts(&sheet.board),
            fresh: true,
        };
        (sheet, layout)
    }
}

/// `board` with each part moved by its shift (borrowed where nothing moves).
fn moved<'a>(board: &'a Board, shifts: &PartShifts) -> Cow<'a, Board> {
    match shifts.is_empty() {
        true => Cow::Borrowed(board),
        false => Cow::Owned(super::layout::moved_by(board, shifts)),
    }
}

/// The parts `board` draws in, in part order.
fn drawn_parts(board: &Board) -> Vec<Part> {
    let parts: std::collections::BTreeSet<Part> = (board.steps().iter())
        .filter(|s| !s.part.hidden)
        .map(|s| s.part)
        .collect();
    parts.into_iter().collect()
}

/// The layout a figure was drawn with ([`figure_held`]): how far each part was moved, the
/// parts there were and which pairs of them overlapped.
///
/// A drag draws its figures with the layout of the figure it started from while that still
/// holds: the same parts, and no pair of them overlapping that did not then (two boxes, or
/// a table and a mark of another part: [`super::layout::overlapping_parts`]). The parts then
/// stand still on the sheet while the pointer moves, as a drafter's sheet does, and a
/// replay changes what the construction moved, not the place of every part the layout
/// would move by a millimetre (the shed roof of LH Aufgabe 4: its four Cremona plans move
/// with every change of the truss's size). A layout that no longer holds (a plan grown into
/// the one beside it) is made afresh. The figure drawn once the pointer rests is laid out
/// afresh, as `render` draws it: the same scene, the same bytes.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layout {
    shifts: PartShifts,
    parts: Vec<Part>,
    overlaps: Vec<(Part, Part)>,
    fresh: bool,
}

impl Layout {
    /// Whether the figure was laid out afresh (it is the figure [`figure`] draws), not with
    /// a layout held.
    pub fn is_fresh(&self) -> bool {
        self.fresh
    }
}

/// The layout's shifts less that of the part drawn first (the structure, as a rule): that
/// part keeps its own coordinates and the others move about it. Moving every part alike
/// moves only the view box, so a drag that makes the layout move all parts (a plan grown
/// under the truss) leaves the first part's layers as they were.
fn anchored(board: &Board, mut shifts: PartShifts) -> PartShifts {
    let Some(first) = board.steps().iter().find(|s| !s.part.hidden) else {
        return shifts;
    };
    let base = shifts
        .get(&first.part)
        .copied()
        .unwrap_or_else(Vector::zeros);
    if base == Vector::zeros() {
        return shifts;
    }
    for step in board.steps() {
        shifts.entry(step.part).or_insert_with(Vector::zeros);
    }
    shifts.values_mut().for_each(|v| *v -= base);
    shifts.retain(|_, v| *v != Vector::zeros());
    shifts
}

/// How far the layout moves each part on the sheet (a part not named is not moved).
type PartShifts = std::collections::BTreeMap<crate::protocol::Part, Vector>;

/// The labels of a figure as [`figure`] places them.
#[cfg(test)]
pub(crate) fn placement(meta: &FigureMeta, board: &Board) -> Placement {
    Sheet::of(meta, board).labels
}

/// The straight strokes the figure draws (lines as clipped, segments, vectors, the sides of
/// curves and of whole circles), for the lettering to keep clear of: each with whether it is
/// drawn with a medium or heavy pen (a given, result or force line, which no letter may
/// lie on) or a thin one (a construction line, which one may cross where nothing else is
/// free).
fn strokes(board: &Board, f: &Frame) -> Vec<labels::Stroke> {
    let mut out = Vec::new();
    for o in board.drawn_objects() {
        let heavy = labels::is_heavy(o.role);
        let stroke = |(a, b): (Point, Point)| labels::Stroke { a, b, heavy };
        match &o.geom {
            Geom::Line { .. } => {
                out.extend((line_ends(o).and_then(|(a, b)| f.clip_segment(a, b))).map(stroke))
            }
            Geom::Segment { segment } | Geom::Vector { segment } => {
                out.push(stroke((segment.a, segment.b)))
            }
            Geom::Curve { points, .. } => {
                out.extend(points.windows(2).map(|w| stroke((w[0], w[1]))))
            }
            Geom::Arc { arc } => {
                let at = |k: usize| arc.point_at_fraction(k as f64 / 16.0);
                out.extend((0..16).map(|k| stroke((at(k), at(k + 1)))));
            }
            Geom::Circle {
                circle, full: true, ..
            } => {
                let at = |k: usize| circle.point_at_deg(7.5 * k as f64);
                out.extend((0..48).map(|k| stroke((at(k), at(k + 1)))));
            }
            _ => {}
        }
    }
    out
}

/// One scale bar's row: its length on the sheet (mm) and the round quantity written under
/// its end (`2500 kg·m`).
struct ScaleRow {
    len: f64,
    end: String,
}

/// The rows of the scale bars, and how far right of the bars' start their names stand (mm),
/// in one column: 12 mm past the longest bar, or past the longest quantity written under a
/// bar's end where that reaches farther (set from 1 mm before the end, at 1.7 mm a
/// character: 0.6 em of 2.8 mm, the width DejaVu Serif gives such a label).
fn scale_rows(scales: &[ScaleBar]) -> (Vec<ScaleRow>, f64) {
    let rows: Vec<ScaleRow> = (scales.iter())
        .map(|s| {
            let q = nice_below(SCALE_BAR * s.per_mm);
            ScaleRow {
                len: q / s.per_mm,
                end: format!("{} {}", num(q, 6), s.unit),
            }
        })
        .collect();
    let names_at = (rows.iter())
        .map(|r| r.len + 12.0f64.max(r.end.chars().count() as f64 * 1.7 + 1.0))
        .fold(0.0, f64::max);
    (rows, names_at)
}

/// The part of the sheet lettering may use (`[x0, y0, x1, y1]`, mm of the figure): the
/// figure and its margins, not the title block above nor the scale rows below.
fn label_region(f: &Frame) -> [f64; 4] {
    let x0 = f.min_x - MARGIN;
    [x0, f.min_y - MARGIN, x0 + f.width, f.max_y + MARGIN]
}

fn frame_of(board: &Board, meta: &FigureMeta) -> Frame {
    // The solid parts (circles, segments, vectors, curves, given points such as a pole) span
    // the figure; lines and constructed points are drawn within reach of them. A table the
    // layout sets where there is room ([`Part::free`](crate::protocol::Part)) widens the
    // sheet but not that reach, so that no line is drawn on into it.
    let (mut solid, mut tables) = (Vec::new(), Vec::new());
    for o in board.drawn_objects() {
        let step = board.steps().get(o.step.0 as usize - 1);
        let given_point = matches!(o.geom, Geom::Point { .. })
            && step.is_some_and(|st| st.kind == crate::protocol::StepKind::Given);
        if matches!(o.geom, Geom::Table { .. }) && step.is_some_and(|st| st.part.free) {
            extent_points(o, &mut tables);
        } else if given_point || !matches!(o.geom, Geom::Line { .. } | Geom::Point { .. }) {
            extent_points(o, &mut solid);
        }
    }
    if solid.is_empty() {
        for o in board.drawn_objects() {
            extent_points(o, &mut solid);
        }
    }
    if solid.is_empty() {
        solid.push(Point::origin());
    }
    let [sx0, sy0, sx1, sy1] = bounds(&solid);
    let reach = CLIP_REACH * (sx1 - sx0).max(sy1 - sy0) + LINE_OVERSHOOT;
    let clip = [sx0 - reach, sy0 - reach, sx1 + reach, sy1 + reach];
    let probe = Frame {
        min_x: 0.0,
        min_y: 0.0,
        max_y: 0.0,
        width: 0.0,
        height: 0.0,
        clip,
        title: Vec::new(),
        source: Vec::new(),
    };
    let mut pts = solid;
    pts.extend(tables);
    for o in board.drawn_objects() {
        let mut more = Vec::new();
        match &o.geom {
            Geom::Line { .. } => {
                if let Some((a, b)) = line_ends(o).and_then(|(a, b)| probe.clip_segment(a, b)) {
                    more.push(a);
                    more.push(b);
                }
            }
            Geom::Point { at } if probe.contains(at) => more.push(*at),
            _ => {}
        }
        pts.extend(more);
    }
    let [mut min_x, mut min_y, mut max_x, mut max_y] = bounds(&pts);
    // Room for labels at the edges.
    min_x -= 4.0;
    max_x += 4.0;
    max_y += 4.0;
    min_y -= 4.0;
    // Wide enough for the scale rows as well; the title and the source line are wrapped to
    // that width (at least what two lines of the title need, at most TITLE_MIN_WIDTH) where
    // they are wider.
    let names_at = scale_rows(&meta.scales).1;
    let text_width = (meta.scales.iter())
        .map(|s| names_at + 2.0 + s.name.chars().count() as f64 * SMALL_CHAR)
        .fold(0.0, f64::max);
    let two_lines = (meta.title.chars().count() as f64 / 2.0 + TITLE_HALF_SLACK) * TITLE_CHAR;
    let inner = (max_x - min_x)
        .max(text_width)
        .max(two_lines.min(TITLE_MIN_WIDTH));
    let (title, title_width) = wrapped(&meta.title, inner, TITLE_CHAR);
    let (source, source_width) = match meta.source.is_empty() {
        true => (Vec::new(), 0.0),
        false => wrapped(&meta.source, inner, TEXT_CHAR),
    };
    let width = (max_x - min_x)
        .max(text_width)
        .max(title_width)
        .max(source_width)
        + 2.0 * MARGIN;
    let mut f = Frame {
        min_x,
        min_y,
        max_y,
        width,
        height: 0.0,
        clip,
        title,
        source,
    };
    f.height =
        (max_y - min_y) + 2.0 * MARGIN + f.title_block() + SCALE_ROW * meta.scales.len() as f64;
    f
}

/// The longest title or source line whose wrap is balanced (characters).
const BALANCED_CHARS: usize = 400;

/// `text` wrapped at spaces to lines of at most `width` (mm) in characters `char_width`
/// wide, and the width of its widest line (a word wider than `width` stands on a line of
/// its own and widens the sheet).
///
/// Of the breaks that take the fewest lines, those that part the fewest phrases
/// ([`crate::fmt::ends_phrase`]: "v = 7 m/s" and "Tafel I" stay whole), and of those the
/// narrowest: balanced lines, not one word under a full line.
fn wrapped(text: &str, width: f64, char_width: f64) -> (Vec<String>, f64) {
    // No line is wider than the text; a text longer than BALANCED_CHARS is wrapped at the
    // full width only (each trial wrap costs its length).
    let len = text.chars().count();
    let columns = ((width / char_width).floor() as usize).min(len).max(1);
    let words = crate::fmt::words_of(text);
    // Each trial wrap is found as the words its lines start at ([`crate::fmt::wrap`]'s
    // lines, without writing them), and only the one taken is written.
    let parted = |starts: &[usize]| {
        let ends = starts.iter().skip(1).map(|&s| words[s - 1].0);
        ends.filter(|w| !crate::fmt::ends_phrase(w)).count()
    };
    // The full width takes the fewest lines; of the narrower wraps that take as few, the one
    // that parts the fewest phrases, and of those the narrowest (the first found).
    let full = crate::fmt::line_starts(&words, columns);
    let fewest = full.len();
    let narrowest = if len > BALANCED_CHARS { columns } else { 1 };
    let narrower = (narrowest..columns).map(|c| crate::fmt::line_starts(&words, c));
    let starts = (narrower.filter(|l| l.len() == fewest))
        .chain(std::iter::once(full))
        .min_by_key(|l| parted(l))
        .expect("the full width is a candidate");
    let lines = crate::fmt::lines_at(&words, &starts);
    let widest = (lines.iter())
        .map(|l| l.chars().count() as f64 * char_width)
        .fold(0.0, f64::max);
    (lines, widest)
}

fn label_text(f: &Pen, at: &Point, label: &Label, joined: &[Label]) -> El {
    let mut t = El::text("text", subscripts(&label.base))
        .set("x", f.x(at))
        .set("y", f.y(at));
    let mut low = false;
    if let Some(i) = label.index {
        t = t.add(index_span(i));
        low = true;
    }
    // The names of segments drawn on the same line follow on it: "S₁, S₂".
    for l in joined {
        let mut next = El::text("tspan", format!(", {}", subscripts(&l.base)));
        if low {
            next = next.set("dy", "-0.9");
        }
        t = t.add(next);
        low = false;
        if let Some(i) = l.index {
            t = t.add(index_span(i));
            low = true;
        }
    }
    t
}

/// A label's index, written lowered and small after its letters.
fn index_span(i: u32) -> El {
    El::text("tspan", i.to_string())
        .set("dy", "0.9")
        .set("font-size", "2.4px")
}

/// A circle: whole, or only the short compass arcs at the points constructed on it.
fn draw_circle(
    f: &Pen,
    class: &str,
    circle: &crate::kernel::Circle,
    full: bool,
    marks: &[f64],
    g: El,
) -> El {
    if full {
        return g.add(
            El::new("circle")
                .set("class", class)
                .set("cx", f.x(&circle.center))
                .set("cy", f.y(&circle.center))
                .set("r", Num(circle.radius, 3)),
        );
    }
    let h = compass_arc_half_angle(circle.radius).to_degrees();
    let mut d = String::new();
    for m in marks {
        let a = circle.point_at_deg(m - h);
        let b = circle.point_at_deg(m + h);
        let r = num(circle.radius, 3);
        // Counter-clockwise on the sheet (y up) is clockwise on the page: sweep flag 1.
        d.push('M');
        f.xy_into(&mut d, &a);
        d.push_str(&format!(" A{r},{r} 0 0,1 "));
        f.xy_into(&mut d, &b);
        d.push(' ');
    }
    if d.is_empty() {
        g
    } else {
        g.add(El::new("path").set("class", class).set("d", d.trim_end()))
    }
}

/// The label of `obj` where the placement put it, with its leader where it stands off.
fn draw_label(f: &Pen, obj: &Object, labels: &Placement, g: El) -> El {
    let Some(pl) = labels.get(obj.id) else {
        return g;
    };
    let mut g = g.add(label_text(f, &pl.at, &obj.label, labels.joined(obj.id)));
    if let Some((a, b)) = pl.leader {
        g = g.add(sheet_line(f, "leader", a, b));
    }
    g
}

fn draw_object(f: &Pen, obj: &Object, labels: &Placement, g: El) -> El {
    let class = class(obj.role);
    let mut g = g;
    match &obj.geom {
        Geom::Point { at } if f.contains(at) => {
            g = g.add(
                El::new("circle")
                    .set("class", "pt")
                    .set("cx", f.x(at))
                    .set("cy", f.y(at))
                    .set("r", Num(DOT, 3)),
            );
            g = draw_label(f, obj, labels, g);
        }
        Geom::Point { .. } => {}
        Geom::Line { .. } => {
            if let Some((a, b)) = line_ends(obj).and_then(|(a, b)| f.clip_segment(a, b)) {
                g = g.add(sheet_line(f, class, a, b));
            }
            g = draw_label(f, obj, labels, g);
        }
        Geom::Segment { segment } | Geom::Vector { segment } => {
            let (a, b) = (segment.a, segment.b);
            // A zero-length force (N at a dead centre) has no direction for its arrowhead.
            if (b - a).norm() > MIN_DRAWN_MM {
                g = g.add(sheet_line(f, class, a, b));
                if obj.role == Role::Guide {
                    g = g.add(hatching(f, a, b));
                }
            }
            g = draw_label(f, obj, labels, g);
        }
        Geom::Circle {
            circle,
            full,
            marks,
        } => g = draw_circle(f, class, circle, *full, marks, g),
        Geom::Arc { arc } => {
            let a = arc.point_at_fraction(0.0);
            let b = arc.point_at_fraction(1.0);
            let r = num(arc.circle.radius, 3);
            let large = if arc.sweep_deg.abs() > 180.0 { 1 } else { 0 };
            // Counter-clockwise on the sheet (y up) is counter-clockwise on the page too, which
            // SVG (y down) writes with the sweep flag 0.
            let sweep = if arc.sweep_deg > 0.0 { 0 } else { 1 };
            g = g.add(El::new("path").set("class", class).set(
                "d",
                format!("M{} A{r},{r} 0 {large},{sweep} {}", f.xy(&a), f.xy(&b)),
            ));
            g = draw_label(f, obj, labels, g);
        }
        Geom::Curve { points, smooth } => {
            let d = if *smooth {
                smooth_path(f, points)
            } else {
                polygon_path(f, points)
            };
            g = g.add(El::new("path").set("class", class).set("d", d));
            g = draw_label(f, obj, labels, g);
        }
        Geom::Table { at, rows } => {
            for (block, corner) in table_blocks(*at, rows) {
                g = draw_table(f, corner, &block, g);
            }
        }
        Geom::Scalar { .. } => {}
    }
    g
}

/// One block of a table, its top-left corner at `at`: a heading as a text, a block of rows
/// in a group of its own translated to its corner, so that a table the layout sets elsewhere
/// (where there is room as the plans grow) changes one attribute, not each cell.
fn draw_table(pen: &Pen, at: Point, rows: &[Vec<String>], parent: El) -> El {
    if is_heading(rows) {
        let p = Point::new(at.x, at.y - 0.8 * HEADING_ROW);
        return parent.add(
            El::text("text", subscripts(&rows[0][0]))
                .set("class", "heading")
                .set("x", pen.x(&p))
                .set("y", pen.y(&p)),
        );
    }
    let mut g = El::new("g").set("transform", translate([pen.x(&at).0, pen.y(&at).0]));
    // The cells in the block's own coordinates.
    let f = &Pen {
        shift: at.coords,
        clip: pen.clip,
    };
    let at = &at;
    let cols = table_columns(rows);
    for (i, row) in rows.iter().enumerate() {
        let y = at.y - (i as f64 + 0.8) * TABLE_ROW;
        let mut x = at.x;
        for (c, cell) in row.iter().enumerate() {
            // Numbers right-aligned in their column, words left-aligned.
            let numeric = cell
                .chars()
                .next()
                .is_some_and(|ch| ch.is_ascii_digit() || "+−-".contains(ch));
            let w = cols[c] - TABLE_GAP;
            let (px, anchor) = if numeric && i > 0 {
                (x + w, "end")
            } else {
                (x, "start")
            };
            g = g.add(
                El::text("text", subscripts(cell))
                    .set("class", "small")
                    .set("x", f.x(&Point::new(px, y)))
                    .set("y", f.y(&Point::new(px, y)))
                    .set("text-anchor", anchor),
            );
            x += cols[c];
        }
        if i == 0 {
            let (w, _) = table_size(rows);
            let ly = at.y - TABLE_ROW * 1.05;
            g = g.add(sheet_line(
                f,
                class_of(Role::Construction),
                Point::new(at.x, ly),
                Point::new(at.x + w, ly),
            ));
        }
    }
    parent.add(g)
}

/// A straight line on the sheet from `a` to `b` in the given class.
fn sheet_line(f: &Pen, class: &str, a: Point, b: Point) -> El {
    El::new("line")
        .set("class", class)
        .set("x1", f.x(&a))
        .set("y1", f.y(&a))
        .set("x2", f.x(&b))
        .set("y2", f.y(&b))
}

/// Short slanted strokes under a guide, on its right-hand side.
fn hatching(f: &Pen, a: Point, b: Point) -> El {
    let v = b - a;
    let len = v.norm();
    let u = v / len;
    let n = Vector::new(u.y, -u.x); // right of a→b
    let slant = (n - u) * (HATCH / std::f64::consts::SQRT_2);
    let mut d = String::new();
    // At most MAX_HATCH_STROKES strokes: a guide drawn kilometres long (an absurd scale) is
    // hatched more coarsely instead of by a loop whose count comes from the scale.
    let k = ((len / HATCH).floor() as usize).min(MAX_HATCH_STROKES);
    let step = if k == MAX_HATCH_STROKES {
        len / k as f64
    } else {
        HATCH
    };
    for i in 0..=k {
        let p = a + u * (i as f64 * step);
        d.push('M');
        f.xy_into(&mut d, &p);
        d.push_str(" L");
        f.xy_into(&mut d, &(p + slant));
        d.push(' ');
    }
    El::new("path").set("class", "hatch").set("d", d.trim_end())
}

/// The polygon through the points (closed with `Z` if the last point repeats the first).
fn polygon_path(f: &Pen, pts: &[Point]) -> String {
    let mut d = String::new();
    for (i, p) in pts.iter().enumerate() {
        d.push_str(if i == 0 { "M" } else { " L" });
        f.xy_into(&mut d, p);
    }
    d
}

/// A smooth curve through the points (Catmull–Rom as cubic Béziers); closed if the last point
/// repeats the first.
fn smooth_path(f: &Pen, pts: &[Point]) -> String {
    let n = pts.len();
    if n < 3 {
        return polygon_path(f, pts);
    }
    let closed = (pts[0] - pts[n - 1]).norm() < MIN_DRAWN_MM;
    let get = |i: isize| -> Point {
        if closed {
            let m = (n - 1) as isize;
            pts[i.rem_euclid(m) as usize]
        } else {
            pts[i.clamp(0, n as isize - 1) as usize]
        }
    };
    let mut d = String::with_capacity(30 * n);
    d.push('M');
    f.xy_into(&mut d, &pts[0]);
    for i in 0..(n - 1) as isize {
        let (p0, p1, p2, p3) = (get(i - 1), get(i), get(i + 1), get(i + 2));
        let c1 = p1 + (p2 - p0) / 6.0;
        let c2 = p2 - (p3 - p1) / 6.0;
        d.push_str(" C");
        f.xy_into(&mut d, &c1);
        d.push(' ');
        f.xy_into(&mut d, &c2);
        d.push(' ');
        f.xy_into(&mut d, &p2);
    }
    d
}

/// An arrowhead marker 3.2 × 1.3 mm, tip at the end of the line.
fn arrow_marker(id: &str, d: &str, class: &str) -> El {
    El::new("marker")
        .set("id", id)
        .set("viewBox", "0 0 10 4")
        .set("refX", "10")
        .set("refY", "2")
        .set("markerWidth", "3.2")
        .set("markerHeight", "1.3")
        .set("markerUnits", "userSpaceOnUse")
        .set("orient", "auto")
        .add(El::new("path").set("d", d).set("class", class))
}

/// Filled arrowheads for forces, open ones for velocities.
fn defs() -> El {
    El::new("defs")
        .add(arrow_marker("arrow", "M0,0 L10,2 L0,4 z", "head"))
        .add(arrow_marker("arrow-open", "M0,0 L10,2 L0,4", "head-open"))
}

/// The next "nice" length (1, 2, 2.5, 5 × 10ᵏ) at or below `x`.
fn nice_below(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let base = 10f64.powf(x.log10().floor());
    for m in [5.0, 2.5, 2.0, 1.0] {
        if m * base <= x * (1.0 + NICE_SCALE_SLACK) {
            return m * base;
        }
    }
    base
}

fn sheet_layer(f: &Frame, meta: &FigureMeta) -> El {
    let mut g = El::new("g")
        .set("id", "sheet")
        .set("inkscape:groupmode", "layer")
        .set("inkscape:label", "000 sheet: title and scales")
        .set("transform", translate(f.origin()));
    for (k, line) in f.title.iter().enumerate() {
        g = g.add(
            El::text("text", line.to_string())
                .set("class", "title")
                .set("x", Num(MARGIN, 3))
                .set("y", Num(MARGIN + 6.0 + TITLE_LINE * k as f64, 3)),
        );
    }
    let below = TITLE_LINE * f.title.len().saturating_sub(1) as f64;
    for (k, line) in f.source.iter().enumerate() {
        g = g.add(
            El::text("text", line.to_string())
                .set("x", Num(MARGIN, 3))
                .set("y", Num(MARGIN + 12.0 + below + SOURCE_LINE * k as f64, 3)),
        );
    }
    // Scale bars, one to a row, under the figure.
    let y0 = f.height - MARGIN - SCALE_ROW * meta.scales.len() as f64 + 4.0;
    let (rows, names_at) = scale_rows(&meta.scales);
    for (k, (s, row)) in meta.scales.iter().zip(rows).enumerate() {
        let x = MARGIN;
        let y = y0 + k as f64 * SCALE_ROW;
        let len = row.len;
        let mut d = format!(
            "M{},{} L{},{}",
            num(x, 3),
            num(y, 3),
            num(x + len, 3),
            num(y, 3)
        );
        for t in 0..=4 {
            let tx = x + len * t as f64 / 4.0;
            let h = if t % 2 == 0 { 1.2 } else { 0.7 };
            d.push_str(&format!(
                " M{},{} L{},{}",
                num(tx, 3),
                num(y - h, 3),
                num(tx, 3),
                num(y, 3)
            ));
        }
        g = g.add(El::new("path").set("class", "given").set("d", d));
        g = g.add(
            El::text("text", "0")
                .set("class", "small")
                .set("x", Num(x - 0.7, 3))
                .set("y", Num(y + 3.2, 3)),
        );
        g = g.add(
            El::text("text", row.end)
                .set("class", "small")
                .set("x", Num(x + len - 1.0, 3))
                .set("y", Num(y + 3.2, 3)),
        );
        g = g.add(
            El::text("text", s.name.to_string())
                .set("class", "small")
                .set("x", Num(MARGIN + names_at, 3))
                .set("y", Num(y + 1.0, 3)),
        );
    }
    g
}

/// `translate(x,y)`, to 0.001 mm.
fn translate([x, y]: [f64; 2]) -> Written<impl Fn(&mut String)> {
    Written(move |out: &mut String| {
        out.push_str("translate(");
        crate::fmt::num_into(out, x, 3);
        out.push(',');
        crate::fmt::num_into(out, y, 3);
        out.push(')');
    })
}

/// The step's title ([`Step::title`]) as the sheet writes it, escaped, straight into the
/// layer's buffer: a `format!` per layer was 3 M instructions of a 1,679-step figure.
fn title(step: &Step) -> Written<impl FnOnce(&mut String) + '_> {
    Written(move |out: &mut String| {
        crate::fmt::push_uint_padded(out, u64::from(step.id.0), 3);
        out.push(' ');
        escaped(out, &step.caption);
        if let Some(c) = &step.context {
            out.push_str(" (");
            escaped(out, c);
            out.push(')');
        }
    })
}

/// The layer of `step`, drawn in its part's own coordinates and moved into place by the part's
/// shift `shift` on the sheet ([`Pen`]).
fn layer(sheet: &Sheet<'_>, shift: Vector, step: &Step, current: bool) -> El {
    let f = &sheet.frame;
    let id = |prefix: &'static str| {
        Written(move |out: &mut String| {
            out.push_str(prefix);
            crate::fmt::push_uint_padded(out, u64::from(step.id.0), 3);
        })
    };
    let mut g = El::new("g")
        .set("id", id("step-"))
        .set("inkscape:groupmode", "layer")
        .set("inkscape:label", title(step))
        .set("data-step", id(""));
    if shift != Vector::zeros() {
        g = g.set("transform", translate([shift.x, -shift.y]));
    }
    if current {
        g = g.set("class", "current");
    }
    let pen = f.pen(shift);
    for oid in &step.outputs {
        if let Some(obj) = sheet.board.object(*oid) {
            g = draw_object(&pen, obj, &sheet.labels, g);
        }
    }
    g
}

/// The SVG of a recorded construction, with every step up to `upto` (all if `None`) as its own
/// Inkscape layer (`<g id="step-NNN" inkscape:groupmode="layer" inkscape:label="NNN caption"
/// data-step="NNN">`). With `upto`, that step is drawn in the highlight colour. The page size
/// is that of the whole construction, so walk-through pages do not jump.
///
/// Deterministic: the same board gives the same bytes (numbers rounded to 0.001 mm).
pub fn figure(meta: &FigureMeta, board: &Board, upto: Option<StepId>) -> String {
    figure_lettered(meta, board, upto).0
}

/// How a figure's lettering went: how many labels it was to write, and how many the crowd
/// rule left out for want of room (each label that is written overprints nothing).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Lettering {
    /// The labels to be written: of its points, lines and curves, and the names of lines
    /// and forces of the parts that have room for all of theirs.
    pub labels: usize,
    /// Those left out: no free place near their point, nor farther out with a leader.
    pub left_out: usize,
    /// Names of segments and forces not written because their part of the sheet had no
    /// room for all of them (a plan is lettered in full or not at all).
    pub withheld: usize,
}

/// What the figure test measures of a figure, on the boxes the label placer works with: a
/// figure reads like a plate when [`FigureReport::is_clean`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FigureReport {
    /// The labels to be written (as [`Lettering::labels`]).
    pub labels: usize,
    /// Those the crowd rule left out.
    pub left_out: usize,
    /// Names of segments and forces withheld from a part without room for all of them.
    pub withheld: usize,
    /// Pairs of written labels that overprint each other.
    pub overprints: usize,
    /// Labels over a point's dot.
    pub on_dots: usize,
    /// Labels that cross the sheet's edge.
    pub off_sheet: usize,
    /// Labels with a given, result, force or other heavy line through their letters.
    pub on_heavy_lines: usize,
    /// Labels with only thin construction lines, axes or transfers through their letters.
    pub on_thin_lines: usize,
    /// Labels joined to their point by a leader, standing off.
    pub leaders: usize,
    /// The names of the book's plate ([`FigureMeta::plate`]) the figure does not write.
    pub unnamed: Vec<String>,
    /// Pairs of parts ([`crate::protocol::Part`]) that overlap once the sheet is laid out.
    pub part_overlaps: usize,
    /// The side of the largest square of the drawing area (mm) that nothing drawn or written
    /// touches: the emptiest region of the sheet, to 2 mm.
    pub emptiest_mm: f64,
    /// The drawing area's width and height (mm), the title block and scale rows left out.
    pub area_mm: [f64; 2],
}

impl FigureReport {
    /// Nothing overprints, no heavy line runs through a letter, every name of the plate is
    /// written, nothing leaves the sheet, no parts overlap.
    pub fn is_clean(&self) -> bool {
        self.overprints == 0
            && self.on_dots == 0
            && self.on_heavy_lines == 0
            && self.unnamed.is_empty()
            && self.off_sheet == 0
            && self.part_overlaps == 0
    }
}

/// The figure test of one figure: its sheet laid out and its labels placed as [`figure`]
/// does, then measured ([`FigureReport`]).
///
/// ```
/// use graphostatik::prelude::*;
/// use graphostatik::render::inspect;
/// let mut b = Board::recording();
/// let n = Note::new("given", Topic::Custom("demo"));
/// for (k, x) in [0.0, 1.0, 2.0].into_iter().enumerate() {
///     let name = ["A", "B", "C"][k];
///     b.point(Point::new(x, 0.0), Role::Given.named(name), n.clone());
/// }
/// let report = inspect(&FigureMeta::titled("Three points 1 mm apart"), &b);
/// assert!(report.is_clean(), "{report:?}");
/// assert_eq!(report.labels, 3);
/// ```
pub fn inspect(meta: &FigureMeta, board: &Board) -> FigureReport {
    let Sheet {
        board,
        frame: f,
        labels: placed,
        ..
    } = Sheet::of(meta, board);
    let region = label_region(&f);
    let at = |o: &Object| placed.get(o.id).map(|p| p.at);
    let o = labels::overprints(&board, &at, Some(region));
    let (on_heavy_lines, on_thin_lines) = labels::lines_through(&board, &at, &strokes(&board, &f));
    let leaders = (board.objects().iter())
        .filter(|o| placed.get(o.id).is_some_and(|p| p.leader.is_some()))
        .count();
    FigureReport {
        unnamed: unnamed(meta, &board, &placed),
        on_heavy_lines,
        on_thin_lines,
        leaders,
        labels: placed.labels,
        left_out: placed.crowded,
        withheld: placed.withheld,
        overprints: o.pairs,
        on_dots: o.on_dots,
        off_sheet: o.off_sheet,
        part_overlaps: super::layout::part_overlaps(&board),
        emptiest_mm: emptiest(&board, &f, &placed),
        area_mm: [region[2] - region[0], region[3] - region[1]],
    }
}

/// The names of the book's plate (`meta.plate`) that the figure does not write: each is
/// written where a label of that name (`P1` for P₁) stands on the sheet, alone or joined
/// to another's, or a table's cell reads it (a shear field's `+`).
fn unnamed(meta: &FigureMeta, board: &Board, placed: &Placement) -> Vec<String> {
    // A name set with a subscript digit (B₁) is the scene's "B1".
    let plain = |s: String| -> String {
        s.chars()
            .map(|c| match c {
                '₀'..='₉' => char::from(b'0' + (c as u32 - '₀' as u32) as u8),
                _ => c,
            })
            .collect()
    };
    let mut written = std::collections::HashSet::new();
    for o in board.drawn_objects() {
        if placed.get(o.id).is_some() {
            written.insert(plain(o.label.to_string()));
            written.extend(placed.joined(o.id).iter().map(|l| plain(l.to_string())));
        }
        if let Geom::Table { rows, .. } = &o.geom {
            written.extend(rows.iter().flatten().map(|c| plain(c.trim().to_string())));
        }
    }
    (meta.plate.iter())
        .filter(|name| !written.contains(&plain(name.to_string())))
        .cloned()
        .collect()
}

/// The side (mm) of the largest square of the drawing area that no stroke, point, table or
/// label touches: the area rasterised on a grid of 2 mm (coarser where that would exceed a
/// million cells), the largest empty square by the usual dynamic programme over the cells.
fn emptiest(board: &Board, f: &Frame, placed: &Placement) -> f64 {
    let [x0, y0, x1, y1] = label_region(f);
    let (w, h) = (x1 - x0, y1 - y0);
    if !(w.is_finite() && h.is_finite() && w > 0.0 && h > 0.0) {
        return 0.0;
    }
    let cell = 2.0f64.max((w * h / 1e6).sqrt());
    let (nx, ny) = ((w / cell).ceil() as usize, (h / cell).ceil() as usize);
    let mut used = vec![false; nx * ny];
    let mut mark = |p: Point| {
        let (i, j) = (((p.x - x0) / cell).floor(), ((p.y - y0) / cell).floor());
        if i >= 0.0 && j >= 0.0 && (i as usize) < nx && (j as usize) < ny {
            used[j as usize * nx + i as usize] = true;
        }
    };
    let fill = |[a, b, c, d]: [f64; 4], mark: &mut dyn FnMut(Point)| {
        let (mut y, mut rows) = (b, 0);
        while y <= d + cell && rows < ny + 1 {
            let (mut x, mut cols) = (a, 0);
            while x <= c + cell && cols < nx + 1 {
                mark(Point::new(x.min(c), y.min(d)));
                x += cell;
                cols += 1;
            }
            y += cell;
            rows += 1;
        }
    };
    for labels::Stroke { a, b, .. } in strokes(board, f) {
        let n = ((b - a).norm() / (0.5 * cell)).ceil().min(1e5) as usize;
        for k in 0..=n {
            mark(a + (b - a) * (k as f64 / n.max(1) as f64));
        }
    }
    let mut pts = Vec::new();
    for o in board.drawn_objects() {
        pts.clear();
        extent_points(o, &mut pts);
        match &o.geom {
            Geom::Table { .. } => {
                let [a, b, c, d] = bounds(&pts);
                fill([a, b, c, d], &mut mark);
            }
            Geom::Line { .. } => {}
            _ => pts.iter().for_each(|p| mark(*p)),
        }
        if let Some(pl) = placed.get(o.id) {
            fill(labels::label_box(&o.label, pl.at), &mut mark);
        }
    }
    largest_empty_square(&used, nx, ny) as f64 * cell
}

/// The side (in cells) of the largest square of `false` cells in an `nx` × `ny` grid.
fn largest_empty_square(used: &[bool], nx: usize, ny: usize) -> usize {
    let mut prev = vec![0usize; nx];
    let mut best = 0;
    for j in 0..ny {
        let mut row = vec![0usize; nx];
        for i in 0..nx {
            if !used[j * nx + i] {
                row[i] = if i == 0 {
                    1
                } else {
                    1 + prev[i].min(row[i - 1]).min(prev[i - 1])
                };
                best = best.max(row[i]);
            }
        }
        prev = row;
    }
    best
}

/// [`figure`], with how its lettering went: the command line says on stderr when labels
/// were left out.
pub fn figure_lettered(
    meta: &FigureMeta,
    board: &Board,
    upto: Option<StepId>,
) -> (String, Lettering) {
    draw(meta, Sheet::of(meta, board), upto)
}

/// The figure of `board`, as [`figure`] draws it, and where the points `ids` stand on its
/// sheet (SVG user units, mm from the sheet's top left corner; `None` for an id that is not a
/// point of the board): what the browser page needs to put a drag handle over a given point.
///
/// ```
/// use graphostatik::protocol::{Board, FigureMeta, Note, Role, Topic};
/// use graphostatik::kernel::Point;
/// let mut b = Board::recording();
/// let n = Note::new("given", Topic::Custom("demo"));
/// let a = b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n.clone());
/// let c = b.point(Point::new(30.0, 10.0), Role::Given.named("C"), n);
/// let (svg, at) = graphostatik::render::figure_with_points(
///     &FigureMeta::titled("Two points"), &b, &[a.id, c.id]);
/// let (a, c) = (at[0].unwrap(), at[1].unwrap());
/// assert!(svg.contains("<svg"));
/// assert!((c[0] - a[0] - 30.0).abs() < 1e-9 && (a[1] - c[1] - 10.0).abs() < 1e-9);
/// ```
pub fn figure_with_points(
    meta: &FigureMeta,
    board: &Board,
    ids: &[crate::protocol::ObjId],
) -> (String, Vec<Option<[f64; 2]>>) {
    let (svg, at, _) = figure_held(meta, board, ids, None);
    (svg, at)
}

/// [`figure_with_points`] with the layout `held` where it still holds ([`Layout`]; `None`:
/// laid out afresh), and the layout the figure was drawn with: the browser's engine draws a
/// drag's figures so.
///
/// ```
/// use graphostatik::protocol::{Board, FigureMeta, Note, Part, Role, Topic};
/// use graphostatik::kernel::Point;
/// use graphostatik::render::{figure_held, figure_with_points};
/// let n = Note::new("given", Topic::Custom("demo"));
/// let two = |x: f64| {
///     let mut b = Board::recording();
///     b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n.clone());
///     b.point(Point::new(x, 10.0), Role::Given.named("B"), n.clone());
///     b.set_part(Part::at(0, 1));
///     b.point(Point::new(0.0, 0.0), Role::Given.named("C"), n.clone());
///     b
/// };
/// let meta = FigureMeta::titled("Two parts");
/// let (first, _, layout) = figure_held(&meta, &two(30.0), &[], None);
/// assert!(layout.is_fresh() && first == figure_with_points(&meta, &two(30.0), &[]).0);
/// // A dragged a little: the second part stays where it stood.
/// let (_, _, kept) = figure_held(&meta, &two(31.0), &[], Some(&layout));
/// assert!(!kept.is_fresh());
/// // Dragged into the second part: laid out afresh.
/// let (_, _, fresh) = figure_held(&meta, &two(60.0), &[], Some(&layout));
/// assert!(fresh.is_fresh());
/// ```
pub fn figure_held(
    meta: &FigureMeta,
    board: &Board,
    ids: &[crate::protocol::ObjId],
    held: Option<&Layout>,
) -> (String, Vec<Option<[f64; 2]>>, Layout) {
    let (sheet, layout) = Sheet::held(meta, board, held);
    let at = (ids.iter())
        .map(|&id| match sheet.board.object(id).map(|o| &o.geom) {
            Some(Geom::Point { at }) => Some(sheet.frame.at(at)),
            _ => None,
        })
        .collect();
    (draw(meta, sheet, None).0, at, layout)
}

/// Draws a sheet made ready: the title block, then one layer per step up to `upto`.
fn draw(meta: &FigureMeta, sheet: Sheet<'_>, upto: Option<StepId>) -> (String, Lettering) {
    let labels = &sheet.labels;
    let lettering = Lettering {
        labels: labels.labels,
        left_out: labels.crowded,
        withheld: labels.withheld,
    };
    let f = &sheet.frame;
    let mut doc = El::document()
        .set(
            "xmlns:inkscape",
            "http://www.inkscape.org/namespaces/inkscape",
        )
        .set("width", format!("{}mm", num(f.width, 3)))
        .set("height", format!("{}mm", num(f.height, 3)))
        .set("viewBox", {
            let [x, y] = f.origin();
            let [w, h] = [f.width, f.height].map(|v| num(v, 3));
            format!("{} {} {w} {h}", num(x, 3), num(y, 3))
        })
        .add(El::text("title", meta.title.to_string()))
        .add(El::text("style", css()))
        .add(defs())
        .add(sheet_layer(f, meta));
    for step in sheet.board.steps() {
        if let Some(u) = upto {
            if step.id > u {
                break;
            }
        }
        if step.part.hidden {
            continue;
        }
        let shift = sheet.shifts.get(&step.part).copied();
        let shift = shift.unwrap_or_else(Vector::zeros);
        doc = doc.add(layer(&sheet, shift, step, Some(step.id) == upto));
    }
    let mut s = doc.write();
    s.push('\n');
    (s, lettering)
}

#[cfg(test)]
mod tests {
    use super::{largest_empty_square, wrapped};

    /// A source line is broken between phrases where it can be, into balanced lines, and a
    /// width of a sheet of any size is no loop over its width.
    #[test]
    fn titles_wrap_between_phrases_into_balanced_lines() {
        let source =
            "LH Gl. 34, Abb. 56; KG (295), Abb. 1050 — R = 315 mm, infinitely long rod, v = 7 m/s";
        let (lines, widest) = wrapped(source, 160.0, 2.0);
        assert_eq!(
            lines,
            [
                "LH Gl. 34, Abb. 56; KG (295), Abb. 1050 —",
                "R = 315 mm, infinitely long rod, v = 7 m/s"
            ]
        );
        assert_eq!(widest, 2.0 * 42.0);
        // No phrase end to break at: the last line is not one word under a full one.
        let (lines, _) = wrapped(
            "Compound engine the cards reduced to piston forces",
            160.0,
            3.4,
        );
        assert_eq!(
            lines,
            ["Compound engine the cards", "reduced to piston forces"]
        );
        let (lines, _) = wrapped(source, f64::MAX, 2.0);
        assert_eq!(lines, [source]);
        let (lines, _) = wrapped(source, f64::NAN, 2.0);
        assert!(lines.iter().all(|l| !l.contains(' ')), "{lines:?}");
    }

    /// The wrap found from the lines' first words is the wrap of the lines written out:
    /// every width of texts with phrase ends, long words and odd spaces.
    #[test]
    fn the_wrap_by_line_starts_is_the_wrap_written_out() {
        let written = |text: &str, width: f64, char_width: f64| {
            let len = text.chars().count();
            let columns = ((width / char_width).floor() as usize).min(len).max(1);
            let parted = |lines: &[String]| {
                let ends = lines.iter().rev().skip(1);
                ends.filter(|l| !(l.split(' ').next_back()).is_some_and(crate::fmt::ends_phrase))
                    .count()
            };
            let full = crate::fmt::wrap(text, columns);
            let fewest = full.len();
            let narrowest = if len > super::BALANCED_CHARS {
                columns
            } else {
                1
            };
            let narrower = (narrowest..columns).map(|c| crate::fmt::wrap(text, c));
            (narrower.filter(|l| l.len() == fewest))
                .chain(std::iter::once(full))
                .min_by_key(|l| parted(l))
                .unwrap()
        };
        let long = "Tafel I: ".repeat(60);
        let texts = [
            "LH Gl. 34, Abb. 56; KG (295), Abb. 1050 — R = 315 mm, infinitely long rod, v = 7 m/s",
            "Compound engine the cards reduced to piston forces",
            "  spaces   between\twords, and a verylongwordthatfitsnowhere at all ",
            "",
            "one",
            "Überdruck, Massendruck; Tangentialdruck — Schwungrad: δ = 1/80, n = 135/min",
            long.as_str(),
        ];
        for text in texts {
            for width in [
                1.0,
                7.0,
                20.0,
                33.0,
                60.0,
                80.0,
                160.0,
                400.0,
                2000.0,
                f64::NAN,
            ] {
                let (lines, _) = wrapped(text, width, 2.0);
                assert_eq!(lines, written(text, width, 2.0), "{text:?} at {width}");
            }
        }
    }

    #[test]
    fn the_largest_empty_square_of_a_grid() {
        // 5 × 4 cells, one used in the middle of the top row: the empty 3 × 3 below it.
        let mut used = vec![false; 20];
        used[2] = true;
        assert_eq!(largest_empty_square(&used, 5, 4), 3);
        used[7 + 5] = true; // (2, 2) too: squares of 2 remain
        assert_eq!(largest_empty_square(&used, 5, 4), 2);
        assert_eq!(largest_empty_square(&[true; 6], 3, 2), 0);
    }
}
