//! The data of the construction protocol: objects, steps, checks.

use crate::kernel::{Arc, Circle, Conditioning, Line, Point, Segment, Vector};
use serde::{Serialize, Serializer};
use std::borrow::Cow;

/// Text on the board: a caption, a label, a book reference. Borrowed from a literal in the
/// procedures (a board that does not record allocates nothing), owned where a scene or a
/// user names it at run time.
pub type Text = Cow<'static, str>;

/// The id of an object on the board (`o1`, `o2`, …); `NONE` when nothing is recorded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ObjId(pub u32);

impl ObjId {
    /// The id handed out by a board that does not record.
    pub const NONE: ObjId = ObjId(0);
}

impl Serialize for ObjId {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&format!("o{}", self.0))
    }
}

/// A short list of object ids, kept inline up to three.
pub type Ids = smallvec::SmallVec<[ObjId; 3]>;

/// The number of a step, written `001`, `002`, … as in a construction protocol.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StepId(pub u32);

impl std::fmt::Display for StepId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:03}", self.0)
    }
}

impl Serialize for StepId {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.to_string())
    }
}

/// What kind of ruler-and-compass operation a step is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum StepKind {
    /// A given element (centre, axis, guide).
    Given,
    /// A circle drawn with the compass.
    Circle,
    /// A ray or line at a given angle (protractor) or through two points (ruler).
    Line,
    /// A parallel through a point (set squares).
    Parallel,
    /// A perpendicular through a point.
    Perpendicular,
    /// Line ∩ line.
    IntersectLineLine,
    /// Line ∩ circle.
    IntersectLineCircle,
    /// Circle ∩ circle.
    IntersectCircleCircle,
    /// Foot of a perpendicular.
    Foot,
    /// A length laid off at a scale, or a segment drawn between points.
    LayOff,
    /// Equal division of a segment, arc or circle.
    Divide,
    /// A length measured and read off at a scale.
    Measure,
    /// A curve drawn through constructed points.
    Curve,
    /// A number reckoned from constructed values and not drawn: the balance of every joint
    /// under the forces a plan found, read as the drafter sums a joint's forces.
    Tally,
}

/// Which part of a procedure a step belongs to; the unit of lazy evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Topic {
    /// Frame of the figure: centre, axes, crank circle, dead centres.
    Setup,
    /// Crank positions and the piston path (KG Abb. 1047, LH Abb. 49).
    PistonPath,
    /// Piston velocity (KG Abb. 1049, LH Abb. 53).
    Velocity,
    /// Forces in the crank drive (LH Abb. 61, 65; KG Abb. 1061, 1063).
    Forces,
    /// Piston acceleration and the inertia forces, by Tolle's parabola (LH Abb. 55-58,
    /// KG Abb. 1050).
    Acceleration,
    /// Given loads and supports in the position plan (Lageplan).
    Loads,
    /// The force polygon and pole rays (Kräfteplan, Polstrahlen).
    ForcePlan,
    /// The funicular polygon and the resultant (Seilpolygon).
    Funicular,
    /// Support reactions by the closing line (Schlusslinie).
    Reactions,
    /// Moment ordinates M = y·H (Momentenfläche).
    Moment,
    /// The shear diagram (Querkraftdiagramm).
    Shear,
    /// The truss drawn to scale: joints, members, supports (Bauplan).
    Truss,
    /// The Cremona plan: one point per space of Bow's notation, every member once.
    Cremona,
    /// A part of a construction a user makes on a board of their own, by their name for it.
    Custom(&'static str),
}

/// How much of a circle the figure draws: the whole circle (a crank circle, a given circle)
/// or, as a draftsman sets the compass, only short arcs where points are cut on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Drawn {
    /// The whole circle.
    Whole,
    /// Only the compass's marks: short arcs where points are constructed on it.
    Marks,
}

/// How an object is drawn: the textbook's hierarchy of lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// Given elements: full lines of medium weight.
    Given,
    /// Axes and centre lines: dash-dot.
    Axis,
    /// Construction lines: thin.
    Construction,
    /// Auxiliary transfers (parallels carried across): thin dashed.
    Auxiliary,
    /// Results: heavy.
    Result,
    /// Force vectors: medium with an arrowhead.
    Force,
    /// Velocity vectors: medium with an open arrowhead.
    Velocity,
    /// A guide or support: heavy with hatching.
    Guide,
    /// A result drawn beside the curve it is reduced from or compared with: medium dashed
    /// (KG Abb. 1062's η·T beside T, "gestrichelte Linie"; Abb. 1067's resistance line
    /// beside the turning force).
    Reduced,
}

