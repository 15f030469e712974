//! The figure's SVG as a light element tree, written in one pass into one string.
//!
//! The figure was built with the `svg` crate, whose elements keep their attributes in a
//! `HashMap<String, Value>` (a SipHash and two strings per attribute) and whose `Display`
//! escapes each value by three `str::replace` (three new strings) and sorts each element's
//! attributes into a new vector. On a figure of thousands of elements that was two thirds of
//! what drawing it cost (the Otto engine of KG Abb. 1056: 105 of 159 M instructions a replay,
//! the construction 12 M). [`El`] keeps an element's attribute values in one buffer and its
//! children in a vector; [`El::write`] gives the bytes the `svg` crate gave, but for two
//! things: attributes sorted by name, every value and text escaped for both kinds of quote
//! ([`crate::fmt::markup_text`]: the crate left `"` standing, so a name could close an
//! attribute), a line break before every child that is not written bare (the `svg`, `style`
//! and `script` elements put every child on a line of its own), and a `text` written on one
//! line with its spans (the crate's line break before a span was laid out as a space).

/// An SVG element: its name, attributes and children. The attributes' values are written,
/// escaped, into one buffer of the element as they are set, and indexed by name in name
/// order, so that writing the element copies them (a string per attribute and a sorted
/// vector per element were a third of what a figure cost to build and free).
#[derive(Clone, Debug)]
pub(crate) struct El {
    name: &'static str,
    /// Each attribute's name and its value's byte range in `values`, sorted by name.
    keys: Vec<(&'static str, u32, u32)>,
    values: String,
    children: Vec<Child>,
}

/// A child of an element: an element, or text (escaped when written).
#[derive(Clone, Debug)]
enum Child {
    El(El),
    Text(String),
}

/// A value an attribute can take, written as the `svg` crate wrote it (numbers by their
/// `Display`, text as it is), escaped.
pub(crate) trait AttrValue {
    /// Writes the value, escaped, at the end of `out`.
    fn write_escaped(self, out: &mut String);
}

impl AttrValue for &str {
    fn write_escaped(self, out: &mut String) {
        escaped(out, self);
    }
}

impl AttrValue for String {
    fn write_escaped(self, out: &mut String) {
        escaped(out, &self);
    }
}

impl AttrValue for &String {
    fn write_escaped(self, out: &mut String) {
        escaped(out, self);
    }
}

macro_rules! displayed {
    ($($t:ty),*) => {$(
        impl AttrValue for $t {
            fn write_escaped(self, out: &mut String) {
                use std::fmt::Write;
                let _ = write!(out, "{self}");
            }
        }
    )*};
}
displayed!(i32, u32, usize, f64);

/// A number written with at most `.1` decimals, trailing zeros dropped ([`crate::fmt::num`]),
/// straight into the element's buffer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Num(pub f64, pub usize);

impl AttrValue for Num {
    fn write_escaped(self, out: &mut String) {
        crate::fmt::num_into(out, self.0, self.1);
    }
}

/// A value its closure writes straight into the element's buffer, unescaped: for text that
/// needs no escape (digits, ASCII names), without a string of its own.
pub(crate) struct Written<F>(pub F);

impl<F: FnOnce(&mut String)> AttrValue for Written<F> {
    fn write_escaped(self, out: &mut String) {
        (self.0)(out);
    }
}

impl std::fmt::Display for Num {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut s = String::new();
        crate::fmt::num_into(&mut s, self.0, self.1);
        f.write_str(&s)
    }
}

impl El {
    /// An empty element.
    pub(crate) fn new(name: &'static str) -> El {
        El {
            name,
            keys: Vec::new(),
            values: String::new(),
            children: Vec::new(),
        }
    }

    /// An element holding `text` (a `text`, `tspan`, `title` or `style`).
    pub(crate) fn text(name: &'static str, text: impl Into<String>) -> El {
        let mut e = El::new(name);
        e.children.push(Child::Text(text.into()));
        e
    }

    /// The root `svg` element with its namespace.
    pub(crate) fn document() -> El {
        El::new("svg").set("xmlns", "http://www.w3.org/2000/svg")
    }

    /// The element with attribute `key` set to `value`; a key set twice keeps the last value.
    pub(crate) fn set(mut self, key: &'static str, value: impl AttrValue) -> El {
        if self.keys.is_empty() {
            self.keys.reserve_exact(6);
            self.values.reserve(48);
        }
        let from = self.values.len();
        value.write_escaped(&mut self.values);
        let range = (from as u32, self.values.len() as u32);
        match self.keys.binary_search_by(|(k, ..)| k.cmp(&key)) {
            Ok(i) => self.keys[i] = (key, range.0, range.1),
            Err(i) => self.keys.insert(i, (key, range.0, range.1)),
        }
        self
    }

