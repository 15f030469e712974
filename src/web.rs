//! The engine as the browser page calls it: a scene's JSON in, one JSON answer out, with
//! everything the page shows (the figure with its step layers, the walk-through's step list,
//! the checks with their bounds, the handles to drag, the sliders) or the one-line error of a
//! refused scene.
//!
//! The same function runs natively (`graphostatik site` writes each page's first answer
//! into it) and as WebAssembly in the page (`wasm/`, a plain C ABI over [`replay`]): it
//! reads no file, starts no thread and asks no clock. A scene is read under the limits of a
//! figure ([`AnyScene::from_json`]), so a dragged input the command line would refuse as too
//! costly is refused here with the same line.

use crate::protocol::{Board, BoardConfig, FigureMeta, ObjId};
use crate::render::layout::parts_within;
use crate::render::{
    figure_held, list_lines, page_count, page_details, page_ranges, step_names, walkthrough_item,
    walkthrough_list, Grouping, Layout,
};
use crate::scene::{handles, AnyScene, Handle, Preview, MAX_SHEET_MM};
use serde::Serialize;
use std::cell::OnceCell;
use std::ops::Range;

mod patch;
pub use patch::{figure_patch, figure_patch_read, FigureLines, FigurePatch};

/// The answer to the page: a construction, or why there is none.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Answer {
    /// The scene was read and constructed.
    Built(Box<Built>),
    /// It was refused: `{"ok": false, "error": "…"}`.
    Refused {
        /// Always false.
        ok: bool,
        /// One line naming the field, as the command line gives it.
        error: String,
    },
}

/// A construction as the page needs it.
#[derive(Debug, Clone, Serialize)]
pub struct Built {
    /// Always true.
    pub ok: bool,
    /// The figure's title and book reference.
    pub title: String,
    /// The book reference under the title.
    pub source: String,
    /// The figure (SVG, one `<g data-step="N">` layer per step).
    pub svg: String,
    /// The walk-through's step list: one `<li>` item per page, its lines alone
    /// ([`StepList::lines`](crate::render::StepList)); in an answer for a drag, only page
    /// [`Built::page`]'s item, its details included.
    pub items: Vec<String>,
    /// What each page shows beside the figure ([`StepList::details`](crate::render::StepList)),
    /// in the order of `items`; none in an answer for a drag or for [`Ask::Lines`].
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub details: Vec<String>,
    /// The page whose item alone `items` holds, in an answer for a drag ([`replay_page`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub page: Option<usize>,
    /// How many steps the construction has.
    pub step_count: usize,
    /// How many pages its walk-through has: one a step, but one for the steps of a part not
    /// drawn (the crane bridge's 5,433 steps on 2,080 pages). A drag's answer carries one
    /// page's item; where this number changed, the page's list of steps is out of date.
    pub page_count: usize,
    /// Every step: number, name, caption, situation, German term, book; none in an answer
    /// for a drag or for [`Ask::Lines`], whose list's lines name every step already (the
    /// crane bridge's 5,433 were 1.6 MB of its 2.4 MB answer when the pointer rests).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub steps: Vec<StepLine>,
    /// Every check of every step, with its bound.
    pub checks: Vec<CheckLine>,
    /// How many checks failed.
    pub failed: usize,
    /// The given points the student can drag.
    pub handles: Vec<PlacedHandle>,
    /// The numbers the scene's `preview.sliders` move, with their values now.
    pub sliders: Vec<SliderLine>,
}

/// One step of the protocol.
#[derive(Debug, Clone, Serialize)]
pub struct StepLine {
    /// Its number.
    pub id: u32,
    /// What it draws ("pole ray").
    pub caption: String,
    /// Its name in the walk-through: the caption with the objects it draws, and which of
    /// several alike it is ([`crate::render::step_names`]).
    pub name: String,
    /// The situation (load case, crank angle), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub context: Option<String>,
    /// The German term.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub term_de: Option<String>,
    /// The book reference.
    pub book: String,
}

