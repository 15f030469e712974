//! What changed between two figures, for a page that shows the first: the lines that
//! changed, by the root's child they are in, and the children whose elements changed.
//!
//! A drag moves points; it seldom adds or drops an element. The page keeps the figure it shows
//! by the root's children (the title, the style, the definitions, the sheet, one layer per
//! step), each as its lines beside its nodes. Given the lines that changed, it sets the
//! attributes and texts that changed; given a child anew, it parses that child alone. Found
//! here, the difference costs the engine a comparison of bytes, where the page would split
//! the whole figure into lines and compare them (the crane bridge's 31,000 lines, 2 MB).

use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Serialize, Serializer};

/// The changes that turn one figure into another: see [`figure_patch`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FigurePatch<'a> {
    /// The root's opening tag, where it changed.
    pub root: Option<&'a str>,
    /// Where the number of the root's children changed (a step more or fewer: a crank off
    /// its dead centre, a diagonal gone slack): from child `at` on, `removed` children of the
    /// old figure give way to `added`, whole. It is applied first: [`FigurePatch::lines`] and
    /// [`FigurePatch::children`] count the children of the new figure.
    pub splice: Option<Splice>,
    /// `(child, line, text)`: line `line` of the root's child `child` (its own first line 0)
    /// is now `text`: a tag with the same name, or a text inside a `text`, `style` or
    /// `title` element.
    pub lines: Vec<(usize, usize, &'a str)>,
    /// `(child, text)`: the root's child `child` whose elements changed, whole.
    pub children: Vec<(usize, String)>,
    /// What each of [`FigurePatch::lines`] held before, in their order.
    was: Vec<&'a str>,
}

/// Children of the root put in place of others: see [`FigurePatch::splice`].
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Splice {
    /// The first child replaced (in both figures: the children before it are paired).
    pub at: usize,
    /// How many children of the old figure go.
    pub removed: usize,
    /// The new figure's children that come in their place, each whole.
    pub added: Vec<String>,
}

impl FigurePatch<'_> {
    /// Whether the two figures are the same.
    pub fn is_empty(&self) -> bool {
        self.root.is_none()
            && self.splice.is_none()
            && self.lines.is_empty()
            && self.children.is_empty()
    }

    /// The patch as the page reads it: `{"root": …, "splice": {"at": …, "removed": …,
    /// "added": […]}, "lines": [[child, line, text, sets], …], "children": [[child, text],
    /// …]}`. `sets`, on a tag's line, lists the attributes that changed as
    /// `name, value, name, value, …` (the value as written, `null` for one gone), so that
    /// the page sets them without reading the two tags; a text's line has none.
    ///
    /// ```
    /// use graphostatik::web::figure_patch;
    /// let old = "<svg>\n<g>\n<line x1=\"0\" y1=\"1\" k=\"a\"/>\n</g>\n</svg>\n";
    /// let new = "<svg>\n<g>\n<line x1=\"0\" y1=\"2\"/>\n</g>\n</svg>\n";
    /// let json = figure_patch(old, new).unwrap().to_json();
    /// assert!(json.contains(r#"[0,1,"<line x1=\"0\" y1=\"2\"/>",["y1","2","k",null]]"#));
    /// ```
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| String::from("null"))
    }
}

impl Serialize for FigurePatch<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("root", &self.root)?;
        if let Some(sp) = &self.splice {
            m.serialize_entry("splice", sp)?;
        }
        let lines: Vec<Line> = (self.lines.iter().enumerate())
            .map(|(i, &(child, line, now))| Line {
                child,
                line,
                now,
                was: self.was.get(i).copied(),
            })
            .collect();
        m.serialize_entry("lines", &lines)?;
        m.serialize_entry("children", &self.children)?;
        m.end()
    }
}

/// One of a patch's lines as the page reads it: see [`FigurePatch::to_json`].
struct Line<'a> {
    child: usize,
    line: usize,
    now: &'a str,
    was: Option<&'a str>,
}

impl Serialize for Line<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let was = self.was.filter(|w| matches!(kind(w), Kind::Tag(_)));
        let mut q = s.serialize_seq(Some(3 + usize::from(was.is_some())))?;
        q.serialize_element(&self.child)?;
        q.serialize_element(&self.line)?;
        q.serialize_element(self.now)?;
        if let Some(was) = was {
            q.serialize_element(&AttributeSets(was, self.now))?;
        }
        q.end()
    }
}

