//! The [`Procedure`] trait: what a book procedure is to the scene format.
//!
//! A procedure is one scene type that implements [`Procedure`]: its header fields come from
//! the crate-internal `scene_struct!` macro; [`Procedure::problem`] reads the parsed scene into
//! the problem it describes, refusing a value that does not hold; the construction, figure
//! metadata and outputs come from the other items. Adding a procedure is its own module and one line in the registry
//! ([`REGISTRY`](super::REGISTRY)).

use super::error::SceneError;
use super::sweep::Setting;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta};
use std::fmt::Debug;

/// The header every scene starts with (`procedure`, `title`, `source`, `notes`), declared once
/// by the crate-internal `scene_struct!` macro that every scene struct is written in.
pub trait SceneHeader {
    /// The `procedure` field as written (absent for a slider-crank scene that leaves it out).
    fn procedure_field(&self) -> Option<&str>;
    /// Title written on the figure.
    fn title(&self) -> &str;
    /// Book reference written under the title (empty when absent).
    fn source(&self) -> &str;
    /// Free notes on where the numbers come from (not drawn).
    fn notes(&self) -> Option<&str>;
    /// The numbers the book prints that the scene reproduces ([`BookValue`]).
    ///
    /// [`BookValue`]: crate::scene::BookValue
    fn book(&self) -> &[crate::scene::BookValue];
    /// What the live page lets a student move besides the given points.
    fn preview(&self) -> Option<&crate::scene::Preview>;
    /// What the book's plate letters (the scene's `plate` field).
    fn plate(&self) -> &[String];
    /// The paper the figure is set on (the scene's `paper` field), where the scene names one.
    fn paper(&self) -> Option<crate::protocol::Paper>;
}

/// A type with a JSON Schema where the `schema` feature is on (the default, with `cli`);
/// every type otherwise, so that a library user does not compile `schemars`.
#[cfg(feature = "schema")]
pub trait SchemaType: schemars::JsonSchema {}
#[cfg(feature = "schema")]
impl<T: schemars::JsonSchema> SchemaType for T {}
/// A type with a JSON Schema where the `schema` feature is on; every type here, where it is
/// off.
#[cfg(not(feature = "schema"))]
pub trait SchemaType {}
#[cfg(not(feature = "schema"))]
impl<T> SchemaType for T {}

