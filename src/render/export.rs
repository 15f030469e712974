//! Exports of a figure besides SVG: PNG (resvg), PDF (svg2pdf) and TikZ for LaTeX authors.
//!
//! All three read the figure's own SVG through one usvg tree. Text is set in the DejaVu Serif
//! shipped in `assets/fonts` (regular and italic), never a system font, so a scene gives the
//! same pixels and the same PDF on every machine. The TikZ picture has one `scope` per
//! construction step, its caption as a comment, lengths in millimetres of the sheet.

use crate::protocol::{Board, FigureMeta};
use resvg::usvg;
use std::fmt::Write as _;
use std::sync::Arc;
use usvg::tiny_skia_path::PathSegment;

/// The serif the figures are set in, shipped with the project (Bitstream Vera licence,
/// `assets/fonts/LICENSE-DejaVu.txt`).
const SERIF: &[u8] = include_bytes!("../../assets/fonts/DejaVuSerif.ttf");
/// Its italic, for labels.
const SERIF_ITALIC: &[u8] = include_bytes!("../../assets/fonts/DejaVuSerif-Italic.ttf");

/// Pixels per inch of a PNG unless asked otherwise.
pub const DEFAULT_DPI: f32 = 150.0;
/// Lowest and highest resolution `png` accepts (a 10 m sheet at 1,200 dpi is already some
/// 470,000 pixels across).
pub const DPI_RANGE: (f32, f32) = (10.0, 1200.0);
/// Most pixels a PNG may have (about 400 MB of RGBA): beyond, the resolution must come down.
pub const MAX_PIXELS: u64 = 100_000_000;

/// A PNG resolution within [`DPI_RANGE`], or why not.
pub fn check_dpi(dpi: f32) -> Result<(), ExportError> {
    if (DPI_RANGE.0..=DPI_RANGE.1).contains(&dpi) {
        Ok(())
    } else {
        Err(ExportError::Size(format!(
            "{dpi} dpi: give between {} and {}",
            DPI_RANGE.0, DPI_RANGE.1
        )))
    }
}

/// Why an export failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExportError {
    /// The figure's SVG could not be read back (a bug: the renderer writes it).
    #[error("the figure could not be read for export: {0}")]
    Svg(String),
    /// The raster would be too large or the resolution is out of range.
    #[error("{0}")]
    Size(String),
    /// The PDF writer failed.
    #[error("PDF: {0}")]
    Pdf(String),
}

/// The usvg tree of an SVG with the shipped fonts and no other.
fn tree(svg: &str) -> Result<usvg::Tree, ExportError> {
    let mut db = usvg::fontdb::Database::new();
    db.load_font_data(SERIF.to_vec());
    db.load_font_data(SERIF_ITALIC.to_vec());
    db.set_serif_family("DejaVu Serif");
    db.set_sans_serif_family("DejaVu Serif");
    let opt = usvg::Options {
        font_family: "DejaVu Serif".into(),
        fontdb: Arc::new(db),
        ..Default::default()
    };
    usvg::Tree::from_str(svg, &opt).map_err(|e| ExportError::Svg(e.to_string()))
}

/// A figure as PNG at `dpi` pixels per inch of the sheet, on white.
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
/// let svg = graphostatik::render::figure(&p.figure_meta(), &board, None);
/// let png = graphostatik::render::export::png(&svg, 50.0).unwrap();
/// assert!(png.starts_with(b"\x89PNG"));
/// ```
pub fn png(svg: &str, dpi: f32) -> Result<Vec<u8>, ExportError> {
    check_dpi(dpi)?;
    let t = tree(svg)?;
    // usvg sizes the sheet in CSS pixels (96 per inch).
    let k = dpi / 96.0;
    let (w, h) = (
        (t.size().width() * k).ceil() as u32,
        (t.size().height() * k).ceil() as u32,
    );
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(ExportError::Size(format!(
            "{w} × {h} pixels at {dpi} dpi, more than {MAX_PIXELS}: lower --dpi"
        )));
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w.max(1), h.max(1))
        .ok_or_else(|| ExportError::Size(format!("{w} × {h} pixels")))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(
        &t,
        resvg::tiny_skia::Transform::from_scale(k, k),
        &mut pixmap.as_mut(),
    );
    let png = pixmap
        .encode_png()
        .map_err(|e| ExportError::Svg(e.to_string()))?;
    Ok(with_resolution(png, dpi))
}

