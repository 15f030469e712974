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
        if x < 0.0 {
            out.push('-');
        }
        push_uint(out, x.abs() as u64);
        return;
    }
    if fixed_fast(out, x, decimals) {
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
    } else if !sci_fast(out, x) {
        let _ = write!(out, "{:.2e}", x);
    }
}

/// Powers of ten that f64 holds exactly.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// `x` scaled by 10^k (|k| ≤ 22) with one rounding: its error is at most half an ulp.
fn scaled(x: f64, k: i32) -> Option<f64> {
    let p = *POW10.get(k.unsigned_abs() as usize)?;
    Some(if k >= 0 { x * p } else { x / p })
}

/// The nearest integer to the exact value of which `m` is the rounded scaling, where that
/// is certain: `m` below 2^40 (its rounding at most 2^-13) and not within 2^-12 of a tie.
/// Otherwise `None`, and the exact formatter decides.
fn certain_round(m: f64) -> Option<f64> {
    let n = m.round();
    (m.abs() < (1u64 << 40) as f64 && (m - n).abs() < 0.5 - 1.0 / 4096.0).then_some(n)
}

/// x·y as the rounded product and its exact error (Dekker's product by Veltkamp's split;
/// exact where neither overflows).
fn two_prod(x: f64, y: f64) -> (f64, f64) {
    let split = |a: f64| {
        let c = 134_217_729.0 * a; // 2^27 + 1
        let hi = c - (c - a);
        (hi, a - hi)
    };
    let p = x * y;
    let ((xh, xl), (yh, yl)) = (split(x), split(y));
    (p, ((xh * yh - p) + xh * yl + xl * yh) + xl * yl)
}

/// The integer nearest to x·10^decimals where that is certain (the exact product below
/// 2^53, not within 1e-9 of a tie); `None` otherwise.
fn fixed_round(x: f64, decimals: usize) -> Option<i64> {
    let scale = *POW10.get(decimals)?;
    let (m, err) = two_prod(x, scale);
    // (NaN fails this too.)
    if m.abs().partial_cmp(&((1u64 << 53) as f64)) != Some(std::cmp::Ordering::Less) {
        return None;
    }
    let n = m.round();
    // m − n is exact (|m| ≥ 2^52 is whole; below, n lies within a factor of two of m or
    // m is under ½); the rest of the distance to n is the product's error.
    let off = (m - n) + err;
    (off.abs() < 0.5 - 1e-9).then_some(n as i64)
}

/// [`num_into`]'s text without the exact float formatting where the rounding is certain:
/// x·10^decimals rounded to an integer and the point set in it; the same text as the
/// exact formatting, trimmed (tested on millions of values against it). `false`: nothing
/// written, the caller formats exactly.
fn fixed_fast(out: &mut String, x: f64, decimals: usize) -> bool {
    let Some(n) = fixed_round(x, decimals) else {
        return false;
    };
    if n == 0 {
        out.push('0');
        return true;
    }
    // The digits right-aligned in a buffer, at least one before the point.
    let mut buf = [b'0'; 40];
    let end = buf.len();
    let mut i = end;
    let mut m = n.unsigned_abs();
    while m > 0 {
        i -= 1;
        buf[i] = b'0' + (m % 10) as u8;
        m /= 10;
    }
    let first = i.min(end - decimals - 1);
    let point = end - decimals;
    // The fraction without its trailing zeros.
    let mut last = end;
    while last > point && buf[last - 1] == b'0' {
        last -= 1;
    }
    if n < 0 {
        out.push('-');
    }
    let text = |r: std::ops::Range<usize>| std::str::from_utf8(&buf[r]).unwrap_or("");
    out.push_str(text(first..point));
    if last > point {
        out.push('.');
        out.push_str(text(point..last));
    }
    true
}

