//! The walk-through: one self-contained `index.html` that shows a construction one step at a
//! time, as GeoGebra's construction protocol does, with the step's caption, German term,
//! book reference and analytic checks beside the figure.
//!
//! The figure is inlined once, each step its own layer (`<g data-step="N">`); the page shows
//! the layers up to the current step and draws the current one in the highlight colour. It
//! works offline from the file system: no script, style or font from outside. Keys: → or
//! space next, ← back, Home and End, `z` zooms the view to the step's new objects, `k` plays
//! the steps at the speed chosen, `p` prints one step per panel (a handout). Each step is a
//! history entry (the browser's Back goes back a step); hovering a step in the list draws
//! its objects in blue; on a sheet larger than its pane the view follows the step.

use super::figure::figure;
use crate::protocol::FigureMeta;
use crate::protocol::{Board, Step};
use std::ops::Range;

/// A file of the walk-through: its name and contents.
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    /// File name (`index.html`).
    pub name: String,
    /// Contents.
    pub contents: String,
}

/// How the steps are paged.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Grouping {
    /// One construction step per page (the default).
    #[default]
    Step,
    /// Consecutive steps made in the same situation (one joint's polygon, one crank angle)
    /// share a page: for long constructions, where the author asks for it.
    Context,
}

/// What a walk-through page carries besides the construction.
#[derive(Debug, Clone, Default)]
pub struct WalkOptions {
    /// How the steps are paged.
    pub grouping: Grouping,
    /// Extra HTML put after the page's own script (the live preview's reload script); the
    /// caller escapes what it puts there.
    pub extra: String,
    /// HTML put at the top of the side panel (the live preview's sliders); the caller escapes
    /// what it puts there.
    pub controls: String,
    /// An error line shown above the figure (the live preview's last failed edit).
    pub error: Option<String>,
    /// Each page's details where the list given holds its lines alone
    /// ([`StepList`]): written into the page as JSON for its script to show.
    pub details: Option<Vec<String>>,
    /// Scripts put after the page's own and `extra`, each inline (the live preview's reload
    /// script): the page's policy names each by its hash.
    pub scripts: Vec<String>,
    /// Style rules put after the page's own (the site's live part).
    pub css: String,
    /// What the page may load beyond its inline scripts and style sheets, which its
    /// Content-Security-Policy names by their hashes ([`super::content_security_policy`]).
    pub allow: super::Allow,
}

/// Text shown literally in HTML: markup escaped (`<`, `>`, `&`, both quotes), characters XML
/// forbids (NUL, most control characters) replaced by U+FFFD.
pub fn html_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    crate::fmt::markup_text(&mut out, s);
    out
}

/// The steps of each page, in order. The steps of a part constructed and checked but not
/// drawn ([`Part::hidden`](crate::protocol::Part::hidden): a crane position whose plan the
/// book does not draw) are one page, whatever the grouping: there is nothing to see step by
/// step.
fn page_groups(board: &Board, grouping: Grouping) -> Vec<Vec<&Step>> {
    let steps = board.steps();
    (page_runs(steps, grouping))
        .map(|r| steps[r].iter().collect())
        .collect()
}

/// The pages as runs of `steps` ([`page_groups`]), found without keeping them: a drag asks
/// for one page and the count (a page per step and a `Vec` each was 1.4 M instructions of
/// a 1,679-step engine's replay).
fn page_runs(steps: &[Step], grouping: Grouping) -> impl Iterator<Item = Range<usize>> + '_ {
    let together = move |first: &Step, s: &Step| {
        let unseen = first.part.hidden && s.part.hidden && first.part.row == s.part.row;
        let situation =
            grouping == Grouping::Context && first.context.is_some() && first.context == s.context;
        unseen || situation
    };
    let mut start = 0;
    std::iter::from_fn(move || {
        let first = steps.get(start)?;
        let len = 1
            + (steps[start + 1..].iter())
                .take_while(|s| together(first, s))
                .count();
        start += len;
        Some(start - len..start)
    })
}

/// The walk-through of `board`: `index.html`, one step per page.
///
/// ```
/// use graphostatik::protocol::BoardConfig;
/// use graphostatik::scene::AnyScene;
/// let p = AnyScene::from_json(r#"{ "procedure": "force_system", "title": "Two forces",
///     "forces": [ { "at_m": [0, 0], "kg": 100, "angle_deg": 90 },
///                 { "at_m": [1, 0], "kg": 50, "angle_deg": 90 } ] }"#, "two.json")
///     .unwrap()
///     .into_problem();
/// let board = p.construct(BoardConfig::DRAWING).unwrap();
/// let pages = graphostatik::render::walkthrough(&p.figure_meta(), &board);
/// assert_eq!(pages.len(), 1);
/// assert!(pages[0].contents.contains("data-step=\"001\""));
/// ```
pub fn walkthrough(meta: &FigureMeta, board: &Board) -> Vec<Page> {
    vec![Page {
        name: "index.html".into(),
        contents: walkthrough_html(meta, board, &WalkOptions::default()),
    }]
}

/// The walk-through page of `board` with its options.
pub fn walkthrough_html(meta: &FigureMeta, board: &Board, opts: &WalkOptions) -> String {
    let items = walkthrough_items(board, opts.grouping);
    walkthrough_page(meta, &figure(meta, board, None), &items, opts)
}

/// The list of the walk-through's pages (`<li>` items of `#wt-steps`), each step's caption,
/// German term, book and checks: what the browser page puts in place after a replay.
pub fn walkthrough_items(board: &Board, grouping: Grouping) -> String {
    walkthrough_item_list(board, grouping).concat()
}

/// [`walkthrough_items`] one item per page, so that a live page can show the current page's
/// details without taking in the whole list.
pub fn walkthrough_item_list(board: &Board, grouping: Grouping) -> Vec<String> {
    let names = step_names(board);
    (page_groups(board, grouping).iter())
        .map(|group| group_item(group, &names))
        .collect()
}

