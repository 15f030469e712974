//! Bad input: one clear error naming the field, exit status 2, no panic, no output file.

use graphostatik::protocol::BoardConfig;
use graphostatik::scene::{Procedure, SceneError, SliderCrankScene};
use std::path::{Path, PathBuf};
use std::process::Command;

const GOOD: &str = r#"{
  "title": "t",
  "mechanism": { "crank_radius_mm": 300, "rod": { "length_mm": 1500 } },
  "speed": { "rpm": 100 },
  "piston_force": { "kg": 1000 },
  "angles": { "divisions": 12 },
  "outputs": ["piston_path", "tangential_force"]
}"#;

fn err(text: &str) -> String {
    match SliderCrankScene::read(text, "s.json") {
        Ok(_) => panic!("accepted: {text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_good_scene_is_accepted() {
    SliderCrankScene::read(GOOD, "s.json").unwrap();
}

#[test]
fn malformed_json_gives_line_and_column() {
    let e = err("{\n  \"title\": \"t\",\n  \"mechanism\": { ,\n}");
    assert!(e.starts_with("s.json:3:"), "{e}");
    match SliderCrankScene::read("{\n \"title\" 1}", "x") {
        Err(SceneError::Json { line, column, .. }) => assert_eq!((line, column), (2, 10)),
        other => panic!("{other:?}"),
    }
}

#[test]
fn unknown_and_missing_fields_are_named() {
    let e = err(&GOOD.replace("\"speed\"", "\"sped\""));
    assert!(e.contains("unknown field `sped`"), "{e}");
    let e = err(&GOOD.replace(
        "\"rod\": { \"length_mm\": 1500 }",
        "\"rod\": { \"length_mm\": 1500, \"mass_kg\": 3 }",
    ));
    assert!(e.contains("mechanism.rod") || e.contains("mass_kg"), "{e}");
    let e = err(&GOOD.replace("\"speed\": { \"rpm\": 100 },", ""));
    assert!(e.contains("missing field `speed`"), "{e}");
    let e = err(&GOOD.replace("\"crank_radius_mm\": 300", "\"crank_radius_mm\": \"300\""));
    assert!(e.contains("mechanism.crank_radius_mm"), "{e}");
    let e = err(&GOOD.replace("\"tangential_force\"", "\"tangential_forse\""));
    assert!(
        e.contains("outputs[1]") && e.contains("tangential_forse"),
        "{e}"
    );
}

#[test]
fn non_positive_lengths_are_named() {
    let e = err(&GOOD.replace("\"crank_radius_mm\": 300", "\"crank_radius_mm\": -300"));
    assert!(
        e.contains("mechanism.crank_radius_mm") && e.contains("positive"),
        "{e}"
    );
    let e = err(&GOOD.replace("\"length_mm\": 1500", "\"length_mm\": 0"));
    assert!(e.contains("mechanism.rod.length_mm"), "{e}");
    let e = err(&GOOD.replace("\"rpm\": 100", "\"rpm\": 0"));
    assert!(e.contains("speed.rpm"), "{e}");
}

#[test]
fn a_rod_not_longer_than_the_crank_locks_the_mechanism() {
    let e = err(&GOOD.replace("\"length_mm\": 1500", "\"length_mm\": 300"));
    assert!(
        e.contains("mechanism.rod.length_mm") && e.contains("locks"),
        "{e}"
    );
    let e = err(&GOOD.replace("{ \"length_mm\": 1500 }", "{ \"l_over_r\": 0.5 }"));
    assert!(
        e.contains("mechanism.rod.l_over_r") && e.contains("locks"),
        "{e}"
    );
}

#[test]
fn crank_angles_out_of_range_and_absurd_division_counts() {
    let e = err(&GOOD.replace("{ \"divisions\": 12 }", "{ \"degrees\": [0, 90, 360] }"));
    assert!(
        e.contains("angles.degrees[2]") && e.contains("out of range"),
        "{e}"
    );
    let e = err(&GOOD.replace("{ \"divisions\": 12 }", "{ \"degrees\": [-5] }"));
    assert!(e.contains("angles.degrees[0]"), "{e}");
    let e = err(&GOOD.replace("\"divisions\": 12", "\"divisions\": 1000000"));
    assert!(e.contains("angles.divisions") && e.contains("3600"), "{e}");
    let e = err(&GOOD.replace("\"divisions\": 12", "\"divisions\": 1"));
    assert!(e.contains("angles.divisions"), "{e}");
    let e = err(&GOOD.replace("\"divisions\": 12", "\"divisions\": -3"));
    assert!(e.contains("angles.divisions"), "{e}");
}

#[test]
fn forces_need_a_piston_force() {
    let e = err(&GOOD.replace("\"piston_force\": { \"kg\": 1000 },", ""));
    assert!(e.contains("piston_force") && e.contains("missing"), "{e}");
    let e = err(&GOOD.replace("{ \"kg\": 1000 }", "{ \"per_angle_kg\": [1, 2] }"));
    assert!(
        e.contains("piston_force.per_angle_kg") && e.contains("12 crank angles"),
        "{e}"
    );
}

fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_graphostatik"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gs-bad-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn cli_exits_2_with_one_clear_line_and_writes_nothing() {
    let d = tmp("cli");
    let good = d.join("good.json");
    std::fs::write(&good, GOOD).unwrap();
    let bad = d.join("bad.json");
    std::fs::write(
        &bad,
        GOOD.replace("\"length_mm\": 1500", "\"length_mm\": 100"),
    )
    .unwrap();
    let out = d.join("out");
    // The good scene first: still nothing may be written, because the second one fails.
    let o = Command::new(bin())
        .args(["render"])
        .arg(&good)
        .arg(&bad)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.contains("bad.json") && stderr.contains("mechanism.rod.length_mm"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"));
    assert!(!out.exists());
    let svg = d.join("plot.svg");
    let plot = ["--svg", svg.to_str().unwrap()];
    for cmd in [
        &["check"][..],
        &["check", "--reference"],
        &["protocol"],
        &["accuracy"],
        &plot,
    ] {
        let cmd = if cmd[0] == "--svg" {
            [&["accuracy"][..], cmd].concat()
        } else {
            cmd.to_vec()
        };
        let o = Command::new(bin()).args(&cmd).arg(&bad).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{cmd:?}");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(
            stderr.contains("mechanism.rod.length_mm") && stderr.lines().count() == 1,
            "{cmd:?}: {stderr}"
        );
        assert!(!svg.exists(), "{cmd:?}: nothing is written");
    }
    let o = Command::new(bin())
        .arg("check")
        .arg(d.join("missing.json"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("missing.json"));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn cli_unwritable_output_folder() {
    let d = tmp("unwritable");
    let good = d.join("good.json");
    std::fs::write(&good, GOOD).unwrap();
    // A regular file where the output folder should be.
    let blocker = d.join("blocker");
    std::fs::write(&blocker, "x").unwrap();
    let o = Command::new(bin())
        .arg("render")
        .arg(&good)
        .arg("--out")
        .arg(blocker.join("figs"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot create the output folder"));
    // Nothing but the two inputs in the folder: no temporary file left behind.
    let mut names: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["blocker", "good.json"]);
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn cli_check_exit_status_and_schema() {
    let o = Command::new(bin())
        .args([
            "check",
            concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/kg_tafel1.json"),
        ])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&o.stdout).contains("36 checks, 36 passed, 0 failed"));
    let o = Command::new(bin()).arg("schema").output().unwrap();
    assert_eq!(o.status.code(), Some(0));
    let schema: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        schema["anyOf"].as_array().unwrap().len(),
        graphostatik::scene::REGISTRY.len()
    );
    assert!(schema["$defs"]["LinkScene"]["properties"]["link"].is_object());
    assert!(schema["$defs"]["YokeScene"]["properties"]["compare_rod"].is_object());
    let defs = &schema["$defs"];
    assert!(defs["SliderCrankScene"]["properties"]["mechanism"].is_object());
    assert!(defs["BeamScene"]["properties"]["beam"].is_object());
    assert!(defs["TrussScene"]["properties"]["load_cases"].is_object());
    assert!(defs["ForceSystemScene"]["properties"]["forces"].is_object());
    assert!(defs["DynamicsScene"]["properties"]["cylinders"].is_object());
    for s in ["SliderCrankScene", "BeamScene", "ForceSystemScene"] {
        assert_eq!(
            defs[s]["additionalProperties"],
            serde_json::Value::Bool(false)
        );
    }
}

#[test]
fn cli_steps_writes_a_walkthrough() {
    let d = tmp("steps");
    let o = Command::new(bin())
        .args([
            "steps",
            concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/scenes/lh_abb22_funicular.json"
            ),
            "--out",
        ])
        .arg(&d)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let index = std::fs::read_to_string(d.join("index.html")).unwrap();
    // Offline and self-contained: the figure is inlined, nothing is fetched.
    let no_namespaces = index
        .replace("xmlns=\"http://www.w3.org/2000/svg\"", "")
        .replace(
            "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"",
            "",
        );
    assert!(!no_namespaces.contains("http://") && !no_namespaces.contains("https://"));
    assert!(!index.contains("<script src") && !index.contains("<link") && !index.contains("<img"));
    assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1, "index.html only");
    assert_eq!(
        index.matches("<li data-first=").count(),
        51,
        "one page per step"
    );
    std::fs::remove_dir_all(&d).unwrap();
}

