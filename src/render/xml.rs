//! The figure's SVG as a light element tree, written in one pass into one string.
//!
//! The figure was built with the `svg` crate, whose elements keep their attributes in a
//! `HashMap<String, Value>` (a SipHash and two strings per attribute) and whose `Display`
//! escapes each value by three `str::replace` (three new strings) and sorts each element's
//! attributes into a new vector. On a figure of thousands of elements that was two thirds of
//! what drawing it cost (the Otto engine of KG Abb. 1056: 105 of 159 M instructions a replay,
//! the construction 12 M). [`El`] keeps an element's attributes in a short vector and its
//! children in another; [`El::write`] gives the bytes the `svg` crate gave: attributes
//! sorted by name, `&`, `<` and `>` escaped, a line break before every child that is not
//! written bare (text is bare in a `title` or `tspan`; the `svg`, `style` and `text`
//! elements put every child on a line of its own).

/// An SVG element: its name, attributes (in the order set; written sorted) and children.
#[derive(Clone, Debug)]
pub(crate) struct El {
    name: &'static str,
    attributes: Vec<(&'static str, String)>,
    children: Vec<Child>,
}

/// A child of an element: an element, or text (escaped when written).
#[derive(Clone, Debug)]
enum Child {
    El(El),
    Text(String),
}

impl El {
    /// An empty element.
    pub(crate) fn new(name: &'static str) -> El {
        El {
            name,
            attributes: Vec::new(),
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

    /// The element with attribute `key` set to `value` (formatted as the `svg` crate formats
    /// it: numbers by their `Display`); a key set twice keeps the last value.
    pub(crate) fn set(mut self, key: &'static str, value: impl Into<svg::node::Value>) -> El {
        let value = String::from(value.into());
        match self.attributes.iter_mut().find(|(k, _)| *k == key) {
            Some(slot) => slot.1 = value,
            None => self.attributes.push((key, value)),
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
        let mut sorted: Vec<&(&'static str, String)> = self.attributes.iter().collect();
        sorted.sort_unstable_by(|a, b| a.0.cmp(b.0));
        for (key, value) in sorted {
            out.push(' ');
            out.push_str(key);
            out.push_str("=\"");
            escaped(out, value);
            out.push('"');
        }
        if self.children.is_empty() {
            out.push_str("/>");
            return;
        }
        out.push('>');
        // The `svg` crate's "bareable" elements write each child on a line of its own.
        let own_lines = matches!(self.name, "svg" | "style" | "text" | "script");
        let mut bare = false;
        for child in &self.children {
            bare = matches!(child, Child::Text(_)) && !own_lines;
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

/// `text` with `&`, `<` and `>` escaped, as the `svg` crate escapes values and text.
/// The three are ASCII, so a byte search finds them (the step captions in the layers' names
/// make the crane bridge's figure 2 MB: a search by `char` took 22 M instructions of it).
fn escaped(out: &mut String, text: &str) {
    let mut rest = text;
    while let Some(i) = memchr::memchr3(b'&', b'<', b'>', rest.as_bytes()) {
        out.push_str(&rest[..i]);
        out.push_str(match rest.as_bytes()[i] {
            b'&' => "&amp;",
            b'<' => "&lt;",
            _ => "&gt;",
        });
        rest = &rest[i + 1..];
    }
    out.push_str(rest);
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
        assert_eq!(ours.write(), theirs.to_string());
    }
}
