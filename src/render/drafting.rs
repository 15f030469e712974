//! The draftsman's drawings as a table: the spread of every checked value.

use crate::fmt::{num, sci};
use crate::scene::DraftingReport;

/// The drafting report as text: per checked value the closed form, the construction drawn
/// without error, the drawings' mean, standard deviation (also relative to the quantity's
/// natural magnitude), 95 %
/// range, the linear estimate the board propagates for the hand and the share of the
/// drawings beyond it, the error budget (the shares of the variance that
/// the pencil, the set square and the scale rule cause alone), and the most glancing cut.
pub fn drafting_table_text(r: &DraftingReport) -> String {
    let head = [
        "step",
        "context",
        "quantity",
        "closed form",
        "drawn exactly",
        "mean",
        "sd",
        "sd %",
        "95 % of the drawings",
        "estimate",
        "beyond it",
        "pencil/square/rule",
        "worst cut",
    ];
    let mut cells: Vec<Vec<String>> = vec![head.iter().map(|s| s.to_string()).collect()];
    for v in &r.values {
        let rel = v.sd / v.reference;
        cells.push(vec![
            v.step.clone(),
            v.context.clone(),
            {
                let unit = if v.unit.is_empty() {
                    String::new()
                } else {
                    format!(" [{}]", v.unit)
                };
                if v.object.is_empty() {
                    format!("{}{unit}", v.quantity)
                } else {
                    format!("{} {}{unit}", v.quantity, v.object)
                }
            },
            num(v.closed_form, 4),
            num(v.drawn_exactly, 4),
            num(v.mean, 4),
            sci(v.sd),
            if rel.is_finite() {
                num(100.0 * rel, 2)
            } else {
                "-".into()
            },
            format!("{} … {}", num(v.range[0], 3), num(v.range[1], 3)),
            sci(v.bound),
            format!("{} %", num(100.0 * v.outside, 1)),
            shares(&v.budget),
            v.worst_cut.map_or("-".into(), |w| {
                format!("{}° at {}", num(w.conditioning.angle_deg(), 1), w.step)
            }),
        ]);
    }
    let mut out = super::table::aligned(&cells, 3..=11);
    let o = &r.options;
    out.push_str(&format!(
        "{} drawings by a hand of pencil {} mm, set square {}°, scale rule {} mm (standard deviations), seeds {}…; {} could not be finished{}{}\n",
        o.runs,
        num(o.hand.mark_mm, 3),
        num(o.hand.angle_rad.to_degrees(), 3),
        num(o.hand.read_mm, 3),
        o.seed,
        r.failed,
        r.first_failure.as_ref().map_or(String::new(), |e| format!(" (the first: {})", crate::fmt::clip(e, 160))),
        if r.missing > 0 { format!("; {} checked values no finished drawing gave", r.missing) } else { String::new() }
    ));
    out.push_str(
        "estimate: the board's linear sum of the hand's standard deviations through every step \
         (not a bound); beyond it: the drawings farther than that from the value drawn exactly\n",
    );
    out
}

/// The error budget as shares of the variance: pencil / set square / scale rule, in percent.
fn shares(b: &[f64; 3]) -> String {
    let total: f64 = b.iter().map(|s| s * s).sum();
    if total.is_nan() || total <= 0.0 {
        return "-".into();
    }
    let p: Vec<String> = b
        .iter()
        .map(|s| format!("{:.0}", 100.0 * s * s / total))
        .collect();
    format!("{} %", p.join("/"))
}