/// `png` with its resolution recorded (a `pHYs` chunk after the header, in pixels per metre),
/// so that a program that places it sets it at the sheet's true size.
fn with_resolution(png: Vec<u8>, dpi: f32) -> Vec<u8> {
    // The signature (8 bytes) and the IHDR chunk (4 + 4 + 13 + 4) come first.
    const AFTER_IHDR: usize = 8 + 25;
    if png.len() < AFTER_IHDR || &png[12..16] != b"IHDR" {
        return png;
    }
    let per_metre = (f64::from(dpi) / 0.0254).round() as u32;
    let mut chunk = Vec::with_capacity(21);
    chunk.extend_from_slice(&9u32.to_be_bytes());
    chunk.extend_from_slice(b"pHYs");
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.extend_from_slice(&per_metre.to_be_bytes());
    chunk.push(1); // the unit: the metre
    let crc = crc32fast::hash(&chunk[4..]);
    chunk.extend_from_slice(&crc.to_be_bytes());
    let mut out = Vec::with_capacity(png.len() + chunk.len());
    out.extend_from_slice(&png[..AFTER_IHDR]);
    out.extend_from_slice(&chunk);
    out.extend_from_slice(&png[AFTER_IHDR..]);
    out
}

/// A figure as PDF, one page the size of the sheet (a 259.5 mm sheet is a 259.5 mm page, so
/// its scale bars print true), vector throughout; its text is drawn as the outlines of the
/// shipped font (so the bytes are the same on every run; the text is not selectable).
pub fn pdf(svg: &str) -> Result<Vec<u8>, ExportError> {
    let t = tree(svg)?;
    // Text as outlines of the shipped font: svg2pdf writes embedded fonts as objects in the
    // order of a hash map, so the same figure would give different bytes from run to run.
    let options = svg2pdf::ConversionOptions {
        embed_text: false,
        ..Default::default()
    };
    // usvg sizes the sheet in CSS pixels, 96 to the inch: so must the page be, or the page
    // comes out 96/72 of the sheet.
    let page = svg2pdf::PageOptions { dpi: 96.0 };
    svg2pdf::to_pdf(&t, options, page).map_err(|e| ExportError::Pdf(e.to_string()))
}

/// Pages as one PDF, each page the size of its SVG (an A4 page of 210 × 297 mm is a PDF page
/// of 595.28 × 841.89 pt), in order: a figure split into pages (`render --paper`). One page is
/// exactly what [`pdf`] writes. Each page is converted by svg2pdf as a form XObject and set
/// on its page; objects are numbered in page order, so the bytes are the same on every run.
pub fn pdf_pages(svgs: &[&str]) -> Result<Vec<u8>, ExportError> {
    use pdf_writer::{Content, Name, Pdf, Rect, Ref};
    if let [one] = svgs {
        return pdf(one);
    }
    let mut alloc = Ref::new(1);
    let (catalog, tree_ref) = (alloc.bump(), alloc.bump());
    let mut doc = Pdf::new();
    let mut kids = Vec::with_capacity(svgs.len());
    let mut chunks = Vec::with_capacity(svgs.len());
    for svg in svgs {
        let t = tree(svg)?;
        let options = svg2pdf::ConversionOptions {
            embed_text: false,
            ..Default::default()
        };
        let (chunk, root) =
            svg2pdf::to_chunk(&t, options).map_err(|e| ExportError::Pdf(e.to_string()))?;
        let mut map = std::collections::HashMap::new();
        let chunk = chunk.renumber(|old| *map.entry(old).or_insert_with(|| alloc.bump()));
        let root = map
            .get(&root)
            .copied()
            .ok_or(ExportError::Pdf("no page".into()))?;
        let (page, content) = (alloc.bump(), alloc.bump());
        // usvg's pixels, 96 to the inch, as points, 72 to the inch.
        let (w, h) = (t.size().width() * 0.75, t.size().height() * 0.75);
        let mut c = Content::new();
        c.transform([w, 0.0, 0.0, h, 0.0, 0.0])
            .x_object(Name(b"S1"));
        doc.stream(content, &c.finish());
        let mut p = doc.page(page);
        p.media_box(Rect::new(0.0, 0.0, w, h));
        p.parent(tree_ref);
        p.contents(content);
        p.resources().x_objects().pair(Name(b"S1"), root);
        drop(p);
        kids.push(page);
        chunks.push(chunk);
    }
    doc.catalog(catalog).pages(tree_ref);
    doc.pages(tree_ref).kids(kids).count(svgs.len() as i32);
    for c in &chunks {
        doc.extend(c);
    }
    Ok(doc.finish())
}