/// A large construction (KG Tafel I: hundreds of steps) is one page per step unless the
/// author groups it by context (`steps --group context`), and every step is listed either way.
#[test]
fn a_long_walkthrough_is_grouped_only_when_asked() {
    use graphostatik::render::{walkthrough_html, Grouping, WalkOptions};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/kg_tafel1.json");
    let p = graphostatik::scene::AnyScene::load(&path)
        .unwrap()
        .into_problem();
    let board = p.construct(BoardConfig::DRAWING).unwrap();
    let n = board.steps().len();
    let mut opts = WalkOptions::default();
    let one = walkthrough_html(&p.figure_meta(), &board, &opts);
    assert_eq!(one.matches("<li data-first=").count(), n);
    opts.grouping = Grouping::Context;
    let grouped = walkthrough_html(&p.figure_meta(), &board, &opts);
    let pages = grouped.matches("<li data-first=").count();
    assert!(pages < n / 4, "{pages} pages for {n} steps");
    for index in [&one, &grouped] {
        for s in board.steps() {
            assert!(
                index.contains(&format!("<b>{}</b>", s.id)),
                "step {} missing",
                s.id
            );
        }
    }
}

#[test]
fn a_closed_pipe_is_not_a_panic() {
    use std::io::Read;
    use std::process::Stdio;
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join("lh_aufgabe4_shed_roof.json");
    let mut child = Command::new(bin())
        .args(["protocol", scene.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 64];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The pipe's reading end is dropped here, long before the protocol (megabytes) is out.
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(o.status.code(), Some(0), "{err}");
}

/// Every scene shown in README.md and docs/ parses, validates and constructs with all checks
/// passing, so the documentation cannot drift from the format.
#[test]
fn the_scenes_in_the_docs_are_valid() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut docs = vec![root.join("README.md")];
    for e in std::fs::read_dir(root.join("docs")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "md") {
            docs.push(p);
        }
    }
    docs.sort();
    let mut n = 0;
    let texts: Vec<(String, String)> = docs
        .iter()
        .map(|p| (p.display().to_string(), std::fs::read_to_string(p).unwrap()))
        .collect();
    for (name, text) in &texts {
        for block in text.split("```json\n").skip(1) {
            let json = block.split("```").next().unwrap();
            let scene = graphostatik::scene::AnyScene::from_json(json, name)
                .unwrap_or_else(|e| panic!("{e}\n{json}"));
            let board = scene.problem().construct(BoardConfig::DRAWING).unwrap();
            assert!(board
                .steps()
                .iter()
                .flat_map(|s| &s.checks)
                .all(|c| c.passed));
            n += 1;
        }
    }
    assert!(n >= 6, "{n} scenes found");
}

