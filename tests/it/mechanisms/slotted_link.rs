//! The oscillating slotted link (KG XIV, Abb. 1071-1072): the table's path and
//! speed by KG's construction against the loop's closed forms, c₁ and c₂ against KG 304-305,
//! β/α for any e > r, and the refusal at e ≤ r.

use graphostatik::mechanisms::slotted_link::*;
use graphostatik::protocol::{Board, ConstructionError};
use proptest::prelude::*;

const V: LinkRequest = LinkRequest { velocity: true };

fn link(r: f64, e: f64, l: f64) -> SlottedLink {
    SlottedLink {
        crank_radius: r,
        centre_distance: e,
        lever_length: l,
        crank_pin_speed: 1.2,
    }
}

fn scales(k: &SlottedLink) -> LinkScales {
    LinkScales {
        length: k.lever_length / 100.0,
        velocity: k.c2() / 40.0,
    }
}

/// Every 5° of the crank, both strokes: every check passes (path, speed, 2β, β/α, stroke, c₁,
/// c₂), the speed is positive on the working stroke (2α of crank angle) and negative on the
/// return, and the mean speeds are in the ratio β/α.
#[test]
fn the_table_follows_the_loop_and_kg_304_305() {
    let k = link(100.0, 200.0, 500.0);
    let phis: Vec<f64> = (0..72).map(|i| 5.0 * i as f64).collect();
    let mut b = Board::recording();
    let r = construct(&mut b, &k, scales(&k), &phis, V).unwrap();
    let failed: Vec<String> = b
        .checks()
        .filter(|c| !c.passed)
        .map(|c| format!("{c:?}"))
        .collect();
    assert!(failed.is_empty(), "{failed:#?}");
    assert!((r.beta - 60.0).abs() < 1e-12 && (r.alpha - 120.0).abs() < 1e-12);
    assert!((r.stroke - 500.0).abs() < 1e-9);
    for row in &r.rows {
        let c = row.c.unwrap();
        if row.phi > 0.0 && row.phi < 240.0 {
            assert!(c > 0.0, "{row:?}");
        } else if row.phi > 240.0 {
            assert!(c < 0.0, "{row:?}");
        }
    }
    // The mean speeds: the stroke over the time of 2α and of 2β.
    let (c1, c2) = r.c1_c2.unwrap();
    assert!((c1 - 1.2 * 500.0 / 300.0).abs() < 1e-12 && (c2 - 1.2 * 5.0).abs() < 1e-12);
    let checks = b.checks().count();
    assert!(checks >= 2 * 72 + 5, "{checks}");
}

/// As e approaches r the return speed grows as 1/(e − r) and the construction still agrees
/// with KG 305 (the cuts near D glance, and say so); at e = r and below it is refused,
/// naming the centre distance.
#[test]
fn the_return_speed_grows_without_bound_and_e_at_r_is_refused() {
    for excess in [1e-1, 1e-3, 1e-6] {
        let k = link(100.0, 100.0 * (1.0 + excess), 500.0);
        let mut b = Board::recording();
        let r = construct(&mut b, &k, scales(&k), &[0.0, 90.0], V).unwrap();
        assert!(b.all_passed(), "excess {excess}");
        let (_, c2) = r.c1_c2.unwrap();
        assert!(
            (c2 / (1.2 * 500.0 / (100.0 * excess)) - 1.0).abs() < 1e-6,
            "{c2}"
        );
        assert!(r.ratio < 1.0);
    }
    for e in [100.0, 99.0, 0.0] {
        let k = link(100.0, e, 500.0);
        let err = construct(
            &mut Board::recording(),
            &k,
            LinkScales {
                length: 5.0,
                velocity: 0.1,
            },
            &[0.0],
            V,
        )
        .unwrap_err();
        match err {
            ConstructionError::Unsupported { input, reason } => {
                assert_eq!(
                    input.to_string(),
                    if e > 0.0 {
                        "centre_distance"
                    } else {
                        "crank_radius"
                    }
                );
                assert!(!reason.contains('\n'), "{reason}");
            }
            other => panic!("{other:?}"),
        }
    }
    let short = link(100.0, 200.0, 299.0);
    let err = construct(
        &mut Board::recording(),
        &short,
        LinkScales {
            length: 5.0,
            velocity: 0.1,
        },
        &[0.0],
        V,
    )
    .unwrap_err();
    assert!(
        matches!(err, ConstructionError::Unsupported { ref input, .. } if *input == "lever_length"),
        "{err:?}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any link with e > r and R ≥ e + r, any crank angle: KG's construction agrees with the
    /// loop's closed form, and β/α = arccos(r/e)/(180° − arccos(r/e)).
    #[test]
    fn any_quick_return_link_agrees(r in 10.0f64..500.0, e_over in 1.01f64..5.0, l_over in 1.0f64..3.0, phi in 0.0f64..360.0) {
        let e = r * e_over;
        let k = link(r, e, (e + r) * l_over);
        let mut b = Board::recording();
        let res = construct(&mut b, &k, scales(&k), &[phi], V).unwrap();
        prop_assert!(b.all_passed());
        let (s, c) = k.exact(phi);
        prop_assert!((res.rows[0].s - s).abs() < 1e-9 * k.lever_length);
        prop_assert!((res.rows[0].c.unwrap() - c).abs() < 1e-9 * k.c2());
        // The speed is the path's derivative: ds/dφ · v/r (central difference).
        let h = 1e-4;
        let ds = (k.exact(phi + h).0 - k.exact(phi - h).0) / (2.0 * h.to_radians());
        prop_assert!((ds * k.crank_pin_speed / r - c).abs() < 1e-6 * k.c2(), "{ds} {c}");
        let beta = (r / e).acos().to_degrees();
        prop_assert!((res.ratio - beta / (180.0 - beta)).abs() < 1e-10);
    }
}

fn scene(patch: &str) -> String {
    super::patched("kg_abb1071_slotted_link.json", patch)
}

/// Bad input: one line naming the field (e ≤ r, a lever too short for the slot, non-positive
/// lengths, rod arcs asked of a link).
#[test]
fn a_slotted_link_scene_names_what_is_wrong() {
    use graphostatik::scene::AnyScene;
    for (patch, field) in [
        (
            "\"centre_distance_mm\": 200 => \"centre_distance_mm\": 80",
            "link.centre_distance_mm",
        ),
        (
            "\"centre_distance_mm\": 200 => \"centre_distance_mm\": 79.999",
            "link.centre_distance_mm",
        ),
        ("\"lever_mm\": 500 => \"lever_mm\": 279", "link.lever_mm"),
        (
            "\"crank_radius_mm\": 80 => \"crank_radius_mm\": -80",
            "link.crank_radius_mm",
        ),
        (
            "\"crank_radius_mm\": 80 => \"crank_radius_mm\": 0",
            "link.crank_radius_mm",
        ),
        (
            "\"divisions\": 24 => \"stroke_parts\": 4",
            "angles.stroke_parts",
        ),
        ("\"rpm\": 30 => \"rpm\": -30", "speed.rpm"),
        (
            "\"velocity_scale_m_s_per_mm\": 0.02 => \"velocity_scale_m_s_per_mm\": 1e9",
            "drawing.velocity_scale_m_s_per_mm",
        ),
    ] {
        let e = AnyScene::from_json(&scene(patch), "l.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{patch}: {e}");
    }
    let ok = AnyScene::from_json(&scene("\"rpm\": 30 => \"rpm\": 30"), "l.json").unwrap();
    assert_eq!(ok.procedure(), "slotted_link");
}
