//! The offset slider-crank (KG XIV, Abb. 1046): the construction against the
//! loop's closed forms, the straight slider-crank at offset 0 to 1e-12, and the refusal of an
//! offset the rod cannot bridge.

use graphostatik::crank::{self, Angles, CrankDrive, Drawing, PistonForce, Request};
use graphostatik::mechanisms::offset_crank::*;
use graphostatik::protocol::{Board, ConstructionError};
use proptest::prelude::*;

const ALL: OffsetRequest = OffsetRequest {
    velocity: true,
    forces: true,
};

fn offset(a: f64) -> OffsetCrank {
    OffsetCrank {
        crank_radius: 300.0,
        rod_length: 1500.0,
        offset: a,
        crank_pin_speed: 4.0,
        piston_force: Some(12_000.0),
    }
}

const SC: OffsetScales = OffsetScales {
    length: 10.0,
    velocity: 0.1,
    force: 200.0,
};

/// At a = 0 the path, velocity, rod force and tangential force are the straight
/// slider-crank's (`crank::construct`, its own construction) to 1e-12 of their scale, at every
/// 10° of both strokes.
#[test]
fn offset_zero_is_the_straight_slider_crank() {
    let thetas: Vec<f64> = (0..36).map(|i| 10.0 * i as f64).collect();
    let mut b = Board::recording();
    let r = construct(&mut b, &offset(0.0), SC, &thetas, ALL).unwrap();
    assert!(b.all_passed());
    assert_eq!(r.delta, 0.0);
    assert!((r.stroke - 600.0).abs() < 1e-12 * 1500.0);
    let drive = CrankDrive {
        crank_radius: 300.0,
        rod_length: 1500.0,
        finite_rod: true,
        crank_pin_speed: 4.0,
        piston_force: PistonForce::Constant(12_000.0),
    };
    let d = Drawing {
        length_scale: 10.0,
        force_scale: 200.0,
        velocity_scale: 0.1,
        acceleration_scale: 1.0,
    };
    let rq = Request {
        piston_path: true,
        velocity_parallel: true,
        rod_force: true,
        guide_force: true,
        tangential_force: true,
        ..Request::default()
    };
    let mut b2 = Board::recording();
    let s = crank::construct(&mut b2, &drive, &d, &Angles::Degrees(thetas), &rq).unwrap();
    for (o, st) in r.rows.iter().zip(&s.rows) {
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-12 * scale;
        assert!(close(o.x, st.x.unwrap(), 1500.0), "x {o:?} {st:?}");
        assert!(
            close(o.c.unwrap(), st.c_parallel.unwrap(), 4.0),
            "c {o:?} {st:?}"
        );
        assert!(
            close(o.rod_force.unwrap(), st.rod_force.unwrap(), 12_000.0),
            "S {o:?} {st:?}"
        );
        assert!(
            close(
                o.tangential_force.unwrap(),
                st.tangential_force.unwrap(),
                12_000.0
            ),
            "T {o:?} {st:?}"
        );
        assert!(
            close(
                o.guide_force.unwrap().abs(),
                st.guide_force.unwrap().abs(),
                12_000.0
            ),
            "N {o:?} {st:?}"
        );
    }
}

/// The offset's effect (KG Abb. 1046): the outstroke takes 180° + δ, the stroke exceeds 2R,
/// and at the dead centres the piston stands still.
#[test]
fn the_offset_makes_the_strokes_unequal() {
    let k = offset(400.0);
    let (i, o) = k.dead_centres();
    let mut b = Board::recording();
    let r = construct(&mut b, &k, SC, &[i, o], ALL).unwrap();
    assert!(b.all_passed());
    let delta = (400.0f64 / 1200.0).asin().to_degrees() - (400.0f64 / 1800.0).asin().to_degrees();
    assert!(
        (r.delta - delta).abs() < 1e-12 * 180.0,
        "{} {delta}",
        r.delta
    );
    assert!(r.stroke > 600.0);
    assert!(r.rows[0].x.abs() < 1e-9 && (r.rows[1].x - r.stroke).abs() < 1e-9);
    assert!(r.rows[0].c.unwrap().abs() < 1e-12 && r.rows[1].c.unwrap().abs() < 1e-12);
    let neg = construct(&mut Board::recording(), &offset(-400.0), SC, &[0.0], ALL).unwrap();
    assert!((neg.delta + delta).abs() < 1e-12 * 180.0);
}