/// The attributes that changed from one tag to the next, flat: see
/// [`FigurePatch::to_json`].
struct AttributeSets<'a>(&'a str, &'a str);

impl Serialize for AttributeSets<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let (was, now): (Vec<_>, Vec<_>) =
            (attributes(self.0).collect(), attributes(self.1).collect());
        let mut q = s.serialize_seq(None)?;
        for &(k, v) in &now {
            if !was.contains(&(k, v)) {
                q.serialize_element(k)?;
                q.serialize_element(v)?;
            }
        }
        for &(k, _) in &was {
            if !now.iter().any(|&(n, _)| n == k) {
                q.serialize_element(k)?;
                q.serialize_element(&None::<&str>)?;
            }
        }
        q.end()
    }
}

/// The attributes of a tag as written, `name="value"` after a space, in their order (the
/// page reads a tag's attributes so too).
fn attributes(tag: &str) -> impl Iterator<Item = (&str, &str)> {
    // Only the start tag's: a text on one line holds its spans' tags after it (a `>` in a
    // value is escaped, so the first one ends the tag).
    let mut rest = &tag[..memchr::memchr(b'>', tag.as_bytes()).map_or(tag.len(), |i| i + 1)];
    std::iter::from_fn(move || loop {
        // The figure's tags are ASCII between their values: a byte search finds what a
        // search by characters finds, some three times faster on a drag's 1,200 tags.
        let at = memchr::memchr(b'=', rest.as_bytes())?;
        let (head, tail) = (&rest[..at], &rest[at + 1..]);
        let space = head.bytes().rposition(|c| c.is_ascii_whitespace());
        let name = &head[space.map_or(0, |i| i + 1)..];
        let started = space.is_some() && !name.is_empty();
        let Some(value) = tail.strip_prefix('"') else {
            rest = tail;
            continue;
        };
        let end = memchr::memchr(b'"', value.as_bytes())?;
        rest = &value[end + 1..];
        if started {
            return Some((name, &value[..end]));
        }
    })
}

/// What changed from the figure `old` to the figure `new` (SVG as the figures are written: a
/// tag or a text per line), by the root's children; `None` where either is not written a tag
/// or a text per line (the page then takes the new figure whole).
///
/// Where the two have as many children, child `k` of one is paired with child `k` of the
/// other. Where they have not, those before some child are paired with their namesakes and
/// those after it from the back, and the children between are spliced: a step put in or
/// taken out costs its own layer and the lines of the layers after it (their numbers).
///
/// ```
/// use graphostatik::web::figure_patch;
/// let old = "<svg a=\"1\">\n<g id=\"s\">\n<line x1=\"0\"/>\n</g>\n<g/>\n</svg>\n";
/// let new = "<svg a=\"2\">\n<g id=\"s\">\n<line x1=\"5\"/>\n</g>\n<g>\n<circle/>\n</g>\n</svg>\n";
/// let p = figure_patch(old, new).unwrap();
/// assert_eq!(p.root, Some("<svg a=\"2\">"));
/// assert_eq!(p.lines, [(0, 1, "<line x1=\"5\"/>")]);
/// assert_eq!(p.children, [(1, "<g>\n<circle/>\n</g>".to_string())]);
/// // A child more: it is spliced in after the one kept.
/// let more = "<svg a=\"1\">\n<g id=\"s\">\n<line x1=\"0\"/>\n</g>\n<text>\nA\n</text>\n<g/>\n</svg>\n";
/// let p = figure_patch(old, more).unwrap();
/// let s = p.splice.unwrap();
/// assert_eq!((s.at, s.removed, s.added), (1, 0, vec!["<text>\nA\n</text>".to_string()]));
/// assert!(figure_patch(old, "<svg>\n<g>\n</svg>\n").is_none());
/// ```
pub fn figure_patch<'a>(old: &'a str, new: &'a str) -> Option<FigurePatch<'a>> {
    figure_patch_read(old, &FigureLines::of(old), new, &FigureLines::of(new))
}

