//! The figure test: a figure reads like a book's plate when none of its labels overprints
//! another label, a point's dot or the sheet's edge, and none of its parts lies on another
//! ([`graphostatik::render::inspect`]). It holds for every bundled figure, and for figures of
//! random scenes (the bundled ones with their numbers changed, as a user varies a book's
//! example), so that a user's scene gets the same guarantee. The real font's layout of the
//! bundled figures is measured as well (`render::export`'s unit test).

use super::support::{bundled_scenes as bundled, Rng};
use graphostatik::protocol::BoardConfig;
use graphostatik::render::{inspect, FigureReport};
use graphostatik::scene::{AnyScene, ReadContext};
use serde_json::Value;

/// The figure test of a scene's text; `None` where the scene is refused or does not
/// construct (bad input, which the fuzz tests hold to one line).
fn report(text: &str, origin: &str) -> Option<FigureReport> {
    let scene = AnyScene::read(text, &ReadContext::figure(origin)).ok()?;
    let problem = scene.problem();
    let board = problem.construct(BoardConfig::DRAWING).ok()?;
    Some(inspect(&problem.figure_meta(), &board))
}

#[test]
fn every_bundled_figure_reads_like_a_plate() {
    // Every figure that misses a name of its plate, all at once: the list a figure author
    // works through.
    let mut unnamed = Vec::new();
    for p in bundled() {
        let text = std::fs::read_to_string(&p).unwrap();
        let name = p.display().to_string();
        let r = report(&text, &name).expect("a bundled scene constructs");
        if !r.unnamed.is_empty() {
            unnamed.push(format!("{name}: {:?}", r.unnamed));
            continue;
        }
        assert!(r.is_clean(), "{name}: {r:?}");
        assert!(r.left_out * 10 < r.labels.max(1), "{name}: {r:?}");
        // The names of member forces, loads and resultants (S₃, P₂, R) are written in full
        // in every plan but the crane bridge's, whose eleven Cremona plans of 96 members
        // keep only Bow's letters.
        let crowded = name.contains("crane_bridge");
        assert_eq!(r.withheld > 0, crowded, "{name}: {r:?}");
    }
    assert!(
        unnamed.is_empty(),
        "plate names not written:\n{}",
        unnamed.join("\n")
    );
}

/// The walk-through a student follows: every step of every bundled scene has its German
/// term, and a name no other step of its situation has (the caption, the objects it draws,
/// and which of several alike it is).
#[test]
fn every_step_has_its_german_term_and_a_name_of_its_own() {
    let mut steps = 0;
    for p in bundled() {
        let name = p.display().to_string();
        let scene = AnyScene::load(&p).unwrap();
        let board = scene.problem().construct(BoardConfig::DRAWING).unwrap();
        for s in board.steps() {
            assert!(
                s.term_de.is_some(),
                "{name}: step {} `{}` has no German term",
                s.id,
                s.caption
            );
        }
        let names = graphostatik::render::step_names(&board);
        let mut seen = std::collections::HashSet::new();
        for (s, n) in board.steps().iter().zip(&names) {
            assert!(n.starts_with(s.caption.as_ref()), "{name}: {n}");
            assert!(
                seen.insert((n.clone(), s.context.clone())),
                "{name}: two steps named `{n}`"
            );
        }
        steps += names.len();
    }
    assert!(steps > 15_000, "{steps} steps");
}

/// A third of the scene's numbers, each scaled by a factor of its own; whole numbers (counts,
/// firing orders, divisions) stay as they are.
fn vary(v: &mut Value, rng: &mut Rng) {
    match v {
        Value::Number(n) if n.is_f64() || n.as_u64().is_some_and(|k| k > 12) => {
            let picked = rng.next() % 3 == 0;
            let x = n.as_f64().unwrap_or(0.0) * (0.8 + 0.45 * rng.unit());
            *v = if picked { Value::from(x) } else { v.clone() };
        }
        Value::Array(a) => a.iter_mut().for_each(|x| vary(x, rng)),
        Value::Object(m) => m.values_mut().for_each(|x| vary(x, rng)),
        _ => {}
    }
}

#[test]
fn figures_of_random_scenes_read_like_plates() {
    let mut rng = Rng(0x6772_6170_686f);
    let (mut drawn, mut refused) = (0, 0);
    for p in bundled() {
        // The crane bridge's 25 load positions take most of a second each in a debug build.
        if p.to_string_lossy().contains("crane_bridge") {
            continue;
        }
        let doc: Value = serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
        for k in 0..6 {
            let mut v = doc.clone();
            vary(&mut v, &mut rng);
            // The plate's names are the book's figure's: a variant's corner may fall where
            // the book's does not (off the sheet's lettering region), so they are not held.
            v.as_object_mut().map(|m| m.remove("plate"));
            let name = format!("{} variant {k}", p.display());
            match report(&v.to_string(), &name) {
                Some(r) => {
                    assert!(r.is_clean(), "{name}: {r:?}\n{v}");
                    drawn += 1;
                }
                None => refused += 1,
            }
        }
    }
    // Most variants are scenes a user could write; the test says little if few construct.
    println!("{drawn} variants drawn, {refused} refused");
    assert!(drawn >= 3 * refused, "{drawn} drawn, {refused} refused");
}

