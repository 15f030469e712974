//! Trusses (LH I B): Cremona plans against the dense joint-equilibrium solve, the book's
//! table of Aufgabe 4, hard cases, bad input, and random parallel-chord trusses.

use graphostatik::kernel::{Point, Vector};
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use graphostatik::scene::Procedure;
use graphostatik::scene::{AnyScene, TrussScene};
use graphostatik::truss::cremona::{construct_plan, construct_truss, CaseResult, TrussDrawing};
use graphostatik::truss::generate::{parallel_chord, Web};
use graphostatik::truss::matrix::{analyse, Determinacy};
use graphostatik::truss::*;
use proptest::prelude::*;

const D: TrussDrawing = TrussDrawing {
    length_scale: 50.0,
    force_scale: 20.0,
};

fn all_checks_pass(b: &Board) -> usize {
    let mut n = 0;
    for c in b.steps().iter().flat_map(|s| &s.checks) {
        assert!(
            c.passed,
            "{}: {} vs {} ({:e} > {:e})",
            c.quantity, c.constructed, c.closed_form, c.error, c.tolerance
        );
        n += 1;
    }
    n
}

fn run(t: &Truss, cases: &[LoadCase]) -> (Board, Vec<CaseResult>) {
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
    let r = construct_truss(&mut b, t, cases, &D).unwrap();
    all_checks_pass(&b);
    (b, r)
}

fn down(joint: usize, kg: f64) -> JointLoad {
    JointLoad {
        joint,
        force: Vector::new(0.0, -kg),
    }
}

fn case(loads: Vec<JointLoad>) -> Vec<LoadCase> {
    vec![LoadCase {
        name: "P".into(),
        loads,
        force_scale: None,
        drawn: true,
        book_name: None,
    }]
}

fn small(joints: &[(f64, f64)], members: &[(usize, usize)], roller_deg: f64) -> Truss {
    let (s, c) = graphostatik::kernel::angle::sin_cos_deg(roller_deg);
    Truss::new(
        joints
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| Joint {
                name: format!("K{i}").into(),
                at: Point::new(x, y),
            })
            .collect(),
        members
            .iter()
            .enumerate()
            .map(|(i, &(a, b))| Member {
                name: (i + 1).to_string().into(),
                ends: [a, b],
            })
            .collect(),
        vec![
            Support::pinned(0, "A"),
            Support::roller(1, Vector::new(c, s), "B"),
        ],
    )
}

/// A roller at joint `j` whose reaction acts at `deg` degrees, named by the joint's index.
fn roller(j: usize, deg: f64) -> Support {
    let (s, c) = graphostatik::kernel::angle::sin_cos_deg(deg);
    Support::roller(j, Vector::new(c, s), default_support_name(j))
}

fn load_scene(file: &str) -> graphostatik::scene::TrussProblem {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(file);
    let any = AnyScene::load(&path).unwrap();
    any.problem().get::<TrussScene>().unwrap().clone()
}

/// LH Aufgabe 4, table of member forces (kg, tension +). The book reads its plans at an
/// unknown force scale; a value agrees if it is within the books' 3.5 % drawing error plus
/// 25 kg (half a millimetre at 1 mm = 50 kg). The disagreements are listed: they are the
/// book's, and the test fails if one appears or goes away.
#[test]
fn aufgabe_4_against_the_book_table() {
    let p = load_scene("lh_aufgabe4_shed_roof.json");
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    // Per case: three reaction components, by moments and by the dense solve; 7 members;
    // the balance of the joints.
    assert_eq!(all_checks_pass(&b), 4 * (2 * 3 + 7 + 1));
    let book: [(&str, [f64; 7]); 4] = [
        (
            "dead load",
            [-840., 455., -1575., 1365., -595., -1925., 1680.],
        ),
        ("wind left", [100., -600., -250., -375., 0., -250., -875.]),
        (
            "wind right",
            [-530., 300., -950., 1000., -495., -950., 1200.],
        ),
        ("snow", [-460., 240., -920., 840., -420., -1160., 1020.]),
    ];
    let mut off = Vec::new();
    for (case, values) in book {
        let res = r.iter().find(|c| c.case == case).unwrap();
        for (m, want) in values.iter().enumerate() {
            let got = res.members[m].force;
            // The sign (tension or compression) must always agree.
            assert!(
                *want == 0.0 || got.signum() == want.signum(),
                "{case} {}: {got} vs {want}",
                m + 1
            );
            if (got - want).abs() > 0.035 * want.abs() + 25.0 {
                off.push(format!("{case} {}: {:.0} vs {want}", m + 1, got));
            }
        }
    }
    assert_eq!(
        off,
        [
            "dead load 3: -1483 vs -1575",
            "dead load 4: 1252 vs 1365",
            "dead load 6: -1808 vs -1925",
            "wind left 3: -214 vs -250",
            "wind left 6: -214 vs -250",
            "snow 3: -983 vs -920",
            "snow 4: 898 vs 840",
            "snow 6: -1233 vs -1160",
            "snow 7: 1095 vs 1020",
        ],
        "{off:#?}"
    );
    // The book's totals (dead load + wind right + snow; it writes "~ +1000" for member 2)
    // agree within the same drawing tolerance, though single columns do not: the errors of
    // its plans partly cancel.

    let book_total = [-1830., 1000., -3450., 3200., -1500., -4035., 3900.];
    let combo = &p.combinations[0];
    for (m, want) in book_total.iter().enumerate() {
        let got: f64 = combo.cases.iter().map(|&c| r[c].members[m].force).sum();
        assert!(
            (got - want).abs() <= 0.035 * want.abs() + 25.0,
            "total {}: {got} vs {want}",
            m + 1
        );
    }
    // The envelope (dead load always, wind from one side at a time, snow if it hurts)
    // is the book's total for every member: wind from the right is the worse side for all.
    let env = graphostatik::truss::envelope::envelope(&r, p.envelope.as_ref());
    for (m, e) in env.iter().enumerate() {
        let total = combo.force(&r, m);
        let extreme = if total > 0.0 { &e.max } else { &e.min };
        assert!(
            (extreme.0 - total).abs() < 1e-9,
            "{}: {:?} vs {total}",
            m + 1,
            extreme
        );
        assert_eq!(extreme.1, "dead load + wind right + snow");
    }
    let table = graphostatik::render::forces::markdown(&r, &p.combinations);
    assert!(
        table.contains("| 6 | 90.4 | −1808.1 |") && table.contains("−4001.7 | Druck |"),
        "{table}"
    );
    assert!(table
        .lines()
        .nth(6)
        .unwrap()
        .contains("| 5 | 28.1 | −562.9 | 0 | 0 |"));
    // The reactions the book computes: A = 925, B = 875 (dead load), A1 = 375, B1 = 625.
    let dead = &r[0];
    assert!((dead.reactions[0].force[1] - 925.0).abs() < 1e-9);
    assert!((dead.reactions[1].force[1] - 875.0).abs() < 1e-9);
    assert!((r[3].reactions[0].force[1] - 375.0).abs() < 1e-9);
}

/// LH Aufgabe 3, the slewing crane: the book's table (1 mm = 100 kg) against a geometry
/// reconstructed from that table, since the dimensions are only in Abb. 32. Five member
/// forces and G fix six numbers; with the post vertical and the base horizontal the shape has
/// five free parameters, so the fit cannot be exact. What it reaches is pinned here: every
/// value within 4 % of the book, and the two beyond the books' 3.5 % drawing error listed.
#[test]
fn aufgabe_3_crane_against_the_book_table() {
    let p = load_scene("lh_aufgabe3_slewing_crane.json");
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    // 7 members and the two reactions (G as a pin: two components), all checked, the
    // reactions both by moments and against the dense solve; and the balance of the joints.
    assert_eq!(all_checks_pass(&b), 7 + 2 * 3 + 1);
    let r = &r[0];
    let book_members: [f64; 5] = [2900.0, -7100.0, -2250.0, 3000.0, -2000.0];
    let book_mm = [29.0, 71.0, 22.5, 30.0, 20.0];
    let mut off = Vec::new();
    for (m, (&want, &mm)) in book_members.iter().zip(&book_mm).enumerate() {
        let got = r.members[m].force;
        assert_eq!(got.signum(), want.signum(), "{}: {got} vs {want}", m + 1);
        assert!(
            (got - want).abs() <= 0.04 * want.abs(),
            "{}: {got} vs {want}",
            m + 1
        );
        // The plan is drawn at the book's scale, so its lengths are the book's column.
        assert!((r.members[m].plan_mm - mm).abs() <= 0.04 * mm, "{}", m + 1);
        if (got - want).abs() > 0.035 * want.abs() {
            off.push(format!("{}: {got:.0} vs {want}", m + 1));
        }
    }
    assert_eq!(off, ["1: 2794 vs 2900", "4: 3114 vs 3000"], "{off:#?}");
    // G: the pin at III holds the crane down with the counterweight; A: the front roller.
    let (g, a) = (&r.reactions[0], &r.reactions[1]);
    assert_eq!((g.support.as_str(), a.support.as_str()), ("G", "A"));
    assert!(g.force[0].abs() < 1e-9 && g.force[1] < 0.0, "{:?}", g.force);
    assert!((g.magnitude() - 3600.0).abs() <= 0.035 * 3600.0);
    assert!((a.force[1] - 7700.0).abs() <= 0.035 * 7700.0);
    assert!((g.plan_mm - 36.0).abs() < 0.5 && (a.plan_mm - 77.0).abs() < 1.0);
    // The rope is internal: A carries Q and G exactly. The book's A is 100 kg more than
    // its own Q + G (7600), a reading error of its plan.
    assert!((a.force[1] - (4000.0 + g.magnitude())).abs() < 1e-9);
    // The tables name the reactions.
    let table = graphostatik::render::forces::markdown(std::slice::from_ref(r), &[]);
    assert!(
        table.contains("| G (III) | 36.4 | 3636.4 ∠270° | Auflager |"),
        "{table}"
    );
    assert!(
        table.contains("| A (IV) | 76.4 | 7636.4 ∠90° | Auflager |"),
        "{table}"
    );
}

