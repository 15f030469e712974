//! Forces in the plane (LH A.2-4, C.2): force polygon, funicular polygon, resultant, couple,
//! equilibrium, resolution along two lines — against vector sums, moments and 2×2 solves.

use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use graphostatik::statics::funicular::*;
use proptest::prelude::*;

const D: SystemDrawing = SystemDrawing {
    length_scale: 50.0,
    force_scale: 10.0,
    pole: None,
    plan_at: None,
    unit: "kg",
};

fn run(forces: &[Force], res: &[Resolution]) -> (Board, SystemResults) {
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
    let r = construct_system(&mut b, forces, &D, res).unwrap();
    for c in b.steps().iter().flat_map(|s| &s.checks) {
        assert!(
            c.passed,
            "{}: {} vs {} ({:e})",
            c.quantity, c.constructed, c.closed_form, c.error
        );
    }
    (b, r)
}

fn f(x: f64, y: f64, fx: f64, fy: f64) -> Force {
    Force {
        at: graphostatik::kernel::Point::new(x, y),
        f: graphostatik::kernel::Vector::new(fx, fy),
    }
}

#[test]
fn lh_s1_forces_on_one_line_of_action() {
    // LH A.1: +500 − 150 − 250 + 50 = +150 kg.
    let forces = [
        f(0.0, 0.0, 500.0, 0.0),
        f(1.0, 0.0, -150.0, 0.0),
        f(2.0, 0.0, -250.0, 0.0),
        f(3.0, 0.0, 50.0, 0.0),
    ];
    let (b, r) = run(&forces, &[]);
    match r.resultant {
        Resultant::Force { r, moment, .. } => {
            assert!((r.x - 150.0).abs() < 1e-9 && r.y.abs() < 1e-9);
            assert!(moment.abs() < 1e-9);
        }
        o => panic!("{o:?}"),
    }
    // LH Abb. 2: the forces laid off one under the other and summed; no pole and no
    // funicular polygon, whose strings would all pass through one point of the line.
    let steps = b.steps();
    let drawn = |w: &str| steps.iter().any(|s| s.caption.contains(w));
    assert!(!drawn("pole") && !drawn("string"));
    let sum = (steps.iter().flat_map(|s| &s.checks))
        .find(|c| c.quantity.starts_with("resultant along the common line"))
        .expect("the algebraic sum is checked");
    assert!(
        (sum.constructed - 150.0).abs() < 1e-9,
        "{}",
        sum.constructed
    );
}

#[test]
fn forces_on_one_line_that_cancel_are_in_equilibrium_lh_abb_1() {
    // LH Abb. 1: P − P₁ = 0, on a vertical line, and a force resolved along two lines.
    let forces = [f(0.0, 0.0, 0.0, 200.0), f(0.0, 2.0, 0.0, -200.0)];
    let res = [Resolution {
        force: 1,
        along: [0.0, 60.0],
        equilibrant: false,
    }];
    let (b, r) = run(&forces, &res);
    assert_eq!(r.resultant, Resultant::Equilibrium);
    assert!(b.steps().iter().all(|s| !s.caption.contains("pole")));
    // 200 kg straight down: −230.94 kg along 60° (pointing down-left) and +115.47 along 0°.
    let c = r.components[0];
    assert!((c.first - 115.470053837925).abs() < 1e-9, "{c:?}");
    assert!((c.second + 230.940107675850).abs() < 1e-9, "{c:?}");
}

#[test]
fn a_force_a_hair_off_the_line_keeps_the_funicular_polygon() {
    // 1 mm off a 3 m line: not one line of action, so the pole and strings are drawn.
    let forces = [f(0.0, 0.0, 500.0, 0.0), f(3.0, 0.001, -150.0, 0.0)];
    let (b, r) = run(&forces, &[]);
    assert!(b.steps().iter().any(|s| s.caption.contains("pole")));
    match r.resultant {
        Resultant::Force { r, .. } => assert!((r.x - 350.0).abs() < 1e-9),
        o => panic!("{o:?}"),
    }
}

#[test]
fn a_couple_has_zero_resultant_and_its_moment() {
    let forces = [f(0.0, 0.0, 0.0, -400.0), f(2.5, 0.0, 0.0, 400.0)];
    let (b, r) = run(&forces, &[]);
    match r.resultant {
        Resultant::Couple { moment } => assert!((moment.abs() - 1000.0).abs() < 1e-9, "{moment}"),
        o => panic!("{o:?}"),
    }
    assert!(b
        .steps()
        .iter()
        .any(|s| s.outcome.as_deref().is_some_and(|o| o.contains("infinity"))));
}