/// Where a part of a figure stands on the sheet: its row (down the sheet) and column
/// (across). A procedure names the part each step draws in (a cylinder's crank figure in row
/// c, column 1; its piston-force diagram in row c, column 0); the sheet layout then sets the
/// rows under one another and the columns side by side, a fixed gap apart, each moved as a
/// whole, so that what one row or column shares (a diagram's base line through the crank's
/// centre, the crank angle's axis) stays shared. A figure that names no part is drawn where
/// it was constructed.
///
/// ```
/// use graphostatik::protocol::Part;
/// assert!(Part::default().is_first());
/// assert!(Part::at(1, 0) > Part::at(0, 3));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default, Serialize)]
pub struct Part {
    /// The row, from the top of the sheet.
    pub row: u16,
    /// The column, from the left.
    pub col: u16,
    /// Whether the layout sets the part out in its row alone: its top level with the row's,
    /// a gap right of the part before it in the row, whatever the parts of other rows are
    /// (a truss's drawing, force polygon and plan, each constructed at its own origin and of
    /// another size in every load case). Otherwise the part keeps the height it was
    /// constructed at and moves with its column, so that what a row or a column shares (a
    /// diagram's base line through the centre of the crank beside it) stays shared.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub packed: bool,
    /// Whether the part shares nothing with a row or a column (a table of results): the
    /// layout sets it in a hole of the sheet the other parts leave, where its box fits clear
    /// of every part and line, nearest to where its row and column would put it; only where
    /// no hole takes it does it stand in its row and column.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub free: bool,
    /// Whether the part is constructed and checked but not drawn: a figure leaves its steps
    /// out (LH Aufgabe 5 draws the plans of the dead load and of three crane positions; the
    /// other positions are computed, Tabelle 2). Set by
    /// [`Board::unseen`](crate::protocol::Board::unseen).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub hidden: bool,
}

impl Part {
    /// The part in row `row` and column `col`.
    pub const fn at(row: u16, col: u16) -> Part {
        Part {
            row,
            col,
            packed: false,
            free: false,
            hidden: false,
        }
    }
    /// The part in row `row` and column `col`, set out in its row alone ([`Part::packed`]).
    pub const fn packed(row: u16, col: u16) -> Part {
        Part {
            row,
            col,
            packed: true,
            free: false,
            hidden: false,
        }
    }
    /// The part in row `row` and column `col` unless the sheet has a hole its box fits in
    /// ([`Part::free`]).
    pub const fn free(row: u16, col: u16) -> Part {
        Part {
            row,
            col,
            packed: false,
            free: true,
            hidden: false,
        }
    }
    /// Whether it is the first row's first column (where a figure that names no part is).
    pub fn is_first(&self) -> bool {
        *self == Part::default()
    }
}

/// What a step's object is drawn as: its pen ([`Role`]) and the name written at it
/// ([`Label`]). A role alone is an unlettered object, so that a step call reads one step per
/// line: `b.parallel(&l, &p, Role::Construction, n)`, `b.point(p, Role::Given.named("A"), n)`.
///
/// ```
/// use graphostatik::protocol::{Label, Mark, Role};
/// let m: Mark = Role::Construction.into();
/// assert_eq!(m.label, Label::NONE);
/// assert_eq!(Role::Given.named("A").label, Label::plain("A"));
/// assert_eq!(Role::Result.labelled(Label::indexed("B", 3)).role, Role::Result);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mark {
    /// The name written at the object.
    pub label: Label,
    /// The pen it is drawn with.
    pub role: Role,
}

impl From<Role> for Mark {
    fn from(role: Role) -> Mark {
        Mark {
            label: Label::NONE,
            role,
        }
    }
}

impl Role {
    /// This pen with a plain name written at the object (`Role::Given.named("A")`).
    pub const fn named(self, base: &'static str) -> Mark {
        Mark {
            label: Label::plain(base),
            role: self,
        }
    }
    /// This pen with a label made elsewhere (an index, a scene's name).
    pub fn labelled(self, label: Label) -> Mark {
        Mark { label, role: self }
    }
}