#[test]
fn a_joint_with_two_members_in_line_and_no_load_has_a_zero_force_member() {
    // A triangle whose tie is split at M by a post to the apex: the post carries nothing.
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 1.0)],
        &[(0, 2), (2, 1), (0, 3), (3, 1), (2, 3)],
        90.0,
    );
    let (_, r) = run(&t, &case(vec![down(3, 1000.0)]));
    let post = &r[0].members[4];
    assert_eq!(post.force, 0.0);
    assert_eq!(post.kind(1e-9), "0");
    assert!((r[0].members[0].force - 500.0).abs() < 1e-9);
}

#[test]
fn a_load_along_a_member_goes_into_that_member_alone() {
    // Triangle I(0,0), II(2,0), III(1,1); a load at III along the rafter III → II.
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (1.0, 1.0)],
        &[(0, 2), (2, 1), (0, 1)],
        90.0,
    );
    let f = Vector::new(1.0, -1.0).normalize() * 800.0;
    let (_, r) = run(&t, &case(vec![JointLoad { joint: 2, force: f }]));
    let s = &r[0].members;
    assert!(s[0].force.abs() < 1e-9, "{}", s[0].force);
    assert!((s[1].force + 800.0).abs() < 1e-9);
}

#[test]
fn a_roller_reaction_parallel_to_a_member() {
    // The roller at II pushes along the rafter III → II.
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (1.0, 1.0)],
        &[(0, 2), (2, 1), (0, 1)],
        135.0,
    );
    let (_, r) = run(&t, &case(vec![down(2, 1000.0)]));
    let res = &r[0];
    // Moments about I: the roller's reaction R along (−1, 1)/√2 through II: 1000·1 = R·2/√2.
    let rb = res.reactions[1].force;
    assert!((rb[0].hypot(rb[1]) - 1000.0 / 2f64.sqrt()).abs() < 1e-9);
    assert!(res.plan_residual < 1e-9 * 1000.0);
}

#[test]
fn shallow_trusses_are_flagged_glancing_but_stay_exact() {
    for ratio in [0.05, 0.005] {
        let t = parallel_chord(Web::Pratt, 8, 1.0, ratio);
        let loads = (1..8).map(|i| down(i, 1000.0)).collect();
        let (b, r) = run(&t, &case(loads));
        let glancing = b
            .steps()
            .iter()
            .filter(|s| s.conditioning.is_some_and(|c| c.glancing()))
            .count();
        assert!(glancing > 0, "h/p = {ratio}");
        // Chord forces grow like 1/ratio: the plan stays in balance relative to them.
        let fmax = r[0]
            .members
            .iter()
            .map(|m| m.force.abs())
            .fold(0.0, f64::max);
        assert!(fmax > 1000.0 / ratio);
        assert!(
            r[0].plan_residual <= 1e-9 * 1000.0,
            "{}",
            r[0].plan_residual
        );
    }
}

#[test]
fn two_thousand_joints_checked_member_by_member_by_the_sparse_solve() {
    // Warren truss of 1000 panels: k = 2001 joints, above the dense solve's limit.
    let t = parallel_chord(Web::Warren, 1000, 1.0, 1.0);
    assert_eq!(t.joints.len(), 2001);
    let loads: Vec<_> = (1..1000).map(|i| down(i, 100.0)).collect();
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
    let r = construct_truss(&mut b, &t, &case(loads), &D).unwrap();
    // No rank test was made (it is a dense SVD), but the sparse solve was: every member
    // force is checked against it, as on a small truss.
    assert!(r[0].members.iter().all(|m| m.matrix.is_some()));
    let members_checked = b
        .checks()
        .filter(|c| c.quantity.starts_with("member force"))
        .collect::<Vec<_>>();
    assert_eq!(members_checked.len(), t.members.len());
    assert!(members_checked.iter().all(|c| c.passed));
    assert!(
        r[0].matrix_residual.unwrap() <= 1e-9 * 1e6,
        "{:?}",
        r[0].matrix_residual
    );
    let fmax = r[0]
        .members
        .iter()
        .map(|m| m.force.abs())
        .fold(0.0, f64::max);
    // Mid-span chord force ≈ q L² / (8 h) with q = 100 kg/m, L = 1000 m.
    assert!((fmax / (100.0 * 1e6 / 8.0) - 1.0).abs() < 0.01, "{fmax}");
    assert!(r[0].plan_residual <= 1e-9 * fmax, "{}", r[0].plan_residual);
    // The reactions are still checked, by moments: three components, all passing.
    let by_moments: Vec<_> = b
        .steps()
        .iter()
        .flat_map(|s| &s.checks)
        .filter(|c| c.quantity.contains("by moments"))
        .collect();
    assert_eq!(by_moments.len(), 3);
    assert!(by_moments.iter().all(|c| c.passed), "{by_moments:?}");
    // And the balance of every joint is a check row of its own, judged against the largest
    // force (the chord's 12.5 t, not the 100 kg loads), naming the joint that balances worst.
    let balance: Vec<_> = b
        .checks()
        .filter(|c| c.quantity.starts_with("joint balance"))
        .collect();
    assert_eq!(balance.len(), 1);
    assert!(balance[0].passed && balance[0].tolerance >= 1e-9 * fmax * 0.99);
    assert!(balance[0].quantity.contains("worst at joint "));
    assert_eq!(balance[0].constructed, r[0].plan_residual);
}

#[test]
fn the_balance_check_names_the_joint_a_wrong_force_unbalances() {
    use graphostatik::truss::matrix::{solve, worst_joint};
    let t = parallel_chord(Web::Warren, 6, 1.0, 1.0);
    let c = &case((1..6).map(|i| down(i, 100.0)).collect())[0];
    let s = solve(&t, c).unwrap();
    let (_, r0) = worst_joint(&t, c, &s.members, &s.reactions).unwrap();
    assert!(r0 < 1e-10, "{r0}");
    for m in [0, 7, t.members.len() - 1] {
        let mut f = s.members.clone();
        f[m] += 1.0;
        let (j, r) = worst_joint(&t, c, &f, &s.reactions).unwrap();
        assert!(t.members[m].ends.contains(&j), "member {m}: joint {j}");
        assert!((r - 1.0).abs() < 1e-9, "{r}");
        // A NaN force is never hidden behind a finite residual.
        f[m] = f64::NAN;
        assert!(worst_joint(&t, c, &f, &s.reactions).unwrap().1.is_nan());
    }
}

#[test]
fn mechanisms_and_over_determinate_trusses_are_named() {
    // A square panel without a diagonal: a joint can move.
    let sq = small(
        &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
        &[(0, 1), (1, 2), (2, 3), (3, 0)],
        90.0,
    );
    match analyse(&sq).determinacy {
        Determinacy::Mechanism { joint, freedoms } => {
            assert_eq!(freedoms, 1);
            assert!(joint == 2 || joint == 3);
        }
        d => panic!("{d:?}"),
    }
    // Both diagonals: one too many.
    let mut x = sq.clone();
    x.members.push(Member {
        name: "5".into(),
        ends: [0, 2],
    });
    x.members.push(Member {
        name: "6".into(),
        ends: [1, 3],
    });
    assert_eq!(analyse(&x).count_excess, 1);
    assert_eq!(
        analyse(&x).determinacy,
        Determinacy::OverDeterminate { redundant: 1 }
    );
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(100.0);
    let e = construct_truss(&mut b, &x, &case(vec![down(2, 1.0)]), &D).unwrap_err();
    assert!(e.to_string().contains("over-determinate by 1"), "{e}");
    // The right number of members but a roller whose line passes through the pin: the truss
    // can turn about the pin.
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (1.0, 1.0)],
        &[(0, 2), (2, 1), (0, 1)],
        0.0,
    );
    assert_eq!(analyse(&t).count_excess, 0);
    assert!(matches!(
        analyse(&t).determinacy,
        Determinacy::Mechanism { .. }
    ));
}

