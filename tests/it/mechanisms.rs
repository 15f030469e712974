//! The other mechanisms of KG XIV: the scotch yoke (KG Abb. 1069) against its
//! closed forms and beside the slider-crank of the same stroke; the slotted link, the offset
//! crank and the four-bars in their modules.

#[path = "mechanisms/four_bar.rs"]
mod four_bar;
#[path = "mechanisms/offset_crank.rs"]
mod offset_crank;
#[path = "mechanisms/slotted_link.rs"]
mod slotted_link;

use graphostatik::crank::{closed_form::Stroke, Angles, Drawing};
use graphostatik::mechanisms::scotch_yoke::*;
use graphostatik::protocol::Board;
use graphostatik::scene::AnyScene;
use proptest::prelude::*;

fn drawing() -> Drawing {
    Drawing {
        length_scale: 5.0,
        force_scale: 1.0,
        velocity_scale: 0.025,
        acceleration_scale: 0.2,
    }
}

const ALL: YokeRequest = YokeRequest {
    velocity: true,
    acceleration: true,
    slider_crank: true,
};

/// KG: the yoke's acceleration is the straight line from +v²/R to −v²/R; the slider-crank of
/// the same stroke needs (1 + R/L)·v²/R at the inner dead centre and (1 − R/L)·v²/R at the
/// outer: 1.20 times the yoke's at R/L = 1/5, the ratio KG prints (its "R/L = 1/2,8" would
/// give 1.36).
#[test]
fn the_slider_crank_needs_one_plus_lambda_times_the_yokes_acceleration() {
    for l_over_r in [5.0, 2.8] {
        let yoke = Yoke {
            crank_radius: 150.0,
            crank_pin_speed: 0.942,
            compare_rod: Some(150.0 * l_over_r),
        };
        let mut b = Board::recording();
        let r = construct(
            &mut b,
            &yoke,
            &drawing(),
            &Angles::Degrees(vec![0.0, 90.0, 180.0]),
            ALL,
        )
        .unwrap();
        assert!(b.all_passed());
        let sc = r.slider_crank.unwrap();
        let lam = 1.0 / l_over_r;
        let inner = sc.rows[0].acceleration.unwrap() / r.rows[0].b.unwrap();
        assert!((inner - (1.0 + lam)).abs() < 1e-9, "{inner}");
        // At the outer dead centre the books' b is in the direction of the return stroke.
        assert_eq!(sc.rows[2].stroke, Stroke::Return);
        let outer = sc.rows[2].acceleration.unwrap() / r.rows[2].b.unwrap();
        assert!((outer - -(1.0 - lam)).abs() < 1e-9, "{outer}");
        // Mid-stroke: the yoke at R with c′ = v and b′ = 0.
        assert!((r.rows[1].x - 150.0).abs() < 1e-9 && r.rows[1].b.unwrap().abs() < 1e-12);
        if l_over_r == 5.0 {
            assert!((inner - 1.20).abs() < 1e-9);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any crank, speed and angle: x′, c′ and b′ agree with KG's closed forms (every check
    /// passes), and the velocity and acceleration ordinates lie on their curves.
    #[test]
    fn the_yoke_follows_its_closed_forms(r in 10.0f64..2000.0, v in 0.1f64..30.0, phi in 0.0f64..360.0) {
        let yoke = Yoke { crank_radius: r, crank_pin_speed: v, compare_rod: None };
        let d = Drawing { length_scale: r / 50.0, force_scale: 1.0, velocity_scale: v / 30.0, acceleration_scale: v * v / (r / 1000.0) / 30.0 };
        let mut b = Board::recording();
        let res = construct(&mut b, &yoke, &d, &Angles::Degrees(vec![phi]), ALL).unwrap();
        prop_assert!(b.all_passed());
        let row = res.rows[0];
        let (s, c) = graphostatik::kernel::angle::sin_cos_deg(phi);
        prop_assert!((row.x - r * (1.0 - c)).abs() < 1e-9 * r);
        prop_assert!((row.c.unwrap() - v * s).abs() < 1e-9 * v);
        prop_assert!((row.b.unwrap() - v * v / (r / 1000.0) * c).abs() < 1e-9 * v * v / (r / 1000.0));
    }
}

/// A bundled scene with one text replaced (`"from => to"`), the replaced text required.
pub(crate) fn patched(file: &str, patch: &str) -> String {
    let path = format!("{}/scenes/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    let (from, to) = patch.split_once(" => ").unwrap();
    assert!(text.contains(from), "{from}");
    text.replace(from, to)
}

fn scene(patch: &str) -> String {
    patched("kg_abb1069_scotch_yoke.json", patch)
}

/// Bad input: one line naming the field.
#[test]
fn a_scotch_yoke_scene_names_what_is_wrong() {
    for (patch, field) in [
        ("\"compare_rod\": { \"l_over_r\": 5 }, => ", "compare_rod"),
        ("\"l_over_r\": 5 => \"l_over_r\": 1", "compare_rod.l_over_r"),
        (
            "\"divisions\": 12 => \"stroke_parts\": 5",
            "angles.stroke_parts",
        ),
        (
            "\"crank_radius_mm\": 150 => \"crank_radius_mm\": -1",
            "crank.crank_radius_mm",
        ),
        ("\"rpm\": 60 => \"rpm\": 0", "speed.rpm"),
        (
            "\"acceleration_scale_m_s2_per_mm\": 0.2 => \"acceleration_scale_m_s2_per_mm\": 1e9",
            "drawing.acceleration_scale_m_s2_per_mm",
        ),
    ] {
        let e = AnyScene::from_json(&scene(patch), "y.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{patch}: {e}");
    }
    let ok =
        AnyScene::from_json(&scene("\"divisions\": 12 => \"divisions\": 12"), "y.json").unwrap();
    assert_eq!(ok.procedure(), "scotch_yoke");
}

/// Near a locking position (L = a + R + 1e-5 mm) the offset crank's closed forms keep their
/// digits: S at 270° against a 50-digit evaluation of P·L/√(L² − (a − R sin θ)²) with the
/// same f64 inputs (L² − across² cancelled 4e-3 kg of 2.1e7 before).
#[test]
fn the_offset_cranks_rod_force_near_locking_keeps_its_digits() {
    use graphostatik::mechanisms::offset_crank::OffsetCrank;
    let k = OffsetCrank {
        crank_radius: 200.0,
        rod_length: 350.00001,
        offset: 150.0,
        crank_pin_speed: 5.0,
        piston_force: Some(5000.0),
    };
    let s = k.exact(270.0).rod_force.abs();
    // mpmath, 50 digits, on the f64 value of 350.00001.
    let truth = 20_916_501.137_967_157;
    assert!((s - truth).abs() <= 1e-12 * truth, "{s} against {truth}");
    let s = k.exact(269.99).rod_force.abs();
    let truth = 18_312_492.208_960_244;
    assert!((s - truth).abs() <= 1e-9 * truth, "{s} against {truth}");
}
