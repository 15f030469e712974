//! What the engine's dynamics cost, and what each rule of LH G gives: the locomotive of LH J
//! (both cylinders at 90°, inertia by Radinger's q, turning-force diagram) at 20, 360 and
//! 3,600 crank divisions, constructed (a) as the bare model sampled at the divisions with the
//! trapezoid rule, (b) on a board that does not record, (c) recorded with every check, the
//! whole path of `graphostatik check` short of printing. Then, per rule, the error of T_m and
//! of the power against the exact integral.
//!
//! `cargo bench --bench dynamics` prints two Markdown tables. Target: (c) at 360 divisions
//! under 5 ms.

use graphostatik::dynamics::{model, rules};
use graphostatik::protocol::BoardConfig;
use graphostatik::scene::Procedure;
use graphostatik::scene::{AnyScene, DynamicsProblem, DynamicsScene};
use std::hint::black_box;
use std::time::Instant;

fn problem(divisions: usize) -> DynamicsProblem {
    let text = include_str!("../scenes/lh_j_locomotive_dynamics.json");
    let mut v: serde_json::Value = serde_json::from_str(text).unwrap();
    v["divisions"] = divisions.into();
    let s = AnyScene::from_json(&v.to_string(), "bench").unwrap();
    s.problem().get::<DynamicsScene>().unwrap().clone()
}

/// (a): the model's turning force at the divisions, its trapezoid mean.
fn sampled(p: &DynamicsProblem) -> f64 {
    let e = &p.engine;
    let n = match p.rays {
        graphostatik::crank::Angles::Divisions(n) => n,
        _ => unreachable!("the benchmark divides the circle"),
    };
    let mut ords: Vec<f64> = (0..n)
        .map(|k| {
            let t = 360.0 * k as f64 / n as f64;
            model::turning_force(&e.kinematics, &e.cylinders, e.efficiency, t)
        })
        .collect();
    ords.push(ords[0]);
    rules::trapezoid(&ords)
}

fn median_ms(f: &dyn Fn()) -> f64 {
    let mut s: Vec<f64> = (0..15)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    s.sort_by(f64::total_cmp);
    s[s.len() / 2]
}

fn main() {
    println!(
        "| divisions | (a) sampled model | (b) construction | (c) recorded + checked | checks |"
    );
    println!("|---:|---:|---:|---:|---:|");
    for n in [20usize, 360, 3600] {
        let p = problem(n);
        let a = median_ms(&|| {
            black_box(sampled(&p));
        });
        let b = median_ms(&|| {
            black_box(DynamicsScene::construct(&p, BoardConfig::SILENT).unwrap());
        });
        let c = median_ms(&|| {
            let (board, _) = DynamicsScene::construct(&p, BoardConfig::DRAWING).unwrap();
            assert!(board.all_passed());
            black_box(board);
        });
        let (board, _) = DynamicsScene::construct(&p, BoardConfig::DRAWING).unwrap();
        println!(
            "| {n} | {a:.3} ms | {b:.3} ms | {c:.3} ms | {} |",
            board.checks().count()
        );
    }
    println!();
    println!("| divisions | rule | T_m [kg] | error of T_m | error of the power [PS] |");
    println!("|---:|---|---:|---:|---:|");
    for n in [20usize, 360, 3600] {
        let p = problem(n);
        let (_, res) = DynamicsScene::construct(&p, BoardConfig::SILENT).unwrap();
        let v = p.engine.kinematics.v;
        for m in &res.mean_heights {
            println!(
                "| {n} | {} | {:.1} | {:+.3e} kg ({:+.2e}) | {:+.3e} |",
                m.rule,
                m.t_m,
                m.error,
                m.error / res.t_m_exact.unwrap(),
                model::power_from_turning(m.error, v)
            );
        }
    }
    let p = problem(20);
    let exact = p.engine.t_m();
    println!();
    println!(
        "exact T_m = {exact:.4} kg, power {:.4} PS (both cylinders)",
        model::power_from_turning(exact, p.engine.kinematics.v)
    );
}
