//! The steam engine with a directly driven double-acting pump (KG Abb. 1053, 1065-1067): KG's
//! P_p1 and P_p2, the pump's rectangle laid against the steam force reduced by η, the work
//! balance of the mean turning force, the pump's resistance line, and bad pump input.

use graphostatik::dynamics::model::{self, area_cm2, Pump};
use graphostatik::protocol::BoardConfig;
use graphostatik::scene::Procedure;
use graphostatik::scene::{AnyScene, DynamicsProblem, DynamicsScene};

const SCENE: &str = include_str!("../../scenes/kg_abb1065_pump_engine.json");
const RESISTANCE: &str = include_str!("../../scenes/kg_abb1067_pump_resistance_line.json");

fn problem(text: &str) -> DynamicsProblem {
    AnyScene::from_json(text, "pump.json")
        .unwrap()
        .problem()
        .get::<DynamicsScene>()
        .unwrap()
        .clone()
}

/// KG: P_p1 = 3490 kg and P_p2 = 3710 kg from d = 28.5 cm, rod 7.5 cm, p_s = 0.45 at,
/// p_a = 5.4 at. The formulas give 3493.4 and 3712.1 kg: KG rounds to 10 kg.
#[test]
fn kg_pump_forces() {
    let p = Pump {
        plunger_cm2: area_cm2(285.0, 0.0),
        rod_cm2: area_cm2(75.0, 0.0),
        suction_at: 0.45,
        delivery_at: 5.4,
        efficiency: 0.9,
    };
    let (p1, p2) = p.forces();
    assert!(
        (p1 - 3493.38).abs() < 0.01 && (p2 - 3712.07).abs() < 0.01,
        "{p1} {p2}"
    );
    assert_eq!(
        ((p1 / 10.0).round() * 10.0, (p2 / 10.0).round() * 10.0),
        (3490.0, 3710.0)
    );
}

/// Every check of the bundled scene passes (the net piston force at every ray is η times the
/// steam force less the pump's rectangle); and the mean turning force obeys the work balance
/// T_m = η·T_m(steam alone) − (P_p1 + P_p2)/π (the pump takes P_p1·2R and P_p2·2R per turn of
/// 2πR; inertia does no net work).
#[test]
fn the_pump_takes_its_work_from_the_turning_force() {
    let p = problem(SCENE);
    let (board, _) = DynamicsScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
    let with = p.engine.t_m();
    let e = &p.engine;
    let pump = e.cylinders[0].pump.unwrap();
    let mut bare = e.cylinders.clone();
    bare[0].pump = None;
    let steam = model::mean_turning_force(&e.kinematics, &bare, 1.0);
    let (p1, p2) = pump.forces();
    let want = pump.efficiency * steam - (p1 + p2) / std::f64::consts::PI;
    assert!((with - want).abs() < 1e-9 * steam, "{with} {want}");
    // At the inner dead centre the drive carries the steam force and the pump's (KG Abb.
    // 1066): P = η·P_steam − P_p1 there.
    let x0 = e.kinematics.x_frac(0.0);
    let steam0 = bare[0].pressure_force(0.0, x0);
    assert!((e.cylinders[0].pressure_force(0.0, x0) - (0.9 * steam0 - p1)).abs() < 1e-9 * steam0);
}

/// Bad pump input: one line naming the field, as every scene error.
#[test]
fn bad_pump_input_names_the_field() {
    for (from, to, field) in [
        (
            "\"suction_at\": 0.45",
            "\"suction_at\": 1.2",
            "cylinders[0].pump.suction_at",
        ),
        (
            "\"suction_at\": 0.45",
            "\"suction_at\": -0.1",
            "cylinders[0].pump.suction_at",
        ),
        (
            "\"delivery_at\": 5.4",
            "\"delivery_at\": -2",
            "cylinders[0].pump.delivery_at",
        ),
        (
            "\"rod_mm\": 75,",
            "\"rod_mm\": 285,",
            "cylinders[0].pump.rod_mm",
        ),
        (
            "\"plunger_mm\": 285",
            "\"plunger_mm\": 0",
            "cylinders[0].pump.plunger_mm",
        ),
        (", \"pump\": true", "", "cylinders[0].pump"),
    ] {
        assert!(SCENE.contains(from), "{from}");
        let e = AnyScene::from_json(&SCENE.replace(from, to), "pump.json")
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains(field) && !e.contains('\n'), "{to}: {e}");
    }
    let no_pump = SCENE.replace(
        ",\n      \"pump\": { \"plunger_mm\": 285, \"rod_mm\": 75, \"suction_at\": 0.45, \"delivery_at\": 5.4 }",
        "",
    );
    assert_ne!(no_pump, SCENE);
    let e = AnyScene::from_json(&no_pump, "pump.json")
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("effects.pump"), "{e}");
}

