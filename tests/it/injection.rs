//! Hostile names in every text field of every bundled scene: each text a scene holds (a
//! title, a member's or joint's name, a load case, a cylinder, a support, a moving load, a
//! note) is given a payload that would open an element, close an attribute, start a script or
//! run TeX, wherever the scene still reads with it (a name and every reference to it change
//! together). The scene goes the whole way to what the engine writes: the figure (parsed as
//! XML), the walk-through and the site's page (read tag by tag as a browser tokenises HTML)
//! and TikZ. The promises: every output is well-formed; no attribute or element a payload
//! carried exists as markup (no `on…` handler, no script or style the page's author did not
//! write); each page sets a Content-Security-Policy that names every script and sheet it runs
//! by its hash and allows no inline code at large; and the payloads do reach the outputs, as
//! text (so the test cannot pass by dropping them).

use base64::Engine as _;
use graphostatik::protocol::BoardConfig;
use graphostatik::render;
use graphostatik::scene::AnyScene;
use graphostatik::site::{scene_page, PageLinks, SiteScene};
use serde_json::Value;
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;

use super::support::bundled_scenes;

/// What a hostile author types into a name: a quote that closes an attribute and adds a
/// handler, a lone quote (an ill-formed figure, before), elements and a script, an HTML
/// comment and CDATA end, TeX that reads a file, entities that must stay text.
const PAYLOADS: [&str; 6] = [
    "\" onmouseover=\"alert(1)\" x=\"",
    "'\" onload='alert(2)",
    "</title></style><script>alert(3)</script><img src=x onerror=alert(4)>",
    "]]><!-- &amp; &lt;b&gt; -->",
    "\\input{/etc/passwd}$#%_^~&{}",
    "<svg onload=alert(5)>",
];

/// Every string value of the document but the two that pick the format and the procedure and
/// the field paths of the preview's sliders (a path, not a name; only the site reads them).
fn strings(v: &Value, key: Option<&str>, out: &mut Vec<String>) {
    match v {
        Value::String(s)
            if !matches!(key, Some("procedure" | "$schema" | "field")) && !out.contains(s) =>
        {
            out.push(s.clone());
        }
        Value::Object(m) => m.iter().for_each(|(k, x)| strings(x, Some(k), out)),
        Value::Array(a) => a.iter().for_each(|x| strings(x, key, out)),
        _ => {}
    }
}

/// The document with every string in `swap` replaced by its hostile name.
fn swapped(v: &Value, swap: &BTreeMap<String, String>, key: Option<&str>) -> Value {
    match v {
        Value::String(s) if !matches!(key, Some("procedure" | "$schema" | "field")) => {
            Value::String(swap.get(s).cloned().unwrap_or_else(|| s.clone()))
        }
        Value::Object(m) => Value::Object(
            m.iter()
                .map(|(k, x)| (k.clone(), swapped(x, swap, Some(k))))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.iter().map(|x| swapped(x, swap, key)).collect()),
        x => x.clone(),
    }
}

fn reads(doc: &Value) -> bool {
    AnyScene::from_json(&doc.to_string(), "hostile.json").is_ok()
}

/// The scene with as many of its texts made hostile as it reads with, and how many.
fn hostile(doc: &Value) -> (Value, usize) {
    let mut texts = Vec::new();
    strings(doc, None, &mut texts);
    let hostile_of = |k: usize, s: &str| format!("{s}{}", PAYLOADS[k % PAYLOADS.len()]);
    // Each text alone first: an enumeration's value ("pin", "trapezoid") is refused.
    let mut swap = BTreeMap::new();
    for (k, s) in texts.iter().enumerate() {
        let one = BTreeMap::from([(s.clone(), hostile_of(k, s))]);
        if reads(&swapped(doc, &one, None)) {
            swap.insert(s.clone(), hostile_of(k, s));
        }
    }
    if !reads(&swapped(doc, &swap, None)) {
        // Two that read alone may clash together (two names made equal): one at a time.
        let all = std::mem::take(&mut swap);
        for (s, h) in all {
            swap.insert(s.clone(), h);
            if !reads(&swapped(doc, &swap, None)) {
                swap.remove(&s);
            }
        }
    }
    (swapped(doc, &swap, None), swap.len())
}

fn sha256(text: &str) -> String {
    base64::engine::general_purpose::STANDARD.encode(Sha256::digest(text.as_bytes()))
}

