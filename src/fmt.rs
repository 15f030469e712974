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
    if !x.is_finite() {
        return if x.is_nan() {
            "NaN".into()
        } else if x > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        };
    }
    let mut s = format!("{:.*}", decimals, x);
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    s
}

/// Formats in scientific notation with 2 significant decimals (`1.23e-10`), for errors.
pub fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{:.2e}", x)
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
