//! `graphostatik site`: a static site of scenes that runs the engine in the page, one page
//! per scene and an index with thumbnails. It opens from the file system or any static host:
//! no server, nothing fetched, the engine (WebAssembly) inlined in `engine.js`.
//!
//! Each scene's page is its walk-through (one step at a time, caption, German term, book,
//! checks, print view), drawn here for the first view, plus a live part (`page.js`): the
//! student drags a given point (a truss joint, a force's point of application or the tail of
//! its arrow, the pole, a crank pin) or moves a slider of the scene's `preview.sliders`, and
//! the engine replays the construction with the pointer ([`crate::web::replay`]).

use crate::protocol::FigureMeta;
use crate::render::{html_text, walkthrough_page, with_policy, Allow, Page, WalkOptions};
use crate::web::{build, Built, SliderLine};

/// The engine's loader (after the module's base64).
const ENGINE_JS: &str = include_str!("engine.js");
/// The live part of a scene's page.
pub const PAGE_JS: &str = include_str!("page.js");

/// A scene to put on the site: its name (the file stem: the page is `NAME.html`) and text.
#[derive(Debug, Clone)]
pub struct SiteScene {
    /// The page's name.
    pub name: String,
    /// What errors call it (its path).
    pub origin: String,
    /// The scene's JSON.
    pub text: String,
}

/// Why a site cannot be written.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SiteError {
    /// The engine is not a WebAssembly module.
    #[error("{0}")]
    Engine(String),
    /// A scene is refused: its one-line error, naming it and the field.
    #[error("{0}")]
    Scene(String),
}

/// The files of the site: `index.html`, `engine.js` (the engine `wasm`, the bytes of
/// `graphostatik_wasm.wasm`), `page.js`, and per scene `NAME.html` and `thumbs/NAME.svg`.
/// A scene that is refused stops the site with its one-line error, as `render` does.
pub fn site(scenes: &[SiteScene], wasm: &[u8]) -> Result<Vec<Page>, SiteError> {
    let engine = engine_js(wasm)?;
    let links = PageLinks {
        index: "index.html".into(),
        engine: true,
        ..Default::default()
    };
    let mut pages = Vec::new();
    let mut cards = String::new();
    for s in scenes {
        if !is_page_name(&s.name) {
            return Err(SiteError::Scene(format!(
                "{}: a page name is letters, digits, `_`, `-` and `.` (rename the file)",
                crate::fmt::clip(&s.origin, 200)
            )));
        }
        let b = build(&s.text, &s.origin).map_err(SiteError::Scene)?;
        cards.push_str(&card(&s.name, &b));
        pages.push(Page {
            name: format!("thumbs/{}.svg", s.name),
            contents: b.svg.clone(),
        });
        pages.push(Page {
            name: format!("{}.html", s.name),
            contents: scene_page(s, &b, &links),
        });
    }
    pages.push(Page {
        name: "index.html".into(),
        contents: index(&cards, scenes.len()),
    });
    pages.push(Page {
        name: "engine.js".into(),
        contents: engine,
    });
    pages.push(Page {
        name: "page.js".into(),
        contents: PAGE_JS.into(),
    });
    Ok(pages)
}

/// Whether `name` can name a page file and a link without escaping.
fn is_page_name(name: &str) -> bool {
    !name.is_empty()
        && !name.starts_with('.')
        && name.len() <= 120
        && (name.bytes()).all(|c| c.is_ascii_alphanumeric() || matches!(c, b'_' | b'-' | b'.'))
}

/// Where a scene's page finds the rest, and what it carries besides the construction: the
/// site's pages link relatively; `serve` links from its root and adds its reload script.
#[derive(Debug, Clone, Default)]
pub struct PageLinks {
    /// The index ("index.html", or "/").
    pub index: String,
    /// The prefix of `engine.js` and `page.js` ("" or "/").
    pub scripts: String,
    /// Whether the engine is there; without it the page is the walk-through alone, with a
    /// line saying how to build the engine.
    pub engine: bool,
    /// An error line shown above the figure (`serve`: the last failed edit).
    pub error: Option<String>,
    /// Scripts put inline after the page's own (`serve`: its reload script), named by their
    /// hashes in the page's Content-Security-Policy.
    pub inline_scripts: Vec<String>,
    /// Whether the page's scripts ask its own origin (`serve`'s reload poll).
    pub connect: bool,
}

/// The command that builds the engine, as the pages and errors quote it.
pub const BUILD_ENGINE: &str =
    "cargo build -p graphostatik-wasm --target wasm32-unknown-unknown --profile wasm";

