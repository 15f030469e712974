//! What one replay of a drag costs natively, on the path the browser engine runs on every
//! pointer move (`wasm/`): `web::replay_into` with the construction kept (read the scene,
//! construct it on a drawing board, draw the figure with the layout of the figure before it
//! while that holds and its labels placed, the current page's item, the checks and handles,
//! the answer as JSON), then `web::figure_patch_read` against the figure before it (read once, as kept), as JSON, for
//! every bundled scene. The scene's first handle is moved as the page's latency bench moves
//! it (0.5 to 2 mm of the sheet, a crank turned by 2 to 8 degrees; where it has none, its
//! first slider by 1 to 4 steps), the page on its last step as a live page opens.
//!
//! `cargo bench --bench replay` prints the table in Markdown (median and worst of 15 drags
//! after 3 to warm up; the patch's size; beside it the same replays and patches with each
//! figure laid out afresh, `web::replay_apart`); `cargo bench --bench replay -- otto` only
//! the scenes whose name holds `otto`.

use graphostatik::web::{figure_patch_read, replay_apart, replay_into, Ask, FigureLines};
use serde_json::Value;
use std::hint::black_box;
use std::time::Instant;

/// The scene `scene` with its first handle moved for the `i`-th drag, as the page's bench
/// moves it, or where it has none its first slider by 1 to 4 steps; `None` where the answer
/// has neither.
fn nudged(scene: &Value, answer: &Value, i: usize) -> Option<Value> {
    let Some(h) = answer["handles"].get(0) else {
        let sl = answer["sliders"].get(0)?;
        let (v, max) = (sl["value"].as_f64()?, sl["max"].as_f64()?);
        let m = (i % 4 + 1) as f64 * sl["step"].as_f64()?;
        let v = if v + m <= max { v + m } else { v - m };
        // A whole number as an integer, as the page writes it (a count of divisions).
        let v = match v.fract() == 0.0 && v.abs() < 1e15 {
            true => serde_json::json!(v as i64),
            false => serde_json::json!(v),
        };
        return put(scene, sl["field"].as_str()?, v);
    };
    let d = &h["drag"];
    let field = d["field"].as_str()?;
    let m = 0.5 * (i % 4 + 1) as f64;
    let now = scene.pointer(field);
    let value = match d["kind"].as_str()? {
        "point" => {
            let per = d["per_mm"].as_f64()?;
            let v = d["value"].as_array()?;
            let [x, y] = [v.first()?.as_f64()?, v.get(1)?.as_f64()?];
            serde_json::json!([x + m * per, y + m * per])
        }
        _ => {
            let v = now.and_then(Value::as_f64).or_else(|| {
                let (at, c) = (&h["at"], &h["center"]);
                let (ax, ay, cx, cy) = (
                    at[0].as_f64()?,
                    at[1].as_f64()?,
                    c[0].as_f64()?,
                    c[1].as_f64()?,
                );
                let (zero, sense) = (d["zero_deg"].as_f64()?, d["sense"].as_f64()?);
                Some(zero + sense * (cy - ay).atan2(ax - cx).to_degrees())
            })?;
            serde_json::json!((v + 4.0 * m).rem_euclid(360.0))
        }
    };
    put(scene, field, value)
}

/// `scene` with the value at the JSON pointer `field` set to `value` (a key added where the
/// object has none).
fn put(scene: &Value, field: &str, value: Value) -> Option<Value> {
    let mut out = scene.clone();
    let (parent, key) = field.rsplit_once('/')?;
    match out.pointer_mut(parent)? {
        Value::Object(o) => {
            o.insert(key.to_string(), value);
        }
        Value::Array(a) => *a.get_mut(key.parse::<usize>().ok()?)? = value,
        _ => return None,
    }
    Some(out)
}

/// Median and worst of `t` (ms).
fn median_worst(mut t: Vec<f64>) -> (f64, f64) {
    t.sort_by(f64::total_cmp);
    (t[t.len() / 2], t[t.len() - 1])
}

fn main() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    // `cargo bench` passes `--bench` to the binary: the first other argument is the filter.
    let only = std::env::args().skip(1).find(|a| !a.starts_with("--"));
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .filter(|p| {
            only.as_ref()
                .is_none_or(|o| p.to_string_lossy().contains(o.as_str()))
        })
        .collect();
    paths.sort();
    println!(
        "| scene | drag median ms | worst ms | patch bytes, median | laid out afresh: median ms |"
    );
    println!("|---|---:|---:|---:|---:|");
    let (mut total, mut total_afresh) = (0.0, 0.0);
    let mut still = Vec::new();
    for path in &paths {
        let text = std::fs::read_to_string(path).unwrap();
        let name = path.file_stem().unwrap().to_string_lossy().to_string();
        let origin = format!("{name}.json");
        let scene: Value = serde_json::from_str(&text).unwrap();
        // The page as it opens: the answer when the pointer rests, its last page shown.
        let mut kept = None;
        let (first, svg) = replay_into(&mut kept, &text, &origin, Ask::Lines);
        let answer: Value = serde_json::from_str(&first).unwrap();
        let page = answer["page_count"].as_u64().unwrap_or(1).saturating_sub(1) as usize;
        let mut shown = svg.unwrap_or_default();
        let mut shown_read = FigureLines::of(&shown);
        let (mut shown_afresh, mut afresh_read) = (shown.clone(), shown_read.clone());
        let Some(texts) = (0..18)
            .map(|i| nudged(&scene, &answer, i).map(|s| s.to_string()))
            .collect::<Option<Vec<String>>>()
        else {
            still.push(name);
            continue;
        };
        let (mut drag, mut afresh, mut bytes) = (Vec::new(), Vec::new(), Vec::new());
        for (i, t) in texts.iter().enumerate() {
            let s = Instant::now();
            let (json, svg) = replay_into(&mut kept, t, &origin, Ask::Page(page));
            let read = svg.as_deref().map(FigureLines::of);
            let patch = svg.as_deref().zip(read.as_ref()).and_then(|(new, r)| {
                let p = figure_patch_read(&shown, &shown_read, new, r)?.to_json();
                Some(p)
            });
            let ms = s.elapsed().as_secs_f64() * 1e3;
            assert!(
                json.starts_with("{\"ok\":true"),
                "{name}, drag {i}: {json:.200}"
            );
            if let (Some(svg), Some(read)) = (svg, read) {
                (shown, shown_read) = (svg, read);
            }
            let s = Instant::now();
            let (json, svg) = replay_apart(t, &origin, Some(page));
            let read = FigureLines::of(&svg);
            black_box((
                &json,
                figure_patch_read(&shown_afresh, &afresh_read, &svg, &read).map(|p| p.to_json()),
            ));
            let fresh_ms = s.elapsed().as_secs_f64() * 1e3;
            (shown_afresh, afresh_read) = (svg, read);
            if i >= 3 {
                drag.push(ms);
                afresh.push(fresh_ms);
                bytes.push(patch.map_or(0.0, |p| p.len() as f64));
            }
        }
        let ((m, worst), (a, _), (b, _)) = (
            median_worst(drag),
            median_worst(afresh),
            median_worst(bytes),
        );
        total += m;
        total_afresh += a;
        println!("| {name} | {m:.2} | {worst:.2} | {b:.0} | {a:.2} |");
    }
    println!(
        "\nsum of the medians: {total:.1} ms a drag, {total_afresh:.1} ms laid out afresh, over {} scenes",
        paths.len() - still.len()
    );
    if !still.is_empty() {
        println!("nothing to drag or slide: {}", still.join(", "));
    }
}
