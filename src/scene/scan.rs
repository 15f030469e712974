//! A first pass over a scene's text that builds nothing: whether it is well-formed JSON (a
//! syntax error is reported at its line and column before any procedure looks at it), its
//! `procedure` field, and the first text longer than its field allows. It streams through
//! the document as serde visits it, so a truss of 100,000 joints is scanned in the time
//! its bytes take to read, not in the time of a tree of maps built and dropped.

use serde::de::{DeserializeSeed, MapAccess, SeqAccess, Visitor};
use std::fmt::Write as _;

/// Longest text a scene field may hold (a title, a name, a reference), in characters: a
/// name of a megabyte would be written into every layer it labels.
pub(super) const MAX_TEXT_CHARS: usize = 400;
/// Longest free `notes` of a scene, in characters (they are not drawn).
pub(super) const MAX_NOTES_CHARS: usize = 20_000;

/// What the scan finds besides well-formedness.
#[derive(Debug, Default, PartialEq)]
pub(super) struct Scanned {
    /// The top level is an object.
    pub object: bool,
    /// The `procedure` field, if the scene has one (any JSON value).
    pub procedure: Option<serde_json::Value>,
    /// The first text (in document order) longer than its field allows, or holding a
    /// control character: its path and what is wrong with it.
    pub too_long: Option<(String, String)>,
}

/// Scans `text`; a syntax error anywhere (trailing data included) is returned as is.
pub(super) fn scan(text: &str) -> Result<Scanned, serde_json::Error> {
    let mut found = Scanned::default();
    let de = &mut serde_json::Deserializer::from_str(text);
    Top(&mut found).deserialize(&mut *de)?;
    de.end()?;
    Ok(found)
}

/// The scan's answer without its walk, for a text that parses: where the bytes alone show
/// what the walk would find, read in one pass over them. The text must be an object (its
/// first byte `{`) with no backslash (so every string runs from one quote to the next),
/// none of the control characters a string may hold unescaped (DEL and U+0080 to U+009F;
/// the others are a syntax error there), no string longer than [`MAX_TEXT_CHARS`] bytes
/// (the top level's `notes`, [`MAX_NOTES_CHARS`]), and a `procedure` that is a text, if
/// any. Then no text is too long or holds a control character, and the procedure is the
/// text after the top level's key `procedure`. `None` where that cannot be told.
///
/// The bytes say nothing of the text's syntax: the answer holds only if the text is JSON,
/// which the typed parse that follows finds out. Where that parse fails, the caller scans in
/// full and reports what the scan reports first.
///
/// The quotes are found 32 bytes at a time ([`Quotes`]) and every text measured between
/// them; only a text that could matter (longer than a field allows, `procedure`, or the
/// value after a `procedure` key) is placed, by walking the bytes before it for its depth
/// and key ([`Cursor`]). A 10,000-joint truss, whose `procedure` comes first, is walked
/// for a few dozen of its bytes.
pub(super) fn quick(text: &str) -> Option<Scanned> {
    let bytes = text.as_bytes();
    if !plain_object(bytes) {
        return None;
    }
    let mut found = Scanned {
        object: true,
        ..Scanned::default()
    };
    let mut walk = Cursor::default();
    let mut look_next = false;
    // Without a backslash every quote opens or closes a text, in turn.
    let mut quotes = Quotes::new(bytes);
    while let Some(quote) = quotes.next() {
        let (open, close) = (quote + 1, quotes.next()?);
        let name = &bytes[open..close];
        if close - open <= MAX_TEXT_CHARS && name != b"procedure" && !look_next {
            continue;
        }
        walk.up_to(bytes, quote)?;
        // The text a key of the top level names, if it is one.
        let value_of = walk.key.take().filter(|_| walk.depth == 1);
        let value_of = value_of.map(|(a, b)| &bytes[a..b]);
        let max = match value_of {
            Some(b"notes") => MAX_NOTES_CHARS,
            _ => MAX_TEXT_CHARS,
        };
        if close - open > max {
            return None;
        }
        if value_of == Some(b"procedure") {
            if found.procedure.is_some() {
                return None;
            }
            found.procedure = Some(serde_json::Value::String(text[open..close].to_string()));
        }
        look_next = false;
        let mut next = bytes[close + 1..]
            .iter()
            .filter(|b| !b.is_ascii_whitespace());
        if next.next() == Some(&b':') {
            // A key; `procedure`'s value must be a text, and is looked at next.
            walk.key = Some((open, close));
            if walk.depth == 1 && name == b"procedure" {
                if next.next() != Some(&b'"') {
                    return None;
                }
                look_next = true;
            }
        }
        walk.at = close + 1;
    }
    Some(found)
}