#[test]
fn three_forces_in_equilibrium_close_both_polygons() {
    // Concurrent at the origin, summing to zero.
    let forces = [
        f(1.0, 0.0, 300.0, 0.0),
        f(0.0, 1.0, 0.0, 400.0),
        f(-0.6, -0.8, -300.0, -400.0),
    ];
    let (_, r) = run(&forces, &[]);
    assert_eq!(r.resultant, Resultant::Equilibrium);
}

#[test]
fn nearly_parallel_forces_place_their_resultant_by_moment_balance() {
    // Two almost vertical forces, 0.06° off parallel: R = (0, −2000) kg; its line of action
    // lies where x·Ry = ΣM = 1·(−1000), at x = 0.5 m.
    let forces = [f(0.0, 0.0, 1.0, -1000.0), f(1.0, 0.0, -1.0, -1000.0)];
    let (_, r) = run(&forces, &[]);
    match r.resultant {
        Resultant::Force { r, through, moment } => {
            assert!(r.x.abs() < 1e-9 && (r.y + 2000.0).abs() < 1e-9);
            assert!((moment + 1000.0).abs() < 1e-9);
            // `through` is where the outer strings meet, on the vertical x = 0.5.
            assert!((through.x - 0.5).abs() < 1e-9, "{through:?}");
        }
        o => panic!("{o:?}"),
    }
}

#[test]
fn resolution_along_two_lines_lh_aufgabe_2() {
    // Q = 5100 kg hanging from two ropes; the rope angles that give S1 = 3750 and
    // S2 = 2700 kg follow from the force triangle with these three sides (law of cosines):
    let (q, s1, s2): (f64, f64, f64) = (5100.0, 3750.0, 2700.0);
    let a1 = ((q * q + s1 * s1 - s2 * s2) / (2.0 * q * s1)).acos(); // between Q and S1
    let a2 = ((q * q + s2 * s2 - s1 * s1) / (2.0 * q * s2)).acos();
    // Q points down (−90°); the ropes pull up-left and up-right.
    let d1 = 90.0 + a1.to_degrees();
    let d2 = 90.0 - a2.to_degrees();
    let forces = [f(0.0, 0.0, 0.0, -q)];
    let hold = Resolution {
        force: 0,
        along: [d1, d2],
        equilibrant: true,
    };
    let (_, r) = run(&forces, &[hold]);
    let Components {
        first: k1,
        second: k2,
    } = r.components[0];
    // The ropes pull towards their attachments: both tensions positive.
    assert!(
        (k1 - s1).abs() < 1e-9 && (k2 - s2).abs() < 1e-9,
        "{k1} {k2}"
    );
    // Resolving Q itself gives the same components, reversed.
    let (_, r) = run(
        &forces,
        &[Resolution {
            equilibrant: false,
            ..hold
        }],
    );
    assert!(
        (r.components[0].first + s1).abs() < 1e-9 && (r.components[0].second + s2).abs() < 1e-9
    );
}