/// A scene's page: the walk-through drawn now (`b`, built from `s`), the scene and its
/// handles for the live part ([`PAGE_JS`]).
pub fn scene_page(s: &SiteScene, b: &Built, links: &PageLinks) -> String {
    let mut meta = FigureMeta::titled(&b.title);
    meta.source = b.source.clone();
    let data = serde_json::json!({
        "name": s.name,
        "handles": b.handles,
    })
    .to_string();
    // The scene's own text, its key order kept, spliced in as the value of `scene`; `<`
    // occurs in JSON only inside strings, where `\u003c` means the same.
    let data = format!("{},\"scene\":{}}}", &data[..data.len() - 1], s.text.trim())
        .replace('<', "\\u003c");
    let (extra, status) = if links.engine {
        (
            format!(
                "<script type=\"application/json\" id=\"gs-data\">{data}</script>\n\
                 <script src=\"{p}engine.js\"></script>\n<script src=\"{p}page.js\"></script>\n",
                p = links.scripts
            ),
            "loading the engine…".to_string(),
        )
    } else {
        (
            String::new(),
            format!(
                "no engine: dragging and sliders need it ({})",
                html_text(BUILD_ENGINE)
            ),
        )
    };
    let controls = format!(
        "<div id=\"gs-live\"><a href=\"{index}\">all scenes</a> · \
         <span id=\"gs-summary\" class=\"{cls}\">{summary}</span> · <span id=\"gs-time\">\
         {status}</span>{save}</div>\n{sliders}",
        save = if links.engine {
            " <button id=\"gs-download\" title=\"the scene as edited, for graphostatik \
             render\">save scene</button>"
        } else {
            ""
        },
        index = html_text(&links.index),
        cls = if b.failed == 0 { "gs-pass" } else { "gs-fail" },
        summary = summary(b),
        sliders = slider_form(&b.sliders),
    );
    let page = walkthrough_page(
        &meta,
        &b.svg,
        &b.items.concat(),
        &WalkOptions {
            controls,
            extra,
            scripts: links.inline_scripts.clone(),
            error: links.error.clone(),
            details: Some(b.details.clone()),
            css: SITE_CSS.into(),
            allow: Allow {
                own_scripts: links.engine,
                wasm: links.engine,
                connect: links.connect,
            },
            ..Default::default()
        },
    );
    // The page opens on the whole construction: what the student drags.
    page.replacen("<body>", "<body data-wt-start=\"end\">", 1)
}

/// `engine.js`: the engine `wasm` (the bytes of `graphostatik_wasm.wasm`) as base64, and its
/// loader.
pub fn engine_js(wasm: &[u8]) -> Result<String, SiteError> {
    if !wasm.starts_with(b"\0asm") {
        return Err(SiteError::Engine(
            "not a WebAssembly module (it must start with \\0asm)".into(),
        ));
    }
    Ok(format!(
        "window.graphostatikWasm = \"{}\";\n{ENGINE_JS}",
        base64(wasm)
    ))
}

/// "365 steps, 112 checks: all pass".
fn summary(b: &Built) -> String {
    format!(
        "{} steps, {} checks: {}",
        b.step_count,
        b.checks.len(),
        if b.failed == 0 {
            "all pass".to_string()
        } else {
            format!("{} fail", b.failed)
        }
    )
}

/// The sliders of `preview.sliders` (moved live by the page).
fn slider_form(sliders: &[SliderLine]) -> String {
    if sliders.is_empty() {
        return String::new();
    }
    let mut f = String::from("<form id=\"wt-sliders\">");
    for (i, s) in sliders.iter().enumerate() {
        f.push_str(&format!(
            "<label>{label} <input type=\"range\" name=\"s{i}\" data-field=\"{field}\" \
             min=\"{min}\" max=\"{max}\" step=\"{step}\" value=\"{v}\"><output>{v}</output></label><br>",
            label = html_text(&s.label),
            field = html_text(&s.field),
            min = s.min,
            max = s.max,
            step = s.step,
            v = s.value,
        ));
    }
    f.push_str("</form>\n");
    f
}

/// One scene on the index: its thumbnail, title, book and what it offers.
fn card(name: &str, b: &Built) -> String {
    format!(
        "<li><a href=\"{name}.html\"><img src=\"thumbs/{name}.svg\" alt=\"\" loading=\"lazy\">\
         <span class=\"t\">{title}</span></a><span class=\"s\">{source}</span>\
         <span class=\"n\">{summary}{handles}</span></li>\n",
        title = html_text(&b.title),
        source = html_text(&b.source),
        summary = summary(b),
        handles = match (b.handles.len(), b.sliders.len()) {
            (0, 0) => String::new(),
            (h, 0) => format!(", {h} points to drag"),
            (0, s) => format!(", {s} sliders"),
            (h, s) => format!(", {h} points to drag, {s} sliders"),
        }
    )
}

