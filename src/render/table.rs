//! The check table: every analytic check of a construction, as text or JSON.

use crate::fmt::{num, num_into, push_uint_padded, sci, sci_into};
use crate::protocol::{Board, Check, CheckSummary, StepId, LISTED_CHECKS};
use serde::Serialize;

/// One row of the check table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckRow {
    /// Step number.
    pub step: String,
    /// The situation ("θ = 30°").
    pub context: String,
    /// The object checked, where the quantity does not name it ("member 5").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub object: Option<String>,
    /// The quantity.
    pub quantity: String,
    /// Unit.
    pub unit: String,
    /// Value read off the construction.
    pub constructed: f64,
    /// Closed-form value.
    pub closed_form: f64,
    /// Formula reference.
    pub formula: String,
    /// Absolute error.
    pub error: f64,
    /// Tolerance.
    pub tolerance: f64,
    /// Passed?
    pub passed: bool,
    /// Whether the bound lies within the tolerance ([`Check::judged`]): where it does not, a
    /// passed check's value cannot be judged at this conditioning.
    pub judged: bool,
    /// The propagated bound of the constructed value's error (f64's rounding amplified by
    /// every cut the value depends on).
    pub bound: f64,
    /// Meeting angle (degrees) of the most glancing cut the value depends on, in its own step
    /// or any step before, if any.
    pub meeting_angle_deg: Option<f64>,
    /// The step of that cut.
    pub cut_step: Option<String>,
    /// Whether that cut was glancing.
    pub glancing: bool,
}

/// The rows of the check table, in step order (where the board kept only a
/// [`CheckSummary`], its failed checks).
pub fn check_rows(board: &Board) -> Vec<CheckRow> {
    board
        .check_entries()
        .into_iter()
        .map(|e| check_row(e.step, e.context, e.check))
        .collect()
}

/// A check as a row.
fn check_row(step: StepId, context: Option<&str>, c: &Check) -> CheckRow {
    CheckRow {
        step: step.to_string(),
        context: context.unwrap_or("").to_string(),
        object: c.object.as_deref().map(str::to_string),
        quantity: c.quantity.to_string(),
        unit: c.unit.to_string(),
        constructed: c.constructed,
        closed_form: c.closed_form,
        formula: c.formula.to_string(),
        error: c.error,
        tolerance: c.tolerance,
        passed: c.passed,
        judged: c.judged(),
        bound: c.bound,
        meeting_angle_deg: c.worst_cut.map(|w| w.conditioning.angle_deg()),
        cut_step: c.worst_cut.map(|w| w.step.to_string()),
        glancing: c.glancing(),
    }
}

/// The checks of a board that kept only their summary, as JSON: counts, a row per kind of
/// check with its worst, and the failed checks kept.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryJson {
    /// Checks made.
    pub checks: u64,
    /// Checks passed (and judged: their bound within their tolerance).
    pub passed: u64,
    /// Checks failed.
    pub failed: u64,
    /// Checks not failed whose bound exceeds their tolerance: not judged.
    #[serde(skip_serializing_if = "is_zero")]
    pub not_judged: u64,
    /// Checks depending on a glancing cut.
    pub glancing: u64,
    /// A kind per quantity and unit, in the order of their first steps.
    pub kinds: Vec<KindJson>,
    /// The failed checks kept whole, in step order.
    pub failures: Vec<CheckRow>,
    /// Failed checks counted but not kept.
    pub failures_not_listed: u64,
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}

/// The checks of one kind, in [`SummaryJson`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct KindJson {
    /// The quantity.
    pub quantity: String,
    /// Its unit.
    pub unit: String,
    /// Checks of this kind.
    pub checks: u64,
    /// Of them failed.
    pub failed: u64,
    /// Of them depending on a glancing cut.
    pub glancing: u64,
    /// The worst (the largest error against its tolerance).
    pub worst: CheckRow,
}

/// The summary of a board's checks as [`SummaryJson`].
pub fn summary_json(board: &Board, s: &CheckSummary) -> SummaryJson {
    SummaryJson {
        checks: s.total,
        passed: s.total - s.failed - s.unjudged,
        failed: s.failed,
        not_judged: s.unjudged,
        glancing: s.glancing,
        kinds: s
            .kinds
            .iter()
            .map(|k| KindJson {
                quantity: k.quantity.to_string(),
                unit: k.unit.to_string(),
                checks: k.count,
                failed: k.failed,
                glancing: k.glancing,
                worst: check_row(k.worst_step, board.context_of(k.worst_step), &k.worst),
            })
            .collect(),
        failures: check_rows(board),
        failures_not_listed: s.failures_not_listed(),
    }
}

