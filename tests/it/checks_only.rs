//! A board that keeps the checks and not the drawing (`Mode::Checks`, what `check`
//! and `forces` use) gives the same check table, byte for byte, as the recorded protocol, for
//! every bundled scene: the same steps numbered alike, the same situations, checks, bounds
//! and worst cuts. It keeps no step and no object.

use graphostatik::protocol::{Board, BoardConfig, Mode};
use graphostatik::render::{check_table_json, check_table_text};
use graphostatik::scene::{AnyScene, ReadContext};

fn construct(path: &std::path::Path, checks_only: bool) -> Board {
    let config = if checks_only {
        BoardConfig::CHECKS
    } else {
        BoardConfig::DRAWING
    };
    let scene = AnyScene::load(path).expect("bundled scenes are valid");
    scene
        .problem()
        .construct(config)
        .expect("bundled scenes construct")
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
        // What is only drawn is counted, though it carries no bound on the lean board.
        assert_eq!(full.object_count(), lean.object_count(), "{}", p.display());
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
    let ctx = ReadContext::checks("girder.json", None);
    let scene = AnyScene::read(&text, &ctx).expect("a check may be this large");
    let board = scene
        .problem()
        .construct(BoardConfig::CHECKS)
        .expect("a determinate girder");
    // Every member checked against the sparse solve, the reactions twice, the balance once:
    // counted, and summed up (a row per kind) rather than kept one by one.
    let members = 4 * 10_500 + 1;
    let summary = board.check_summary().expect("more checks than are listed");
    let forces = summary
        .kinds
        .iter()
        .find(|k| k.quantity.starts_with("member force"))
        .expect("member forces are checked");
    assert_eq!(forces.count, members as u64);
    assert!(board.check_count() > members as u64);
    assert_eq!(summary.total, board.check_count());
    assert!(board.all_passed());
    assert!(board.steps().is_empty());
    assert_eq!(
        board.checks().count(),
        0,
        "no check kept whole: none failed"
    );
}

/// A checks-only board of `n` lengths checked, the lengths listed in `wrong` checked against
/// a wrong closed form.
fn lengths_checked(n: usize, wrong: &[usize], every_check: bool) -> Board {
    use graphostatik::prelude::*;
    let mut b = Board::new(BoardConfig {
        mode: Mode::Checks { every: every_check },
        ..BoardConfig::DRAWING
    });
    let note = Note::new("lengths", Topic::Custom("test"));
    let o = b.point(Point::new(0.0, 0.0), Role::Given.named("O"), note.clone());
    for i in 1..=n {
        b.set_context(|| format!("length {i}"));
        let at = Point::new(3.0 * i as f64, 4.0 * i as f64);
        let a = b.point(at, Role::Given, note.clone());
        let x = b
            .line_through(&o, &a, Role::Construction, note.clone())
            .unwrap();
        let d = b.measure(&o, &a, &x, Scale::new(1.0, "mm"), Label::NONE, note.clone());
        let off = if wrong.contains(&i) { 1.0 } else { 0.0 };
        b.check(&d, "OA", "mm", "Pythagoras", 5.0 * i as f64, || {
            5.0 * i as f64 + off
        });
        if i % 2 == 0 {
            b.check(&d, "OA again", "mm", "Pythagoras", 5.0 * i as f64, || {
                5.0 * i as f64
            });
        }
    }
    b
}