/// The walk-through's step list as a live page keeps it: the list's lines apart from what
/// each page shows beside the figure.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepList {
    /// One `<li>` item per page: its steps' numbers, names and situation, a line each
    /// (the item of [`walkthrough_item_list`] without the details it keeps hidden).
    pub lines: Vec<String>,
    /// What each page shows beside the figure: the inner HTML of its item of
    /// [`walkthrough_item_list`], the German term, book, cut and checks included (none from
    /// [`walkthrough_lines`]).
    pub details: Vec<String>,
    /// Every step's name ([`step_names`]), which the lines show: a caller that lists the
    /// steps too need not name them again (the crane bridge's 5,433 names are a tenth of
    /// its full answer to the browser page).
    pub names: Vec<String>,
}

/// [`walkthrough_item_list`] with the details apart from the list ([`StepList`]): a page that
/// puts the list in place anew after a replay lays out the lines alone (the crane bridge's
/// 2,080 items of 1.5 MB are 0.5 MB of lines; the details, 33,000 elements the list hid,
/// are text until their page is shown).
pub fn walkthrough_list(board: &Board, grouping: Grouping) -> StepList {
    let names = step_names(board);
    let (lines, details) = (page_groups(board, grouping).iter())
        .map(|group| {
            let parts = group_parts(group, &names);
            (
                list_line(group, parts.iter().map(|p| &p.line[..])),
                shown(&parts),
            )
        })
        .unzip();
    StepList {
        lines,
        details,
        names,
    }
}

/// [`walkthrough_list`] without the details (`details` empty): the lines and the names, for
/// a live page that asks for a page's details when it shows it ([`walkthrough_details`]).
pub fn walkthrough_lines(board: &Board, grouping: Grouping) -> StepList {
    let names = step_names(board);
    StepList {
        lines: list_lines(board, grouping, &names),
        details: Vec::new(),
        names,
    }
}

/// The lines of [`walkthrough_lines`], the steps named by `names` ([`step_names`]): for a
/// caller that named them before (a live page whose construction is kept from a drag).
pub fn list_lines(board: &Board, grouping: Grouping, names: &[String]) -> Vec<String> {
    (page_groups(board, grouping).iter())
        .map(|group| list_item(group, |out| push_group_lines(out, group, names)))
        .collect()
}

/// What page `k` of `board`'s walk-through shows beside the figure (one of
/// [`StepList::details`]), its steps named by `names` ([`step_names`]); `None` past the
/// last page. A live page asks for a page's details when it shows it, from the construction
/// it keeps, instead of taking in every page's with each replay.
///
/// ```
/// use graphostatik::protocol::BoardConfig;
/// use graphostatik::render::{step_names, walkthrough_details, walkthrough_list, Grouping};
/// use graphostatik::scene::AnyScene;
/// let text = std::fs::read_to_string("scenes/lh_abb22_funicular.json").unwrap();
/// let scene = AnyScene::from_json(&text, "abb22.json").unwrap();
/// let board = scene.problem().construct(BoardConfig::DRAWING).unwrap();
/// let list = walkthrough_list(&board, Grouping::Step);
/// // LH Abb. 22: each page's details, asked for alone, are the list's.
/// for k in 0..list.lines.len() {
///     let d = walkthrough_details(&board, Grouping::Step, k, &list.names);
///     assert_eq!(d.as_ref(), Some(&list.details[k]));
/// }
/// assert_eq!(walkthrough_details(&board, Grouping::Step, list.lines.len(), &list.names), None);
/// ```
pub fn walkthrough_details(
    board: &Board,
    grouping: Grouping,
    k: usize,
    names: &[String],
) -> Option<String> {
    let range = page_ranges(board, grouping).into_iter().nth(k)?;
    Some(page_details(board, range, names))
}

/// The steps of each page of `board`'s walk-through, as ranges of indices into
/// [`Board::steps`]: one step a page, but one page for the steps of a part not drawn.
pub fn page_ranges(board: &Board, grouping: Grouping) -> Vec<Range<usize>> {
    page_runs(board.steps(), grouping).collect()
}

/// What the page of the steps `steps` ([`page_ranges`]) shows beside the figure, its steps
/// named by `names` ([`walkthrough_details`] of a page whose range is known).
pub fn page_details(board: &Board, steps: Range<usize>, names: &[String]) -> String {
    let group: Vec<&Step> = board
        .steps()
        .get(steps)
        .unwrap_or_default()
        .iter()
        .collect();
    if group.is_empty() {
        return String::new();
    }
    shown(&group_parts(&group, names))
}

/// How many pages the walk-through of `board` has: one per step, but one for all the steps of
/// a part not drawn (a position of a moving load that is computed, not drawn).
pub fn page_count(board: &Board, grouping: Grouping) -> usize {
    page_runs(board.steps(), grouping).count()
}

/// The item of page `k` alone ([`walkthrough_item_list`]'s `k`-th), for a live page that
/// shows only the current page's details while the student drags; `None` past the last.
pub fn walkthrough_item(board: &Board, grouping: Grouping, k: usize) -> Option<String> {
    let steps = board.steps();
    let run = page_runs(steps, grouping).nth(k)?;
    // Only this page's steps are named, each told apart from the steps of its situation
    // (named once each, on demand): a drag asks for one page on each pointer move, and
    // naming the crane bridge's 5,438 steps took a fifth of its replay.
    let mut plain: Vec<Option<String>> = vec![None; steps.len()];
    let mut scratch = (String::new(), String::new());
    let mut names = vec![String::new(); steps.len()];
    for i in run.clone() {
        let context = steps[i].context.as_deref();
        let alike = (0..steps.len()).filter(|&j| steps[j].context.as_deref() == context);
        let mut n_alike = 0;
        let mut before = 0;
        let name = plain[i]
            .get_or_insert_with(|| plain_name(board, &steps[i], &mut scratch))
            .clone();
        for j in alike {
            let other = plain[j].get_or_insert_with(|| plain_name(board, &steps[j], &mut scratch));
            if *other == name {
                n_alike += 1;
                before += usize::from(j <= i);
            }
        }
        names[i] = match n_alike {
            1 => name,
            n => format!("{name} ({before} of {n})"),
        };
    }
    let group: Vec<&Step> = steps[run].iter().collect();
    Some(group_item(&group, &names))
}