/// The places of the quotes in a text, in order: found 32 bytes at a time as a mask of
/// the bytes that are one (a loop the compiler turns into vector compares), the mask's bits
/// then read off one by one. On a scene, where a quote comes every few bytes, some five
/// times fewer instructions than a `memchr` call per quote.
struct Quotes<'a> {
    bytes: &'a [u8],
    /// Where the current block of 32 bytes starts, and its quotes not yet given.
    block: usize,
    mask: u32,
}

impl<'a> Quotes<'a> {
    fn new(bytes: &'a [u8]) -> Self {
        let mut q = Quotes {
            bytes,
            block: 0,
            mask: 0,
        };
        q.mask = q.mask_at(0);
        q
    }

    /// The quotes among the 32 bytes from `at` (fewer at the end), as bits: a whole block
    /// as an array, whose fixed length lets the compiler compare it as vectors.
    fn mask_at(&self, at: usize) -> u32 {
        let end = (at + 32).min(self.bytes.len());
        let chunk = self.bytes.get(at..end).unwrap_or_default();
        match <&[u8; 32]>::try_from(chunk) {
            Ok(block) => quote_bits(block.iter()),
            Err(_) => quote_bits(chunk.iter()),
        }
    }
}

/// Bit `i` set where the `i`th byte is a quote.
#[inline(always)]
fn quote_bits<'b>(bytes: impl Iterator<Item = &'b u8>) -> u32 {
    bytes
        .enumerate()
        .fold(0, |m, (i, &b)| m | (u32::from(b == b'"') << i))
}

impl Iterator for Quotes<'_> {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        while self.mask == 0 {
            self.block += 32;
            if self.block >= self.bytes.len() {
                return None;
            }
            self.mask = self.mask_at(self.block);
        }
        let bit = self.mask.trailing_zeros() as usize;
        self.mask &= self.mask - 1;
        Some(self.block + bit)
    }
}

/// The depth of brackets and the last key before a place in a scene's bytes, found by
/// walking them from where the last walk ended: a key is the text before a colon, and any
/// other byte but white space and the colon ends it.
#[derive(Default)]
struct Cursor {
    /// The bytes before this one have been walked.
    at: usize,
    depth: i32,
    key: Option<(usize, usize)>,
}

impl Cursor {
    /// Walks up to `end` (a quote that opens a text); `None` if a text runs off the end.
    fn up_to(&mut self, bytes: &[u8], end: usize) -> Option<()> {
        let mut i = self.at;
        while i < end {
            match bytes[i] {
                b'{' | b'[' => (self.depth, self.key) = (self.depth + 1, None),
                b'}' | b']' => (self.depth, self.key) = (self.depth - 1, None),
                b'"' => {
                    let open = i + 1;
                    let close = open + memchr::memchr(b'"', &bytes[open..])?;
                    self.key = None;
                    let next = bytes[close + 1..].iter().find(|b| !b.is_ascii_whitespace());
                    if next == Some(&b':') {
                        self.key = Some((open, close));
                    }
                    i = close;
                }
                // A key's value is the next thing after its colon.
                b':' => {}
                b if !b.is_ascii_whitespace() => self.key = None,
                _ => {}
            }
            i += 1;
        }
        self.at = end;
        Some(())
    }
}

