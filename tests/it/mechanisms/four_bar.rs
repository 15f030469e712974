//! The crank-rocker and the parallel crank (KG XIV, Abb. 1043, 1045): B by two
//! circles against the loop's closed form, the dead positions, the transmission angle flagged,
//! the parallel crank's change points typed, and Grashof's limits refused naming the links.

use graphostatik::mechanisms::four_bar::*;
use graphostatik::protocol::{Board, ConstructionError, Drawn};
use proptest::prelude::*;

const ALL: FourBarRequest = FourBarRequest {
    dead_positions: true,
    transmission: true,
};

fn rocker(assembly: Assembly) -> FourBar {
    FourBar {
        frame: 400.0,
        crank: 100.0,
        coupler: 350.0,
        rocker: 300.0,
        assembly,
        min_transmission: 40.0,
    }
}

/// Both closures, every 10°: every check passes; the dead positions' swing and ϑ agree with
/// the extremes of the rocker angle found by sweeping the crank finely (an independent check
/// of the closed forms).
#[test]
fn the_crank_rocker_swings_between_its_dead_positions() {
    for asm in [Assembly::Left, Assembly::Right] {
        let fb = rocker(asm);
        let thetas: Vec<f64> = (0..36).map(|i| 10.0 * i as f64).collect();
        let mut b = Board::recording();
        let r = construct(&mut b, &fb, 5.0, &thetas, ALL).unwrap();
        assert!(b.all_passed(), "{asm:?}");
        assert!(r.rows.iter().all(|row| !row.change_point));
        let (swing, vartheta) = r.dead.unwrap();
        let sweep: Vec<(f64, f64)> = (0..360_000)
            .map(|i| {
                let t = i as f64 / 1000.0;
                (t, fb.exact(t).1)
            })
            .collect();
        let (tmin, pmin) =
            sweep
                .iter()
                .copied()
                .fold((0.0, f64::INFINITY), |a, x| if x.1 < a.1 { x } else { a });
        let (tmax, pmax) =
            sweep.iter().copied().fold(
                (0.0, f64::NEG_INFINITY),
                |a, x| if x.1 > a.1 { x } else { a },
            );
        assert!(
            (pmax - pmin - swing).abs() < 1e-5,
            "{asm:?}: {} {swing}",
            pmax - pmin
        );
        let apart = (tmax - tmin).rem_euclid(360.0);
        let between = (apart - 180.0).abs();
        assert!(
            (between - vartheta).abs() < 2e-3,
            "{asm:?}: {between} {vartheta}"
        );
    }
}

/// The transmission angle is flagged exactly where min(μ, 180° − μ) is below the limit.
#[test]
fn a_small_transmission_angle_is_flagged() {
    let mut fb = rocker(Assembly::Left);
    fb.min_transmission = 60.0;
    let thetas: Vec<f64> = (0..72).map(|i| 5.0 * i as f64).collect();
    let mut b = Board::recording();
    let r = construct(&mut b, &fb, 5.0, &thetas, ALL).unwrap();
    let flagged = r.rows.iter().filter(|x| x.flagged).count();
    assert!(flagged > 0 && flagged < r.rows.len(), "{flagged}");
    for row in &r.rows {
        let mu = row.transmission.unwrap();
        assert_eq!(row.flagged, mu.min(180.0 - mu) < 60.0);
    }
}

/// The parallel crank: B = P + OA at every angle; at θ = 0° and 180° all links lie in one
/// line, the circles touch, and the cut is typed as a change point (no branch), with the
/// transmission angle 0 there.
#[test]
fn the_parallel_crank_has_two_change_points() {
    let fb = FourBar {
        frame: 1800.0,
        crank: 300.0,
        coupler: 1800.0,
        rocker: 300.0,
        assembly: Assembly::Parallel,
        min_transmission: 30.0,
    };
    let thetas: Vec<f64> = (0..12).map(|i| 30.0 * i as f64).collect();
    let mut b = Board::recording();
    let r = construct(&mut b, &fb, 20.0, &thetas, ALL).unwrap();
    assert!(b.all_passed());
    assert!(
        r.dead.is_none(),
        "the rocker turns round: no dead positions"
    );
    for row in &r.rows {
        let at_change = row.theta == 0.0 || row.theta == 180.0;
        assert_eq!(row.change_point, at_change, "{row:?}");
        // The rocker stays parallel to the crank: ∠OAB = 180° − θ folded into [0°, 180°].
        let want = 180.0
            - if row.theta <= 180.0 {
                row.theta
            } else {
                360.0 - row.theta
            };
        assert!((row.rocker_angle - want).abs() < 1e-9, "{row:?}");
        if at_change {
            assert!(
                row.flagged
                    && row
                        .transmission
                        .unwrap()
                        .min(180.0 - row.transmission.unwrap())
                        < 1e-6
            );
        }
    }
    let tangent_steps = b
        .steps()
        .iter()
        .filter(|s| s.outcome.as_deref() == Some("tangent: one double point"))
        .count();
    // The circles touch at θ = 0° and 180° only: once where the positions are divided, once
    // where the change points U₁, U₂ are drawn with the links in one line.
    assert_eq!(tangent_steps, 4);
}

