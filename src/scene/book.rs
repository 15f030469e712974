//! The numbers a book prints beside the construction that reproduces them: a scene's `book`
//! field. `graphostatik check` writes each as its own row under the checks: what the book
//! printed, what the construction gives, what the book's own inputs give (the check's closed
//! form), and whether they agree within what the printed number stands for; where they do
//! not, the cause the scene names (a rounding of the book, a slip, a drawing error, a model
//! the book simplifies).

use crate::kernel::Point;
use crate::protocol::{Board, Geom, Note, Part, Topic};
use serde::{Deserialize, Serialize};

/// A number a book prints that a scene's construction stands for.
///
/// ```
/// use graphostatik::scene::BookValue;
/// let v: BookValue = serde_json::from_str(
///     r#"{"check": "piston acceleration b (Tolle’s parabola)", "at": "θ = 0°",
///         "printed": 181.5, "source": "LH B.3: p₀ = 181,5 m/s²"}"#,
/// ).unwrap();
/// assert_eq!(v.tolerance(), 0.05); // half a unit of the printed last place
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BookValue {
    /// The check it stands beside, by the quantity the check table names
    /// (`"rod force S"`).
    pub check: String,
    /// The situation of that check as the check table's context column writes it
    /// (`"θ = 30°"`, `"dead load"`, `"dead load: joint I, member 1"`), where the quantity
    /// is checked in several; absent: the first check of that quantity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<String>,
    /// The number as the book prints it, in the check's unit.
    pub printed: f64,
    /// What the printed number stands for, ± in the check's unit; absent: half a unit of its
    /// last printed place (181.5 stands for ±0.05).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub within: Option<f64>,
    /// What `within` stands for where it is given (`"the books' drawing error of 3.5 %"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub basis: Option<String>,
    /// Where the book prints it (`"LH B.3, S. 67: p₀ = 181,5 m/s²"`).
    pub source: String,
    /// Why the printed number and the construction differ by more than `within`, where they
    /// do: a rounding of the book, an arithmetic slip, a drawing error, another model input.
    /// A book value that differs with no cause given fails the check.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cause: Option<String>,
    /// How the sheet's table of book values names it: a symbol or a few words (`"c_max"`,
    /// `"S₁, dead load"`); absent: the check's quantity and situation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
}

impl BookValue {
    /// What the printed number stands for: `within`, or half a unit of its last printed place.
    pub fn tolerance(&self) -> f64 {
        self.within.unwrap_or_else(|| {
            let text = format!("{}", self.printed);
            let places = text.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
            0.5 * 10f64.powi(-places)
        })
    }
}

/// How a printed number stands against the construction.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Within what the printed number stands for.
    Reproduced,
    /// Outside it, for the cause the scene names.
    Explained,
    /// Outside it, and no cause is named: the check fails.
    Unexplained,
    /// No check of that quantity (and situation) was made: the check fails.
    NoSuchCheck,
}

/// One book row.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BookRow {
    /// Where the book prints it.
    pub source: String,
    /// The check's quantity, and its situation where one was named.
    pub quantity: String,
    /// How the sheet's table names it ([`BookValue::name`], else `quantity`).
    pub name: String,
    /// The check's unit.
    pub unit: String,
    /// As printed.
    pub printed: f64,
    /// What the construction gives.
    pub constructed: Option<f64>,
    /// What the book's own inputs give (the check's closed form).
    pub inputs: Option<f64>,
    /// What the printed number stands for (±).
    pub within: f64,
    /// What `within` stands for.
    pub basis: String,
    /// How they stand.
    pub verdict: Verdict,
    /// The cause the scene names, where they differ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cause: Option<String>,
}

impl BookRow {
    /// Reproduced, or explained.
    pub fn passed(&self) -> bool {
        matches!(self.verdict, Verdict::Reproduced | Verdict::Explained)
    }
}

