//! The JSON Schema editors complete scenes with: committed beside the scenes, current with the
//! code, and named by every bundled scene's `$schema` line.

use std::path::Path;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// `schema/scene.schema.json` is what `graphostatik schema` writes today: a changed scene
/// field changes it, and the file is regenerated with
/// `cargo run --release -- schema > schema/scene.schema.json`.
#[cfg(feature = "schema")]
#[test]
fn the_committed_schema_is_the_one_the_code_writes() {
    let committed =
        std::fs::read_to_string(Path::new(ROOT).join("schema/scene.schema.json")).unwrap();
    assert_eq!(
        committed.trim_end(),
        graphostatik::scene::schema_json().trim_end(),
        "regenerate: cargo run --release -- schema > schema/scene.schema.json"
    );
}

/// `docs/scene-reference.md` is the scene reference the code writes today, regenerated with
/// `cargo run --release -- schema --markdown > docs/scene-reference.md`.
#[cfg(feature = "schema")]
#[test]
fn the_committed_scene_reference_is_the_one_the_code_writes() {
    let committed =
        std::fs::read_to_string(Path::new(ROOT).join("docs/scene-reference.md")).unwrap();
    assert_eq!(
        committed.trim_end(),
        graphostatik::scene::reference_markdown().trim_end(),
        "regenerate: cargo run --release -- schema --markdown > docs/scene-reference.md"
    );
}

/// Every bundled scene begins with `"$schema": "../schema/scene.schema.json"`, and the
/// key is accepted (and ignored) by every procedure.
#[test]
fn every_bundled_scene_names_the_schema() {
    let mut n = 0;
    for entry in std::fs::read_dir(Path::new(ROOT).join("scenes")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let named = v["$schema"].as_str().unwrap_or("");
        assert_eq!(named, "../schema/scene.schema.json", "{}", path.display());
        assert!(path.parent().unwrap().join(named).exists());
        assert!(graphostatik::scene::AnyScene::from_json(&text, "s.json").is_ok());
        n += 1;
    }
    assert!(n >= 30);
    // A scene without the line is as good.
    let text = std::fs::read_to_string(Path::new(ROOT).join("scenes/kg_tafel1.json")).unwrap();
    let bare = text.replace("\"$schema\": \"../schema/scene.schema.json\",", "");
    assert_ne!(bare, text);
    assert!(graphostatik::scene::AnyScene::from_json(&bare, "b.json").is_ok());
}