#[test]
fn a_pole_on_a_side_of_the_force_polygon_is_a_clear_error() {
    // Pole on the line of the first side: string 1 ∥ line of action 2?  Put the pole on the
    // extension of side 2 (from corner 1 to corner 2): ray 1 and ray 2 run along it.
    let forces = [
        f(0.0, 0.0, 0.0, -100.0),
        f(1.0, 0.0, 100.0, 0.0),
        f(2.0, 1.0, 0.0, 50.0),
    ];
    let mut d = D;
    // Corners: (0,0) → (0,−100) → (100,−100) → (100,−50) in kg; the pole at (−100,−100)
    // lies on the line of side 2.
    d.pole = Some(graphostatik::kernel::Vector::new(-100.0, -100.0));
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
    let e = construct_system(&mut b, &forces, &d, &[])
        .unwrap_err()
        .to_string();
    assert!(e.contains("pole"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    /// Random systems: the funicular polygon's resultant has the vector sum and the moment of
    /// the system, for any pole that is not on a side.
    #[test]
    fn resultant_matches_sum_and_moment(
        forces in proptest::collection::vec(((-5.0f64..5.0, -5.0f64..5.0), (-1000.0f64..1000.0, -1000.0f64..1000.0)), 1..10),
        pole in proptest::option::of((-2000.0f64..2000.0, -2000.0f64..2000.0)),
    ) {
        let forces: Vec<Force> = forces
            .into_iter()
            .filter(|(_, (fx, fy))| fx.hypot(*fy) > 1.0)
            .map(|((x, y), (fx, fy))| f(x, y, fx, fy))
            .collect();
        prop_assume!(!forces.is_empty());
        let mut d = D;
        d.pole = pole.map(|(x, y)| graphostatik::kernel::Vector::new(x, y));
        let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
        match construct_system(&mut b, &forces, &d, &[]) {
            Ok(_) => {
                for c in b.steps().iter().flat_map(|s| &s.checks) {
                    prop_assert!(c.passed, "{}: {} vs {} ({:e} > {:e})", c.quantity, c.constructed, c.closed_form, c.error, c.tolerance);
                }
            }
            // A random pole may sit (nearly) on a side: that is reported, never a panic.
            Err(e) => prop_assert!(e.to_string().contains("pole")),
        }
    }
}

#[test]
fn lh_abb_21_auxiliary_forces_and_their_degenerate_case() {
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
    // Antiparallel, unequal: the resultant lies outside, a = l·K2/(K1 + K2) with signs.
    let a = parallel_pair_by_auxiliary_forces(
        &mut b,
        f(0.0, 0.0, 0.0, -300.0),
        f(2.0, 0.0, 0.0, 100.0),
        200.0,
        &D,
    )
    .unwrap();
    assert!((a - 2.0 * -100.0 / (300.0 - 100.0)).abs() < 1e-9, "{a}");
    for c in b.steps().iter().flat_map(|s| &s.checks) {
        assert!(c.passed);
    }
    // Equal and opposite: a couple, the partial resultants are parallel.
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
    let e = parallel_pair_by_auxiliary_forces(
        &mut b,
        f(0.0, 0.0, 0.0, -300.0),
        f(2.0, 0.0, 0.0, 300.0),
        200.0,
        &D,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("couple"), "{e}");
    assert!(b
        .steps()
        .iter()
        .any(|s| s.outcome.as_deref().is_some_and(|o| o.contains("parallel"))));
    // Not parallel: refused.
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
    assert!(parallel_pair_by_auxiliary_forces(
        &mut b,
        f(0.0, 0.0, 0.0, -300.0),
        f(2.0, 0.0, 10.0, 300.0),
        200.0,
        &D
    )
    .is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    /// Any auxiliary force gives the same resultant (the lever rule), at any inclination.
    #[test]
    fn any_auxiliary_force_gives_the_lever_rule(
        k1 in 10.0f64..1000.0, k2 in 10.0f64..1000.0, l in 0.2f64..5.0,
        aux in 5.0f64..2000.0, angle in 0.0f64..360.0,
    ) {
        let (s, c) = graphostatik::kernel::angle::sin_cos_deg(angle);
        let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
        let a = parallel_pair_by_auxiliary_forces(
            &mut b,
            f(0.0, 0.0, -s * k1, c * k1),
            f(l * c, l * s, -s * k2, c * k2),
            aux,
            &D,
        ).unwrap();
        prop_assert!((a - l * k2 / (k1 + k2)).abs() < 1e-9 * l.max(1.0) * (1.0 + (k1 + k2) / aux));
        for c in b.steps().iter().flat_map(|s| &s.checks) {
            prop_assert!(c.passed, "{}: {} vs {}", c.quantity, c.constructed, c.closed_form);
        }
    }
}

#[test]
fn directions_a_hair_from_antiparallel_are_refused_as_parallel() {
    // 0° and 180° − 1e-12°: parallel lines, whichever side of 180° the difference falls.
    for along in [
        "[0, 179.999999999999]",
        "[0, -179.999999999999]",
        "[30, 210]",
        "[10, 10]",
    ] {
        let text = format!(
            r#"{{ "procedure": "force_system", "title": "t",
                 "forces": [ {{ "at_m": [0, 0], "kg_xy": [0, -100] }} ],
                 "resolve": [ {{ "force": 1, "along_deg": {along} }} ] }}"#
        );
        let e = graphostatik::scene::AnyScene::from_json(&text, "r.json")
            .unwrap_err()
            .to_string();
        assert!(e.contains("resolve[0].along_deg"), "{along}: {e}");
    }
}

#[test]
fn the_lever_rule_by_auxiliary_forces_holds_at_any_points_of_application() {
    // Abb. 21 with the points of application off one horizontal, the second left of the
    // first, and slanted forces: the resultant still divides the join as K2 : K1.
    let d = SystemDrawing {
        length_scale: 25.0,
        force_scale: 10.0,
        pole: None,
        plan_at: None,
        unit: "kg",
    };
    for (p1, p2, dir) in [
        ((0.0, -1.0), (2.0, 0.0), (0.0, -1.0)),
        ((2.0, 0.5), (-1.0, -0.25), (0.0, -1.0)),
        ((0.0, 0.0), (3.0, 1.0), (0.6, -0.8)),
    ] {
        let k1 = Force::new(p1, (300.0 * dir.0, 300.0 * dir.1));
        let k2 = Force::new(p2, (500.0 * dir.0, 500.0 * dir.1));
        let mut b = Board::recording();
        let a = parallel_pair_by_auxiliary_forces(&mut b, k1, k2, 250.0, &d).unwrap();
        let dist = (k2.at - k1.at).norm();
        assert!(
            (a - dist * 500.0 / 800.0).abs() < 1e-9,
            "{p1:?} {p2:?}: a = {a}"
        );
        assert!(b.all_passed());
    }
    // Points on one line of action: no line for the auxiliary forces; named, not NaN.
    let k1 = Force::new((0.0, 0.0), (0.0, -300.0));
    let k2 = Force::new((0.0, 2.0), (0.0, -500.0));
    let e = parallel_pair_by_auxiliary_forces(&mut Board::silent(), k1, k2, 250.0, &d).unwrap_err();
    assert!(e.to_string().contains("one line of action"), "{e}");
}

#[test]
fn a_construction_error_names_the_scene_field_that_caused_it() {
    // The pole given on a corner of the force polygon: the error is about drawing.pole_kg.
    let text = r#"{ "procedure": "force_system", "title": "t",
        "forces": [ { "at_m": [0, 0], "kg_xy": [0, -100] }, { "at_m": [1, 0], "kg_xy": [0, -100] } ],
        "drawing": { "pole_kg": [0, -100] } }"#;
    let problem = graphostatik::scene::AnyScene::from_json(text, "p.json")
        .unwrap()
        .into_problem();
    let e = problem.construct(BoardConfig::DRAWING).unwrap_err();
    assert_eq!(
        problem.error_field(&e).as_deref(),
        Some("drawing.pole_kg"),
        "{e}"
    );
    assert_eq!(
        graphostatik::scene::scene_field(
            "resolutions[2].along",
            &[("resolutions", "resolve"), (".along", ".along_deg")]
        ),
        "resolve[2].along_deg"
    );
}