/// An offset the rod cannot bridge (|a| ≥ L − R: at equality the arc L − R only touches the
/// line of the stroke) is refused, naming the offset.
#[test]
fn an_offset_beyond_l_minus_r_is_refused() {
    for a in [1200.0, -1200.0, 1500.0, f64::NAN] {
        let e = construct(&mut Board::recording(), &offset(a), SC, &[0.0], ALL).unwrap_err();
        assert!(
            matches!(e, ConstructionError::Unsupported { ref input, .. } if *input == "offset"),
            "{e:?}"
        );
    }
    let mut short = offset(0.0);
    short.rod_length = 300.0;
    let e = construct(&mut Board::recording(), &short, SC, &[0.0], ALL).unwrap_err();
    assert!(
        matches!(e, ConstructionError::Unsupported { ref input, .. } if *input == "rod_length")
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any crank, rod, offset and angle: every check passes, the velocity is the path's
    /// derivative (so the closed forms agree with each other, not only with the drawing), and
    /// the tangential force does the piston force's work: T·v = P·|c|.
    #[test]
    fn any_offset_crank_agrees(r in 10.0f64..500.0, l_over in 1.2f64..8.0, a_frac in -0.98f64..0.98, theta in 0.0f64..360.0) {
        let l = r * l_over;
        let k = OffsetCrank { crank_radius: r, rod_length: l, offset: a_frac * (l - r), crank_pin_speed: 3.0, piston_force: Some(5000.0) };
        let sc = OffsetScales { length: l / 100.0, velocity: 0.05, force: 100.0 };
        let mut b = Board::recording();
        let res = construct(&mut b, &k, sc, &[theta], ALL).unwrap();
        let failed: Vec<String> = b.checks().filter(|c| !c.passed).map(|c| format!("{c:?}")).collect();
        prop_assert!(failed.is_empty(), "{:?}", failed);
        let e = k.exact(theta);
        let h = 1e-5;
        let dx = (k.exact(theta + h).x - k.exact(theta - h).x) / (2.0 * h.to_radians());
        prop_assert!((dx * 3.0 / r - e.c).abs() < 1e-5 * 3.0 * l / r, "{} {}", dx * 3.0 / r, e.c);
        prop_assert!((e.tangential_force * 3.0 - 5000.0 * e.c.abs()).abs() < 1e-9 * 5000.0 * 3.0 * l / r);
        prop_assert!((res.rows[0].x - e.x).abs() < 1e-9 * l);
    }
}

fn scene(patch: &str) -> String {
    super::patched("kg_abb1046_offset_crank.json", patch)
}

/// Bad input: one line naming the field (an offset larger than the rod allows, a rod shorter
/// than the crank, a missing or stray piston force).
#[test]
fn an_offset_crank_scene_names_what_is_wrong() {
    use graphostatik::scene::AnyScene;
    for (patch, field) in [
        ("\"offset_mm\": 150 => \"offset_mm\": 600", "offset_mm"),
        ("\"offset_mm\": 150 => \"offset_mm\": -700", "offset_mm"),
        ("\"length_mm\": 800 => \"length_mm\": 150", "rod.length_mm"),
        (
            "\"crank_radius_mm\": 200 => \"crank_radius_mm\": 0",
            "crank_radius_mm",
        ),
        ("\"piston_force_kg\": 5000, => ", "piston_force_kg"),
        (
            "\"outputs\": [\"velocity\", \"forces\"] => \"outputs\": [\"velocity\"]",
            "piston_force_kg",
        ),
        (
            "\"divisions\": 12 => \"stroke_parts\": 6",
            "angles.stroke_parts",
        ),
        (
            "\"force_scale_kg_per_mm\": 200 => \"force_scale_kg_per_mm\": 1e-12",
            "drawing.force_scale_kg_per_mm",
        ),
    ] {
        let e = AnyScene::from_json(&scene(patch), "o.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{patch}: {e}");
    }
    let ok = AnyScene::from_json(&scene("\"rpm\": 120 => \"rpm\": 120"), "o.json").unwrap();
    assert_eq!(ok.procedure(), "offset_crank");
}
