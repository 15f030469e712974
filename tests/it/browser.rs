//! The walk-through and the live preview in a real browser: Debian's chromium, headless,
//! driven through chromedriver (WebDriver over loopback).
//!
//! Where chromium or chromedriver is missing the tests say they are skipped, unless
//! `GRAPHOSTATIK_BROWSER=required` (as `.ci/run` sets after installing both), when they fail.
//! With `GRAPHOSTATIK_SCREENSHOTS=DIR` the screenshots are written to `DIR` (the README's
//! come from `GRAPHOSTATIK_SCREENSHOTS=figures/screenshots cargo test --test it browser::`).

#[path = "browser/webdriver.rs"]
mod webdriver;

use graphostatik::protocol::BoardConfig;
use std::path::{Path, PathBuf};
use std::process::Command;
use webdriver::{Browser, Session};

fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_graphostatik"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gs-browser-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn browser_or_skip(test: &str) -> Option<Browser> {
    match Browser::find() {
        Some(b) => Some(b),
        None if webdriver::required() => {
            panic!("{test}: chromium and chromedriver are required but not installed")
        }
        None => {
            eprintln!("{test}: skipped (no /usr/bin/chromium and /usr/bin/chromedriver)");
            None
        }
    }
}

/// Writes a screenshot where `GRAPHOSTATIK_SCREENSHOTS` says, or into `fallback`.
pub fn keep_screenshot(png: &[u8], name: &str, fallback: &Path) -> PathBuf {
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "a PNG");
    assert!(
        png.len() > 10_000,
        "a screenshot with content: {} bytes",
        png.len()
    );
    let dir = std::env::var_os("GRAPHOSTATIK_SCREENSHOTS")
        .map(|d| Path::new(env!("CARGO_MANIFEST_DIR")).join(d))
        .unwrap_or_else(|| fallback.to_path_buf());
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, png).unwrap();
    path
}

/// How many step layers the page shows, and which are drawn as the current step.
fn shown(s: &Session) -> (u64, Vec<u64>) {
    let v = s.script(
        "var g = document.querySelectorAll('#wt-figure g[data-step]'); var n = 0, cur = [];\
         for (var i = 0; i < g.length; i++) {\
           if (getComputedStyle(g[i]).display !== 'none') n++;\
           if (g[i].classList.contains('current')) cur.push(Number(g[i].getAttribute('data-step')));\
         } return [n, cur];",
    );
    let cur = v[1]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect();
    (v[0].as_u64().unwrap(), cur)
}