/// A figure's text read into lines and the root's children (see [`figure_patch`]), kept
/// beside the text by a caller that patches from the same figure again: the engine keeps the
/// figure it drew last, and reads each figure once instead of twice (reading the lines was
/// 6 % of a drag of the compound engine's speed in WebAssembly).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FigureLines {
    /// Each line's bytes, `[start, end)`, without its line break.
    lines: Vec<(u32, u32)>,
    /// The root's children as ranges of lines `[first, last]`, where the text is one root
    /// element written a tag or a text per line.
    kids: Option<Vec<(usize, usize)>>,
}

impl FigureLines {
    /// The lines and the root's children of `text`. (Byte offsets are kept in 32 bits: a
    /// text past 4 GiB has no children here, and is taken whole.)
    pub fn of(text: &str) -> FigureLines {
        if u32::try_from(text.len()).is_err() {
            return FigureLines::default();
        }
        let lines = line_ranges(text);
        let kids = {
            let view: Vec<&str> = lines
                .iter()
                .map(|&(a, b)| &text[a as usize..b as usize])
                .collect();
            children(&view)
        };
        FigureLines { lines, kids }
    }

    /// The bytes of child `k`'s lines `[first, last]`, breaks between them included.
    fn child_bytes<'a>(&self, text: &'a str, (first, last): (usize, usize)) -> &'a str {
        &text[self.lines[first].0 as usize..self.lines[last].1 as usize]
    }

    /// The lines `[first, last]` of `text`.
    fn view<'a>(&self, text: &'a str, (first, last): (usize, usize)) -> Vec<&'a str> {
        (self.lines[first..=last].iter())
            .map(|&(a, b)| &text[a as usize..b as usize])
            .collect()
    }
}

/// [`figure_patch`] of two figures read already ([`FigureLines::of`] each).
pub fn figure_patch_read<'a>(
    old: &'a str,
    read_old: &FigureLines,
    new: &'a str,
    read_new: &FigureLines,
) -> Option<FigurePatch<'a>> {
    let (ka, kb) = (read_old.kids.as_ref()?, read_new.kids.as_ref()?);
    let line0 = |t: &'a str, r: &FigureLines| &t[r.lines[0].0 as usize..r.lines[0].1 as usize];
    let (root_old, root_new) = (line0(old, read_old), line0(new, read_new));
    let mut out = FigurePatch {
        root: (root_old != root_new).then_some(root_new),
        ..FigurePatch::default()
    };
    let was = |i: usize| read_old.child_bytes(old, ka[i]);
    let now = |k: usize| read_new.child_bytes(new, kb[k]);
    // The pairs: (old child, new child).
    let pairs: Vec<(usize, usize)> = if ka.len() == kb.len() {
        (0..ka.len()).map(|k| (k, k)).collect()
    } else {
        let was: Vec<Vec<&str>> = ka.iter().map(|&r| read_old.view(old, r)).collect();
        let now: Vec<Vec<&str>> = kb.iter().map(|&r| read_new.view(new, r)).collect();
        let (was, now): (Vec<&[&str]>, Vec<&[&str]>) = (
            was.iter().map(Vec::as_slice).collect(),
            now.iter().map(Vec::as_slice).collect(),
        );
        let (at, pairs) = spliced(&was, &now);
        let kept = pairs.len();
        out.splice = Some(Splice {
            at,
            removed: was.len() - kept,
            added: now[at..at + now.len() - kept]
                .iter()
                .map(|c| c.join("\n"))
                .collect(),
        });
        pairs
    };
    for (i, k) in pairs {
        if was(i) == now(k) {
            continue;
        }
        let (w, n) = (read_old.view(old, ka[i]), read_new.view(new, kb[k]));
        match changed_lines(&w, &n) {
            Some(changed) => {
                out.was.extend(changed.iter().map(|&i| w[i]));
                out.lines.extend(changed.into_iter().map(|i| (k, i, n[i])));
            }
            None => out.children.push((k, now(k).to_string())),
        }
    }
    Some(out)
}

