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
    /// Meeting angle (degrees) of the glancing-most intersection the value depends on directly
    /// (the intersection step that made the measured point), if any.
    pub meeting_angle_deg: Option<f64>,
    /// Whether that intersection was glancing.
    pub glancing: bool,
}

/// The rows of the check table, in step order.
pub fn check_rows(board: &Board) -> Vec<CheckRow> {
    let mut rows = Vec::new();
    for step in board.steps() {
        if step.checks.is_empty() {
            continue;
        }
        // The conditioning of the intersections that made the measured points.
        let mut angle: Option<f64> = None;
        let mut glancing = false;
        for id in &step.inputs {
            if let Some(obj) = board.object(*id) {
                if let Some(src) = board.steps().get(obj.step.0 as usize - 1) {
                    if let Some(c) = src.conditioning {
                        let a = c.angle_deg();
                        angle = Some(angle.map_or(a, |m: f64| m.min(a)));
                        glancing |= c.glancing();
                    }
                }
            }
        }
        for c in &step.checks {
            rows.push(CheckRow {
                step: step.id.to_string(),
                context: step.context.as_deref().unwrap_or("").to_string(),
                quantity: c.quantity.to_string(),
                unit: c.unit.to_string(),
                constructed: c.constructed,
                closed_form: c.closed_form,
                formula: c.formula.to_string(),
                error: c.error,
                tolerance: c.tolerance,
                passed: c.passed,
                meeting_angle_deg: angle,
                glancing,
            });
        }
    }
    rows
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
        "tolerance",
        "cut angle",
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
            sci(r.tolerance),
            match r.meeting_angle_deg {
                Some(a) => format!(
                    "{}°{}",
                    num(a, 1),
                    if r.glancing { " glancing" } else { "" }
                ),
                None => "-".into(),
            },
            if r.passed { "ok" } else { "FAIL" }.into(),
        ]);
    }
    let ncol = head.len();
    let widths: Vec<usize> = (0..ncol)
        .map(|c| {
            cells
                .iter()
                .map(|r| r[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for (i, r) in cells.iter().enumerate() {
        let line: Vec<String> = r
            .iter()
            .enumerate()
            .map(|(c, s)| {
                let pad = widths[c] - s.chars().count();
                if (3..=6).contains(&c) {
                    format!("{}{}", " ".repeat(pad), s)
                } else {
                    format!("{}{}", s, " ".repeat(pad))
                }
            })
            .collect();
        out.push_str(line.join("  ").trim_end());
        out.push('\n');
        if i == 0 {
            let total: usize = widths.iter().sum::<usize>() + 2 * (ncol - 1);
            out.push_str(&"-".repeat(total));
            out.push('\n');
        }
    }
    let failed = rows.iter().filter(|r| !r.passed).count();
    let glancing = rows.iter().filter(|r| r.glancing).count();
    out.push_str(&format!(
        "{} checks, {} passed, {} failed, {} on a glancing intersection\n",
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
