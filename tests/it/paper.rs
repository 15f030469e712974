//! Sheets that fit a page (`render --paper`): every bundled figure set on A3 (or the paper
//! its scene names) is a page of A-series paper with its labels at least 2.5 mm high,
//! everything it draws within the page, its scale bars measuring the reduced drawing true,
//! and its PDF pages the size of its SVG pages.

use super::support::bundled_scenes;
use graphostatik::protocol::{BoardConfig, Paper};
use graphostatik::render::export::{ink_box, pdf_pages};
use graphostatik::render::paper::{on_paper, Page, MIN_LETTERING, PAPER_MARGIN};
use graphostatik::scene::AnyScene;
use std::path::PathBuf;
use std::process::Command;

/// A label's lettering on the sheet (mm): `text` in the figure's stylesheet.
const LABEL_MM: f64 = 3.5;
/// How far a measured box may pass the page's margin (mm): usvg's boxes are f32.
const BOX_SLACK: f32 = 0.01;

fn root_mm(svg: &str, name: &str) -> f64 {
    let tag = &svg[..svg.find('>').unwrap()];
    let key = format!(" {name}=\"");
    let at = tag.find(&key).unwrap() + key.len();
    let v = &tag[at..at + tag[at..].find('"').unwrap()];
    v.strip_suffix("mm").unwrap().parse().unwrap()
}

/// The scale the sheet is drawn at on the page (`scale(k)` of its layer).
fn drawn_at(svg: &str) -> f64 {
    let g = &svg[svg.find("<g id=\"paper-sheet\"").unwrap()..];
    let s = &g[g.find("scale(").unwrap() + 6..];
    s[..s.find(')').unwrap()].parse().unwrap()
}

/// The PDF's page sizes (mm), from each page's MediaBox, in order.
fn media_boxes(pdf: &[u8]) -> Vec<[f64; 2]> {
    let text = String::from_utf8_lossy(pdf);
    text.match_indices("/MediaBox [")
        .map(|(i, m)| {
            let rest = &text[i + m.len()..];
            let v: Vec<f64> = rest[..rest.find(']').unwrap()]
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            [(v[2] - v[0]) * 25.4 / 72.0, (v[3] - v[1]) * 25.4 / 72.0]
        })
        .collect()
}

/// Each force or moment scale bar of the page, as (the bar's length on paper, the quantity
/// written at its end, the quantity per mm its name states): the bar measures the reduced
/// drawing true when the length times the stated scale is the quantity.
fn bars(svg: &str, k: f64) -> Vec<(f64, f64, f64)> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let sheet = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("sheet"))
        .unwrap();
    let kids: Vec<_> = sheet.children().filter(|n| n.is_element()).collect();
    let mut out = Vec::new();
    for (i, n) in kids.iter().enumerate() {
        if n.tag_name().name() != "path" || i + 3 >= kids.len() {
            continue;
        }
        let d = n.attribute("d").unwrap();
        let xs: Vec<f64> = d
            .split(['M', 'L', ' '])
            .filter(|s| !s.is_empty())
            .take(2)
            .map(|p| p.split(',').next().unwrap().parse().unwrap())
            .collect();
        let end = kids[i + 2].text().unwrap_or("");
        let name = kids[i + 3].text().unwrap_or("");
        let Some((_, per)) = name.split_once(" 1 mm = ") else {
            continue;
        };
        let q: f64 = end.split(' ').next().unwrap().parse().unwrap();
        let f: f64 = per.split(' ').next().unwrap().parse().unwrap();
        out.push(((xs[1] - xs[0]) * k, q, f));
    }
    out
}

/// One page held to the paper: its size, its lettering, its ink, its scale bars.
fn check_page(name: &str, page: &Page) {
    let at = page.at.unwrap_or_else(|| panic!("{name}: not on paper"));
    let [pw, ph] = at.page_mm();
    let size = [root_mm(&page.svg, "width"), root_mm(&page.svg, "height")];
    assert_eq!(size, [pw, ph], "{name}: the page is not {}", at.name());
    let k = drawn_at(&page.svg);
    assert!((k - 1.0 / at.reduction).abs() < 1e-6, "{name}: {k}");
    assert!(
        LABEL_MM * k >= MIN_LETTERING - 1e-9,
        "{name}: lettering {} mm",
        LABEL_MM * k
    );
    let [x0, y0, x1, y1] = ink_box(&page.svg).unwrap();
    let m = PAPER_MARGIN as f32 - BOX_SLACK;
    assert!(
        x0 >= m && y0 >= m && x1 <= pw as f32 - m && y1 <= ph as f32 - m,
        "{name}: ink {:?} outside the margins of {pw} × {ph}",
        [x0, y0, x1, y1]
    );
    for (len, q, per_mm) in bars(&page.svg, k) {
        assert!(
            (len * per_mm - q).abs() <= 1e-4 * q,
            "{name}: a bar of {len} mm at 1 mm = {per_mm} is not {q}"
        );
    }
}

