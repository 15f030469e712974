//! `render --format png,pdf,tikz`: the same pixels on every machine (a PNG hash snapshot, text
//! in the shipped font), a PDF with the same bytes on every run, and TikZ with one scope per step that a
//! TeX installation can read. Where `lualatex` is installed the TikZ picture is compiled; where
//! it is not, its syntax is checked here.

use graphostatik::protocol::BoardConfig;
use graphostatik::render::{self, export};
use graphostatik::scene::AnyScene;
use std::path::Path;
use std::process::Command;

fn board(
    scene: &str,
) -> (
    graphostatik::protocol::FigureMeta,
    graphostatik::protocol::Board,
) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(scene);
    let p = AnyScene::load(&path).unwrap().into_problem();
    (p.figure_meta(), p.construct(BoardConfig::DRAWING).unwrap())
}

/// FNV-1a, 64 bits: a hash that is the same on every platform and Rust version.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf29ce484222325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100000001b3)
    })
}

#[test]
fn a_png_is_the_same_pixels_on_every_machine() {
    let (meta, b) = board("lh_abb22_funicular.json");
    let svg = render::figure(&meta, &b, None);
    let png = export::png(&svg, 60.0).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    // 269 × 204 mm at 60 dpi.
    let w = u32::from_be_bytes(png[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(png[20..24].try_into().unwrap());
    assert_eq!((w, h), (636, 483));
    assert_eq!(export::png(&svg, 60.0).unwrap(), png, "deterministic");
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.set_prepend_module_to_snapshot(false);
    s.bind(|| {
        insta::assert_snapshot!(
            "lh_abb22_funicular.png_hash",
            format!("{:016x} {} bytes {w}x{h}", fnv1a(&png), png.len())
        )
    });
    // Out of range is refused with the reason, not attempted.
    assert!(export::png(&svg, 5000.0)
        .unwrap_err()
        .to_string()
        .contains("dpi"));
}

#[test]
fn a_pdf_is_the_same_bytes_on_every_run() {
    let (meta, b) = board("lh_abb22_funicular.json");
    let svg = render::figure(&meta, &b, None);
    let pdf = export::pdf(&svg).unwrap();
    assert!(pdf.starts_with(b"%PDF-"));
    let text = String::from_utf8_lossy(&pdf);
    // Text is outlined in the shipped font: no font object whose order could vary.
    assert!(!text.contains("/Type /Font"));
    assert!(text.trim_end().ends_with("%%EOF"));
    for _ in 0..8 {
        // svg2pdf would write embedded fonts in the order of a hash map.
        assert!(export::pdf(&svg).unwrap() == pdf, "deterministic");
    }
}

/// The PDF's page is the sheet, to the hundredth of a millimetre (it was 96/72 of it, so a
/// printed scale bar lied by a third), and a PNG records its resolution.
#[test]
fn exports_keep_the_sheets_true_size() {
    for name in [
        "lh_abb22_funicular.json",
        "lh_abb24_beam.json",
        "kg_abb1043_crank_rocker.json",
    ] {
        let (meta, b) = board(name);
        let svg = render::figure(&meta, &b, None);
        let mm = |key: &str| -> f64 {
            let at = svg.find(&format!(" {key}=\"")).unwrap() + key.len() + 3;
            svg[at..].split("mm\"").next().unwrap().parse().unwrap()
        };
        let (w, h) = (mm("width"), mm("height"));
        let pdf = export::pdf(&svg).unwrap();
        let text = String::from_utf8_lossy(&pdf);
        let media = text.split("/MediaBox [").nth(1).unwrap();
        let box_pt: Vec<f64> = media
            .split(']')
            .next()
            .unwrap()
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        let to_mm = 25.4 / 72.0;
        assert!(
            (box_pt[2] * to_mm - w).abs() < 0.01,
            "{name}: page {} mm, sheet {w} mm",
            box_pt[2] * to_mm
        );
        assert!(
            (box_pt[3] * to_mm - h).abs() < 0.01,
            "{name}: page {} mm, sheet {h} mm",
            box_pt[3] * to_mm
        );
        let png = export::png(&svg, 300.0).unwrap();
        let at = png
            .windows(4)
            .position(|c| c == b"pHYs")
            .expect("a pHYs chunk");
        let per_metre = u32::from_be_bytes(png[at + 4..at + 8].try_into().unwrap());
        assert_eq!(
            (per_metre, png[at + 12]),
            (11811, 1),
            "{name}: 300 dpi in pixels per metre"
        );
    }
}

/// The TikZ picture's structure: balanced braces outside comments, one scope per step in
/// step order after the sheet's, every caption a one-line comment.
fn check_tikz(tex: &str, b: &graphostatik::protocol::Board) {
    let mut depth = 0i64;
    for line in tex.lines() {
        let code = match line.find('%') {
            // A `\%` is an escaped percent sign, not a comment.
            Some(i) if i == 0 || !line[..i].ends_with('\\') => &line[..i],
            _ => line,
        };
        let mut prev = ' ';
        for c in code.chars() {
            if prev != '\\' {
                depth += i64::from(c == '{') - i64::from(c == '}');
            }
            prev = if prev == '\\' && c == '\\' { ' ' } else { c };
            assert!(depth >= 0, "unbalanced braces: {line}");
        }
    }
    assert_eq!(depth, 0, "unbalanced braces");
    let scopes: Vec<&str> = tex
        .lines()
        .filter_map(|l| l.strip_prefix("\\begin{scope} % "))
        .collect();
    let drawn: Vec<String> = b.steps().iter().map(|s| s.title()).collect();
    assert_eq!(
        scopes.len(),
        drawn.len() + 1,
        "the sheet and one scope per step"
    );
    assert_eq!(scopes[0], "000 sheet: title and scales");
    for (s, t) in scopes[1..].iter().zip(&drawn) {
        assert_eq!(*s, t.replace(['\n', '\r'], " "));
    }
    assert_eq!(
        tex.matches("\\begin{scope}").count(),
        tex.matches("\\end{scope}").count()
    );
    assert!(tex.contains("\\begin{tikzpicture}") && tex.trim_end().ends_with("\\end{tikzpicture}"));
}

#[test]
fn tikz_has_one_scope_per_step_with_its_caption() {
    let (meta, b) = board("lh_aufgabe4_shed_roof.json");
    let tex = export::tikz(&meta, &b).unwrap();
    check_tikz(&tex, &b);
    assert!(
        tex.contains("\\draw[line width=0.6mm]"),
        "result lines keep their pen"
    );
    assert!(
        tex.contains("dash pattern=on"),
        "dashed lines keep their dashes"
    );
    compile_if_tex_is_installed(&tex, "shed_roof");
}

#[test]
fn hostile_text_is_set_literally_in_every_format() {
    // (A control character in a title is refused when the scene is read: bad_input.rs.)
    let title = "<b>x</b> ]]> & 100% $a_b^c~ {x} #1 \\end{tikzpicture} second part";
    let scene = format!(
        r#"{{ "procedure": "force_system", "title": {}, "source": "a < b",
            "forces": [ {{ "at_m": [0, 0], "kg": 100, "angle_deg": 90 }},
                        {{ "at_m": [1, 0], "kg": 50, "angle_deg": 90 }} ] }}"#,
        serde_json::to_string(title).unwrap()
    );
    let p = AnyScene::from_json(&scene, "hostile.json")
        .unwrap()
        .into_problem();
    let b = p.construct(BoardConfig::DRAWING).unwrap();
    let meta = p.figure_meta();
    let svg = render::figure(&meta, &b, None);
    // usvg reads the SVG back: it is well-formed XML.
    assert!(export::png(&svg, 20.0).is_ok());
    assert!(export::pdf(&svg).is_ok());
    let tex = export::tikz(&meta, &b).unwrap();
    check_tikz(&tex, &b);
    // The title's `\\end{tikzpicture}` stays in a comment line or is escaped.
    let code: Vec<&str> = tex.lines().filter(|l| !l.starts_with('%')).collect();
    assert_eq!(
        code.iter()
            .filter(|l| l.contains("\\end{tikzpicture}"))
            .count(),
        1
    );
    assert!(tex.contains("100\\%") && tex.contains("\\$a\\_b\\textasciicircum{}c"));
    assert!(tex.lines().next().unwrap().starts_with("% <b>x</b>"));
    assert!(!tex.contains('\u{0}'));
    let html = render::walkthrough(&meta, &b).remove(0).contents;
    assert!(html.contains("&lt;b&gt;x&lt;/b&gt; ]]&gt; &amp;"));
    assert!(!html.contains('\u{0}') && !html.contains("<b>x</b>"));
}