/// One check: constructed value against the closed form, with its bound and tolerance.
#[derive(Debug, Clone, Serialize)]
pub struct CheckLine {
    /// The step that made it.
    pub step: u32,
    /// What is checked.
    pub quantity: String,
    /// The object checked, where the quantity does not name it ("member 5").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub object: Option<String>,
    /// Its unit.
    pub unit: String,
    /// The value read off the construction.
    pub constructed: f64,
    /// The closed form's value.
    pub closed_form: f64,
    /// Their difference.
    pub error: f64,
    /// The propagated bound of the construction's error.
    pub bound: f64,
    /// What the check allows.
    pub tolerance: f64,
    /// Whether it passed.
    pub passed: bool,
}

/// A handle where the figure draws its point, in the figure's SVG user units (those of its
/// root, whose view box starts at the sheet's top left).
#[derive(Debug, Clone, Serialize)]
pub struct PlacedHandle {
    /// The handle.
    #[serde(flatten)]
    pub handle: Handle,
    /// Where its point stands on the sheet (user units).
    pub at: [f64; 2],
    /// Where an angle's centre stands on the sheet (user units).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub center: Option<[f64; 2]>,
}

/// A slider of `preview.sliders`, its field as a JSON pointer and its value now.
#[derive(Debug, Clone, Serialize)]
pub struct SliderLine {
    /// The JSON pointer of the number (`/forces/1/angle_deg`).
    pub field: String,
    /// The name on the page.
    pub label: String,
    /// Lowest value.
    pub min: f64,
    /// Highest value.
    pub max: f64,
    /// Step between values.
    pub step: f64,
    /// The value in the scene now.
    pub value: f64,
}

/// Reads `scene` (JSON text; `origin` names it in errors), constructs it for a figure and
/// answers as [`Answer`]'s JSON. Never panics on any input text.
///
/// ```
/// let scene = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"),
///     "/scenes/lh_aufgabe4_shed_roof.json")).unwrap();
/// let a: serde_json::Value = serde_json::from_str(
///     &graphostatik::web::replay(&scene, "shed_roof.json")).unwrap();
/// assert_eq!(a["ok"], true);
/// assert_eq!(a["failed"], 0);
/// // Each joint can be dragged: LH B.4, Aufgabe 4 draws the truss once per load case.
/// assert!(a["handles"].as_array().unwrap().iter().any(|h| h["name"] == "joint III"));
/// let refused = graphostatik::web::replay("{ \"title\": 3 }", "x.json");
/// assert!(refused.starts_with("{\"ok\":false,\"error\":\"x.json"));
/// ```
pub fn replay(scene: &str, origin: &str) -> String {
    replay_page(scene, origin, None)
}

/// [`replay`] for a drag: with `page`, the answer carries the step list's item of that page
/// alone and no list of steps (what a page needs while the pointer moves; the full answer
/// when it rests).
pub fn replay_page(scene: &str, origin: &str, page: Option<usize>) -> String {
    let answer = match build_page(scene, origin, page) {
        Ok(b) => Answer::Built(Box::new(b)),
        Err(error) => Answer::Refused { ok: false, error },
    };
    answer_json(&answer, origin)
}

/// The answer as JSON; a failure to write it, as a refusal naming `origin`.
fn answer_json(answer: &Answer, origin: &str) -> String {
    serde_json::to_string(answer).unwrap_or_else(|e| {
        serde_json::json!({ "ok": false, "error": format!("{origin}: {e}") }).to_string()
    })
}

/// [`replay_page`] with the figure apart: the answer as JSON with an empty `svg`, and the
/// figure's SVG (empty where the scene is refused). The browser's engine answers so: the
/// figure is the bulk of the answer (the Otto engine's 0.69 MB), and inside JSON each of its
/// quotes is escaped on the way out and unescaped on the way in.
///
/// ```
/// let scene = std::fs::read_to_string("scenes/lh_abb22_funicular.json").unwrap();
/// let (json, svg) = graphostatik::web::replay_apart(&scene, "abb22.json", Some(0));
/// let a: serde_json::Value = serde_json::from_str(&json).unwrap();
/// assert_eq!((a["ok"].as_bool(), a["svg"].as_str()), (Some(true), Some("")));
/// assert!(svg.starts_with("<svg "));
/// ```
pub fn replay_apart(scene: &str, origin: &str, page: Option<usize>) -> (String, String) {
    let ask = page.map_or(Ask::All, Ask::Page);
    let (json, svg, _) = replay_kept(scene, origin, ask);
    (json, svg)
}

