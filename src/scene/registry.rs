//! The registry of every procedure, and the scene of any procedure ([`AnyScene`],
//! [`AnyProblem`]) that the command line works with. Adding a procedure is one line in
//! [`REGISTRY`].

use super::error::SceneError;
use super::procedure::{parse_scene, syntax_error, Procedure, ReadContext};
use super::sweep::Setting;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, Mode};
use std::any::Any;
use std::fmt::Debug;

/// A registered procedure: its name, its line of description, and the type-erased parser and
/// schema of its scene.
pub struct Entry {
    /// The `procedure` value.
    pub name: &'static str,
    /// What it constructs and where the books have it.
    pub about: &'static str,
    /// The outputs a scene of it can ask for.
    pub outputs: &'static [&'static str],
    parse: fn(&str, &ReadContext) -> Result<AnyScene, SceneError>,
    /// The Rust type of its scene (the schema's definition name).
    #[cfg(feature = "schema")]
    scene_type: fn() -> String,
    #[cfg(feature = "schema")]
    schema: fn(&mut schemars::SchemaGenerator) -> schemars::Schema,
}

impl Entry {
    /// The entry of procedure `P`.
    pub const fn of<P: Procedure>() -> Entry {
        Entry {
            name: P::NAME,
            about: P::ABOUT,
            outputs: P::OUTPUTS,
            parse: |text, ctx| {
                parse_scene::<P>(text, ctx).map(|(scene, problem)| AnyScene {
                    problem: AnyProblem {
                        book: super::procedure::SceneHeader::book(&scene).into(),
                        plate: super::procedure::SceneHeader::plate(&scene).into(),
                        paper: super::procedure::SceneHeader::paper(&scene),
                        inner: Box::new(ProblemOf::<P>(problem)),
                    },
                    scene: Box::new(scene),
                })
            },
            #[cfg(feature = "schema")]
            scene_type: || P::schema_name().into_owned(),
            #[cfg(feature = "schema")]
            schema: |g| g.subschema_for::<P>(),
        }
    }
}

impl Debug for Entry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Entry").field("name", &self.name).finish()
    }
}

/// Every procedure a scene can name, the default (`slider_crank`, for a scene without a
/// `procedure` field) first. Adding a procedure is one line here.
pub static REGISTRY: &[Entry] = &[
    Entry::of::<super::types::SliderCrankScene>(),
    Entry::of::<super::beam::BeamScene>(),
    Entry::of::<super::force_system::ForceSystemScene>(),
    Entry::of::<super::centroid::CentroidScene>(),
    Entry::of::<super::shaft::ShaftScene>(),
    Entry::of::<super::truss::TrussScene>(),
    Entry::of::<super::crank_dynamics::DynamicsScene>(),
    Entry::of::<super::scotch_yoke::YokeScene>(),
    Entry::of::<super::slotted_link::LinkScene>(),
    Entry::of::<super::offset_crank::OffsetScene>(),
    Entry::of::<super::four_bar::FourBarScene>(),
    Entry::of::<super::combustion::CombustionScene>(),
];

/// The registered procedure of this name.
pub fn entry(name: &str) -> Option<&'static Entry> {
    REGISTRY.iter().find(|e| e.name == name)
}

