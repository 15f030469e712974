//! The scene reference: the JSON Schema of the scene format written out as Markdown, a
//! section per procedure with a table of its fields, then every type the fields use. It is
//! generated, never written by hand, so that it says what the code reads today:
//! `graphostatik schema --markdown > docs/scene-reference.md` (a test keeps the committed
//! file current).

use serde_json::{Map, Value};
use std::collections::BTreeSet;

/// The scene reference as Markdown, from the schema of [`schema_json`](super::schema_json).
pub fn reference_markdown() -> String {
    let schema: Value =
        serde_json::from_str(&super::schema_json()).expect("the schema is the code's own JSON");
    let defs = schema["$defs"].as_object().cloned().unwrap_or_default();
    let mut out = String::from(HEADER);
    let mut used = BTreeSet::new();
    for branch in schema["anyOf"].as_array().into_iter().flatten() {
        let name = ref_name(branch).unwrap_or_default();
        let about = branch["description"].as_str().unwrap_or_default();
        let (procedure, what) = about.split_once(": ").unwrap_or((about, ""));
        out += &format!("\n## `{procedure}`\n\n{}\n\n", capitalised(&sentence(what)));
        out += &format!("Scene type `{name}`.\n\n");
        out += &object_table(&defs[&name], &mut used);
    }
    let scenes: BTreeSet<String> = schema["anyOf"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(ref_name)
        .collect();
    out += "\n## Types the fields use\n";
    let mut done = BTreeSet::new();
    while let Some(name) = used.iter().find(|n| !done.contains(*n)).cloned() {
        done.insert(name.clone());
        if scenes.contains(&name) {
            continue;
        }
        out += &type_section(&name, &defs, &mut used);
    }
    out
}

const HEADER: &str = "# Scene reference

Generated from the JSON Schema of the scene format (`graphostatik schema --markdown`); do not
edit by hand. A scene is a JSON object; its `procedure` field picks the procedure
(`slider_crank` when absent). Unknown fields are refused. How scenes are put together,
procedure by procedure, is in [scenes](scenes.md); what each procedure constructs, in
[procedures](procedures.md).
";

/// The name of the definition a `{"$ref": "#/$defs/X"}` points at.
fn ref_name(v: &Value) -> Option<String> {
    v["$ref"]
        .as_str()
        .and_then(|r| r.strip_prefix("#/$defs/"))
        .map(str::to_string)
}

/// A description on one line, ending in a full stop.
fn sentence(text: &str) -> String {
    let one = text.split_whitespace().collect::<Vec<_>>().join(" ");
    match one.chars().last() {
        None => String::new(),
        Some('.' | ')' | ':') => one,
        Some(_) => one + ".",
    }
}

/// The text with its first letter a capital.
fn capitalised(text: &str) -> String {
    let mut c = text.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => String::new(),
    }
}

/// A table cell: one line, with the pipes escaped.
fn cell(text: &str) -> String {
    sentence(text).replace('|', "\\|")
}

/// The type of a schema node, written short: a link to a definition, `number`, `[number]`,
/// `string or null`, a constant.
fn type_of(v: &Value, used: &mut BTreeSet<String>) -> String {
    if let Some(name) = ref_name(v) {
        used.insert(name.clone());
        return format!("[`{name}`](#{})", name.to_lowercase());
    }
    if let Some(c) = v.get("const") {
        return format!("`{c}`");
    }
    if let Some(alts) = v
        .get("anyOf")
        .or_else(|| v.get("oneOf"))
        .and_then(Value::as_array)
    {
        let parts: Vec<String> = alts.iter().map(|a| type_of(a, used)).collect();
        return parts.join(" or ");
    }
    let kinds: Vec<&str> = match &v["type"] {
        Value::String(s) => vec![s.as_str()],
        Value::Array(a) => a.iter().filter_map(Value::as_str).collect(),
        _ => vec![],
    };
    let parts: Vec<String> = kinds
        .iter()
        .map(|k| match *k {
            "array" => match v.get("items") {
                Some(items) if items.is_array() => "tuple".to_string(),
                Some(items) => format!("[{}]", type_of(items, used)),
                None => "array".to_string(),
            },
            "object" if v.get("properties").is_some() => "object".to_string(),
            "object" => "map".to_string(),
            k => k.to_string(),
        })
        .collect();
    if parts.is_empty() {
        "any".to_string()
    } else {
        parts.join(" or ")
    }
}