#[test]
fn a_long_check_is_summed_up_and_its_failures_listed() {
    use graphostatik::protocol::LISTED_CHECKS;
    // Exactly at the limit every check is kept and listed.
    let at = lengths_checked(667, &[], false); // 667 + 333 checks
    assert_eq!(at.check_count(), LISTED_CHECKS as u64);
    assert!(at.check_summary().is_none());
    assert_eq!(at.checks().count(), LISTED_CHECKS);
    // Past it, a row per kind and the failures.
    let b = lengths_checked(3_000, &[7, 2_999], false);
    let s = b.check_summary().expect("past the limit");
    assert_eq!((s.total, s.failed), (4_500, 2));
    assert_eq!(s.kinds.len(), 2);
    assert_eq!((s.kinds[0].count, s.kinds[0].failed), (3_000, 2));
    // The worst of the kind is the earlier of the two equal failures, in its situation.
    assert_eq!(b.context_of(s.kinds[0].worst_step), Some("length 7"));
    assert_eq!(b.checks().count(), 2);
    assert!(!b.all_passed());
    let text = check_table_text(&b);
    assert!(text.starts_with("4500 checks, more than 1000: one row per quantity"));
    assert!(text.contains("\nfailed checks\n"), "{text}");
    assert!(text.contains("length 2999"), "{text}");
    assert!(text.ends_with("4500 checks, 4498 passed, 2 failed, 0 depending on a glancing cut\n"));
    assert!(text.lines().count() < 20, "{text}");
    let json: serde_json::Value = serde_json::from_str(&check_table_json(&b)).unwrap();
    assert_eq!(json["checks"], 4_500);
    assert_eq!(json["kinds"][1]["quantity"], "OA again");
    assert_eq!(json["kinds"][1]["checks"], 1_500);
    assert_eq!(json["failures"].as_array().unwrap().len(), 2);
    assert_eq!(json["failures"][1]["context"], "length 2999");
    // Every check asked for: every row, the same count line.
    let all = lengths_checked(3_000, &[7, 2_999], true);
    assert!(all.check_summary().is_none());
    let text_all = check_table_text(&all);
    assert_eq!(text_all.lines().count(), 4_500 + 3);
    assert!(
        text_all.ends_with("4500 checks, 4498 passed, 2 failed, 0 depending on a glancing cut\n")
    );
}

/// A board, its steps and its checks may be built on one thread and read on another (a
/// library user's pool of constructions): their shared texts are counted atomically.
#[test]
fn boards_and_their_checks_cross_threads() {
    fn send_and_sync<T: Send + Sync>() {}
    send_and_sync::<Board>();
    send_and_sync::<graphostatik::protocol::Step>();
    send_and_sync::<graphostatik::protocol::Check>();
    let board = std::thread::spawn(|| {
        construct(
            std::path::Path::new("scenes/lh_aufgabe5_crane_bridge.json"),
            true,
        )
    })
    .join()
    .unwrap();
    assert!(board.check_count() > 0);
}

/// On a board that keeps only its checks the situation lives in its ledger: a naming puts
/// the caller's back, a cleared one stays cleared, and each step keeps the one it was made in.
#[test]
fn a_checks_only_board_keeps_its_situations_in_order() {
    use graphostatik::kernel::Point;
    use graphostatik::protocol::{Note, Role, StepId, Topic};
    let n = Note::new("point", Topic::Custom("test"));
    let mut b = Board::new(BoardConfig::CHECKS);
    // Steps are numbered from 1: the step just made is the count of steps.
    let made = |b: &Board| StepId(b.step_count() as u32);
    assert_eq!(b.context(), None);
    b.set_context(|| "case P".into());
    b.point(Point::new(0.0, 0.0), Role::Result, n.clone());
    let first = made(&b);
    b.naming(
        |s| s.push_str("member 1"),
        |b| b.point(Point::new(1.0, 0.0), Role::Result, n.clone()),
    );
    let named = made(&b);
    assert_eq!(b.context().as_deref(), Some("case P"));
    b.naming(|s| s.push_str("nothing made"), |_| ());
    assert_eq!(b.context().as_deref(), Some("case P"));
    b.clear_context();
    b.point(Point::new(2.0, 0.0), Role::Result, n);
    let last = made(&b);
    assert_eq!(b.context(), None);
    assert_eq!((first.0, named.0, last.0), (1, 2, 3));
    assert_eq!(b.context_of(first), Some("case P"));
    assert_eq!(b.context_of(named), Some("case P, member 1"));
    assert_eq!(b.context_of(last), None);
}