#[test]
fn bad_truss_scenes_are_named() {
    let good = r#"{ "procedure": "truss", "title": "t",
        "joints": [ { "name": "I", "at_m": [0, 0] }, { "name": "II", "at_m": [2, 0] }, { "name": "III", "at_m": [1, 1] } ],
        "members": [ { "name": "1", "joints": ["I", "III"] }, { "name": "2", "joints": ["III", "II"] }, { "name": "3", "joints": ["I", "II"] } ],
        "supports": [ { "joint": "I", "kind": "pinned" }, { "joint": "II", "kind": "roller", "direction_deg": 90 } ],
        "load_cases": [ { "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] } ] }"#;
    AnyScene::from_json(good, "s.json").unwrap();
    for (bad, field, words) in [
        (
            good.replace(r#"["I", "III"]"#, r#"["I", "IX"]"#),
            "members[0].joints[1]",
            "IX",
        ),
        (
            good.replace(r#"["I", "II"]"#, r#"["III", "I"]"#),
            "members[2]",
            "duplicates",
        ),
        (
            good.replace(r#"["I", "II"]"#, r#"["I", "I"]"#),
            "members[2].joints",
            "zero length",
        ),
        (
            good.replace("[1, 1]", "[2, 0]"),
            "joints[2]",
            "lies on joint `II`",
        ),
        (
            good.replace(r#""joint": "III", "kg""#, r#""joint": "VII", "kg""#),
            "load_cases[0].loads[0].joint",
            "VII",
        ),
        (
            good.replace(r#""direction_deg": 90"#, r#""direction_deg": 0"#),
            "joints[",
            "mechanism",
        ),
        (
            good.replace(r#", { "name": "3", "joints": ["I", "II"] }"#, ""),
            "joints[",
            "mechanism",
        ),
        (
            good.replace(r#""joint": "II", "kind""#, r#""joint": "IV", "kind""#),
            "supports[1].joint",
            "IV",
        ),
        (
            good.replace(r#", "direction_deg": 90"#, ""),
            "supports[1].direction_deg",
            "direction",
        ),
        (
            good.replace(r#""kg": 1000"#, r#""kg": 1000, "kg_xy": [1, 2]"#),
            "load_cases[0].loads[0]",
            "kg_xy",
        ),
        (
            good.replace(r#""kg": 1000"#, r#""kg": 1000, "toward": "V""#),
            "load_cases[0].loads[0]",
            "joint `V`",
        ),
        (
            good.replace(r#""kg": 1000"#, r#""kg": 1000, "toward": "III""#),
            "load_cases[0].loads[0]",
            "itself",
        ),
        (
            good.replace(
                r#""kg": 1000"#,
                r#""kg": 1000, "toward": "I", "angle_deg": 3"#,
            ),
            "load_cases[0].loads[0]",
            "toward",
        ),
        (
            good.replace(r#""kind": "pinned""#, r#""kind": "pinned", "name": "B""#),
            "supports[1].name",
            "two supports are called `B`",
        ),
        (
            good.replace(
                r#"{ "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] } ]"#,
                r#"{ "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] },
                   { "name": "P", "loads": [ { "joint": "III", "kg": 5 } ] } ]"#,
            ),
            "load_cases[1].name",
            "`P` is named twice (also by load_cases[0])",
        ),
        (
            good.replace(
                r#"{ "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] } ]"#,
                r#"{ "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] },
                   { "name": "cart at III", "loads": [ { "joint": "III", "kg": 5 } ] } ],
                   "moving_loads": [ { "name": "cart", "loads_kg": [100], "path": ["I", "III"] } ]"#,
            ),
            "moving_loads[0].name",
            "`cart at III` is named twice",
        ),
    ] {
        let e = AnyScene::from_json(&bad, "s.json").unwrap_err().to_string();
        assert!(e.contains(field) && e.contains(words), "{field}: {e}");
    }
}

#[test]
fn the_plan_alone_gives_the_same_forces() {
    let t = parallel_chord(Web::Howe, 6, 2.0, 1.5);
    let cases = case((1..6).map(|i| down(i, 500.0 + 100.0 * i as f64)).collect());
    let (_, with) = run(&t, &cases);
    let mut b = Board::new(BoardConfig::recording(false)).with_figure_size(400.0);
    let alone = construct_plan(&mut b, &t, &cases, &D).unwrap();
    for (a, w) in alone[0].members.iter().zip(&with[0].members) {
        assert_eq!(a.force, w.force);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn random_parallel_chord_trusses_agree_with_the_matrix_solve(
        web in prop_oneof![Just(Web::Warren), Just(Web::Pratt), Just(Web::Howe)],
        n in 2usize..12,
        panel in 0.5f64..4.0,
        height in 0.2f64..4.0,
        loads in proptest::collection::vec((0usize..100, 0.0f64..2000.0, 180.0f64..360.0), 1..8),
    ) {
        let t = parallel_chord(web, n, panel, height);
        let k = t.joints.len();
        let cases = case(loads.iter().map(|&(j, kg, deg)| {
            let (s, c) = graphostatik::kernel::angle::sin_cos_deg(deg);
            JointLoad { joint: j % k, force: Vector::new(kg * c, kg * s) }
        }).collect());
        let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
        let r = construct_truss(&mut b, &t, &cases, &D).unwrap();
        for c in b.steps().iter().flat_map(|s| &s.checks) {
            prop_assert!(c.passed, "{}: {} vs {}", c.quantity, c.constructed, c.closed_form);
        }
        let fmax = r[0].members.iter().map(|m| m.force.abs()).fold(1.0, f64::max);
        prop_assert!(r[0].plan_residual <= 1e-9 * fmax);
        prop_assert!(r[0].members.iter().all(|m| m.matrix.is_some()));
    }
}

#[test]
fn a_moving_load_gives_one_case_per_position_and_an_envelope() {
    let scene = r#"{ "procedure": "truss", "title": "t",
        "joints": [ { "name": "B0", "at_m": [0, 0] }, { "name": "B1", "at_m": [2, 0] }, { "name": "B2", "at_m": [4, 0] },
                    { "name": "B3", "at_m": [6, 0] }, { "name": "T1", "at_m": [2, 2] }, { "name": "T2", "at_m": [4, 2] } ],
        "members": [ { "name": "1", "joints": ["B0", "B1"] }, { "name": "2", "joints": ["B1", "B2"] },
                     { "name": "3", "joints": ["B2", "B3"] }, { "name": "4", "joints": ["B0", "T1"] },
                     { "name": "5", "joints": ["T1", "T2"] }, { "name": "6", "joints": ["T2", "B3"] },
                     { "name": "7", "joints": ["B1", "T1"] }, { "name": "8", "joints": ["B2", "T2"] },
                     { "name": "9", "joints": ["T1", "B2"] } ],
        "supports": [ { "joint": "B0", "kind": "pinned" }, { "joint": "B3", "kind": "roller", "direction_deg": 90 } ],
        "load_cases": [ { "name": "dead", "loads": [ { "joint": "B1", "kg": 500 }, { "joint": "B2", "kg": 500 } ] } ],
        "moving_loads": [ { "name": "crane", "path": ["B0", "B1", "B2", "B3"], "loads_kg": [3000, 1000] } ] }"#;
    let any = AnyScene::from_json(scene, "m.json").unwrap();
    let p = any.problem().get::<TrussScene>().unwrap().clone();
    // The train of two loads takes three positions on four joints.
    let names: Vec<_> = p.cases.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["dead", "crane at B0", "crane at B1", "crane at B2"]);
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    all_checks_pass(&b);
    let env = graphostatik::truss::envelope::envelope(&r, None);
    for (m, e) in env.iter().enumerate() {
        let max = r.iter().map(|c| c.members[m].force).fold(0.0, f64::max);
        let min = r.iter().map(|c| c.members[m].force).fold(0.0, f64::min);
        assert_eq!(e.max.0, if max > 1e-3 { max } else { 0.0 });
        assert_eq!(e.min.0, if min < -1e-3 { min } else { 0.0 });
    }
    // The bottom chord's middle member is in tension, largest with the heavy load at B1.
    assert_eq!(env[1].max.1, "crane at B1");
    for (bad, field) in [
        (
            scene.replace(r#""B3"], "loads_kg""#, r#""B9"], "loads_kg""#),
            "moving_loads[0].path[3]",
        ),
        (
            scene.replace("[3000, 1000]", "[]"),
            "moving_loads[0].loads_kg",
        ),
    ] {
        let e = AnyScene::from_json(&bad, "m.json").unwrap_err().to_string();
        assert!(e.contains(field), "{e}");
    }
}

/// LH Aufgabe 5 draws the plans of three crane positions and computes the rest (Tabelle 2):
/// a position not drawn is constructed and checked as a drawn one, leaves the figure, and
/// stands in the table of positions.
#[test]
fn positions_not_drawn_are_checked_and_tabled_but_not_drawn() {
    let scene = |drawn: &str| {
        format!(
            r#"{{ "procedure": "truss", "title": "t",
        "joints": [ {{ "name": "B0", "at_m": [0, 0] }}, {{ "name": "B1", "at_m": [2, 0] }}, {{ "name": "B2", "at_m": [4, 0] }},
                    {{ "name": "B3", "at_m": [6, 0] }}, {{ "name": "T1", "at_m": [2, 2] }}, {{ "name": "T2", "at_m": [4, 2] }} ],
        "members": [ {{ "name": "1", "joints": ["B0", "B1"] }}, {{ "name": "2", "joints": ["B1", "B2"] }},
                     {{ "name": "3", "joints": ["B2", "B3"] }}, {{ "name": "4", "joints": ["B0", "T1"] }},
                     {{ "name": "5", "joints": ["T1", "T2"] }}, {{ "name": "6", "joints": ["T2", "B3"] }},
                     {{ "name": "7", "joints": ["B1", "T1"] }}, {{ "name": "8", "joints": ["B2", "T2"] }},
                     {{ "name": "9", "joints": ["T1", "B2"] }} ],
        "supports": [ {{ "joint": "B0", "kind": "pinned" }}, {{ "joint": "B3", "kind": "roller", "direction_deg": 90 }} ],
        "moving_loads": [ {{ "name": "crane", "path": ["B0", "B1", "B2", "B3"], "loads_kg": [3000, 1000] {drawn} }} ] }}"#
        )
    };
    let build = |drawn: &str| {
        let any = AnyScene::from_json(&scene(drawn), "m.json").unwrap();
        let p = any.problem().get::<TrussScene>().unwrap().clone();
        let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
        let svg = graphostatik::render::figure(&TrussScene::figure_meta(&p), &b, None);
        (b, r, svg)
    };
    let (all, all_r, all_svg) = build("");
    let (some, some_r, svg) = build(r#", "drawn_at": ["B1"]"#);
    all_checks_pass(&some);
    // The same results and the same checks, case by case (less the two rows' headings).
    assert_eq!(all_r, some_r);
    let checks = |b: &Board| -> Vec<(String, f64)> {
        (b.steps().iter().flat_map(|s| &s.checks))
            .map(|c| (c.quantity.to_string(), c.constructed))
            .collect()
    };
    assert_eq!(checks(&all), checks(&some));
    // Two of three positions hidden; their steps make no layer and their labels are not
    // written; the table lists all three positions.
    let hidden: Vec<_> = (some.steps().iter()).filter(|s| s.part.hidden).collect();
    assert!(hidden.iter().any(|s| !s.checks.is_empty()));
    assert!(hidden
        .iter()
        .all(|s| s.context.as_deref() != Some("crane at B1")));
    for s in &hidden {
        assert!(!svg.contains(&format!("data-step=\"{:03}\"", s.id.0)));
    }
    assert!(!all_svg.contains("most loaded diagonal"));
    assert!(svg.contains("crane: every position, its most loaded diagonal and vertical"));
    for name in ["crane at B0", "crane at B1", "crane at B2"] {
        assert!(svg.contains(&format!(">{name}</text>")), "{name}");
    }
    assert!(svg.len() < all_svg.len() * 3 / 4);
    // The walk-through shows each position not drawn as one page.
    use graphostatik::render::{walkthrough_item_list, Grouping};
    let pages = walkthrough_item_list(&some, Grouping::Step);
    let shown = some.steps().len() - hidden.len();
    assert_eq!(pages.len(), shown + 2);
    let unseen: Vec<&String> = pages.iter().filter(|p| p.contains("not drawn: ")).collect();
    assert_eq!(unseen.len(), 2);
    // A position not drawn is one line in the list (its steps' numbers, how many, the
    // load case once); its steps, one line each with their checks, are its details.
    for p in unseen {
        assert_eq!(p.matches("class=\"wt-step\"").count(), 1, "{p}");
        let line = &p[..p.find("<div class=\"wt-detail\">").unwrap()];
        assert!(line.contains("<i>crane at B"), "{line}");
        assert!(!line.contains(": joint"), "{line}");
        let subs = p.matches("class=\"wt-sub\"").count();
        let checks = p.matches("<tr class=\"wt-ok\">").count();
        assert!(
            line.contains(&format!(
                "not drawn: {subs} steps constructed, {checks} checks made"
            )),
            "{line}"
        );
    }
    // The book's names of the positions stand beside theirs in the table.
    let (_, _, named) = build(r#", "drawn_at": ["B1"], "position_names": ["III", "I", "II"]"#);
    assert!(named.contains(">I (crane at B1)</text>"));
    // And the heading over the drawn position's row, as the book heads its plans.
    assert!(
        named.matches(">I (crane at B1)").count() == 2,
        "the table's row and the heading"
    );
    // A position that is none, or named twice, or a list of names that is not one a
    // position, is refused at its place.
    for (bad, field, says) in [
        (
            r#", "drawn_at": ["B3"]"#,
            "moving_loads[0].drawn_at[0]",
            "no position of `crane`",
        ),
        (
            r#", "drawn_at": ["B1", "B1"]"#,
            "moving_loads[0].drawn_at[1]",
            "named twice",
        ),
        (
            r#", "drawn_at": ["B1"], "position_names": ["I", "II"]"#,
            "moving_loads[0].position_names",
            "one name for each of the 3 positions",
        ),
    ] {
        let e = AnyScene::from_json(&scene(bad), "m.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains(field) && e.contains(says), "{e}");
    }
}

/// A parallel girder of three square panels with both diagonals in every panel (LH Abb. 19):
/// k = 8, s = 16 = 2k − 3 + 3.
fn double_diagonal_scene(mode: &str) -> String {
    crossed_girder_scene(3, mode)
}

/// A parallel girder of `n` square panels with both diagonals in every panel (members
/// 2n + n + 1 + 2i + 1 and + 2 the pair of panel i, the first rising to the right), loaded
/// at B1 and B2 in case P and at B1 in case Q.
fn crossed_girder_scene(n: usize, mode: &str) -> String {
    let mut joints = Vec::new();
    for i in 0..=n {
        joints.push(format!(r#"{{ "name": "B{i}", "at_m": [{}, 0] }}"#, 2 * i));
        joints.push(format!(r#"{{ "name": "T{i}", "at_m": [{}, 2] }}"#, 2 * i));
    }
    let mut members = Vec::new();
    let mut m = |a: String, b: String| {
        let n = members.len() + 1;
        members.push(format!(r#"{{ "name": "{n}", "joints": ["{a}", "{b}"] }}"#));
    };
    for i in 0..n {
        m(format!("B{i}"), format!("B{}", i + 1));
        m(format!("T{i}"), format!("T{}", i + 1));
    }
    for i in 0..=n {
        m(format!("B{i}"), format!("T{i}"));
    }
    // Pairs: with n = 3 members 11/12, 13/14, 15/16; the first of each rises to the right.
    let mut pairs = Vec::new();
    for i in 0..n {
        m(format!("B{i}"), format!("T{}", i + 1));
        m(format!("T{i}"), format!("B{}", i + 1));
        let first = 3 * n + 2 + 2 * i;
        pairs.push(format!(r#"["{first}", "{}"]"#, first + 1));
    }
    format!(
        r#"{{ "procedure": "truss", "title": "t", "joints": [{}], "members": [{}],
        "supports": [ {{ "joint": "B0", "kind": "pinned" }}, {{ "joint": "B{n}", "kind": "roller", "direction_deg": 90 }} ],
        "load_cases": [ {{ "name": "P", "loads": [ {{ "joint": "B1", "kg": 1000 }}, {{ "joint": "B2", "kg": 1000 }} ] }},
                        {{ "name": "Q", "loads": [ {{ "joint": "B1", "kg": 3000 }} ] }} ],
        "diagonal_pairs": [{}], "diagonal_mode": "{mode}" }}"#,
        joints.join(", "),
        members.join(", "),
        pairs.join(", ")
    )
}

#[test]
fn thousands_of_counter_diagonals_in_linear_time_with_a_short_case_name() {
    // Every pair looked up among all members, every member among all dropped, and a case
    // named by all its slack diagonals (the situation of every step): 16,000 panels took 31 s
    // and 3.6 GB. Now linear; the name lists the first 24 and the count.
    let n = if cfg!(debug_assertions) { 500 } else { 2_000 };
    let any = AnyScene::from_json(&crossed_girder_scene(n, "tension_only"), "d.json").unwrap();
    let (b, r) = TrussScene::construct(
        any.problem().get::<TrussScene>().unwrap(),
        BoardConfig::DRAWING,
    )
    .unwrap();
    all_checks_pass(&b);
    let c = &r[0];
    assert!(
        c.plan_residual < 1e-9 * 2000.0 * n as f64,
        "{}",
        c.plan_residual
    );
    let contexts: Vec<&str> = b
        .steps()
        .iter()
        .filter_map(|s| s.context.as_deref())
        .collect();
    assert!(
        contexts
            .iter()
            .any(|c| c.starts_with("P (") && c.contains(&format!(", … {n} slack)"))),
        "{:?}",
        contexts.first()
    );
    assert!(contexts.iter().all(|c| c.len() < 300));
}

fn pairs_problem(mode: &str) -> graphostatik::scene::TrussProblem {
    let any = AnyScene::from_json(&double_diagonal_scene(mode), "d.json").unwrap();
    any.problem().get::<TrussScene>().unwrap().clone()
}

#[test]
fn double_diagonals_split_into_two_systems_with_half_loads() {
    let p = pairs_problem("split_half_loads");
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    // Two sub-trusses per case, each checked against its own dense solve and for the
    // balance of its joints.
    assert_eq!(all_checks_pass(&b), 2 * 2 * (2 * 3 + 13 + 1));
    for c in &r {
        // The sum is in balance at every joint of the whole truss.
        assert!(c.plan_residual < 1e-9 * 3000.0, "{}", c.plan_residual);
    }
    // Symmetric load: in the end panels the two diagonals carry ±½ of the shear √2.
    let d = &r[0].members;
    assert!((d[10].force + d[11].force).abs() < 1e-9);
    assert!((d[10].force.abs() - 0.5 * 1000.0 * 2f64.sqrt()).abs() < 1e-9);
}

#[test]
fn tension_only_counter_diagonals_switch_until_every_working_diagonal_pulls() {
    let p = pairs_problem("tension_only");
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    all_checks_pass(&b);
    for c in &r {
        assert!(c.plan_residual < 1e-9 * 3000.0, "{}", c.plan_residual);
        for pair in [[10, 11], [12, 13], [14, 15]] {
            let (f0, f1) = (c.members[pair[0]].force, c.members[pair[1]].force);
            // One of the two is slack, the other pulls (or both are idle).
            assert!(f0 == 0.0 || f1 == 0.0, "{}: {f0} {f1}", c.case);
            assert!(f0 >= -1e-9 && f1 >= -1e-9, "{}: {f0} {f1}", c.case);
        }
    }
    // Case P: in the left panel the rising diagonal 11 would push, so 12 works.
    assert_eq!(r[0].members[10].force, 0.0);
    assert!((r[0].members[11].force - 1000.0 * 2f64.sqrt()).abs() < 1e-9);
    // The figure names the slack bars of each case.
    assert!(b.steps().iter().any(|s| s
        .context
        .as_deref()
        .is_some_and(|c| c.starts_with("P (11,"))));
}

#[test]
fn bad_diagonal_pairs_are_named() {
    let good = double_diagonal_scene("tension_only");
    for (bad, field) in [
        (
            good.replace(r#"["15", "16"]"#, r#"["15", "17"]"#),
            "diagonal_pairs[2][1]",
        ),
        (
            good.replace(r#"["15", "16"]"#, r#"["15", "11"]"#),
            "diagonal_pairs[2][1]",
        ),
        (
            good.replace(r#", "diagonal_mode": "tension_only""#, ""),
            "diagonal_mode",
        ),
        (
            good.replace(r#", ["15", "16"]"#, ""),
            "over-determinate by 1",
        ),
    ] {
        let e = AnyScene::from_json(&bad, "d.json").unwrap_err().to_string();
        assert!(e.contains(field), "{field}: {e}");
    }
}

/// LH Aufgabe 4 with the loads generated from the roof (Gl. 3-10) instead of typed in: the
/// book rounds its node loads (500 for 495, 650 for 648, 1200 for 1192, 485 for 483), so
/// they agree within 1.5 %.
#[test]
fn aufgabe_4_loads_from_the_roof_formulas() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join("lh_aufgabe4_shed_roof.json");
    let text = std::fs::read_to_string(path).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["load_cases"] = serde_json::json!([]);
    v["roof"] = serde_json::json!({
        "bay_m": 3, "truss_kg_per_m2": 50, "wind_k_kg_per_m2": 150,
        "slopes": [ { "joints": ["I", "II"], "cover_kg_per_m2": 30 },
                    { "joints": ["II", "III", "IV"], "cover_kg_per_m2": 40 } ] });
    let any = AnyScene::from_json(&v.to_string(), "roof.json").unwrap();
    let p = any.problem().get::<TrussScene>().unwrap().clone();
    let names: Vec<_> = p.cases.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["dead load", "wind left", "wind right", "snow"]);
    let total = |c: usize, j: usize| -> Vector {
        p.cases[c]
            .loads
            .iter()
            .filter(|l| l.joint == j)
            .map(|l| l.force)
            .sum()
    };
    let near = |got: f64, want: f64| (got - want).abs() <= 0.015 * want.abs();
    // Dead load at I, II, III, IV: 250, 575, 650, 325 kg.
    for (j, want) in [(0, 250.0), (1, 575.0), (2, 650.0), (3, 325.0)] {
        assert!(near(-total(0, j).y, want), "dead {j}: {}", total(0, j));
    }
    // Wind from the left: W/2 = 600 kg at I and II, normal to the 60° slope.
    for j in [0, 1] {
        let w = total(1, j);
        assert!(near(w.norm(), 600.0) && (w.y / w.x + 30f64.to_radians().tan()).abs() < 1e-6);
    }
    // Wind from the right: W′ = 485 kg per zinc panel; snow 250, 500, 250 kg.
    assert!(near(total(2, 2).norm(), 485.0));
    for (j, want) in [(1, 250.0), (2, 500.0), (3, 250.0)] {
        assert!(near(-total(3, j).y, want), "snow {j}");
    }
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    all_checks_pass(&b);
    let typed = TrussScene::construct(
        &load_scene("lh_aufgabe4_shed_roof.json"),
        BoardConfig::SILENT,
    )
    .unwrap()
    .1;
    for (g, t) in r.iter().zip(&typed) {
        for (mg, mt) in g.members.iter().zip(&t.members) {
            assert!(
                (mg.force - mt.force).abs() <= 0.015 * mt.force.abs() + 1e-6,
                "{} {}: {} vs {}",
                g.case,
                mg.member,
                mg.force,
                mt.force
            );
        }
    }
}

/// Henneberg's second step on member `m` of the triangle (u, v, x): drop u–v, put a joint w
/// inside the triangle and join it to u, v and x. The truss stays determinate and plane, but
/// w starts with three unknown members, and two such steps stall the plan of joints.
fn henneberg(t: &Truss, m: usize, x: usize) -> Truss {
    let mut t = t.clone();
    let [u, v] = t.members[m].ends;
    let c = (t.joints[u].at.coords + t.joints[v].at.coords + t.joints[x].at.coords) / 3.0;
    t.joints.push(Joint {
        name: format!("W{}", t.joints.len()).into(),
        at: Point::from(c),
    });
    let w = t.joints.len() - 1;
    t.members.remove(m);
    for e in [u, v, x] {
        let name = (t.members.len() + 100).to_string();
        t.members.push(Member {
            name: name.into(),
            ends: [w, e],
        });
    }
    t
}

/// (member, third joint) of every triangle of members.
fn triangles(t: &Truss) -> Vec<(usize, usize)> {
    let joined = |a: usize, b: usize| {
        t.members
            .iter()
            .any(|m| m.ends == [a, b] || m.ends == [b, a])
    };
    let mut out = Vec::new();
    for (mi, m) in t.members.iter().enumerate() {
        for x in 0..t.joints.len() {
            if !m.ends.contains(&x) && joined(m.ends[0], x) && joined(m.ends[1], x) {
                out.push((mi, x));
            }
        }
    }
    out
}

#[test]
fn a_stalled_plan_goes_on_by_ritters_section() {
    // Warren girder of three panels, two Henneberg steps: no joint with two unknowns is left
    // after the supports' joints.
    let t0 = parallel_chord(Web::Warren, 3, 2.0, 2.0);
    let t = henneberg(&henneberg(&t0, 4, 0), 5, 2);
    assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
    let (b, r) = run(&t, &case((1..3).map(|i| down(i, 1000.0)).collect()));
    let ritter: Vec<_> = b
        .steps()
        .iter()
        .filter(|s| s.caption.starts_with("Ritter section"))
        .collect();
    assert_eq!(ritter.len(), 1);
    // The moment point is a drawn cut of two member lines, and the step names the section.
    assert!(ritter[0].conditioning.is_some());
    assert!(ritter[0]
        .context
        .as_deref()
        .unwrap()
        .contains("Ritter section through"));
    assert!(r[0].plan_residual < 1e-9 * 1000.0);
}

#[test]
fn a_triangular_prism_is_refused_with_the_joints_named() {
    // Outer triangle joined to an inner one: every section through three members meets in a
    // corner, so neither joints nor Ritter's section start the plan. (With the inner
    // triangle placed so that the three links meet in one point, it is a mechanism, and
    // the rank test says so.)
    let t = small(
        &[
            (0.0, 0.0),
            (6.0, 0.0),
            (3.0, 5.0),
            (2.0, 1.2),
            (4.2, 1.0),
            (3.3, 3.2),
        ],
        &[
            (0, 1),
            (1, 2),
            (2, 0),
            (3, 4),
            (4, 5),
            (5, 3),
            (0, 3),
            (1, 4),
            (2, 5),
        ],
        90.0,
    );
    assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
    let e = construct_truss(&mut b, &t, &case(vec![down(2, 1000.0)]), &D).unwrap_err();
    assert!(
        e.to_string().contains("stalls") && e.to_string().contains("K0"),
        "{e}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn henneberg_trusses_are_solved_or_refused_cleanly(
        web in prop_oneof![Just(Web::Warren), Just(Web::Pratt)],
        n in 2usize..6,
        picks in proptest::collection::vec(0usize..1000, 0..3),
        height in 0.5f64..3.0,
    ) {
        let mut t = parallel_chord(web, n, 2.0, height);
        for p in picks {
            let tri = triangles(&t);
            if tri.is_empty() {
                break;
            }
            let (m, x) = tri[p % tri.len()];
            t = henneberg(&t, m, x);
        }
        prop_assume!(analyse(&t).determinacy == Determinacy::Determinate);
        let loads = case((1..n).map(|i| down(i, 1000.0)).collect());
        let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
        match construct_truss(&mut b, &t, &loads, &D) {
            Ok(r) => {
                for c in b.steps().iter().flat_map(|s| &s.checks) {
                    prop_assert!(c.passed, "{}: {} vs {}", c.quantity, c.constructed, c.closed_form);
                }
                prop_assert!(r[0].plan_residual < 1e-9 * 1000.0 * 100.0);
            }
            // The only refusal allowed: a plan that neither joints nor a section can start
            // (or a split that folded the drawing).
            Err(e) => prop_assert!(
                e.to_string().contains("stalls") || e.to_string().contains("cross"),
                "{e}"
            ),
        }
    }
}

#[test]
fn zero_force_members_are_marked_in_the_truss_drawing() {
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 1.0)],
        &[(0, 2), (2, 1), (0, 3), (3, 1), (2, 3)],
        90.0,
    );
    let (b, _) = run(&t, &case(vec![down(3, 1000.0)]));
    let marks: Vec<_> = b
        .steps()
        .iter()
        .filter(|s| s.caption == "zero-force member")
        .collect();
    assert_eq!(marks.len(), 1);
    assert_eq!(marks[0].inputs.len(), 2);
}

#[test]
fn an_empty_load_case_and_a_self_balanced_one_give_clean_plans() {
    let t = parallel_chord(Web::Pratt, 4, 2.0, 1.5);
    // Two equal and opposite horizontal pulls on the bottom chord: no reactions, the chord
    // between them in tension.
    let pull = |j: usize, x: f64| JointLoad {
        joint: j,
        force: Vector::new(x, 0.0),
    };
    let cases = vec![
        LoadCase {
            name: "nothing".into(),
            loads: vec![],
            force_scale: None,
            drawn: true,
            book_name: None,
        },
        LoadCase {
            name: "pulled".into(),
            loads: vec![pull(0, -500.0), pull(4, 500.0)],
            force_scale: None,
            drawn: true,
            book_name: None,
        },
    ];
    let (_, r) = run(&t, &cases);
    assert!(r[0].members.iter().all(|m| m.force == 0.0));
    assert!(r[0]
        .reactions
        .iter()
        .all(|v| v.force == graphostatik::kernel::Vector::zeros()));
    for m in 0..4 {
        assert!((r[1].members[m].force - 500.0).abs() < 1e-9, "{m}");
    }
    assert!(r[1].reactions.iter().all(|v| v.magnitude() < 1e-9));
}

/// LH Aufgabe 5, Tabelle 2: the support reactions of the ten crane positions, and the
/// diagonal force D = A / sin δ. The book's girder stands on a trestle that is only in
/// Tafel I; the scene takes the supports at the bottom chord (its notes say so). A and B are
/// statics of the girder alone and agree within 3.5 % of the crane's 12000 kg. D agrees
/// where the crane stands in the span (I, IV-VII); where it stands over or beyond the
/// support (II, III, VIII-X) the book sends all of A into one diagonal of its trestle, which
/// this girder does not have.
/// Tabelle 1 of Aufgabe 5, load positions I-III, for the book's members 13-35: the left half
/// of the span, panel by panel from support A (x = 0) to mid-span. The book numbers them only
/// in Tafel I; the order follows from its position I column (chord forces growing by 6000 kg a
/// panel, diagonals 8500, verticals −6000): in panel k ≥ 2 (x from 2k − 2 to 2k) top chord
/// 4k + 9, diagonal 4k + 10, bottom chord 4k + 11, vertical at x = 2k − 2 is 4k + 12; panel 1
/// is 16 top, 13 diagonal, 14 bottom, 15 the vertical over A; mid-span 33, 34, 35. Tolerance
/// 3.5 % of the crane load, as for Tabelle 2. The disagreements are listed, with their causes:
/// - II: the book keeps the first diagonals although the shear beyond the crane is negative
///   (its 18 = −800 is a flat bar in compression, against its own rule), and draws with its
///   rounded A = 11400; the tension-only plan switches them, which moves the chords' moment
///   points by a panel;
/// - III: members 13-16 at the support, where the book's trestle (only in Tafel I) carries A
///   into the girder; 33, where the book uses its rounded B = −3700 (−3818 here);
/// - the dead-load column is not compared: the book spreads 175000 kg over 25 joints, which
///   does not fit 19 panels (see the scene's notes).
fn tabelle_1_span_members(r: &[CaseResult]) {
    let force = |case: &str, name: String| -> f64 {
        let c = r.iter().find(|c| c.case == case).unwrap();
        c.members.iter().find(|m| m.member == name).unwrap().force
    };
    // The working diagonal of the pair in a panel: the one that pulls.
    let diagonal = |case: &str, k: usize| {
        force(case, (65 + 2 * k).to_string()).max(force(case, (66 + 2 * k).to_string()))
    };
    // The scene's members: top chord of panel k is 4 + k, bottom 23 + k, the vertical at
    // x = 2j is 43 + j, and the diagonals of panel k are 65 + 2k and 66 + 2k.
    let ours = |case: &str, book: usize| -> f64 {
        match book {
            13 => diagonal(case, 1),
            14 => force(case, "24".into()),
            15 => force(case, "43".into()),
            16 => force(case, "5".into()),
            33 => force(case, "10".into()),
            34 => diagonal(case, 6),
            35 => force(case, "29".into()),
            _ => {
                let (k, role) = ((book - 9) / 4, (book - 9) % 4);
                match role {
                    0 => force(case, (4 + k).to_string()),
                    1 => diagonal(case, k),
                    2 => force(case, (23 + k).to_string()),
                    _ => force(case, (43 + k - 1).to_string()),
                }
            }
        }
    };
    #[rustfmt::skip]
    let book: [(&str, &str, [f64; 23]); 3] = [
        ("I", "crane at O9", [8500., 0., -6000., -6000., -12000., 8500., 6000., -6000., -18000.,
            8500., 12000., -6000., -24000., 8500., 18000., -6000., -30000., 8500., 24000.,
            -6000., -30000., 0., 30000.]),
        ("II", "crane at O4", [7600., 0., -5400., -5400., -4800., -800., 5400., -6000., -4100.,
            800., 4800., -600., -3500., 800., 4100., -600., -2900., 800., 3500., -600., -2300.,
            800., 2900.]),
        ("III", "crane at O0", [-40000., 30000., 38500., -4000., 34400., 5800., -38500.,
            -4000., 30500., 5800., -34500., -4000., 26500., 5800., -30400., -4000., 22500.,
            5800., -26500., -4000., 18500., 5800., -22500.]),
    ];
    let mut off = Vec::new();
    for (pos, case, values) in book {
        for (i, want) in values.iter().enumerate() {
            let got = ours(case, 13 + i);
            if (got - want).abs() > 420.0 {
                off.push(format!("{pos} {}: {got:.0} vs {want}", 13 + i));
            }
        }
    }
    assert_eq!(
        off,
        [
            "II 15: -11455 vs -5400",
            "II 17: -5455 vs -4800",
            "II 18: 771 vs -800",
            "II 19: 4909 vs 5400",
            "II 21: -4909 vs -4100",
            "II 23: 4364 vs 4800",
            "II 25: -4364 vs -3500",
            "II 29: -3818 vs -2900",
            "II 33: -3273 vs -2300",
            "III 13: 5400 vs -40000",
            "III 14: -42000 vs 30000",
            "III 15: -15818 vs 38500",
            "III 16: 38182 vs -4000",
            "III 33: 19091 vs 18500",
        ],
        "{off:#?}"
    );
}

#[test]
fn aufgabe_5_table_2_reactions_and_diagonals() {
    let p = load_scene("lh_aufgabe5_crane_bridge.json");
    let (b, r) = TrussScene::construct(&p, BoardConfig::DRAWING).unwrap();
    all_checks_pass(&b);
    // (case, position, A, B, D) from Tabelle 2.
    let book = [
        ("crane at O9", "I", 6000.0, 6000.0, 8500.0),
        ("crane at O4", "II", 11400.0, 600.0, 16100.0),
        ("crane at O0", "III", 15700.0, -3700.0, 22000.0),
        ("crane at O8", "IV", 7000.0, 5000.0, 9900.0),
        ("crane at O7", "V", 8200.0, 3800.0, 11600.0),
        ("crane at O6", "VI", 9300.0, 2700.0, 13200.0),
        ("crane at O5", "VII", 10400.0, 1600.0, 14700.0),
        ("crane at O3", "VIII", 12300.0, -300.0, 17400.0),
        ("crane at O2", "IX", 13400.0, -1400.0, 19000.0),
        ("crane at O1", "X", 14800.0, -2800.0, 21000.0),
    ];
    let mut d_off = Vec::new();
    for (case, pos, a, bb, d) in book {
        let c = r.iter().find(|c| c.case == case).unwrap();
        let (ra, rb) = (c.reactions[0].force[1], c.reactions[1].force[1]);
        assert!((ra - a).abs() <= 420.0, "{pos}: A = {ra} vs {a}");
        assert!((rb - bb).abs() <= 420.0, "{pos}: B = {rb} vs {bb}");
        // The largest diagonal force (members 59 … 96 are the diagonals).
        let dmax = c.members[58..].iter().map(|m| m.force).fold(0.0, f64::max);
        if (dmax - d).abs() > 0.035 * d {
            d_off.push(pos);
        }
    }
    assert_eq!(d_off, ["II", "III", "VIII", "IX", "X"]);
    // Each plan at its own force scale (LH: "unter Berücksichtigung des jeweiligen
    // Kräftemaßstabes"): the dead load's at 500 kg per mm, the crane's at 100.
    for c in &r {
        let kg_per_mm = if c.case == "dead load" { 500.0 } else { 100.0 };
        for m in c.members.iter().filter(|m| m.force.abs() > 1.0) {
            let read = m.plan_mm * kg_per_mm;
            assert!(
                (read - m.force.abs()).abs() < 1e-6 * read,
                "{}: {m:?}",
                c.case
            );
        }
    }
    let scales = TrussScene::figure_meta(&p).scales;
    let named: Vec<&str> = scales.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        named,
        [
            "Längenmaßstab 1 : 200",
            "Kräftemaßstab 1 mm = 500 kg",
            "Kräftemaßstab 1 mm = 100 kg"
        ]
    );
    tabelle_1_span_members(&r);
    // Flat bars: no diagonal is ever in compression.
    for c in &r {
        assert!(
            c.members[58..].iter().all(|m| m.force >= -1e-9),
            "{}",
            c.case
        );
    }
}

#[test]
fn crossing_members_are_solved_by_joint_polygons_one_by_one() {
    // A square panel with both diagonals and no top: determinate (s = 5 = 2·4 − 3) but the
    // diagonals cross, so there is no plane drawing for Bow's notation.
    let t = small(
        &[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)],
        &[(0, 1), (1, 2), (0, 3), (0, 2), (1, 3)],
        90.0,
    );
    assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
    let loads = vec![
        down(2, 1000.0),
        JointLoad {
            joint: 3,
            force: Vector::new(300.0, -500.0),
        },
    ];
    let (b, r) = run(&t, &case(loads));
    assert!(b.steps().iter().any(|s| s
        .context
        .as_deref()
        .is_some_and(|c| c.contains("joint polygon"))));
    // Every member found once, each checked against the dense solve.
    let member_checks = b
        .steps()
        .iter()
        .flat_map(|s| &s.checks)
        .filter(|c| c.quantity.starts_with("member force"))
        .count();
    assert_eq!(member_checks, 5);
    assert!(r[0].plan_residual < 1e-9 * 1000.0);
}

#[test]
fn a_load_inside_the_outline_is_solved_by_joint_polygons() {
    // Henneberg's step on an inner diagonal puts the new joint inside the girder: Bow's
    // notation cannot name a load there.
    let t0 = parallel_chord(Web::Warren, 3, 2.0, 2.0);
    let inner = t0
        .members
        .iter()
        .position(|m| m.ends == [4, 1] || m.ends == [1, 4] || m.ends == [5, 1] || m.ends == [1, 5])
        .unwrap();
    let tri = triangles(&t0)
        .into_iter()
        .find(|&(m, _)| m == inner)
        .unwrap();
    let t = henneberg(&t0, tri.0, tri.1);
    let w = t.joints.len() - 1;
    let (b, r) = run(&t, &case(vec![down(w, 1000.0), down(1, 500.0)]));
    assert!(b.steps().iter().any(|s| s
        .context
        .as_deref()
        .is_some_and(|c| c.contains("joint polygon"))));
    assert!(r[0].plan_residual < 1e-9 * 1000.0);
}

#[test]
fn three_rollers_by_culmanns_line() {
    // A triangle on three rollers: vertical at I, inclined at II, horizontal at III.
    let mut t = small(
        &[(0.0, 0.0), (4.0, 0.0), (2.0, 3.0)],
        &[(0, 2), (2, 1), (0, 1)],
        90.0,
    );
    t.supports = vec![roller(0, 90.0), roller(1, 120.0), roller(2, 0.0)];
    assert_eq!(analyse(&t).determinacy, Determinacy::Determinate);
    let loads = vec![
        down(2, 1000.0),
        JointLoad {
            joint: 0,
            force: Vector::new(400.0, -200.0),
        },
    ];
    let (b, r) = run(&t, &case(loads));
    // Three reactions read along their lines and checked by moments about the meeting point
    // of the other two lines and by the dense solve; Culmann's line drawn.
    let roller_checks = b
        .steps()
        .iter()
        .flat_map(|s| &s.checks)
        .filter(|c| c.quantity.starts_with("roller reaction"))
        .count();
    assert_eq!(roller_checks, 6);
    assert!(b.steps().iter().any(|s| s.caption.starts_with("Culmann")));
    assert!(r[0].plan_residual < 1e-9 * 1000.0);
    // A couple on three rollers has no resultant to cut: a clear refusal.
    let couple = vec![
        JointLoad {
            joint: 0,
            force: Vector::new(0.0, 500.0),
        },
        JointLoad {
            joint: 1,
            force: Vector::new(0.0, -500.0),
        },
    ];
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
    let e = construct_truss(&mut b, &t, &case(couple), &D).unwrap_err();
    assert!(e.to_string().contains("couple"), "{e}");
}

/// The reactions by moments (LH C.2) agree with the dense solve for three rollers of which
/// two are parallel (moments are then taken as forces across them), for a roller at an
/// angle, and are refused (`None`) for a roller whose line passes through the pin.
#[test]
fn reactions_by_moments_agree_with_the_dense_solve() {
    use graphostatik::truss::matrix::solve;
    use graphostatik::truss::reactions::by_moments;
    let mut t = small(
        &[(0.0, 0.0), (4.0, 0.0), (2.0, 3.0)],
        &[(0, 2), (2, 1), (0, 1)],
        90.0,
    );
    let loads = vec![
        JointLoad {
            joint: 2,
            force: Vector::new(300.0, -900.0),
        },
        down(1, 250.0),
    ];
    let lc = LoadCase {
        name: "P".into(),
        loads: loads.clone(),
        force_scale: None,
        drawn: true,
        book_name: None,
    };
    let cases: [Vec<Support>; 2] = [
        // Vertical at I and II (parallel), horizontal at III.
        vec![roller(0, 90.0), roller(1, 90.0), roller(2, 0.0)],
        // Pin at I, roller at 120° at II.
        vec![Support::pinned(0, "A"), roller(1, 120.0)],
    ];
    for supports in cases {
        t.supports = supports;
        let m = by_moments(&t, &loads).unwrap();
        let sol = solve(&t, &lc).unwrap();
        let mut col = 0;
        for (s, sup) in t.supports.iter().enumerate() {
            match sup.kind {
                SupportKind::Pinned => {
                    assert!((m[s].x - sol.reactions[col]).abs() < 1e-9);
                    assert!((m[s].y - sol.reactions[col + 1]).abs() < 1e-9);
                    col += 2;
                }
                SupportKind::Roller { dir } => {
                    assert!((m[s].dot(&dir) - sol.reactions[col]).abs() < 1e-9);
                    col += 1;
                }
            }
        }
    }
    // A roller whose line passes through the pin cannot be resolved by moments.
    t.supports = vec![Support::pinned(0, "A"), roller(1, 0.0)];
    assert!(by_moments(&t, &loads).is_none());
}

#[test]
fn coincident_joints_are_found_whatever_lies_between_them() {
    let scene = |joints: &str| {
        format!(
            r#"{{ "procedure": "truss", "title": "t", "joints": [ {joints} ],
            "members": [ {{ "name": "1", "joints": ["A", "B"] }} ],
            "supports": [ {{ "joint": "A", "kind": "pinned" }} ],
            "load_cases": [ {{ "name": "P", "loads": [ {{ "joint": "B", "kg": 1 }} ] }} ] }}"#
        )
    };
    for (joints, on) in [
        // −0.0 is 0: IV lies on III, with I sorted between them.
        (
            r#"{ "name": "A", "at_m": [-0.0, 1] }, { "name": "B", "at_m": [0, 0] }, { "name": "C", "at_m": [0, 1] }"#,
            "joint `C` lies on joint `A`",
        ),
        // 1e-300 m from (0, 0) on a 2 m truss, with (0, 1) between them by x.
        (
            r#"{ "name": "A", "at_m": [0, 0] }, { "name": "B", "at_m": [0, 1] }, { "name": "C", "at_m": [1e-300, 0] }, { "name": "D", "at_m": [2, 0] }"#,
            "joint `C` lies on joint `A`",
        ),
    ] {
        let e = AnyScene::from_json(&scene(joints), "c.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains(on) && e.contains("joints[2]"), "{e}");
    }
}

#[test]
fn a_scene_too_big_to_draw_is_refused_before_it_is_built_naming_the_moving_load() {
    // 300 joints on a line, a load moving over all of them: 300 cases of about 2,400 steps.
    let n = 300;
    let joints: Vec<String> = (0..n)
        .map(|i| format!(r#"{{ "name": "J{i}", "at_m": [{i}, {}] }}"#, i % 2))
        .collect();
    let members: Vec<String> = (1..n)
        .map(|i| format!(r#"{{ "name": "{i}", "joints": ["J{}", "J{i}"] }}"#, i - 1))
        .collect();
    let path: Vec<String> = (0..n).map(|i| format!("\"J{i}\"")).collect();
    let text = format!(
        r#"{{ "procedure": "truss", "title": "t", "joints": [{}], "members": [{}],
        "supports": [ {{ "joint": "J0", "kind": "pinned" }}, {{ "joint": "J1", "kind": "roller", "direction_deg": 90 }} ],
        "moving_loads": [ {{ "name": "cart", "loads_kg": [100], "path": [{}] }} ] }}"#,
        joints.join(","),
        members.join(","),
        path.join(",")
    );
    let t = std::time::Instant::now();
    let e = AnyScene::from_json(&text, "big.json")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("big.json: moving_loads: 300 load cases"),
        "{e}"
    );
    assert!(e.contains("more than the 200000"), "{e}");
    assert!(
        t.elapsed().as_secs_f64() < 5.0,
        "refused before anything heavy"
    );
}

#[test]
fn a_truss_not_in_metres_is_refused_naming_its_joints() {
    for (scale, words) in [("1e-300", "spans 2e-300 m"), ("1e7", "spans 2e7 m")] {
        let text = format!(
            r#"{{ "procedure": "truss", "title": "t",
            "joints": [ {{ "name": "I", "at_m": [0, 0] }}, {{ "name": "II", "at_m": [{s2}, 0] }}, {{ "name": "III", "at_m": [{scale}, {scale}] }} ],
            "members": [ {{ "name": "1", "joints": ["I", "III"] }}, {{ "name": "2", "joints": ["III", "II"] }}, {{ "name": "3", "joints": ["I", "II"] }} ],
            "supports": [ {{ "joint": "I", "kind": "pinned" }}, {{ "joint": "II", "kind": "roller", "direction_deg": 90 }} ],
            "load_cases": [ {{ "name": "P", "loads": [ {{ "joint": "III", "kg": 1000 }} ] }} ] }}"#,
            s2 = 2.0 * scale.parse::<f64>().unwrap()
        );
        let e = AnyScene::from_json(&text, "t.json")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("t.json: joints: the truss") && e.contains(words),
            "{e}"
        );
    }
}

#[test]
fn a_flat_but_determinate_triangle_is_not_a_mechanism_and_its_cuts_are_flagged() {
    // A hard case: apex 1e-10 of the span. Determinate; member forces of 2.5e12 kg from
    // cuts at 1e-8 degrees, every such row flagged as glancing.
    let text = r#"{ "procedure": "truss", "title": "t",
        "joints": [ { "name": "I", "at_m": [0, 0] }, { "name": "II", "at_m": [2, 0] }, { "name": "III", "at_m": [1, 2e-10] } ],
        "members": [ { "name": "1", "joints": ["I", "III"] }, { "name": "2", "joints": ["III", "II"] }, { "name": "3", "joints": ["I", "II"] } ],
        "supports": [ { "joint": "I", "kind": "pinned" }, { "joint": "II", "kind": "roller", "direction_deg": 90 } ],
        "load_cases": [ { "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] } ] }"#;
    let any = AnyScene::from_json(text, "flat.json").unwrap();
    let board = any.problem().construct(BoardConfig::DRAWING).unwrap();
    let rows = graphostatik::render::check_rows(&board);
    let members: Vec<_> = rows
        .iter()
        .filter(|r| r.quantity.starts_with("member force"))
        .collect();
    assert_eq!(members.len(), 3);
    for r in members {
        assert!(r.glancing, "{r:?}");
        assert!((r.constructed.abs() / 2.5e12 - 1.0).abs() < 1e-6, "{r:?}");
    }
}

/// The rank an SVD finds, by the same rule as `analyse` (the reference for the sparse test).
fn svd_rank(t: &Truss) -> usize {
    let a = graphostatik::truss::matrix::equilibrium_matrix(t);
    let sv = a.svd(false, false).singular_values;
    let smax = sv.iter().cloned().fold(0.0, f64::max);
    sv.iter()
        .filter(|&&x| x > graphostatik::truss::matrix::RANK_REL * smax)
        .count()
}

#[test]
fn the_sparse_rank_test_never_calls_determinate_what_the_svd_calls_a_mechanism() {
    // A triangle flattened towards three joints in line (a mechanism at h = 0), and a
    // 20-panel girder whose middle top joint is lowered into the bottom chord's line.
    let mut trusses = Vec::new();
    for h in [
        1.0, 1e-3, 1e-6, 1e-9, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15, 1e-16, 0.0,
    ] {
        trusses.push(small(
            &[(0.0, 0.0), (2.0, 0.0), (1.0, h)],
            &[(0, 2), (2, 1), (0, 1)],
            90.0,
        ));
        let mut g = parallel_chord(Web::Warren, 20, 1.0, 1.0);
        let top = g.joints.len() - 10;
        g.joints[top].at.y = h;
        trusses.push(g);
    }
    let mut mechanisms = 0;
    for t in &trusses {
        let rank = svd_rank(t);
        let a = analyse(t);
        if rank < 2 * t.joints.len() {
            mechanisms += 1;
            assert!(
                matches!(a.determinacy, Determinacy::Mechanism { .. }),
                "{:?} against SVD rank {rank}",
                a.determinacy
            );
        } else {
            assert_eq!(a.determinacy, Determinacy::Determinate);
        }
    }
    eprintln!(
        "{mechanisms} of {} are mechanisms by the SVD",
        trusses.len()
    );
    assert!(
        (3..=trusses.len() - 10).contains(&mechanisms),
        "{mechanisms}"
    );
}

#[test]
fn a_large_determinate_truss_gets_its_rank_without_the_svd() {
    // 2,001 joints: above the SVD's limit, the sparse test still finds the full rank.
    let t = parallel_chord(Web::Warren, 1000, 1.0, 1.0);
    let a = analyse(&t);
    assert_eq!(a.rank, Some(2 * t.joints.len()));
    assert_eq!(a.determinacy, Determinacy::Determinate);
}

/// The CSV table holds every digit: each force and plan length reads back as the very f64
/// the construction found (it rounded to 3 decimals).
#[test]
fn the_csv_table_reads_back_as_the_same_numbers() {
    let p = load_scene("lh_aufgabe4_shed_roof.json");
    let (_, r) = TrussScene::construct(&p, BoardConfig::SILENT).unwrap();
    let csv = graphostatik::render::forces::csv(&r, &p.combinations);
    let row: Vec<&str> = csv.lines().nth(3).unwrap().split(',').collect();
    assert_eq!(row[0], "\"3\"");
    for (k, case) in r.iter().enumerate() {
        let plan: f64 = row[1 + 2 * k].parse().unwrap();
        let force: f64 = row[2 + 2 * k].parse().unwrap();
        assert_eq!(plan, case.members[2].plan_mm);
        assert_eq!(force, case.members[2].force);
    }
}

#[test]
fn a_long_girder_checks_its_reactions_at_the_scale_of_its_forces() {
    // 5,000 Pratt panels under 1.3 t loads: reactions of 3.3e6 kg but chord forces of 4e9 kg.
    // The sparse solve is exact to ε times its largest force, so its horizontal pin reaction
    // is some 5e-6 kg, not 0: judged at the reactions' scale (1.6e-6 kg) this check failed;
    // the solve's checks are judged at the larger of the case's scale and the solve's own.
    let n = 5000;
    let t = parallel_chord(Web::Pratt, n, 2.0, 2.0);
    let loads: Vec<_> = (1..n)
        .map(|i| down(i, 1000.0 + (i % 7) as f64 * 100.0))
        .collect();
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
    construct_truss(&mut b, &t, &case(loads), &D).unwrap();
    let failed: Vec<_> = b
        .checks()
        .filter(|c| !c.passed)
        .map(|c| c.quantity.to_string())
        .collect();
    assert!(failed.is_empty(), "{failed:?}");
    let solve_scale = b
        .checks()
        .filter(|c| c.quantity.as_ref() == "pin reaction, horizontal")
        .map(|c| c.tolerance)
        .next()
        .expect("the pin's horizontal reaction is checked against the solve");
    assert!(solve_scale > 1e-3, "tolerance {solve_scale:e} kg");
}

/// The pebble game's generic verdict equals the SVD's rank on trusses with members taken out
/// and put in at random (joints at generic positions: the girder's joints jittered), so that
/// above the SVD's limit the game can stand in for it.
#[test]
fn the_pebble_game_agrees_with_the_rank_on_random_trusses() {
    use graphostatik::truss::pebble::generic;
    let mut seed = 12345u64;
    let mut next = |n: usize| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 33) as usize) % n
    };
    for trial in 0..60 {
        let web = [Web::Warren, Web::Pratt, Web::Howe][trial % 3];
        let mut t = parallel_chord(web, 3 + trial % 5, 1.0, 0.8);
        for (i, j) in t.joints.iter_mut().enumerate() {
            j.at.x += 0.013 * ((i * 37 % 11) as f64 - 5.0) / 5.0;
            j.at.y += 0.011 * ((i * 53 % 13) as f64 - 6.0) / 6.0;
        }
        for _ in 0..next(3) {
            let m = next(t.members.len());
            t.members.remove(m);
        }
        for _ in 0..next(3) {
            let (a, b) = (next(t.joints.len()), next(t.joints.len()));
            if a != b
                && !t
                    .members
                    .iter()
                    .any(|m| m.ends == [a, b] || m.ends == [b, a])
            {
                t.members.push(Member {
                    name: format!("x{a}-{b}").into(),
                    ends: [a, b],
                });
            }
        }
        let g = generic(&t);
        let k = t.joints.len();
        let unknowns = t.members.len() + t.reaction_unknowns();
        // Square systems that are regular skip the SVD: the rank is 2k then.
        let rank = analyse(&t).rank.unwrap();
        assert_eq!(g.freedoms, 2 * k - rank, "trial {trial}: freedoms");
        assert_eq!(g.redundant, unknowns - rank, "trial {trial}: redundant");
        assert_eq!(g.loose_joint.is_some(), g.freedoms > 0, "trial {trial}");
    }
}

/// Above the SVD's limit a truss that is not determinate is refused before its plan, naming
/// the joint that can move (it used to be found only by the plan stalling, or not at all
/// for a system with too many members).
#[test]
fn a_large_truss_that_is_not_determinate_is_named_without_the_svd() {
    let n = 1000; // Pratt: 2,000 joints, above DENSE_MAX_JOINTS
    let base = parallel_chord(Web::Pratt, n, 1.0, 1.0);
    assert!(base.joints.len() > graphostatik::truss::matrix::DENSE_MAX_JOINTS);
    assert_eq!(analyse(&base).determinacy, Determinacy::Determinate);
    // A diagonal of an inner panel out: the square system is short of one member.
    let mut t = base.clone();
    let d = t.members.len() - 1;
    let [a, b] = t.members[d].ends;
    t.members.remove(d);
    let Determinacy::Mechanism { joint, freedoms } = analyse(&t).determinacy else {
        panic!("a mechanism")
    };
    assert_eq!(freedoms, 1);
    let near = |j: usize| (t.joints[j].at.x - t.joints[a].at.x).abs() <= 2.0;
    assert!(
        near(joint),
        "joint {} far from the panel of {a}-{b}",
        t.joints[joint].name
    );
    // The same member moved into another panel as a second diagonal: square, the count
    // right, and still a mechanism (one panel braced twice, one not at all).
    let mut t2 = t.clone();
    // B2-T3 crosses the diagonal T2-B3 of the braced second panel (T(i) is joint n + i).
    let (p, q) = (2, n + 3);
    t2.members.push(Member {
        name: "extra".into(),
        ends: [p, q],
    });
    assert_eq!(
        t2.members.len() + t2.reaction_unknowns(),
        2 * t2.joints.len()
    );
    assert!(matches!(
        analyse(&t2).determinacy,
        Determinacy::Mechanism { freedoms: 1, .. }
    ));
    // One member too many: over-determinate by one, not determinate.
    let mut t3 = base.clone();
    t3.members.push(Member {
        name: "extra".into(),
        ends: [p, q],
    });
    assert_eq!(
        analyse(&t3).determinacy,
        Determinacy::OverDeterminate { redundant: 1 }
    );
    // And the construction refuses the mechanism before drawing, naming the joint.
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
    let e = construct_truss(&mut b, &t, &case(vec![down(1, 100.0)]), &D).unwrap_err();
    assert!(e.to_string().contains(t.joints[joint].name.as_str()), "{e}");
}

/// Above the SVD's limit the pebble game's searches have a budget: a truss of members joined
/// at random (where the game is quadratic, and a sparse LU fills in to gigabytes) is refused
/// as undecided at once, naming `members`; girders of any size stay well within it.
#[test]
fn a_large_truss_of_members_joined_at_random_is_refused_at_once() {
    let k = 4000;
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let joints: Vec<Joint> = (0..k)
        .map(|i| Joint {
            name: format!("J{i}").into(),
            at: Point::new(
                (next() % 10_000) as f64 / 100.0,
                (next() % 10_000) as f64 / 100.0,
            ),
        })
        .collect();
    let mut seen = std::collections::HashSet::new();
    let mut members = Vec::new();
    while members.len() < 2 * k - 3 {
        let (a, b) = ((next() % k as u64) as usize, (next() % k as u64) as usize);
        if a != b && seen.insert((a.min(b), a.max(b))) {
            members.push(Member {
                name: format!("{}", members.len() + 1).into(),
                ends: [a, b],
            });
        }
    }
    let t = Truss::new(
        joints,
        members,
        vec![
            Support::pinned(0, "A"),
            Support::roller(1, Vector::new(0.0, 1.0), "B"),
        ],
    );
    assert!(matches!(
        analyse(&t).determinacy,
        Determinacy::Undecided { .. }
    ));
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(1000.0);
    let e = construct_truss(&mut b, &t, &case(vec![down(5, 100.0)]), &D).unwrap_err();
    assert!(e.to_string().contains("not joined in panels"), "{e}");
    for web in [Web::Warren, Web::Pratt, Web::Howe] {
        let g = parallel_chord(web, 2500, 2.0, 2.0);
        assert_eq!(analyse(&g).determinacy, Determinacy::Determinate, "{web:?}");
    }
}
