//! Every bundled scene translated far from the origin constructs the same
//! to about 1e-12 relative: the constructions and the closed forms work in the scene's own
//! frame, not in absolute sheet coordinates.

use graphostatik::protocol::BoardConfig;
use graphostatik::scene::AnyScene;
use serde_json::Value;

/// The fields that hold a position in the scene's frame (metres): shifted by `dx` in x (and
/// in y where they are points).
fn shift(v: &mut Value, dx: f64) {
    match v {
        Value::Object(map) => {
            for (k, val) in map.iter_mut() {
                match k.as_str() {
                    "at_m" => shift_point(val, dx),
                    "polygon_m" => val
                        .as_array_mut()
                        .into_iter()
                        .flatten()
                        .for_each(|p| shift_point(p, dx)),
                    "supports_m" | "ends_m" | "stringers_m" => val
                        .as_array_mut()
                        .into_iter()
                        .flatten()
                        .for_each(|x| add(x, dx)),
                    "x_m" | "from_m" | "to_m" => add(val, dx),
                    _ => shift(val, dx),
                }
            }
        }
        Value::Array(a) => a.iter_mut().for_each(|x| shift(x, dx)),
        _ => {}
    }
}

fn add(x: &mut Value, dx: f64) {
    if let Some(f) = x.as_f64() {
        *x = Value::from(f + dx);
    }
}

fn shift_point(p: &mut Value, dx: f64) {
    p.as_array_mut()
        .into_iter()
        .flatten()
        .for_each(|x| add(x, dx));
}

/// The largest check error of a scene, relative to each check's natural magnitude.
fn worst_relative(text: &str, name: &str) -> (f64, usize, String) {
    let p = AnyScene::from_json(text, name).unwrap().into_problem();
    let b = p
        .construct(BoardConfig::DRAWING)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut worst = (0.0, 0, String::new());
    for c in b.checks() {
        let rel = c.error / c.closed_form.abs().max(c.reference.abs());
        // A check whose tolerance is a model's stated bound (a rule against the exact
        // value) is judged by its own tolerance, not by rounding.
        let model = c.tolerance > 1.01e-9 * c.closed_form.abs().max(c.reference.abs());
        if !model && rel > worst.0 {
            worst = (rel, 0, c.quantity.to_string());
        }
        assert!(
            c.passed,
            "{name}: {} {} vs {}",
            c.quantity, c.constructed, c.closed_form
        );
    }
    worst.1 = b.checks().count();
    worst
}

#[test]
fn every_bundled_scene_far_from_the_origin_keeps_its_digits() {
    let (mut shifted, mut worst) = (0, 0.0f64);
    for path in super::support::bundled_scenes() {
        let text = std::fs::read_to_string(&path).unwrap();
        let base: Value = serde_json::from_str(&text).unwrap();
        for dx in [1e3, 1e6, 1e8] {
            let mut v = base.clone();
            shift(&mut v, dx);
            if v == base {
                break; // nothing in the scene is placed in a frame (a crank): nothing to shift
            }
            let name = format!("{} at {dx:e} m", path.display());
            let (rel, n, what) = worst_relative(&v.to_string(), &name);
            assert!(n > 0, "{name}");
            assert!(rel <= 1e-12, "{name}: {what} off by {rel:e} relative");
            worst = worst.max(rel);
            shifted += 1;
        }
    }
    // 18 scenes place something in a frame (the cranks do not), each at three distances.
    assert!(shifted >= 54, "{shifted} shifted constructions");
    eprintln!("{shifted} shifted constructions, largest check error {worst:e} relative");
}