#[test]
fn a_student_pages_through_a_walkthrough_with_the_keyboard() {
    let Some(browser) = browser_or_skip("walk-through") else {
        return;
    };
    let dir = tmp("walk");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_abb22_funicular.json");
    let o = Command::new(bin())
        .arg("steps")
        .arg(&scene)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let p = graphostatik::scene::AnyScene::load(&scene)
        .unwrap()
        .into_problem();
    let board = p.construct(BoardConfig::DRAWING).unwrap();
    let steps = board.steps();
    let s = Session::start(&browser, &dir.join("profile"));
    s.goto(&format!("file://{}", dir.join("index.html").display()));
    policy_holds(&s, "the walk-through");
    let n = steps.len();
    for (i, step) in steps.iter().enumerate() {
        assert_eq!(s.text("#wt-count"), format!("step {} / {n}", i + 1));
        let now = s.text("#wt-now");
        assert!(now.contains(&step.id.to_string()), "{now}");
        assert!(
            now.contains(step.caption.as_ref()),
            "step {}: {now}",
            step.id
        );
        if !step.book.is_empty() {
            assert!(now.contains(step.book.as_ref()), "{now}");
        }
        for c in &step.checks {
            assert!(
                now.contains(c.quantity.as_ref()) && now.contains("ok"),
                "{now}"
            );
        }
        // The check columns stay in view in a window 1,400 px wide: the details beside the
        // figure do not scroll sideways.
        let over =
            "var e = document.getElementById('wt-now'); return e.scrollWidth - e.clientWidth;";
        assert_eq!(
            s.script(over),
            serde_json::json!(0),
            "step {}: the checks scroll",
            step.id
        );
        let (visible, current) = shown(&s);
        assert_eq!(visible as usize, i + 1, "layers shown at step {}", step.id);
        assert_eq!(current, vec![u64::from(step.id.0)]);
        s.keys("\u{E014}"); // →
    }
    // Past the end it stays on the last step; the browser's Back goes back a step, Forward
    // returns; ← goes back, Home to the first.
    assert_eq!(s.text("#wt-count"), format!("step {n} / {n}"));
    s.cmd("POST", "/back", Some(serde_json::json!({})));
    assert_eq!(s.text("#wt-count"), format!("step {} / {n}", n - 1));
    s.cmd("POST", "/forward", Some(serde_json::json!({})));
    assert_eq!(s.text("#wt-count"), format!("step {n} / {n}"));
    s.keys("\u{E012}"); // ←
    assert_eq!(s.text("#wt-count"), format!("step {} / {n}", n - 1));
    s.keys("\u{E011}"); // Home
    assert_eq!(s.text("#wt-count"), format!("step 1 / {n}"));
    // Play at 20 steps a second: the page moves on by itself, k pauses it.
    s.script(
        "var v = document.getElementById('wt-speed'); v.value = '20';\
              v.dispatchEvent(new Event('change')); return 0;",
    );
    s.keys("k");
    wait_for(
        &s,
        "return Number(document.getElementById('wt-count').textContent.split(' ')[1]) > 5;",
        &serde_json::json!(true),
        "playing",
    );
    s.keys("k");
    let paused = s.text("#wt-count");
    std::thread::sleep(std::time::Duration::from_millis(300));
    assert_eq!(s.text("#wt-count"), paused, "paused");
    // Hovering a step in the list draws its objects in blue.
    s.script("document.querySelectorAll('#wt-steps li')[3].dispatchEvent(new Event('mouseenter')); return 0;");
    assert_eq!(
        s.script("return document.querySelectorAll('#wt-figure g.wt-hover').length;"),
        serde_json::json!(1)
    );
    s.keys("\u{E011}"); // Home
                        // A step with a check shows it beside the figure; z zooms the view to that step.
    let checked = steps.iter().position(|st| !st.checks.is_empty()).unwrap();
    s.script(&format!(
        "window.graphostatikWalk.show({checked}); return 0;"
    ));
    let full = s.script("return document.querySelector('#wt-figure svg').getAttribute('viewBox');");
    s.keys("z");
    let zoomed =
        s.script("return document.querySelector('#wt-figure svg').getAttribute('viewBox');");
    assert_ne!(full, zoomed, "z zooms to the step");
    assert!(s.text("#wt-now").contains("closed form"));
    let png = s.screenshot();
    keep_screenshot(&png, "walkthrough.png", &dir);
    s.keys("z");
    let back = s.script("return document.querySelector('#wt-figure svg').getAttribute('viewBox');");
    assert_eq!(full, back, "z again shows the whole sheet");
    // The print view: one panel per step.
    let panels = s.script(
        "window.dispatchEvent(new Event('beforeprint'));\
         return document.querySelectorAll('#wt-print .wt-panel').length;",
    );
    assert_eq!(panels.as_u64(), Some(n as u64));
    let errors = s.console_errors();
    assert!(errors.is_empty(), "console errors: {errors:?}");
    drop(s);
    std::fs::remove_dir_all(&dir).ok();
}

/// Polls `js` in the page until it returns `want` (the page may be reloading meanwhile).
/// The page's Content-Security-Policy is in force and names what the page needs: an inline
/// handler does not run, while the page's own sheet, the figure's and (on a site page) the
/// site's apply.
fn policy_holds(s: &Session, what: &str) {
    // Nothing the page does itself is refused (the browser logs each refusal as an error).
    let before = s.console_errors();
    assert!(before.is_empty(), "{what}: {before:?}");
    let got = s.script(
        "var b = document.createElement('button'); b.setAttribute('onclick', 'window.__ran = 1');\
         document.body.appendChild(b); b.click(); b.remove();\
         var t = document.querySelector('#wt-figure svg text:not([class])');\
         return [window.__ran === 1, getComputedStyle(document.body).marginTop,\
           t ? getComputedStyle(t).fontStyle : null,\
           document.querySelectorAll('meta[http-equiv=\"Content-Security-Policy\"]').length];",
    );
    assert_eq!(
        got,
        serde_json::json!([false, "0px", "italic", 1]),
        "{what}"
    );
    let refused = s.console_errors();
    assert!(
        refused.len() == 1 && refused[0].contains("inline event handler"),
        "{what}: {refused:?}"
    );
}