/// The box of everything a figure or page draws and writes, `[x0, y0, x1, y1]` in mm from
/// its top left corner (strokes at their width, text as the shipped font sets it): what
/// must lie within a page.
pub fn ink_box(svg: &str) -> Result<[f32; 4], ExportError> {
    // The leaves' boxes: a group's own box counts its origin in.
    fn walk(g: &usvg::Group, out: &mut [f32; 4]) {
        for node in g.children() {
            let b = match node {
                usvg::Node::Group(g) => {
                    walk(g, out);
                    continue;
                }
                usvg::Node::Path(p) => p.abs_stroke_bounding_box(),
                usvg::Node::Text(t) => t.abs_stroke_bounding_box(),
                usvg::Node::Image(i) => i.abs_bounding_box(),
            };
            *out = [
                out[0].min(b.left()),
                out[1].min(b.top()),
                out[2].max(b.right()),
                out[3].max(b.bottom()),
            ];
        }
    }
    let t = tree(svg)?;
    let mut b = [
        f32::INFINITY,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NEG_INFINITY,
    ];
    walk(t.root(), &mut b);
    Ok(b.map(|v| v * MM_PER_PX))
}

/// Millimetres of the sheet per usvg pixel (usvg works at 96 pixels per inch).
const MM_PER_PX: f32 = 25.4 / 96.0;
/// TeX points per millimetre.
const PT_PER_MM: f32 = 72.27 / 25.4;

/// A construction as a TikZ picture for LaTeX: one `scope` per step (and one for the sheet),
/// each headed by the step's caption as a comment, in step order. Lengths are millimetres of
/// the sheet (`x=1mm, y=-1mm`: SVG's y runs down). Labels keep their text (Unicode: compile
/// with LuaLaTeX or XeLaTeX and `fontspec`, in a font with Greek letters and subscripts, such
/// as the shipped DejaVu Serif; CI compiles the bundled figures so).
pub fn tikz(meta: &FigureMeta, board: &Board) -> Result<String, ExportError> {
    let svg = super::figure(meta, board, None);
    let t = tree(&svg)?;
    let mut out = String::new();
    let _ = writeln!(out, "% {}", comment(&meta.title));
    if !meta.source.is_empty() {
        let _ = writeln!(out, "% {}", comment(&meta.source));
    }
    out.push_str(
        "% Made by graphostatik: one scope per construction step. Compile with LuaLaTeX (or\n\
         % XeLaTeX): \\usepackage{tikz}, and \\usepackage{fontspec} with a font that has the\n\
         % figure's Greek letters and subscripts, e.g. \\setmainfont{DejaVu Serif}.\n\
         \\begin{tikzpicture}[x=1mm, y=-1mm, line cap=round, line join=round]\n",
    );
    layers(t.root(), board, &mut out);
    out.push_str("\\end{tikzpicture}\n");
    Ok(out)
}

/// The sheet's and the steps' layers as scopes, wherever usvg nests them (it wraps the sheet
/// in a group for the viewBox); anything outside a layer is drawn as it comes.
fn layers(g: &usvg::Group, board: &Board, out: &mut String) {
    for node in g.children() {
        let usvg::Node::Group(g) = node else {
            emit(node, out);
            continue;
        };
        let step = g
            .id()
            .strip_prefix("step-")
            .and_then(|n| n.parse::<usize>().ok());
        let title = match step {
            Some(n) => board.steps().get(n.wrapping_sub(1)).map(|s| s.title()),
            None if g.id() == "sheet" => Some("000 sheet: title and scales".into()),
            None => None,
        };
        match title {
            Some(title) => {
                let _ = writeln!(out, "\\begin{{scope}} % {}", comment(&title));
                for c in g.children() {
                    emit(c, out);
                }
                out.push_str("\\end{scope}\n");
            }
            None => layers(g, board, out),
        }
    }
}