impl From<&'static str> for Label {
    fn from(base: &'static str) -> Label {
        Label::plain(base)
    }
}

/// The name written at an object: `base` with an optional index (`B₃`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Label {
    /// The letter(s), or the name a scene gives (`U1`).
    pub base: Text,
    /// The index, written as a subscript.
    pub index: Option<u32>,
    /// Whether the figure writes it (construction points keep their name in the protocol
    /// but stay unlettered in the figure, as in the books).
    pub shown: bool,
}

/// The most positions of a crowd (a divided crank circle) the figure letters each of: more
/// are lettered every second, third … ([`Label::of_crowd`]).
pub const CROWD_LETTERED: usize = 12;

impl Label {
    /// A label without index.
    pub const fn plain(base: &'static str) -> Label {
        Label {
            base: Cow::Borrowed(base),
            index: None,
            shown: true,
        }
    }
    /// A label made at run time (a member or joint named in a scene), without index.
    pub fn named(base: impl Into<Text>) -> Label {
        Label {
            base: base.into(),
            index: None,
            shown: true,
        }
    }
    /// The label of a name a scene gives, written as the books write it: letters followed by
    /// a number become the letters with the number as index (`"U1"` is U₁, `"B0"` is B₀);
    /// any other name is written as it is (`"II"`, `"W"`, `"U01"`, `"Stab a"`).
    ///
    /// ```
    /// use graphostatik::protocol::Label;
    /// assert_eq!(Label::from_name("U12"), Label::indexed("U", 12));
    /// assert_eq!(Label::from_name("III"), Label::plain("III"));
    /// assert_eq!(Label::from_name("U01").index, None);
    /// ```
    pub fn from_name(name: &str) -> Label {
        let split = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
        let (base, digits) = name.split_at(split);
        let canonical = !digits.is_empty() && (digits == "0" || !digits.starts_with('0'));
        match digits.parse::<u32>() {
            Ok(i) if canonical && !base.is_empty() && base.chars().all(char::is_alphabetic) => {
                Label {
                    base: Cow::Owned(base.to_string()),
                    index: Some(i),
                    shown: true,
                }
            }
            _ => Label::named(name.to_string()),
        }
    }
    /// A label with an index.
    pub const fn indexed(base: &'static str, index: u32) -> Label {
        Label {
            base: Cow::Borrowed(base),
            index: Some(index),
            shown: true,
        }
    }
    /// The k-th of a crowd of `n` positions (crank pins, load positions) named
    /// `base`, written in the figure only where the books letter it: every position up to
    /// [`CROWD_LETTERED`] of them, every second up to twice as many, and so on (the plates
    /// letter 0, 1, 2 … or every second of a finely divided crank circle); the others keep
    /// their name in the protocol.
    ///
    /// ```
    /// use graphostatik::protocol::Label;
    /// assert!(Label::of_crowd("A", 5, 12).shown);
    /// assert!(!Label::of_crowd("A", 5, 24).shown && Label::of_crowd("A", 6, 24).shown);
    /// assert_eq!(Label::of_crowd("A", 9, 48).to_string(), "A9");
    /// ```
    pub fn of_crowd(base: &'static str, k: u32, n: usize) -> Label {
        Label {
            shown: (k as usize) % Label::crowd_every(n) == 0,
            ..Label::indexed(base, k)
        }
    }
    /// Every how many of a crowd of `n` positions one is lettered ([`Label::of_crowd`]).
    pub fn crowd_every(n: usize) -> usize {
        n.div_ceil(CROWD_LETTERED).max(1)
    }
    /// A name kept in the protocol but not written in the figure.
    pub const fn quiet(base: &'static str, index: u32) -> Label {
        Label {
            base: Cow::Borrowed(base),
            index: Some(index),
            shown: false,
        }
    }
    /// No label.
    pub const NONE: Label = Label {
        base: Cow::Borrowed(""),
        index: None,
        shown: false,
    };
    /// True if nothing is written.
    pub fn is_empty(&self) -> bool {
        self.base.is_empty() || !self.shown
    }
}

impl std::fmt::Display for Label {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.index {
            Some(i) => write!(f, "{}{}", self.base, i),
            None => write!(f, "{}", self.base),
        }
    }
}