/// Links that do not close the loop, a four-bar whose crank cannot turn round (Grashof), and
/// the parallel closure of links that are not a parallel crank: refused, naming the link.
#[test]
fn bad_links_are_refused_naming_them() {
    let cases = [
        (
            FourBar {
                frame: 1000.0,
                ..rocker(Assembly::Left)
            },
            "frame",
            "do not close the loop",
        ),
        (
            FourBar {
                crank: 320.0,
                ..rocker(Assembly::Left)
            },
            "crank",
            "Grashof",
        ),
        (
            FourBar {
                coupler: 90.0,
                ..rocker(Assembly::Left)
            },
            "crank",
            "Grashof",
        ),
        (
            FourBar {
                crank: -1.0,
                ..rocker(Assembly::Left)
            },
            "crank",
            "positive",
        ),
        (rocker(Assembly::Parallel), "assembly", "parallel"),
    ];
    for (fb, field, words) in cases {
        let e = construct(&mut Board::recording(), &fb, 5.0, &[0.0], ALL).unwrap_err();
        match e {
            ConstructionError::Unsupported { input, reason } => {
                assert_eq!(&*input, field, "{reason}");
                assert!(reason.contains(words) && !reason.contains('\n'), "{reason}");
            }
            other => panic!("{other:?}"),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any Grashof crank-rocker, either closure, any angle: every check passes and B lies at
    /// the coupler's length from the pin and the rocker's from A (the closed form closes the
    /// loop).
    #[test]
    fn any_crank_rocker_agrees(r in 10.0f64..100.0, d in 300.0f64..500.0, l in 200.0f64..600.0, theta in 0.0f64..360.0, left in any::<bool>()) {
        // The rocker that makes it Grashof with margin: r + max ≤ the other two.
        let rho = (d + l) / 2.0;
        let fb = FourBar { frame: d, crank: r, coupler: l, rocker: rho, assembly: if left { Assembly::Left } else { Assembly::Right }, min_transmission: 40.0 };
        prop_assume!(fb.validate().is_ok());
        let mut b = Board::recording();
        construct(&mut b, &fb, d / 100.0, &[theta], ALL).unwrap();
        prop_assert!(b.all_passed());
        let (bp, _, _) = fb.exact(theta);
        let (s, c) = graphostatik::kernel::angle::sin_cos_deg(theta);
        let pin = graphostatik::kernel::Point::new(r * c, r * s);
        prop_assert!(((bp - pin).norm() - l).abs() < 1e-9 * d);
        prop_assert!(((bp - graphostatik::kernel::Point::new(d, 0.0)).norm() - rho).abs() < 1e-9 * d);
    }
}

fn scene(patch: &str) -> String {
    super::patched("kg_abb1043_crank_rocker.json", patch)
}

/// Bad input in a scene: one line naming the field.
#[test]
fn a_four_bar_scene_names_what_is_wrong() {
    use graphostatik::scene::AnyScene;
    for (patch, field) in [
        ("\"frame_mm\": 400 => \"frame_mm\": 900", "links.frame_mm"),
        ("\"crank_mm\": 100 => \"crank_mm\": 320", "links.crank_mm"),
        ("\"rocker_mm\": 300 => \"rocker_mm\": 0", "links.rocker_mm"),
        (
            "\"assembly\": \"left\" => \"assembly\": \"parallel\"",
            "assembly",
        ),
        (
            "\"min_transmission_deg\": 40 => \"min_transmission_deg\": 95",
            "min_transmission_deg",
        ),
        (
            "\"divisions\": 12 => \"stroke_parts\": 3",
            "angles.stroke_parts",
        ),
    ] {
        let e = AnyScene::from_json(&scene(patch), "f.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{patch}: {e}");
    }
    let ok =
        AnyScene::from_json(&scene("\"divisions\": 12 => \"divisions\": 12"), "f.json").unwrap();
    assert_eq!(ok.procedure(), "four_bar");
}

/// The crank-rocker at its dead positions, seen from the rocker: the pin is where the
/// coupler's circle about B meets the crank circle, and at B₁ and B₂ (crank and coupler in
/// one line) the two circles touch: a typed tangency with one double point and no branch,
/// not an error and not NaN.
#[test]
fn at_the_dead_positions_the_circles_touch() {
    use graphostatik::kernel::{Branch, Point};
    use graphostatik::protocol::{Label, Role};
    let fb = rocker(Assembly::Left);
    for reach in [fb.coupler + fb.crank, fb.coupler - fb.crank] {
        let note = graphostatik::protocol::note(
            "test",
            None,
            "test",
            graphostatik::protocol::Topic::Custom("test"),
        );
        let mut b = Board::recording();
        let o = b.point(Point::origin(), Role::Given, note.clone());
        let a = b.point(Point::new(fb.frame, 0.0), Role::Given, note.clone());
        let crank = b
            .circle(&o, fb.crank, Drawn::Whole, Role::Given, note.clone())
            .unwrap();
        let rock = b
            .circle(&a, fb.rocker, Drawn::Whole, Role::Given, note.clone())
            .unwrap();
        let arc = b
            .circle(&o, reach, Drawn::Marks, Role::Given, note.clone())
            .unwrap();
        let dead = b
            .cut_circle_circle(&arc, &rock, Branch::Second, Label::NONE, note.clone())
            .unwrap();
        assert!(!b.last_cut_touched());
        let coupler = b
            .circle(&dead, fb.coupler, Drawn::Marks, Role::Given, note.clone())
            .unwrap();
        let pin = b
            .cut_circle_circle(&coupler, &crank, Branch::Second, Label::NONE, note)
            .unwrap();
        assert!(b.last_cut_touched(), "reach {reach}");
        assert!(pin.g.x.is_finite() && ((pin.g - o.g).norm() - fb.crank).abs() < 1e-9);
        let step = b.steps().last().unwrap();
        assert_eq!(step.outcome.as_deref(), Some("tangent: one double point"));
        assert!(step.branch.is_none());
    }
}