/// One node of the tree as TikZ commands (groups recursively).
fn emit(node: &usvg::Node, out: &mut String) {
    match node {
        usvg::Node::Group(g) => {
            for c in g.children() {
                emit(c, out);
            }
        }
        usvg::Node::Path(p) if p.is_visible() => path(p, out),
        usvg::Node::Text(t) => text(t, out),
        _ => {}
    }
}

/// A number of millimetres, rounded to 0.001 mm as the SVG is (and no `-0`).
fn mm(x: f32) -> String {
    crate::fmt::num(f64::from(x), 3)
}

fn colour(p: &usvg::Paint) -> Option<String> {
    match p {
        usvg::Paint::Color(c) if (c.red, c.green, c.blue) == (0, 0, 0) => None,
        usvg::Paint::Color(c) => Some(format!(
            "{{rgb,255:red,{};green,{};blue,{}}}",
            c.red, c.green, c.blue
        )),
        _ => None,
    }
}

/// A path: `\draw` with its pen (width, dashes, colour), `\fill` where it is filled only.
fn path(p: &usvg::Path, out: &mut String) {
    let tr = p.abs_transform();
    let pt = |q: usvg::tiny_skia_path::Point| {
        let mut q = q;
        tr.map_point(&mut q);
        format!("({},{})", mm(q.x * MM_PER_PX), mm(q.y * MM_PER_PX))
    };
    let mut d = String::new();
    for seg in p.data().segments() {
        match seg {
            PathSegment::MoveTo(a) => {
                let _ = write!(d, " {}", pt(a));
            }
            PathSegment::LineTo(a) => {
                let _ = write!(d, " -- {}", pt(a));
            }
            PathSegment::QuadTo(a, b) => {
                let _ = write!(d, " .. controls {} .. {}", pt(a), pt(b));
            }
            PathSegment::CubicTo(a, b, c) => {
                let _ = write!(d, " .. controls {} and {} .. {}", pt(a), pt(b), pt(c));
            }
            PathSegment::Close => d.push_str(" -- cycle"),
        }
    }
    let mut opts: Vec<String> = Vec::new();
    let scale = tr.sx.abs().max(tr.sy.abs()) * MM_PER_PX;
    if let Some(s) = p.stroke() {
        opts.push(format!("line width={}mm", mm(s.width().get() * scale)));
        if let Some(c) = colour(s.paint()) {
            opts.push(format!("draw={c}"));
        }
        if let Some(dash) = s.dasharray() {
            let parts: Vec<String> = dash
                .chunks(2)
                .map(|c| {
                    let off = c.get(1).copied().unwrap_or(c[0]);
                    format!("on {}mm off {}mm", mm(c[0] * scale), mm(off * scale))
                })
                .collect();
            opts.push(format!("dash pattern={}", parts.join(" ")));
        }
    }
    if let Some(f) = p.fill() {
        opts.push(format!(
            "fill={}",
            colour(f.paint()).unwrap_or("black".into())
        ));
    }
    let cmd = if p.stroke().is_some() {
        "\\draw"
    } else {
        "\\path"
    };
    let _ = writeln!(out, "  {cmd}[{}]{d};", opts.join(", "));
}

