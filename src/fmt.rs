//! Fixed number formatting, so that the same scene gives the same bytes.

/// Formats `x` with at most `decimals` decimals, trailing zeros and a negative zero removed.
///
/// ```
/// use graphostatik::fmt::num;
/// assert_eq!(num(0.30000000000000004, 3), "0.3");
/// assert_eq!(num(-0.0, 3), "0");
/// assert_eq!(num(-1e-9, 3), "0");
/// assert_eq!(num(12.6, 0), "13");
/// ```
pub fn num(x: f64, decimals: usize) -> String {
    let mut s = String::new();
    num_into(&mut s, x, decimals);
    s
}

/// [`num`] written at the end of `out` (no allocation of its own: for tables of many rows).
///
/// ```
/// let mut s = String::from("M = ");
/// graphostatik::fmt::num_into(&mut s, -2.50, 3);
/// assert_eq!(s, "M = -2.5");
/// ```
pub fn num_into(out: &mut String, x: f64, decimals: usize) {
    use std::fmt::Write;
    if !x.is_finite() {
        out.push_str(if x.is_nan() {
            "NaN"
        } else if x > 0.0 {
            "inf"
        } else {
            "-inf"
        });
        return;
    }
    // A whole number (most angles, many scales) prints as itself: the same text as the
    // trimmed decimals below, without the exact float formatting (its slow path was 3 % of a
    // recorded crank construction, for "θ = 10°").
    if x.fract() == 0.0 && x.abs() < 1e15 {
        let _ = write!(out, "{}", x as i64);
        return;
    }
    let start = out.len();
    let _ = write!(out, "{:.*}", decimals, x);
    if out[start..].contains('.') {
        let kept = out[start..]
            .trim_end_matches('0')
            .trim_end_matches('.')
            .len();
        out.truncate(start + kept);
    }
    if &out[start..] == "-0" {
        out.truncate(start);
        out.push('0');
    }
}

/// Formats in scientific notation with 2 significant decimals (`1.23e-10`), for errors.
pub fn sci(x: f64) -> String {
    let mut s = String::new();
    sci_into(&mut s, x);
    s
}

/// [`sci`] written at the end of `out`.
pub fn sci_into(out: &mut String, x: f64) {
    use std::fmt::Write;
    if x == 0.0 {
        out.push('0');
    } else {
        let _ = write!(out, "{:.2e}", x);
    }
}

/// A number with every digit it has: the shortest decimal that reads back as the same f64
/// (Rust's round-trip formatting), in exponent form beyond 1e16 and below 1e-5, `0` for
/// either zero, no trailing `.0`. For files a program reads again (CSV).
///
/// ```
/// use graphostatik::fmt::full;
/// assert_eq!(full(0.1 + 0.2), "0.30000000000000004");
/// assert_eq!(full(-1575.0), "-1575");
/// assert_eq!(full(-0.0), "0");
/// assert_eq!(full(2.5e-7), "2.5e-7");
/// assert_eq!(full(1e300).parse::<f64>().unwrap(), 1e300);
/// ```
pub fn full(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:?}");
    match s.strip_suffix(".0") {
        Some(t) => t.to_string(),
        None => s,
    }
}

/// A user's string as an error message quotes it: on one line (control characters escaped)
/// and at most `max` characters, an ellipsis marking the cut.
///
/// ```
/// use graphostatik::fmt::clip;
/// assert_eq!(clip("U1\nU2", 10), "U1\\nU2");
/// assert_eq!(clip("abcdefgh", 4), "abcd…");
/// ```
pub fn clip(s: &str, max: usize) -> String {
    let mut out = String::new();
    for (k, c) in s.chars().enumerate() {
        if k == max {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// Text as it may stand in an SVG or HTML document: the characters XML forbids (controls
/// but tab, line feed and carriage return; U+FFFE, U+FFFF) become U+FFFD, so that a name a
/// scene gives can never make the figure ill-formed.
///
/// ```
/// use graphostatik::fmt::sheet_text;
/// assert_eq!(sheet_text("U1\u{0}\u{1b}"), "U1\u{fffd}\u{fffd}");
/// assert_eq!(sheet_text("a\tb"), "a\tb");
/// ```
pub fn sheet_text(s: &str) -> std::borrow::Cow<'_, str> {
    let bad = |c: char| {
        (c.is_control() && !matches!(c, '\t' | '\n' | '\r') && (c as u32) < 0x20)
            || c == '\u{7f}'
            || c == '\u{fffe}'
            || c == '\u{ffff}'
    };
    if s.chars().any(bad) {
        s.chars()
            .map(|c| if bad(c) { '\u{fffd}' } else { c })
            .collect::<String>()
            .into()
    } else {
        s.into()
    }
}

/// A text cell of a CSV file, quoted, that a spreadsheet will not run as a formula: a cell
/// starting with `=`, `+`, `-`, `@`, a tab or a carriage return gets a leading apostrophe
/// (numbers are written as numbers, not through here).
///
/// ```
/// use graphostatik::fmt::csv_text;
/// assert_eq!(csv_text("U1"), "\"U1\"");
/// assert_eq!(csv_text("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
/// ```
pub fn csv_text(s: &str) -> String {
    let formula = s.starts_with(['=', '+', '-', '@', '\t', '\r']);
    let s = s.replace('"', "\"\"");
    if formula {
        format!("\"'{s}\"")
    } else {
        format!("\"{s}\"")
    }
}

/// A cell of a Markdown table: a `|` escaped, line breaks and other controls as spaces.
///
/// ```
/// use graphostatik::fmt::markdown_cell;
/// assert_eq!(markdown_cell("a|b\nc"), "a\\|b c");
/// ```
pub fn markdown_cell(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '|' => out.push_str("\\|"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// Most characters of an error line; a longer one is cut with an ellipsis.
pub const MAX_ERROR_CHARS: usize = 1000;

/// An error as the command line prints it: one line (control characters escaped, so a
/// newline in a scene's name cannot split it) of at most [`MAX_ERROR_CHARS`] characters.
///
/// ```
/// use graphostatik::fmt::error_line;
/// assert_eq!(error_line("s.json: joints[2]: joint `a\nb` lies on joint `c`"),
///            "s.json: joints[2]: joint `a\\nb` lies on joint `c`");
/// ```
pub fn error_line(msg: &str) -> String {
    clip(msg, MAX_ERROR_CHARS)
}