/// The head of the check table.
const HEAD: [&str; 10] = [
    "step",
    "context",
    "quantity",
    "constructed",
    "closed form",
    "error",
    "bound",
    "tolerance",
    "worst cut",
    "ok",
];

/// The check table as aligned text (fixed number formatting: deterministic). Written from
/// the board's checks straight into one buffer of cells. Where the board kept only a
/// [`CheckSummary`](crate::protocol::CheckSummary) (more than
/// [`LISTED_CHECKS`](crate::protocol::LISTED_CHECKS) checks), a row per kind of check, its
/// worst, and every failed check.
pub fn check_table_text(board: &Board) -> String {
    use std::fmt::Write;
    let mut unjudged = 0;
    let (mut out, rows, failed, glancing) = match board.check_summary() {
        Some(s) => {
            unjudged = s.unjudged;
            (summary_text(board, s), s.total, s.failed, s.glancing)
        }
        None => {
            let mut cells = Cells::new(&HEAD);
            let (mut rows, mut failed, mut glancing) = (0, 0, 0);
            for e in board.check_entries() {
                rows += 1;
                failed += u64::from(!e.check.passed);
                unjudged += u64::from(e.check.passed && !e.check.judged());
                glancing += u64::from(e.check.glancing());
                check_cells(&mut cells, e.step, e.context, e.check, None);
            }
            (cells.aligned(3..=7), rows, failed, glancing)
        }
    };
    let _ = write!(
        out,
        "{} checks, {} passed, {} failed, ",
        rows,
        rows - failed - unjudged,
        failed
    );
    if unjudged > 0 {
        let _ = write!(
            out,
            "{unjudged} not judged (their bound exceeds their tolerance: the value cannot be \
             judged at this conditioning), "
        );
    }
    let _ = writeln!(out, "{glancing} depending on a glancing cut");
    out
}

/// One check's cells (with `count`, the cells of a kind's checks before its value cells).
fn check_cells(
    cells: &mut Cells,
    step: StepId,
    context: Option<&str>,
    c: &Check,
    count: Option<(u64, u64)>,
) {
    cells.cell(|s| push_uint_padded(s, step.0.into(), 3));
    // The situation, and the object where the quantity does not name it and the situation
    // names it not already: "P: joint B0, member 5".
    cells.cell(|s| {
        let context = context.unwrap_or("");
        s.push_str(context);
        let named =
            |o: &str| context == o || context.strip_suffix(o).is_some_and(|h| h.ends_with(", "));
        if let Some(object) = c.object.as_deref().filter(|o| !named(o)) {
            if !context.is_empty() {
                s.push_str(", ");
            }
            s.push_str(object);
        }
    });
    cells.cell(|s| {
        s.push_str(&c.quantity);
        // A ratio (R/L, a reduction factor) has no unit, and no empty brackets.
        if !c.unit.is_empty() {
            s.push_str(" [");
            s.push_str(&c.unit);
            s.push(']');
        }
    });
    if let Some((n, failed)) = count {
        cells.cell(|s| push_uint_padded(s, n, 1));
        cells.cell(|s| push_uint_padded(s, failed, 1));
    }
    cells.cell(|s| num_into(s, c.constructed, 6));
    cells.cell(|s| num_into(s, c.closed_form, 6));
    cells.cell(|s| sci_into(s, c.error));
    cells.cell(|s| sci_into(s, c.bound));
    cells.cell(|s| sci_into(s, c.tolerance));
    cells.cell(|s| match c.worst_cut {
        Some(w) => {
            num_into(s, w.conditioning.angle_deg(), 1);
            s.push_str("° at ");
            push_uint_padded(s, w.step.0.into(), 3);
            if c.glancing() {
                s.push_str(" glancing");
            }
        }
        None => s.push('-'),
    });
    let ok = count.map_or(c.passed, |(_, failed)| failed == 0);
    cells.cell(|s| {
        s.push_str(match (ok, c.judged()) {
            (false, _) => "FAIL",
            (true, true) => "ok",
            (true, false) => "not judged",
        })
    });
}

