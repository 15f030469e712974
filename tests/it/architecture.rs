//! The shape of the source tree, checked: the layers of the crate docs use only the layers
//! before them, no two modules import each other (directly or round a loop), no function
//! of a procedure runs over the length at which it should be split, no thread-local state
//! outside a documented cache, and docs and comments point only at what the repository holds.
//!
//! An edge A → B is a path from a file of module A into module B: `crate::…`, `super::…`,
//! `self::…`, or a child module's name. A parent's re-exports (`pub use child::X;`) declare
//! its face and are not uses; test modules are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Module = Vec<String>;

fn modules() -> BTreeMap<Module, PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = BTreeMap::new();
    let mut stack = vec![root.clone()];
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let rel = p.strip_prefix(&root).unwrap().with_extension("");
                let mut m: Module = rel.iter().map(|s| s.to_string_lossy().into()).collect();
                if matches!(m.last().map(String::as_str), Some("mod" | "lib" | "main")) {
                    m.pop();
                }
                out.insert(m, p);
            }
        }
    }
    out
}

/// The source a module depends on: comments, re-exports and test modules taken out.
fn uses_of(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    let mut out = String::new();
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("");
        if !code.trim_start().starts_with("pub use ") {
            out.push_str(code);
            out.push('\n');
        }
    }
    out
}

/// Every `a::b::c` path in the text (identifiers joined by `::`), with its start.
fn paths(text: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let b = text.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut i = 0;
    while i < b.len() {
        if ident(b[i]) && (i == 0 || !(ident(b[i - 1]) || b[i - 1] == b':')) {
            let mut segs = Vec::new();
            let mut j = i;
            loop {
                let s = j;
                while j < b.len() && ident(b[j]) {
                    j += 1;
                }
                segs.push(text[s..j].to_string());
                if text[j..].starts_with("::") && j + 2 < b.len() && ident(b[j + 2]) {
                    j += 2;
                } else if text[j..].starts_with("::{") {
                    // A use group: each member continues the path.
                    let end = text[j..].find('}').map_or(b.len(), |e| j + e);
                    for item in text[j + 3..end].split(',') {
                        let first = item.trim().split("::").next().unwrap_or("").trim();
                        if !first.is_empty() && first != "self" {
                            let mut p = segs.clone();
                            p.push(first.to_string());
                            out.push(p);
                        }
                    }
                    j = end;
                    break;
                } else {
                    break;
                }
            }
            if segs.len() > 1 {
                out.push(segs);
            }
            i = j.max(i + 1);
        } else {
            i += 1;
        }
    }
    out
}

fn resolve(mods: &BTreeMap<Module, PathBuf>, cur: &Module, path: &[String]) -> Option<Module> {
    let (mut base, rest): (Module, &[String]) = match path[0].as_str() {
        "crate" => (vec![], &path[1..]),
        "self" => (cur.clone(), &path[1..]),
        "super" => {
            let mut b = cur.clone();
            let mut k = 0;
            while k < path.len() && path[k] == "super" {
                b.pop();
                k += 1;
            }
            (b, &path[k..])
        }
        first => {
            let mut child = cur.clone();
            child.push(first.to_string());
            if !mods.contains_key(&child) {
                return None;
            }
            (cur.clone(), path)
        }
    };
    let mut best = base.clone();
    for seg in rest {
        base.push(seg.clone());
        if mods.contains_key(&base) {
            best = base.clone();
        } else {
            break;
        }
    }
    Some(best)
}

fn edges(mods: &BTreeMap<Module, PathBuf>) -> BTreeMap<Module, BTreeSet<Module>> {
    let mut out = BTreeMap::new();
    for (m, p) in mods {
        let text = uses_of(&std::fs::read_to_string(p).unwrap());
        let mut to = BTreeSet::new();
        for path in paths(&text) {
            if let Some(t) = resolve(mods, m, &path) {
                if &t != m && mods.contains_key(&t) {
                    to.insert(t);
                }
            }
        }
        out.insert(m.clone(), to);
    }
    out
}

/// The layer of a module, as the crate docs list them.
fn layer(m: &Module) -> usize {
    match m.first().map(String::as_str) {
        None => 6, // lib.rs, main.rs: the crate root and the command line
        Some("kernel" | "fmt" | "io" | "jobs") => 0,
        Some("protocol") => 1,
        Some("crank" | "dynamics" | "mechanisms" | "statics" | "truss") => 2,
        Some("scene") => 3,
        Some("render") => 4,
        Some("prelude" | "serve" | "web" | "site") => 5,
        Some(other) => panic!("module {other} is in no layer: add it to the layer list"),
    }
}