/// [`sci_into`]'s text (`{:.2e}`) without the exact float formatting where the rounding
/// to three digits is certain (tested on millions of values against it).
fn sci_fast(out: &mut String, x: f64) -> bool {
    let a = x.abs();
    if !a.is_normal() {
        return false;
    }
    let mut e = a.log10().floor() as i32;
    // The estimate of the exponent may be one off either way: the scaled value tells.
    let mut m = match scaled(a, 2 - e) {
        Some(m) => m,
        None => return false,
    };
    if m < 100.0 {
        e -= 1;
    } else if m >= 1000.0 {
        e += 1;
    }
    if !(100.0..1000.0).contains(&m) {
        match scaled(a, 2 - e) {
            Some(v) if (100.0..1000.0).contains(&v) => m = v,
            _ => return false,
        }
    }
    let Some(n) = certain_round(m) else {
        return false;
    };
    let mut n = n as u32;
    if n == 1000 {
        n = 100;
        e += 1;
    }
    if x < 0.0 {
        out.push('-');
    }
    let digit = |d: u32| char::from(b'0' + d as u8);
    out.push(digit(n / 100));
    out.push('.');
    out.push(digit(n / 10 % 10));
    out.push(digit(n % 10));
    out.push('e');
    if e < 0 {
        out.push('-');
    }
    push_uint(out, u64::from(e.unsigned_abs()));
    true
}

/// The decimal digits of `n`, at least `width` of them (zeros in front), without the
/// formatting machinery: for tables of many rows.
///
/// ```
/// let mut s = String::from("step ");
/// graphostatik::fmt::push_uint_padded(&mut s, 7, 3);
/// assert_eq!(s, "step 007");
/// ```
pub fn push_uint_padded(out: &mut String, mut n: u64, width: usize) {
    let mut buf = [b'0'; 24];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    let i = i.min(buf.len().saturating_sub(width));
    // Only ASCII digits were written.
    if let Ok(digits) = std::str::from_utf8(&buf[i..]) {
        out.push_str(digits);
    }
}

fn push_uint(out: &mut String, n: u64) {
    push_uint_padded(out, n, 1);
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
    // Read by byte first: a sheet's text seldom holds a control character, and U+FFFE and
    // U+FFFF are the only ones above ASCII, both led by the byte 0xEF in UTF-8.
    // (A tab or a line break is suspect too; the chars tell.) Folded by blocks, so that the
    // compiler can test a block's bytes at once.
    let suspect = |block: &[u8]| {
        (block.iter()).fold(false, |any, &b| {
            any | (b < 0x20) | (b == 0x7f) | (b == 0xef)
        })
    };
    if s.as_bytes().chunks(64).any(suspect) && s.chars().any(bad) {
        s.chars()
            .map(|c| if bad(c) { '\u{fffd}' } else { c })
            .collect::<String>()
            .into()
    } else {
        s.into()
    }
}

/// The letters Unicode sets as subscripts that the sheet's DejaVu Serif has, with their
/// subscripts.
const SUBSCRIPT_LETTERS: [(char, char); 17] = [
    ('a', 'ₐ'),
    ('e', 'ₑ'),
    ('h', 'ₕ'),
    ('i', 'ᵢ'),
    ('j', 'ⱼ'),
    ('k', 'ₖ'),
    ('l', 'ₗ'),
    ('m', 'ₘ'),
    ('n', 'ₙ'),
    ('o', 'ₒ'),
    ('p', 'ₚ'),
    ('r', 'ᵣ'),
    ('s', 'ₛ'),
    ('t', 'ₜ'),
    ('u', 'ᵤ'),
    ('v', 'ᵥ'),
    ('x', 'ₓ'),
];

/// The subscript form of a character, where Unicode has one that the sheet's DejaVu Serif
/// sets (figures, and a e h k l m n o p s t x, i r u v j).
pub fn subscript_of(c: char) -> Option<char> {
    match c {
        '0'..='9' => char::from_u32('₀' as u32 + (c as u32 - '0' as u32)),
        _ => (SUBSCRIPT_LETTERS.iter())
            .find(|(l, _)| *l == c)
            .map(|(_, s)| *s),
    }
}

/// Whether a character is one of the subscripts [`subscript_of`] gives.
pub fn is_subscript(c: char) -> bool {
    ('₀'..='₉').contains(&c) || SUBSCRIPT_LETTERS.iter().any(|(_, s)| *s == c)
}

