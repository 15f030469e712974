//! The board: every kernel operation, recorded as a step.

use super::accuracy::{ErrorModel, Track, WorstCut};
use super::config::{BoardConfig, Jitter, Mode};
use super::reference::{self as refr, ReferenceRow, Shadow, DP};
use super::step::*;
use crate::kernel::angle::SinCos;
use crate::kernel::construct;
use crate::kernel::tolerance::CHECK_REL;
use crate::kernel::{
    intersect_circle_circle, intersect_line_circle, intersect_line_line, Branch, Circle,
    CircleCircle, Conditioning, Line, LineCircle, LineLine, Point, PrimitiveError, Segment,
    Tolerance, Vector,
};
use serde::Serialize;

pub use super::error::{ConstructionError, CutOutcome};

/// A handle to an object on the board: its id and its geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct H<T> {
    /// The object id ([`ObjId::NONE`] on a board that does not record).
    pub id: ObjId,
    /// The geometry or value.
    pub g: T,
}

/// The outcome of a line–line intersection on the board: a point, or the named degenerate case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cut {
    /// The lines meet.
    Point(H<Point>, Conditioning),
    /// The lines are parallel: they meet at infinity.
    Parallel {
        /// Their distance (mm).
        distance: f64,
    },
    /// The lines coincide.
    Coincident,
}

/// A value read earlier (a force, a velocity measured elsewhere) and its scale, as the
/// dividers carry it to be laid off ([`Board::transfer`]).
#[derive(Debug, Clone, Copy)]
pub struct Reading<'a> {
    /// The value.
    pub value: &'a H<f64>,
    /// Its units per mm of the sheet.
    pub per_mm: f64,
}

/// The objects a number is reckoned from and how much it moves when one of them moves by one
/// unit (a number) or one mm (a point): `1/n` for a mean of n ordinates ([`Board::reckon`]).
#[derive(Debug, Clone, Copy)]
pub struct Weighted<'a> {
    /// The objects.
    pub inputs: &'a [ObjId],
    /// The weight of each.
    pub weight: f64,
}

/// How a circle is divided: the sense in which its points follow each other.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Turning {
    /// Clockwise on the sheet.
    Clockwise,
    /// Anticlockwise on the sheet.
    Anticlockwise,
}

/// How a curve is drawn through its points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Trace {
    /// A smooth curve through them (the French curve).
    Smooth,
    /// The polygon through them.
    Polygon,
}

/// How a measured length is converted to a quantity: `value = mm on the sheet × per_mm`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scale {
    /// Quantity units per mm of the sheet (e.g. 200 kg per mm, or 10 mm of machine per mm).
    pub per_mm: f64,
    /// The unit of the quantity.
    pub unit: &'static str,
}

impl Scale {
    /// `per_mm` units of `unit` per mm of the sheet.
    pub const fn new(per_mm: f64, unit: &'static str) -> Scale {
        Scale { per_mm, unit }
    }

    /// A force scale: `per_mm` kg per mm of the sheet (the books' "1 mm = 100 kg").
    pub const fn kg(per_mm: f64) -> Scale {
        Scale { per_mm, unit: "kg" }
    }
}

/// The board of a construction: objects and steps, in the order made.
///
/// A board either records (objects and steps kept, captions, checks) or only computes: the
/// same procedure code runs on both, so the benchmark can show what recording costs.
///
/// ```
/// use graphostatik::protocol::{note, Board, Label, Note, Role, Topic};
/// use graphostatik::kernel::{Point, Vector};
/// const N: Note = note("given", None, "", Topic::Setup);
/// let mut b = Board::recording();
/// let o = b.point(Point::new(0.0, 0.0), Role::Given.named("O"), N);
/// let axis = b.line_dir(&o, Vector::new(1.0, 0.0), Role::Axis, N).unwrap();
/// assert_eq!(b.steps().len(), 2);
/// assert_eq!(b.steps()[1].inputs.as_slice(), &[o.id]);
/// assert_eq!(axis.g.dir, Vector::new(1.0, 0.0));
/// ```
#[derive(Debug, Clone, Serialize)]
pub struct Board {
    tolerance: Tolerance,
    #[serde(skip)]
    recording: bool,
    /// The tolerance follows the extent of the construction (no figure size was given).
    #[serde(skip)]
    follows_extent: bool,
    /// Bounding box of what has been placed, where the tolerance follows it.
    #[serde(skip)]
    extent: Option<[f64; 4]>,
    #[serde(skip)]
    context: Option<std::sync::Arc<str>>,
    /// The part of the figure the next steps draw in.
    #[serde(skip)]
    part: Part,
    #[serde(skip)]
    next_step: u32,
    /// Whether the last cut found only one double point (a tangency).
    #[serde(skip)]
    last_touched: bool,
    /// The error model the bounds follow.
    #[serde(skip)]
    model: ErrorModel,
    /// Each object's propagated error bound (recording only), in object order.
    #[serde(skip)]
    tracks: super::tracks::Tracks,
    /// Each object's double-double reference value, where a reference replay was asked for.
    #[serde(skip)]
    shadows: Option<Vec<Shadow>>,
    /// A draftsman's hand, where the setup asks for one.
    #[serde(skip)]
    jitter: Option<Jitter>,
    /// What a board that keeps the checks and not the drawing files instead of steps and
    /// objects ([`Mode::Checks`]).
    #[serde(skip)]
    ledger: Option<Box<Ledger>>,
    objects: Vec<Object>,
    steps: Vec<Step>,
}

/// The checks of a board that does not keep its drawing: steps and objects are counted, the
/// checks kept with the step and the situation they belong to, and each object's error
/// bound tracked, in some 50 bytes per object instead of a protocol of some 1 KB per step.
#[derive(Debug, Clone, Default)]
struct Ledger {
    /// The value of each number, by its id (in id order): what the bounds of numbers
    /// reckoned from numbers need. The step that made each object is in its track.
    numbers: Vec<(ObjId, f64)>,
    /// The checks with the step they are attached to, in the order filed, while there are
    /// at most [`LISTED_CHECKS`](super::summary::LISTED_CHECKS) (or every one was asked for).
    checks: super::tracks::Chunked<(StepId, Check)>,
    /// Every check counted, per kind, with the worst of each kind and every failure.
    summary: super::summary::CheckSummary,
    /// Keep every check however many ([`Mode::Checks`]'s `every`).
    every: bool,
    /// The situation from each step on where it changed, in step order.
    contexts: Vec<(StepId, Option<std::sync::Arc<str>>)>,
}

impl Ledger {
    fn new(every: bool) -> Ledger {
        Ledger {
            every,
            ..Ledger::default()
        }
    }

    /// Counts a check, and keeps it while the checks are listed one by one.
    fn file(&mut self, step: StepId, check: Check) {
        self.summary.add(step, &check);
        if !self.summarised() {
            self.checks.push((step, check));
        } else if self.checks.len() > 0 {
            self.checks = Default::default();
        }
    }

    /// Whether only the summary is kept: more checks than are listed, and not every one asked
    /// for.
    fn summarised(&self) -> bool {
        !self.every && self.summary.total > super::summary::LISTED_CHECKS as u64
    }

    /// The checks kept whole: every one, or past the list's limit the failures.
    fn kept(&self) -> impl Iterator<Item = &(StepId, Check)> {
        let failures = if self.summarised() {
            &self.summary.failures[..]
        } else {
            &[]
        };
        self.checks.iter().chain(failures)
    }