/// What an answer carries of the walk-through besides the figure, checks and handles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ask {
    /// The step list's lines, every page's details and every step: what a page is written
    /// with ([`build`]).
    All,
    /// The lines, but no page's details and no list of steps ([`Built::steps`]): the page asks
    /// the construction kept ([`Kept::details`]) for those of a page as it shows it. The
    /// crane bridge's details are 1.4 MB of its 4.8 MB answer, and the student sees one page
    /// of 2,080 at a time.
    Lines,
    /// The item of page `k` alone, its details included, and no list of steps: the answer to
    /// a drag while the pointer moves.
    Page(usize),
}

/// The construction of an answer, kept to answer for a page's details
/// ([`Ask::Lines`]) without constructing it again, and for the same scene asked again
/// ([`replay_into`]).
pub struct Kept {
    board: Board,
    /// The scene's text and name it was built from.
    text: String,
    origin: String,
    /// Its answer without the walk-through (no items, details or steps) and the figure.
    drawn: Built,
    /// Its figure's title block, and the layout its figure was drawn with: that of the
    /// figure before it during a drag ([`Layout`]).
    meta: FigureMeta,
    layout: Layout,
    names: OnceCell<Vec<String>>,
    pages: OnceCell<Vec<Range<usize>>>,
}

impl Kept {
    /// The answer to `ask` for the scene this was built from, the figure left out (its
    /// `svg` empty), without constructing or drawing it again: the same answer as
    /// [`build_asked`] gives. The steps are named once, for the first list asked for.
    pub fn answer(&self, ask: Ask) -> Built {
        let mut b = self.drawn.clone();
        list_into(&mut b, &self.board, ask, &self.names);
        b
    }

    /// Whether this is the construction of the scene `text` named `origin`.
    pub fn is_of(&self, text: &str, origin: &str) -> bool {
        self.text == text && self.origin == origin
    }

    /// Whether its figure was laid out afresh, as `render` draws it (not with the layout of
    /// a drag's figure before it: [`Layout`]).
    pub fn is_laid_out_afresh(&self) -> bool {
        self.layout.is_fresh()
    }

    /// Draws the figure anew, laid out afresh (the construction is not made again): the
    /// figure of the scene as `render` draws it, for the page once the pointer rests.
    fn redraw(&mut self) -> String {
        let handles = self
            .drawn
            .handles
            .iter()
            .map(|h| h.handle.clone())
            .collect();
        let sliders = std::mem::take(&mut self.drawn.sliders);
        let (mut b, layout) = drawn(&self.meta, &self.board, handles, sliders, None);
        let svg = std::mem::take(&mut b.svg);
        self.drawn = b;
        self.layout = layout;
        svg
    }

    /// What page `k` shows beside the figure (as [`Built::details`] holds it for [`Ask::All`]);
    /// `None` past the last page. The steps are named and the pages found once, on the first
    /// call: the print view asks for every page (the crane bridge's 2,080).
    pub fn details(&self, k: usize) -> Option<String> {
        let names = self.names.get_or_init(|| step_names(&self.board));
        let pages = (self.pages).get_or_init(|| page_ranges(&self.board, Grouping::Step));
        Some(page_details(&self.board, pages.get(k)?.clone(), names))
    }
}

/// [`replay_apart`] for what `ask` says, with the construction kept for [`Kept::details`]
/// (none where the scene is refused): the browser's engine answers so.
///
/// ```
/// use graphostatik::web::{replay_kept, Ask};
/// let scene = std::fs::read_to_string("scenes/lh_abb22_funicular.json").unwrap();
/// let (json, _, kept) = replay_kept(&scene, "abb22.json", Ask::Lines);
/// let a: serde_json::Value = serde_json::from_str(&json).unwrap();
/// // LH Abb. 22: the list's lines, and each page's details from the construction kept.
/// assert!(a.get("details").is_none());
/// let pages = a["page_count"].as_u64().unwrap() as usize;
/// let kept = kept.unwrap();
/// assert!(kept.details(0).unwrap().contains("wt-detail"));
/// assert!(kept.details(pages).is_none());
/// ```
pub fn replay_kept(scene: &str, origin: &str, ask: Ask) -> (String, String, Option<Kept>) {
    replay_held(scene, origin, ask, None)
}