/// One book procedure as the scene format sees it: what the scene is called, how its values
/// are checked, what it constructs and what the sheet writes besides the construction.
///
/// The scene type itself implements the trait; [`AnyScene`](super::AnyScene) dispatches to it by the scene's
/// `procedure` field through [`REGISTRY`](super::REGISTRY).
///
/// ```
/// use graphostatik::protocol::BoardConfig;
/// use graphostatik::scene::{BeamScene, Procedure};
/// let (scene, problem) = BeamScene::read(r#"{
///   "procedure": "beam", "title": "LH Abb. 24",
///   "beam": { "supports_m": [0, 6] },
///   "point_loads": [ { "x_m": 2, "kg": 600 } ]
/// }"#, "inline").unwrap();
/// assert_eq!(scene.point_loads.len(), 1);
/// let (board, results) = BeamScene::construct(&problem, BoardConfig::DRAWING).unwrap();
/// assert!(board.all_passed());
/// assert!((results.reactions.a - 400.0).abs() < 1e-9); // A = 600·4/6 (LH C.4)
/// ```
pub trait Procedure:
    SceneHeader + serde::de::DeserializeOwned + SchemaType + Debug + Clone + Send + Sync + 'static
{
    /// The value of the scene's `procedure` field (`"beam"`).
    const NAME: &'static str;
    /// One line on what it constructs and where the books have it.
    const ABOUT: &'static str;
    /// What sets the size of its figure, as a refusal of a figure too large names it
    /// (`"angles (crank positions) or outputs"`).
    const SIZED_BY: &'static str = "loads or parts";
    /// What a scene can ask for besides the procedure's core (its `outputs` values).
    const OUTPUTS: &'static [&'static str] = &[];
    /// The validated scene in machine units, with every scale chosen.
    type Problem: Debug + Clone + Send + Sync + 'static;
    /// The named results of a construction.
    type Results;

    /// The problem the parsed scene describes, in machine units with every scale chosen; a
    /// value that does not hold is refused with an error naming its field. `ctx` says where
    /// the scene comes from and what it is read for (the limits of a figure, or of a check).
    fn problem(&self, ctx: &ReadContext) -> Result<Self::Problem, SceneError>;
    /// Parses a scene of this procedure and reads it into its problem, under the limits of a
    /// figure ([`parse_scene`]); `origin` (a file name) prefixes every error.
    fn read(text: &str, origin: &str) -> Result<(Self, Self::Problem), SceneError> {
        parse_scene::<Self>(text, &ReadContext::figure(origin))
    }
    /// Constructs the problem on fresh boards set up by `config`.
    fn construct(
        problem: &Self::Problem,
        config: BoardConfig,
    ) -> Result<(Board, Self::Results), ConstructionError>;
    /// Title, source and scale bars of the figure.
    fn figure_meta(problem: &Self::Problem) -> FigureMeta;

    /// The knobs of this procedure that trade time for accuracy, swept by `graphostatik
    /// accuracy` beside the precision every scene has: each setting constructs the problem
    /// so set and measures its error against the exact value. None by default; only what the
    /// problem asks for is swept (a beam without uniform loads has no point-load knob).
    fn sweeps(problem: &Self::Problem) -> Vec<Setting<'_>> {
        let _ = problem;
        Vec::new()
    }

    /// How large the figure comes out on the sheet at the problem's scales (mm), with the
    /// scale field that drives it: its lengths against the length scale and its forces against
    /// the force scale, whichever is larger. Checked against `MAX_SHEET_MM` when a scene
    /// is read, so that an absurd scale is named as such.
    fn sheet_extent(problem: &Self::Problem) -> (f64, &'static str) {
        let _ = problem;
        (0.0, "")
    }

    /// The smallest diagram the problem asks to draw (its largest ordinate, mm on the sheet)
    /// and the scale field that sets it; checked against
    /// [`MIN_PART_REL`](crate::kernel::tolerance::MIN_PART_REL) times the figure's extent
    /// when a scene is read, so that a scale that shrinks a diagram to nothing beside its
    /// sheet is named. `None`: the procedure draws one part.
    fn smallest_part(problem: &Self::Problem) -> Option<(f64, &'static str)> {
        let _ = problem;
        None
    }

    /// Two quantities the figure draws at one scale, as far apart in size as its inputs
    /// make them: their ratio (largest over smallest), what they are, and the input field
    /// that sets it. Beyond 1/[`MIN_PART_REL`](crate::kernel::tolerance::MIN_PART_REL) no
    /// scale draws both on a sheet, and the scene is refused naming that input, not the
    /// scale (whose every value would be refused in turn). `None` by default.
    fn spread(problem: &Self::Problem) -> Option<Spread> {
        let _ = problem;
        None
    }

    /// How the procedure's own inputs (`ConstructionError::Unsupported::input`, e.g.
    /// `"forces[2]"`, `"pole"`) are called in the scene: pairs of (input prefix, scene field).
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[];
    /// The scene field a construction that finds no point (a cut that misses, a degenerate
    /// primitive) is blamed on: what sets the geometry.
    const GEOMETRY_FIELD: &'static str = "";

    /// The scene field a construction error comes from, so that the error can name it:
    /// by [`Procedure::INPUT_FIELDS`] for an input the procedure names, else
    /// [`Procedure::GEOMETRY_FIELD`].
    fn error_field(problem: &Self::Problem, err: &ConstructionError) -> Option<String> {
        let _ = problem;
        match err {
            ConstructionError::Unsupported { input, .. } => {
                Some(scene_field(input, Self::INPUT_FIELDS))
            }
            _ => Some(Self::GEOMETRY_FIELD.to_string()).filter(|f| !f.is_empty()),
        }
    }
}

/// The scene's name for a procedure input: the longest prefix in `table` replaced (`forces[2]`
/// with ("forces", "forces") stays `forces[2]`; `resolutions[0].along` with
/// ("resolutions", "resolve"), (".along", …) becomes `resolve[0].along_deg`).
pub fn scene_field(input: &str, table: &[(&str, &str)]) -> String {
    let mut out = input.to_string();
    for (from, to) in table {
        if let Some(rest) = out.strip_prefix(from) {
            out = format!("{to}{rest}");
        } else if let Some(k) = out.find(from) {
            out = format!("{}{to}{}", &out[..k], &out[k + from.len()..]);
        }
    }
    out
}