/// The figures' label counts and emptiest regions, as README reports them:
/// `cargo test --test it figures::report -- --ignored --nocapture`.
#[test]
#[ignore = "a report"]
fn report_labels_and_emptiest_regions() {
    for p in bundled() {
        let text = std::fs::read_to_string(&p).unwrap();
        let r = report(&text, &p.display().to_string()).unwrap();
        let [w, h] = r.area_mm;
        println!(
            "{:45} {:5} labels {:3} left out {:3} withheld {:3} on heavy {:3} on thin {:3} leaders  area {:6.0} × {:6.0} mm  emptiest square {:5.0} mm ({:3.0} % of the shorter side)",
            p.file_stem().unwrap().to_string_lossy(),
            r.labels,
            r.left_out,
            r.withheld,
            r.on_heavy_lines,
            r.on_thin_lines,
            r.leaders,
            w,
            h,
            r.emptiest_mm,
            100.0 * r.emptiest_mm / w.min(h)
        );
    }
}

/// The table of the book's printed values goes where the sheet is empty: LH Abb. 52's
/// velocity curve and the pole B₁ high over the crank leave the upper left free, and the
/// table takes it without growing the sheet. The book's angles are written as it prints
/// them (79°16′), the drawn ones beside them.
#[test]
fn the_book_values_take_the_sheets_empty_room() {
    let text = std::fs::read_to_string("scenes/lh_abb52_esselborn.json").unwrap();
    let mut bare: Value = serde_json::from_str(&text).unwrap();
    bare.as_object_mut().unwrap().remove("book");
    let svg = |text: &str| {
        let scene = AnyScene::from_json(text, "lh_abb52_esselborn.json").unwrap();
        let problem = scene.problem();
        let board = problem.construct(BoardConfig::DRAWING).unwrap();
        let report = inspect(&problem.figure_meta(), &board);
        assert!(report.is_clean(), "{report:?}");
        graphostatik::render::figure(&problem.figure_meta(), &board, None)
    };
    let (with, without) = (svg(&text), svg(&bare.to_string()));
    let size = |s: &str| {
        let view = s.split("viewBox=\"").nth(1).unwrap();
        view.split('"').next().unwrap().to_string()
    };
    assert_eq!(size(&with), size(&without));
    for cell in [
        "79°16′",
        "78°41.4′",
        "100°44′",
        "another quantity",
        "reproduced",
    ] {
        assert!(with.contains(cell) && !without.contains(cell), "{cell}");
    }
}

/// A joint dragged a little keeps the drawing's scale: LH Aufgabe 4's member 5 (III–V) is
/// 16.1 mm at the book's 1 : 50, and joint V moved 2 cm up and right (member 5 then 15.6 mm)
/// neither enlarges the four trusses nor grows the sheet past a few millimetres.
#[test]
fn a_joint_dragged_a_little_keeps_the_drawings_scale() {
    let text = std::fs::read_to_string("scenes/lh_aufgabe4_shed_roof.json").unwrap();
    let sheet = |text: &str| {
        let problem = AnyScene::from_json(text, "lh_aufgabe4_shed_roof.json")
            .unwrap()
            .into_problem();
        let board = problem.construct(BoardConfig::DRAWING).unwrap();
        let svg = graphostatik::render::figure(&problem.figure_meta(), &board, None);
        assert!(
            !svg.contains("lengths 1 :"),
            "a truss drawn at a scale of its own"
        );
        let view = svg.split("viewBox=\"").nth(1).unwrap();
        let v: Vec<f64> = (view.split('"').next().unwrap().split(' '))
            .map(|x| x.parse().unwrap())
            .collect();
        (v[2], v[3])
    };
    let mut moved: Value = serde_json::from_str(&text).unwrap();
    let v = moved.pointer_mut("/joints/4/at_m").unwrap();
    assert_eq!(v, &serde_json::json!([3.34641, 0.6]), "joint V");
    *v = serde_json::json!([3.36641, 0.62]);
    let (w0, h0) = sheet(&text);
    let (w1, h1) = sheet(&moved.to_string());
    assert!(
        (w1 - w0).abs() < 20.0 && (h1 - h0).abs() < 20.0,
        "{w0}x{h0} -> {w1}x{h1}"
    );
}