/// Whether a check stands in the situation `at`: its context, or its context and object as
/// the check table's context column writes them ("dead load: joint I, member 1").
fn situated(e: &crate::protocol::CheckEntry, at: &str) -> bool {
    let context = e.context.unwrap_or("");
    match &e.check.object {
        None => e.context == Some(at),
        Some(object) => {
            e.context == Some(at)
                || match at.strip_suffix(&**object) {
                    Some(head) if context.is_empty() => head.is_empty(),
                    Some(head) => head.strip_suffix(", ") == Some(context),
                    None => false,
                }
        }
    }
}

/// The book rows of `values` against the checks on `board` (every check must be kept:
/// a board of [`Mode::Checks`](crate::protocol::Mode) with `every`, or a drawing board).
pub fn book_rows(board: &Board, values: &[BookValue]) -> Vec<BookRow> {
    let entries = board.check_entries();
    (values.iter())
        .map(|v| {
            let found = entries.iter().find(|e| {
                *e.check.quantity == *v.check && v.at.as_deref().is_none_or(|at| situated(e, at))
            });
            let within = v.tolerance();
            let verdict = match found {
                None => Verdict::NoSuchCheck,
                Some(e) if (e.check.constructed - v.printed).abs() <= within => Verdict::Reproduced,
                Some(_) if v.cause.is_some() => Verdict::Explained,
                Some(_) => Verdict::Unexplained,
            };
            let quantity = match &v.at {
                Some(at) => format!("{}, {at}", v.check),
                None => v.check.clone(),
            };
            BookRow {
                source: v.source.clone(),
                name: v.name.clone().unwrap_or_else(|| quantity.clone()),
                quantity,
                unit: found.map_or(String::new(), |e| e.check.unit.to_string()),
                printed: v.printed,
                constructed: found.map(|e| e.check.constructed),
                inputs: found.map(|e| e.check.closed_form),
                within,
                basis: (v.basis.clone())
                    .unwrap_or_else(|| "half a unit of the printed last place".into()),
                cause: (verdict != Verdict::Reproduced)
                    .then(|| v.cause.clone())
                    .flatten(),
                verdict,
            }
        })
        .collect()
}

/// The most book values the sheet's table lists; a scene with more (LH Aufgabe 5's 93, most
/// of them the book's Tabelle 1 and 2, which the figure draws as tables of its own) leaves
/// them to the check table.
pub const SHEET_BOOK_ROWS: usize = 40;

/// The longest cause the sheet's table writes in full; a longer one is written as its first
/// clause, where that is shorter: the head before a colon ("another quantity"), else the
/// words before a semicolon, comma or bracket ("an arithmetic slip of the book"); else as
/// "explained" (the check table gives every cause in full).
const SHEET_CAUSE_CHARS: usize = 40;

/// How the sheet writes a row's verdict: "reproduced", the cause (or its first clause),
/// "differs" or "no such check".
fn sheet_verdict(r: &BookRow) -> String {
    let short = |t: &str| t.chars().count() <= SHEET_CAUSE_CHARS;
    match (&r.verdict, r.cause.as_deref()) {
        (Verdict::Reproduced, _) => "reproduced".into(),
        (Verdict::Explained, Some(c)) => {
            let head = c.split_once(':').map_or(c, |(h, _)| h).trim();
            let clause = (c.split([';', ',']).next().unwrap_or(c))
                .split(" (")
                .next()
                .unwrap_or(c)
                .trim();
            [c, head, clause]
                .into_iter()
                .find(|t| short(t))
                .unwrap_or("explained")
                .into()
        }
        (Verdict::Explained | Verdict::Unexplained, _) => "differs".into(),
        (Verdict::NoSuchCheck, _) => "no such check".into(),
    }
}

/// The places after the point of a number as the scene writes it (`5.1`: 1).
fn places(x: f64) -> usize {
    format!("{x}").split_once('.').map_or(0, |(_, f)| f.len())
}

