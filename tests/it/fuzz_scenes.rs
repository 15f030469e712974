//! Mutated scenes, as a careless or hostile user writes them: every bundled scene with a key
//! deleted, a value retyped, an extreme number, a control character or a long string put in.
//! Each goes the whole way a user's file goes (parse, validate, construct on a recording
//! board, draw the figure), in a thread of its own with a time limit. The promises: no panic,
//! no hang, an error is one line naming the file, a check table holds no NaN or infinity,
//! and a figure holds nothing XML forbids.
//!
//! The seed is fixed (`FUZZ_SEED` picks another), so a failure repeats; the budget
//! (`FUZZ_SECONDS`, default 40 s) bounds the run on CI's two cores.

use graphostatik::protocol::BoardConfig;
use graphostatik::render;
use graphostatik::scene::AnyScene;
use serde_json::Value;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use super::support::Rng;

/// Every path to a value in the document (object keys and array indices).
fn paths(v: &Value, here: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
    out.push(here.clone());
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                here.push(Value::String(k.clone()));
                paths(x, here, out);
                here.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                here.push(Value::from(i));
                paths(x, here, out);
                here.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut Value, path: &[Value]) -> &'a mut Value {
    let mut cur = v;
    for p in path {
        cur = match p {
            Value::String(k) => &mut cur[k.as_str()],
            Value::Number(i) => &mut cur[i.as_u64().unwrap() as usize],
            _ => unreachable!(),
        };
    }
    cur
}

/// Numbers a careless hand or a hostile one types.
const EXTREMES: [f64; 12] = [
    0.0, -0.0, -1.0, 1e-300, -1e-300, 1e300, -1e300, 1e12, 1e-12, 4.9e-324, 0.5, 3600.0,
];

/// One mutation of the scene at a random place.
fn mutate(doc: &Value, rng: &mut Rng) -> (String, Value) {
    let mut all = Vec::new();
    paths(doc, &mut Vec::new(), &mut all);
    let path = all[rng.below(all.len())].clone();
    let mut v = doc.clone();
    let what;
    match rng.below(7) {
        0 if !path.is_empty() => {
            let (last, parent) = path.split_last().unwrap();
            let p = at(&mut v, parent);
            match (p, last) {
                (Value::Object(m), Value::String(k)) => {
                    m.remove(k);
                }
                (Value::Array(a), Value::Number(i)) => {
                    a.remove(i.as_u64().unwrap() as usize);
                }
                _ => {}
            }
            what = "deleted";
        }
        1 => {
            *at(&mut v, &path) = Value::from(EXTREMES[rng.below(EXTREMES.len())]);
            what = "extreme number";
        }
        2 => {
            *at(&mut v, &path) = Value::from("x\u{0}\u{1b}<&\"\n|=");
            what = "control characters";
        }
        3 => {
            *at(&mut v, &path) = Value::from("n".repeat(300 + rng.below(300)));
            what = "long string";
        }
        4 => {
            let x = at(&mut v, &path).clone();
            *at(&mut v, &path) = Value::Array(vec![x.clone(), x]);
            what = "doubled into an array";
        }
        5 => {
            let target = at(&mut v, &path);
            if let Value::Array(a) = target {
                if let Some(first) = a.first().cloned() {
                    a.push(first);
                }
            }
            what = "array element repeated";
        }
        _ => {
            *at(&mut v, &path) = match rng.below(4) {
                0 => Value::Null,
                1 => Value::Bool(true),
                2 => Value::from(-7),
                _ => Value::Object(Default::default()),
            };
            what = "retyped";
        }
    }
    (format!("{what} at {path:?}"), v)
}

/// The whole way of a file: parse, validate, construct (recording), draw. Returns the error
/// line, if any.
fn run(text: &str) -> Result<(), String> {
    // As the command line prints an error: graphostatik::fmt::error_line.
    let line = |e: String| graphostatik::fmt::error_line(&e);
    let scene = AnyScene::from_json(text, "fuzz.json").map_err(|e| line(e.to_string()))?;
    let problem = scene.problem();
    let board =
        problem
            .construct(BoardConfig::DRAWING)
            .map_err(|e| match problem.error_field(&e) {
                Some(field) => line(format!("fuzz.json: {field}: {e}")),
                None => line(format!("fuzz.json: {e}")),
            })?;
    // An accepted scene's check table holds numbers: no NaN, no infinity.
    for c in board.checks() {
        let row = [c.constructed, c.closed_form, c.error, c.tolerance, c.bound];
        if !row.iter().all(|x| x.is_finite()) {
            return Err(format!("BUG: {} is {row:?} in the check table", c.quantity));
        }
    }
    let svg = render::figure(&problem.figure_meta(), &board, None);
    let forbidden = |c: char| (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{fffe}';
    if svg.chars().any(forbidden) {
        return Err("BUG: the figure holds a character XML forbids".into());
    }
    Ok(())
}

#[test]
fn mutated_scenes_never_panic_hang_or_answer_in_more_than_one_line() {
    let budget = std::env::var("FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(40.0);
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<(String, Value)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (
                p.display().to_string(),
                serde_json::from_str(&text).unwrap(),
            )
        })
        .collect();
    scenes.sort_by(|a, b| a.0.cmp(&b.0));
    let seed = std::env::var("FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_6a5f_1922_0001);
    let mut rng = Rng(seed);
    let start = Instant::now();
    let (mut runs, mut refused) = (0usize, 0usize);
    while start.elapsed().as_secs_f64() < budget {
        let (name, doc) = &scenes[runs % scenes.len()];
        let (what, mutated) = mutate(doc, &mut rng);
        let text = mutated.to_string();
        let (tx, rx) = mpsc::channel();
        let job = text.clone();
        std::thread::spawn(move || {
            let r = std::panic::catch_unwind(|| run(&job));
            let _ = tx.send(r);
        });
        match rx.recv_timeout(Duration::from_secs(20)) {
            Err(_) => panic!("{name}, {what}: no answer in 20 s (a hang)"),
            Ok(Err(_)) => panic!("{name}, {what}: a panic"),
            Ok(Ok(Err(e))) => {
                assert!(!e.starts_with("BUG"), "{name}, {what}: {e}");
                assert_eq!(e.lines().count(), 1, "{name}, {what}: {e}");
                assert!(e.starts_with("fuzz.json"), "{name}, {what}: {e}");
                assert!(
                    e.len() < 2000,
                    "{name}, {what}: an error of {} bytes",
                    e.len()
                );
                refused += 1;
            }
            Ok(Ok(Ok(()))) => {}
        }
        runs += 1;
    }
    eprintln!("{runs} mutated scenes in {budget} s, {refused} refused with one line");
    assert!(
        runs >= scenes.len(),
        "every scene was mutated at least once"
    );
}