/// Each step's name in the walk-through, so that no two steps of one situation read alike,
/// as GeoGebra's construction protocol names each object: the caption, then the names of the
/// objects it draws (or, for a step that only reads a value off, of those it reads from; at
/// most three), then, where steps still share all that, which of them it is: `pole ray O
/// (2 of 4)`, `member 3`, `joint load P₀ (3 of 4)`.
///
/// ```
/// use graphostatik::kernel::Point;
/// use graphostatik::protocol::{Board, Note, Role, Topic};
/// let mut b = Board::recording();
/// let n = Note::new("given point", Topic::Custom("demo"));
/// b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n.clone());
/// b.point(Point::new(1.0, 0.0), Role::Given, n.clone());
/// b.point(Point::new(2.0, 0.0), Role::Given, n);
/// let names = graphostatik::render::step_names(&b);
/// assert_eq!(names, ["given point A", "given point (1 of 2)", "given point (2 of 2)"]);
/// ```
pub fn step_names(board: &Board) -> Vec<String> {
    let named = plain_names(board);
    let key = |i: usize| (&named[i], board.steps()[i].context.as_deref());
    let mut count: foldhash::HashMap<_, usize> = Default::default();
    for i in 0..named.len() {
        *count.entry(key(i)).or_default() += 1;
    }
    let mut seen: foldhash::HashMap<_, usize> = Default::default();
    let which: Vec<(usize, usize)> = (0..named.len())
        .map(|i| match count[&key(i)] {
            1 => (1, 1),
            n => {
                let k = seen.entry(key(i)).or_default();
                *k += 1;
                (*k, n)
            }
        })
        .collect();
    drop((count, seen));
    (named.into_iter().zip(which))
        .map(|(mut name, (k, n))| {
            if n > 1 {
                use std::fmt::Write;
                let _ = write!(name, " ({k} of {n})");
            }
            name
        })
        .collect()
}

/// Each step's caption with the names of the objects it draws (or reads from), before steps
/// of one name are told apart.
fn plain_names(board: &Board) -> Vec<String> {
    let mut scratch = (String::new(), String::new());
    (board.steps().iter())
        .map(|s| plain_name(board, s, &mut scratch))
        .collect()
}

/// Step `s`'s name of [`plain_names`]; `scratch` holds two labels while it is made.
fn plain_name(board: &Board, s: &Step, (label, last): &mut (String, String)) -> String {
    let labelled =
        |id: &crate::protocol::ObjId| (board.object(*id)).is_some_and(|o| !o.label.base.is_empty());
    let ids = match s.outputs.iter().any(labelled) {
        true => &s.outputs,
        false => &s.inputs,
    };
    // The labels in turn, each once where it repeats the one before, less those the
    // caption says already ("ordinate line through O"), at most three and "…".
    let mut name = s.caption.to_string();
    let mut told = 0;
    last.clear();
    for id in ids {
        if !object_label(board, *id, label) || label == last {
            continue;
        }
        std::mem::swap(label, last);
        if s.caption
            .split([' ', ',', ':', '(', ')'])
            .any(|w| w == last)
        {
            continue;
        }
        told += 1;
        match told {
            1 => name.push(' '),
            2 | 3 => name.push_str(", "),
            _ => continue,
        }
        name.push_str(last);
    }
    if told > 3 {
        name.push_str(", …");
    }
    name
}

/// Whether object `id` of `board` has a label, and if so `out` holds it (the base and the
/// index as subscript digits: `P₁₂`).
fn object_label(board: &Board, id: crate::protocol::ObjId, out: &mut String) -> bool {
    let Some(l) = board.object(id).map(|o| &o.label) else {
        return false;
    };
    if l.base.is_empty() {
        return false;
    }
    out.clear();
    out.push_str(&l.base);
    if let Some(i) = l.index {
        let digits = i.to_string();
        out.extend(digits.chars().filter_map(crate::fmt::subscript_of));
    }
    true
}

/// The walk-through page around a figure drawn already (`svg`) and its step list
/// ([`walkthrough_items`]).
pub fn walkthrough_page(meta: &FigureMeta, svg: &str, items: &str, opts: &WalkOptions) -> String {
    let error = opts
        .error
        .as_ref()
        .map(|e| format!("<p id=\"wt-error\" role=\"alert\">{}</p>\n", html_text(e)))
        .unwrap_or_default();
    // In a script, `</` could end it and `<!` open a comment; in JSON they stand only inside
    // strings, where `<\/` and `\u003c!` mean the same.
    let details = (opts.details.as_ref())
        .map(|d| {
            let json = serde_json::to_string(d).expect("a list of strings is JSON");
            format!(
                "<script type=\"application/json\" id=\"wt-details\">{}</script>\n",
                json.replace("</", "<\\/").replace("<!", "\\u003c!")
            )
        })
        .unwrap_or_default();
    let page = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}: step by step</title>\n<style>\n{css}{more_css}</style>\n</head>\n<body>\n\
         <header><h1>{title}</h1><p class=\"wt-source\">{source}</p></header>\n{error}\
         <main>\n<section id=\"wt-figure\" aria-label=\"construction\">\n{svg}</section>\n\
         <aside id=\"wt-side\">\n{controls}{nav}<div id=\"wt-now\" aria-live=\"polite\"></div>\n\
         <ol id=\"wt-steps\">\n{items}</ol>\n</aside>\n</main>\n\
         <div id=\"wt-print\"></div>\n{details}<script>{script}</script>\n{extra}{more}</body>\n</html>\n",
        title = html_text(&meta.title),
        source = html_text(&meta.source),
        css = PAGE_CSS,
        more_css = opts.css,
        nav = NAV,
        controls = opts.controls,
        script = SCRIPT,
        extra = opts.extra,
        more = (opts.scripts.iter())
            .map(|s| format!("<script>{s}</script>\n"))
            .collect::<String>(),
    );
    // What the page's own tags hold, as the browser hashes it: its sheet, the figure's, its
    // scripts.
    let page_css = format!("\n{PAGE_CSS}{}", opts.css);
    let figure_css = super::style::style_text();
    let mut scripts = vec![SCRIPT];
    scripts.extend(opts.scripts.iter().map(String::as_str));
    super::with_policy(page, &scripts, &[&page_css, &figure_css], opts.allow)
}