/// Whether the bytes may be read quickly at all: an object (the first byte `{`), no
/// backslash (so every string runs from one quote to the next), and none of the control
/// characters a string may hold unescaped.
fn plain_object(bytes: &[u8]) -> bool {
    bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{')
        && memchr::memchr2(b'\\', 0x7f, bytes).is_none()
        && !holds_c1(bytes)
}

/// Whether the bytes hold one of U+0080 to U+009F (C2 80 to C2 9F in UTF-8), control
/// characters JSON lets stand unescaped in a string, or a character [`is_unseen_format`]
/// (D8 9C, E2 80 8E-8F, E2 80 A8-AE, E2 81 A6-A9).
fn holds_c1(bytes: &[u8]) -> bool {
    memchr::memchr_iter(0xc2, bytes).any(|k| matches!(bytes.get(k + 1), Some(0x80..=0x9f)))
        || memchr::memchr_iter(0xd8, bytes).any(|k| bytes.get(k + 1) == Some(&0x9c))
        || memchr::memchr_iter(0xe2, bytes).any(|k| {
            matches!(
                (bytes.get(k + 1), bytes.get(k + 2)),
                (Some(0x80), Some(0x8e..=0x8f | 0xa8..=0xae)) | (Some(0x81), Some(0xa6..=0xa9))
            )
        })
}

/// Whether `c` reorders or breaks the text around it without being seen: the bidirectional
/// marks, embeddings, overrides and isolates (U+061C, U+200E, U+200F, U+202A to U+202E,
/// U+2066 to U+2069) and the line and paragraph separators (U+2028, U+2029). A name holding U+202E
/// shows its letters backwards in the figure, the table and the terminal.
pub(crate) fn is_unseen_format(c: char) -> bool {
    matches!(
        c,
        '\u{061c}' | '\u{200e}' | '\u{200f}' | '\u{2028}'..='\u{202e}' | '\u{2066}'..='\u{2069}'
    )
}

/// A visitor's methods for numbers, booleans and null, which the scan takes as they come.
macro_rules! accept_scalars {
    () => {
        fn visit_f64<E>(self, _: f64) -> Result<(), E> {
            Ok(())
        }
        fn visit_i64<E>(self, _: i64) -> Result<(), E> {
            Ok(())
        }
        fn visit_u64<E>(self, _: u64) -> Result<(), E> {
            Ok(())
        }
        fn visit_bool<E>(self, _: bool) -> Result<(), E> {
            Ok(())
        }
        fn visit_unit<E>(self) -> Result<(), E> {
            Ok(())
        }
    };
}

/// The top level: an object whose `procedure` is kept; anything else is noted as not one.
struct Top<'a>(&'a mut Scanned);

impl<'de> DeserializeSeed<'de> for Top<'_> {
    type Value = ();
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Top<'_> {
    type Value = ();
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a scene")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        self.0.object = true;
        let mut path: Vec<Seg<'de>> = Vec::new();
        while let Some(key) = map.next_key::<Key<'de>>()? {
            let key = key.0;
            if key == "procedure" {
                let v: serde_json::Value = map.next_value()?;
                if let serde_json::Value::String(s) = &v {
                    check_len(s, &[Seg::Key(key)], &mut self.0.too_long);
                }
                self.0.procedure = Some(v);
                continue;
            }
            path.clear();
            path.push(Seg::Key(key));
            map.next_value_seed(Walk {
                path: &mut path,
                found: &mut self.0.too_long,
            })?;
        }
        Ok(())
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {}
        Ok(())
    }
    fn visit_str<E>(self, _: &str) -> Result<(), E> {
        Ok(())
    }
    accept_scalars!();
}

/// An object's key, borrowed from the text where it holds no escape (serde's own
/// `Cow<str>` always copies: a key a heap allocation, 70,000 of them in a 10,000-joint truss).
struct Key<'de>(std::borrow::Cow<'de, str>);