/// [`replay_kept`], the figure drawn with the layout `held` where it still holds ([`Layout`]).
fn replay_held(
    scene: &str,
    origin: &str,
    ask: Ask,
    held: Option<&Layout>,
) -> (String, String, Option<Kept>) {
    let (answer, svg, kept) = match build_held(scene, origin, ask, held) {
        Ok((mut b, kept)) => {
            let svg = std::mem::take(&mut b.svg);
            (Answer::Built(Box::new(b)), svg, Some(kept))
        }
        Err(error) => (Answer::Refused { ok: false, error }, String::new(), None),
    };
    (answer_json(&answer, origin), svg, kept)
}

/// [`replay_kept`] with the construction kept in `kept`: where it is of this scene (the
/// same text and name) the answer is made from it, and the figure is `None` (the one drawn
/// last); else the scene is built, its figure returned and its construction kept (a refused
/// scene keeps the one before, whose figure the page still shows). A page replays the
/// scene of its last drag once more when the pointer is released, for the step list: the
/// crane bridge of LH Aufgabe 5 then constructs nothing again.
///
/// A drag's figure ([`Ask::Page`]) is drawn with the layout of the figure kept while that
/// layout holds ([`Layout`]): the parts stand still under the pointer. Asked for anything
/// else, a figure drawn so is drawn again laid out afresh (the construction kept): the
/// figure once the pointer rests is the one `render` draws of the scene.
///
/// ```
/// use graphostatik::web::{replay_into, replay_kept, Ask};
/// let scene = std::fs::read_to_string("scenes/lh_abb22_funicular.json").unwrap();
/// let mut kept = None;
/// let (drag, svg) = replay_into(&mut kept, &scene, "abb22.json", Ask::Page(2));
/// assert!(svg.is_some_and(|s| s.starts_with("<svg ")));
/// // LH Abb. 22, the pointer released: the answer of the construction kept.
/// let (rest, svg) = replay_into(&mut kept, &scene, "abb22.json", Ask::Lines);
/// assert_eq!(svg, None);
/// assert_eq!(rest, replay_kept(&scene, "abb22.json", Ask::Lines).0);
/// assert_ne!(rest, drag);
/// ```
pub fn replay_into(
    kept: &mut Option<Kept>,
    scene: &str,
    origin: &str,
    ask: Ask,
) -> (String, Option<String>) {
    let drag = matches!(ask, Ask::Page(_));
    if let Some(k) = kept.as_mut().filter(|k| k.is_of(scene, origin)) {
        // The pointer rests on a figure drawn with a drag's layout: laid out afresh.
        let svg = (!drag && !k.is_laid_out_afresh()).then(|| k.redraw());
        let answer = Answer::Built(Box::new(k.answer(ask)));
        return (answer_json(&answer, origin), svg);
    }
    // A drag keeps the layout of the figure before it while that holds.
    let held = kept.as_ref().filter(|_| drag).map(|k| &k.layout);
    let (json, svg, fresh) = replay_held(scene, origin, ask, held);
    if fresh.is_some() {
        *kept = fresh;
    }
    (json, Some(svg))
}

/// The construction of `text` with everything the page shows.
pub fn build(text: &str, origin: &str) -> Result<Built, String> {
    build_page(text, origin, None)
}

/// [`build`], for a drag where `page` is given ([`replay_page`]).
pub fn build_page(text: &str, origin: &str, page: Option<usize>) -> Result<Built, String> {
    build_asked(text, origin, page.map_or(Ask::All, Ask::Page)).map(|(b, _)| b)
}

/// The construction of `text` with what `ask` says, and the construction kept.
pub fn build_asked(text: &str, origin: &str, ask: Ask) -> Result<(Built, Kept), String> {
    build_held(text, origin, ask, None)
}