#[test]
fn every_layer_uses_only_the_layers_before_it() {
    let mods = modules();
    let mut wrong = Vec::new();
    for (a, to) in edges(&mods) {
        for b in to {
            if layer(&b) > layer(&a) {
                wrong.push(format!("{} -> {}", a.join("::"), b.join("::")));
            }
        }
    }
    assert!(wrong.is_empty(), "imports against the layers: {wrong:#?}");
}

#[test]
fn no_module_imports_another_round_a_loop() {
    let mods = modules();
    let e = edges(&mods);
    // Tarjan's strongly connected components.
    struct St<'a> {
        e: &'a BTreeMap<Module, BTreeSet<Module>>,
        index: BTreeMap<Module, usize>,
        low: BTreeMap<Module, usize>,
        stack: Vec<Module>,
        on: BTreeSet<Module>,
        next: usize,
        loops: Vec<Vec<String>>,
    }
    fn visit(s: &mut St, v: &Module) {
        s.index.insert(v.clone(), s.next);
        s.low.insert(v.clone(), s.next);
        s.next += 1;
        s.stack.push(v.clone());
        s.on.insert(v.clone());
        for w in s.e[v].clone() {
            if !s.index.contains_key(&w) {
                visit(s, &w);
                let l = s.low[v].min(s.low[&w]);
                s.low.insert(v.clone(), l);
            } else if s.on.contains(&w) {
                let l = s.low[v].min(s.index[&w]);
                s.low.insert(v.clone(), l);
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on.remove(&w);
                comp.push(w.join("::"));
                if &w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                s.loops.push(comp);
            }
        }
    }
    let mut s = St {
        e: &e,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        next: 0,
        loops: Vec::new(),
    };
    for v in mods.keys() {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    assert!(
        s.loops.is_empty(),
        "modules that import each other: {:#?}",
        s.loops
    );
    assert!(e.len() > 60, "the tree was read: {} modules", e.len());
}

#[test]
fn the_checker_finds_a_loop_and_a_layer_breach() {
    // The resolver on a made-up tree: a -> b through `super::b`, b -> a through `crate::a`.
    let mut mods = BTreeMap::new();
    for m in [vec![], vec!["a".to_string()], vec!["b".to_string()]] {
        mods.insert(m, PathBuf::new());
    }
    let a = vec!["a".to_string()];
    let p = paths("use super::b::{X, Y};\nlet z = crate::a::f();");
    assert_eq!(resolve(&mods, &a, &p[0]), Some(vec!["b".to_string()]));
    assert_eq!(resolve(&mods, &a, &p[p.len() - 1]), Some(a.clone()));
    assert!(layer(&vec!["render".to_string()]) > layer(&vec!["scene".to_string()]));
}