impl<'de> serde::Deserialize<'de> for Key<'de> {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct KeyVisitor;
        impl<'de> Visitor<'de> for KeyVisitor {
            type Value = Key<'de>;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a key")
            }
            fn visit_borrowed_str<E>(self, s: &'de str) -> Result<Key<'de>, E> {
                Ok(Key(std::borrow::Cow::Borrowed(s)))
            }
            fn visit_str<E>(self, s: &str) -> Result<Key<'de>, E> {
                Ok(Key(std::borrow::Cow::Owned(s.to_owned())))
            }
        }
        d.deserialize_str(KeyVisitor)
    }
}

/// One step of a field's path: a key of an object or an index of an array. The path is
/// written out only for the text found too long.
enum Seg<'de> {
    Key(std::borrow::Cow<'de, str>),
    Index(usize),
}

/// The path as error messages write it: `joints[3].name` (long keys clipped).
fn path_text(path: &[Seg]) -> String {
    let mut out = String::new();
    for seg in path {
        match seg {
            Seg::Key(k) => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(&crate::fmt::clip(k, 40));
            }
            Seg::Index(i) => {
                let _ = write!(out, "[{i}]");
            }
        }
    }
    out
}

/// Notes the text at `path` if it is longer than its field allows (the scene's free
/// `notes` may run to [`MAX_NOTES_CHARS`], every other text to [`MAX_TEXT_CHARS`]), unless
/// an earlier one was found.
fn check_len(s: &str, path: &[Seg], found: &mut Option<(String, String)>) {
    if found.is_some() {
        return;
    }
    let notes = matches!(path, [Seg::Key(k)] if k == "notes");
    // A control character (ESC, NUL, a line end in a name) would reach a terminal, a CSV
    // row, a Markdown table or TeX as it is: texts are one line of printable characters,
    // the notes may break lines.
    let allowed = |c: char| notes && matches!(c, '\n' | '\r' | '\t');
    if let Some(c) = s.chars().find(|&c| is_unseen_format(c)) {
        *found = Some((
            path_text(path),
            format!(
                "a direction or line-separator character (U+{:04X}) in a text: it would reorder \
                 or break what a reader sees of a name",
                c as u32
            ),
        ));
        return;
    }
    if let Some(c) = s.chars().find(|&c| c.is_control() && !allowed(c)) {
        *found = Some((
            path_text(path),
            format!(
                "a control character (U+{:04X}) in a text: a name or title is one line of printable characters",
                c as u32
            ),
        ));
        return;
    }
    // A character is at least one byte: most texts are settled without counting.
    if s.len() <= MAX_TEXT_CHARS {
        return;
    }
    let max = if notes {
        MAX_NOTES_CHARS
    } else {
        MAX_TEXT_CHARS
    };
    let n = s.chars().count();
    if n > max {
        *found = Some((
            path_text(path),
            format!("a text of {n} characters: at most {max} are allowed"),
        ));
    }
}

/// Any value below the top level, its path kept for the error.
struct Walk<'a, 'de> {
    path: &'a mut Vec<Seg<'de>>,
    found: &'a mut Option<(String, String)>,
}