/// The books' subscripts where a text writes them with an underscore: `T_m` is set `Tₘ`,
/// `c_max` `cₘₐₓ`, `N_i` `Nᵢ`. Only a symbol is set so: one or two letters standing as a word
/// of their own, an underscore, and one to four letters or figures that end the word, each
/// with a subscript form. Anything else (`slider_crank`, `length_mm`, `_x`, `a_b_c`) stays as
/// written. For the lettering of a figure, not for messages that quote a scene's fields.
///
/// ```
/// use graphostatik::fmt::subscripts;
/// assert_eq!(subscripts("T_m = 12900 kg"), "Tₘ = 12900 kg");
/// assert_eq!(subscripts("c_max and N_i"), "cₘₐₓ and Nᵢ");
/// assert_eq!(subscripts("length_mm, slider_crank, _x, a_b_c"), "length_mm, slider_crank, _x, a_b_c");
/// ```
pub fn subscripts(s: &str) -> std::borrow::Cow<'_, str> {
    if !s.contains('_') {
        return s.into();
    }
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::with_capacity(s.len());
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        // The symbol before: one or two letters from the start of a word.
        let symbol = (1..=2).any(|n| {
            i >= n
                && chars[i - n..i].iter().all(|c| c.is_alphabetic())
                && (i == n || !chars[i - n - 1].is_alphanumeric())
        });
        if c == '_' && symbol {
            let run: Vec<char> = chars[i + 1..]
                .iter()
                .take_while(|c| c.is_alphanumeric() || **c == '_')
                .copied()
                .collect();
            let subs: Option<String> = run.iter().map(|c| subscript_of(*c)).collect();
            let whole = !run.contains(&'_');
            if let Some(subs) = subs.filter(|_| whole && (1..=4).contains(&run.len())) {
                out.push_str(&subs);
                i += 1 + run.len();
                continue;
            }
        }
        out.push(c);
        i += 1;
    }
    out.into()
}

/// Text as it may stand in XML or HTML, as an element's text or inside an attribute's quotes
/// (either kind): `&`, `<`, `>`, `"` and `'` as entities, and the characters XML forbids
/// (controls but tab, line feed and carriage return; U+FFFE, U+FFFF) as U+FFFD, so that no
/// name a scene gives can close an attribute, open an element or make the document
/// ill-formed. Every SVG, HTML and walk-through the engine writes escapes its text here.
///
/// ```
/// use graphostatik::fmt::markup_text;
/// let mut out = String::new();
/// markup_text(&mut out, "1\" onmouseover=\"x\" a='<b>&\u{0}");
/// assert_eq!(out, "1&quot; onmouseover=&quot;x&quot; a=&#39;&lt;b&gt;&amp;\u{fffd}");
/// ```
pub fn markup_text(out: &mut String, text: &str) {
    let s = sheet_text(text);
    let bytes = s.as_bytes();
    let mut from = 0;
    for (i, &b) in bytes.iter().enumerate() {
        let entity = match b {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            b'\'' => "&#39;",
            _ => continue,
        };
        out.push_str(&s[from..i]);
        out.push_str(entity);
        from = i + 1;
    }
    out.push_str(&s[from..]);
}

/// The vulgar fractions a ratio is written with where its decimals would not end (thirds,
/// sixths, sevenths, ninths) or a half: (numerator, denominator, character); the sheet's
/// DejaVu Serif has them all. A ratio of tenths (16.8) stays decimal.
const FRACTIONS: [(u32, u32, char); 7] = [
    (1, 2, '½'),
    (1, 3, '⅓'),
    (2, 3, '⅔'),
    (1, 6, '⅙'),
    (5, 6, '⅚'),
    (1, 7, '⅐'),
    (1, 9, '⅑'),
];