/// A text: one node per chunk, anchored at its baseline as in the SVG; italic and smaller
/// shifted spans (subscripts) kept.
fn text(t: &usvg::Text, out: &mut String) {
    let tr = t.abs_transform();
    let scale = tr.sx.abs().max(tr.sy.abs()) * MM_PER_PX;
    for chunk in t.chunks() {
        let (Some(x), Some(y)) = (chunk.x(), chunk.y()) else {
            continue;
        };
        let mut q = usvg::tiny_skia_path::Point::from_xy(x, y);
        tr.map_point(&mut q);
        let anchor = match chunk.anchor() {
            usvg::TextAnchor::Start => "base west",
            usvg::TextAnchor::Middle => "base",
            usvg::TextAnchor::End => "base east",
        };
        let mut body = String::new();
        let mut size_pt = 10.0f32;
        let first_size = chunk.spans().first().map_or(0.0, |s| s.font_size().get());
        for (i, span) in chunk.spans().iter().enumerate() {
            let s = chunk
                .text()
                .get(span.start()..span.end())
                .unwrap_or_default();
            let mut piece = latex_escape(s);
            if span.font().style() != usvg::FontStyle::Normal {
                piece = format!("\\textit{{{piece}}}");
            }
            let shifted = span
                .baseline_shift()
                .iter()
                .any(|b| !matches!(b, usvg::BaselineShift::Baseline));
            // A label's index is a smaller span (F₁ is "F" and a smaller "1").
            if shifted || span.font_size().get() < 0.9 * first_size {
                piece = format!("\\textsubscript{{{piece}}}");
            }
            if i == 0 {
                size_pt = span.font_size().get() * scale * PT_PER_MM;
            }
            body.push_str(&piece);
        }
        let _ = writeln!(
            out,
            "  \\node[anchor={anchor}, inner sep=0pt, font=\\fontsize{{{}}}{{{}}}\\selectfont] at ({},{}) {{{body}}};",
            mm(size_pt),
            mm(size_pt * 1.2),
            mm(q.x * MM_PER_PX),
            mm(q.y * MM_PER_PX),
        );
    }
}

/// Text for a TeX comment: one line, no control characters.
fn comment(s: &str) -> String {
    crate::fmt::sheet_text(s)
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// Text set literally by TeX: its ten special characters escaped, control characters dropped.
pub fn latex_escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in crate::fmt::sheet_text(s).chars() {
        match c {
            '\\' => o.push_str("\\textbackslash{}"),
            '{' | '}' | '#' | '$' | '%' | '&' | '_' => {
                o.push('\\');
                o.push(c);
            }
            '^' => o.push_str("\\textasciicircum{}"),
            '~' => o.push_str("\\textasciitilde{}"),
            c if c.is_control() => o.push(' '),
            c => o.push(c),
        }
    }
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inked box of every text of a figure (`[x0, y0, x1, y1]`, mm of the sheet), as the
    /// shipped DejaVu Serif sets it through usvg's own text layout.
    fn ink_boxes(svg: &str) -> Vec<[f32; 4]> {
        fn walk(g: &usvg::Group, out: &mut Vec<[f32; 4]>) {
            for node in g.children() {
                match node {
                    usvg::Node::Group(g) => walk(g, out),
                    usvg::Node::Text(t) => {
                        // The glyphs' box in the text's own space, then the layer's
                        // translation (the flattened group does not carry it).
                        let r = t.flattened().bounding_box();
                        let r = r.transform(t.abs_transform()).expect("a finite box");
                        out.push([r.left(), r.top(), r.right(), r.bottom()]);
                    }
                    _ => {}
                }
            }
        }
        let mut out = Vec::new();
        walk(tree(svg).expect("a figure parses").root(), &mut out);
        out
    }

    /// Pairs of boxes that overlap by more than `slack` (mm) each way: sorted by their left
    /// edge and swept.
    fn overlapping(boxes: &mut [[f32; 4]], slack: f32) -> usize {
        boxes.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut n = 0;
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                if b[0] >= a[2] - slack {
                    break;
                }
                if b[1] < a[3] - slack && a[1] < b[3] - slack {
                    n += 1;
                }
            }
        }
        n
    }

    /// No lettering of a bundled figure overprints other lettering, measured with the real
    /// font through usvg (the label placer works from estimates).
    #[test]
    fn no_lettering_overprints_other_lettering() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/figures");
        let mut report = Vec::new();
        let mut paths: Vec<_> = (std::fs::read_dir(dir).unwrap())
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "svg"))
            .collect();
        paths.sort();
        for p in &paths {
            let svg = std::fs::read_to_string(p).unwrap();
            let n = overlapping(&mut ink_boxes(&svg), 0.05);
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            if n > 0 {
                report.push(format!("{name}: {n}"));
            }
        }
        assert!(report.is_empty(), "lettering overprints: {report:#?}");
    }
}