fn wait_for(s: &Session, js: &str, want: &serde_json::Value, what: &str) {
    let t = std::time::Instant::now();
    loop {
        let (status, body) = webdriver::http_session(s, "/execute/sync", js);
        if status == 200 {
            let v: serde_json::Value = serde_json::from_str(&body).unwrap_or_default();
            if &v["value"] == want {
                return;
            }
        }
        assert!(
            t.elapsed() < std::time::Duration::from_secs(20),
            "{what}: waited 20 s, last {body}"
        );
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
}

/// `graphostatik serve` stopped when the test ends.
struct Server(std::process::Child);

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[test]
fn an_author_edits_a_scene_and_moves_a_slider_in_the_live_preview() {
    use serde_json::json;
    use std::io::BufRead;
    let Some(browser) = browser_or_skip("serve") else {
        return;
    };
    let Some(engine) = engine_or_skip("serve") else {
        return;
    };
    let dir = tmp("serve");
    let scene = dir.join("funicular.json");
    let good = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lh_abb22_funicular.json"),
    )
    .unwrap();
    std::fs::write(&scene, &good).unwrap();
    let mut child = Command::new(bin())
        .args(["serve", "--port", "0", "--engine"])
        .arg(&engine)
        .arg(&dir)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let mut first = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    let server = Server(child);
    let base = first
        .split_whitespace()
        .find(|w| w.starts_with("http://127.0.0.1:"))
        .unwrap_or_else(|| panic!("no address in {first:?}"))
        .trim_end_matches('/')
        .to_string();
    let s = Session::start(&browser, &dir.join("profile"));
    s.goto(&format!("{base}/scene/funicular"));
    let ready = "return !!window.graphostatikSite && window.graphostatikSite.ready;";
    wait_for(&s, ready, &json!(true), "the engine loaded from the server");
    policy_holds(&s, "the live preview");
    assert!(s.text("#wt-count").starts_with("step "));
    assert!(s.text("#wt-sliders").contains("direction of P2"));
    // A slider replays the construction in the page as it moves, on the step shown.
    s.keys("\u{E011}"); // Home
    s.keys("\u{E014}\u{E014}"); // → →
    let step = s.text("#wt-count");
    let move_slider = |i: usize, v: &str| {
        s.script(&format!(
            "var i = document.querySelector('#wt-sliders input[name=s{i}]'); i.value = '{v}';\
             i.dispatchEvent(new Event('input', {{ bubbles: true }})); return 0;"
        ));
    };
    move_slider(1, "800");
    wait_for(
        &s,
        "return window.graphostatikSite.good().forces[2].kg === 800;",
        &json!(true),
        "the page replayed at the slider's value",
    );
    move_slider(0, "250");
    wait_for(
        &s,
        "return window.graphostatikSite.good().forces[1].angle_deg === 250;",
        &json!(true),
        "the second slider",
    );
    assert_eq!(s.text("#wt-count"), step, "the step shown stays");
    assert_eq!(
        s.script("return window.graphostatikSite.answer().failed;"),
        json!(0)
    );
    s.keys("\u{E010}"); // End
    let png = s.screenshot();
    keep_screenshot(&png, "serve.png", &dir);
    // An edit reloads the page.
    std::fs::write(
        &scene,
        good.replace("Funicular polygon:", "Seileck, edited:"),
    )
    .unwrap();
    wait_for(
        &s,
        "return document.querySelector('h1').textContent.indexOf('Seileck, edited:') === 0;",
        &json!(true),
        "the edited title",
    );
    // A bad edit shows its line and column over the last good figure.
    std::fs::write(&scene, good.replace("\"kg\": 600", "\"kg\": 600,,")).unwrap();
    wait_for(
        &s,
        "var e = document.getElementById('wt-error'); return !!e && /funicular.json:\\d+:\\d+/.test(e.textContent)\
         && document.querySelectorAll('#wt-figure g[data-step]').length > 10\
         && !!window.graphostatikSite && window.graphostatikSite.ready;",
        &json!(true),
        "the error line over the last good figure",
    );
    // A bad field is named.
    std::fs::write(&scene, good.replace("\"kg\": 600", "\"kg\": \"600\"")).unwrap();
    wait_for(
        &s,
        "var e = document.getElementById('wt-error'); return !!e && e.textContent.indexOf('forces[1]') >= 0;",
        &json!(true),
        "the field named",
    );
    std::fs::write(&scene, &good).unwrap();
    wait_for(
        &s,
        "return !document.getElementById('wt-error') && !!document.getElementById('wt-count');",
        &json!(true),
        "the error gone once the scene is mended",
    );
    let errors = s.console_errors();
    assert!(errors.is_empty(), "console errors: {errors:?}");
    drop(s);
    drop(server);
    std::fs::remove_dir_all(&dir).ok();
}