/// The names of every registered procedure, for messages: `slider_crank, beam, …`.
fn known_names() -> String {
    REGISTRY
        .iter()
        .map(|e| e.name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// A scene of a procedure, type-erased.
trait DynScene: Debug + Send + Sync {
    fn as_any(&self) -> &dyn Any;
    fn clone_box(&self) -> Box<dyn DynScene>;
    fn book(&self) -> &[super::BookValue];
    fn preview(&self) -> Option<&super::Preview>;
}

impl<P: Procedure> DynScene for P {
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn book(&self) -> &[super::BookValue] {
        super::procedure::SceneHeader::book(self)
    }
    fn preview(&self) -> Option<&super::Preview> {
        super::procedure::SceneHeader::preview(self)
    }
    fn clone_box(&self) -> Box<dyn DynScene> {
        Box::new(self.clone())
    }
}

/// A problem of a procedure, type-erased.
trait DynProblem: Debug + Send + Sync {
    fn name(&self) -> &'static str;
    fn error_field(&self, err: &ConstructionError) -> Option<String>;
    fn construct(&self, config: BoardConfig) -> Result<Board, ConstructionError>;
    fn figure_meta(&self) -> FigureMeta;
    fn sweeps(&self) -> Vec<Setting<'_>>;
    fn as_any(&self) -> &dyn Any;
    fn clone_box(&self) -> Box<dyn DynProblem>;
}

struct ProblemOf<P: Procedure>(P::Problem);

/// The most steps a figure may draw: every step is a layer of the SVG, its objects are
/// lettered and set out, and a browser replays them on every drag. The bundled figures draw
/// at most 5,427 (the crane bridge); 64 cylinders at 3,600 divisions ran out of memory.
pub const MAX_FIGURE_STEPS: usize = 50_000;

/// A drawing board's construction (the figure, and every other board that keeps the
/// drawing: a reference replay, a drafting run, the precision sweep), refused past
/// [`MAX_FIGURE_STEPS`] naming what sets its size. The board keeps at most that many steps
/// and counts on past them without keeping anything ([`Board::spilled`]): a figure too large
/// costs the limit's memory and a silent construction's time, and one within it is
/// constructed once. `check` draws nothing and takes more.
fn figure<P: Procedure>(
    problem: &P::Problem,
    config: BoardConfig,
) -> Result<Board, ConstructionError> {
    let most = config
        .keep_steps
        .map_or(MAX_FIGURE_STEPS as u32, |k| k.min(MAX_FIGURE_STEPS as u32));
    let (board, _) = P::construct(problem, config.keeping_at_most(most))?;
    if !board.spilled() {
        return Ok(board);
    }
    let steps = board.step_count();
    let what = match (config.reference, config.hand.is_some()) {
        (true, _) => "a reference replay keeps the drawing",
        (_, true) => "drafting draws the figure",
        _ => "",
    };
    let what = if what.is_empty() {
        String::new()
    } else {
        format!(" ({what})")
    };
    Err(ConstructionError::Unsupported {
        input: "figure".into(),
        reason: format!(
            "it would draw {steps} steps, more than the {MAX_FIGURE_STEPS} a figure may \
             hold{what}: ask for fewer {} (graphostatik check takes it: it draws nothing)",
            P::SIZED_BY
        ),
    })
}

impl<P: Procedure> Debug for ProblemOf<P> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.fmt(f)
    }
}

impl<P: Procedure> DynProblem for ProblemOf<P> {
    fn name(&self) -> &'static str {
        P::NAME
    }
    fn error_field(&self, err: &ConstructionError) -> Option<String> {
        P::error_field(&self.0, err)
    }
    fn construct(&self, config: BoardConfig) -> Result<Board, ConstructionError> {
        if config.mode == Mode::Drawing {
            return figure::<P>(&self.0, config);
        }
        P::construct(&self.0, config).map(|(b, _)| b)
    }
    fn figure_meta(&self) -> FigureMeta {
        P::figure_meta(&self.0)
    }
    fn sweeps(&self) -> Vec<Setting<'_>> {
        P::sweeps(&self.0)
    }
    fn as_any(&self) -> &dyn Any {
        &self.0
    }
    fn clone_box(&self) -> Box<dyn DynProblem> {
        Box::new(ProblemOf::<P>(self.0.clone()))
    }
}

/// A scene of any registered procedure, read into its problem.
///
/// ```
/// use graphostatik::scene::{AnyScene, TrussScene};
/// let e = AnyScene::from_json(r#"{"procedure": "bridge", "title": "?"}"#, "x.json").unwrap_err();
/// assert!(e.to_string().starts_with("x.json: procedure: unknown procedure `bridge`"));
/// assert!(e.to_string().contains("truss"));
/// ```
#[derive(Debug)]
pub struct AnyScene {
    scene: Box<dyn DynScene>,
    problem: AnyProblem,
}