/// The text of an attribute value or an SVG text as the parser gives it back.
fn decode(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&amp;", "&")
}

/// The figure as XML: well-formed, no handler, no script, and every text it holds.
fn check_svg(svg: &str, what: &str) -> String {
    let doc = roxmltree::Document::parse(svg)
        .unwrap_or_else(|e| panic!("{what}: the figure is not well-formed XML: {e}"));
    let mut texts = String::new();
    for n in doc.descendants() {
        if n.is_element() {
            let name = n.tag_name().name();
            assert!(
                !matches!(name, "script" | "foreignObject" | "iframe" | "img"),
                "{what}: a <{name}> element in the figure"
            );
            for a in n.attributes() {
                assert!(
                    !a.name().to_ascii_lowercase().starts_with("on"),
                    "{what}: an attribute {}=\"{}\" in the figure",
                    a.name(),
                    a.value()
                );
                texts.push_str(a.value());
                texts.push('\n');
            }
        } else if let Some(t) = n.text() {
            texts.push_str(t);
            texts.push('\n');
        }
    }
    texts
}

/// A page read as a browser tokenises it: every start tag's attributes (no handler), every
/// script (run only if the policy names its hash: a data block or a file of the site's own
/// otherwise), every sheet likewise, the figure's inline SVG parsed as XML. Gives the page's
/// text.
fn check_page(page: &str, what: &str) -> String {
    let csp_at = page
        .find("<meta http-equiv=\"Content-Security-Policy\" content=\"")
        .unwrap_or_else(|| panic!("{what}: no Content-Security-Policy"));
    let head = &page[csp_at..];
    let csp = &head[head.find("content=\"").unwrap() + 9..];
    let csp = &csp[..csp.find('"').unwrap()];
    assert!(csp.starts_with("default-src 'none';"), "{what}: {csp}");
    assert!(
        !csp.contains("unsafe-inline") && !csp.contains("unsafe-hashes"),
        "{what}"
    );
    let allowed = |body: &str| csp.contains(&format!("'sha256-{}'", sha256(body)));
    let mut text = String::new();
    let mut rest = page;
    let mut in_svg = false;
    while let Some(lt) = rest.find('<') {
        text.push_str(&rest[..lt]);
        rest = &rest[lt..];
        if let Some(r) = rest.strip_prefix("<!--") {
            rest = &r[r.find("-->").expect("a comment ends") + 3..];
            continue;
        }
        let gt = rest
            .find('>')
            .unwrap_or_else(|| panic!("{what}: a tag never ends"));
        let tag = &rest[1..gt];
        rest = &rest[gt + 1..];
        if let Some(end) = tag.strip_prefix('/') {
            if end.trim() == "svg" {
                in_svg = false;
            }
            continue;
        }
        let name_end = tag
            .find(|c: char| c.is_ascii_whitespace() || c == '/')
            .unwrap_or(tag.len());
        let name = tag[..name_end].to_ascii_lowercase();
        let attrs = attributes(&tag[name_end..], what);
        for (k, v) in &attrs {
            assert!(
                !k.starts_with("on"),
                "{what}: an attribute {k}=\"{v}\" on a <{name}>"
            );
            text.push_str(v);
            text.push('\n');
        }
        match name.as_str() {
            "svg" if !in_svg => {
                // The figure, whole, as XML.
                let close = rest.find("</svg>").expect("the figure ends");
                let svg = format!("<{tag}>{}</svg>", &rest[..close]);
                text.push_str(&check_svg(&svg, what));
                for style in svg.split("<style>").skip(1) {
                    let body = decode(&style[..style.find("</style>").unwrap()]);
                    assert!(
                        allowed(&body),
                        "{what}: the figure's sheet is not in the policy"
                    );
                }
                rest = &rest[close + 6..];
            }
            "script" => {
                let end = rest.find("</script>").expect("a script ends");
                let body = &rest[..end];
                let src = attrs.iter().any(|(k, _)| k == "src");
                let data = attrs
                    .iter()
                    .any(|(k, v)| k == "type" && v == "application/json");
                if src {
                    assert!(
                        csp.contains("script-src 'self'"),
                        "{what}: a source not allowed"
                    );
                    let v = &attrs.iter().find(|(k, _)| k == "src").unwrap().1;
                    assert!(
                        v.ends_with("engine.js") || v.ends_with("page.js"),
                        "{what}: {v}"
                    );
                } else if data {
                    // A data block: JSON, never run.
                    serde_json::from_str::<Value>(body)
                        .unwrap_or_else(|e| panic!("{what}: a data block is not JSON: {e}"));
                    text.push_str(body);
                } else {
                    assert!(allowed(body), "{what}: a script the policy does not name");
                }
                rest = &rest[end + 9..];
            }
            "style" => {
                let end = rest.find("</style>").expect("a sheet ends");
                assert!(
                    allowed(&rest[..end]),
                    "{what}: a sheet the policy does not name"
                );
                rest = &rest[end + 8..];
            }
            "title" | "textarea" => {
                let close = format!("</{name}>");
                let end = rest.find(&close).expect("a raw text ends");
                text.push_str(&rest[..end]);
                rest = &rest[end + close.len()..];
            }
            _ => {}
        }
    }
    text
}