/// [`build_asked`], the figure drawn with the layout `held` where it still holds.
fn build_held(
    text: &str,
    origin: &str,
    ask: Ask,
    held: Option<&Layout>,
) -> Result<(Built, Kept), String> {
    let scene = AnyScene::from_json(text, origin).map_err(|e| e.to_string())?;
    let sliders = sliders(scene.preview(), text, origin)?;
    let p = scene.problem();
    let board = (p.construct(BoardConfig::DRAWING))
        .and_then(|b| parts_within(&b, MAX_SHEET_MM).map(|()| b))
        .map_err(|e| match p.error_field(&e) {
            Some(f) => format!("{origin}: {f}: {e}"),
            None => format!("{origin}: {e}"),
        })?;
    let meta = p.figure_meta();
    let (mut built, layout) = drawn(&meta, &board, handles(&scene, &board), sliders, held);
    let svg = std::mem::take(&mut built.svg);
    let kept_part = built.clone();
    built.svg = svg;
    let names = OnceCell::new();
    list_into(&mut built, &board, ask, &names);
    Ok((
        built,
        Kept {
            board,
            text: text.to_string(),
            origin: origin.to_string(),
            drawn: kept_part,
            meta,
            layout,
            names,
            pages: OnceCell::new(),
        },
    ))
}

/// The answer of a constructed board but for its walk-through ([`list_into`]), its figure
/// drawn with the layout `held` where it still holds, and the layout it was drawn with.
fn drawn(
    meta: &FigureMeta,
    board: &Board,
    handles: Vec<Handle>,
    sliders: Vec<SliderLine>,
    held: Option<&Layout>,
) -> (Built, Layout) {
    let mut ids: Vec<ObjId> = handles.iter().map(|h| h.object).collect();
    ids.extend(handles.iter().filter_map(Handle::center));
    let (svg, at, layout) = figure_held(meta, board, &ids, held);
    let n = handles.len();
    let mut centers = at[n..].iter();
    let placed = (handles.into_iter().zip(&at[..n]))
        .filter_map(|(h, at)| {
            let center = match h.center() {
                Some(_) => Some((*centers.next()?)?),
                None => None,
            };
            Some(PlacedHandle {
                handle: h,
                at: (*at)?,
                center,
            })
        })
        .collect();
    let checks = check_lines(board);
    let built = Built {
        ok: true,
        title: meta.title.to_string(),
        source: meta.source.to_string(),
        svg,
        items: Vec::new(),
        details: Vec::new(),
        page: None,
        step_count: board.steps().len(),
        page_count: 0,
        steps: Vec::new(),
        failed: checks.iter().filter(|c| !c.passed).count(),
        checks,
        handles: placed,
        sliders,
    };
    (built, layout)
}

/// Every check of `board` with its step, as the page lists it.
fn check_lines(board: &Board) -> Vec<CheckLine> {
    (board.steps().iter())
        .flat_map(|s| s.checks.iter().map(move |c| (s.id.0, c)))
        .map(|(step, c)| CheckLine {
            step,
            quantity: c.quantity.to_string(),
            object: c.object.as_deref().map(str::to_string),
            unit: c.unit.to_string(),
            constructed: c.constructed,
            closed_form: c.closed_form,
            error: c.error,
            bound: c.bound,
            tolerance: c.tolerance,
            passed: c.passed,
        })
        .collect()
}

/// The walk-through of `board` as `ask` says put into `b`: the list's items, the pages'
/// details and every step (for [`Ask::All`]), or the item of the drag's page, and the
/// number of pages. The steps are named once, into `names`, where all are named.
fn list_into(b: &mut Built, board: &Board, ask: Ask, names: &OnceCell<Vec<String>>) {
    match ask {
        Ask::Page(k) => {
            let k = k.min(board.steps().len().saturating_sub(1));
            b.items = walkthrough_item(board, Grouping::Step, k)
                .into_iter()
                .collect();
            b.page = Some(k);
            b.page_count = page_count(board, Grouping::Step);
        }
        Ask::Lines => {
            let names = names.get_or_init(|| step_names(board));
            b.items = list_lines(board, Grouping::Step, names);
            b.page_count = b.items.len();
        }
        Ask::All => {
            let list = walkthrough_list(board, Grouping::Step);
            b.steps = step_lines(board, &list.names);
            (b.items, b.details) = (list.lines, list.details);
            b.page_count = b.items.len();
            let _ = names.set(list.names);
        }
    }
}