/// The buttons (the keys do the same).
const NAV: &str =
    "<nav id=\"wt-nav\"><button id=\"wt-first\" title=\"first step (Home)\">|&lt;</button> \
<button id=\"wt-prev\" title=\"back (←)\">&lt; back</button> <span id=\"wt-count\"></span> \
<button id=\"wt-next\" title=\"next (→, space)\">next &gt;</button> \
<button id=\"wt-last\" title=\"last step (End)\">&gt;|</button> \
<button id=\"wt-zoom\" title=\"zoom to the step (z)\" aria-pressed=\"false\">zoom</button> \
<button id=\"wt-printbtn\" title=\"one step per panel (p)\">print</button> \
<button id=\"wt-play\" title=\"play the steps one after another (k)\" aria-pressed=\"false\">play</button> \
<select id=\"wt-speed\" title=\"steps per second\"><option value=\"0.5\">½ step/s</option>\
<option value=\"1\">1 step/s</option><option value=\"2\" selected>2 steps/s</option>\
<option value=\"5\">5 steps/s</option><option value=\"20\">20 steps/s</option></select></nav>\n";

/// One step's line of the list (its number, name and situation) and its details (German
/// term, book, cut, checks), which the list hides and the page shows for the current step.
struct Part {
    line: String,
    detail: String,
}

impl Part {
    /// The step as the page shows it: its line and, below, its details.
    fn full(&self) -> String {
        format!(
            "<div class=\"wt-step\">{}<div class=\"wt-detail\">{}</div></div>",
            self.line, self.detail
        )
    }
}

/// The steps of one page of the list, a [`Part`] each (one for a part not drawn).
fn group_parts(group: &[&Step], names: &[String]) -> Vec<Part> {
    if group[0].part.hidden {
        vec![unseen_steps(group, names)]
    } else {
        (group.iter())
            .map(|s| step_detail(s, step_name(s, names)))
            .collect()
    }
}

/// Step `s`'s name of `names` ([`step_names`]), its caption where `names` has none.
fn step_name<'a>(s: &'a Step, names: &'a [String]) -> &'a str {
    let i = (s.id.0 as usize).checked_sub(1);
    i.and_then(|i| names.get(i)).map_or(&s.caption, |n| n)
}

/// The `<li>` around a page's steps, with the range of steps it shows; `inner` writes what
/// it holds.
fn list_item(group: &[&Step], inner: impl FnOnce(&mut String)) -> String {
    use std::fmt::Write;
    let mut out = String::new();
    let (first, last) = (group[0].id, group[group.len() - 1].id);
    let _ = write!(out, "<li data-first=\"{first}\" data-last=\"{last}\">");
    inner(&mut out);
    out.push_str("</li>\n");
    out
}

/// A page's item in the list without its details: its steps' lines alone.
fn list_line<'a>(group: &[&Step], lines: impl IntoIterator<Item = &'a str>) -> String {
    list_item(group, |out| {
        for l in lines {
            push_in_step(out, |out| out.push_str(l));
        }
    })
}

/// A step's `<div>` in the list, `inner` writing what it holds.
fn push_in_step(out: &mut String, inner: impl FnOnce(&mut String)) {
    out.push_str("<div class=\"wt-step\">");
    inner(out);
    out.push_str("</div>");
}

/// The lines of a page's steps ([`group_parts`] without their details), each in its `<div>`,
/// put at the end of `out`.
fn push_group_lines(out: &mut String, group: &[&Step], names: &[String]) {
    if group[0].part.hidden {
        push_in_step(out, |out| push_unseen_line(out, group));
    } else {
        for s in group {
            push_in_step(out, |out| push_step_line(out, s, step_name(s, names)));
        }
    }
}

/// What a page shows beside the figure: its steps' lines, each with its details.
fn shown(parts: &[Part]) -> String {
    parts.iter().map(Part::full).collect()
}

/// One page of the list: the steps it shows, a line each, and their details.
fn group_item(group: &[&Step], names: &[String]) -> String {
    list_item(group, |out| {
        out.push_str(&shown(&group_parts(group, names)))
    })
}

/// The steps of a part constructed and checked but not drawn (a position of a moving load
/// that the book computes, not draws), as one step: in the list, the steps' numbers, how many
/// and the situation, once; in the details, each step on a line of its own with its German
/// term, the books they follow once, and the checks. (The crane bridge's seven positions not
/// drawn wrote 1.3 MB of the list's 2.1 MB, 483 lines each, when each step was written in
/// full.)
fn unseen_steps(group: &[&Step], names: &[String]) -> Part {
    Part {
        line: unseen_line(group),
        detail: unseen_details(group, names),
    }
}

/// The line in the list of the steps of a part not drawn ([`unseen_steps`]).
fn unseen_line(group: &[&Step]) -> String {
    let mut out = String::new();
    push_unseen_line(&mut out, group);
    out
}