/// Compiles a TikZ picture with `lualatex` where it and the `standalone` class are
/// installed (Unicode labels need it or XeLaTeX); says it is skipped where they are not.
fn compile_if_tex_is_installed(tex: &str, name: &str) {
    let Ok(found) = Command::new("lualatex").arg("--version").output() else {
        eprintln!("lualatex not installed: the TikZ syntax was checked without TeX");
        return;
    };
    if !found.status.success() {
        return;
    }
    // LuaLaTeX without the LaTeX extras has no `standalone` class: skipped, not failed.
    let class = Command::new("kpsewhich").arg("standalone.cls").output();
    if !class.is_ok_and(|o| o.status.success() && !o.stdout.is_empty()) {
        eprintln!("standalone.cls not installed: the TikZ syntax was checked without TeX");
        return;
    }
    let dir = std::env::temp_dir().join(format!("gs-tikz-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let doc = format!(
        "\\documentclass{{standalone}}\n\\usepackage{{tikz}}\n\\begin{{document}}\n{tex}\\end{{document}}\n"
    );
    std::fs::write(dir.join("fig.tex"), doc).unwrap();
    let o = Command::new("lualatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "fig.tex"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stdout));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn render_writes_every_format_asked_for_and_refuses_a_bad_resolution() {
    let dir = std::env::temp_dir().join(format!("gs-export-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lh_abb22_funicular.json"
    );
    let exe = env!("CARGO_BIN_EXE_graphostatik");
    let o = Command::new(exe)
        .args([
            "render",
            scene,
            "--format",
            "tikz,png,svg,pdf,png",
            "--dpi",
            "40",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    for ext in ["svg", "png", "pdf", "tikz"] {
        let f = dir.join(format!("lh_abb22_funicular.{ext}"));
        assert!(
            std::fs::metadata(&f).unwrap().len() > 1000,
            "{}",
            f.display()
        );
    }
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        4,
        "each format once"
    );
    let o = Command::new(exe)
        .args(["render", scene, "--format", "png", "--dpi", "0", "--out"])
        .arg(dir.join("none"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("--dpi") && e.lines().count() == 1, "{e}");
    assert!(!dir.join("none").exists(), "nothing written");
    std::fs::remove_dir_all(&dir).ok();
}

/// The TikZ pictures compile with LuaLaTeX, `fontspec` and the shipped DejaVu Serif, with no
/// character missing from the font (a Greek letter, a subscript) and no error: a truss with
/// its plans, a mechanism and an engine. `GRAPHOSTATIK_TEX=required` (CI) makes a missing
/// `lualatex` a failure, not a skip.
#[test]
fn tikz_compiles_with_lualatex() {
    let Ok(lualatex) = which("lualatex") else {
        assert!(
            std::env::var("GRAPHOSTATIK_TEX").as_deref() != Ok("required"),
            "lualatex is required but not installed"
        );
        eprintln!("tikz_compiles_with_lualatex: skipped (no lualatex)");
        return;
    };
    let dir = std::env::temp_dir().join(format!("gs-tikz-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let fonts = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/");
    for name in [
        "lh_aufgabe4_shed_roof",
        "kg_abb1043_crank_rocker",
        "lh_j_compound_engine",
    ] {
        let (meta, b) = board(&format!("{name}.json"));
        let tex = export::tikz(&meta, &b).unwrap();
        std::fs::write(dir.join(format!("{name}.tikz")), tex).unwrap();
        let doc = format!(
            "\\documentclass{{article}}\n\\usepackage{{tikz}}\n\\usepackage{{fontspec}}\n\
             \\setmainfont{{DejaVuSerif.ttf}}[Path={fonts}, ItalicFont=DejaVuSerif-Italic.ttf]\n\
             \\begin{{document}}\n\\input{{{name}.tikz}}\n\\end{{document}}\n"
        );
        std::fs::write(dir.join(format!("{name}.tex")), doc).unwrap();
        let o = std::process::Command::new(&lualatex)
            .args(["-interaction=nonstopmode", "-halt-on-error"])
            .arg(format!("{name}.tex"))
            .current_dir(&dir)
            .output()
            .unwrap();
        let log = std::fs::read_to_string(dir.join(format!("{name}.log"))).unwrap_or_default();
        assert!(
            o.status.success(),
            "{name}: lualatex failed:\n{}",
            tail(&log)
        );
        let missing: Vec<&str> = log
            .lines()
            .filter(|l| l.contains("Missing character"))
            .collect();
        assert!(missing.is_empty(), "{name}: {missing:?}");
        assert!(dir.join(format!("{name}.pdf")).exists());
    }
    std::fs::remove_dir_all(&dir).ok();
}

fn which(program: &str) -> Result<std::path::PathBuf, ()> {
    let path = std::env::var_os("PATH").ok_or(())?;
    std::env::split_paths(&path)
        .map(|d| d.join(program))
        .find(|p| p.is_file())
        .ok_or(())
}

fn tail(log: &str) -> String {
    let lines: Vec<&str> = log.lines().collect();
    lines[lines.len().saturating_sub(30)..].join("\n")
}