/// The children paired where their numbers differ by `d`: those before child `at` with their
/// namesakes, those after it `d` apart; `at` where the pairs hold the most alike children (a
/// pair of equal children counts two, a pair with the same elements one), so that a step put
/// in or taken out leaves the layers before and after it paired with their own.
fn spliced(was: &[&[&str]], now: &[&[&str]]) -> (usize, Vec<(usize, usize)>) {
    let short = was.len().min(now.len());
    let (da, db) = (was.len() - short, now.len() - short);
    let score = |i: usize, k: usize| -> i64 {
        if was[i] == now[k] {
            2
        } else {
            i64::from(changed_lines(was[i], now[k]).is_some())
        }
    };
    let front: Vec<i64> = (0..short).map(|k| score(k, k)).collect();
    let back: Vec<i64> = (0..short).map(|k| score(k + da, k + db)).collect();
    let mut sum: i64 = back.iter().sum();
    let (mut best, mut at) = (sum, 0);
    for k in 0..short {
        sum += front[k] - back[k];
        if sum > best {
            (best, at) = (sum, k + 1);
        }
    }
    let pairs = (0..at).map(|k| (k, k));
    (
        at,
        pairs.chain((at..short).map(|k| (k + da, k + db))).collect(),
    )
}

/// The figure's lines as byte ranges `[start, end)` (the text is below 4 GiB).
fn line_ranges(text: &str) -> Vec<(u32, u32)> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len() / 48 + 1);
    let mut from = 0u32;
    for i in memchr::memchr_iter(b'\n', bytes) {
        out.push((from, i as u32));
        from = i as u32 + 1;
    }
    out.push((from, bytes.len() as u32));
    out
}

/// What a line holds: an end tag, a text, or a tag of that name.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind<'a> {
    End,
    Text,
    Tag(&'a str),
}

fn kind(line: &str) -> Kind<'_> {
    match line.as_bytes() {
        [b'<', b'/', ..] => Kind::End,
        [b'<', rest @ ..] => {
            let end = (rest.iter())
                .position(|&c| c.is_ascii_whitespace() || c == b'/' || c == b'>')
                .unwrap_or(rest.len());
            Kind::Tag(&line[1..1 + end])
        }
        _ => Kind::Text,
    }
}

/// Whether the tag on `line` stays open (its children follow on lines of their own).
fn opens(line: &str) -> bool {
    // (A byte search: `str::contains` of a two-byte pattern runs the two-way searcher, 4 %
    // of a drag in WebAssembly.)
    let b = line.as_bytes();
    !b.ends_with(b"/>") && !memchr::memchr_iter(b'<', b).any(|i| b.get(i + 1) == Some(&b'/'))
}

/// The root's children as ranges of lines `[first, last]`; `None` where the text is not one
/// root element written a tag or a text per line.
fn children(lines: &[&str]) -> Option<Vec<(usize, usize)>> {
    let mut out = Vec::new();
    let (mut depth, mut first) = (0usize, 0usize);
    for (i, l) in lines.iter().enumerate().skip(1) {
        match kind(l) {
            Kind::End if depth == 0 => {
                return lines[i + 1..].iter().all(|l| l.is_empty()).then_some(out);
            }
            Kind::End => {
                depth -= 1;
                if depth == 0 {
                    out.push((first, i));
                }
            }
            Kind::Text if depth == 0 && !l.is_empty() => return None,
            Kind::Text => {}
            Kind::Tag(_) if opens(l) => {
                if depth == 0 {
                    first = i;
                }
                depth += 1;
            }
            Kind::Tag(_) if depth == 0 => out.push((i, i)),
            Kind::Tag(_) => {}
        }
    }
    None
}