impl Clone for AnyScene {
    fn clone(&self) -> Self {
        AnyScene {
            scene: self.scene.clone_box(),
            problem: self.problem.clone(),
        }
    }
}

impl AnyScene {
    /// Parses a scene of any procedure, by its `procedure` field (absent: `slider_crank`),
    /// and reads it into its problem under the limits of a figure. Malformed JSON is
    /// reported at its line and column, an unknown procedure with the list of known ones.
    pub fn from_json(text: &str, origin: &str) -> Result<AnyScene, SceneError> {
        AnyScene::read(text, &ReadContext::figure(origin))
    }

    /// [`AnyScene::from_json`] for what `ctx` says the scene is read for (its checks alone
    /// may take a larger scene than a figure).
    pub fn read(text: &str, ctx: &ReadContext) -> Result<AnyScene, SceneError> {
        // Most scenes are read in one typed pass, their procedure found by the bytes alone;
        // a scene that does not parse so is read again the long way, so that its error is
        // the one the scan finds first (a syntax error anywhere before any field). A scene
        // refused after it parsed is valid JSON, where the quick answer is the scan's: its
        // error stands.
        if let Some(found) = super::scan::quick(text) {
            if let Ok(e) = Self::entry_of(found, ctx.origin) {
                match (e.unwrap_or(&REGISTRY[0]).parse)(text, ctx) {
                    Err(SceneError::Json { .. }) => {}
                    read => return read,
                }
            }
        }
        let found = super::scan::scan(text).map_err(|e| syntax_error(e, ctx.origin))?;
        let e = Self::entry_of(found, ctx.origin)?.unwrap_or(&REGISTRY[0]);
        (e.parse)(text, ctx)
    }

    /// The registry's entry for a scene's `procedure` field (`None` where it has none).
    fn entry_of(
        found: super::scan::Scanned,
        origin: &str,
    ) -> Result<Option<&'static Entry>, SceneError> {
        match Self::procedure_of(found, origin)? {
            None => Ok(None),
            Some(n) => entry(&n).map(Some).ok_or_else(|| SceneError::Invalid {
                origin: origin.to_string(),
                field: "procedure".into(),
                message: format!(
                    "unknown procedure `{}`; known: {}",
                    crate::fmt::clip(&n, 60),
                    known_names()
                ),
            }),
        }
    }

    /// The `procedure` field of a scanned scene (a syntax error anywhere in the file was
    /// reported by the scan, at its own line and column, before any procedure's fields are
    /// looked at), refused where it is not a text or the scan found a text too long.
    fn procedure_of(
        found: super::scan::Scanned,
        origin: &str,
    ) -> Result<Option<String>, SceneError> {
        let invalid = |field: String, message: String| SceneError::Invalid {
            origin: origin.to_string(),
            field,
            message,
        };
        if !found.object {
            return Err(invalid(
                String::new(),
                "a scene is a JSON object ({ \"title\": …, … })".into(),
            ));
        }
        if let Some((field, message)) = found.too_long {
            return Err(invalid(field, message));
        }
        match found.procedure {
            None => Ok(None),
            Some(serde_json::Value::String(s)) => Ok(Some(s)),
            Some(other) => Err(invalid(
                "procedure".into(),
                format!(
                    "must be a string naming the procedure ({}), got {}",
                    known_names(),
                    crate::fmt::clip(&other.to_string(), 60)
                ),
            )),
        }
    }

    /// The numbers the book prints that the scene reproduces (its `book` field).
    pub fn book(&self) -> &[super::BookValue] {
        self.scene.book()
    }

    /// What the live page lets a student move (its `preview` field), if the scene says.
    pub fn preview(&self) -> Option<&super::Preview> {
        self.scene.preview()
    }

    /// Reads a scene file of any procedure ([`AnyScene::from_json`]).
    pub fn load(path: &std::path::Path) -> Result<AnyScene, SceneError> {
        Self::load_with(path, false, None)
    }

    /// Reads a scene file for its checks alone ([`ReadContext::checks`]), which may be
    /// larger than a figure's, with the memory free for the work.
    pub fn load_for_checks(
        path: &std::path::Path,
        free_memory: Option<u64>,
    ) -> Result<AnyScene, SceneError> {
        Self::load_with(path, true, free_memory)
    }

    /// A scene file read for a figure or for its checks alone ([`ReadContext`]).
    fn load_with(
        path: &std::path::Path,
        checks_only: bool,
        free_memory: Option<u64>,
    ) -> Result<AnyScene, SceneError> {
        let text =
            crate::io::read_text(path, crate::io::MAX_SCENE_BYTES).map_err(|e| SceneError::Io {
                path: path.display().to_string(),
                message: e.to_string(),
            })?;
        let origin = path.display().to_string();
        let ctx = ReadContext {
            origin: &origin,
            checks_only,
            free_memory,
        };
        AnyScene::read(&text, &ctx)
    }

    /// The procedure's name (`"truss"`).
    pub fn procedure(&self) -> &'static str {
        self.problem.procedure()
    }

    /// The scene as its own type, if it is one: `scene.get::<TrussScene>()`.
    pub fn get<P: Procedure>(&self) -> Option<&P> {
        self.scene.as_any().downcast_ref::<P>()
    }

    /// The problem the scene describes.
    pub fn problem(&self) -> &AnyProblem {
        &self.problem
    }

    /// The problem the scene describes, the scene itself dropped.
    pub fn into_problem(self) -> AnyProblem {
        self.problem
    }
}