/// The length of every function in the file (first line of `fn` to its closing brace), by
/// brace matching outside strings and comments.
fn function_lengths(text: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let t = line.trim_start();
        let t = t
            .strip_prefix("pub(crate) ")
            .or_else(|| t.strip_prefix("pub(super) "))
            .or_else(|| t.strip_prefix("pub "))
            .unwrap_or(t);
        let t = t.strip_prefix("const ").unwrap_or(t);
        let Some(rest) = t.strip_prefix("fn ") else {
            continue;
        };
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let (mut depth, mut started) = (0i32, false);
        for (j, l) in lines.iter().enumerate().skip(i) {
            let code = strip_strings(l);
            for c in code.chars() {
                match c {
                    '{' => {
                        depth += 1;
                        started = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if !started && code.trim_end().ends_with(';') {
                break; // a declaration without a body
            }
            if started && depth <= 0 {
                out.push((name.clone(), i + 1, j - i + 1));
                break;
            }
        }
    }
    out
}

/// A line with its string and char literals emptied and its comment cut.
fn strip_strings(line: &str) -> String {
    let mut out = String::new();
    let mut chars = line.chars().peekable();
    let mut in_str = false;
    while let Some(c) = chars.next() {
        if in_str {
            match c {
                '\\' => {
                    chars.next();
                }
                '"' => in_str = false,
                _ => {}
            }
        } else if c == '"' {
            in_str = true;
        } else if c == '/' && chars.peek() == Some(&'/') {
            break;
        } else if c == '\'' {
            // A char literal ('{', '\n') or a lifetime ('a): skip a literal's body.
            let ahead: String = chars.clone().take(3).collect();
            if ahead.starts_with('\\') || ahead.chars().nth(1) == Some('\'') {
                while let Some(d) = chars.next() {
                    if d == '\\' {
                        chars.next();
                    } else if d == '\'' {
                        break;
                    }
                }
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// Longest a function may run before it should be split (the guide's "~80 lines").
const MAX_FUNCTION_LINES: usize = 80;

#[test]
fn no_function_runs_over_eighty_lines() {
    let mut long = Vec::new();
    for (m, p) in modules() {
        let text = std::fs::read_to_string(&p).unwrap();
        let text = text.split("#[cfg(test)]").next().unwrap_or("");
        for (name, line, len) in function_lengths(text) {
            if len > MAX_FUNCTION_LINES {
                long.push(format!(
                    "{}::{name} (line {line}): {len} lines",
                    m.join("::")
                ));
            }
        }
    }
    assert!(long.is_empty(), "split these: {long:#?}");
}

#[test]
fn function_lengths_are_measured_through_strings_and_braces() {
    let text = "fn a() {\n    let s = \"{\";\n    let c = '}';\n}\nfn b();\npub fn c() { }\n";
    let got = function_lengths(text);
    assert_eq!(got, vec![("a".into(), 1, 4), ("c".into(), 6, 1)]);
}

/// Every text file under `dir` (recursively) with one of the extensions, skipping build
/// output and installed packages.
fn files_under(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap_or_default().to_string_lossy();
        if p.is_dir() {
            if !matches!(name.as_ref(), "target" | "node_modules" | ".git") {
                files_under(&p, exts, out);
            }
        } else if p.extension().is_some_and(|x| exts.iter().any(|e| x == *e)) {
            out.push(p);
        }
    }
}

/// A `thread_local!` is state that a call cannot see: it may hold a cache (what is kept must
/// not change a result), documented as one within the five lines above it, and nothing else.
#[test]
fn no_thread_local_state_outside_a_documented_cache() {
    let mut found = Vec::new();
    for p in modules().values() {
        let text = std::fs::read_to_string(p).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            if !l.trim_start().starts_with(concat!("thread_", "local!")) {
                continue;
            }
            let above = &lines[i.saturating_sub(5)..i];
            let documented = above
                .iter()
                .any(|a| a.trim_start().starts_with("//") && a.contains("cache"));
            if !documented {
                found.push(format!("{}:{}", p.display(), i + 1));
            }
        }
    }
    assert!(found.is_empty(), "state a call cannot see: {found:#?}");
}

/// Where a text points outside the repository: at the list of procedures the books were
/// read into (not shipped here) or at an issue tracker's numbers, which mean nothing to a
/// reader of the repository. Books are cited by their sections (LH C.4, KG Abb. 1047).
fn outside_pointers(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let lower = text.to_lowercase();
    // The outside list is spelt in capitals; `docs/procedures.md` is the repository's own.
    let procedures = concat!("PROCEDURES", ".md");
    for (k, _) in text.match_indices(procedures) {
        out.push(text[k..].chars().take(40).collect());
    }
    for (k, _) in lower.match_indices("issue") {
        let rest = lower[k + 5..].trim_start_matches([' ', '#']);
        let spaced = lower[k + 5..].starts_with([' ', '#']);
        if spaced && rest.starts_with(|c: char| c.is_ascii_digit()) {
            out.push(text[k..].chars().take(40).collect());
        }
    }
    out
}

#[test]
fn docs_and_comments_point_only_into_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["src", "tests", "benches", "examples", "fuzz", "docs", ".ci"] {
        files_under(
            &root.join(dir),
            &["rs", "md", "py", "sh", "js", "html"],
            &mut files,
        );
    }
    files_under(root, &["md"], &mut files);
    files.sort();
    files.dedup();
    let mut found = Vec::new();
    for p in &files {
        let text = std::fs::read_to_string(p).unwrap_or_default();
        for hit in outside_pointers(&text) {
            found.push(format!("{}: {hit}", p.display()));
        }
    }
    assert!(found.is_empty(), "point into the repository: {found:#?}");
}

#[test]
fn the_pointer_test_finds_what_it_looks_for() {
    let issue = concat!("Iss", "ue 12, case 3");
    assert_eq!(outside_pointers(issue).len(), 1);
    assert_eq!(
        outside_pointers(&format!("see {}", concat!("PROCEDURES", ".md D1"))).len(),
        1
    );
    assert_eq!(outside_pointers(concat!("(iss", "ue #7)")).len(), 1);
    assert!(outside_pointers("an issue of the book, LH C.4, 12 issues").is_empty());
}

/// README is a front page (what it is, a picture, the set-up, one example per command, where
/// next); the rest lives in `docs/`.
#[test]
fn the_readme_is_a_front_page() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(
        lines <= 250,
        "README.md has {lines} lines: move detail to docs/"
    );
    // Every document it points to is there.
    for link in readme.split("](").skip(1) {
        let target = link.split(')').next().unwrap();
        if target.starts_with("http") || target.starts_with('#') {
            continue;
        }
        assert!(
            root.join(target).exists(),
            "README links to missing {target}"
        );
    }
}