/// The index of all scenes.
fn index(cards: &str, n: usize) -> String {
    let page = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>graphostatik: {n} constructions</title>\n<style>\n{INDEX_CSS}</style>\n</head>\n\
         <body>\n<header><h1>graphostatik: {n} constructions of the books</h1>\n\
         <p>Open one to follow it step by step; drag its given points and the construction \
         follows, every check beside it.</p></header>\n<ul id=\"gs-index\">\n{cards}</ul>\n\
         </body>\n</html>\n"
    );
    with_policy(page, &[], &[&format!("\n{INDEX_CSS}")], Allow::default())
}

/// What the site adds to the walk-through's style (before its `</style>`).
const SITE_CSS: &str =
    "#gs-live { padding: 0.5em; border-bottom: 1px solid #ddd; font-size: 0.9em; }
.gs-pass { color: #2a6b2a; } .gs-fail { color: #b0362a; font-weight: bold; }
#gs-download { font: inherit; margin-left: 0.5em; }
#wt-figure { touch-action: none; }
#wt-figure svg { max-height: none; }
.gs-handle { fill: rgba(176, 54, 42, 0.12); stroke: #b0362a; stroke-width: 0.35; cursor: grab; }
.gs-handle:hover { fill: rgba(176, 54, 42, 0.35); }
.gs-dragging .gs-handle { cursor: grabbing; }
@media print { .gs-handles { display: none; } }
";

/// The index's style: a grid of cards.
const INDEX_CSS: &str =
    "body { font-family: Georgia, 'DejaVu Serif', serif; margin: 0; color: #222; }
header { padding: 0.6em 1em; border-bottom: 1px solid #ccc; }
header h1 { font-size: 1.3em; margin: 0 0 0.2em; }
header p { margin: 0; color: #555; }
#gs-index { list-style: none; margin: 0; padding: 1em; display: grid; gap: 1em;
  grid-template-columns: repeat(auto-fill, minmax(15em, 1fr)); }
#gs-index li { border: 1px solid #ddd; padding: 0.5em; display: flex; flex-direction: column; }
#gs-index a { color: inherit; text-decoration: none; }
#gs-index img { width: 100%; height: 11em; object-fit: contain; background: #fff; display: block; }
#gs-index .t { display: block; font-weight: bold; margin-top: 0.3em; }
#gs-index .s, #gs-index .n { font-size: 0.85em; color: #555; }
";

/// Standard base64 (RFC 4648, with padding).
fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (u32::from(c[0]) << 16)
            | (u32::from(*c.get(1).unwrap_or(&0)) << 8)
            | u32::from(*c.get(2).unwrap_or(&0));
        for k in 0..4 {
            if k <= c.len() {
                out.push(A[(n >> (18 - 6 * k)) as usize & 63] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648() {
        for (raw, enc) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(raw.as_bytes()), enc);
        }
    }

    #[test]
    fn page_names_need_no_escaping() {
        assert!(is_page_name("lh_abb22_funicular"));
        for bad in ["", ".hidden", "a b", "a/b", "<x>", "é"] {
            assert!(!is_page_name(bad), "{bad}");
        }
    }

    #[test]
    fn a_scene_page_carries_its_scene_and_handles_and_no_raw_markup() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/scenes/lh_abb22_funicular.json"
        ))
        .unwrap()
        .replace("Funicular polygon:", "Funicular </script><b>polygon</b>:");
        let pages = site(
            &[SiteScene {
                name: "f".into(),
                origin: "f.json".into(),
                text,
            }],
            b"\0asm\x01\0\0\0",
        )
        .unwrap();
        let names: Vec<&str> = pages.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "thumbs/f.svg",
                "f.html",
                "index.html",
                "engine.js",
                "page.js"
            ]
        );
        let page = &pages[1].contents;
        // The details, the data, the walk-through's script, the engine's and the page's.
        assert_eq!(
            page.matches("</script>").count(),
            5,
            "no scene text closes a script"
        );
        let details = page.split("id=\"wt-details\">").nth(1).unwrap();
        let details: Vec<String> =
            serde_json::from_str(details.split("</script>").next().unwrap()).unwrap();
        assert_eq!(details.len(), page.matches("<li data-first=").count());
        let data = page.split("id=\"gs-data\">").nth(1).unwrap();
        let data: serde_json::Value =
            serde_json::from_str(data.split("</script>").next().unwrap()).unwrap();
        assert_eq!(data["name"], "f");
        assert_eq!(data["scene"]["forces"][1]["kg"], 600);
        assert!(data["handles"].as_array().unwrap().len() >= 8);
        assert!(pages[3]
            .contents
            .starts_with("window.graphostatikWasm = \"AGFzbQEAAAA=\";"));
    }
}