/// A constructible problem of any registered procedure, with the numbers its book prints
/// (the scene's `book` field), which a figure sets beside the construction.
#[derive(Debug)]
pub struct AnyProblem {
    inner: Box<dyn DynProblem>,
    book: std::sync::Arc<[super::BookValue]>,
    plate: std::sync::Arc<[String]>,
    paper: Option<crate::protocol::Paper>,
}

impl Clone for AnyProblem {
    fn clone(&self) -> Self {
        AnyProblem {
            inner: self.inner.clone_box(),
            book: self.book.clone(),
            plate: self.plate.clone(),
            paper: self.paper,
        }
    }
}

impl AnyProblem {
    /// The procedure's name.
    pub fn procedure(&self) -> &'static str {
        self.inner.name()
    }

    /// The problem as its own type, if it is one: `problem.get::<TrussScene>()` gives the
    /// `TrussProblem`.
    pub fn get<P: Procedure>(&self) -> Option<&P::Problem> {
        self.inner.as_any().downcast_ref::<P::Problem>()
    }

    /// Constructs the problem on fresh boards set up by `config` (the results are in the
    /// protocol); a board that records ends with the table of the book's printed values
    /// beside the construction ([`super::book_table`]).
    pub fn construct(&self, config: BoardConfig) -> Result<Board, ConstructionError> {
        let mut board = self.inner.construct(config)?;
        if board.is_recording() && !self.book.is_empty() {
            super::book_table(&mut board, &self.book);
        }
        Ok(board)
    }

    /// Title, source and scale bars of the figure, and what the book's plate letters (the
    /// scene's `plate` field).
    pub fn figure_meta(&self) -> FigureMeta {
        FigureMeta {
            plate: self.plate.to_vec(),
            ..self.inner.figure_meta()
        }
    }

    /// The paper the scene asks its figure to be set on (its `paper` field), if it names one.
    pub fn paper(&self) -> Option<crate::protocol::Paper> {
        self.paper
    }

    /// The knobs of the procedure that trade time for accuracy
    /// ([`Procedure::sweeps`]), each setting ready to run.
    pub fn sweeps(&self) -> Vec<Setting<'_>> {
        self.inner.sweeps()
    }

    /// The scene field a construction error comes from, where the procedure can tell.
    pub fn error_field(&self, err: &ConstructionError) -> Option<String> {
        self.inner.error_field(err)
    }
}