/// The summed-up table: what was summed up and why, a row per kind of check (its count,
/// its failures and its worst check), then every failed check kept.
fn summary_text(board: &Board, s: &CheckSummary) -> String {
    use std::fmt::Write;
    let mut out = format!(
        "{} checks, more than {}: one row per quantity with its worst check (the largest error \
         against its tolerance), then every failed check; `check --all` lists every check\n\n",
        s.total, LISTED_CHECKS
    );
    let mut head: Vec<&str> = HEAD[..3].to_vec();
    head.extend(["checks", "failed"]);
    head.extend(&HEAD[3..]);
    let mut cells = Cells::new(&head);
    for k in &s.kinds {
        let context = board.context_of(k.worst_step);
        check_cells(
            &mut cells,
            k.worst_step,
            context,
            &k.worst,
            Some((k.count, k.failed)),
        );
    }
    out += &cells.aligned(3..=9);
    if s.failed > 0 {
        let _ = writeln!(out, "\nfailed checks");
        let mut cells = Cells::new(&HEAD);
        for e in board.check_entries() {
            check_cells(&mut cells, e.step, e.context, e.check, None);
        }
        out += &cells.aligned(3..=7);
        if s.failures_not_listed() > 0 {
            let _ = writeln!(
                out,
                "and {} more failed checks, not listed (`check --all` lists them)",
                s.failures_not_listed()
            );
        }
    }
    out.push('\n');
    out
}

/// The cells of a text table in one buffer, row after row: what [`Cells::aligned`] lines up.
pub(super) struct Cells {
    text: String,
    /// Each cell's end in `text`.
    ends: Vec<usize>,
    /// The widest cell of each column so far, in characters.
    widths: Vec<usize>,
}

/// `n` blanks.
fn push_spaces(out: &mut String, mut n: usize) {
    const BLANKS: &str = "                                                                ";
    while n > 0 {
        let k = n.min(BLANKS.len());
        out.push_str(&BLANKS[..k]);
        n -= k;
    }
}

/// A cell's width in characters.
fn width(s: &str) -> usize {
    if s.is_ascii() {
        s.len()
    } else {
        s.chars().count()
    }
}

impl Cells {
    /// A table with this head row.
    pub(super) fn new(head: &[&str]) -> Cells {
        let mut c = Cells {
            text: String::new(),
            ends: Vec::new(),
            widths: vec![0; head.len()],
        };
        for h in head {
            c.cell(|s| s.push_str(h));
        }
        c
    }

    /// The next cell, written by `f` (rows wrap after as many cells as the head has).
    pub(super) fn cell(&mut self, f: impl FnOnce(&mut String)) {
        let start = self.text.len();
        f(&mut self.text);
        let column = self.ends.len() % self.widths.len();
        let w = width(&self.text[start..]);
        self.widths[column] = self.widths[column].max(w);
        self.ends.push(self.text.len());
    }

    /// The rows lined up in columns two spaces apart (the columns in `right` flush right),
    /// the head underlined, trailing blanks dropped.
    pub(super) fn aligned(&self, right: std::ops::RangeInclusive<usize>) -> String {
        let n = self.widths.len();
        let total: usize = self.widths.iter().sum::<usize>() + 2 * (n - 1);
        let rows = self.ends.len() / n;
        let mut out = String::with_capacity((rows + 2) * (total + 1));
        let mut start = 0;
        for (r, row) in self.ends.chunks(n).enumerate() {
            let line = out.len();
            for (c, &end) in row.iter().enumerate() {
                if c > 0 {
                    out.push_str("  ");
                }
                let cell = &self.text[start..end];
                start = end;
                let pad = self.widths[c] - width(cell);
                if right.contains(&c) {
                    push_spaces(&mut out, pad);
                    out.push_str(cell);
                } else {
                    out.push_str(cell);
                    push_spaces(&mut out, pad);
                }
            }
            let kept = out[line..].trim_end().len();
            out.truncate(line + kept);
            out.push('\n');
            if r == 0 {
                out.extend(std::iter::repeat_n('-', total));
                out.push('\n');
            }
        }
        out
    }
}

/// The check table as pretty JSON: an array of every row, or where the board kept only a
/// [`CheckSummary`], a [`SummaryJson`] object.
pub fn check_table_json(board: &Board) -> String {
    match board.check_summary() {
        Some(s) => serde_json::to_string_pretty(&summary_json(board, s)),
        None => serde_json::to_string_pretty(&check_rows(board)),
    }
    .expect("rows are plain data")
}