#[test]
fn cli_names_an_unknown_procedure_and_lists_the_known_ones() {
    let dir = tmp("unknown-procedure");
    let scene = dir.join("bridge.json");
    std::fs::write(&scene, r#"{ "procedure": "bridge", "title": "t" }"#).unwrap();
    let out = dir.join("out");
    let o = Command::new(bin())
        .args([
            "render",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(e.contains("procedure: unknown procedure `bridge`; known: slider_crank, beam"));
    assert!(!out.exists(), "nothing written");
    // A syntax error in a beam scene is reported where it is, not as a slider-crank field.
    std::fs::write(
        &scene,
        "{\n  \"procedure\": \"beam\",\n  \"title\": \"t\",\n  \"beam\": { \"supports_m\": [0, NaN] }\n}",
    )
    .unwrap();
    let o = Command::new(bin())
        .args(["check", scene.to_str().unwrap()])
        .output()
        .unwrap();
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        e.contains("bridge.json:4:") && !e.contains("unknown field"),
        "{e}"
    );
    let o = Command::new(bin()).arg("procedures").output().unwrap();
    let list = String::from_utf8_lossy(&o.stdout);
    for name in [
        "slider_crank",
        "beam",
        "force_system",
        "centroid",
        "shaft",
        "truss",
    ] {
        assert!(list.contains(name), "{list}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn render_is_all_or_nothing_and_refuses_two_scenes_with_one_name() {
    let dir = tmp("batch");
    let good = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lh_abb22_funicular.json"
    );
    let (a, b) = (dir.join("a"), dir.join("b"));
    for d in [&a, &b] {
        std::fs::create_dir_all(d).unwrap();
        std::fs::copy(good, d.join("same.json")).unwrap();
    }
    let out = dir.join("out");
    let run = |args: &[&Path]| {
        Command::new(bin())
            .arg("render")
            .args(args)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap()
    };
    let o = run(&[&a.join("same.json"), &b.join("same.json")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("same.svg"));
    assert!(!out.exists());
    // A target that is a folder: refused before any figure is written.
    std::fs::copy(good, a.join("other.json")).unwrap();
    std::fs::create_dir_all(out.join("same.svg")).unwrap();
    let o = run(&[&a]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!out.join("other.svg").exists());
    let left: Vec<_> = std::fs::read_dir(&out).unwrap().collect();
    assert_eq!(left.len(), 1, "no temporaries left behind");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn steps_owns_its_pages_and_nothing_else() {
    let dir = tmp("steps-own");
    let out = dir.join("walk");
    std::fs::create_dir_all(&out).unwrap();
    for stale in ["step-999.svg", "step-1000.svg"] {
        std::fs::write(out.join(stale), "old").unwrap();
    }
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    std::fs::write(out.join("step-notes.svg"), "mine").unwrap();
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lh_abb22_funicular.json"
    );
    let o = Command::new(bin())
        .args(["steps", scene, "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // It writes index.html alone and removes nothing: files of that name it did not write
    // (nor does it write such files any more) stay.
    assert!(out.join("step-999.svg").exists() && out.join("step-1000.svg").exists());
    assert!(out.join("notes.txt").exists() && out.join("step-notes.svg").exists());
    assert!(out.join("index.html").exists() && !out.join("step-001.svg").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn names_cannot_break_the_svg_the_csv_or_the_markdown() {
    let dir = tmp("names");
    let scene = dir.join("t.json");
    let text = r#"{ "procedure": "truss", "title": "t <x> & \"q\"",
        "joints": [ { "name": "I", "at_m": [0, 0] }, { "name": "II", "at_m": [2, 0] }, { "name": "III", "at_m": [1, 1] } ],
        "members": [ { "name": "=1+1", "joints": ["I", "III"] }, { "name": "a|b", "joints": ["III", "II"] }, { "name": "@3", "joints": ["I", "II"] } ],
        "supports": [ { "joint": "I", "kind": "pinned" }, { "joint": "II", "kind": "roller", "direction_deg": 90 } ],
        "load_cases": [ { "name": "P", "loads": [ { "joint": "III", "kg": 1000 } ] } ] }"#;
    // A control character in any name (ESC would reach the terminal through `check`'s
    // table, NUL would break TeX, a line end a CSV row) is refused, naming the field.
    // A character that turns text around or breaks it unseen (U+202E shows a name backwards),
    // raw or escaped, likewise.
    let control = "a control character";
    let unseen = "a direction or line-separator character";
    for (from, to, field, why) in [
        ("\"III\"", "\"III\\u0000\"", "joints[2].name", control),
        ("\"a|b\"", "\"a|b\\nc\"", "members[1].name", control),
        ("\"P\"", "\"P\\u001b[2J\"", "load_cases[0].name", control),
        ("\"a|b\"", "\"a\u{202e}b\"", "members[1].name", unseen),
        ("\"P\"", "\"P\\u2028Q\"", "load_cases[0].name", unseen),
        ("\"III\"", "\"III\u{2067}\"", "joints[2].name", unseen),
        ("\"P\"", "\"P\u{061c}\"", "load_cases[0].name", unseen),
    ] {
        std::fs::write(&scene, text.replacen(from, to, 1)).unwrap();
        for cmd in ["check", "render", "forces"] {
            let mut c = Command::new(bin());
            c.arg(cmd).arg(&scene);
            if cmd == "render" {
                c.arg("--out").arg(dir.join("refused"));
            }
            let o = c.output().unwrap();
            let e = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{cmd}: {e}");
            assert!(e.contains(&format!("{field}: {why}")), "{cmd}: {e}");
            assert!(o.stdout.is_empty() && !dir.join("refused").exists());
        }
    }
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("out");
    let o = Command::new(bin())
        .args([
            "render",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let svg = std::fs::read_to_string(out.join("t.svg")).unwrap();
    let forbidden = |c: char| (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{fffe}';
    assert!(
        !svg.chars().any(forbidden),
        "the SVG holds a character XML forbids"
    );
    let table = |format: &str| {
        let o = Command::new(bin())
            .args(["forces", scene.to_str().unwrap(), "--format", format])
            .output()
            .unwrap();
        String::from_utf8(o.stdout).unwrap()
    };
    let csv = table("csv");
    assert!(
        csv.contains("\"'=1+1\"") && csv.contains("\"'@3\""),
        "{csv}"
    );
    assert!(!csv
        .lines()
        .any(|l| l.starts_with('=') || l.starts_with("\"=")));
    let md = table("markdown");
    assert!(md.contains("a\\|b"), "{md}");
    let rows: Vec<&str> = md
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---"))
        .collect();
    let cols = rows[0].matches(" | ").count();
    assert!(rows
        .iter()
        .all(|r| r.replace("\\|", "").matches(" | ").count() == cols));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_long_walkthrough_costs_one_figure_not_a_page_per_step() {
    let dir = tmp("bigwalk");
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lh_aufgabe5_crane_bridge.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let case = v["load_cases"][0].clone();
    let cases: Vec<serde_json::Value> = (0..25)
        .map(|i| {
            let mut c = case.clone();
            c["name"] = format!("dead {i}").into();
            c
        })
        .collect();
    v["load_cases"] = cases.into();
    let o = v.as_object_mut().unwrap();
    o.remove("envelope");
    let scene = dir.join("big.json");
    std::fs::write(&scene, v.to_string()).unwrap();
    let out = dir.join("walk");
    let o = Command::new(bin())
        .args([
            "steps",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // One figure and one list: the page grows with the construction, not with its square
    // (a page per step drew 1.4 million objects here and had to be refused).
    let page = std::fs::metadata(out.join("index.html")).unwrap().len();
    let p = graphostatik::scene::AnyScene::load(&scene)
        .unwrap()
        .into_problem();
    let board = p.construct(BoardConfig::DRAWING).unwrap();
    let fig = graphostatik::render::figure(&p.figure_meta(), &board, None).len() as u64;
    let steps = board.steps().len() as u64;
    assert!(steps > 2000, "{steps}");
    assert!(
        page < fig + 2000 * steps,
        "{page} bytes: figure {fig}, {steps} steps"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_absurd_scale_is_named_as_the_cause() {
    let e = err(&GOOD.replace(
        r#""angles": { "divisions": 12 },"#,
        r#""angles": { "divisions": 12 }, "drawing": { "length_scale": 1e-12 },"#,
    ));
    assert!(
        e.starts_with("s.json: drawing.length_scale: with this value the figure would be"),
        "{e}"
    );
    let e = err(&GOOD.replace(
        r#""angles": { "divisions": 12 },"#,
        r#""angles": { "divisions": 12 }, "drawing": { "force_scale_kg_per_mm": 1e-9 },"#,
    ));
    assert!(
        e.starts_with("s.json: drawing.force_scale_kg_per_mm:"),
        "{e}"
    );
}

#[test]
fn a_rod_a_hair_longer_than_the_crank_is_refused_and_a_little_longer_constructs() {
    // A hard case: R/L = 0.999999999 failed its checks at 90°, and R/L = 1 − 1e-12 passed
    // validation and was refused at 89.999999°. Near locking is refused at validation; from
    // L/R = 1 + 1.1e-6 on, every angle constructs and every check passes.
    let scene = |k: &str| {
        GOOD.replace(r#""length_mm": 1500"#, &format!(r#""l_over_r": {k}"#))
            .replace(
                r#""divisions": 12"#,
                r#""degrees": [89.999999, 90, 90.000001, 270, 269.999999]"#,
            )
    };
    for k in ["1.000000001", "1.000000000001"] {
        let e = err(&scene(k));
        assert!(
            e.starts_with("s.json: mechanism.rod.l_over_r: the rod is only"),
            "{e}"
        );
    }
    let (_, p) = SliderCrankScene::read(&scene("1.0000011"), "s.json").unwrap();
    let (board, _) = SliderCrankScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
}

#[test]
fn render_on_every_core_writes_what_a_serial_run_writes_and_names_the_first_bad_scene() {
    let dir = tmp("jobs");
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let run = |src: &Path, out: &Path, jobs: &str| {
        Command::new(bin())
            .arg("render")
            .arg(src)
            .arg("--out")
            .arg(out)
            .args(["--jobs", jobs])
            .output()
            .unwrap()
    };
    let (one, four) = (dir.join("one"), dir.join("four"));
    let o1 = run(&scenes, &one, "1");
    let o4 = run(&scenes, &four, "4");
    assert!(o1.status.success() && o4.status.success());
    let listed = |o: &std::process::Output, out: &Path| {
        String::from_utf8_lossy(&o.stdout).replace(&*out.to_string_lossy(), "OUT")
    };
    assert_eq!(
        listed(&o1, &one),
        listed(&o4, &four),
        "the same files, in order"
    );
    let mut n = 0;
    for e in std::fs::read_dir(&one).unwrap() {
        let name = e.unwrap().file_name();
        let a = std::fs::read(one.join(&name)).unwrap();
        let b = std::fs::read(four.join(&name)).unwrap();
        assert!(a == b, "{name:?} differs between --jobs 1 and --jobs 4");
        n += 1;
    }
    assert!(n >= 20, "{n} figures");
    // Two bad scenes among good ones: whichever worker finishes first, the error is the one a
    // serial run meets first (file order), and nothing is written.
    let mixed = dir.join("mixed");
    std::fs::create_dir_all(&mixed).unwrap();
    for (i, e) in std::fs::read_dir(&scenes).unwrap().enumerate().take(8) {
        std::fs::copy(e.unwrap().path(), mixed.join(format!("s{i}.json"))).unwrap();
    }
    std::fs::write(mixed.join("s3b.json"), "{\"procedure\": 1}").unwrap();
    std::fs::write(mixed.join("s6b.json"), "not json").unwrap();
    for jobs in ["1", "2", "8"] {
        let out = dir.join(format!("mixed-out-{jobs}"));
        let o = run(&mixed, &out, jobs);
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("s3b.json") && !err.contains("s6b"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!out.exists());
    }
    // Every format, the PNGs and PDFs made as jobs of their own: the same bytes on any number
    // of cores.
    for bad in ["s3b.json", "s6b.json"] {
        std::fs::remove_file(mixed.join(bad)).unwrap();
    }
    let formats = |out: &Path, jobs: &str| {
        let o = Command::new(bin())
            .arg("render")
            .arg(&mixed)
            .arg("--out")
            .arg(out)
            .args([
                "--jobs",
                jobs,
                "--format",
                "svg,png,pdf,tikz",
                "--dpi",
                "30",
            ])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    let (a, b) = (dir.join("formats-1"), dir.join("formats-3"));
    formats(&a, "1");
    formats(&b, "3");
    let names: Vec<_> = std::fs::read_dir(&a)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 8 * 4);
    for name in names {
        let same = std::fs::read(a.join(&name)).unwrap() == std::fs::read(b.join(&name)).unwrap();
        assert!(same, "{name:?} differs between --jobs 1 and --jobs 3");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_bad_engine_is_refused_by_the_command_line_with_its_field_and_nothing_written() {
    // Bad input through the CLI: one line naming the field, exit 2, no figure.
    let d = tmp("engine");
    let good = include_str!("../../scenes/lh_j_locomotive_dynamics.json");
    let cases = [
        (
            "\"cutoff\": 0.175",
            "\"cutoff\": 1.5",
            "indicator.steam.cutoff",
        ),
        (
            "\"q_kg_per_cm2\": 0.28",
            "\"q_kg_per_cm2\": -0.28",
            "q_kg_per_cm2",
        ),
        (
            "\"back_at\": 0.2",
            "\"back_at\": -1.2",
            "indicator.steam.back_at",
        ),
    ];
    for (k, (from, to, field)) in cases.iter().enumerate() {
        let bad = d.join(format!("engine{k}.json"));
        std::fs::write(&bad, good.replacen(from, to, 1)).unwrap();
        let out = d.join(format!("out{k}"));
        let o = Command::new(bin())
            .arg("render")
            .arg(&bad)
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{field}");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(stderr.contains(field), "{stderr}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
        assert!(!out.exists());
    }
    std::fs::remove_dir_all(&d).unwrap();
}

/// Found by cargo fuzz: an unknown key holding a newline (JSON `\n`) was echoed raw by the
/// library's error (the command line escaped it, a library user got two lines).
#[test]
fn an_unknown_key_with_a_newline_is_one_line_in_the_library_error_too() {
    let text = "{ \"title\\nX\": \"t\", \"title\": \"t\", \"mechanism\": { \"crank_radius_mm\": 300, \"rod\": { \"l_over_r\": 5 } } }";
    let e = graphostatik::scene::AnyScene::from_json(text, "a\nb.json")
        .err()
        .unwrap()
        .to_string();
    assert!(
        !e.contains('\n') && e.contains("title\\nX") && e.contains("a\\nb.json"),
        "{e}"
    );
}

/// Shell completions and the manual page come from the command line's own definition, so
/// they know every subcommand and option.
#[test]
fn completions_and_the_manual_page_know_every_command() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let o = Command::new(bin())
            .args(["completions", shell])
            .output()
            .unwrap();
        assert!(o.status.success(), "{shell}");
        let text = String::from_utf8_lossy(&o.stdout);
        for cmd in ["render", "check", "accuracy", "drafting", "forces"] {
            assert!(text.contains(cmd), "{shell}: {cmd}");
        }
    }
    assert!(text_of(&["completions", "bash"]).contains("--reference"));
    let man = text_of(&["man"]);
    assert!(
        man.starts_with(".ie") && man.contains(".TH graphostatik 1"),
        "{man}"
    );
    for cmd in ["render", "check", "accuracy", "drafting", "completions"] {
        assert!(
            man.contains(&format!("graphostatik\\-{cmd}")) || man.contains(cmd),
            "{cmd}"
        );
    }
    let o = Command::new(bin())
        .args(["completions", "tcsh"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
}

fn text_of(args: &[&str]) -> String {
    let o = Command::new(bin()).args(args).output().unwrap();
    assert!(o.status.success(), "{args:?}");
    String::from_utf8(o.stdout).unwrap()
}

/// `--quiet` leaves only the product and errors; `--verbose` adds a line per scene on
/// standard error; the progress bar is never written where standard error is not a terminal
/// (as here); the two flags together are refused as usage.
#[test]
fn quiet_and_verbose() {
    let d = tmp("quiet");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_c2_couple.json");
    let run = |flags: &[&str]| {
        let o = Command::new(bin())
            .args(flags)
            .arg("render")
            .arg(&scene)
            .arg("--out")
            .arg(&d)
            .output()
            .unwrap();
        assert!(o.status.success(), "{flags:?}");
        (
            String::from_utf8(o.stdout).unwrap(),
            String::from_utf8(o.stderr).unwrap(),
        )
    };
    let (out, err) = run(&[]);
    assert!(
        out.contains("lh_c2_couple.svg") && err.is_empty(),
        "{out} / {err}"
    );
    let (out, err) = run(&["--quiet"]);
    assert!(out.is_empty() && err.is_empty(), "{out} / {err}");
    let (out, err) = run(&["-v"]);
    assert!(out.contains("lh_c2_couple.svg"), "{out}");
    assert!(
        err.contains("lh_c2_couple.json: ") && err.contains(" steps, 3 checks, "),
        "{err}"
    );
    let o = Command::new(bin())
        .args(["-q", "-v", "check"])
        .arg(&scene)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    // The check table is the product: --quiet keeps it.
    let o = Command::new(bin())
        .args(["check", "-q"])
        .arg(&scene)
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&o.stdout).contains("3 checks, 3 passed"));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn render_names_a_scene_whose_labels_were_left_out_in_one_line_after_writing() {
    // The crane bridge's plans leave no room for the names of some lines and forces: the
    // figure is written, and stderr says how many were withheld (and nothing of labels left
    // out, where none were); `--quiet` says nothing of it.
    let dir = tmp("crowd");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_aufgabe5_crane_bridge.json");
    let run = |quiet: bool| {
        let mut c = Command::new(bin());
        c.arg("render").arg(&scene).arg("--out").arg(&dir);
        if quiet {
            c.arg("-q");
        }
        let o = c.output().unwrap();
        assert!(o.status.success());
        String::from_utf8_lossy(&o.stderr).into_owned()
    };
    let err = run(false);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("lh_aufgabe5_crane_bridge.json: "), "{err}");
    assert!(err.contains("names of lines and forces withheld"), "{err}");
    assert!(!err.contains("0 of"), "{err}");
    assert!(dir.join("lh_aufgabe5_crane_bridge.svg").exists());
    assert_eq!(run(true), "");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn check_fails_on_a_book_value_that_differs_for_no_named_cause() {
    // Esselborn's scene with the cause of its 79°16′ taken out: the check table says the book
    // row differs unexplained, and `check` exits 1; with the cause it passes.
    let dir = tmp("book");
    let good = include_str!("../../scenes/lh_abb52_esselborn.json");
    let mut doc: serde_json::Value = serde_json::from_str(good).unwrap();
    doc["book"][1].as_object_mut().unwrap().remove("cause");
    let bad = dir.join("esselborn.json");
    std::fs::write(&bad, doc.to_string()).unwrap();
    let run = |p: &Path| Command::new(bin()).arg("check").arg(p).output().unwrap();
    let o = run(&bad);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(
        out.contains("DIFFERS, and the scene names no cause"),
        "{out}"
    );
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_abb52_esselborn.json");
    assert_eq!(run(&scene).status.code(), Some(0));
    std::fs::remove_dir_all(&dir).ok();
}

/// A command's exit status and its standard error.
fn run_cli(args: &[&std::ffi::OsStr]) -> (Option<i32>, String) {
    let o = Command::new(bin()).args(args).output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn only_regular_files_are_read_and_bad_utf8_has_its_place() {
    let dir = tmp("regular");
    // /dev/zero would be read until memory runs out: refused before it is opened.
    let (code, e) = run_cli(&["check".as_ref(), "/dev/zero".as_ref()]);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("not a regular file"), "{e}");
    // A FIFO named *.json in a folder would block `render` forever.
    let scenes = dir.join("scenes");
    std::fs::create_dir_all(&scenes).unwrap();
    let fifo = scenes.join("a.json");
    let made = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success());
    if made {
        let (code, e) = run_cli(&[
            "render".as_ref(),
            scenes.as_os_str(),
            "--out".as_ref(),
            dir.join("out").as_os_str(),
        ]);
        assert_eq!(code, Some(2), "{e}");
        assert!(
            e.contains("a.json") && e.contains("not a regular file"),
            "{e}"
        );
        std::fs::remove_file(&fifo).unwrap();
    }
    // Text that is not UTF-8 is refused at its line and column.
    let bad = dir.join("bad.json");
    std::fs::write(&bad, b"{\n  \"title\": \"caf\xe9\"\n}").unwrap();
    let (code, e) = run_cli(&["check".as_ref(), bad.as_os_str()]);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("2:16: not UTF-8"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn accuracy_tries_its_plot_file_before_the_sweep_and_never_writes_over_a_device() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/lh_abb24_beam.json");
    let dir = tmp("accuracy-out");
    let missing = dir.join("no/such/folder/plot.svg");
    let t = std::time::Instant::now();
    let (code, e) = run_cli(&[
        "accuracy".as_ref(),
        scene.as_ref(),
        "--svg".as_ref(),
        missing.as_os_str(),
    ]);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("--svg") && e.contains("plot.svg"), "{e}");
    // The sweep takes seconds; the refusal comes before it (a loose bound, for a slow machine).
    assert!(t.elapsed() < std::time::Duration::from_secs(20));
    if Path::new("/dev/null").exists() {
        let (code, e) = run_cli(&[
            "accuracy".as_ref(),
            scene.as_ref(),
            "--svg".as_ref(),
            "/dev/null".as_ref(),
        ]);
        assert_eq!(code, Some(2), "{e}");
        assert!(e.contains("not a regular file"), "{e}");
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            let kind = std::fs::metadata("/dev/null").unwrap().file_type();
            assert!(kind.is_char_device(), "/dev/null is still a device");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_envelope_counts_each_load_case_once() {
    let shed = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/lh_aufgabe4_shed_roof.json"
    ))
    .unwrap();
    for (from, to, field) in [
        (
            "\"permanent\": [\"dead load\"]",
            "\"permanent\": [\"dead load\", \"dead load\"]",
            "envelope.permanent[1]",
        ),
        (
            "[[\"wind left\", \"wind right\"]]",
            "[[\"wind left\", \"dead load\"]]",
            "envelope.exclusive[0][1]",
        ),
    ] {
        assert!(shed.contains(from));
        let e = graphostatik::scene::AnyScene::from_json(&shed.replace(from, to), "shed.json")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(&format!(
                "shed.json: {field}: load case `dead load` is listed already"
            )),
            "{e}"
        );
    }
}

#[test]
fn a_scale_that_shrinks_a_figure_to_a_point_is_refused() {
    // LH Abb. 22 at 1 : 1e308: the positions underflowed beside forces drawn at their scale,
    // and the moment of the resultant came out NaN; the crank-rocker at 1 : 1e308 drew a
    // point with every check NaN.
    let funicular = include_str!("../../scenes/lh_abb22_funicular.json");
    let e = graphostatik::scene::AnyScene::from_json(
        &funicular.replace("\"length_scale\": 25", "\"length_scale\": 1e308"),
        "f.json",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("f.json: drawing.length_scale: a scale must lie between"),
        "{e}"
    );
    let rocker = include_str!("../../scenes/kg_abb1043_crank_rocker.json");
    let mut doc: serde_json::Value = serde_json::from_str(rocker).unwrap();
    doc["drawing"]["length_scale"] = serde_json::json!(1e300);
    let e = graphostatik::scene::AnyScene::from_json(&doc.to_string(), "r.json")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("r.json: drawing.length_scale: "), "{e}");
    assert!(
        e.contains("less than the 1 mm a figure must take") || e.contains("a scale must lie"),
        "{e}"
    );
}

#[test]
fn a_refusal_prints_enough_digits_to_show_the_difference() {
    // The lever 1e-7 mm short of e + r = 280 mm was refused as "at least 280, got 280".
    let link = include_str!("../../scenes/kg_abb1071_slotted_link.json");
    let mut doc: serde_json::Value = serde_json::from_str(link).unwrap();
    doc["link"]["lever_mm"] = serde_json::json!(279.9999999);
    let e = graphostatik::scene::AnyScene::from_json(&doc.to_string(), "l.json")
        .unwrap_err()
        .to_string();
    assert!(e.contains("e + r = 280 mm, got 279.9999999"), "{e}");
    // A crank-rocker whose rocker is 1e-9 mm short of turning: every length as given.
    let rocker = include_str!("../../scenes/kg_abb1043_crank_rocker.json");
    let mut doc: serde_json::Value = serde_json::from_str(rocker).unwrap();
    doc["links"] = serde_json::json!({ "frame_mm": 400, "crank_mm": 100, "coupler_mm": 350, "rocker_mm": 149.999999999 });
    let e = graphostatik::scene::AnyScene::from_json(&doc.to_string(), "r.json")
        .unwrap_err()
        .to_string();
    assert!(e.contains("rocker 149.999999999 mm"), "{e}");
}

/// Two quantities one scale must draw, too unequal for any scale: the refusal names the input
/// that makes them so, not the scale (whose every value was refused in turn, too large or
/// too small); a little less unequal, the default scales draw it.
#[test]
fn no_scale_can_draw_it_names_the_input_not_the_scale() {
    let link = include_str!("../../scenes/kg_abb1071_slotted_link.json");
    let otto = include_str!("../../scenes/kg_abb1056_otto_four_cylinders.json");
    let read = |doc: &serde_json::Value| {
        graphostatik::scene::AnyScene::from_json(&doc.to_string(), "s.json").map(|_| ())
    };
    for (e, scale) in [(80.0 * (1.0 + 1e-6), None), (80.00008, Some(1e4))] {
        let mut doc: serde_json::Value = serde_json::from_str(link).unwrap();
        doc["link"]["centre_distance_mm"] = serde_json::json!(e);
        match scale {
            Some(v) => doc["drawing"]["velocity_scale_m_s_per_mm"] = serde_json::json!(v),
            None => drop(
                doc["drawing"]
                    .as_object_mut()
                    .unwrap()
                    .remove("velocity_scale_m_s_per_mm"),
            ),
        }
        let msg = read(&doc).unwrap_err().to_string();
        assert!(
            msg.contains("link.centre_distance_mm") && msg.contains("no scale draws both"),
            "{msg}"
        );
        doc["link"]["centre_distance_mm"] = serde_json::json!(80.008);
        drop(
            doc["drawing"]
                .as_object_mut()
                .unwrap()
                .remove("velocity_scale_m_s_per_mm"),
        );
        read(&doc).unwrap();
    }
    // A combustion engine whose pistons weigh 1.2 kg at a millionth of its size: the inertia
    // is 3e6 times the atmosphere's force on the piston.
    let mut doc: serde_json::Value = serde_json::from_str(otto).unwrap();
    doc["mechanism"]["stroke_mm"] = serde_json::json!(130e-6);
    doc["cylinders"]["bore_mm"] = serde_json::json!(100e-6);
    drop(doc.as_object_mut().unwrap().remove("drawing"));
    let msg = read(&doc).unwrap_err().to_string();
    assert!(
        msg.contains("cylinders.reciprocating_kg") && msg.contains("no scale draws both"),
        "{msg}"
    );
}

#[test]
fn a_pump_too_strong_for_the_sheet_is_refused_before_it_is_drawn() {
    // KG Tafel I's pump at 5,400 at delivery drew a sheet of 35 m; at 4.3e9 at, or with a
    // plunger of a kilometre, the construction never ended.
    let pump = include_str!("../../scenes/kg_abb1065_pump_engine.json");
    for (field, value) in [
        ("delivery_at", 5400.0),
        ("delivery_at", 4.3e9),
        ("plunger_mm", 1e6),
    ] {
        let mut doc: serde_json::Value = serde_json::from_str(pump).unwrap();
        doc["cylinders"][0]["pump"][field] = serde_json::json!(value);
        let t = std::time::Instant::now();
        let e = graphostatik::scene::AnyScene::from_json(&doc.to_string(), "p.json")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("more than the 10 m a figure may take"),
            "{field} {value}: {e}"
        );
        assert!(t.elapsed() < std::time::Duration::from_secs(5));
    }
}

#[test]
fn a_figure_too_large_is_refused_before_it_is_drawn_and_check_still_takes_it() {
    // A slider-crank at 3,600 angles draws 108,011 steps (its PNG took 15 s); 64 cylinders
    // at 3,600 divisions ran out of memory. Past the limit the board only counts.
    let scene = GOOD
        .replace("\"divisions\": 12", "\"divisions\": 3600")
        .replace(
            "\"outputs\": [\"piston_path\", \"tangential_force\"]",
            "\"outputs\": [\"piston_path\", \"velocity\", \"tangential_force\"]",
        );
    let p = graphostatik::scene::AnyScene::from_json(&scene, "s.json")
        .unwrap()
        .into_problem();
    let t = std::time::Instant::now();
    let e = match p.construct(BoardConfig::DRAWING) {
        Ok(b) => panic!("drawn: {} steps", b.step_count()),
        Err(e) => e,
    };
    assert!(t.elapsed() < std::time::Duration::from_secs(10));
    let text = e.to_string();
    assert!(
        text.starts_with("it would draw ") && text.contains("more than the 50000"),
        "{text}"
    );
    assert!(text.contains("fewer angles"), "{text}");
    let checks = p.construct(BoardConfig::CHECKS).unwrap();
    assert!(checks.all_passed() && checks.check_count() > 3600);
}

#[test]
fn drafting_reference_and_accuracy_are_costed_before_they_run() {
    // Twelve cylinders at 3,600 shaft divisions: about a million steps, a figure `render`
    // refuses. Each command that draws the figure refuses it as fast, at the memory of the
    // figure's limit, naming what sets its size; none runs first (drafting once took 89 s
    // and 2.1 GB for 20 runs, `check --reference` 66 s).
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/it/hostile");
    let big = dir.join("combustion_12cyl_3600div.json");
    let refused = |args: &[&str], want: &str| {
        let t = std::time::Instant::now();
        let o = Command::new(bin()).args(args).output().unwrap();
        let secs = t.elapsed().as_secs_f64();
        let e = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(e.contains(want), "{args:?}: {e}");
        assert!(o.stdout.is_empty());
        assert!(secs < 30.0, "{args:?} took {secs:.1} s to refuse");
    };
    let big = big.to_str().unwrap();
    let figure = "more than the 50000 a figure may hold";
    refused(&["drafting", big, "--runs", "20"], figure);
    refused(
        &["check", "--reference", big],
        "(a reference replay keeps the drawing)",
    );
    refused(&["accuracy", big], figure);
    // A figure that fits, drawn more often than drafting's budget allows: the runs named,
    // with the most that fit.
    let crane = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_aufgabe5_crane_bridge.json");
    refused(
        &["drafting", crane.to_str().unwrap(), "--runs", "100000"],
        "--runs: 100000 drawings of",
    );
    // `check` without the replay takes the scene: it draws nothing.
    let o = Command::new(bin()).args(["check", big]).output().unwrap();
    assert!(
        o.status.code() != Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn a_stopped_render_leaves_no_temporaries() {
    // Ctrl-C while `render` writes its batch: the temporaries it made are removed before it
    // exits (130); a run that completes leaves none either.
    let out = tmp("stopped");
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut child = Command::new(bin())
        .args(["render", "-q", "--format", "svg,pdf", "--out"])
        .arg(&out)
        .arg(&scenes)
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let temporaries = || {
        (std::fs::read_dir(&out).unwrap().flatten())
            .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
            .count()
    };
    let t = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() && temporaries() == 0 {
        assert!(t.elapsed().as_secs() < 300, "render never began writing");
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    let pid = child.id().to_string();
    let _ = Command::new("kill").args(["-INT", &pid]).status();
    let status = child.wait().unwrap();
    assert!(matches!(status.code(), Some(0 | 130)), "{status:?}");
    assert_eq!(temporaries(), 0, "temporaries left after {status:?}");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn command_line_errors_are_one_line_with_their_reason() {
    // clap's errors, each one line naming what to ask for more.
    for (args, want) in [
        (
            &["render", "x", "--frob"][..],
            "unexpected argument '--frob'",
        ),
        (
            &["drafting", "x", "--runs", "abc"][..],
            "invalid value 'abc' for '--runs",
        ),
        (&["frob"][..], "unrecognized subcommand 'frob'"),
    ] {
        let o = Command::new(bin()).args(args).output().unwrap();
        let e = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert_eq!(e.lines().count(), 1, "{args:?}: {e}");
        assert!(
            e.starts_with("error: ") && e.contains(want),
            "{args:?}: {e}"
        );
        assert!(e.contains("--help` lists them"), "{e}");
    }
    // An error quoting a long value (a firing order of 400 entries) keeps its reason.
    let scene =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/it/hostile/firing_order_of_400.json");
    let o = Command::new(bin())
        .arg("check")
        .arg(&scene)
        .output()
        .unwrap();
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.contains("cylinders.firing_order: [") && e.contains(" … "),
        "{e}"
    );
    assert!(e.trim_end().ends_with("(e.g. [1, 3, 4, 2])"), "{e}");
}

#[test]
fn a_figure_whose_drawn_parts_pass_the_sheet_is_refused_and_its_checks_are_not_judged() {
    // Inputs within every limit whose derived parts are not: a truss joint 1e-10 m off the
    // line of its members (forces of 5e12 kg: a force plan 250,000 km long), a couple off
    // balance by 1e-6 kg (a resultant 4e7 km away). `render` refuses each naming the part
    // and nothing is written; `check` takes it and says which checks cannot be judged.
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/it/hostile");
    let out = tmp("far");
    for scene in ["truss_joint_1e-10_off_its_line", "couple_off_by_1e-6_kg"] {
        let f = dir.join(format!("{scene}.json"));
        let o = Command::new(bin())
            .arg("render")
            .arg(&f)
            .arg("--out")
            .arg(out.join("x"))
            .output()
            .unwrap();
        let e = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{scene}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(
            e.contains("m across on the sheet, more than the 10 m"),
            "{e}"
        );
        assert!(!out.join("x").exists(), "{scene}: something was written");
    }
    let o = Command::new(bin())
        .arg("check")
        .arg(dir.join("truss_joint_1e-10_off_its_line.json"))
        .output()
        .unwrap();
    let table = String::from_utf8_lossy(&o.stdout);
    assert!(
        table.contains("4 not judged (their bound exceeds their tolerance"),
        "{table}"
    );
    assert_eq!(table.matches("not judged\n").count(), 4, "{table}");
    std::fs::remove_dir_all(&out).ok();
}