/// A start tag's attributes as the HTML tokeniser reads them: quoted either way or bare.
fn attributes(mut s: &str, what: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    loop {
        s = s.trim_start_matches(|c: char| c.is_ascii_whitespace() || c == '/');
        if s.is_empty() {
            return out;
        }
        let end = s
            .find(|c: char| c.is_ascii_whitespace() || c == '=' || c == '/')
            .unwrap_or(s.len());
        let key = s[..end].to_ascii_lowercase();
        s = s[end..].trim_start();
        let value = if let Some(r) = s.strip_prefix('=') {
            let r = r.trim_start();
            let (v, after) = match r.chars().next() {
                Some(q @ ('"' | '\'')) => {
                    let close = r[1..]
                        .find(q)
                        .unwrap_or_else(|| panic!("{what}: an attribute {key} never ends"));
                    (&r[1..1 + close], &r[close + 2..])
                }
                _ => {
                    let e = r.find(|c: char| c.is_ascii_whitespace()).unwrap_or(r.len());
                    (&r[..e], &r[e..])
                }
            };
            s = after;
            decode(v)
        } else {
            String::new()
        };
        out.push((key, value));
    }
}

/// What TeX reads of a line: up to its first `%` that is not escaped (a comment).
fn tex_code(line: &str) -> &str {
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'%' => return &line[..i],
            _ => i += 1,
        }
    }
    line
}

#[test]
fn hostile_names_in_every_text_field_stay_text_in_every_output() {
    let (mut scenes, mut texts) = (0, 0);
    for path in bundled_scenes() {
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let doc: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let (doc, n) = hostile(&doc);
        if n == 0 {
            continue;
        }
        let text = doc.to_string();
        let scene = AnyScene::from_json(&text, "hostile.json").unwrap();
        let problem = scene.problem();
        let Ok(board) = problem.construct(BoardConfig::DRAWING) else {
            continue;
        };
        scenes += 1;
        texts += n;
        let meta = problem.figure_meta();
        let svg = render::figure(&meta, &board, None);
        let figure_text = check_svg(&svg, &format!("{name}: figure"));
        // The title and the captions carry the names: at least one payload comes back whole.
        assert!(
            PAYLOADS.iter().any(|p| figure_text.contains(p)),
            "{name}: no payload reached the figure as text"
        );
        let walk = render::walkthrough_html(&meta, &board, &render::WalkOptions::default());
        let walk_text = check_page(&walk, &format!("{name}: walk-through"));
        assert!(PAYLOADS.iter().any(|p| walk_text.contains(p)), "{name}");
        let built = graphostatik::web::build(&text, "hostile.json").unwrap();
        let site = scene_page(
            &SiteScene {
                name: name.clone(),
                origin: "hostile.json".into(),
                text: text.clone(),
            },
            &built,
            &PageLinks {
                index: "index.html".into(),
                engine: true,
                ..Default::default()
            },
        );
        check_page(&site, &format!("{name}: site page"));
        // TeX: no payload's command reaches the picture unescaped.
        let tikz = render::export::tikz(&meta, &board).unwrap();
        for line in tikz.lines() {
            assert!(
                !tex_code(line).contains("\\input{"),
                "{name}: TeX reads a file: {line}"
            );
        }
    }
    assert!(scenes >= 40, "only {scenes} scenes took hostile names");
    assert!(texts >= 200, "only {texts} texts were made hostile");
    eprintln!("{texts} hostile texts in {scenes} scenes");
}