#[cfg(feature = "schema")]
/// The JSON Schema of the scene format, pretty-printed: any of the registered procedures'
/// scenes, each with its `procedure` value as a constant.
pub fn schema_json() -> String {
    let mut g = schemars::SchemaGenerator::default();
    let branches: Vec<serde_json::Value> = REGISTRY
        .iter()
        .map(|e| {
            let mut s = serde_json::Value::from((e.schema)(&mut g));
            s["description"] = format!("{}: {}", e.name, e.about).into();
            s
        })
        .collect();
    let mut defs = g.take_definitions(true);
    for (k, e) in REGISTRY.iter().enumerate() {
        if let Some(def) = defs.get_mut(&(e.scene_type)()) {
            pin_procedure(def, e.name, k == 0);
        }
    }
    let root = serde_json::json!({
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "Scene",
        "description": format!(
            "A graphostatik scene. Its `procedure` field picks the book procedure: {} \
             (`slider_crank` when absent).",
            known_names()
        ),
        "anyOf": branches,
        "$defs": defs,
    });
    serde_json::to_string_pretty(&root).expect("a schema is plain JSON")
}

#[cfg(feature = "schema")]
/// Writes the procedure's name into its scene's schema as the constant its `procedure` field
/// must have (required, except for the default procedure).
fn pin_procedure(def: &mut serde_json::Value, name: &str, default: bool) {
    def["properties"]["procedure"] = serde_json::json!({
        "description": format!("`\"{name}\"`{}", if default { " (the default when absent)" } else { "" }),
        "const": name,
    });
    if !default {
        if let Some(req) = def.get_mut("required").and_then(|r| r.as_array_mut()) {
            req.insert(0, name_value("procedure"));
        } else {
            def["required"] = serde_json::json!(["procedure"]);
        }
    }
}

#[cfg(feature = "schema")]
fn name_value(s: &str) -> serde_json::Value {
    serde_json::Value::String(s.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_names_are_unique_and_parse_their_own_scenes_only() {
        let mut names: Vec<_> = REGISTRY.iter().map(|e| e.name).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), REGISTRY.len());
        assert_eq!(REGISTRY[0].name, "slider_crank");
    }

    #[test]
    fn syntax_errors_are_reported_where_they_are_whatever_the_procedure() {
        let text = "{\n  \"procedure\": \"beam\",\n  \"title\": \"t\",\n  \"beam\": {\"supports_m\": [0, 6],}\n}";
        let e = AnyScene::from_json(text, "b.json").unwrap_err().to_string();
        assert!(e.starts_with("b.json:4:"), "{e}");
        assert!(!e.contains("unknown field"), "{e}");
    }

    #[test]
    fn a_megabyte_name_is_refused_naming_its_field() {
        let long = "x".repeat(crate::scene::scan::MAX_TEXT_CHARS + 1);
        let text = format!(
            r#"{{"procedure": "truss", "title": "t", "load_cases": [{{"name": "{long}"}}]}}"#
        );
        let e = AnyScene::from_json(&text, "l.json")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("l.json: load_cases[0].name: a text of 401"),
            "{e}"
        );
        assert!(e.len() < 200, "the error quotes no megabyte: {e}");
        let e = AnyScene::from_json("[1, 2]", "a.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains("a scene is a JSON object"), "{e}");
    }

    #[test]
    fn trailing_data_is_refused() {
        let e = AnyScene::from_json("{\"title\": \"t\"} {}", "t.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains("trailing characters"), "{e}");
    }

    #[test]
    fn procedure_must_be_a_known_string() {
        let e = AnyScene::from_json("{\"procedure\": 3}", "p.json")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("p.json: procedure: must be a string"), "{e}");
        let e = AnyScene::from_json("{\"procedure\": \"crane\"}", "p.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains("known: slider_crank, beam"), "{e}");
    }

    #[test]
    #[cfg(feature = "schema")]
    fn schema_pins_each_procedure() {
        let s: serde_json::Value = serde_json::from_str(&schema_json()).unwrap();
        assert_eq!(s["anyOf"].as_array().unwrap().len(), REGISTRY.len());
        let beam = &s["$defs"]["BeamScene"];
        assert_eq!(beam["properties"]["procedure"]["const"], "beam");
        assert_eq!(beam["required"][0], "procedure");
    }
}