/// The lines of a child that changed, where each holds what it held (a tag of the same name,
/// or a text inside a `text`, `style` or `title`); `None` where an element changed.
fn changed_lines(was: &[&str], now: &[&str]) -> Option<Vec<usize>> {
    if was.len() != now.len() {
        return None;
    }
    let mut out = Vec::new();
    // The depth of the open elements, and that of the `text`, `style` or `title` we are in.
    let (mut depth, mut inside) = (0usize, None::<usize>);
    for (i, (w, n)) in was.iter().zip(now).enumerate() {
        let k = kind(n);
        if w != n {
            let same = match (kind(w), k) {
                (Kind::Tag(x), Kind::Tag(y)) => x == y && opens(w) == opens(n),
                (Kind::Text, Kind::Text) => inside.is_some(),
                _ => false,
            };
            if !same {
                return None;
            }
            out.push(i);
        }
        match k {
            Kind::End => {
                depth = depth.checked_sub(1)?;
                if inside == Some(depth) {
                    inside = None;
                }
            }
            Kind::Tag(name) if opens(n) => {
                if inside.is_none() && matches!(name, "text" | "style" | "title") {
                    inside = Some(depth);
                }
                depth += 1;
            }
            _ => {}
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::figure_patch;

    /// Lines that keep their kind are patched; a child whose elements changed goes whole.
    #[test]
    fn a_patch_turns_the_old_figure_into_the_new() {
        let old = "<svg>\n<title>A</title>\n<g id=\"1\">\n<text x=\"1\">\nU\n<tspan>0</tspan>\n</text>\n</g>\n<g id=\"2\">\n<line/>\n</g>\n</svg>\n";
        let new = "<svg>\n<title>A</title>\n<g id=\"1\">\n<text x=\"2\">\nV\n<tspan>1</tspan>\n</text>\n</g>\n<g id=\"2\">\n<circle/>\n</g>\n</svg>\n";
        let p = figure_patch(old, new).unwrap();
        assert_eq!(p.root, None);
        assert_eq!(
            p.lines,
            [
                (1, 1, "<text x=\"2\">"),
                (1, 2, "V"),
                (1, 3, "<tspan>1</tspan>")
            ]
        );
        assert_eq!(
            p.children,
            [(2, "<g id=\"2\">\n<circle/>\n</g>".to_string())]
        );
        assert!(figure_patch(new, new).unwrap().is_empty());
        // A text outside a text element, or a line that is no tag at the root: whole.
        let bare = "<svg>\n<g>\nx\n</g>\n</svg>\n";
        let other = "<svg>\n<g>\ny\n</g>\n</svg>\n";
        assert_eq!(figure_patch(bare, other).unwrap().children.len(), 1);
        assert!(figure_patch("<svg>\nx\n</svg>\n", "<svg>\n</svg>\n").is_none());
    }

    /// The old figure's lines with the patch applied, child by child.
    fn applied(old: &str, p: &super::FigurePatch) -> String {
        let lines: Vec<&str> = old.split('\n').collect();
        let kids = super::children(&lines).unwrap();
        let mut parts: Vec<Vec<String>> = (kids.iter())
            .map(|&(a, b)| lines[a..=b].iter().map(|l| l.to_string()).collect())
            .collect();
        if let Some(sp) = &p.splice {
            let added = sp
                .added
                .iter()
                .map(|c| c.split('\n').map(str::to_string).collect());
            parts.splice(sp.at..sp.at + sp.removed, added);
        }
        for &(k, i, t) in &p.lines {
            parts[k][i] = t.to_string();
        }
        for (k, t) in &p.children {
            parts[*k] = t.split('\n').map(str::to_string).collect();
        }
        let mut out = vec![p.root.unwrap_or(lines[0]).to_string()];
        out.extend(parts.into_iter().flatten());
        out.push("</svg>".into());
        out.join("\n") + "\n"
    }

    /// Each tag's line of the patch as the page reads it: its attributes set as `sets` says
    /// give the new tag's, and a changed text has no sets.
    fn sets_turn_each_tag_into_the_next(p: &super::FigurePatch) {
        use std::collections::BTreeMap;
        let json: serde_json::Value = serde_json::from_str(&p.to_json()).unwrap();
        let lines = json["lines"].as_array().unwrap();
        assert_eq!(lines.len(), p.lines.len());
        let mut tags = 0;
        for ((x, &(.., now)), was) in lines.iter().zip(&p.lines).zip(&p.was) {
            let x = x.as_array().unwrap();
            let Some(sets) = x.get(3) else {
                assert!(!was.starts_with('<'), "{was}");
                continue;
            };
            tags += 1;
            let mut a: BTreeMap<&str, &str> = super::attributes(was).collect();
            let sets = sets.as_array().unwrap();
            for kv in sets.chunks(2) {
                let k = kv[0].as_str().unwrap();
                match kv[1].as_str() {
                    Some(v) => a.insert(k, v),
                    None => a.remove(k),
                };
            }
            let b: BTreeMap<&str, &str> = super::attributes(now).collect();
            assert_eq!(a, b, "{was} -> {now}");
        }
        assert!(tags > 0);
    }

    /// The attributes are read as the page's pattern reads them.
    #[test]
    fn attributes_are_read_as_written() {
        let tag = r#"<text x="1" class="a b" data-k="p=q">u=v</text>"#;
        let got: Vec<_> = super::attributes(tag).collect();
        assert_eq!(got, [("x", "1"), ("class", "a b"), ("data-k", "p=q")]);
        assert_eq!(super::attributes("<tspan>a=\"b\"</tspan>").count(), 0);
        // A text on one line: its spans' attributes are not the text's.
        let line = r#"<text x="1">P<tspan dy="0.9">1</tspan></text>"#;
        assert_eq!(super::attributes(line).collect::<Vec<_>>(), [("x", "1")]);
    }

    /// Bundled scenes with their first handle moved as a drag moves it: the patch applied to
    /// the old figure gives the new one, byte for byte, and it is smaller than the figure where
    /// part of the figure stays (the shed roof's first joint is a support: the whole truss and
    /// its four plans move). Where every mark moves (the slewing crane's first joint carries
    /// the truss and its plan) the patch is every line that holds one, no more than the figure
    /// and a tenth.
    #[test]
    fn a_dragged_scene_is_patched_to_its_new_figure() {
        for (name, h, most) in [
            ("lh_aufgabe4_shed_roof", 0, 1.0),
            ("lh_abb22_funicular", 0, 1.0),
            ("lh_aufgabe3_slewing_crane", 0, 1.1),
        ] {
            let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(&path).unwrap();
            let (json, old) = crate::web::replay_apart(&text, name, Some(0));
            let answer: serde_json::Value = serde_json::from_str(&json).unwrap();
            let drag = &answer["handles"][h]["drag"];
            let mut scene: serde_json::Value = serde_json::from_str(&text).unwrap();
            let field = drag["field"].as_str().unwrap();
            assert_eq!(drag["kind"], "point", "{name}");
            let d = drag["per_mm"].as_f64().unwrap();
            let v = scene.pointer(field).unwrap().as_array().unwrap();
            let moved: Vec<f64> = v.iter().map(|x| x.as_f64().unwrap() + d).collect();
            *scene.pointer_mut(field).unwrap() = serde_json::json!(moved);
            let (_, new) = crate::web::replay_apart(&scene.to_string(), name, Some(0));
            assert_ne!(old, new, "{name}: the drag changed nothing");
            let p = figure_patch(&old, &new).unwrap_or_else(|| panic!("{name}: no patch"));
            assert!(!p.lines.is_empty(), "{name}");
            assert_eq!(applied(&old, &p), new, "{name}");
            sets_turn_each_tag_into_the_next(&p);
            let size = p.to_json().len();
            assert!(
                (size as f64) < most * new.len() as f64,
                "{name}: a patch of {size} bytes for {} bytes",
                new.len()
            );
        }
    }
    /// A drag that adds or drops a step (the crank pin turned off its dead centre, and back):
    /// the patch splices the layers between and renumbers those after; applied, it gives the
    /// new figure byte for byte and is a fraction of it.
    #[test]
    fn a_step_more_or_fewer_is_spliced() {
        let path = format!(
            "{}/scenes/lh_abb52_esselborn.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(&path).unwrap();
        let mut scene: serde_json::Value = serde_json::from_str(&text).unwrap();
        *scene.pointer_mut("/angles/degrees/0").unwrap() = serde_json::json!(10);
        let at_dead_centre = crate::web::replay_apart(&text, "a", Some(0));
        let off = crate::web::replay_apart(&scene.to_string(), "a", Some(0));
        let count = |json: &str| {
            serde_json::from_str::<serde_json::Value>(json).unwrap()["step_count"].clone()
        };
        assert_ne!(
            count(&at_dead_centre.0),
            count(&off.0),
            "the step count changed"
        );
        for (old, new) in [(&at_dead_centre.1, &off.1), (&off.1, &at_dead_centre.1)] {
            let p = figure_patch(old, new).unwrap();
            let sp = p.splice.as_ref().expect("a splice");
            assert!(sp.added.len() + sp.removed > 0);
            assert_eq!(&applied(old, &p), new);
            sets_turn_each_tag_into_the_next(&p);
            // (A third: each changed tag's attributes are sent beside its line.)
            let size = p.to_json().len();
            assert!(
                size < new.len() / 3,
                "a patch of {size} bytes for {}",
                new.len()
            );
        }
    }
}