/// [`unseen_line`] put at the end of `out`.
fn push_unseen_line(out: &mut String, group: &[&Step]) {
    use std::fmt::Write;
    let checks: usize = group.iter().map(|s| s.checks.len()).sum();
    let _ = write!(
        out,
        "<b>{}–{}</b> <span class=\"wt-unseen\">not drawn: {} steps constructed, \
         {checks} checks made</span>",
        group[0].id,
        group[group.len() - 1].id,
        group.len(),
    );
    push_context(out, shared_context(group));
}

/// A situation's ` <i>…</i>` after a step's name, where there is one.
fn push_context(out: &mut String, context: Option<&str>) {
    if let Some(c) = context {
        out.push_str(" <i>");
        crate::fmt::markup_text(out, c);
        out.push_str("</i>");
    }
}

/// The details of the steps of a part not drawn ([`unseen_steps`]).
fn unseen_details(group: &[&Step], names: &[String]) -> String {
    let mut books: Vec<&str> = Vec::new();
    let mut d = String::new();
    for s in group {
        if !s.book.is_empty() && !books.contains(&&*s.book) {
            books.push(&s.book);
        }
        d.push_str(&format!(
            "<p class=\"wt-sub\"><b>{}</b> {}{}</p>",
            s.id,
            html_text(step_name(s, names)),
            (s.term_de.as_ref())
                .map(|de| format!(
                    " <span class=\"wt-de\" lang=\"de\">{}</span>",
                    html_text(de)
                ))
                .unwrap_or_default()
        ));
        if !s.checks.is_empty() {
            d.push_str(&checks_table(s));
        }
    }
    format!(
        "<p class=\"wt-book\">{}</p>{d}",
        html_text(&books.join("; "))
    )
}

/// The situation the steps of `group` share: what their contexts begin with alike, up to where
/// one ends or goes on after a `: ` ("crane at O5 (… slack)" of that and "crane at O5 (…
/// slack): joint U0").
fn shared_context<'a>(group: &[&'a Step]) -> Option<&'a str> {
    let first = group[0].context.as_deref()?;
    let mut len = first.len();
    for s in &group[1..] {
        let c = s.context.as_deref()?;
        // The bytes alike, back to the start of the character they end in: where the first
        // character that differs starts.
        len = (first.as_bytes()[..len].iter().zip(c.as_bytes()))
            .take_while(|(a, b)| a == b)
            .count();
        while !first.is_char_boundary(len) {
            len -= 1;
        }
    }
    // Each context is the shared part, or the shared part and what follows a `: `.
    let ends = |c: &str| c.len() == len || c[len..].starts_with(": ");
    if group.iter().all(|s| s.context.as_deref().is_some_and(ends)) {
        return Some(&first[..len]);
    }
    first[..len].rfind(": ").map(|i| &first[..i])
}

/// One step: number, caption and context (the line in the list), then the German term, the
/// book, the cut's angle, a degenerate outcome and the checks (shown for the current step).
fn step_detail(step: &Step, name: &str) -> Part {
    Part {
        line: step_line(step, name),
        detail: step_details(step),
    }
}

/// A step's line in the list: its number, name and situation.
fn step_line(step: &Step, name: &str) -> String {
    let mut out = String::new();
    push_step_line(&mut out, step, name);
    out
}

/// [`step_line`] put at the end of `out`.
fn push_step_line(out: &mut String, step: &Step, name: &str) {
    use std::fmt::Write;
    let _ = write!(out, "<b>{}</b> ", step.id);
    crate::fmt::markup_text(out, name);
    push_context(out, step.context.as_deref());
}

/// A step's details: German term, book, cut, outcome and checks.
fn step_details(step: &Step) -> String {
    let mut d = String::new();
    if let Some(de) = &step.term_de {
        d.push_str(&format!(
            "<p class=\"wt-de\" lang=\"de\">{}</p>",
            html_text(de)
        ));
    }
    if !step.book.is_empty() {
        d.push_str(&format!(
            "<p class=\"wt-book\">{}</p>",
            html_text(&step.book)
        ));
    }
    if let Some(c) = &step.conditioning {
        d.push_str(&format!(
            "<p class=\"wt-cond{}\">cut at {}°{}</p>",
            if c.glancing() { " wt-glancing" } else { "" },
            crate::fmt::num(c.angle_deg(), 1),
            if c.glancing() { " (glancing)" } else { "" }
        ));
    }
    if let Some(o) = &step.outcome {
        d.push_str(&format!("<p class=\"wt-outcome\">{}</p>", html_text(o)));
    }
    if !step.checks.is_empty() {
        d.push_str(&checks_table(step));
    }
    d
}

/// The step's checks: constructed value against the closed form.
fn checks_table(step: &Step) -> String {
    let mut t = String::from(
        "<table class=\"wt-checks\"><tr><th>check</th><th>constructed</th><th>closed form</th>\
         <th>error</th><th>bound</th><th>tolerance</th><th></th></tr>",
    );
    for c in &step.checks {
        t.push_str(&format!(
            "<tr class=\"{}\"><td>{} [{}]<br><small>{}</small></td><td>{}</td><td>{}</td>\
             <td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            if c.passed { "wt-ok" } else { "wt-fail" },
            html_text(&match &c.object {
                Some(object) => format!("{}, {object}", c.quantity),
                None => c.quantity.to_string(),
            }),
            html_text(&c.unit),
            html_text(&c.formula),
            crate::fmt::num(c.constructed, 6),
            crate::fmt::num(c.closed_form, 6),
            crate::fmt::sci(c.error),
            crate::fmt::sci(c.bound),
            crate::fmt::sci(c.tolerance),
            match (c.passed, c.judged()) {
                (false, _) => "FAIL",
                (true, true) => "ok",
                (true, false) => "not judged",
            }
        ));
    }
    t.push_str("</table>");
    t
}