    /// The situation the step was made in.
    fn context(&self, step: StepId) -> Option<&str> {
        let i = self.contexts.partition_point(|(s, _)| *s <= step);
        i.checked_sub(1).and_then(|i| self.contexts[i].1.as_deref())
    }
}

/// A check with the step it is attached to and the situation that step was made in: a row
/// of the check table, from a board that keeps its drawing or from one that keeps only its
/// checks ([`Board::check_entries`]).
#[derive(Debug, Clone, Copy)]
pub struct CheckEntry<'a> {
    /// The step that made the checked value.
    pub step: StepId,
    /// The situation of that step ("θ = 30°").
    pub context: Option<&'a str>,
    /// The check.
    pub check: &'a Check,
}

impl Board {
    /// A board set up by `config`: what it keeps, the error model its bounds follow, a
    /// draftsman's hand, a reference replay. Its length tolerance follows the extent of what
    /// has been placed on it, unless [`Board::with_figure_size`] fixes it.
    pub fn new(config: BoardConfig) -> Board {
        let recording = config.is_recording();
        Board {
            tolerance: Tolerance::for_figure(0.0),
            follows_extent: true,
            extent: None,
            recording,
            context: None,
            part: Part::default(),
            next_step: 0,
            last_touched: false,
            model: config.model,
            tracks: Default::default(),
            shadows: (config.reference && config.mode == Mode::Drawing).then(Vec::new),
            jitter: config.hand.map(Jitter::new),
            ledger: match config.mode {
                Mode::Checks { every } => Some(Box::new(Ledger::new(every))),
                _ => None,
            },
            objects: Vec::new(),
            steps: Vec::new(),
        }
    }

    /// A board that records every step, object and check ([`BoardConfig::DRAWING`]).
    pub fn recording() -> Board {
        Board::new(BoardConfig::DRAWING)
    }

    /// A board that only computes (nothing recorded, no checks evaluated): the fast path of
    /// the same procedure code ([`BoardConfig::SILENT`]).
    pub fn silent() -> Board {
        Board::new(BoardConfig::SILENT)
    }

    /// This board for a figure of a known size (mm on the sheet), which fixes its length
    /// tolerance up front instead of following the construction's extent.
    pub fn with_figure_size(mut self, figure_size: f64) -> Board {
        self.tolerance = Tolerance::for_figure(figure_size);
        self.follows_extent = false;
        self
    }

    /// A silent board with this board's tolerance: for a dry run that measures where the
    /// parts of a figure will go before they are drawn.
    pub fn scratch(&self) -> Board {
        Board {
            tolerance: self.tolerance,
            follows_extent: self.follows_extent,
            extent: self.extent,
            model: self.model,
            ..Board::silent()
        }
    }

    /// The error model the bounds follow.
    pub fn error_model(&self) -> ErrorModel {
        self.model
    }

    /// Whether the board replays its steps in double-double
    /// ([`BoardConfig::with_reference`]).
    pub fn has_reference(&self) -> bool {
        self.shadows.is_some()
    }

    /// A point as the draftsman marks it (as it is, without a hand).
    #[inline]
    fn mark(&mut self, p: Point) -> Point {
        match self.jitter.as_mut() {
            Some(j) => j.mark(p),
            None => p,
        }
    }

    /// A line as the draftsman rules it: its origin marked, its direction turned.
    #[inline]
    fn rule(&mut self, l: Line) -> Line {
        match self.jitter.as_mut() {
            Some(j) => Line {
                origin: j.mark(l.origin),
                dir: j.turn(l.dir),
            },
            None => l,
        }
    }

    /// A length (mm) as the draftsman sets or reads it on the scale rule.
    #[inline]
    fn read(&mut self, mm: f64) -> f64 {
        match self.jitter.as_mut() {
            Some(j) => j.read(mm),
            None => mm,
        }
    }

    /// The propagated error bound of an object (mm for a point, its unit for a number) and
    /// the worst cut it depends on; `None` on a board that does not record.
    pub fn bound(&self, id: ObjId) -> Option<(f64, Option<WorstCut>)> {
        let t = self.tracks.get((id.0 as usize).wrapping_sub(1))?;
        Some((t.err, t.worst))
    }

    fn tr(&self, id: ObjId) -> Track {
        self.tracks
            .get((id.0 as usize).wrapping_sub(1))
            .unwrap_or_default()
    }

    /// Sets an object's bound on a recording board: the guard inlined, the bound reckoned
    /// apart, so that a board that does not record pays a test for it.
    #[inline(always)]
    fn set_tr(&mut self, id: ObjId, t: impl FnOnce(&Board) -> Track) {
        if self.recording && id != ObjId::NONE {
            self.set_tr_recorded(id, t);
        }
    }

    #[inline(never)]
    fn set_tr_recorded(&mut self, id: ObjId, t: impl FnOnce(&Board) -> Track) {
        let t = t(self);
        self.tracks.set(id.0 as usize - 1, t);
    }

    fn shadow(&self, id: ObjId) -> Shadow {
        self.shadows
            .as_ref()
            .and_then(|s| s.get((id.0 as usize).wrapping_sub(1)).copied())
            .unwrap_or_default()
    }

    #[inline]
    fn set_shadow(&mut self, id: ObjId, f: impl FnOnce(&Board) -> Shadow) {
        if self.shadows.is_some() && id != ObjId::NONE {
            self.set_shadow_replayed(id, f);
        }
    }

    #[inline(never)]
    fn set_shadow_replayed(&mut self, id: ObjId, f: impl FnOnce(&Board) -> Shadow) {
        let v = f(self);
        if let Some(s) = self.shadows.as_mut() {
            s[id.0 as usize - 1] = v;
        }
    }

    // The reference of a handle is its object's, unless a procedure made the handle with an
    // object's id but geometry of its own (a line's normal, a value's magnitude): then the
    // handle's f64 geometry is taken as given.

