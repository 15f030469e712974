//! The board: every kernel operation, recorded as a step.

use super::accuracy::{ErrorModel, Track, Worst, WorstCut};
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

mod cut;
mod draw;
mod follow;
mod keep;
mod read;

use keep::Ledger;

/// A handle to an object on the board: its id and its geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct H<T> {
    /// The object id ([`ObjId::NONE`] on a board that does not record, and for what a board
    /// that keeps only its checks only draws: a segment, a curve).
    pub id: ObjId,
    /// The geometry or value.
    pub g: T,
}

impl H<f64> {
    /// The number 0 of no object: what a caller carries where nothing was read (its
    /// transfer lays off nothing and carries no bound).
    pub const NONE_ZERO: H<f64> = H {
        id: ObjId::NONE,
        g: 0.0,
    };
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
    /// The situation the next step is made in, on a board without a ledger (one that keeps
    /// only its checks keeps it as the ledger's last context).
    #[serde(skip)]
    context: Option<std::sync::Arc<str>>,
    /// The object the checks made inside [`Board::checking`] name.
    #[serde(skip)]
    checked_object: Option<std::sync::Arc<str>>,
    /// Where [`Board::naming`] and [`Board::checking`] write a name before it is shared
    /// (kept for its room).
    #[serde(skip)]
    scratch: String,
    /// The part of the figure the next steps draw in.
    #[serde(skip)]
    part: Part,
    /// Whether the steps made now are constructed and checked but not drawn
    /// ([`Board::unseen`]).
    #[serde(skip)]
    unseen: bool,
    #[serde(skip)]
    next_step: u32,
    /// The most steps kept ([`BoardConfig::keep_steps`]); past it the board only counts.
    #[serde(skip)]
    keep_steps: u32,
    /// Whether the board went past `keep_steps` and let go of what it kept.
    #[serde(skip)]
    spilled: bool,
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
            checked_object: None,
            scratch: String::new(),
            part: Part::default(),
            unseen: false,
            next_step: 0,
            keep_steps: config.keep_steps.unwrap_or(u32::MAX),
            spilled: false,
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

    /// A silent board with this board's tolerance: for a trial run whose drawing is not kept
    /// (the counter-diagonals' trial plans, LH B.5).
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

    /// Whether the board went past the steps it may keep ([`BoardConfig::keep_steps`]): it
    /// then let go of its steps, objects, bounds and checks and only counted on, as a board
    /// that does not record; [`Board::step_count`] still counts every step.
    pub fn spilled(&self) -> bool {
        self.spilled
    }

