//! A board that keeps the checks and not the drawing (`Setup::checks_only`, what `check`
//! and `forces` use) gives the same check table, byte for byte, as the recorded protocol, for
//! every bundled scene: the same steps numbered alike, the same situations, checks, bounds
//! and worst cuts. It keeps no step and no object.

use graphostatik::protocol::{with_setup, Board, Setup};
use graphostatik::render::{check_table_json, check_table_text};
use graphostatik::scene::AnyScene;

fn construct(path: &std::path::Path, checks_only: bool) -> Board {
    let setup = Setup {
        checks_only,
        ..Setup::default()
    };
    with_setup(setup, || {
        let scene = AnyScene::load(path).expect("bundled scenes are valid");
        scene
            .problem()
            .construct(true)
            .expect("bundled scenes construct")
    })
}

#[test]
fn every_bundled_scene_checks_alike_without_its_drawing() {
    let mut paths: Vec<_> = std::fs::read_dir("scenes")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    assert!(paths.len() > 30);
    let mut checks = 0;
    for p in &paths {
        let full = construct(p, false);
        let lean = construct(p, true);
        assert_eq!(
            check_table_text(&full),
            check_table_text(&lean),
            "{}",
            p.display()
        );
        assert_eq!(check_table_json(&full), check_table_json(&lean));
        assert_eq!(full.step_count(), lean.step_count(), "{}", p.display());
        assert_eq!(full.all_passed(), lean.all_passed());
        assert!(lean.steps().is_empty() && lean.objects().is_empty());
        assert!(lean.is_recording() && !lean.is_drawing() && full.is_drawing());
        checks += lean.checks().count();
    }
    assert!(checks > 1000, "{checks}");
}

/// A Pratt-like girder of `n` panels as scene text (a diagonal in every panel, a load at
/// every inner bottom joint).
fn girder_scene(n: usize) -> String {
    let mut joints = Vec::new();
    for i in 0..=n {
        joints.push(format!(r#"{{"name": "B{i}", "at_m": [{}, 0]}}"#, 2 * i));
        joints.push(format!(r#"{{"name": "T{i}", "at_m": [{}, 2]}}"#, 2 * i));
    }
    let mut members = Vec::new();
    let mut add = |a: String, b: String| {
        members.push(format!(
            r#"{{"name": "{}", "joints": ["{a}", "{b}"]}}"#,
            members.len() + 1
        ))
    };
    for i in 0..n {
        add(format!("B{i}"), format!("B{}", i + 1));
        add(format!("T{i}"), format!("T{}", i + 1));
        add(format!("B{i}"), format!("T{}", i + 1));
    }
    for i in 0..=n {
        add(format!("B{i}"), format!("T{i}"));
    }
    let loads: Vec<String> = (1..n)
        .map(|i| format!(r#"{{"joint": "B{i}", "kg": {}}}"#, 1000 + 100 * (i % 7)))
        .collect();
    format!(
        r#"{{"procedure": "truss", "title": "girder", "joints": [{}], "members": [{}],
            "supports": [{{"joint": "B0", "kind": "pinned"}},
                         {{"joint": "B{n}", "kind": "roller", "direction_deg": 90}}],
            "load_cases": [{{"name": "P", "loads": [{}]}}]}}"#,
        joints.join(","),
        members.join(","),
        loads.join(",")
    )
}

#[test]
fn a_truss_too_large_for_a_figure_is_checked_whole() {
    // 21,002 joints: more than a figure may have, within what a check may.
    let text = girder_scene(10_500);
    let err = AnyScene::from_json(&text, "girder.json")
        .unwrap_err()
        .to_string();
    assert!(err.contains("joints: more than 20000 joints"), "{err}");
    let setup = Setup {
        checks_only: true,
        ..Setup::default()
    };
    let board = with_setup(setup, || {
        let scene = AnyScene::from_json(&text, "girder.json").expect("a check may be this large");
        scene
            .problem()
            .construct(true)
            .expect("a determinate girder")
    });
    // Every member checked against the sparse solve, the reactions twice, the balance once.
    let members = 4 * 10_500 + 1;
    assert_eq!(
        board
            .checks()
            .filter(|c| c.quantity.starts_with("member force"))
            .count(),
        members
    );
    assert!(board.checks().count() > members);
    assert!(board.all_passed());
    assert!(board.steps().is_empty());
}