    fn sp(&self, h: &H<Point>) -> DP {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Point(p), Some(Geom::Point { at })) if *at == h.g => p,
            _ => DP::of(&h.g),
        }
    }

    fn sl(&self, h: &H<Line>) -> (DP, DP) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Line { o, d }, Some(Geom::Line { line, .. })) if *line == h.g => (o, d),
            _ => (DP::of(&h.g.origin), DP::of_vec(&h.g.dir)),
        }
    }

    fn sc(&self, h: &H<Circle>) -> (DP, twofloat::TwoFloat) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Circle { c, r }, Some(Geom::Circle { circle, .. })) if *circle == h.g => {
                (c, r)
            }
            _ => (DP::of(&h.g.center), h.g.radius.into()),
        }
    }

    fn sv(&self, h: &H<f64>) -> twofloat::TwoFloat {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Scalar(v), Some(Geom::Scalar { value, .. })) if *value == h.g => v,
            _ => h.g.into(),
        }
    }

    /// The length tolerance of the figure.
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }

    /// Grows the extent by a point, where the tolerance follows the construction.
    fn grow(&mut self, p: &Point) {
        if !(self.follows_extent && p.x.is_finite() && p.y.is_finite()) {
            return;
        }
        let e = self.extent.get_or_insert([p.x, p.y, p.x, p.y]);
        *e = [e[0].min(p.x), e[1].min(p.y), e[2].max(p.x), e[3].max(p.y)];
        self.tolerance = Tolerance::for_figure((e[2] - e[0]).max(e[3] - e[1]));
    }

    /// Whether checks are made and bounds tracked (steps are kept too where
    /// [`Board::is_drawing`]).
    pub fn is_recording(&self) -> bool {
        self.recording
    }

    /// Whether steps and objects are kept for a drawing: a recording board that was not
    /// made to keep only its checks ([`Mode::Checks`]).
    /// Work that only the drawing needs (a table of readings written on the sheet, a curve
    /// through points already checked) is skipped where this is false.
    #[inline]
    pub fn is_drawing(&self) -> bool {
        self.recording && self.ledger.is_none()
    }

    /// How many steps were made (recorded or only counted).
    pub fn step_count(&self) -> usize {
        self.next_step as usize
    }

    /// How many objects were made on a recording board (kept, or only counted where the board
    /// keeps only its checks); 0 on a board that does not record.
    pub fn object_count(&self) -> usize {
        self.tracks.len()
    }

    /// Every analytic check the board kept, in step order (on a board that keeps only a
    /// [`CheckSummary`](super::CheckSummary), its failures; [`Board::check_count`] counts
    /// all).
    ///
    /// ```
    /// use graphostatik::prelude::*;
    /// let mut b = Board::recording();
    /// let n = Note::new("a length", Topic::Custom("demo"));
    /// let o = b.point(Point::new(0.0, 0.0), Role::Given.named("O"), n.clone());
    /// let a = b.point(Point::new(3.0, 4.0), Role::Given.named("A"), n.clone());
    /// let x = b.line_through(&o, &a, Role::Construction, n.clone())?;
    /// let d = b.measure(&o, &a, &x, Scale::new(1.0, "mm"), Label::plain("d"), n);
    /// b.check(&d, "OA", "mm", "Pythagoras", 5.0, || 5.0);
    /// assert_eq!(b.checks().count(), 1);
    /// assert!(b.all_passed());
    /// # Ok::<(), ConstructionError>(())
    /// ```
    pub fn checks(&self) -> impl Iterator<Item = &Check> {
        let kept = self.ledger.iter().flat_map(|l| l.kept().map(|(_, c)| c));
        self.steps.iter().flat_map(|s| s.checks.iter()).chain(kept)
    }

    /// Every check with its step and situation, in step order (checks of one step in the
    /// order filed): the rows of the check table, whether the board kept its drawing or only
    /// its checks. Where only a [`CheckSummary`](super::CheckSummary) was kept, the failed
    /// checks.
    pub fn check_entries(&self) -> Vec<CheckEntry<'_>> {
        let Some(l) = self.ledger.as_deref() else {
            return self
                .steps
                .iter()
                .flat_map(|s| {
                    s.checks.iter().map(|check| CheckEntry {
                        step: s.id,
                        context: s.context.as_deref(),
                        check,
                    })
                })
                .collect();
        };
        let mut out: Vec<CheckEntry<'_>> = l
            .kept()
            .map(|(step, check)| CheckEntry {
                step: *step,
                context: l.context(*step),
                check,
            })
            .collect();
        // Stable: the checks of one step stay in the order they were filed.
        out.sort_by_key(|e| e.step);
        out
    }

    /// The summary of the checks, where the board kept only it: a board that keeps only its
    /// checks and made more than [`LISTED_CHECKS`](super::LISTED_CHECKS) of them, unless
    /// [`Mode::Checks`]'s `every` asked for every one.
    pub fn check_summary(&self) -> Option<&super::CheckSummary> {
        self.ledger
            .as_deref()
            .filter(|l| l.summarised())
            .map(|l| &l.summary)
    }

    /// The situation ("θ = 30°") of a step, on a board that keeps its drawing or only its
    /// checks.
    pub fn context_of(&self, step: StepId) -> Option<&str> {
        match self.ledger.as_deref() {
            Some(l) => l.context(step),
            None => self
                .steps
                .get((step.0 as usize).wrapping_sub(1))
                .and_then(|s| s.context.as_deref()),
        }
    }

    /// How many checks were made (kept or only counted).
    pub fn check_count(&self) -> u64 {
        match self.ledger.as_deref() {
            Some(l) => l.summary.total,
            None => self.steps.iter().map(|s| s.checks.len() as u64).sum(),
        }
    }

    /// How many checks failed, counted or kept.
    pub fn failed_count(&self) -> u64 {
        match self.ledger.as_deref() {
            Some(l) => l.summary.failed,
            None => self.checks().filter(|c| !c.passed).count() as u64,
        }
    }

    /// Whether every check on the board passed (true for a board without checks), counted
    /// or kept.
    pub fn all_passed(&self) -> bool {
        match self.ledger.as_deref() {
            Some(l) => l.summary.failed == 0,
            None => self.checks().all(|c| c.passed),
        }
    }

    /// The recorded steps.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// The recorded objects.
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The object with this id.
    pub fn object(&self, id: ObjId) -> Option<&Object> {
        // Ids are dense and start at 1.
        self.objects.get((id.0 as usize).wrapping_sub(1))
    }

    /// Sets the situation in which the following steps are made ("φ = 30°"); recorded only.
    #[inline]
    pub fn set_context(&mut self, f: impl FnOnce() -> String) {
        if self.recording {
            self.set_context_recorded(f().into());
        }
    }

    fn set_context_recorded(&mut self, c: std::sync::Arc<str>) {
        if let Some(l) = self.ledger.as_mut() {
            l.contexts
                .push((StepId(self.next_step + 1), Some(c.clone())));
        }
        self.context = Some(c);
    }

    /// Reserves room for `steps` more steps and `objects` more objects, so that a long
    /// construction does not spend its time moving a growing protocol around in memory.
    /// (A board that keeps only its checks files no steps and objects, only their bounds,
    /// which grow in chunks: room is made in the first.)
    pub fn reserve(&mut self, steps: usize, objects: usize) {
        if self.recording {
            self.tracks.reserve(objects);
        }
        if self.is_drawing() {
            self.steps.reserve(steps);
            self.objects.reserve(objects);
        }
    }

    /// Sets the part of the figure the following steps draw in ([`Part`]): the sheet layout
    /// sets the parts out in rows and columns.
    pub fn set_part(&mut self, part: Part) {
        self.part = part;
    }

    /// The part the next steps draw in.
    pub fn part(&self) -> Part {
        self.part
    }

    /// Moves each part's drawing on the sheet by `by(part)`: the sheet layout. The steps,
    /// numbers and checks stay as they are; only where the objects are drawn changes.
    pub fn move_parts(&mut self, by: impl Fn(Part) -> Vector) {
        let steps = &self.steps;
        for o in &mut self.objects {
            if let Some(st) = steps.get((o.step.0 as usize).wrapping_sub(1)) {
                let v = by(st.part);
                if v != Vector::zeros() {
                    o.geom.translate(v);
                }
            }
        }
    }

    /// Clears the context.
    pub fn clear_context(&mut self) {
        if let Some(l) = self.ledger.as_mut() {
            l.contexts.push((StepId(self.next_step + 1), None));
        }
        self.context = None;
    }

    fn step_id_next(&self) -> StepId {
        StepId(self.next_step + 1)
    }

    /// Counts a step and, on a recording board, files it. Inlined, so that a board that does
    /// not record pays only the count for it (the construction's hot path).
    #[inline]
    fn begin(&mut self, kind: StepKind, note: &Note, inputs: &[ObjId]) {
        self.next_step += 1;
        if self.recording {
            self.file_step(kind, note, inputs);
        }
    }

    fn file_step(&mut self, kind: StepKind, note: &Note, inputs: &[ObjId]) {
        if self.ledger.is_none() {
            self.steps.push(Step {
                id: StepId(self.next_step),
                kind,
                topic: note.topic,
                caption: note.caption.clone(),
                term_de: note.term_de.clone(),
                book: note.book.clone(),
                context: self.context.clone(),
                inputs: Ids::from_slice(inputs),
                outputs: Ids::new(),
                conditioning: None,
                branch: None,
                outcome: None,
                checks: Vec::new(),
                part: self.part,
            });
        }
    }

    #[inline]
    fn add(&mut self, label: Label, role: Role, geom: impl FnOnce() -> Geom) -> ObjId {
        if !self.recording {
            return ObjId::NONE;
        }
        if self.ledger.is_some() {
            return self.count_object(geom());
        }
        self.file_object(label, role, geom())
    }

    /// An object of a board that keeps only its checks: an id, its bound, its step and,
    /// for a number, its value.
    fn count_object(&mut self, geom: Geom) -> ObjId {
        let id = ObjId(self.tracks.len() as u32 + 1);
        self.tracks.push(StepId(self.next_step));
        if let (Geom::Scalar { value, .. }, Some(l)) = (geom, self.ledger.as_mut()) {
            l.numbers.push((id, value));
        }
        id
    }

    /// The value of a number on the board (kept or only counted), `None` for other objects.
    fn number(&self, id: ObjId) -> Option<f64> {
        let i = (id.0 as usize).wrapping_sub(1);
        match self.ledger.as_deref() {
            Some(l) => l
                .numbers
                .binary_search_by_key(&id, |n| n.0)
                .ok()
                .map(|k| l.numbers[k].1),
            None => match self.objects.get(i).map(|o| &o.geom) {
                Some(Geom::Scalar { value, .. }) => Some(*value),
                _ => None,
            },
        }
    }

    fn file_object(&mut self, label: Label, role: Role, geom: Geom) -> ObjId {
        let id = ObjId(self.tracks.len() as u32 + 1);
        let step = StepId(self.next_step);
        self.tracks.push(step);
        if let Some(s) = self.shadows.as_mut() {
            s.push(Shadow::None);
        }
        self.objects.push(Object {
            id,
            step,
            label,
            role,
            geom,
        });
        if let Some(s) = self.steps.last_mut() {
            s.outputs.push(id);
        }
        id
    }

    #[inline]
    fn last_step(&mut self) -> Option<&mut Step> {
        if self.recording {
            self.steps.last_mut()
        } else {
            None
        }
    }

    /// Grows the drawn extent of a line, or adds a compass mark on a circle, so that the
    /// figure shows the line up to the point constructed on it.
    #[inline]
    fn touch(&mut self, on: ObjId, p: &Point) {
        if !self.recording || on == ObjId::NONE {
            return;
        }
        self.touch_recorded(on, p);
    }

    fn touch_recorded(&mut self, on: ObjId, p: &Point) {
        let idx = on.0 as usize - 1;
        if let Some(obj) = self.objects.get_mut(idx) {
            match &mut obj.geom {
                Geom::Line { line, extent } => {
                    let t = line.param_of(p);
                    extent[0] = extent[0].min(t);
                    extent[1] = extent[1].max(t);
                }
                Geom::Circle { circle, marks, .. } => {
                    let v = p - circle.center;
                    marks.push(v.y.atan2(v.x).to_degrees());
                }
                _ => {}
            }
        }
    }

    fn prim<T>(&self, r: Result<T, PrimitiveError>, note: &Note) -> Result<T, ConstructionError> {
        r.map_err(|source| ConstructionError::Primitive {
            step: self.step_id_next(),
            caption: note.caption.clone(),
            source,
        })
    }

    /// A length or ratio that must be a finite number for the step `note` would take.
    fn finite(&self, x: f64, note: &Note) -> Result<(), ConstructionError> {
        if x.is_finite() {
            Ok(())
        } else {
            Err(ConstructionError::Primitive {
                step: self.step_id_next(),
                caption: note.caption.clone(),
                source: PrimitiveError::NotFinite,
            })
        }
    }

    /// A given point.
    pub fn point(&mut self, p: Point, mark: impl Into<Mark>, note: Note) -> H<Point> {
        let Mark { label, role } = mark.into();
        let p = self.mark(p);
        self.grow(&p);
        self.begin(StepKind::Given, &note, &[]);
        let id = self.add(label, role, || Geom::Point { at: p });
        self.set_tr(id, |b| b.model.given(&p));
        self.set_shadow(id, |_| Shadow::Point(DP::of(&p)));
        H { id, g: p }
    }

    /// The line through a point in a given direction (a given axis, or a ray laid off with
    /// the protractor).
    pub fn line_dir(
        &mut self,
        p: &H<Point>,
        dir: Vector,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Line>, ConstructionError> {
        let Mark { label, role } = mark.into();
        let line = self.prim(Line::new(p.g, dir), &note)?;
        let line = self.rule(line);
        let kind = if p.id == ObjId::NONE || note.topic == Topic::Setup {
            StepKind::Given
        } else {
            StepKind::Line
        };
        self.begin(kind, &note, &[p.id]);
        let id = self.add(label, role, || Geom::Line {
            line,
            extent: [0.0, 0.0],
        });
        self.set_tr(id, |b| b.model.line_at(&b.tr(p.id), &dir));
        self.set_shadow(id, |b| Shadow::Line {
            o: b.sp(p),
            d: DP::of_vec(&dir).unit(),
        });
        Ok(H { id, g: line })
    }

    /// The line through two points (the ruler).
    pub fn line_through(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Line>, ConstructionError> {
        let Mark { label, role } = mark.into();
        let line = self.prim(Line::through(a.g, b.g, self.tolerance.length), &note)?;
        let line = self.rule(line);
        self.begin(StepKind::Line, &note, &[a.id, b.id]);
        let tb = line.param_of(&b.g);
        let id = self.add(label, role, || Geom::Line {
            line,
            extent: [tb.min(0.0), tb.max(0.0)],
        });
        self.set_tr(id, |bd| {
            bd.model
                .ruled(&bd.tr(a.id), &bd.tr(b.id), (b.g - a.g).norm())
        });
        self.set_shadow(id, |bd| {
            let (pa, pb) = (bd.sp(a), bd.sp(b));
            Shadow::Line {
                o: pa,
                d: pb.sub(&pa).unit(),
            }
        });
        Ok(H { id, g: line })
    }

    /// The parallel to `line` through `p`.
    pub fn parallel(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Line> {
        let g = construct::parallel_through(&line.g, p.g);
        self.slide(StepKind::Parallel, line, p, g, mark.into(), note)
    }

    /// The perpendicular to `line` through `p`.
    pub fn perpendicular(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Line> {
        let g = construct::perpendicular_through(&line.g, p.g);
        self.slide(StepKind::Perpendicular, line, p, g, mark.into(), note)
    }

    /// The set square slid along `line` to `p`, ruling `g` (the parallel, or the
    /// perpendicular: [`StepKind::Perpendicular`]).
    fn slide(
        &mut self,
        kind: StepKind,
        line: &H<Line>,
        p: &H<Point>,
        g: Line,
        mark: Mark,
        note: Note,
    ) -> H<Line> {
        let g = self.rule(g);
        self.begin(kind, &note, &[line.id, p.id]);
        let id = self.add(mark.label, mark.role, || Geom::Line {
            line: g,
            extent: [0.0, 0.0],
        });
        self.slid(id, line, p, kind == StepKind::Perpendicular);
        H { id, g }
    }

    /// The bound and reference of a line slid along `line` to `p` (turned 90°: `turned`).
    #[inline]
    fn slid(&mut self, id: ObjId, line: &H<Line>, p: &H<Point>, turned: bool) {
        self.set_tr(id, |b| {
            let dir = if turned { line.g.normal() } else { line.g.dir };
            b.model.slid(&b.tr(line.id), &b.tr(p.id), &dir)
        });
        self.set_shadow(id, |b| {
            let d = b.sl(line).1;
            Shadow::Line {
                o: b.sp(p),
                d: if turned { d.normal() } else { d },
            }
        });
    }

    /// The circle about `center` with `radius` mm (the compass), drawn whole or only in the
    /// short arcs where points are constructed on it ([`Drawn`]).
    pub fn circle(
        &mut self,
        center: &H<Point>,
        radius: f64,
        drawn: Drawn,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Circle>, ConstructionError> {
        let Mark { label, role } = mark.into();
        let radius = self.read(radius);
        let c = self.prim(Circle::new(center.g, radius), &note)?;
        self.grow(&(c.center + Vector::new(c.radius, c.radius)));
        self.grow(&(c.center - Vector::new(c.radius, c.radius)));
        let kind = if note.topic == Topic::Setup {
            StepKind::Given
        } else {
            StepKind::Circle
        };
        self.begin(kind, &note, &[center.id]);
        let id = self.add(label, role, || Geom::Circle {
            circle: c,
            full: drawn == Drawn::Whole,
            marks: Vec::new(),
        });
        self.set_tr(id, |b| {
            b.model.compass(&b.tr(center.id), &c.center, c.radius)
        });
        self.set_shadow(id, |b| Shadow::Circle {
            c: b.sp(center),
            r: c.radius.into(),
        });
        Ok(H { id, g: c })
    }

    /// The point of a circle at the angle `deg` (laid off with the protractor), with the ray
    /// from the centre drawn as a segment of the given role.
    pub fn point_on_circle(
        &mut self,
        circle: &H<Circle>,
        deg: f64,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let dir = SinCos::of_deg(deg);
        self.point_on_circle_dir(circle, dir, mark, note)
    }

    /// The point of a circle in the direction given by its sine and cosine ([`SinCos`]), for an
    /// angle better known by those than by its degrees (180° − θ for a tiny θ: forming
    /// 180 − θ would round θ away), with the ray from the centre drawn.
    pub fn point_on_circle_dir(
        &mut self,
        circle: &H<Circle>,
        dir: SinCos,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let Mark { label, role } = mark.into();
        let SinCos { sin: s, cos: c } = dir;
        let g = &circle.g;
        let p = Point::new(g.center.x + g.radius * c, g.center.y + g.radius * s);
        let p = self.mark(p);
        self.begin(StepKind::Divide, &note, &[circle.id]);
        let id = self.add(label, Role::Given, || Geom::Point { at: p });
        self.on_circle(id, circle, &p, dir);
        let c = circle.g.center;
        self.add(Label::NONE, role, || Geom::Segment {
            segment: Segment { a: c, b: p },
        });
        self.touch(circle.id, &p);
        H { id, g: p }
    }

    /// The bound and reference of the point `p` of a circle in the direction `(sin, cos)`.
    fn on_circle(&mut self, id: ObjId, circle: &H<Circle>, p: &Point, dir: SinCos) {
        let SinCos { sin: s, cos: c } = dir;
        self.set_tr(id, |b| {
            b.model.on_circle(&b.tr(circle.id), p, circle.g.radius)
        });
        self.set_shadow(id, |b| {
            let (cc, r) = b.sc(circle);
            Shadow::Point(DP {
                x: cc.x + r * c,
                y: cc.y + r * s,
            })
        });
    }

    /// Divides a circle into `n` equal parts from `start_deg` (one step, `n` points).
    pub fn divide_circle(
        &mut self,
        circle: &H<Circle>,
        start_deg: f64,
        n: usize,
        turning: Turning,
        label: &'static str,
        note: Note,
    ) -> Vec<H<Point>> {
        let clockwise = turning == Turning::Clockwise;
        let mut pts = construct::divide_circle(&circle.g, start_deg, n, clockwise);
        pts.iter_mut().for_each(|p| *p = self.mark(*p));
        self.begin(StepKind::Divide, &note, &[circle.id]);
        let mut out = Vec::with_capacity(pts.len());
        let sign = if clockwise { -1.0 } else { 1.0 };
        for (k, p) in pts.into_iter().enumerate() {
            let id = self.add(Label::indexed(label, k as u32), Role::Given, || {
                Geom::Point { at: p }
            });
            if self.recording {
                let deg = start_deg + sign * 360.0 * k as f64 / n.max(1) as f64;
                self.on_circle(id, circle, &p, SinCos::of_deg(deg));
            }
            self.touch(circle.id, &p);
            out.push(H { id, g: p });
        }
        out
    }

    /// The sign of a fixed pivot under `pivot` (the frame, Gestell): a small triangle on a
    /// hatched ground line, drawn at its size on the sheet whatever the scale.
    pub fn ground(&mut self, pivot: &H<Point>, note: Note) {
        if !self.recording {
            return;
        }
        const HALF: f64 = 3.0;
        const DEPTH: f64 = 4.0;
        let p = pivot.g;
        let (l, r) = (
            Point::new(p.x - HALF, p.y - DEPTH),
            Point::new(p.x + HALF, p.y - DEPTH),
        );
        self.begin(StepKind::Given, &note, &[pivot.id]);
        for (a, b, role) in [(p, l, Role::Given), (p, r, Role::Given)] {
            self.add(Label::NONE, role, || Geom::Segment {
                segment: Segment { a, b },
            });
        }
        let (a, b) = (l - Vector::new(1.5, 0.0), r + Vector::new(1.5, 0.0));
        // Hatched on the right of a → b: below the line, as the ground is.
        self.add(Label::NONE, Role::Guide, || Geom::Segment {
            segment: Segment { a, b },
        });
    }

    /// A segment drawn between two points (a crank, a rod).
    pub fn segment(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Segment> {
        let Mark { label, role } = mark.into();
        let s = Segment { a: a.g, b: b.g };
        self.begin(StepKind::LayOff, &note, &[a.id, b.id]);
        let id = self.add(label, role, || match role {
            Role::Force | Role::Velocity => Geom::Vector { segment: s },
            _ => Geom::Segment { segment: s },
        });
        H { id, g: s }
    }

    /// Lays off `length` mm from `from` along the direction of `along` (negative: backwards),
    /// drawing the laid-off length as a vector of the given role (force, velocity) or a segment.
    pub fn lay_off(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        length: f64,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        // The line's direction is a unit vector already: no normalisation needed.
        self.lay_off_carried(from, along, (length, None), mark.into(), note)
    }

    /// Lays off a value read earlier (a force, a velocity measured elsewhere) at `per_mm`
    /// units per mm from `from` along `along`: the dividers' transfer, whose error and
    /// reference follow the value it carries.
    pub fn transfer(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        reading: Reading<'_>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let Reading { value, per_mm } = reading;
        let length = value.g / per_mm;
        self.lay_off_carried(
            from,
            along,
            (length, Some((value, per_mm))),
            mark.into(),
            note,
        )
    }

    fn lay_off_carried(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        (length, carried): (f64, Option<(&H<f64>, f64)>),
        mark: Mark,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let Mark { label, role } = mark;
        self.finite(length, &note)?;
        let length = self.read(length);
        let p = from.g + along.g.dir * length;
        self.finite(p.x, &note)?;
        self.finite(p.y, &note)?;
        self.grow(&p);
        match carried {
            Some((v, _)) => self.begin(StepKind::LayOff, &note, &[from.id, along.id, v.id]),
            None => self.begin(StepKind::LayOff, &note, &[from.id, along.id]),
        }
        let a = from.g;
        let id = self.add(label, Role::Given, || Geom::Point { at: p });
        self.set_tr(id, |b| {
            let mut c = carried.map_or(Track::default(), |(v, _)| b.tr(v.id));
            c.err /= carried.map_or(1.0, |(_, per_mm)| per_mm.abs());
            b.model
                .laid(&b.tr(from.id), &b.tr(along.id), length, &p, &c)
        });
        self.set_shadow(id, |b| {
            let len = carried.map_or(length.into(), |(v, per_mm)| b.sv(v) / per_mm);
            Shadow::Point(b.sp(from).add(&b.sl(along).1.scale(len)))
        });
        self.add(Label::NONE, role, || match role {
            Role::Force | Role::Velocity => Geom::Vector {
                segment: Segment { a, b: p },
            },
            _ => Geom::Segment {
                segment: Segment { a, b: p },
            },
        });
        self.touch(along.id, &p);
        Ok(H { id, g: p })
    }

    /// The foot of the perpendicular from `p` on `line`, with the perpendicular drawn.
    pub fn foot(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let Mark { label, role } = mark.into();
        let f = construct::foot_on_line(&line.g, &p.g);
        let f = self.mark(f);
        self.begin(StepKind::Foot, &note, &[line.id, p.id]);
        let id = self.add(label, Role::Given, || Geom::Point { at: f });
        self.set_tr(id, |b| {
            b.model
                .foot(&b.tr(line.id), &line.g, (&b.tr(p.id), &p.g), &f)
        });
        self.set_shadow(id, |b| {
            let ((o, d), q) = (b.sl(line), b.sp(p));
            Shadow::Point(o.add(&d.scale(q.sub(&o).dot(&d))))
        });
        let a = p.g;
        self.add(Label::NONE, role, || Geom::Segment {
            segment: Segment { a, b: f },
        });
        self.touch(line.id, &f);
        H { id, g: f }
    }

    /// Intersects two lines; a parallel or coincident pair is recorded as its named case.
    pub fn meet(&mut self, a: &H<Line>, b: &H<Line>, label: impl Into<Label>, note: Note) -> Cut {
        let label = label.into();
        let r = intersect_line_line(&a.g, &b.g, &self.tolerance);
        self.begin(StepKind::IntersectLineLine, &note, &[a.id, b.id]);
        match r {
            LineLine::Point {
                point,
                conditioning,
                ..
            } => {
                let point = self.mark(point);
                if let Some(s) = self.last_step() {
                    s.conditioning = Some(conditioning);
                }
                let id = self.add(label, Role::Given, || Geom::Point { at: point });
                self.lines_met(id, (a, b), &point, conditioning);
                self.touch(a.id, &point);
                self.touch(b.id, &point);
                Cut::Point(H { id, g: point }, conditioning)
            }
            LineLine::Parallel { distance } => {
                if let Some(s) = self.last_step() {
                    s.outcome = Some(format!(
                        "parallel, {} mm apart: they meet at infinity",
                        crate::fmt::num(distance, 3)
                    ));
                }
                Cut::Parallel { distance }
            }
            LineLine::Coincident => {
                if let Some(s) = self.last_step() {
                    s.outcome = Some("the lines coincide".into());
                }
                Cut::Coincident
            }
        }
    }

    /// The bound and reference of the point where two lines met.
    fn lines_met(
        &mut self,
        id: ObjId,
        (a, b): (&H<Line>, &H<Line>),
        p: &Point,
        cond: Conditioning,
    ) {
        let step = StepId(self.next_step);
        self.set_tr(id, |bd| {
            let (ta, tb) = (bd.tr(a.id), bd.tr(b.id));
            let across = ((ta.across(&a.g, p), a.g.dir), (tb.across(&b.g, p), b.g.dir));
            let extent = p.coords.norm() + a.g.origin.coords.norm() + b.g.origin.coords.norm();
            let worst = super::accuracy::worse(ta.worst, tb.worst);
            bd.model.cut_lines(step, cond, across, extent, worst)
        });
        self.set_shadow(id, |bd| {
            let ((ao, ad), (bo, bdir)) = (bd.sl(a), bd.sl(b));
            Shadow::Point(refr::meet(&ao, &ad, &bo, &bdir))
        });
    }

    /// Intersects two lines where the construction needs a point: a degenerate case is an error.
    pub fn meet_point(
        &mut self,
        a: &H<Line>,
        b: &H<Line>,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let step = self.step_id_next();
        let caption = note.caption.clone();
        match self.meet(a, b, label, note) {
            Cut::Point(p, _) => Ok(p),
            Cut::Parallel { distance } => Err(ConstructionError::NoIntersection {
                step,
                caption,
                outcome: CutOutcome::Parallel { distance },
            }),
            Cut::Coincident => Err(ConstructionError::NoIntersection {
                step,
                caption,
                outcome: CutOutcome::Coincident,
            }),
        }
    }

    /// Cuts a line with a circle and takes the branch given.
    pub fn cut_line_circle(
        &mut self,
        line: &H<Line>,
        circle: &H<Circle>,
        branch: Branch,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let r = intersect_line_circle(&line.g, &circle.g, &self.tolerance);
        let step = self.step_id_next();
        self.begin(StepKind::IntersectLineCircle, &note, &[line.id, circle.id]);
        let (p, cond, br) = match r {
            LineCircle::Two {
                points,
                conditioning,
            } => {
                let (p, _) = branch.pick(points);
                (p, conditioning, Some(branch))
            }
            LineCircle::Tangent { point } => (point, Conditioning::from_angle(0.0), None),
            LineCircle::Disjoint { gap } => {
                return Err(self.fail_cut(step, &note, CutOutcome::Misses { gap }));
            }
        };
        let h = self.finish_cut(p, cond, br, [line.id, circle.id], label);
        let step = StepId(self.next_step);
        self.set_tr(h.id, |b| {
            let (tl, tc) = (b.tr(line.id), b.tr(circle.id));
            let delta = tl.across(&line.g, &p) + tc.err;
            let (c, r) = (circle.g.center, circle.g.radius);
            let extent = p.coords.norm() + r + c.coords.norm() + line.g.origin.coords.norm();
            let worst = super::accuracy::worse(tl.worst, tc.worst);
            b.model.cut(step, cond, (delta, extent, r), worst)
        });
        self.set_shadow(h.id, |b| {
            let ((o, d), (c, r)) = (b.sl(line), b.sc(circle));
            Shadow::Point(refr::line_circle(&o, &d, &c, r, &p))
        });
        Ok(h)
    }

    /// Records a cut that has no point and returns the error naming its case.
    fn fail_cut(&mut self, step: StepId, note: &Note, outcome: CutOutcome) -> ConstructionError {
        if let Some(s) = self.last_step() {
            s.outcome = Some(outcome.to_string());
        }
        ConstructionError::NoIntersection {
            step,
            caption: note.caption.clone(),
            outcome,
        }
    }

    /// Records the point of a cut: conditioning, branch (none for a tangency), the point, and
    /// the marks on the two curves it lies on.
    fn finish_cut(
        &mut self,
        p: Point,
        cond: Conditioning,
        br: Option<Branch>,
        on: [ObjId; 2],
        label: Label,
    ) -> H<Point> {
        self.last_touched = br.is_none();
        if let Some(s) = self.last_step() {
            s.conditioning = Some(cond);
            s.branch = br;
            if br.is_none() {
                s.outcome = Some("tangent: one double point".into());
            }
        }
        let p = self.mark(p);
        let id = self.add(label, Role::Given, || Geom::Point { at: p });
        self.touch(on[0], &p);
        self.touch(on[1], &p);
        H { id, g: p }
    }

    /// Whether the last cut of a line or circle with a circle found the two touching: one
    /// double point, no branch to choose (a linkage whose links fall into one line). Typed,
    /// on silent boards too.
    pub fn last_cut_touched(&self) -> bool {
        self.last_touched
    }

    /// Cuts two circles and takes the branch given (`First`/`Second` mean right/left of the
    /// line from the first centre to the second).
    pub fn cut_circle_circle(
        &mut self,
        a: &H<Circle>,
        b: &H<Circle>,
        branch: Branch,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let r = intersect_circle_circle(&a.g, &b.g, &self.tolerance);
        let step = self.step_id_next();
        self.begin(StepKind::IntersectCircleCircle, &note, &[a.id, b.id]);
        let (p, cond, br) = match r {
            CircleCircle::Two {
                points,
                conditioning,
            } => (branch.pick(points).0, conditioning, Some(branch)),
            CircleCircle::TangentExternal { point } | CircleCircle::TangentInternal { point } => {
                (point, Conditioning::from_angle(0.0), None)
            }
            other => {
                let outcome = match other {
                    CircleCircle::Separate { gap } => CutOutcome::CirclesApart { gap },
                    CircleCircle::Contained { gap } => CutOutcome::CircleInside { gap },
                    CircleCircle::Concentric => CutOutcome::Concentric,
                    _ => CutOutcome::CirclesCoincide,
                };
                return Err(self.fail_cut(step, &note, outcome));
            }
        };
        let h = self.finish_cut(p, cond, br, [a.id, b.id], label);
        let step = StepId(self.next_step);
        self.set_tr(h.id, |bd| {
            let (ta, tb) = (bd.tr(a.id), bd.tr(b.id));
            let (ga, gb) = (&a.g, &b.g);
            let extent = p.coords.norm()
                + ga.radius
                + gb.radius
                + ga.center.coords.norm()
                + gb.center.coords.norm();
            let worst = super::accuracy::worse(ta.worst, tb.worst);
            let geom = (ta.err + tb.err, extent, ga.radius.max(gb.radius));
            bd.model.cut(step, cond, geom, worst)
        });
        self.set_shadow(h.id, |bd| {
            let ((c1, r1), (c2, r2)) = (bd.sc(a), bd.sc(b));
            Shadow::Point(refr::circle_circle(&c1, r1, &c2, r2, &p))
        });
        Ok(h)
    }

    /// Measures the signed distance from `from` to `to` along the direction of `axis` and
    /// reads it off at `scale`: the drafter's dividers on the scale rule.
    pub fn measure(
        &mut self,
        from: &H<Point>,
        to: &H<Point>,
        axis: &H<Line>,
        scale: Scale,
        label: impl Into<Label>,
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let mm = (to.g - from.g).dot(&axis.g.dir);
        let mm = self.read(mm);
        let value = mm * scale.per_mm;
        self.begin(StepKind::Measure, &note, &[from.id, to.id, axis.id]);
        let unit = scale.unit;
        let id = self.add(label, Role::Result, || Geom::Scalar { value, unit });
        self.set_tr(id, |b| {
            let ends = (&b.tr(from.id), &b.tr(to.id));
            b.model
                .measured(ends, &b.tr(axis.id), mm, scale.per_mm, (&from.g, &to.g))
        });
        self.set_shadow(id, |b| {
            let mm = b.sp(to).sub(&b.sp(from)).dot(&b.sl(axis).1);
            Shadow::Scalar(mm * scale.per_mm)
        });
        H { id, g: value }
    }

    /// Records a number reckoned from constructed values (`inputs`), not drawn: a value the
    /// checks can hold against its closed form, as the balance of the joints under a plan's
    /// forces is held against zero. Its error bound is the sum of its number inputs' bounds
    /// and the rounding of summing them.
    pub fn tally(
        &mut self,
        value: f64,
        unit: &'static str,
        label: impl Into<Label>,
        inputs: &[ObjId],
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let inputs = Weighted {
            inputs,
            weight: 1.0,
        };
        self.reckon(value, unit, label, inputs, note)
    }

    /// [`Board::tally`] with the weight of its inputs: `weight` is how much the number
    /// changes when one of its inputs moves by one unit (a number input) or one mm (a point
    /// input), so that their bounds follow into it: `1/n` for a mean of n ordinates, the
    /// sheet's width plus height for an area reckoned from points of a curve.
    pub fn reckon(
        &mut self,
        value: f64,
        unit: &'static str,
        label: impl Into<Label>,
        weighted: Weighted<'_>,
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let Weighted { inputs, weight } = weighted;
        self.begin(StepKind::Tally, &note, inputs);
        let id = self.add(label, Role::Result, || Geom::Scalar { value, unit });
        self.set_tr(id, |b| {
            let t: Vec<(Track, f64)> = inputs
                .iter()
                .map(|i| {
                    let mut t = b.tr(*i);
                    t.err *= weight.abs();
                    (t, b.number(*i).map_or(0.0, |v| v * weight))
                })
                .collect();
            b.model.reckoned(t.iter(), value)
        });
        H { id, g: value }
    }

    /// Writes a table on the sheet with its top-left corner at `at` (the evaluation of a
    /// plan, LH B.4 "Auswertung"); `inputs` are the objects its numbers were read from.
    pub fn table(&mut self, at: Point, rows: Vec<Vec<String>>, inputs: &[ObjId], note: Note) {
        if !self.recording {
            return;
        }
        self.begin(StepKind::Measure, &note, inputs);
        self.add(Label::NONE, Role::Result, || Geom::Table { at, rows });
    }

    /// Draws a curve through points, smooth or as their polygon ([`Trace`]).
    pub fn curve(
        &mut self,
        points: &[H<Point>],
        trace: Trace,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<ObjId> {
        let Mark { label, role } = mark.into();
        if !self.recording {
            return H {
                id: ObjId::NONE,
                g: ObjId::NONE,
            };
        }
        let ids: Vec<ObjId> = points.iter().map(|p| p.id).collect();
        self.begin(StepKind::Curve, &note, &ids);
        let pts: Vec<Point> = points.iter().map(|p| p.g).collect();
        let id = self.add(label, role, || Geom::Curve {
            points: pts,
            smooth: trace == Trace::Smooth,
        });
        H { id, g: id }
    }

    /// Divides the segment from `a` to `b` into `n ≥ 1` equal parts: the `n + 1` division
    /// points, ends included (the ends are the given points themselves).
    pub fn divide_segment(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        n: usize,
        label: &'static str,
        note: Note,
    ) -> Vec<H<Point>> {
        let mut pts = construct::divide_segment(&Segment { a: a.g, b: b.g }, n);
        let last = pts.len() - 1;
        pts[1..last].iter_mut().for_each(|p| *p = self.mark(*p));
        self.begin(StepKind::Divide, &note, &[a.id, b.id]);
        let last = pts.len() - 1;
        let n = n.max(1);
        let mut out = Vec::with_capacity(pts.len());
        for (k, p) in pts.into_iter().enumerate() {
            if k == 0 {
                out.push(*a);
            } else if k == last {
                out.push(*b);
            } else {
                let id = self.add(Label::quiet(label, k as u32), Role::Given, || Geom::Point {
                    at: p,
                });
                self.between(id, (a, b), k as f64 / n as f64, &p);
                out.push(H { id, g: p });
            }
        }
        out
    }

    /// The point dividing the segment from `a` to `b` in the ratio `t : (1 − t)`, drawn as a
    /// mark on the segment (a tangent of Tolle's parabola divided at the crank angle's
    /// parameter, LH Abb. 55).
    pub fn divide_at(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        t: f64,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        self.finite(t, &note)?;
        let p = construct::point_at_ratio(&Segment { a: a.g, b: b.g }, t);
        let p = self.mark(p);
        self.grow(&p);
        self.begin(StepKind::Divide, &note, &[a.id, b.id]);
        let id = self.add(label, Role::Given, || Geom::Point { at: p });
        self.between(id, (a, b), t, &p);
        Ok(H { id, g: p })
    }

    /// The bound and reference of the point `p` at the ratio `t` from `a` to `b`.
    fn between(&mut self, id: ObjId, (a, b): (&H<Point>, &H<Point>), t: f64, p: &Point) {
        self.set_tr(id, |bd| bd.model.between(&bd.tr(a.id), &bd.tr(b.id), t, p));
        self.set_shadow(id, |bd| Shadow::Point(DP::between(&bd.sp(a), &bd.sp(b), t)));
    }

    /// The angle at `vertex` from the ray through `from` to the ray through `to`, in degrees
    /// in [0°, 180°]: the protractor laid on the drawing.
    pub fn measure_angle(
        &mut self,
        vertex: &H<Point>,
        from: &H<Point>,
        to: &H<Point>,
        label: impl Into<Label>,
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let (u, v) = (from.g - vertex.g, to.g - vertex.g);
        // atan2 of cross and dot keeps every digit near 0° and 180°, where acos loses half.
        let value = u.perp(&v).abs().atan2(u.dot(&v)).to_degrees();
        self.begin(StepKind::Measure, &note, &[vertex.id, from.id, to.id]);
        let id = self.add(label, Role::Result, || Geom::Scalar { value, unit: "°" });
        self.set_tr(id, |b| {
            let (tv, tf, tt) = (b.tr(vertex.id), b.tr(from.id), b.tr(to.id));
            b.model.angle(&tv, &tf, &tt, (u.norm(), v.norm()), value)
        });
        self.set_shadow(id, |b| {
            Shadow::Scalar(refr::angle_deg(&b.sp(vertex), &b.sp(from), &b.sp(to)))
        });
        H { id, g: value }
    }

    /// Attaches a check whose tolerance is a stated bound rather than the rounding of the
    /// construction: a model's difference from the exact value (Tolle's parabola against the
    /// finite rod's exact acceleration is within its truncation bound O(λ³)). The closed form
    /// and the bound are evaluated only on a recording board.
    #[inline]
    pub fn check_within(
        &mut self,
        value: &H<f64>,
        quantity: impl Into<Text>,
        unit: impl Into<Text>,
        formula: impl Into<Text>,
        reference: f64,
        closed_and_bound: impl FnOnce() -> (f64, f64),
    ) {
        if self.recording {
            self.check_recorded(
                value,
                [quantity.into(), unit.into(), formula.into()],
                reference,
                closed_and_bound,
            );
        }
    }

    /// [`Board::check_within`] on a recording board.
    #[inline(never)]
    fn check_recorded(
        &mut self,
        value: &H<f64>,
        [quantity, unit, formula]: [Text; 3],
        reference: f64,
        closed_and_bound: impl FnOnce() -> (f64, f64),
    ) {
        let (closed, model_bound) = closed_and_bound();
        let tolerance = model_bound.max(CHECK_REL * closed.abs().max(reference.abs()));
        let error = (value.g - closed).abs();
        let (bound, worst_cut) = self
            .bound(value.id)
            .unwrap_or((self.model.rel * value.g.abs(), None));
        self.push_check(
            value.id,
            Check {
                quantity,
                unit,
                constructed: value.g,
                closed_form: closed,
                formula,
                error,
                tolerance,
                reference,
                passed: error <= tolerance,
                bound,
                worst_cut,
            },
        );
    }

    /// Attaches an analytic check to the step that made `value`. The closed form is evaluated
    /// only on a recording board. The tolerance is [`CHECK_REL`] × max(|closed form|, `reference`).
    #[inline]
    pub fn check(
        &mut self,
        value: &H<f64>,
        quantity: impl Into<Text>,
        unit: impl Into<Text>,
        formula: impl Into<Text>,
        reference: f64,
        closed_form: impl FnOnce() -> f64,
    ) {
        self.check_within(value, quantity, unit, formula, reference, || {
            (closed_form(), 0.0)
        });
    }

    /// Files a check with the step that made the object `id` (every recording board's
    /// tracks know it, whether it keeps its steps or only its checks).
    fn push_check(&mut self, id: ObjId, check: Check) {
        let Some(step) = self.tracks.step((id.0 as usize).wrapping_sub(1)) else {
            return;
        };
        match self.ledger.as_mut() {
            Some(l) => l.file(step, check),
            None => {
                if let Some(s) = self.steps.get_mut((step.0 as usize).wrapping_sub(1)) {
                    s.checks.push(check);
                }
            }
        }
    }

    /// Per step with a point or a number among its results: how far f64 strayed from the
    /// double-double replay and what the propagated bound predicted (empty unless the board
    /// was made with [`BoardConfig::with_reference`]).
    pub fn reference_report(&self) -> Vec<ReferenceRow> {
        let figure = self.tolerance.length / crate::kernel::tolerance::REL_LENGTH_EPS;
        let mut rows = Vec::new();
        for step in &self.steps {
            let checked = step
                .checks
                .iter()
                .map(|c| c.reference.abs())
                .fold(0.0, f64::max);
            let mut row: Option<ReferenceRow> = None;
            for id in &step.outputs {
                let (Some(obj), t) = (self.object(*id), self.tr(*id)) else {
                    continue;
                };
                let (observed, scale) = match (self.shadow(*id), &obj.geom) {
                    (Shadow::Point(r), Geom::Point { at }) => (r.off(at), figure),
                    (Shadow::Scalar(r), Geom::Scalar { value, .. }) => {
                        let dev = (twofloat::TwoFloat::from(*value) - r).hi().abs();
                        (dev, r.hi().abs().max(checked))
                    }
                    _ => continue,
                };
                let r = row.get_or_insert(ReferenceRow {
                    step: step.id,
                    observed: 0.0,
                    bound: 0.0,
                    scale,
                    worst_cut: None,
                });
                r.observed = r.observed.max(observed);
                r.bound = r.bound.max(t.err);
                r.scale = r.scale.max(scale);
                r.worst_cut = super::accuracy::worse(r.worst_cut, t.worst);
            }
            rows.extend(row);
        }
        rows
    }

    /// The protocol as pretty JSON (deterministic: objects and steps in the order made).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("the board holds only serialisable data")
    }
}