/// A ratio as the books write it: a whole number where it is one (to 1e-9 of itself), a
/// whole number and a vulgar fraction where it is one of [`FRACTIONS`] (7⅑ for 64/9, the
/// compound engine's 1 : 7⅑), else to `decimals` decimals.
///
/// ```
/// use graphostatik::fmt::book_number;
/// assert_eq!(book_number(64.0 / 9.0, 3), "7⅑");
/// assert_eq!(book_number(6.0000000001, 3), "6");
/// assert_eq!(book_number(2.5, 3), "2½");
/// assert_eq!(book_number(16.8, 3), "16.8");
/// assert_eq!(book_number(3.14159, 3), "3.142");
/// ```
pub fn book_number(x: f64, decimals: usize) -> String {
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * x.abs().max(1.0);
    if !x.is_finite() || x < 0.0 {
        return num(x, decimals);
    }
    let whole = x.floor();
    if close(x, x.round()) {
        return num(x.round(), 0);
    }
    for (n, d, c) in FRACTIONS {
        if close(x, whole + f64::from(n) / f64::from(d)) {
            return if whole == 0.0 {
                c.to_string()
            } else {
                format!("{}{c}", num(whole, 0))
            };
        }
    }
    num(x, decimals)
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

/// Most characters of an error line; a longer one is cut in its middle with an ellipsis.
pub const MAX_ERROR_CHARS: usize = 1000;

/// An error as the command line prints it: one line (control characters escaped, so a
/// newline in a scene's name cannot split it) of at most [`MAX_ERROR_CHARS`] characters. A
/// longer one keeps its beginning (the file and the field) and its end (the reason, after
/// whatever long value it quotes) and loses its middle.
///
/// ```
/// use graphostatik::fmt::error_line;
/// assert_eq!(error_line("s.json: joints[2]: joint `a\nb` lies on joint `c`"),
///            "s.json: joints[2]: joint `a\\nb` lies on joint `c`");
/// let long = format!("s.json: order: {:?}: name each once", [4; 400]);
/// let line = error_line(&long);
/// assert!(line.starts_with("s.json: order: [4, 4") && line.ends_with(": name each once"));
/// assert!(line.chars().count() <= 1000 && line.contains(" … "));
/// ```
pub fn error_line(msg: &str) -> String {
    let line = clip(msg, usize::MAX);
    let n = line.chars().count();
    if n <= MAX_ERROR_CHARS {
        return line;
    }
    let (head, tail) = (MAX_ERROR_CHARS * 3 / 5, MAX_ERROR_CHARS * 2 / 5 - 3);
    let mut out: String = line.chars().take(head).collect();
    out.push_str(" … ");
    out.extend(line.chars().skip(n - tail));
    out
}

/// `text` broken at spaces into lines of at most `columns` characters (a longer word stands
/// on a line of its own); an empty text is one empty line.
///
/// ```
/// use graphostatik::fmt::wrap;
/// assert_eq!(wrap("a bc def", 4), ["a bc", "def"]);
/// assert_eq!(wrap("", 4), [""]);
/// ```
pub fn wrap(text: &str, columns: usize) -> Vec<String> {
    let words = words_of(text);
    lines_at(&words, &line_starts(&words, columns))
}

/// The words of `text` between white space, each with its length in characters: what
/// [`wrap`] breaks into lines.
pub(crate) fn words_of(text: &str) -> Vec<(&str, usize)> {
    (text.split_whitespace())
        .map(|w| (w, w.chars().count()))
        .collect()
}

/// The words each line starts at where `words` ([`words_of`]) are wrapped at `columns`: a
/// word goes on the line before where it fits there after a space, else it starts a line.
/// A wrap found so writes nothing (a title tried at every width: [`wrap`] writing each try
/// was 35 M of the 706 M instructions of rendering the bundled scenes).
pub(crate) fn line_starts(words: &[(&str, usize)], columns: usize) -> Vec<usize> {
    let mut starts = Vec::new();
    let mut line = 0;
    for (i, &(_, n)) in words.iter().enumerate() {
        if i > 0 && line + 1 + n <= columns {
            line += 1 + n;
        } else {
            starts.push(i);
            line = n;
        }
    }
    starts
}

/// The lines of `words` starting at `starts` ([`line_starts`]), the words of a line joined
/// by a space; no words are one empty line.
pub(crate) fn lines_at(words: &[(&str, usize)], starts: &[usize]) -> Vec<String> {
    if words.is_empty() {
        return vec![String::new()];
    }
    let ends = starts.iter().skip(1).copied().chain([words.len()]);
    (starts.iter().zip(ends))
        .map(|(&a, b)| {
            let mut line = String::new();
            for (k, w) in words[a..b].iter().enumerate() {
                if k > 0 {
                    line.push(' ');
                }
                line.push_str(w.0);
            }
            line
        })
        .collect()
}

/// Whether a line may end after `word` without parting a phrase: a word ending in a comma,
/// a colon or a semicolon, or a dash standing alone.
///
/// ```
/// use graphostatik::fmt::ends_phrase;
/// assert!(ends_phrase("Tafel I:") && ends_phrase("—") && !ends_phrase("Tafel"));
/// ```
pub fn ends_phrase(word: &str) -> bool {
    word.ends_with([',', ':', ';']) || word == "—"
}

#[cfg(test)]
mod fast_tests {
    use super::*;

    fn exact_num(x: f64, d: usize) -> String {
        let mut s = format!("{:.*}", d, x);
        if s.contains('.') {
            s = s.trim_end_matches('0').trim_end_matches('.').to_string();
        }
        if s == "-0" {
            s = "0".into();
        }
        s
    }

    fn exact_sci(x: f64) -> String {
        if x == 0.0 {
            "0".into()
        } else {
            format!("{:.2e}", x)
        }
    }

    /// Values of every magnitude, ties of both formats, and values a hair off them.
    fn samples() -> Vec<f64> {
        let mut xs = vec![
            0.0078125,
            0.5e-6,
            1.5e-6,
            2.5e-6,
            1234.5,
            0.125,
            0.0000005,
            999.5,
            9.995,
            9.9949999,
            1.005,
            2.675,
            1e-300,
            5e-324,
            1e300,
            123456.789,
            1099511627776.5,
            0.1 + 0.2,
            -3394.1125496954,
            4.547473508864641e-13,
            1.235e-9,
            9.995e-7,
            1e22,
            1e23,
            7.0e-21,
        ];
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        // Fewer without optimisation: the exact formatting compared with is slow there.
        let rounds = if cfg!(debug_assertions) {
            4_000
        } else {
            40_000
        };
        for _ in 0..rounds {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            // Any bit pattern, and numbers of table-like size.
            let bits = f64::from_bits(state);
            if bits.is_finite() {
                xs.push(bits);
            }
            let mag = 10f64.powi((state % 40) as i32 - 20);
            xs.push(mag * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5));
            // Ties and near-ties of six decimals and of three digits.
            let k = (state >> 20) % 2_000_000;
            xs.push((k as f64 + 0.5) / 1e6);
            xs.push((k as f64 + 0.5) * 10f64.powi((state % 30) as i32 - 15) / 1000.0);
        }
        let near: Vec<f64> = xs
            .iter()
            .flat_map(|x| {
                [
                    f64::from_bits(x.to_bits() + 1),
                    f64::from_bits(x.to_bits().wrapping_sub(1)),
                ]
            })
            .filter(|x| x.is_finite())
            .collect();
        xs.extend(near);
        let neg: Vec<f64> = xs.iter().map(|x| -x).collect();
        xs.extend(neg);
        xs
    }

    #[test]
    fn the_fast_paths_write_the_exact_formatting_s_text() {
        let (mut fast_num, mut fast_sci) = (0, 0);
        let xs = samples();
        for &x in &xs {
            for d in [0, 1, 3, 6] {
                let mut s = String::new();
                num_into(&mut s, x, d);
                assert_eq!(s, exact_num(x, d), "num({x:e}, {d})");
                fast_num += usize::from(fixed_fast(&mut String::new(), x, d));
            }
            let mut s = String::new();
            sci_into(&mut s, x);
            assert_eq!(s, exact_sci(x), "sci({x:e})");
            fast_sci += usize::from(x != 0.0 && sci_fast(&mut String::new(), x));
        }
        // The fast paths take most values (every bit pattern included).
        assert!(
            fast_num > 2 * xs.len() && fast_sci > xs.len() / 2,
            "{fast_num} {fast_sci} of {}",
            xs.len()
        );
    }
}
