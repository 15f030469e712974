//! The check table: every analytic check of a construction, as text or JSON.

use crate::fmt::{num, sci};
use crate::protocol::Board;
use serde::Serialize;

/// One row of the check table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckRow {
    /// Step number.
    pub step: String,
    /// The situation ("θ = 30°").
    pub context: String,
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

/// The rows of the check table, in step order.
pub fn check_rows(board: &Board) -> Vec<CheckRow> {
    board
        .check_entries()
        .into_iter()
        .map(|e| {
            let c = e.check;
            CheckRow {
                step: e.step.to_string(),
                context: e.context.unwrap_or("").to_string(),
                quantity: c.quantity.to_string(),
                unit: c.unit.to_string(),
                constructed: c.constructed,
                closed_form: c.closed_form,
                formula: c.formula.to_string(),
                error: c.error,
                tolerance: c.tolerance,
                passed: c.passed,
                bound: c.bound,
                meeting_angle_deg: c.worst_cut.map(|w| w.conditioning.angle_deg()),
                cut_step: c.worst_cut.map(|w| w.step.to_string()),
                glancing: c.glancing(),
            }
        })
        .collect()
}

/// The check table as aligned text (fixed number formatting: deterministic).
pub fn check_table_text(board: &Board) -> String {
    let rows = check_rows(board);
    let head = [
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
    let mut cells: Vec<Vec<String>> = vec![head.iter().map(|s| s.to_string()).collect()];
    for r in &rows {
        cells.push(vec![
            r.step.clone(),
            r.context.clone(),
            format!("{} [{}]", r.quantity, r.unit),
            num(r.constructed, 6),
            num(r.closed_form, 6),
            sci(r.error),
            sci(r.bound),
            sci(r.tolerance),
            match (r.meeting_angle_deg, &r.cut_step) {
                (Some(a), Some(at)) => format!(
                    "{}° at {at}{}",
                    num(a, 1),
                    if r.glancing { " glancing" } else { "" }
                ),
                _ => "-".into(),
            },
            if r.passed { "ok" } else { "FAIL" }.into(),
        ]);
    }
    let mut out = aligned(&cells, 3..=7);
    let failed = rows.iter().filter(|r| !r.passed).count();
    let glancing = rows.iter().filter(|r| r.glancing).count();
    out.push_str(&format!(
        "{} checks, {} passed, {} failed, {} depending on a glancing cut\n",
        rows.len(),
        rows.len() - failed,
        failed,
        glancing
    ));
    out
}

/// The check table as pretty JSON.
pub fn check_table_json(board: &Board) -> String {
    serde_json::to_string_pretty(&check_rows(board)).expect("rows are plain data")
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
    let ncol = cells[0].len();
    let mut widths = vec![0; ncol];
    let mut bytes = 0;
    for r in cells {
        for (w, s) in widths.iter_mut().zip(r) {
            *w = (*w).max(s.chars().count());
            bytes += s.len() + 2;
        }
    }
    let total: usize = widths.iter().sum::<usize>() + 2 * (ncol - 1);
    // Written in place: a table of 20,000 checks is some 3 MB of text.
    let mut out = String::with_capacity(bytes + cells.len() * total / 2 + 2 * total);
    for (i, r) in cells.iter().enumerate() {
        let start = out.len();
        for (c, s) in r.iter().enumerate() {
            if c > 0 {
                out.push_str("  ");
            }
            let pad = widths[c] - s.chars().count();
            if right.contains(&c) {
                out.extend(std::iter::repeat_n(' ', pad));
                out.push_str(s);
            } else {
                out.push_str(s);
                out.extend(std::iter::repeat_n(' ', pad));
            }
        }
        let kept = out[start..].trim_end().len();
        out.truncate(start + kept);
        out.push('\n');
        if i == 0 {
            out.extend(std::iter::repeat_n('-', total));
            out.push('\n');
        }
    }
    out
}
