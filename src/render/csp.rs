//! The Content-Security-Policy every page the engine writes carries: scripts and style sheets
//! run only where the page's own author wrote them, never where a scene's text could.
//!
//! A page inlines its scripts and style sheets (a walk-through opens from the file system as
//! one file), so the policy names each by its SHA-256 hash (CSP Level 3, "hash-source") rather
//! than allowing inline code at large. The page's writer names the scripts and sheets it
//! wrote (the hashes are not taken from the finished page, which would allow whatever a name
//! smuggled into it): an attribute a hostile name put there (`onmouseover="…"`) or an element
//! it opened would not be run even if an escape were missed. Event handlers in attributes never run under it (no `'unsafe-inline'`, no
//! `'unsafe-hashes'`), nor `style` attributes; the figures style their marks by classes and
//! presentation attributes.

use base64::Engine as _;
use sha2::{Digest, Sha256};

/// What a page may load beyond its own inline scripts and style sheets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Allow {
    /// Scripts from the page's own origin (`<script src>`: the site's `engine.js`, `page.js`).
    pub own_scripts: bool,
    /// Compiling WebAssembly (`'wasm-unsafe-eval'`): the site's engine.
    pub wasm: bool,
    /// Requests to the page's own origin (`fetch`: `serve`'s reload poll).
    pub connect: bool,
}

/// The policy of a page whose inline scripts are `scripts` and whose inline style sheets
/// are `styles` (each the exact text between its tags, as the browser hashes it: an inline
/// SVG's sheet with its entities decoded). Each is named by its hash, so that a script or
/// sheet the page's author did not write (one a name smuggled in) is not run; images from the
/// page's own folder, `data:` and `blob:`; nothing else unless `allow` says so.
///
/// ```
/// use graphostatik::render::{content_security_policy, Allow};
/// let p = content_security_policy(&["go()"], &["b{}"], Allow::default());
/// assert!(p.starts_with("default-src 'none'; script-src 'sha256-"));
/// assert!(!p.contains("unsafe-inline"));
/// ```
pub fn content_security_policy(scripts: &[&str], styles: &[&str], allow: Allow) -> String {
    let mut p = String::from("default-src 'none'; script-src");
    if allow.own_scripts {
        p.push_str(" 'self'");
    }
    if allow.wasm {
        p.push_str(" 'wasm-unsafe-eval'");
    }
    sources(&mut p, scripts);
    if scripts.is_empty() && !allow.own_scripts && !allow.wasm {
        p.push_str(" 'none'");
    }
    p.push_str("; style-src");
    sources(&mut p, styles);
    if styles.is_empty() {
        p.push_str(" 'none'");
    }
    p.push_str("; img-src 'self' data: blob:");
    if allow.connect {
        p.push_str("; connect-src 'self'");
    }
    p.push_str("; base-uri 'none'; form-action 'none'");
    p
}

/// `page` with its policy ([`content_security_policy`]) as a `<meta http-equiv>` at the top
/// of its head, right after `<meta charset="utf-8">` (or after `<head>`).
pub fn with_policy(page: String, scripts: &[&str], styles: &[&str], allow: Allow) -> String {
    let policy = content_security_policy(scripts, styles, allow);
    let meta = format!("<meta http-equiv=\"Content-Security-Policy\" content=\"{policy}\">\n");
    let at = [
        "<meta charset=\"utf-8\">\n",
        "<meta charset=\"utf-8\">",
        "<head>\n",
        "<head>",
    ]
    .iter()
    .find_map(|m| page.find(m).map(|i| i + m.len()));
    match at {
        Some(i) => {
            let mut out = String::with_capacity(page.len() + meta.len());
            out.push_str(&page[..i]);
            out.push_str(&meta);
            out.push_str(&page[i..]);
            out
        }
        None => meta + &page,
    }
}

/// Each text's hash as a source, once.
fn sources(p: &mut String, texts: &[&str]) {
    let mut seen: Vec<String> = Vec::new();
    for t in texts {
        let h = hash(t);
        if seen.contains(&h) {
            continue;
        }
        p.push_str(" 'sha256-");
        p.push_str(&h);
        p.push('\'');
        seen.push(h);
    }
}

/// The base64 of the SHA-256 of `text`, as a hash-source names it.
fn hash(text: &str) -> String {
    base64::engine::general_purpose::STANDARD.encode(Sha256::digest(text.as_bytes()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_text_is_named_once_by_its_hash() {
        let p = content_security_policy(&["f()", "f()"], &["a{}"], Allow::default());
        assert_eq!(p.matches("'sha256-").count(), 2, "{p}");
        assert!(p.contains(&hash("f()")) && p.contains(&hash("a{}")));
        let page = "<head><meta charset=\"utf-8\">\n<title>t</title>".to_string();
        let secured = with_policy(page, &[], &[], Allow::default());
        assert!(secured.starts_with(
            "<head><meta charset=\"utf-8\">\n<meta http-equiv=\"Content-Security-Policy\""
        ));
    }

    #[test]
    fn a_page_without_scripts_runs_none() {
        let p = content_security_policy(&[], &[], Allow::default());
        assert!(p.contains("script-src 'none'") && p.contains("style-src 'none'"));
    }

    /// The hash of "" is the one CSP's examples give for an empty script.
    #[test]
    fn hashes_are_base64_of_sha256() {
        assert_eq!(hash(""), "47DEQpj8HBSa+/TImW+5JCeuQeRkm5NMpJWZG3hSuFU=");
    }
}