    /// The element with `child` appended.
    pub(crate) fn add(mut self, child: El) -> El {
        self.children.push(Child::El(child));
        self
    }

    /// The element's text as the `svg` crate writes it.
    pub(crate) fn write(&self) -> String {
        let mut out = String::with_capacity(1 << 16);
        self.write_into(&mut out);
        out
    }

    fn write_into(&self, out: &mut String) {
        out.push('<');
        out.push_str(self.name);
        for &(key, from, to) in &self.keys {
            out.push(' ');
            out.push_str(key);
            out.push_str("=\"");
            out.push_str(&self.values[from as usize..to as usize]);
            out.push('"');
        }
        if self.children.is_empty() {
            out.push_str("/>");
            return;
        }
        out.push('>');
        // A text is written on one line with its spans: a line break between a letter and the
        // span of its index would be laid out as a space ("P 1" for P₁).
        let inline = matches!(self.name, "text" | "tspan" | "title");
        // The `svg` crate's "bareable" elements write each child on a line of its own.
        let own_lines = matches!(self.name, "svg" | "style" | "script");
        let mut bare = false;
        for child in &self.children {
            bare = inline || (matches!(child, Child::Text(_)) && !own_lines);
            if !bare {
                out.push('\n');
            }
            match child {
                Child::El(e) => e.write_into(out),
                Child::Text(t) => escaped(out, t),
            }
        }
        if !bare {
            out.push('\n');
        }
        out.push_str("</");
        out.push_str(self.name);
        out.push('>');
    }
}

/// `text` escaped for an attribute's value or an element's text ([`crate::fmt::markup_text`]).
pub(crate) fn escaped(out: &mut String, text: &str) {
    crate::fmt::markup_text(out, text);
}

#[cfg(test)]
mod tests {
    use super::El;
    use svg::node::element::{Group, Line, Style, TSpan, Text, Title};
    use svg::Document;

    /// The tree writes the `svg` crate's bytes for every kind of node the figures use:
    /// sorted attributes, numbers, escapes, text bare or on its own line, a key set twice.
    #[test]
    fn writes_what_the_svg_crate_writes() {
        let ours = El::document()
            .set("viewBox", "0 0 10 10")
            .set("data-x", "a < b & c > d")
            .add(El::text("title", "F & G <1>"))
            .add(El::text("style", "text{fill:#000}"))
            .add(
                El::new("g")
                    .set("id", "step-001")
                    .add(
                        El::new("line")
                            .set("x1", 1)
                            .set("y2", 2.5)
                            .set("class", "axis"),
                    )
                    .add(
                        El::text("text", "S")
                            .set("x", 3)
                            .add(El::text("tspan", "1").set("dy", "0.9")),
                    )
                    .set("id", "step-002"),
            )
            .add(El::new("g"));
        let theirs = Document::new()
            .set("viewBox", "0 0 10 10")
            .set("data-x", "a < b & c > d")
            .add(Title::new("F & G <1>"))
            .add(Style::new("text{fill:#000}"))
            .add(
                Group::new()
                    .set("id", "step-001")
                    .add(Line::new().set("x1", 1).set("y2", 2.5).set("class", "axis"))
                    .add(
                        Text::new("S")
                            .set("x", 3)
                            .add(TSpan::new("1").set("dy", "0.9")),
                    )
                    .set("id", "step-002"),
            )
            .add(Group::new());
        // The crate breaks the line before a text's span, which a renderer shows as a space.
        let theirs = theirs
            .to_string()
            .replace(">\nS\n<tspan", ">S<tspan")
            .replace("0.9\">1</tspan>\n</text>", "0.9\">1</tspan></text>");
        assert_eq!(ours.write(), theirs);
    }

    /// A name cannot close the attribute it stands in, nor a span stand apart from its letter.
    #[test]
    fn quotes_are_escaped_and_spans_attached() {
        let t = El::text("text", "P")
            .set("data-n", "1\" onmouseover=\"x")
            .add(El::text("tspan", "1"));
        assert_eq!(
            t.write(),
            "<text data-n=\"1&quot; onmouseover=&quot;x\">P<tspan>1</tspan></text>"
        );
    }
}