impl<'de> DeserializeSeed<'de> for Walk<'_, 'de> {
    type Value = ();
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Walk<'_, 'de> {
    type Value = ();
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_str<E>(self, s: &str) -> Result<(), E> {
        check_len(s, self.path, self.found);
        Ok(())
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while let Some(Key(key)) = map.next_key::<Key<'de>>()? {
            self.path.push(Seg::Key(key));
            map.next_value_seed(Walk {
                path: &mut *self.path,
                found: &mut *self.found,
            })?;
            self.path.pop();
        }
        Ok(())
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let mut i = 0usize;
        loop {
            self.path.push(Seg::Index(i));
            let more = seq.next_element_seed(Walk {
                path: &mut *self.path,
                found: &mut *self.found,
            })?;
            self.path.pop();
            if more.is_none() {
                return Ok(());
            }
            i += 1;
        }
    }
    accept_scalars!();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_procedure_and_the_first_text_too_long_with_its_path() {
        let long = "x".repeat(401);
        let text = format!(
            r#"{{"procedure": "truss", "joints": [{{"name": "A"}}, {{"name": "{long}"}}],
               "notes": "{long}", "title": "{long}"}}"#
        );
        let s = scan(&text).unwrap();
        assert!(s.object);
        assert_eq!(s.procedure, Some(serde_json::json!("truss")));
        assert_eq!(
            s.too_long,
            Some((
                "joints[1].name".into(),
                "a text of 401 characters: at most 400 are allowed".into()
            ))
        );
        // Notes may be longer; a character is counted as one however many bytes it takes.
        let s = scan(&format!(
            r#"{{"notes": "{long}", "title": "{}"}}"#,
            "é".repeat(400)
        ))
        .unwrap();
        assert_eq!(s.too_long, None);
    }

    /// The quick answer as it was first written, walking every byte: the answer `quick`
    /// must give, found in fewer steps.
    fn quick_walking_every_byte(text: &str) -> Option<Scanned> {
        let bytes = text.as_bytes();
        if !plain_object(bytes) {
            return None;
        }
        let mut found = Scanned {
            object: true,
            ..Scanned::default()
        };
        // Strings run from one quote to the next; the bytes between them hold the brackets.
        let (mut depth, mut i, mut key) = (0i32, 0, None::<(usize, usize)>);
        while i < bytes.len() {
            match bytes[i] {
                b'{' | b'[' => (depth, key) = (depth + 1, None),
                b'}' | b']' => (depth, key) = (depth - 1, None),
                b'"' => {
                    let open = i + 1;
                    let close = open + bytes[open..].iter().position(|&b| b == b'"')?;
                    // The text a key of the top level names, if it is one.
                    let value_of = key.take().filter(|_| depth == 1);
                    let value_of = value_of.map(|(a, b)| &bytes[a..b]);
                    let max = match value_of {
                        Some(b"notes") => MAX_NOTES_CHARS,
                        _ => MAX_TEXT_CHARS,
                    };
                    if close - open > max {
                        return None;
                    }
                    if value_of == Some(b"procedure") {
                        if found.procedure.is_some() {
                            return None;
                        }
                        let name = text[open..close].to_string();
                        found.procedure = Some(serde_json::Value::String(name));
                    }
                    let mut next = bytes[close + 1..]
                        .iter()
                        .filter(|b| !b.is_ascii_whitespace());
                    if next.next() == Some(&b':') {
                        // A key; `procedure`'s value must be a text.
                        key = Some((open, close));
                        if depth == 1
                            && &bytes[open..close] == b"procedure"
                            && next.next() != Some(&b'"')
                        {
                            return None;
                        }
                    }
                    i = close;
                }
                // A key's value is the next thing after its colon.
                b':' => {}
                b if !b.is_ascii_whitespace() => key = None,
                _ => {}
            }
            i += 1;
        }
        Some(found)
    }

    #[test]
    fn the_quick_answer_is_the_one_every_byte_walked_gives() {
        let long = "x".repeat(401);
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
        let mut texts: Vec<String> = vec![
            r#"{"title": "procedure", "procedure": "beam"}"#.into(),
            r#"{"a": {"procedure": 1}, "b": ["procedure", {"procedure": "x"}], "procedure": "truss"}"#.into(),
            r#"{"a": [{"procedure": "x"}], "procedure" :
                "truss", "procedure": "beam"}"#.into(),
            r#"{"procedure": ["truss"]}"#.into(),
            r#"{"procedure" "truss"}"#.into(),
            r#"{"procedure": "trus"#.into(),
            r#"{"a": "b", "c"#.into(),
            r#"{"a": [1, {"b": "c"}], "notes": "n"}"#.into(),
            format!(r#"{{"procedure": "{long}"}}"#),
            format!(r#"{{"a": [{{"b": 1}}], "notes": "{long}", "procedure": "beam"}}"#),
            format!(r#"{{"a": {{"b": [1, 2]}}, "c": {{"notes": "{long}"}}}}"#),
            format!(r#"{{"notes": 1, "x": "{long}"}}"#),
            format!(r#"{{"notes": "{}"}}"#, "y".repeat(20_001)),
            format!(r#"{{"notes": "{long}", "notes": "{long}", "t": "{long}"}}"#),
        ];
        for e in std::fs::read_dir(dir).unwrap() {
            let text = std::fs::read_to_string(e.unwrap().path()).unwrap();
            // The scene, its notes made long, and its procedure moved last.
            let notes = text.replacen('{', &format!(r#"{{"notes": "{long}", "#), 1);
            let moved = text.replacen(r#""procedure""#, r#""procedure_was""#, 1);
            let moved = match moved.rfind('}') {
                Some(at) => format!(r#"{}, "procedure": "beam"}}"#, &moved[..at]),
                None => moved,
            };
            texts.extend([text, notes, moved]);
        }
        for t in &texts {
            assert_eq!(quick(t), quick_walking_every_byte(t), "{t:.120}");
        }
    }

    #[test]
    fn the_quick_answer_is_the_scans_or_none() {
        let long = "x".repeat(401);
        let mut texts: Vec<String> = [
            r#"{"procedure": "truss", "joints": [{"name": "A"}]}"#,
            r#"{"title": "t", "procedure": null}"#,
            r#"{"procedure": 3, "a": [1, 2.5e3, true, null, {}]}"#,
            r#"{"procedure": "truss", "procedure": "beam"}"#,
            r#"{"title": "a\u001bb"}"#,
            "{\"title\": \"a\u{7f}b\"}",
            "{\"title\": \"a\u{85}b\"}",
            "{\"title\": \"\u{e9}\u{20ac}\"}",
            r#"{"a": [1, 2,]}"#,
            r#"{"a": 1} x"#,
            r#"["procedure"]"#,
            "  \n{}",
            "{",
            r#"{"a": "b}"#,
        ]
        .map(String::from)
        .into();
        texts.push(format!(r#"{{"notes": "{long}"}}"#));
        texts.push(format!(r#"{{"a": {{"notes": "{long}"}}}}"#));
        texts.push(format!(r#"{{"a": ["notes", "{long}"]}}"#));
        texts.push(format!(r#"{{"notes" : "{}"}}"#, "y".repeat(20_001)));
        texts.push(format!(r#"{{"title": "{}"}}"#, "x".repeat(400)));
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
        let mut bundled = 0;
        for e in std::fs::read_dir(dir).unwrap() {
            texts.push(std::fs::read_to_string(e.unwrap().path()).unwrap());
            bundled += 1;
        }
        // Where the text is JSON, the quick answer is none or the scan's.
        let mut quick_ones = 0;
        for t in &texts {
            if let (Some(q), Ok(full)) = (quick(t), scan(t)) {
                assert_eq!(q, full, "{t:.80}");
                quick_ones += 1;
            }
        }
        assert!(
            quick_ones >= bundled,
            "{quick_ones} quick of {}",
            texts.len()
        );
        assert!(quick(r#"{"title": "a\u001bb"}"#).is_none());
        assert!(quick(r#"{"title": "t", "procedure": null}"#).is_none());
        assert_eq!(
            quick(r#" {"a": {"procedure": 1}, "procedure" : "beam"}"#)
                .unwrap()
                .procedure,
            Some(serde_json::json!("beam"))
        );
    }

    #[test]
    fn reports_syntax_errors_and_what_is_not_an_object() {
        assert!(scan(r#"{"a": [1, 2,]}"#).is_err());
        assert!(scan(r#"{"a": 1} x"#).is_err());
        assert!(!scan("[1, 2]").unwrap().object);
        assert!(scan(&"[".repeat(200)).is_err());
        assert_eq!(
            scan(r#"{"procedure": 3}"#).unwrap().procedure,
            Some(serde_json::json!(3))
        );
    }
}