/// An angle in degrees and minutes, the minutes to `decimals` places (`79°16′`).
fn degrees_minutes(deg: f64, decimals: usize) -> String {
    let scale = 10f64.powi(decimals as i32);
    let total = (deg.abs() * 60.0 * scale).round() / scale;
    let (d, m) = (
        (total / 60.0).floor(),
        total - 60.0 * (total / 60.0).floor(),
    );
    let sign = if deg < 0.0 { "-" } else { "" };
    format!("{sign}{d}°{}′", crate::fmt::num(m, decimals))
}

/// The rows of the sheet's table of book values: a heading, then per value its name and
/// unit, the printed number as the scene gives it, the constructed one to a place more (at
/// most five) and how they stand.
pub fn sheet_rows(rows: &[BookRow]) -> Vec<Vec<String>> {
    let mut out = vec![vec![
        "book value".to_string(),
        "printed".into(),
        "drawn".into(),
        "".into(),
    ]];
    for r in rows {
        let unit = match r.unit.is_empty() {
            true => String::new(),
            false => format!(" [{}]", r.unit),
        };
        // An angle the book prints in minutes (79°16′, kept as 79.26667°) in minutes again.
        let minutes = r.unit == "°" && places(r.printed) >= 4;
        let (printed, drawn) = match minutes {
            true => (
                degrees_minutes(r.printed, 0),
                r.constructed.map(|x| degrees_minutes(x, 1)),
            ),
            false => (
                format!("{}", r.printed),
                (r.constructed).map(|x| crate::fmt::num(x, (places(r.printed) + 1).min(5))),
            ),
        };
        let unit = if minutes { "" } else { &unit };
        out.push(vec![
            format!("{}{unit}", r.name),
            printed.replace('-', "−"),
            drawn.map_or("–".into(), |d| d.replace('-', "−")),
            sheet_verdict(r),
        ]);
    }
    out
}

/// Where the book prints the values: each `source`'s head before its colon ("LH B.2, Gl.
/// 26"), once each, in order.
fn book_places(values: &[BookValue]) -> String {
    let mut places: Vec<&str> = Vec::new();
    for v in values {
        let head = v
            .source
            .split_once(':')
            .map_or(&v.source[..], |(h, _)| h)
            .trim();
        if !places.contains(&head) {
            places.push(head);
        }
    }
    places.join("; ")
}