/// The page's style: figure left, protocol right; print: one step per panel.
const PAGE_CSS: &str = r#"body { font-family: Georgia, 'DejaVu Serif', serif; margin: 0; color: #222; }
header { padding: 0.4em 1em; border-bottom: 1px solid #ccc; }
header h1 { font-size: 1.25em; margin: 0; }
.wt-source { margin: 0.2em 0 0; color: #555; }
#wt-error { margin: 0; padding: 0.5em 1em; background: #fbe3df; color: #8a1d12; font-family: monospace; white-space: pre-wrap; }
main { display: flex; height: calc(100vh - 4em); }
#wt-figure { flex: 3; overflow: auto; padding: 0.5em; }
#wt-figure svg { width: 100%; height: auto; max-height: 100%; background: #fff; }
#wt-side { flex: 2; display: flex; flex-direction: column; border-left: 1px solid #ccc; min-width: 18em; }
#wt-nav { padding: 0.5em; border-bottom: 1px solid #ddd; }
#wt-sliders { padding: 0.5em; border-bottom: 1px solid #ddd; background: #f7f5ef; }
#wt-sliders input { vertical-align: middle; width: 14em; }
#wt-nav button { font: inherit; padding: 0.2em 0.6em; }
#wt-nav button[aria-pressed="true"] { background: #f3e2df; }
#wt-nav select { font: inherit; padding: 0.15em; }
#wt-figure g.wt-hover * { stroke: #1f5fbf !important; }
#wt-figure g.wt-hover text { fill: #1f5fbf !important; stroke: none !important; }
#wt-count { display: inline-block; min-width: 6em; text-align: center; }
#wt-now { padding: 0.5em 1em; border-bottom: 1px solid #ddd; max-height: 45%; overflow: auto; }
#wt-steps { flex: 1; overflow-y: auto; margin: 0; padding: 0.5em 1em; font-size: 0.9em; list-style: none; }
#wt-steps li { cursor: pointer; padding: 0.1em 0; }
#wt-steps li.wt-on { background: #f3e2df; }
#wt-steps .wt-detail { display: none; }
.wt-detail p { margin: 0.2em 0; }
.wt-de, .wt-book { color: #555; }
.wt-glancing, .wt-fail td { color: #b0362a; font-weight: bold; }
.wt-ok td:last-child { color: #2a6b2a; }
.wt-outcome { color: #7a4d00; }
.wt-unseen { color: #555; font-style: italic; }
.wt-sub { margin: 0.1em 0 0 1em; }
.wt-checks { border-collapse: collapse; font-size: 0.8em; margin-top: 0.4em; }
.wt-checks td, .wt-checks th { border-top: 1px solid #ddd; padding: 0.15em 0.2em; text-align: right; vertical-align: top; }
.wt-checks td { white-space: nowrap; }
.wt-checks td:first-child, .wt-checks th:first-child { text-align: left; white-space: normal; min-width: 6.5em; }
#wt-print { display: none; }
@media print {
  header, main { display: none; }
  #wt-print { display: block; }
  .wt-panel { page-break-inside: avoid; break-inside: avoid; margin-bottom: 1em; }
  .wt-panel svg { width: 100%; height: auto; max-height: 60vh; }
  .wt-panel .wt-detail { display: block; }
}
"#;

/// The page's behaviour: layers up to the current step shown, the current one highlighted,
/// zoom to its bounding box, keys and buttons, and the print panels.
const SCRIPT: &str = r#"(function () {
'use strict';
var svg, layers, items, full, k = 0, zoom = false;
// Each page's details where the list holds its lines alone (a live page, whose list is put
// anew after a replay, lays out the lines without them): an array, or a function of the
// page that makes them (the live page's engine); else null, each item holds its own.
var given = document.getElementById('wt-details');
var details = given ? JSON.parse(given.textContent) : null;
function detailOf(j) {
  if (!details) return items[j].innerHTML;
  return typeof details === 'function' ? details(j) : details[j];
}
// The figure and the step list as the page holds them now (a live page puts new ones in
// place after each replay and binds them again).
function bind() {
  svg = document.querySelector('#wt-figure svg');
  layers = stepLayers(svg);
  items = Array.prototype.slice.call(list.children);
  full = svg.getAttribute('viewBox');
}
// The list's items are listened to by the list (its items are put anew after a replay: the
// crane bridge's 5,438 would take 16,000 listeners each time). A pointer entering or
// leaving an item is caught on its way down to the item.
var list = document.getElementById('wt-steps');
function itemOf(e) { return e.target.parentNode === list ? e.target : null; }
list.addEventListener('click', function (e) {
  var li = e.target.closest && e.target.closest('#wt-steps > li');
  if (li) show(items.indexOf(li));
});
list.addEventListener('mouseenter', function (e) { var li = itemOf(e); if (li) hover(li, true); }, true);
list.addEventListener('mouseleave', function (e) { var li = itemOf(e); if (li) hover(li, false); }, true);
bind();
// The figure's step layers: children of its root (read off the children: a selector
// searches all of the crane bridge's 17,000 elements).
function stepLayers(root) {
  return Array.prototype.filter.call(root.children, function (g) { return g.hasAttribute('data-step'); });
}
function range(li) { return [Number(li.getAttribute('data-first')), Number(li.getAttribute('data-last'))]; }
function setLayers(root, r) {
  stepLayers(root).forEach(function (g) {
    var s = Number(g.getAttribute('data-step')), d = s <= r[1] ? '' : 'none';
    // (Set only where it changes: the crane bridge has 5,433 layers.)
    if (g.style.display !== d) g.style.display = d;
    g.classList.toggle('current', s >= r[0] && s <= r[1]);
  });
}
function boxOf(lo, hi) {
  var box = null;
  layers.forEach(function (g) {
    var s = Number(g.getAttribute('data-step'));
    if (s < lo || s > hi || !g.firstChild) return;
    // A layer's box in its own coordinates, moved as its transform moves it (a translate).
    var b = g.getBBox(), t = g.transform.baseVal.consolidate();
    if (b.width === 0 && b.height === 0) return;
    if (t) b = { x: b.x + t.matrix.e, y: b.y + t.matrix.f, width: b.width, height: b.height };
    box = box ? { x: Math.min(box.x, b.x), y: Math.min(box.y, b.y),
      x2: Math.max(box.x2, b.x + b.width), y2: Math.max(box.y2, b.y + b.height) }
      : { x: b.x, y: b.y, x2: b.x + b.width, y2: b.y + b.height };
  });
  return box;
}
// Setting the view box lays the figure out anew even where the value is the same (a tenth of
// a second on the largest sheets): it is set only where it changes.
function setView(v) { if (svg.getAttribute('viewBox') !== v) svg.setAttribute('viewBox', v); }
function zoomTo(r) {
  // A step that only measures draws nothing: zoom to the last step before it that drew.
  var box = boxOf(r[0], r[1]);
  for (var lo = r[0] - 1; !box && lo >= 1; lo--) box = boxOf(lo, lo);
  if (!box) { setView(full); return; }
  var w = Math.max(box.x2 - box.x, 20), h = Math.max(box.y2 - box.y, 20);
  var cx = (box.x + box.x2) / 2, cy = (box.y + box.y2) / 2;
  setView([cx - 0.65 * w, cy - 0.65 * h, 1.3 * w, 1.3 * h].join(' '));
}
// On a sheet larger than its pane, the pane scrolls so that the step's new objects are in
// view (zoom aside).
function follow(r) {
  var pane = document.getElementById('wt-figure'), box = null;
  if (pane.scrollHeight <= pane.clientHeight && pane.scrollWidth <= pane.clientWidth) return;
  for (var s = r[0]; s <= r[1]; s++) {
    var g = svg.querySelector('g[data-step="' + String(s).padStart(3, '0') + '"]');
    if (!g || !g.firstChild) continue;
    var b = g.getBoundingClientRect();
    if (b.width === 0 && b.height === 0) continue;
    box = box ? { l: Math.min(box.l, b.left), t: Math.min(box.t, b.top), r: Math.max(box.r, b.right), b: Math.max(box.b, b.bottom) }
      : { l: b.left, t: b.top, r: b.right, b: b.bottom };
  }
  if (!box) return;
  var p = pane.getBoundingClientRect();
  var dx = box.l < p.left || box.r > p.right ? (box.l + box.r) / 2 - (p.left + p.right) / 2 : 0;
  var dy = box.t < p.top || box.b > p.bottom ? (box.t + box.b) / 2 - (p.top + p.bottom) / 2 : 0;
  if (dx || dy) pane.scrollBy(dx, dy);
}
// Shows page i. `how`: 'push' (the default: the browser's Back returns to the page before),
// 'replace' (the address follows, no history entry: opening, playing, a replay), 'pop' (the
// browser went back or forward).
function show(i, how) {
  if (items.length === 0) { document.getElementById('wt-count').textContent = 'no steps'; return; }
  var was = k;
  k = Math.max(0, Math.min(items.length - 1, i));
  var r = range(items[k]);
  setLayers(svg, r);
  items.forEach(function (li, j) { li.classList.toggle('wt-on', j === k); });
  document.getElementById('wt-now').innerHTML = detailOf(k);
  document.getElementById('wt-count').textContent = 'step ' + (k + 1) + ' / ' + items.length;
  if (zoom) zoomTo(r); else { setView(full); follow(r); }
  items[k].scrollIntoView({ block: 'nearest' });
  if (!window.history || !window.history.replaceState || how === 'pop') return;
  if ((how || 'push') === 'push' && k !== was) window.history.pushState({ step: k + 1 }, '', '#' + (k + 1));
  else window.history.replaceState({ step: k + 1 }, '', '#' + (k + 1));
}
var timer = null;
function play() {
  var button = document.getElementById('wt-play');
  if (timer) { clearInterval(timer); timer = null; button.textContent = 'play'; button.setAttribute('aria-pressed', 'false'); return; }
  if (k >= items.length - 1) show(0, 'replace');
  button.textContent = 'pause';
  button.setAttribute('aria-pressed', 'true');
  var rate = Number(document.getElementById('wt-speed').value) || 2;
  timer = setInterval(function () {
    if (k >= items.length - 1) { play(); return; }
    show(k + 1, 'replace');
  }, 1000 / rate);
}
function hover(li, on) {
  var r = range(li);
  layers.forEach(function (g) {
    var s = Number(g.getAttribute('data-step'));
    if (s < r[0] || s > r[1]) return;
    g.classList.toggle('wt-hover', on);
    if (on) g.style.display = '';
  });
  if (!on) setLayers(svg, range(items[k]));
}
function toggleZoom() {
  zoom = !zoom;
  document.getElementById('wt-zoom').setAttribute('aria-pressed', String(zoom));
  show(k);
}
function buildPrint() {
  var out = document.getElementById('wt-print');
  out.innerHTML = '';
  items.forEach(function (li, j) {
    var panel = document.createElement('section');
    panel.className = 'wt-panel';
    var copy = svg.cloneNode(true);
    copy.setAttribute('viewBox', full);
    Array.prototype.forEach.call(copy.querySelectorAll('[id]'), function (e) {
      if (e.tagName.toLowerCase() === 'g') e.removeAttribute('id');
    });
    setLayers(copy, range(li));
    panel.appendChild(copy);
    var text = document.createElement('div');
    text.innerHTML = detailOf(j);
    panel.appendChild(text);
    out.appendChild(panel);
  });
}
document.getElementById('wt-first').addEventListener('click', function () { show(0); });
document.getElementById('wt-prev').addEventListener('click', function () { show(k - 1); });
document.getElementById('wt-next').addEventListener('click', function () { show(k + 1); });
document.getElementById('wt-last').addEventListener('click', function () { show(items.length - 1); });
document.getElementById('wt-zoom').addEventListener('click', toggleZoom);
document.getElementById('wt-printbtn').addEventListener('click', function () { buildPrint(); window.print(); });
window.addEventListener('beforeprint', buildPrint);
document.addEventListener('keydown', function (e) {
  if (e.target && (e.target.tagName === 'INPUT' || e.target.tagName === 'TEXTAREA')) return;
  if (e.key === 'ArrowRight' || e.key === ' ' || e.key === 'PageDown') { show(k + 1); e.preventDefault(); }
  else if (e.key === 'ArrowLeft' || e.key === 'PageUp') { show(k - 1); e.preventDefault(); }
  else if (e.key === 'Home') show(0);
  else if (e.key === 'End') show(items.length - 1);
  else if (e.key === 'z') toggleZoom();
  else if (e.key === 'p') { buildPrint(); window.print(); }
  else if (e.key === 'k') play();
});
document.getElementById('wt-play').addEventListener('click', play);
document.getElementById('wt-speed').addEventListener('change', function () { if (timer) { play(); play(); } });
window.addEventListener('popstate', function (e) {
  var n = e.state && e.state.step ? e.state.step : Number((window.location.hash || '#1').slice(1));
  if (isFinite(n) && n > 0) show(n - 1, 'pop');
});
// The step in the address, else the first (the last where the page asks to open on the
// whole construction: <body data-wt-start="end">).
var start = Number((window.location.hash ||
  (document.body.getAttribute('data-wt-start') === 'end' ? '#' + items.length : '#1')).slice(1));
show(isFinite(start) && start > 0 ? start - 1 : 0, 'replace');
// A new figure of the same construction (a live page's replay while the student drags): the
// current page's layers on the fresh figure, nothing else touched. `now` is the current
// page's item as the replay gives it; `fresh`, where the figure was set in place, the step
// layers put anew (the others keep what the page set on them); `moved`, whether the steps
// were numbered anew (a step more or fewer: every layer is set); `pages`, how many pages
// the replay has (the list follows when the drag ends).
function swapFigure(now, fresh, moved, pages) {
  var li = null;
  if (now !== undefined) {
    var ul = document.createElement('ul');
    ul.innerHTML = now;
    li = ul.firstElementChild;
  }
  var r = li ? range(li) : range(items[k]);
  var set = function (g) {
    var s = Number(g.getAttribute('data-step'));
    if (s > r[1]) g.style.display = 'none';
    else if (s >= r[0]) g.classList.add('current');
  };
  svg = document.querySelector('#wt-figure svg');
  if (fresh && !moved) {
    if (fresh.length) layers = stepLayers(svg);
    fresh.forEach(function (g) { if (g.hasAttribute('data-step')) set(g); });
  } else if (fresh) {
    layers = stepLayers(svg);
    setLayers(svg, r);
  } else {
    layers = stepLayers(svg);
    layers.forEach(set);
  }
  full = svg.getAttribute('viewBox');
  if (li) document.getElementById('wt-now').innerHTML = li.innerHTML;
  if (pages !== undefined && pages !== items.length) {
    document.getElementById('wt-count').textContent = 'step ' + Math.min(k + 1, pages) + ' / ' + pages;
  }
  if (zoom) zoomTo(r);
}
window.graphostatikWalk = { show: show, step: function () { return k; }, pages: items.length,
  // The list put anew: `d`, where given, each page's details (its lines alone are listed),
  // as an array or a function of the page.
  rebind: function (d) {
    if (d !== undefined) details = d;
    bind();
    window.graphostatikWalk.pages = items.length;
    show(k, 'replace');
  },
  swapFigure: swapFigure };
})();
"#;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::protocol::{Note, Role, Topic};

    fn note(caption: &'static str) -> Note {
        Note::new(caption, Topic::Custom("demo"))
    }

    /// A board of named points and a distance checked, with markup in a name and a check.
    fn board() -> Board {
        let mut b = Board::recording();
        let n = note("given point");
        let a = b.point(Point::new(0.0, 0.0), Role::Given.named("A"), n.clone());
        let c = b.point(Point::new(1.0, 0.0), Role::Given.named("</script><!--"), n);
        let axis = b
            .line_dir(
                &a,
                crate::kernel::Vector::new(1.0, 0.0),
                Role::Axis,
                note("axis"),
            )
            .unwrap();
        let scale = crate::protocol::Scale::new(1.0, "mm");
        let v = b.measure(&a, &c, &axis, scale, "d", note("distance read off"));
        b.check(&v, "distance </b>", "mm", "given", 1.0, || 1.0);
        b
    }

    #[test]
    fn the_lines_and_details_apart_make_the_items_whole() {
        let b = board();
        for grouping in [Grouping::Step, Grouping::Context] {
            let whole = walkthrough_item_list(&b, grouping);
            let list = walkthrough_list(&b, grouping);
            assert_eq!(list.lines.len(), whole.len());
            for ((line, detail), item) in list.lines.iter().zip(&list.details).zip(&whole) {
                let open = &line[..=line.find('>').unwrap()];
                assert_eq!(&format!("{open}{detail}</li>\n"), item);
                assert!(!line.contains("wt-detail"), "{line}");
                assert!(item.starts_with(open), "{item}");
            }
        }
    }

    #[test]
    fn the_details_in_the_page_cannot_end_its_script() {
        let b = board();
        let list = walkthrough_list(&b, Grouping::Step);
        assert!(list.details.iter().any(|d| d.contains("</")));
        let meta = FigureMeta::default();
        let opts = WalkOptions {
            details: Some(list.details.clone()),
            ..Default::default()
        };
        let page = walkthrough_page(&meta, "<svg></svg>", &list.lines.concat(), &opts);
        let at = page.find("id=\"wt-details\">").unwrap() + 16;
        let json = &page[at..at + page[at..].find("</script>").unwrap()];
        assert!(!json.contains("<!"), "{json}");
        let read: Vec<String> = serde_json::from_str(json).unwrap();
        assert_eq!(read, list.details);
    }
}