#[test]
fn every_bundled_figure_on_paper_keeps_its_lettering_and_stays_on_the_page() {
    let (mut whole, mut split) = (std::collections::BTreeMap::new(), Vec::new());
    for p in bundled_scenes() {
        let name = p.file_stem().unwrap().to_string_lossy().into_owned();
        let scene = AnyScene::load(&p).unwrap();
        let problem = scene.problem();
        let board = problem.construct(BoardConfig::DRAWING).unwrap();
        let paper = problem.paper().unwrap_or(Paper::A3);
        let set = on_paper(&problem.figure_meta(), &board, paper);
        for page in &set.pages {
            check_page(&name, page);
        }
        let at = set.pages[0].at.unwrap();
        if set.pages.len() > 1 {
            split.push(format!(
                "{name}: {} pages of {}",
                set.pages.len(),
                at.name()
            ));
            // The PDF: a page per page, each the size of its SVG.
            let svgs: Vec<&str> = set.pages.iter().map(|p| p.svg.as_str()).collect();
            let boxes = media_boxes(&pdf_pages(&svgs).unwrap());
            let sizes: Vec<[f64; 2]> = set.pages.iter().map(|p| p.at.unwrap().page_mm()).collect();
            assert_eq!(boxes.len(), sizes.len(), "{name}");
            for (b, s) in boxes.iter().zip(&sizes) {
                assert!(
                    (b[0] - s[0]).abs() < 0.01 && (b[1] - s[1]).abs() < 0.01,
                    "{name}: {b:?} {s:?}"
                );
            }
        }
        *whole.entry(at.paper.name()).or_insert(0) += usize::from(set.pages.len() == 1);
        // The pages say what was done where the figure did not go whole on A3.
        assert_eq!(
            set.said.is_some(),
            set.pages.len() > 1 || at.paper != paper,
            "{name}"
        );
    }
    // The crane bridge, 1116 × 816 mm, is split a load case to a page.
    assert!(
        split
            .iter()
            .any(|s| s.starts_with("lh_aufgabe5_crane_bridge")),
        "{split:?}"
    );
    eprintln!("on A3 or larger: {whole:?}; split: {split:?}");
}

/// A one-page PDF of a page on paper is the paper's size, as its SVG.
#[test]
fn a_one_page_pdf_is_the_size_of_its_svg_page() {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_abb22_funicular.json");
    let scene = AnyScene::load(&p).unwrap();
    let problem = scene.problem();
    let board = problem.construct(BoardConfig::DRAWING).unwrap();
    let set = on_paper(&problem.figure_meta(), &board, Paper::A4);
    assert_eq!(set.pages.len(), 1);
    let page = &set.pages[0];
    check_page("lh_abb22_funicular", page);
    let pdf = pdf_pages(&[page.svg.as_str()]).unwrap();
    let b = media_boxes(&pdf);
    let [w, h] = page.at.unwrap().page_mm();
    assert_eq!(b.len(), 1);
    assert!(
        (b[0][0] - w).abs() < 0.01 && (b[0][1] - h).abs() < 0.01,
        "{b:?}"
    );
}

fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_graphostatik"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gs-paper-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// An unknown paper, on the command line or in the scene: one line naming it, exit 2,
/// nothing written.
#[test]
fn an_unknown_paper_is_one_line_naming_the_field_and_nothing_is_written() {
    let d = tmp("bad");
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_abb22_funicular.json");
    let out = d.join("out");
    let o = Command::new(bin())
        .args(["render", "--paper", "a5", "--out"])
        .arg(&out)
        .arg(&scene)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("--paper") && err.contains("a5"), "{err}");
    assert!(!out.exists());
    let text = std::fs::read_to_string(&scene).unwrap();
    let bad = text.replacen("\"title\"", "\"paper\": \"letter\",\n  \"title\"", 1);
    let f = d.join("bad.json");
    std::fs::write(&f, bad).unwrap();
    let o = Command::new(bin())
        .args(["render", "--out"])
        .arg(&out)
        .arg(&f)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("paper") && err.contains("letter"), "{err}");
    assert!(!out.exists());
    std::fs::remove_dir_all(&d).ok();
}

/// The crane bridge on A4: a page per row of parts in name-1.svg, name-2.svg, …, one PDF of
/// as many pages each the size of its SVG, and one line saying so, naming the scene.
#[test]
fn a_figure_too_large_is_split_into_pages_and_render_says_so() {
    let d = tmp("split");
    let scene =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_aufgabe5_crane_bridge.json");
    let o = Command::new(bin())
        .args(["render", "--paper", "a4", "--format", "svg,pdf", "--out"])
        .arg(&d)
        .arg(&scene)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let said: Vec<&str> = err.lines().filter(|l| l.contains("lettering")).collect();
    assert_eq!(said.len(), 1, "{err}");
    assert!(
        said[0].contains("lh_aufgabe5_crane_bridge") && said[0].contains("pages"),
        "{err}"
    );
    let mut svgs = Vec::new();
    while let Ok(s) =
        std::fs::read_to_string(d.join(format!("lh_aufgabe5_crane_bridge-{}.svg", svgs.len() + 1)))
    {
        svgs.push(s);
    }
    assert!(svgs.len() >= 4, "{} pages", svgs.len());
    assert!(!d.join("lh_aufgabe5_crane_bridge.svg").exists());
    let pdf = std::fs::read(d.join("lh_aufgabe5_crane_bridge.pdf")).unwrap();
    let boxes = media_boxes(&pdf);
    assert_eq!(boxes.len(), svgs.len());
    for (b, s) in boxes.iter().zip(&svgs) {
        let (w, h) = (root_mm(s, "width"), root_mm(s, "height"));
        assert!(
            (b[0] - w).abs() < 0.01 && (b[1] - h).abs() < 0.01,
            "{b:?} {w} {h}"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}
