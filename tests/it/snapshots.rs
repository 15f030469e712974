//! The figures and check tables of every bundled scene, each stored once: the SVG in
//! `figures/` (what the README and the docs show, and what the renderer must produce now),
//! the check table as an insta snapshot in `snapshots/`.

use graphostatik::protocol::BoardConfig;
use graphostatik::render;
use graphostatik::scene::AnyScene;
use std::path::Path;

use super::support::bundled_scenes as scenes;

fn stem(p: &Path) -> String {
    p.file_stem().unwrap().to_string_lossy().into_owned()
}

fn build(p: &Path) -> (String, String) {
    let problem = AnyScene::load(p).unwrap().into_problem();
    let board = problem.construct(BoardConfig::DRAWING).unwrap();
    (
        render::figure(&problem.figure_meta(), &board, None),
        render::check_table_text(&board),
    )
}

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.set_prepend_module_to_snapshot(false);
    s
}

#[test]
fn check_table_of_every_bundled_scene() {
    for p in scenes() {
        let (svg, table) = build(&p);
        let name = stem(&p);
        settings().bind(|| {
            insta::assert_snapshot!(format!("{name}.checks"), table);
        });
        assert!(svg.starts_with("<svg"), "{name}");
    }
}

#[test]
fn the_same_scene_gives_the_same_bytes() {
    for p in scenes() {
        assert_eq!(build(&p), build(&p));
    }
}

#[test]
fn figures_folder_is_what_the_renderer_produces_now() {
    let figs = Path::new(env!("CARGO_MANIFEST_DIR")).join("figures");
    let mut expected = Vec::new();
    for p in scenes() {
        let name = format!("{}.svg", stem(&p));
        let (svg, _) = build(&p);
        let on_disk = std::fs::read_to_string(figs.join(&name)).unwrap_or_else(|_| {
            panic!("figures/{name} is missing: run `cargo run --release -- render scenes --out figures`")
        });
        if on_disk != svg {
            let (line, (was, now)) = on_disk
                .lines()
                .zip(svg.lines())
                .enumerate()
                .find(|(_, (a, b))| a != b)
                .unwrap_or((0, ("(lengths differ)", "")));
            panic!(
                "figures/{name} differs from what the renderer draws now, first at line {}:\n\
                 was: {}\nnow: {}\nReview the change (render it, look at it as a PNG, `git diff \
                 figures/`), then: cargo run --release -- render scenes --out figures",
                line + 1,
                was.chars().take(200).collect::<String>(),
                now.chars().take(200).collect::<String>()
            );
        }
        expected.push(name);
    }
    let mut present: Vec<String> = std::fs::read_dir(&figs)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.ends_with(".svg"))
        .collect();
    present.sort();
    expected.sort();
    assert_eq!(
        present, expected,
        "figures/ holds a figure of no bundled scene"
    );
}

#[test]
fn every_layer_is_a_named_inkscape_layer() {
    for p in scenes() {
        let problem = AnyScene::load(&p).unwrap().into_problem();
        let board = problem.construct(BoardConfig::DRAWING).unwrap();
        let svg = render::figure(&problem.figure_meta(), &board, None);
        // Every attribute value after `key="`, collected once (a search per step would be
        // quadratic in the size of a large figure).
        let values = |key: &str| -> std::collections::HashSet<String> {
            svg.split(key)
                .skip(1)
                .filter_map(|rest| rest.split('"').next().map(str::to_string))
                .collect()
        };
        let ids = values("id=\"");
        let data = values("data-step=\"");
        let labels = values("inkscape:label=\"");
        // A step constructed and checked but not drawn (a hidden part) has no layer.
        let drawn = || board.steps().iter().filter(|s| !s.part.hidden);
        for s in drawn() {
            let id = s.id.to_string();
            assert!(ids.contains(&format!("step-{id}")));
            assert!(data.contains(&id));
            // As the figure writes it: escaped for an attribute.
            let mut want = format!("{id} ");
            graphostatik::fmt::markup_text(&mut want, &s.caption);
            assert!(labels.iter().any(|l| l.starts_with(&want)), "{want}");
        }
        assert_eq!(
            svg.matches("inkscape:groupmode=\"layer\"").count(),
            drawn().count() + 1
        );
        assert!(svg.contains("xmlns:inkscape="));
        // No non-finite number anywhere ("infinite" in a caption is a word, not a number).
        let bad = svg
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-'))
            .filter(|t| {
                matches!(
                    t.trim_start_matches(['M', 'L', 'C', 'A']),
                    "inf" | "-inf" | "NaN"
                )
            })
            .count();
        assert_eq!(bad, 0);
    }
}
