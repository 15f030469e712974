//! Walk-through pages: one cumulative SVG per step and an offline `index.html` that pages
//! through them with their captions.

use super::figure::figure;
use crate::protocol::FigureMeta;
use crate::protocol::{Board, Step};

/// A file of the walk-through: its name and contents.
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    /// File name (`step-001.svg`, `index.html`).
    pub name: String,
    /// Contents.
    pub contents: String,
}

pub(super) fn html_escape(s: &str) -> String {
    crate::fmt::sheet_text(s)
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Most pages a walk-through writes. Each page is a whole figure, so a construction of
/// thousands of steps (a crane bridge with ten load positions) would write gigabytes; above
/// this, consecutive steps that share a context (one joint polygon, one crank angle) share
/// a page, and if that is still too many, neighbouring groups are merged evenly.
pub const MAX_PAGES: usize = 150;

/// The steps of each page, in order.
fn page_groups(board: &Board) -> Vec<Vec<&Step>> {
    let steps = board.steps();
    if steps.len() <= MAX_PAGES {
        return steps.iter().map(|s| vec![s]).collect();
    }
    let mut groups: Vec<Vec<&Step>> = Vec::new();
    for s in steps {
        match groups.last_mut() {
            Some(g) if g[0].context == s.context => g.push(s),
            _ => groups.push(vec![s]),
        }
    }
    if groups.len() > MAX_PAGES {
        let per = groups.len().div_ceil(MAX_PAGES);
        groups = groups
            .chunks(per)
            .map(|c| c.iter().flatten().copied().collect())
            .collect();
    }
    groups
}

/// What a walk-through of `board` costs before it is written: its pages, and the objects
/// they draw in all (each page draws every object up to its step).
pub fn walkthrough_cost(board: &Board) -> (usize, usize) {
    let groups = page_groups(board);
    let mut drawn = 0usize;
    let mut upto = 0usize;
    let objects = board.objects();
    for g in &groups {
        let last = g[g.len() - 1].id;
        while upto < objects.len() && objects[upto].step <= last {
            upto += 1;
        }
        drawn = drawn.saturating_add(upto);
    }
    (groups.len(), drawn)
}

/// Most objects all pages of one walk-through may draw together (about 350 bytes each, so
/// some 350 MB): beyond, `steps` refuses before it writes anything.
pub const MAX_WALKTHROUGH_OBJECTS: usize = 1_000_000;

/// The pages of a walk-through: `step-NNN.svg` showing steps 1..NNN with NNN highlighted,
/// and `index.html`, which works offline (no script from outside, images by relative path),
/// with buttons and the arrow keys to step back and forth. Beyond [`MAX_PAGES`] steps a page
/// shows a group of steps (named by its last one) and lists them all.
pub fn walkthrough(meta: &FigureMeta, board: &Board) -> Vec<Page> {
    let mut pages = Vec::new();
    let mut items = String::new();
    for group in page_groups(board) {
        let last = group[group.len() - 1];
        let name = format!("step-{}.svg", last.id);
        pages.push(Page {
            name: name.clone(),
            contents: figure(meta, board, Some(last.id)),
        });
        let lines: Vec<String> = group.iter().map(|s| step_line(s)).collect();
        items.push_str(&format!(
            "<li data-src=\"{name}\">{}</li>\n",
            lines.join("<br>")
        ));
    }
    let index = format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{title}: step by step</title>
<style>
body {{ font-family: Georgia, 'Times New Roman', serif; margin: 0; display: flex; height: 100vh; }}
#fig {{ flex: 3; display: flex; flex-direction: column; align-items: center; padding: 1em; }}
#fig img {{ max-width: 100%; max-height: 80vh; border: 1px solid #ccc; background: #fff; }}
#nav {{ margin: 0.5em; }}
#caption {{ font-size: 1.1em; margin: 0.5em; text-align: center; }}
ol {{ flex: 2; overflow-y: auto; margin: 0; padding: 1em 1em 1em 3em; border-left: 1px solid #ccc; font-size: 0.9em; }}
li {{ cursor: pointer; padding: 0.15em 0; }}
li.on {{ background: #f3e2df; }}
.de, .book {{ color: #555; }} .cond.glancing(), .fail {{ color: #b0362a; font-weight: bold; }}
.ok {{ color: #2a6b2a; }} .outcome {{ color: #7a4d00; }}
</style>
</head>
<body>
<div id="fig">
<h1 style="font-size:1.3em">{title}</h1>
<div id="nav"><button id="first">|&lt;</button> <button id="prev">&lt; back</button>
<span id="count"></span> <button id="next">next &gt;</button> <button id="last">&gt;|</button></div>
<img id="img" alt="construction step">
<div id="caption"></div>
</div>
<ol id="steps">
{items}</ol>
<script>
var items = Array.prototype.slice.call(document.querySelectorAll('#steps li'));
var k = 0;
function show(i) {{
  if (items.length === 0) return;
  k = Math.max(0, Math.min(items.length - 1, i));
  items.forEach(function (li, j) {{ li.className = j === k ? 'on' : ''; }});
  document.getElementById('img').src = items[k].getAttribute('data-src');
  document.getElementById('caption').innerHTML = items[k].innerHTML;
  document.getElementById('count').textContent = (k + 1) + ' / ' + items.length;
  items[k].scrollIntoView({{block: 'nearest'}});
}}
items.forEach(function (li, j) {{ li.onclick = function () {{ show(j); }}; }});
document.getElementById('first').onclick = function () {{ show(0); }};
document.getElementById('prev').onclick = function () {{ show(k - 1); }};
document.getElementById('next').onclick = function () {{ show(k + 1); }};
document.getElementById('last').onclick = function () {{ show(items.length - 1); }};
document.onkeydown = function (e) {{
  if (e.key === 'ArrowRight') show(k + 1);
  if (e.key === 'ArrowLeft') show(k - 1);
}};
show(0);
</script>
</body>
</html>
"#,
        title = html_escape(&meta.title),
        items = items
    );
    pages.push(Page {
        name: "index.html".into(),
        contents: index,
    });
    pages
}

/// One step's line in the index: number, caption, context, German term, book, cut angle,
/// outcome and checks.
fn step_line(step: &Step) -> String {
    let mut detail = String::new();
    if let Some(de) = &step.term_de {
        detail.push_str(&format!(" <span class=\"de\">({})</span>", html_escape(de)));
    }
    if !step.book.is_empty() {
        detail.push_str(&format!(
            " <span class=\"book\">{}</span>",
            html_escape(&step.book)
        ));
    }
    if let Some(c) = &step.conditioning {
        detail.push_str(&format!(
            " <span class=\"cond{}\">cut at {}°</span>",
            if c.glancing() { " glancing" } else { "" },
            crate::fmt::num(c.angle_deg(), 1)
        ));
    }
    if let Some(o) = &step.outcome {
        detail.push_str(&format!(
            " <span class=\"outcome\">{}</span>",
            html_escape(o)
        ));
    }
    for c in &step.checks {
        detail.push_str(&format!(
            " <span class=\"check {}\">{} = {} {} (closed form {}, error {})</span>",
            if c.passed { "ok" } else { "fail" },
            html_escape(&c.quantity),
            crate::fmt::num(c.constructed, 6),
            html_escape(&c.unit),
            crate::fmt::num(c.closed_form, 6),
            crate::fmt::sci(c.error)
        ));
    }
    format!(
        "<b>{}</b> {}{}{}",
        step.id,
        html_escape(&step.caption),
        step.context
            .as_ref()
            .map(|c| format!(" <i>{}</i>", html_escape(c)))
            .unwrap_or_default(),
        detail
    )
}