/// The table of an object's fields: name, type, whether required, what it means.
fn object_table(def: &Value, used: &mut BTreeSet<String>) -> String {
    let Some(props) = def["properties"].as_object() else {
        return String::new();
    };
    let required: BTreeSet<&str> = def["required"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(Value::as_str)
        .collect();
    let mut out = String::from("| field | type | | meaning |\n|---|---|---|---|\n");
    for (name, p) in sorted(props) {
        let need = if required.contains(name.as_str()) {
            "required"
        } else {
            ""
        };
        let meaning = p["description"].as_str().unwrap_or_default();
        out += &format!(
            "| `{name}` | {} | {need} | {} |\n",
            type_of(p, used),
            cell(meaning)
        );
    }
    out
}

/// Properties by name, as the schema lists them.
fn sorted(props: &Map<String, Value>) -> Vec<(String, &Value)> {
    let mut v: Vec<(String, &Value)> = props.iter().map(|(k, p)| (k.clone(), p)).collect();
    v.sort_by(|a, b| a.0.cmp(&b.0));
    v
}

/// One definition: a table of its fields, or the list of the forms it takes.
fn type_section(name: &str, defs: &Map<String, Value>, used: &mut BTreeSet<String>) -> String {
    let Some(def) = defs.get(name) else {
        return String::new();
    };
    let mut out = format!("\n### {name}\n\n");
    let about = def["description"].as_str().unwrap_or_default();
    if !about.is_empty() {
        out += &format!("{}\n\n", sentence(about));
    }
    if let Some(alts) = def
        .get("oneOf")
        .or_else(|| def.get("anyOf"))
        .and_then(Value::as_array)
    {
        out += "One of:\n\n";
        for a in alts {
            out += &format!("- {}\n", variant(a, used));
        }
    } else if def.get("properties").is_some() {
        out += &object_table(def, used);
    } else {
        out += &format!("A {}.\n", type_of(def, used));
    }
    out
}

/// One form of a one-of: a constant, an object with one key, or another type.
fn variant(a: &Value, used: &mut BTreeSet<String>) -> String {
    let about = cell(a["description"].as_str().unwrap_or_default());
    let form = match (a.get("const"), a["properties"].as_object()) {
        (Some(c), _) => format!("`{c}`"),
        (None, Some(props)) if props.len() == 1 => {
            let (k, p) = props.iter().next().expect("one property");
            format!("`{{\"{k}\": …}}` with {}", type_of(p, used))
        }
        (None, Some(_)) => {
            let fields: Vec<String> = a["properties"]
                .as_object()
                .into_iter()
                .flatten()
                .map(|(k, p)| format!("`{k}`: {}", type_of(p, used)))
                .collect();
            format!("an object of {}", fields.join(", "))
        }
        _ => type_of(a, used),
    };
    if about.is_empty() {
        form
    } else {
        format!("{form}: {about}")
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_procedure_and_every_type_it_uses_has_a_section() {
        let md = super::reference_markdown();
        for e in super::super::REGISTRY {
            assert!(md.contains(&format!("\n## `{}`\n", e.name)), "{}", e.name);
        }
        // A type a field links to is described further down.
        for link in md.split("](#").skip(1) {
            let anchor = link.split(')').next().unwrap();
            assert!(
                md.to_lowercase().contains(&format!("\n### {anchor}\n")),
                "{anchor} has no section"
            );
        }
    }
}
