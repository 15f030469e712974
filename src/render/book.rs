//! The book rows of a check table: each number a scene says its book prints, beside the
//! check it stands for ([`BookValue`]).

use crate::fmt::num;
pub use crate::scene::{book_rows, BookRow, Verdict};
use std::fmt::Write;

/// The book rows as text, one block a row: the quantity and where the book prints it, then
/// printed, constructed and the book's inputs side by side, then the verdict and its cause.
pub fn book_table_text(rows: &[BookRow]) -> String {
    let mut out = String::new();
    if rows.is_empty() {
        return out;
    }
    let _ = writeln!(
        out,
        "\nbook values: printed, constructed, the book's own inputs"
    );
    let value = |x: Option<f64>| x.map_or("-".to_string(), |x| num(x, 6));
    for r in rows {
        let unit = if r.unit.is_empty() {
            String::new()
        } else {
            format!(" [{}]", r.unit)
        };
        let _ = writeln!(out, "{}{unit} ({})", r.quantity, r.source);
        let _ = writeln!(
            out,
            "    printed {}  constructed {}  inputs {}  within ±{} ({})",
            num(r.printed, 6),
            value(r.constructed),
            value(r.inputs),
            num(r.within, 6),
            r.basis
        );
        let verdict = match r.verdict {
            Verdict::Reproduced => "reproduced".to_string(),
            Verdict::Explained => format!(
                "differs by {}: {}",
                num((r.constructed.unwrap_or(0.0) - r.printed).abs(), 4),
                r.cause.as_deref().unwrap_or("")
            ),
            Verdict::Unexplained => "DIFFERS, and the scene names no cause".to_string(),
            Verdict::NoSuchCheck => "NO SUCH CHECK in the table".to_string(),
        };
        let _ = writeln!(out, "    {verdict}");
    }
    let (n, ok) = (rows.len(), rows.iter().filter(|r| r.passed()).count());
    let explained = rows
        .iter()
        .filter(|r| r.verdict == Verdict::Explained)
        .count();
    let _ = writeln!(
        out,
        "{n} book values, {} reproduced, {explained} differing for a named cause, {} failed",
        ok - explained,
        n - ok
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::protocol::{Board, Note, Role, Scale, Topic};
    use crate::scene::BookValue;

    fn value(printed: f64, at: Option<&str>, cause: Option<&str>) -> BookValue {
        BookValue {
            check: "AB".into(),
            at: at.map(str::to_string),
            printed,
            within: None,
            basis: None,
            source: "a book".into(),
            cause: cause.map(str::to_string),
            name: None,
        }
    }

    #[test]
    fn a_printed_number_is_reproduced_explained_or_a_failure() {
        let n = Note::new("p", Topic::Custom("book"));
        let mut b = Board::recording();
        let a = b.point(Point::new(0.0, 0.0), Role::Given, n.clone());
        let c = b.point(Point::new(12.34, 0.0), Role::Given, n.clone());
        let l = b.line_through(&a, &c, Role::Given, n.clone()).unwrap();
        b.set_context(|| "here".into());
        let m = b.measure(&a, &c, &l, Scale::new(1.0, "mm"), "AB", n);
        b.check(&m, "AB", "mm", "given", 12.34, || 12.34);
        let rows = book_rows(
            &b,
            &[
                value(12.3, None, None),
                value(12.4, Some("here"), None),
                value(12.4, None, Some("the book rounds up")),
                value(12.34, Some("elsewhere"), None),
            ],
        );
        let verdicts: Vec<_> = rows.iter().map(|r| r.verdict.clone()).collect();
        assert_eq!(
            verdicts,
            [
                Verdict::Reproduced,
                Verdict::Unexplained,
                Verdict::Explained,
                Verdict::NoSuchCheck
            ]
        );
        assert_eq!(rows[0].within, 0.05);
        assert!(rows[0].passed() && !rows[1].passed() && rows[2].passed() && !rows[3].passed());
        let text = book_table_text(&rows);
        assert!(
            text.contains("differs by 0.06: the book rounds up"),
            "{text}"
        );
        assert!(
            text.contains("4 book values, 1 reproduced, 1 differing for a named cause, 2 failed")
        );
    }

    /// Where checks of one quantity differ only by their object (the members at a joint),
    /// `at` names the object as the check table does.
    #[test]
    fn a_book_value_finds_its_member_by_the_tables_context() {
        let n = Note::new("member", Topic::Custom("book"));
        let mut b = Board::recording();
        b.set_context(|| "dead load: joint I".into());
        for (k, force) in [(1, -869.4), (2, 441.6)] {
            let s = b.tally(force, "kg", "S", &[], n.clone());
            b.checking(
                |s| {
                    let _ = write!(s, "member {k}");
                },
                |b| b.check(&s, "AB", "kg", "ΣY = 0", 1000.0, || force),
            );
        }
        let rows = book_rows(
            &b,
            &[
                value(441.6, Some("dead load: joint I, member 2"), None),
                value(-869.4, Some("dead load: joint I"), None),
                value(441.6, Some("joint I, member 2"), None),
                value(441.6, Some("dead load: joint I, member 22"), None),
            ],
        );
        let verdicts: Vec<_> = rows.iter().map(|r| r.verdict.clone()).collect();
        assert_eq!(
            verdicts,
            [
                Verdict::Reproduced,
                Verdict::Reproduced,
                Verdict::NoSuchCheck,
                Verdict::NoSuchCheck
            ]
        );
    }
}