/// Where a scene comes from and what it is read for: the limits a scene read for its checks
/// alone (`check`, `forces`: a board in [`Mode::Checks`](crate::protocol::Mode::Checks)) are
/// wider than those of a figure, which must fit a sheet and a protocol of some 1 KB per step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReadContext<'a> {
    /// The file name (or other origin) that errors name.
    pub origin: &'a str,
    /// The scene is read for its checks alone, not for a figure.
    pub checks_only: bool,
    /// The memory free for the work (bytes), which a scene read for its checks may take at
    /// most half of; `None`: not known, not limited.
    pub free_memory: Option<u64>,
}

impl<'a> ReadContext<'a> {
    /// A scene read for its figure (or walk-through, protocol, export).
    pub const fn figure(origin: &'a str) -> ReadContext<'a> {
        ReadContext {
            origin,
            checks_only: false,
            free_memory: None,
        }
    }

    /// A scene read for its checks alone, with the memory the machine has free (the command
    /// line passes [`available_memory`](crate::io::available_memory)).
    pub const fn checks(origin: &'a str, free_memory: Option<u64>) -> ReadContext<'a> {
        ReadContext {
            origin,
            checks_only: true,
            free_memory,
        }
    }
}

/// Two quantities drawn at one scale ([`Procedure::spread`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// The larger over the smaller.
    pub ratio: f64,
    /// What the two are, for the refusal ("the return speed c₂ and the working speed c₁").
    pub between: &'static str,
    /// The input field that sets the ratio.
    pub field: &'static str,
}

/// The largest figure a scene may draw (mm on the sheet): ten metres of paper, some eight A0
/// sheets side by side. A larger one comes from a scale typed wrong (1 : 1e-12).
pub const MAX_SHEET_MM: f64 = 10_000.0;

/// The smallest figure a scene may draw (mm across): below it a scale such as 1 : 1e308
/// shrinks the figure to a point, its coordinates underflow and its checks turn NaN.
pub const MIN_SHEET_MM: f64 = 1.0;

/// Parses a scene of one procedure, keeping field path, line and column, refusing trailing
/// data after the JSON, reads it into its problem, and checks that its figure fits a sheet.
pub fn parse_scene<P: Procedure>(
    text: &str,
    ctx: &ReadContext,
) -> Result<(P, P::Problem), SceneError> {
    let origin = ctx.origin;
    // Most scenes parse: read without tracking the path (a third of the time of a large
    // scene), and again with it only to say where one does not.
    let scene: P = match serde_json::from_str(text) {
        Ok(scene) => scene,
        Err(_) => {
            let de = &mut serde_json::Deserializer::from_str(text);
            let scene: P =
                serde_path_to_error::deserialize(&mut *de).map_err(|e| json_error(e, origin))?;
            de.end().map_err(|e| syntax_error(e, origin))?;
            scene
        }
    };
    let problem = scene.problem(ctx)?;
    if let Some(e) = too_spread::<P>(&problem, origin) {
        return Err(e);
    }
    let extent = P::sheet_extent(&problem);
    let small = too_small_part::<P>(&problem, extent, origin);
    // A part too small against a figure its own scale sets cannot be mended by that scale:
    // say so before advising a value that would be refused in turn.
    if !small.as_ref().is_some_and(|(_, hopeless)| *hopeless) {
        if let Some(e) = wrong_size(extent, origin) {
            return Err(e);
        }
    }
    if let Some((e, _)) = small {
        return Err(e);
    }
    Ok((scene, problem))
}

/// The refusal of a figure whose two parts at one scale are too unequal for any scale.
fn too_spread<P: Procedure>(problem: &P::Problem, origin: &str) -> Option<SceneError> {
    let limit = 1.0 / crate::kernel::tolerance::MIN_PART_REL;
    let s = P::spread(problem).filter(|s| s.ratio.is_nan() || s.ratio > limit)?;
    Some(SceneError::Invalid {
        origin: origin.to_string(),
        field: s.field.to_string(),
        message: format!(
            "with this value {} differ {}-fold, more than the {} one scale can draw on a \
             sheet without the smaller drowning in its rounding: no scale draws both; change \
             this value",
            s.between,
            crate::fmt::sci(s.ratio),
            crate::fmt::sci(limit)
        ),
    })
}

/// The refusal of a figure of `mm` across, set by the scale `field`, too large or too small
/// for a sheet.
pub(super) fn wrong_size((mm, field): (f64, &str), origin: &str) -> Option<SceneError> {
    if field.is_empty() {
        return None;
    }
    let fits = mm.partial_cmp(&MAX_SHEET_MM).is_some_and(|o| o.is_le());
    let large_enough = mm.partial_cmp(&MIN_SHEET_MM).is_some_and(|o| o.is_ge());
    let message = if !fits {
        format!(
            "with this value the figure would be {} m across on the sheet, more than the {} m \
             a figure may take: change it (a scale of 1 : n takes a larger n)",
            if mm < 1e9 {
                crate::fmt::num(mm / 1000.0, 3)
            } else {
                crate::fmt::sci(mm / 1000.0)
            },
            crate::fmt::num(MAX_SHEET_MM / 1000.0, 3)
        )
    } else if !large_enough {
        format!(
            "with this value the figure would be {} mm across on the sheet, less than the \
             {} mm a figure must take: change it (a scale of 1 : n takes a smaller n)",
            crate::fmt::sci(mm),
            crate::fmt::num(MIN_SHEET_MM, 3)
        )
    } else {
        return None;
    };
    Some(SceneError::Invalid {
        origin: origin.to_string(),
        field: field.to_string(),
        message,
    })
}

/// The refusal of a scene whose smallest part (a diagram at a scale) would be drawn below
/// [`MIN_PART_REL`](crate::kernel::tolerance::MIN_PART_REL) of its figure of `mm` across,
/// and whether no value of its scale can mend it: when that scale also sets the figure's
/// extent, the part and the figure grow together.
fn too_small_part<P: Procedure>(
    problem: &P::Problem,
    (mm, extent_field): (f64, &str),
    origin: &str,
) -> Option<(SceneError, bool)> {
    let min = crate::kernel::tolerance::MIN_PART_REL * mm;
    let (part, field) = P::smallest_part(problem).filter(|(p, _)| p.is_nan() || *p < min)?;
    let hopeless = field == extent_field;
    let advice = if hopeless {
        format!(
            "no scale draws it: the figure's largest part at this scale is {} times it; make \
             the quantities it compares less unequal",
            crate::fmt::sci(mm / part),
        )
    } else {
        format!(
            "choose a scale that draws it at least {} mm long",
            crate::fmt::sci(min)
        )
    };
    let e = SceneError::Invalid {
        origin: origin.to_string(),
        field: field.to_string(),
        message: format!(
            "with this value its diagram would be {} mm on a figure {} mm across, less than \
             {} of it: its digits would drown in the sheet's rounding; {advice}",
            crate::fmt::sci(part),
            crate::fmt::num(mm, 1),
            crate::fmt::sci(crate::kernel::tolerance::MIN_PART_REL),
        ),
    };
    Some((e, hopeless))
}

pub(super) fn json_error(
    e: serde_path_to_error::Error<serde_json::Error>,
    origin: &str,
) -> SceneError {
    let field = e.path().to_string();
    let inner = e.into_inner();
    SceneError::Json {
        origin: origin.to_string(),
        line: inner.line(),
        column: inner.column(),
        field: if field == "." {
            String::new()
        } else {
            crate::fmt::clip(&field, 120)
        },
        message: quoted_clipped(&strip_position(&inner.to_string())),
    }
}

/// serde's message with each text it quotes (`…`, a scene's key or value) clipped to 60
/// characters, so that a long key leaves room for the reason after it ("expected one of …"),
/// then the whole to 600.
fn quoted_clipped(msg: &str) -> String {
    let mut out = String::with_capacity(msg.len().min(700));
    for (k, part) in msg.split('`').enumerate() {
        if k > 0 {
            out.push('`');
        }
        // The odd parts stand between backticks.
        out.push_str(&if k % 2 == 1 {
            crate::fmt::clip(part, 60)
        } else {
            part.to_string()
        });
    }
    crate::fmt::clip(&out, 600)
}

pub(super) fn syntax_error(e: serde_json::Error, origin: &str) -> SceneError {
    SceneError::Json {
        origin: origin.to_string(),
        line: e.line(),
        column: e.column(),
        field: String::new(),
        message: quoted_clipped(&strip_position(&e.to_string())),
    }
}

/// serde_json appends " at line L column C" to its messages; the error reports those apart.
fn strip_position(msg: &str) -> String {
    match msg.rfind(" at line ") {
        Some(k) => msg[..k].to_string(),
        None => msg.to_string(),
    }
}