/// The engine for the site (`target/wasm32-unknown-unknown/wasm/graphostatik_wasm.wasm`
/// beside this build), built as `.ci/run` builds it (a no-op when fresh); `None` where the
/// wasm target is not installed and the browser tests are not required.
fn engine_or_skip(test: &str) -> Option<PathBuf> {
    let target = bin().parent()?.parent()?.to_path_buf();
    let wasm = target.join("wasm32-unknown-unknown/wasm/graphostatik_wasm.wasm");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let built = Command::new(cargo)
        .args(["build", "-q", "-p", "graphostatik-wasm"])
        .args(["--target", "wasm32-unknown-unknown", "--profile", "wasm"])
        .env("CARGO_TARGET_DIR", &target)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .is_ok_and(|s| s.success());
    match (built && wasm.is_file(), webdriver::required()) {
        (true, _) => Some(wasm),
        (false, true) => panic!("{test}: the engine (wasm32-unknown-unknown) did not build"),
        (false, false) => {
            eprintln!("{test}: skipped (rustup target add wasm32-unknown-unknown)");
            None
        }
    }
}

/// `graphostatik site` of `scenes` (paths from the crate's root) into `out`.
fn write_site(scenes: &[&str], out: &Path) {
    write_site_with(scenes, out, None);
}