/// The words of a step: an English caption, the German book term, the book reference, and the
/// topic it belongs to. The procedures' notes are `const` (borrowed text, so that a board that
/// does not record allocates nothing); a user's construction can make its own at run time.
///
/// ```
/// use graphostatik::protocol::{Note, Topic};
/// let n = Note::new(format!("resultant of {} forces", 3), Topic::Custom("my resultant"))
///     .term("Mittelkraft")
///     .book("LH Abb. 22");
/// assert_eq!(n.caption, "resultant of 3 forces");
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Note {
    /// Short English caption ("arc with the rod length about the crank pin").
    pub caption: Text,
    /// The German book term, where the books have one ("Schubstangenkreisbogen").
    pub term_de: Option<Text>,
    /// Book reference ("KG Abb. 1047; LH Abb. 49").
    pub book: Text,
    /// The part of the procedure.
    pub topic: Topic,
}

impl Note {
    /// A note with a caption (any string) and a topic; no German term, no book reference.
    pub fn new(caption: impl Into<Text>, topic: Topic) -> Note {
        Note {
            caption: caption.into(),
            term_de: None,
            book: Cow::Borrowed(""),
            topic,
        }
    }
    /// With the German book term.
    pub fn term(mut self, term_de: impl Into<Text>) -> Note {
        self.term_de = Some(term_de.into());
        self
    }
    /// With the book reference.
    pub fn book(mut self, book: impl Into<Text>) -> Note {
        self.book = book.into();
        self
    }
}

/// A [`Note`] in one line, for the `const` notes of the procedures.
pub const fn note(
    caption: &'static str,
    term_de: Option<&'static str>,
    book: &'static str,
    topic: Topic,
) -> Note {
    Note {
        caption: Cow::Borrowed(caption),
        term_de: match term_de {
            Some(t) => Some(Cow::Borrowed(t)),
            None => None,
        },
        book: Cow::Borrowed(book),
        topic,
    }
}

/// The geometry of an object.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "type")]
pub enum Geom {
    /// A point.
    Point {
        /// Position (mm on the sheet).
        at: Point,
    },
    /// A line, drawn over the parameter interval `extent` (mm along its direction).
    Line {
        /// The infinite line.
        line: Line,
        /// Drawn part, grown to cover every point constructed on it.
        extent: [f64; 2],
    },
    /// A segment.
    Segment {
        /// The segment.
        segment: Segment,
    },
    /// A vector drawn with an arrowhead (a force or velocity at its scale).
    Vector {
        /// Tail and head.
        segment: Segment,
    },
    /// A circle; `full` draws it whole, otherwise only short compass arcs at `marks` (degrees).
    Circle {
        /// The circle.
        circle: Circle,
        /// Whether the whole circle is drawn.
        full: bool,
        /// Angles (degrees) of the points constructed on it, where compass arcs are drawn.
        marks: Vec<f64>,
    },
    /// An arc.
    Arc {
        /// The arc.
        arc: Arc,
    },
    /// A curve through points: a smooth curve through exact points (a velocity curve, a
    /// parabola), or a polygon (`smooth: false`: a shear diagram, a load outline).
    Curve {
        /// The points, in order.
        points: Vec<Point>,
        /// Smooth through the points, or straight between them.
        smooth: bool,
    },
    /// A table written on the sheet (the book's "Auswertung" next to a force plan): rows of
    /// cells, the first row the header, its top-left corner at `at`. Beyond
    /// [`TABLE_BLOCK_ROWS`] rows it is written in blocks side by side, each under the header.
    Table {
        /// Top-left corner (mm on the sheet).
        at: Point,
        /// The rows, each the same number of cells.
        rows: Vec<Vec<String>>,
    },
    /// A measured number.
    Scalar {
        /// The value in the quantity's unit.
        value: f64,
        /// The unit.
        unit: &'static str,
    },
}

/// Most body rows of a table block on the sheet; a longer table continues in a block beside.
pub const TABLE_BLOCK_ROWS: usize = 30;

/// An object on the board.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Object {
    /// Its id.
    pub id: ObjId,
    /// The step that made it.
    pub step: StepId,
    /// Its name in the figure.
    pub label: Label,
    /// How it is drawn.
    pub role: Role,
    /// Its geometry.
    pub geom: Geom,
}