    /// How many objects were made on a recording board (kept, or only counted where the board
    /// keeps only its checks); 0 on a board that does not record.
    pub fn object_count(&self) -> usize {
        self.tracks.len() + self.ledger.as_ref().map_or(0, |l| l.drawings)
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

    /// The situation the next steps are made in ("dead load: joint III"), where one is set
    /// and the board records: a shared construction names its objects within it.
    pub fn context(&self) -> Option<std::sync::Arc<str>> {
        match self.ledger.as_deref() {
            Some(l) => l.current().cloned(),
            None => self.context.clone(),
        }
    }

    /// Sets the context to `base` (the caller's, from [`Board::context`]) followed by
    /// `what` ("dead load: ray 2"; "ray 2" where there was none), for steps that
    /// make no check: only a board that keeps its drawing names them, so that a board that
    /// keeps only its checks spends nothing on it (a beam of a million loads).
    pub fn set_context_within(&mut self, base: Option<&str>, what: impl FnOnce() -> String) {
        if self.is_drawing() {
            self.set_context(|| match base {
                Some(c) => format!("{c}: {}", what()),
                None => what(),
            });
        }
    }

    /// Runs `steps` with their context naming `what` after the caller's ("dead load: joint
    /// I" becomes "dead load: joint I, member 1"), on a board that records (so that its checks
    /// read alike with and without the drawing); the caller's context is put back after. For
    /// steps of one situation that differ only in their object (the two member forces read
    /// off a joint's polygon), so that each has a situation of its own in the walk-through. A
    /// check made within names `what` once: the check table leaves out an object its context
    /// names already.
    ///
    /// ```
    /// use graphostatik::kernel::Point;
    /// use graphostatik::protocol::{Board, Note, Role, Topic};
    /// let n = Note::new("member force", Topic::Custom("doc"));
    /// let mut b = Board::recording();
    /// b.set_context(|| "dead load: joint I".into());
    /// b.naming(|s| s.push_str("member 1"), |b| b.point(Point::new(0.0, 0.0), Role::Result, n.clone()));
    /// b.point(Point::new(1.0, 0.0), Role::Result, n);
    /// let contexts: Vec<_> = b.steps().iter().map(|s| s.context.as_deref()).collect();
    /// assert_eq!(contexts, [Some("dead load: joint I, member 1"), Some("dead load: joint I")]);
    /// ```
    pub fn naming<R>(
        &mut self,
        what: impl FnOnce(&mut String),
        steps: impl FnOnce(&mut Board) -> R,
    ) -> R {
        if !self.recording {
            return steps(self);
        }
        let base = self.context();
        // One allocation a naming where the name, the joined text and the shared one were
        // three (a truss check names every member force it reads).
        let named = self.written(|s| {
            if let Some(c) = &base {
                s.push_str(c);
                s.push_str(", ");
            }
            what(s);
        });
        self.put_context(Some(named));
        let out = steps(self);
        self.set_context_to(base);
        out
    }

    /// A text written by `write` into the board's buffer (kept for its room) and shared:
    /// one allocation, the shared text's own.
    fn written(&mut self, write: impl FnOnce(&mut String)) -> std::sync::Arc<str> {
        let mut s = std::mem::take(&mut self.scratch);
        s.clear();
        write(&mut s);
        let shared = s.as_str().into();
        self.scratch = s;
        shared
    }

    /// Puts back a context taken with [`Board::context`] after
    /// [`Board::set_context_within`].
    pub fn restore_context(&mut self, base: Option<std::sync::Arc<str>>) {
        if self.is_drawing() {
            self.set_context_to(base);
        }
    }

    /// Sets the context to one taken with [`Board::context`] (`None` clears it), on a board
    /// that records: for a construction whose steps and checks are named within its caller's
    /// situation on every board that records them (the crank's "HP, θ = 30°").
    pub fn set_context_to(&mut self, context: Option<std::sync::Arc<str>>) {
        match context {
            Some(c) if self.recording => self.put_context(Some(c)),
            Some(_) => {}
            None => self.clear_context(),
        }
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

    /// The step with this id (on a board that keeps its drawing).
    pub fn step(&self, id: StepId) -> Option<&Step> {
        // Ids are dense and start at 1.
        self.steps.get((id.0 as usize).wrapping_sub(1))
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
            self.put_context(Some(f().into()));
        }
    }

    /// Makes `c` the context of the next steps (`None` clears it). A board that keeps only
    /// its checks keeps its contexts in its ledger alone (the last one filed is the one
    /// now): a context moves there, shared by nothing else, and a naming costs no count of
    /// its text's owners but the one that keeps the caller's.
    fn put_context(&mut self, c: Option<std::sync::Arc<str>>) {
        match self.ledger.as_mut() {
            Some(l) => l.set_context(StepId(self.next_step + 1), c),
            None => self.context = c,
        }
    }

    /// Reserves room for `steps` more steps and `objects` more objects, so that a long
    /// construction does not spend its time moving a growing protocol around in memory.
    /// (A board that keeps only its checks files no steps and objects, only their bounds,
    /// which grow in chunks: room is made in the first.) Room is made for no more steps than
    /// the board may keep ([`BoardConfig::keep_steps`]), and for their share of the objects:
    /// a figure too large to draw asks for room it will never use (64 cylinders at 3,600
    /// divisions, 6.2 million steps).
    ///
    /// ```
    /// use graphostatik::protocol::{Board, BoardConfig};
    /// let mut b = Board::new(BoardConfig::DRAWING.keeping_at_most(100));
    /// b.reserve(1 << 40, 1 << 41); // room for 100 steps and 200 objects, not a trillion
    /// assert_eq!(b.step_count(), 0);
    /// ```
    pub fn reserve(&mut self, steps: usize, objects: usize) {
        let room = (self.keep_steps as usize).saturating_sub(self.next_step as usize);
        let (steps, objects) = match steps > room {
            // Objects in the proportion asked for: objects / steps of the steps kept.
            true => (
                room,
                (objects as u128 * room as u128 / steps as u128) as usize,
            ),
            false => (steps, objects),
        };
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
        self.part = Part {
            hidden: part.hidden || self.unseen,
            ..part
        };
    }

    /// Runs `f` with its steps constructed and checked as any others, but not drawn: every
    /// part they draw in is [`Part::hidden`], and a figure leaves them out. The book draws
    /// a few cases and computes the rest: LH Aufgabe 5 draws the Cremona plans of the dead
    /// load and of crane positions I, II and III, and finds the others' diagonals by
    /// D = A / sin δ (Tabelle 2).
    ///
    /// ```
    /// use graphostatik::kernel::Point;
    /// use graphostatik::protocol::{Board, Note, Part, Role, Topic};
    /// let mut b = Board::recording();
    /// let n = |caption: &str| Note::new(caption.to_string(), Topic::Truss);
    /// b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n("drawn"));
    /// b.unseen(|b| {
    ///     b.set_part(Part::at(1, 0));
    ///     b.point(Point::new(1.0, 0.0), Role::Given.named("B"), n("computed"))
    /// });
    /// assert!(!b.steps()[0].part.hidden && b.steps()[1].part.hidden);
    /// assert_eq!(b.drawn_objects().count(), 1);
    /// ```
    pub fn unseen<R>(&mut self, f: impl FnOnce(&mut Board) -> R) -> R {
        let (was, part) = (self.unseen, self.part);
        self.unseen = true;
        self.set_part(part);
        let r = f(self);
        self.unseen = was;
        self.part = part;
        r
    }

    /// Hides from the figure the steps of every part `keep` refuses, as [`Board::unseen`]
    /// hides a part constructed and not drawn: a figure split into pages draws each page
    /// from the board with the other pages' parts hidden. The steps, numbers and checks stay.
    ///
    /// ```
    /// use graphostatik::kernel::Point;
    /// use graphostatik::protocol::{Board, Note, Part, Role, Topic};
    /// let mut b = Board::recording();
    /// let n = || Note::new("given", Topic::Truss);
    /// b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n());
    /// b.set_part(Part::at(1, 0));
    /// b.point(Point::new(1.0, 0.0), Role::Given.named("B"), n());
    /// b.show_only(|p| p.row == 1);
    /// assert_eq!(b.drawn_objects().count(), 1);
    /// ```
    pub fn show_only(&mut self, keep: impl Fn(Part) -> bool) {
        for s in &mut self.steps {
            if !keep(s.part) {
                s.part.hidden = true;
            }
        }
    }

    /// The objects a figure draws: those of the steps not in a [`Part::hidden`] part.
    pub fn drawn_objects(&self) -> impl Iterator<Item = &Object> + '_ {
        (self.objects.iter()).filter(|o| self.step(o.step).is_none_or(|s| !s.part.hidden))
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
        self.put_context(None);
    }

    /// Runs `checks` with their object named by `object` (made on a recording board only):
    /// the check table then says which member a member force is ("member 5"), where the
    /// quantity is the same for every member.
    ///
    /// ```
    /// use graphostatik::protocol::{Board, Label, Note, Topic};
    /// let n = Note::new("sum", Topic::Custom("doc"));
    /// let mut b = Board::recording();
    /// let s = b.tally(2400.0, "kg", Label::NONE, &[], n);
    /// let closed = || 2400.0;
    /// b.checking(|name| name.push_str("member 5"), |b| b.check(&s, "member force", "kg", "ΣY = 0", 1.0, closed));
    /// assert_eq!(b.steps().last().unwrap().checks[0].object.as_deref(), Some("member 5"));
    /// ```
    pub fn checking(&mut self, object: impl FnOnce(&mut String), checks: impl FnOnce(&mut Board)) {
        if self.recording {
            // Shared by every check made within: one allocation for the name (a truss
            // check names every member it checks).
            self.checked_object = Some(self.written(object));
        }
        checks(self);
        self.checked_object = None;
    }

    /// The protocol as pretty JSON (deterministic: objects and steps in the order made).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("the board holds only serialisable data")
    }
}