#[test]
fn directions_5e_minus_11_degrees_apart_are_refused_either_way_round() {
    // A hard case: [0, 5e-11] passed validation and failed in construction, while
    // [5e-11, 0] was refused; both are parallel, and both are refused at validation.
    for along in ["[0, 5e-11]", "[5e-11, 0]"] {
        let text = format!(
            r#"{{ "procedure": "force_system", "title": "t",
                 "forces": [ {{ "at_m": [0, 0], "kg_xy": [0, -100] }} ],
                 "resolve": [ {{ "force": 1, "along_deg": {along} }} ] }}"#
        );
        let e = graphostatik::scene::AnyScene::from_json(&text, "r.json")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("r.json: resolve[0].along_deg"),
            "{along}: {e}"
        );
    }
}

#[test]
fn a_force_polygon_closed_to_rounding_is_a_couple_judged_against_the_forces() {
    // A hard case: R = 1e-9 kg against forces of 1000 kg is closed; the system is the
    // couple of their moment, 1000 kg·m, not equilibrium.
    let forces = [f(0.0, 0.0, 0.0, -1000.0), f(1.0, 0.0, 0.0, 999.999999999)];
    let (b, r) = run(&forces, &[]);
    match r.resultant {
        Resultant::Couple { moment } => assert!((moment.abs() - 1000.0).abs() < 1e-6, "{moment}"),
        other => panic!("{other:?}"),
    }
    assert!(b.all_passed());
}

#[test]
fn forces_far_from_the_origin_keep_their_resultant_and_moment() {
    // A hard case: the resultant's line and its moment about the origin, for four forces
    // near the origin and the same forces 1e6 and 1e8 m away.
    let near = [
        f(0.0, 0.0, 100.0, -300.0),
        f(2.0, 1.0, -50.0, -200.0),
        f(3.5, -0.5, 0.0, -400.0),
        f(5.0, 0.5, 80.0, -150.0),
    ];
    let (_, r0) = run(&near, &[]);
    let Resultant::Force {
        r: rv0,
        through: t0,
        ..
    } = r0.resultant
    else {
        panic!("{:?}", r0.resultant)
    };
    for dx in [1e6, 1e8] {
        let far: Vec<Force> = near
            .iter()
            .map(|g| Force {
                at: graphostatik::kernel::Point::new(g.at.x + dx, g.at.y + dx),
                f: g.f,
            })
            .collect();
        let (b, r) = run(&far, &[]);
        assert!(b.all_passed());
        let Resultant::Force {
            r: rv,
            through,
            moment,
        } = r.resultant
        else {
            panic!("{:?}", r.resultant)
        };
        assert!((rv - rv0).norm() < 1e-9 * rv0.norm());
        // `through` is one point of the line: compare the lines by their distance.
        let n = graphostatik::kernel::Vector::new(-rv0.y, rv0.x) / rv0.norm();
        let off = (through - graphostatik::kernel::Point::new(t0.x + dx, t0.y + dx)).dot(&n);
        assert!(off.abs() < 1e-6, "{off}");
        let (_, m_exact) = sum_and_moment(&far);
        assert!(
            (moment - m_exact).abs() < 1e-9 * m_exact.abs(),
            "{moment} against {m_exact}"
        );
    }
}