/// Every step of `board` as the page lists it, with its name of `names` ([`step_names`]).
fn step_lines(board: &Board, names: &[String]) -> Vec<StepLine> {
    (board.steps().iter().zip(names))
        .map(|(s, name)| StepLine {
            id: s.id.0,
            caption: s.caption.to_string(),
            name: name.clone(),
            context: s.context.as_deref().map(str::to_string),
            term_de: s.term_de.as_deref().map(str::to_string),
            book: s.book.to_string(),
        })
        .collect()
}

/// The scene's `preview.sliders` (read with the scene) with their values now; a slider
/// that names no number of the scene is refused naming it. The text is read as a JSON tree
/// only where there are sliders to look up: a drag's replay reads its scene once.
fn sliders(preview: Option<&Preview>, text: &str, origin: &str) -> Result<Vec<SliderLine>, String> {
    let Some(preview) = preview.filter(|p| !p.sliders.is_empty()) else {
        return Ok(Vec::new());
    };
    let value: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("{origin}: {e}"))?;
    let mut out = Vec::new();
    for (i, s) in preview.sliders.iter().enumerate() {
        let field = format!("{origin}: preview.sliders[{i}]");
        if let Some(why) = s.problem() {
            return Err(format!("{field}: {why}"));
        }
        let ptr = s.pointer().unwrap_or_default();
        let Some(v) = value.pointer(&ptr).and_then(serde_json::Value::as_f64) else {
            return Err(format!(
                "{field}.field: the scene has no number `{}`",
                s.field
            ));
        };
        out.push(SliderLine {
            label: s.label.clone().unwrap_or_else(|| s.field.clone()),
            field: ptr,
            min: s.min,
            max: s.max,
            step: s.step(),
            value: v,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{build_asked, Ask};

    /// The answer when the pointer rests lists the same lines as the page is
    /// written with, and the construction kept gives each page's details as that answer
    /// holds them: drawn steps, and the crane bridge's positions that are not drawn.
    #[test]
    fn the_details_kept_are_the_details_listed() {
        for scene in ["lh_aufgabe4_shed_roof", "lh_aufgabe5_crane_bridge"] {
            let path = format!("{}/scenes/{scene}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(path).unwrap();
            let (all, _) = build_asked(&text, "x.json", Ask::All).unwrap();
            let (lines, kept) = build_asked(&text, "x.json", Ask::Lines).unwrap();
            assert_eq!(lines.items, all.items, "{scene}");
            assert_eq!(lines.page_count, all.page_count, "{scene}");
            assert!(lines.steps.is_empty(), "{scene}");
            assert_eq!(all.steps.len(), all.step_count, "{scene}");
            assert!(lines.details.is_empty() && all.details.len() == all.items.len());
            for (k, d) in all.details.iter().enumerate() {
                assert_eq!(kept.details(k).as_ref(), Some(d), "{scene}, page {k}");
            }
            assert_eq!(kept.details(all.items.len()), None);
            // A drag's construction names its steps only when a page's details are asked for.
            let (drag, dragged) = build_asked(&text, "x.json", Ask::Page(3)).unwrap();
            assert_eq!(drag.step_count, all.step_count, "{scene}");
            assert_eq!(lines.step_count, all.step_count, "{scene}");
            assert_eq!(
                dragged.details(3).as_ref(),
                Some(&all.details[3]),
                "{scene}"
            );
        }
    }

    /// An answer made again from the construction kept is the answer of the scene built
    /// afresh, for every ask in turn; another text is built anew, and a refused one keeps
    /// the construction before it.
    #[test]
    fn an_answer_kept_is_the_answer_afresh() {
        use super::{replay_into, replay_kept};
        for scene in ["lh_aufgabe4_shed_roof", "lh_abb22_funicular"] {
            let path = format!("{}/scenes/{scene}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(path).unwrap();
            let mut kept = None;
            let asks = [Ask::Page(3), Ask::Lines, Ask::Page(0), Ask::All, Ask::Lines];
            for (i, ask) in asks.into_iter().enumerate() {
                let (json, svg) = replay_into(&mut kept, &text, "x.json", ask);
                let (fresh, fresh_svg, _) = replay_kept(&text, "x.json", ask);
                assert_eq!(json, fresh, "{scene}, {ask:?}");
                assert_eq!(svg, (i == 0).then_some(fresh_svg), "{scene}, {ask:?}");
            }
            // The same text under another name is built anew; so is another text.
            assert!(replay_into(&mut kept, &text, "y.json", Ask::Lines)
                .1
                .is_some());
            let other = format!("{text} ");
            assert!(replay_into(&mut kept, &other, "y.json", Ask::Lines)
                .1
                .is_some());
            let (refused, _) = replay_into(&mut kept, "{", "y.json", Ask::Lines);
            assert!(refused.starts_with("{\"ok\":false"), "{refused}");
            assert!(kept.as_ref().is_some_and(|k| k.is_of(&other, "y.json")));
            assert_eq!(replay_into(&mut kept, &other, "y.json", Ask::Lines).1, None);
        }
    }

    /// A drag draws its figures with the layout of the figure it started from: the parts
    /// stand where they stood (every layer's place as before), where a fresh layout moves
    /// them; the pointer at rest draws the figure as `render` does, byte for byte.
    #[test]
    fn a_drag_keeps_its_layout_and_the_figure_at_rest_is_laid_out_afresh() {
        use super::{replay_into, replay_kept};
        let path = format!(
            "{}/scenes/lh_aufgabe4_shed_roof.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(path).unwrap();
        let support = "{ \"name\": \"I\", \"at_m\": [0, 0] }";
        assert!(text.contains(support));
        let moved = |x: f64| {
            text.replace(
                support,
                &format!("{{ \"name\": \"I\", \"at_m\": [{x}, 0] }}"),
            )
        };
        // Where each step's layer is moved to (the part's place on the sheet).
        let places = |svg: &str| -> Vec<String> {
            (svg.lines())
                .filter(|l| l.starts_with("<g ") && l.contains("data-step"))
                .map(|l| l.split(" transform=").nth(1).unwrap_or("").to_string())
                .collect()
        };
        let mut kept = None;
        let start = replay_into(&mut kept, &text, "x.json", Ask::Lines)
            .1
            .unwrap();
        assert!(kept.as_ref().unwrap().is_laid_out_afresh());
        let mut afresh_moves = 0;
        for k in 1..=4 {
            let scene = moved(0.02 * f64::from(k));
            let svg = replay_into(&mut kept, &scene, "x.json", Ask::Page(0))
                .1
                .unwrap();
            assert!(!kept.as_ref().unwrap().is_laid_out_afresh(), "drag {k}");
            assert_eq!(places(&svg), places(&start), "drag {k}");
            let (_, fresh, _) = replay_kept(&scene, "x.json", Ask::Lines);
            afresh_moves += usize::from(places(&fresh) != places(&start));
        }
        assert!(
            afresh_moves > 0,
            "a fresh layout moves the parts too: the test tells nothing"
        );
        // The pointer released: the figure laid out afresh, as `render` draws it.
        let scene = moved(0.08);
        let (json, svg) = replay_into(&mut kept, &scene, "x.json", Ask::Lines);
        let (fresh_json, fresh_svg, _) = replay_kept(&scene, "x.json", Ask::Lines);
        assert_eq!(svg, Some(fresh_svg));
        assert_eq!(json, fresh_json);
        assert!(kept.as_ref().unwrap().is_laid_out_afresh());
        assert_eq!(replay_into(&mut kept, &scene, "x.json", Ask::Lines).1, None);
    }

    /// Every bundled scene gives the student something to move on its page (a handle, or a
    /// slider of `preview.sliders`), and a slider's first step either way is a scene the
    /// engine constructs: the page's latency bench moves exactly that.
    #[test]
    fn every_bundled_scene_has_something_to_move() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
        let mut paths: Vec<_> = (std::fs::read_dir(dir).unwrap().flatten())
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
        paths.sort();
        assert!(paths.len() >= 50, "{}", paths.len());
        for path in paths {
            let text = std::fs::read_to_string(&path).unwrap();
            let name = path.display().to_string();
            let (built, _) = build_asked(&text, &name, Ask::Page(0)).unwrap();
            assert!(
                !built.handles.is_empty() || !built.sliders.is_empty(),
                "{name}: nothing to drag or slide"
            );
            let Some(sl) = built.sliders.first().filter(|_| built.handles.is_empty()) else {
                continue;
            };
            let scene: serde_json::Value = serde_json::from_str(&text).unwrap();
            for v in [sl.value + sl.step, sl.value - sl.step] {
                assert!(sl.min <= v && v <= sl.max, "{name}: {v} outside the slider");
                let mut moved = scene.clone();
                let v = match v.fract() == 0.0 {
                    true => serde_json::json!(v as i64),
                    false => serde_json::json!(v),
                };
                *moved.pointer_mut(&sl.field).unwrap() = v.clone();
                let r = build_asked(&moved.to_string(), &name, Ask::Page(0));
                assert!(r.is_ok(), "{name}, {} = {v}: {:?}", sl.field, r.err());
            }
        }
    }

    /// A drag's answer names its page's steps as the full step list does, alike steps told
    /// apart the same way ("joint load P₀ (3 of 4)"): the page's name is found without naming
    /// every step.
    #[test]
    fn a_page_alone_is_named_as_in_the_list() {
        for scene in ["lh_aufgabe4_shed_roof", "kg_abb1043_crank_rocker"] {
            let path = format!("{}/scenes/{scene}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(path).unwrap();
            let all = super::build(&text, "x.json").unwrap();
            let ordinal = |i: &&String| {
                (i.split(" (").skip(1))
                    .any(|p| p.starts_with(|c: char| c.is_ascii_digit()) && p.contains(" of "))
            };
            let told_apart = all.items.iter().filter(ordinal).count();
            assert!(told_apart > 0, "{scene}: no steps alike");
            for k in (0..all.items.len()).step_by(7) {
                let one = super::build_page(&text, "x.json", Some(k)).unwrap();
                // The list's line is the item without its details, which come apart.
                let line = &all.items[k];
                let open = &line[..=line.find('>').unwrap()];
                let whole = format!("{open}{}</li>\n", all.details[k]);
                assert_eq!(one.items.len(), 1, "{scene}, page {k}");
                assert_eq!(one.items[0], whole, "{scene}, page {k}");
                assert!(!line.contains("wt-detail") && whole.contains("wt-detail"));
            }
        }
    }

    /// Every page's item asked for alone ([`crate::render::walkthrough_item`], what a drag
    /// asks) is the list's item: drawn steps told apart within their situation (the
    /// compound engine's rays), and the crane bridge's pages of positions not drawn.
    #[test]
    fn every_page_alone_is_its_item_of_the_list() {
        use crate::protocol::BoardConfig;
        use crate::render::{page_count, walkthrough_item, walkthrough_item_list, Grouping};
        let scenes = [
            ("lh_j_compound_engine", 1),
            ("kg_abb1043_crank_rocker", 1),
            ("lh_aufgabe5_crane_bridge", 29),
        ];
        for (scene, every) in scenes {
            let path = format!("{}/scenes/{scene}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(path).unwrap();
            let s = crate::scene::AnyScene::from_json(&text, "x.json").unwrap();
            let board = s.problem().construct(BoardConfig::DRAWING).unwrap();
            for grouping in [Grouping::Step, Grouping::Context] {
                let list = walkthrough_item_list(&board, grouping);
                assert_eq!(page_count(&board, grouping), list.len(), "{scene}");
                for k in (0..list.len()).step_by(every).chain([list.len() - 1]) {
                    let one = walkthrough_item(&board, grouping, k);
                    assert_eq!(
                        one.as_ref(),
                        Some(&list[k]),
                        "{scene}, {grouping:?}, page {k}"
                    );
                }
                assert_eq!(walkthrough_item(&board, grouping, list.len()), None);
            }
        }
    }
}