/// The step that sets the book's printed values on the sheet beside what the construction
/// gives ([`sheet_rows`]): a table of its own part, which the sheet layout puts in a hole of
/// the figure, under the drawing where none takes it. Nothing on a board that does not
/// record, or for a scene of no book values or more than [`SHEET_BOOK_ROWS`].
pub fn book_table(board: &mut Board, values: &[BookValue]) {
    if !board.is_recording() || values.is_empty() || values.len() > SHEET_BOOK_ROWS {
        return;
    }
    let rows = sheet_rows(&book_rows(board, values));
    let row = (board.steps().iter())
        .map(|s| s.part.row)
        .max()
        .unwrap_or(0);
    let left = (board.objects().iter())
        .filter_map(|o| match &o.geom {
            Geom::Point { at } => Some(at.x),
            Geom::Segment { segment } | Geom::Vector { segment } => {
                Some(segment.a.x.min(segment.b.x))
            }
            _ => None,
        })
        .fold(f64::INFINITY, f64::min);
    let left = if left.is_finite() { left } else { 0.0 };
    board.set_part(Part::free(row.saturating_add(1), 0));
    let note = Note::new(
        "the book's printed values beside the construction",
        Topic::Custom("book"),
    )
    .term("Zahlenwerte des Buches")
    .book(book_places(values));
    board.table(Point::new(left, 0.0), rows, &[], note);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::protocol::Geom;

    fn row(quantity: &str, unit: &str, printed: f64, drawn: f64, verdict: Verdict) -> BookRow {
        BookRow {
            source: "LH B.2".into(),
            quantity: quantity.into(),
            name: quantity.into(),
            unit: unit.into(),
            printed,
            constructed: Some(drawn),
            inputs: Some(drawn),
            within: 0.05,
            basis: String::new(),
            verdict,
            cause: None,
        }
    }

    /// Each verdict in a few words; a long cause by its first clause; an angle the book
    /// prints in minutes in minutes again.
    #[test]
    fn the_sheet_writes_each_value_in_a_line() {
        let mut rows = vec![
            row("c_max", "m/s", 5.1, 5.09902, Verdict::Reproduced),
            row("α of c_max", "°", 79.26667, 78.690068, Verdict::Explained),
            row("b", "m/s²", 129.7, 129.63, Verdict::Explained),
            row("N_i", "PS", 35.0, 30.1, Verdict::Explained),
            row("S", "kg", 900.0, 1605.8, Verdict::Unexplained),
            row("V", "kg", 900.0, 0.0, Verdict::NoSuchCheck),
        ];
        rows[1].cause = Some("another quantity: LH's 79°16′ is the zero of Gl. 29, …".into());
        rows[2].cause = Some("an arithmetic slip of the book, far below drawing accuracy".into());
        rows[3].cause = Some("x".repeat(41) + "; and more");
        rows[5].constructed = None;
        let sheet = sheet_rows(&rows);
        assert_eq!(sheet[0], ["book value", "printed", "drawn", ""]);
        assert_eq!(sheet[1], ["c_max [m/s]", "5.1", "5.1", "reproduced"]);
        assert_eq!(
            sheet[2],
            ["α of c_max", "79°16′", "78°41.4′", "another quantity"]
        );
        assert_eq!(sheet[3][3], "an arithmetic slip of the book");
        assert_eq!(sheet[4][3], "explained");
        assert_eq!(sheet[5][3], "differs");
        assert_eq!(sheet[6][2..], ["–", "no such check"]);
        assert_eq!(degrees_minutes(100.73333, 0), "100°44′");
        assert_eq!(degrees_minutes(-0.5, 1), "-0°30′");
    }

    /// The table is the board's last step, in a free part of a row of its own under the
    /// others; a board that does not record, or a scene of too many values, gets none.
    #[test]
    fn the_book_table_is_a_free_part_after_the_construction() {
        let value = |printed: f64| BookValue {
            check: "T".into(),
            at: None,
            printed,
            within: None,
            basis: None,
            source: "LH J".into(),
            cause: None,
            name: Some("T_m".into()),
        };
        let build = |mut b: Board, n: usize| {
            let note = Note::new("t", Topic::Custom("book"));
            b.set_part(Part::at(2, 1));
            let t = b.tally(1160.0, "kg", "T", &[], note.clone());
            b.check(&t, "T", "kg", "given", 1000.0, || 1160.0);
            let steps = b.steps().len();
            book_table(&mut b, &vec![value(1160.0); n]);
            (b, steps)
        };
        let (b, steps) = build(Board::recording(), 1);
        assert_eq!(b.steps().len(), steps + 1);
        let last = b.steps().last().unwrap();
        assert_eq!(last.part, Part::free(3, 0));
        assert_eq!(last.term_de.as_deref(), Some("Zahlenwerte des Buches"));
        assert_eq!(last.book, "LH J");
        let table = b.objects().iter().find_map(|o| match &o.geom {
            Geom::Table { rows, .. } => Some(rows.clone()),
            _ => None,
        });
        assert_eq!(
            table.unwrap()[1],
            ["T_m [kg]", "1160", "1160", "reproduced"]
        );
        let (b, steps) = build(Board::recording(), SHEET_BOOK_ROWS + 1);
        assert_eq!(b.steps().len(), steps);
        let (b, steps) = build(Board::new(crate::protocol::BoardConfig::CHECKS), 1);
        assert_eq!(b.steps().len(), steps);
    }
}