/// KG Abb. 1067: the pump's resistance line T_p and the steam engine's turning force T_s,
/// every ordinate checked. T_p is the rectangle carried through the crank: nothing at the
/// dead centres, P_p itself where the rod stands square to the crank; T_s − T_p is the
/// turning force T of the diagram above at every ordinate; the mean of T_p tends to
/// (P_p1 + P_p2)/π, the pump's work per turn over the crank circle.
#[test]
fn kg_abb1067_resistance_line_beside_the_turning_force() {
    let p = problem(RESISTANCE);
    let (board, res) = DynamicsScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
    let (p1, p2) = p.engine.cylinders[0].pump.unwrap().forces();
    let r = res.resistance.as_ref().expect("asked for");
    assert_eq!(r.ordinates.len(), 24);
    for (&(theta, tp, ts), &(t_theta, t)) in r.ordinates.iter().zip(&res.turning) {
        assert_eq!(theta, t_theta);
        assert!(
            (ts - tp - t).abs() < 1e-6 * p2,
            "θ = {theta}: {ts} − {tp} ≠ {t}"
        );
        assert!(
            tp >= -1e-9 * p2,
            "θ = {theta}: a pump never drives, T_p = {tp}"
        );
        if theta % 180.0 == 0.0 {
            assert!(
                tp.abs() < 1e-9 * p2,
                "θ = {theta}: T_p = {tp} at a dead centre"
            );
        }
    }
    // At 90° the rod stands square to the crank only for the infinite rod; with R/L = 0.2
    // T_p = P_p1 there exactly (sin(φ + ψ)/cos ψ = 1 at φ = 90°).
    let at90 = r.ordinates.iter().find(|o| o.0 == 90.0).unwrap();
    assert!((at90.1 - p1).abs() < 1e-9 * p1, "{} {p1}", at90.1);
    let exact = (p1 + p2) / std::f64::consts::PI;
    assert!((r.mean_exact - exact).abs() < 1e-9 * exact);
    // 24 strips of the trapezoid rule: within 1 % of the exact mean, from below (the curve
    // is concave over most of each stroke).
    let rel = (r.mean - exact) / exact;
    assert!((-0.01..0.0).contains(&rel), "{} {exact} {rel}", r.mean);
    // Doubling the divisions brings the rule closer.
    let finer = problem(&RESISTANCE.replace("\"divisions\": 24", "\"divisions\": 48"));
    let (_, res48) = DynamicsScene::construct(&finer, BoardConfig::DRAWING).unwrap();
    let rel48 = (res48.resistance.unwrap().mean - exact) / exact;
    assert!(rel48.abs() < rel.abs() / 3.0, "{rel48} {rel}");
}

/// The resistance line is a pump's: without one the output is refused naming `outputs`.
#[test]
fn a_resistance_line_needs_a_pump() {
    let bare = RESISTANCE
        .replace(
            ",\n      \"pump\": { \"plunger_mm\": 285, \"rod_mm\": 75, \"suction_at\": 0.45, \"delivery_at\": 5.4 }",
            "",
        )
        .replace(", \"pump\": true", "");
    assert!(!bare.contains("plunger"));
    let e = AnyScene::from_json(&bare, "pump.json")
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains("outputs") && e.contains("resistance_line") && !e.contains('\n'),
        "{e}"
    );
}
