//! Combustion engines (KG Abb. 1056-1060).

use graphostatik::dynamics::combustion::*;
use graphostatik::dynamics::model::{area_cm2, Kinematics};

fn diesel(strokes: Strokes) -> GasCycle {
    GasCycle {
        strokes,
        combustion: Combustion::ConstantPressure { cutoff: 0.08 },
        compression_ratio: 14.0,
        charge_at: 0.95,
        peak_at: 33.0,
        n_compression: 1.35,
        n_expansion: 1.3,
        release: 0.9,
        exhaust_at: 1.1,
    }
}

#[test]
fn the_turning_force_does_the_indicated_work() {
    let k = Kinematics {
        r: 150.0,
        lambda: 0.2,
        v: 150.0 / 1000.0 * 2.0 * std::f64::consts::PI * 300.0 / 60.0,
    };
    for strokes in [Strokes::Four, Strokes::Two] {
        for mass in [0.0, 30.0] {
            let cyls: Vec<GasCylinder> = (0..3)
                .map(|i| GasCylinder {
                    name: format!("{i}"),
                    area_cm2: area_cm2(250.0, 0.0),
                    cycle: diesel(strokes),
                    mass,
                    fires_at: strokes.cycle_deg() * i as f64 / 3.0,
                })
                .collect();
            let cycle = strokes.cycle_deg();
            let exact = mean_turning_force(&k, &cyls, cycle);
            let work = mean_from_work(&k, &cyls, cycle);
            assert!(
                (exact - work).abs() < 1e-7 * work.abs(),
                "{strokes:?} {mass}: {exact} {work}"
            );
        }
    }
}

fn engine(strokes: Strokes, combustion: Combustion, n: usize, mass: f64) -> GasEngine {
    let mut c = diesel(strokes);
    c.combustion = combustion;
    if combustion == Combustion::ConstantVolume {
        c.compression_ratio = 5.5;
        c.peak_at = 25.0;
    }
    let cycle = strokes.cycle_deg();
    GasEngine {
        kinematics: Kinematics {
            r: 150.0,
            lambda: 0.2,
            v: 4.7,
        },
        cylinders: (0..n)
            .map(|i| GasCylinder {
                name: format!("{}", i + 1),
                area_cm2: area_cm2(250.0, 0.0),
                cycle: c,
                mass,
                fires_at: cycle * i as f64 / n as f64,
            })
            .collect(),
        cycle_deg: cycle,
    }
}

/// Four-stroke Diesel and Otto, two-stroke Otto with its peak at the firing dead centre,
/// with and without inertia, one and four cylinders: every check passes (gas and resulting
/// forces, the polar construction's T, the turning force, the mean of the ordinates), and
/// the drawn mean approaches the exact one.
#[test]
fn the_forces_are_constructed_and_checked() {
    use graphostatik::protocol::Board;
    for (strokes, comb) in [
        (Strokes::Four, Combustion::ConstantPressure { cutoff: 0.08 }),
        (Strokes::Four, Combustion::ConstantVolume),
        (Strokes::Two, Combustion::ConstantVolume),
    ] {
        for (cyls, mass) in [(1, 0.0), (4, 25.0)] {
            let e = engine(strokes, comb, cyls, mass);
            let d = GasDrawing {
                length_scale: 10.0,
                force_scale: 500.0,
                mm_per_deg: 0.25,
            };
            let mut b = Board::recording();
            let r = construct(&mut b, &e, &d, 72).unwrap();
            let failed: Vec<String> = b
                .checks()
                .filter(|c| !c.passed)
                .map(|c| format!("{c:?}"))
                .collect();
            assert!(
                failed.is_empty(),
                "{strokes:?} {comb:?} {cyls}: {failed:#?}"
            );
            let rel = (r.t_m - r.t_m_exact).abs() / r.t_m_exact.abs();
            assert!(
                rel < 0.05,
                "{strokes:?} {comb:?} {cyls}: {} {}",
                r.t_m,
                r.t_m_exact
            );
            // The two-stroke Otto peaks at the dead centre, where T vanishes: finite, zero.
            if strokes == Strokes::Two && cyls == 1 {
                assert!(r.rows[0].cylinders[0][2].abs() < 1e-9 * r.rows[0].cylinders[0][0].abs());
            }
        }
    }
}

/// Bad input: one line naming the field (a compression ratio ≤ 1, pressures at or below
/// absolute zero, a peak below the compression's end, a firing order that misses a cylinder,
/// inertia without the weight).
#[test]
fn bad_combustion_input_names_the_field() {
    use graphostatik::scene::AnyScene;
    let text = include_str!("../../scenes/kg_abb1056_otto_four_cylinders.json");
    for (from, to, field) in [
        (
            "\"compression_ratio\": 5",
            "\"compression_ratio\": 1",
            "gas.compression_ratio",
        ),
        (
            "\"compression_ratio\": 5",
            "\"compression_ratio\": 0.5",
            "gas.compression_ratio",
        ),
        ("\"charge_at\": 0.9", "\"charge_at\": -0.2", "gas.charge_at"),
        ("\"charge_at\": 0.9", "\"charge_at\": 0", "gas.charge_at"),
        ("\"peak_at\": 25", "\"peak_at\": 5", "gas.peak_at"),
        ("[1, 3, 4, 2]", "[1, 3, 3, 2]", "cylinders.firing_order"),
        ("[1, 3, 4, 2]", "[]", "cylinders.firing_order"),
        (
            ", \"reciprocating_kg\": 1.2",
            "",
            "cylinders.reciprocating_kg",
        ),
        (
            "\"n_expansion\": 1.3",
            "\"n_expansion\": 0.5",
            "gas.n_expansion",
        ),
        ("\"release\": 0.9", "\"release\": 1.5", "gas.release"),
        ("\"divisions\": 24", "\"divisions\": 3", "divisions"),
    ] {
        assert!(text.contains(from), "{from}");
        let e = AnyScene::from_json(&text.replace(from, to), "e.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{to}: {e}");
    }
}

/// The four-cylinder engine firing 1-3-4-2 every 180°: its turning force repeats every half
/// turn, and each cylinder fires when its crank stands at its cover-side dead centre.
#[test]
fn the_firing_order_spaces_the_cylinders() {
    use graphostatik::scene::{AnyScene, CombustionScene};
    let text = include_str!("../../scenes/kg_abb1056_otto_four_cylinders.json");
    let p = AnyScene::from_json(text, "e.json")
        .unwrap()
        .problem()
        .get::<CombustionScene>()
        .unwrap()
        .clone();
    let e = &p.engine;
    let fires: Vec<f64> = e.cylinders.iter().map(|c| c.fires_at).collect();
    assert_eq!(fires, vec![0.0, 540.0, 180.0, 360.0]);
    for c in &e.cylinders {
        assert_eq!(c.angles(c.fires_at), (0.0, 0.0));
    }
    for t in [10.0, 77.0, 133.0] {
        let a = turning_force(&e.kinematics, &e.cylinders, t);
        let b = turning_force(&e.kinematics, &e.cylinders, t + 180.0);
        assert!((a - b).abs() < 1e-9 * a.abs().max(1.0), "{t}: {a} {b}");
    }
}