/// An analytic check: a constructed value against the closed form it stands for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    /// The quantity ("piston path x").
    pub quantity: Text,
    /// The object checked, where the quantity and the step's context do not name it
    /// ("member 5" of a truss: every member's force is one quantity, read at its joint).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub object: Option<std::sync::Arc<str>>,
    /// Its unit.
    pub unit: Text,
    /// The value read off the construction at its scale.
    pub constructed: f64,
    /// The closed-form value.
    pub closed_form: f64,
    /// The formula it comes from ("KG (285), LH Gl. 20").
    pub formula: Text,
    /// |constructed − closed form|.
    pub error: f64,
    /// The tolerance: `CHECK_REL × max(|closed form|, reference)`.
    pub tolerance: f64,
    /// The natural magnitude the tolerance is relative to.
    pub reference: f64,
    /// Whether the check is not failed: the error is within the tolerance, or, where the
    /// bound exceeds the tolerance, within the bound ([`Check::judged`]).
    pub passed: bool,
    /// What the constructed value's error can be, propagated through every step it depends
    /// on from f64's rounding (the board's error model): each cut amplifies the errors of the
    /// curves it cuts by 1 / sin of its angle.
    pub bound: f64,
    /// The most glancing cut the constructed value depends on, its own step's or any before.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub worst_cut: Option<crate::protocol::WorstCut>,
}

impl Check {
    /// Whether the value depends on a glancing cut (below
    /// [`GLANCING_ANGLE`](crate::kernel::tolerance::GLANCING_ANGLE)).
    pub fn glancing(&self) -> bool {
        self.worst_cut.is_some_and(|w| w.conditioning.glancing())
    }

    /// Whether the check can judge its value: its propagated bound lies within its
    /// tolerance. Where it does not, an error within the tolerance may be the rounding's luck
    /// (a joint 1e-10 m off the line of its members: forces of 5e12 kg, a bound of 1.55e8 kg
    /// against a tolerance of 5,000), and an error past the tolerance but within the bound
    /// what the rounding at this conditioning gives (a scene drawn at 1e-9 of its lengths):
    /// the value cannot be judged, the check is not failed ([`Check::passed`] holds, an error
    /// past the bound fails), and the check table says "not judged" instead of "ok".
    pub fn judged(&self) -> bool {
        self.bound.partial_cmp(&self.tolerance) != Some(std::cmp::Ordering::Greater)
    }
}

/// One step of the construction protocol.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Step {
    /// Its number.
    pub id: StepId,
    /// The operation.
    pub kind: StepKind,
    /// The part of the procedure.
    pub topic: Topic,
    /// English caption.
    pub caption: Text,
    /// German book term.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub term_de: Option<Text>,
    /// Book reference.
    pub book: Text,
    /// The situation the step is made in ("θ = 30°"), shared by the steps made in it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub context: Option<std::sync::Arc<str>>,
    /// Ids of the objects it uses (inline up to three: no allocation for a ruler step).
    pub inputs: Ids,
    /// Ids of the objects it makes (inline up to three).
    pub outputs: Ids,
    /// For an intersection: how well it was conditioned.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conditioning: Option<Conditioning>,
    /// For a two-point intersection: which branch was taken.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub branch: Option<crate::kernel::Branch>,
    /// For a degenerate outcome: what happened instead ("parallel: meets at infinity").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outcome: Option<String>,
    /// Analytic checks attached to this step.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub checks: Vec<Check>,
    /// The part of the figure it draws in ([`Part`]).
    #[serde(skip_serializing_if = "Part::is_first")]
    pub part: Part,
}

impl Geom {
    /// Moves the drawing by `by` (mm on the sheet): the sheet layout setting a part out.
    /// Numbers stay as they are.
    pub fn translate(&mut self, by: Vector) {
        match self {
            Geom::Point { at } | Geom::Table { at, .. } => *at += by,
            Geom::Line { line, .. } => line.origin += by,
            Geom::Segment { segment } | Geom::Vector { segment } => {
                segment.a += by;
                segment.b += by;
            }
            Geom::Circle { circle, .. } => circle.center += by,
            Geom::Arc { arc } => arc.circle.center += by,
            Geom::Curve { points, .. } => points.iter_mut().for_each(|p| *p += by),
            Geom::Scalar { .. } => {}
        }
    }
}

impl Step {
    /// `NNN caption (context)`, the layer name.
    pub fn title(&self) -> String {
        match &self.context {
            Some(c) => format!("{} {} ({})", self.id, self.caption, c),
            None => format!("{} {}", self.id, self.caption),
        }
    }
}