/// [`write_site`] with the engine `engine` where one is named (else the one built).
fn write_site_with(scenes: &[&str], out: &Path, engine: Option<&Path>) {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut site = Command::new(bin());
    site.arg("site")
        .args(scenes.iter().map(|p| manifest.join(p)))
        .arg("--out")
        .arg(out);
    if let Some(e) = engine {
        site.arg("--engine").arg(e);
    }
    let o = site.output().unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The screen centre of the first handle called `name` that is in view (a truss draws each
/// joint once per load case; the pane may be scrolled to the last).
fn handle_at(s: &Session, name: &str) -> (f64, f64) {
    let v = s.script(&format!(
        "var hs = document.querySelectorAll('.gs-handle');\
         for (var i = 0; i < hs.length; i++) {{\
           if (hs[i].querySelector('title').textContent.split(':')[0] !== {name:?}) continue;\
           var r = hs[i].getBoundingClientRect(), x = r.x + r.width / 2, y = r.y + r.height / 2;\
           if (x > 40 && y > 40 && x < window.innerWidth - 40 && y < window.innerHeight - 40) return [x, y]; }}\
         return null;"
    ));
    let a = v.as_array().unwrap_or_else(|| panic!("no handle {name}"));
    (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
}

/// Where on the screen the handle `name` turns about (its centre), in CSS pixels.
fn center_at(s: &Session, name: &str) -> (f64, f64) {
    let v = s.script(&format!(
        "var h = window.graphostatikSite.answer().handles.filter(function (h) {{\
           return h.name === {name:?}; }})[0];\
         var m = document.querySelector('#wt-figure svg').getScreenCTM();\
         var p = new DOMPoint(h.center[0], h.center[1]).matrixTransform(m); return [p.x, p.y];"
    ));
    let a = v
        .as_array()
        .unwrap_or_else(|| panic!("no centre of {name}"));
    (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
}

/// The constructed values of the page's last construction, and how many checks failed.
fn checks(s: &Session) -> (Vec<f64>, u64) {
    let v = s.script(
        "var a = window.graphostatikSite.answer();\
         return [a.checks.map(function (c) { return c.constructed; }), a.failed];",
    );
    let values = (v[0].as_array().unwrap().iter())
        .map(|x| x.as_f64().unwrap_or(f64::NAN))
        .collect();
    (values, v[1].as_u64().unwrap())
}

fn figure_text(s: &Session) -> String {
    s.script("return document.querySelector('#wt-figure svg').outerHTML;")
        .as_str()
        .unwrap()
        .to_string()
}

#[test]
fn a_student_drags_a_joint_and_a_crank_pin_in_the_site() {
    use serde_json::json;
    let Some(browser) = browser_or_skip("site") else {
        return;
    };
    let Some(_) = engine_or_skip("site") else {
        return;
    };
    let dir = tmp("site");
    write_site(
        &[
            "scenes/lh_aufgabe4_shed_roof.json",
            "tests/it/browser/grid_truss.json",
            "scenes/lh_abb52_esselborn.json",
        ],
        &dir.join("site"),
    );
    let s = Session::start(&browser, &dir.join("profile"));
    s.goto(&format!("file://{}", dir.join("site/index.html").display()));
    assert_eq!(
        s.script("return document.querySelectorAll('#gs-index li').length;"),
        json!(3)
    );
    let link = s.find("a[href='lh_aufgabe4_shed_roof.html']");
    s.cmd("POST", &format!("/element/{link}/click"), Some(json!({})));
    let ready = "return !!window.graphostatikSite && window.graphostatikSite.ready;";
    wait_for(
        &s,
        ready,
        &json!(true),
        "the engine loaded in the truss page",
    );
    policy_holds(&s, "the site's page");
    assert_eq!(
        s.script("return getComputedStyle(document.getElementById('wt-figure')).touchAction;"),
        json!("none"),
        "the site's own rules apply"
    );

    // Drag joint V of LH Aufgabe 4's shed roof: the figure, the members' forces (Cremona
    // plans of four load cases) and the scene follow; all checks pass.
    let (before, failed) = checks(&s);
    assert_eq!(failed, 0);
    let fig_before = figure_text(&s);
    let (cx, cy) = handle_at(&s, "joint V");
    let path: Vec<(f64, f64)> = (1..=6)
        .map(|k| (cx - 3.0 * k as f64, cy - 3.0 * k as f64))
        .collect();
    s.pointer(Some((cx, cy)), &path, false);
    wait_for(
        &s,
        "var c = window.graphostatikSite.scene().joints[4].at_m; return c[0] < 3.3 && c[1] > 0.62;",
        &json!(true),
        "joint V moved left and up in the scene",
    );
    // Mid-drag the figure is set in place (what changed changed); it is what a fresh parse
    // of the engine's answer gives.
    let same = "return window.graphostatikSite.figureIsAnswer();";
    assert_eq!(s.script(same), json!(""), "mid-drag");
    let png = s.screenshot();
    keep_screenshot(&png, "site-drag.png", &dir);
    s.pointer(None, &[], true);
    assert_eq!(s.script(same), json!(""), "after the drag");
    let listed = "return window.graphostatikSite.listDiffers();";
    assert_eq!(s.script(listed), json!(""), "after the drag, the list");
    let (after, failed) = checks(&s);
    assert_eq!(failed, 0, "every check passes after the drag");
    assert_eq!(after.len(), before.len());
    assert!(
        before.iter().zip(&after).any(|(a, b)| (a - b).abs() > 1e-6),
        "member forces changed"
    );
    assert_ne!(fig_before, figure_text(&s), "the figure changed");

    // A truss on a grid of 1 m, joint C onto joint B: refused with the error line over the
    // last good figure; back: drawn again.
    s.goto(&format!(
        "file://{}",
        dir.join("site/grid_truss.html").display()
    ));
    wait_for(
        &s,
        ready,
        &json!(true),
        "the engine loaded in the grid truss page",
    );
    let good = s.script("return window.graphostatikSite.good().joints[2].at_m;");
    let (cx, cy) = handle_at(&s, "joint C");
    let (bx, by) = handle_at(&s, "joint B");
    s.pointer(
        Some((cx, cy)),
        &[((cx + bx) / 2.0, (cy + by) / 2.0), (bx, by)],
        false,
    );
    wait_for(
        &s,
        "var e = document.getElementById('wt-error');\
         return !!e && e.textContent.indexOf('joint `C` lies on joint `B`') >= 0\
         && document.querySelectorAll('#wt-figure g[data-step]').length > 10;",
        &json!(true),
        "the refusal over the last good figure",
    );
    let last_good = s.script("return window.graphostatikSite.good().joints[2].at_m;");
    assert_ne!(
        last_good,
        json!([2, 0]),
        "the refused scene is not kept as good"
    );
    assert_ne!(last_good, good, "the good positions on the way were drawn");
    s.pointer(None, &[(bx, by - 30.0), (cx, cy)], true);
    wait_for(
        &s,
        "return !document.getElementById('wt-error');",
        &json!(true),
        "the error gone once the joint is back",
    );
    assert_eq!(checks(&s).1, 0);
    assert_eq!(s.script(same), json!(""), "after the refusal and back");

    // The crank page: a quarter turn of the pin at θ = 30° moves it to about 120°. The
    // angles are no longer equally spaced, so the mean piston speed over equal times of a
    // stroke is not drawn: a step fewer. While the pointer moves, the figure takes the step
    // out in place (a splice: no figure parsed anew, no step list) and shows the current
    // page's layers; the step list follows when the pointer is released.
    s.goto(&format!(
        "file://{}",
        dir.join("site/lh_abb52_esselborn.html").display()
    ));
    wait_for(
        &s,
        ready,
        &json!(true),
        "the engine loaded on the crank page",
    );
    let (before, _) = checks(&s);
    let before_counts = s.script("return window.graphostatikSite.counts;");
    let steps_before = s.script("return window.graphostatikSite.answer().steps;");
    let (px, py) = handle_at(&s, "crank pin at θ = 30°");
    let (ox, oy) = center_at(&s, "crank pin at θ = 30°");
    let (rx, ry) = (px - ox, py - oy);
    let arc: Vec<(f64, f64)> = (1..=8)
        .map(|k| {
            // A positive angle turns clockwise on the screen (y down), as the crank turns
            // in LH Abb. 45: θ grows.
            let a = std::f64::consts::FRAC_PI_2 * k as f64 / 8.0;
            (
                ox + rx * a.cos() - ry * a.sin(),
                oy + rx * a.sin() + ry * a.cos(),
            )
        })
        .collect();
    s.pointer(Some((px, py)), &arc, false);
    wait_for(
        &s,
        "var t = window.graphostatikSite.scene().angles.degrees[1]; return t > 110 && t < 130;",
        &json!(true),
        "the crank angle turned by about 90°",
    );
    let spliced = format!(
        "return window.graphostatikSite.counts.splice > {};",
        before_counts["splice"]
    );
    wait_for(&s, &spliced, &json!(true), "the step taken out in place");
    let steps_mid = s.script("return window.graphostatikSite.answer().steps;");
    assert_eq!(
        steps_mid.as_u64().unwrap() + 1,
        steps_before.as_u64().unwrap(),
        "a step fewer"
    );
    let mid = s.script("return window.graphostatikSite.counts;");
    assert_eq!(mid["list"], before_counts["list"], "no step list mid-drag");
    assert_eq!(
        mid["parsed"], before_counts["parsed"],
        "no figure parsed anew"
    );
    assert_eq!(
        s.script(same),
        json!(""),
        "mid-drag, the figure is the answer's"
    );
    // The layers up to the current page's last step shown, its own marked current.
    let layers = "var S = window.graphostatikSite, ul = document.createElement('ul');\
        ul.innerHTML = S.answer().item; var li = ul.firstElementChild;\
        var r0 = Number(li.getAttribute('data-first')), r1 = Number(li.getAttribute('data-last'));\
        return Array.prototype.filter.call(document.querySelector('#wt-figure svg').children,\
          function (g) { if (!g.hasAttribute('data-step')) return false;\
            var n = Number(g.getAttribute('data-step'));\
            return (n > r1) !== (g.style.display === 'none') ||\
              (n >= r0 && n <= r1) !== g.classList.contains('current'); }).length;";
    assert_eq!(s.script(layers), json!(0), "mid-drag, the page's layers");
    s.pointer(None, &[], true);
    let listed = "return [document.querySelectorAll('#wt-steps li').length,\
                  window.graphostatikSite.answer().pages];";
    wait_for(
        &s,
        "var v = [document.querySelectorAll('#wt-steps li').length,\
           window.graphostatikSite.answer().pages]; return v[0] === v[1];",
        &json!(true),
        "after the drag, every step listed",
    );
    let (after, failed) = checks(&s);
    assert_eq!(failed, 0);
    assert!(
        before.iter().zip(&after).any(|(a, b)| (a - b).abs() > 1e-6),
        "the velocities changed"
    );
    assert_eq!(s.script(same), json!(""), "after the crank's drag");
    // The pin at the dead centre θ = 0° turned off it, the step count kept: the figure
    // follows in place.
    let (px, py) = handle_at(&s, "crank pin at θ = 0°");
    let (ox, oy) = center_at(&s, "crank pin at θ = 0°");
    let (rx, ry) = (px - ox, py - oy);
    let arc: Vec<(f64, f64)> = (1..=4)
        .map(|k| {
            let a = 0.1 * k as f64;
            (
                ox + rx * a.cos() - ry * a.sin(),
                oy + rx * a.sin() + ry * a.cos(),
            )
        })
        .collect();
    s.pointer(Some((px, py)), &arc, false);
    wait_for(
        &s,
        "var t = window.graphostatikSite.scene().angles.degrees[0]; return t > 5 && t < 40;",
        &json!(true),
        "the dead-centre pin turned",
    );
    s.pointer(None, &[], true);
    let v = s.script(listed);
    assert_eq!(v[0], v[1], "after the drag, every step listed");
    assert_eq!(
        s.script(same),
        json!(""),
        "after the dead-centre pin's drag"
    );
    // The step count kept, the list was kept and only its changed items put anew.
    let kept = s.script("return window.graphostatikSite.counts;");
    assert_eq!(kept["list"], mid["list"].as_u64().unwrap() + 1, "{kept}");
    assert_eq!(
        s.script("return window.graphostatikSite.listDiffers();"),
        json!(""),
        "after the dead-centre pin's drag, the list"
    );
    let patched = s.script("return window.graphostatikSite.phases.patch > 0;");
    assert_eq!(patched, json!(true), "a replay set the figure in place");
    let errors = s.console_errors();
    assert!(errors.is_empty(), "console errors: {errors:?}");
    drop(s);
    std::fs::remove_dir_all(&dir).ok();
}

/// The replay latency in the browser, per bundled scene: the engine call and the page's
/// update (figure, step list, handles) timed with performance.now, median and worst of 15
/// replays after 3 to warm up, the first handle held as a pointer holds it (the sheet's size
/// and view box kept until the release). README's table comes from
/// `cargo test --release --test it browser::replay_latency -- --ignored --nocapture`
/// (`GRAPHOSTATIK_LATENCY_ONLY=crane,roof` for the scenes whose name holds either,
/// `GRAPHOSTATIK_LATENCY_ENGINE=old.wasm` for another build of the engine).
#[test]
#[ignore = "a measurement: prints README's latency table"]
fn replay_latency() {
    use serde_json::json;
    let Some(browser) = browser_or_skip("latency") else {
        return;
    };
    let Some(built) = engine_or_skip("latency") else {
        return;
    };
    // GRAPHOSTATIK_LATENCY_ENGINE=other.wasm measures another build of the engine (an
    // earlier commit's, say) with this page, so that two engines compare in one run.
    let other = std::env::var_os("GRAPHOSTATIK_LATENCY_ENGINE").map(PathBuf::from);
    let wasm = other.clone().unwrap_or(built);
    let dir = tmp("latency");
    write_site_with(&["scenes"], &dir.join("site"), other.as_deref());
    let s = Session::start(&browser, &dir.join("profile"));
    let gz = {
        let out = Command::new("gzip").arg("-9c").arg(&wasm).output().unwrap();
        out.stdout.len()
    };
    println!(
        "engine: {:.2} MB, {:.2} MB gzipped\n\n| scene | moved | steps | engine median ms | page median ms, parsed anew | page median ms, in place | page worst ms, in place | set in place | step count changed: replays, worst ms | release ms | page's phases, mean ms |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|",
        std::fs::metadata(&wasm).unwrap().len() as f64 / 1e6,
        gz as f64 / 1e6
    );
    let mut scenes: Vec<_> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes"))
            .unwrap()
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
    scenes.sort();
    // GRAPHOSTATIK_LATENCY_ONLY=crane,roof measures only the scenes whose name holds
    // `crane` or `roof`.
    if let Ok(only) = std::env::var("GRAPHOSTATIK_LATENCY_ONLY") {
        let name = |p: &PathBuf| p.file_stem().unwrap().to_string_lossy().into_owned();
        scenes.retain(|p| only.split(',').any(|o| name(p).contains(o)));
    }
    for scene in scenes {
        let name = scene.file_stem().unwrap().to_string_lossy().into_owned();
        s.goto(&format!(
            "file://{}",
            dir.join(format!("site/{name}.html")).display()
        ));
        let ready = "return !!window.graphostatikSite && window.graphostatikSite.ready;";
        wait_for(&s, ready, &json!(true), "the engine loaded");
        // 15 replays with each figure parsed anew, then 15 set in place where they can be
        // (three calls: a script has 30 s, and the crane bridge's take 15 s).
        s.script("var S = window.graphostatikSite; S.bench(3, false, true); S.setInPlace(false);");
        s.script("window.gsAnew = window.graphostatikSite.bench(15, false, true);");
        let v = s.script(
            "var S = window.graphostatikSite, median = function (t, f) {\
               var v = t.map(f).sort(function (a, b) { return a - b; }); return v[v.length >> 1]; };\
             S.setInPlace(true); S.bench(3, false, true);\
             for (var k in S.phases) S.phases[k] = 0; var t = S.bench(15, false, true);\
             var total = function (x) { return x.total; };\
             var worst = t.map(total).sort(function (a, b) { return b - a; })[0];\
             var ph = Object.keys(S.phases).filter(function (k) { return S.phases[k] > 0; })\
               .map(function (k) { return k + ' ' + (S.phases[k] / 15).toFixed(1); });\
             var moved = t.filter(function (x, i) { return x.steps !== (i ? t[i - 1].steps : t.before); });\
             var movedWorst = moved.map(total).sort(function (a, b) { return b - a; })[0];\
             return [S.answer().steps, median(t, function (x) { return x.engine; }),\
               median(window.gsAnew, total), median(t, total), worst,\
               t.filter(function (x) { return x.inPlace; }).length, t.length, ph.join(', '),\
               moved.length ? moved.length + ', worst ' + movedWorst.toFixed(1) : '–', t.release,\
               t.moved];",
        );
        println!(
            "| {name} | {} | {} | {:.1} | {:.1} | {:.1} | {:.1} | {} of {} | {} | {:.1} | {} |",
            v[10].as_str().unwrap_or("nothing"),
            v[0],
            v[1].as_f64().unwrap(),
            v[2].as_f64().unwrap(),
            v[3].as_f64().unwrap(),
            v[4].as_f64().unwrap(),
            v[5],
            v[6],
            v[8].as_str().unwrap_or_default(),
            v[9].as_f64().unwrap_or(f64::NAN),
            v[7].as_str().unwrap_or_default()
        );
    }
    drop(s);
    std::fs::remove_dir_all(&dir).ok();
}
