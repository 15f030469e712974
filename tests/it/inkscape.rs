//! Every bundled figure opens in Inkscape with its step layers in step
//! order. Run where Inkscape is installed (`apt-get install inkscape`); elsewhere the test says
//! so and passes, and `tests/it/snapshots.rs` checks the same layers' names in the text.
//!
//! `inkscape --query-all` lists every object Inkscape reads, in document order, with its
//! bounding box; a layer that draws nothing (a step that only measures) has no box and is not
//! listed. So the layers it lists must be exactly the non-empty `step-NNN` layers of the file,
//! in step order, each with a finite box.

use std::path::Path;
use std::process::Command;

/// The `step-NNN` layers of an SVG that hold something, in document order.
fn drawn_layers(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    for part in svg.split("<g ").skip(1) {
        let Some(head_end) = part.find('>') else {
            continue;
        };
        let head = &part[..head_end];
        let Some(id) = head
            .split("id=\"")
            .nth(1)
            .and_then(|r| r.split('"').next())
            .filter(|id| id.starts_with("step-"))
        else {
            continue;
        };
        let empty = head.ends_with('/') || part[head_end + 1..].trim_start().starts_with("</g>");
        if !empty {
            out.push(id.to_string());
        }
    }
    out
}

#[test]
fn every_figure_opens_in_inkscape_with_its_layers_in_step_order() {
    let Ok(v) = Command::new("inkscape").arg("--version").output() else {
        eprintln!("inkscape is not installed: the check is skipped (apt-get install inkscape)");
        return;
    };
    assert!(v.status.success());
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("figures");
    let home = std::env::temp_dir().join(format!("graphostatik-inkscape-{}", std::process::id()));
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "svg") {
            continue;
        }
        let svg = std::fs::read_to_string(&path).unwrap();
        let o = Command::new("inkscape")
            .arg("--query-all")
            .arg(&path)
            .env("HOME", &home)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", path.display());
        let listed: Vec<(String, Vec<f64>)> = String::from_utf8_lossy(&o.stdout)
            .lines()
            .filter(|l| l.starts_with("step-"))
            .map(|l| {
                let mut f = l.split(',');
                let id = f.next().unwrap().to_string();
                (id, f.map(|x| x.parse().unwrap_or(f64::NAN)).collect())
            })
            .collect();
        let ids: Vec<String> = listed.iter().map(|(id, _)| id.clone()).collect();
        assert_eq!(ids, drawn_layers(&svg), "{}", path.display());
        assert!(!ids.is_empty(), "{}", path.display());
        for (id, bbox) in &listed {
            assert!(
                bbox.len() == 4 && bbox.iter().all(|x| x.is_finite()),
                "{id}: {bbox:?}"
            );
        }
        n += 1;
    }
    assert!(n >= 30, "{n} figures");
    let _ = std::fs::remove_dir_all(&home);
}