/// One row of the reference table: a step replayed in double-double.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReferenceTableRow {
    /// Step number.
    pub step: String,
    /// The situation ("θ = 30°").
    pub context: String,
    /// The step's caption.
    pub caption: String,
    /// |f64 − double-double| of the step's results (mm on the sheet, or the value's unit).
    pub observed: f64,
    /// The propagated bound of the same results.
    pub bound: f64,
    /// Digits f64 lost against the replay.
    pub digits_lost: f64,
    /// Digits the propagated bound predicted.
    pub digits_predicted: f64,
    /// Meeting angle (degrees) of the most glancing cut the results depend on.
    pub meeting_angle_deg: Option<f64>,
    /// The step of that cut.
    pub cut_step: Option<String>,
    /// Whether the observed error is within the bound.
    pub within: bool,
}

/// The rows of the reference table (empty unless the board replayed in double-double).
pub fn reference_rows(board: &Board) -> Vec<ReferenceTableRow> {
    board
        .reference_report()
        .into_iter()
        .map(|r| {
            let step = &board.steps()[r.step.0 as usize - 1];
            ReferenceTableRow {
                step: r.step.to_string(),
                context: step.context.as_deref().unwrap_or("").to_string(),
                caption: step.caption.to_string(),
                observed: r.observed,
                bound: r.bound,
                digits_lost: r.digits_lost(),
                digits_predicted: r.digits_predicted(),
                meeting_angle_deg: r.worst_cut.map(|w| w.conditioning.angle_deg()),
                cut_step: r.worst_cut.map(|w| w.step.to_string()),
                within: r.observed <= r.bound,
            }
        })
        .collect()
}

/// The reference table as text: the steps that lost or were predicted to lose a digit or
/// more (and every step where the bound failed), then a summary of all.
pub fn reference_table_text(board: &Board) -> String {
    let rows = reference_rows(board);
    let shown: Vec<&ReferenceTableRow> = rows
        .iter()
        .filter(|r| r.digits_lost >= 1.0 || r.digits_predicted >= 1.0 || !r.within)
        .collect();
    let head = [
        "step",
        "context",
        "caption",
        "f64 error",
        "bound",
        "lost",
        "predicted",
        "worst cut",
        "ok",
    ];
    let mut cells: Vec<Vec<String>> = vec![head.iter().map(|s| s.to_string()).collect()];
    for r in &shown {
        cells.push(vec![
            r.step.clone(),
            r.context.clone(),
            r.caption.clone(),
            sci(r.observed),
            sci(r.bound),
            num(r.digits_lost, 1),
            num(r.digits_predicted, 1),
            match (r.meeting_angle_deg, &r.cut_step) {
                (Some(a), Some(at)) => format!("{}° at {at}", num(a, 3)),
                _ => "-".into(),
            },
            if r.within { "ok" } else { "OVER" }.into(),
        ]);
    }
    let mut out = aligned(&cells, 3..=6);
    let over = rows.iter().filter(|r| !r.within).count();
    let worst = rows
        .iter()
        .max_by(|a, b| a.digits_lost.total_cmp(&b.digits_lost));
    out.push_str(&format!(
        "{} steps replayed in double-double ({} listed, the rest lost and were predicted to lose less than one digit); the bound held at {} of them{}\n",
        rows.len(),
        shown.len(),
        rows.len() - over,
        match worst {
            Some(w) => format!(
                "; most digits lost: {} at step {} (predicted {})",
                num(w.digits_lost, 1),
                w.step,
                num(w.digits_predicted, 1)
            ),
            None => String::new(),
        }
    ));
    out
}

/// The reference table as pretty JSON (every replayed step).
pub fn reference_table_json(board: &Board) -> String {
    serde_json::to_string_pretty(&reference_rows(board)).expect("rows are plain data")
}

/// Cells as aligned text with a rule under the header; `right` columns right-aligned.
pub(super) fn aligned(cells: &[Vec<String>], right: std::ops::RangeInclusive<usize>) -> String {
    let head: Vec<&str> = cells[0].iter().map(String::as_str).collect();
    let mut t = Cells::new(&head);
    for row in &cells[1..] {
        for x in row {
            t.cell(|s| s.push_str(x));
        }
    }
    t.aligned(right)
}
