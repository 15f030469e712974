//! The table of member forces of a truss (LH B.4, "Auswertung"): per load case the length of
//! the member's segment in the plan and its force, tension + and compression −, and the
//! combinations the scene asks for (the book's "Gesamtbelastung"). As Markdown, CSV or JSON.

use crate::fmt::num;
use crate::kernel::Vector;
use crate::truss::cremona::CaseResult;
pub use crate::truss::envelope::{envelope, Combination, EnvelopeRule, Extremes};
use serde::Serialize;

pub use crate::kernel::tolerance::ZERO_KG;

fn signed(x: f64) -> String {
    if x.abs() <= ZERO_KG {
        "0".into()
    } else if x > 0.0 {
        format!("+{}", num(x, 1))
    } else {
        format!("−{}", num(-x, 1))
    }
}

fn kind(x: f64) -> &'static str {
    if x.abs() <= ZERO_KG {
        "0"
    } else if x > 0.0 {
        "Zug"
    } else {
        "Druck"
    }
}

/// A reaction as magnitude and direction, "7640 ∠90°" (degrees counter-clockwise from +x).
fn polar(f: Vector) -> String {
    let m = f.x.hypot(f.y);
    if m <= ZERO_KG {
        return "0".into();
    }
    let mut deg = f.y.atan2(f.x).to_degrees();
    if deg < 0.0 {
        deg += 360.0;
    }
    format!("{} ∠{}°", num(m, 1), num(deg, 1))
}

/// A name in a Markdown cell.
fn md(s: &str) -> String {
    crate::fmt::markdown_cell(s)
}

/// The envelope as a Markdown table.
pub fn envelope_markdown(results: &[CaseResult], rule: Option<&EnvelopeRule>) -> String {
    let mut out =
        String::from("| member | max (kg) | from | min (kg) | from |\n|---|---:|---|---:|---|\n");
    for e in envelope(results, rule) {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            md(&e.member),
            signed(e.max.0),
            md(&e.max.1),
            signed(e.min.0),
            md(&e.min.1)
        ));
    }
    out
}

/// The table as Markdown: member, then per case the plan length (mm) and force (kg), then the
/// combinations, then tension or compression of the last column; below the members one row
/// per support reaction, as magnitude and direction ("925 ∠90°").
pub fn markdown(results: &[CaseResult], combos: &[Combination]) -> String {
    let mut head = vec!["member".to_string()];
    for r in results {
        head.push(format!("{} plan (mm)", md(&r.case)));
        head.push(format!("{} (kg)", md(&r.case)));
    }
    for c in combos {
        head.push(format!("{} (kg)", md(&c.name)));
    }
    head.push("kind".into());
    let mut out = format!("| {} |\n", head.join(" | "));
    out.push('|');
    for (i, _) in head.iter().enumerate() {
        out.push_str(if i == 0 { "---|" } else { "---:|" });
    }
    out.push('\n');
    let n = results.first().map_or(0, |r| r.members.len());
    for m in 0..n {
        let mut row = vec![md(&results[0].members[m].member)];
        let mut last = 0.0;
        for r in results {
            row.push(num(r.members[m].plan_mm, 1));
            row.push(signed(r.members[m].force));
            last = r.members[m].force;
        }
        for c in combos {
            last = c.force(results, m);
            row.push(signed(last));
        }
        row.push(kind(last).into());
        out.push_str(&format!("| {} |\n", row.join(" | ")));
    }
    // The support reactions, as magnitude and direction.
    let k = results.first().map_or(0, |r| r.reactions.len());
    for s in 0..k {
        let r0 = &results[0].reactions[s];
        let mut row = vec![md(&format!("{} ({})", r0.support, r0.joint))];
        for r in results {
            row.push(num(r.reactions[s].plan_mm, 1));
            row.push(polar(r.reactions[s].force));
        }
        for c in combos {
            row.push(polar(c.reaction(results, s)));
        }
        row.push("Auflager".into());
        out.push_str(&format!("| {} |\n", row.join(" | ")));
    }
    out
}

/// The same as CSV (comma-separated, plain minus signs, one header line), every number
/// with all its digits (the shortest decimal that reads back as the same f64); each support
/// reaction as two rows, its x and y components, with the plan column left empty.
pub fn csv(results: &[CaseResult], combos: &[Combination]) -> String {
    let q = |s: &str| crate::fmt::csv_text(s);
    let full = crate::fmt::full;
    let mut head = vec![q("member")];
    for r in results {
        head.push(q(&format!("{} plan_mm", r.case)));
        head.push(q(&format!("{} kg", r.case)));
    }
    for c in combos {
        head.push(q(&format!("{} kg", c.name)));
    }
    let mut out = head.join(",") + "\n";
    let n = results.first().map_or(0, |r| r.members.len());
    for m in 0..n {
        let mut row = vec![q(&results[0].members[m].member)];
        for r in results {
            row.push(full(r.members[m].plan_mm));
            row.push(full(r.members[m].force));
        }
        for c in combos {
            row.push(full(c.force(results, m)));
        }
        out.push_str(&(row.join(",") + "\n"));
    }
    // The support reactions as x and y components, with an empty plan column.
    let k = results.first().map_or(0, |r| r.reactions.len());
    for s in 0..k {
        let r0 = &results[0].reactions[s];
        for (axis, comp) in [("x", 0), ("y", 1)] {
            let mut row = vec![q(&format!("{} ({}) {axis}", r0.support, r0.joint))];
            for r in results {
                row.push(String::new());
                row.push(full(r.reactions[s].force[comp]));
            }
            for c in combos {
                row.push(full(c.reaction(results, s)[comp]));
            }
            out.push_str(&(row.join(",") + "\n"));
        }
    }
    out
}

/// The cases and combinations as JSON.
pub fn json(results: &[CaseResult], combos: &[Combination], rule: Option<&EnvelopeRule>) -> String {
    #[derive(Serialize)]
    struct Combo<'a> {
        name: &'a str,
        cases: Vec<&'a str>,
        members: Vec<(String, f64)>,
    }
    #[derive(Serialize)]
    struct All<'a> {
        cases: &'a [CaseResult],
        combinations: Vec<Combo<'a>>,
        envelope: Vec<Extremes>,
    }
    let n = results.first().map_or(0, |r| r.members.len());
    let all = All {
        cases: results,
        combinations: combos
            .iter()
            .map(|c| Combo {
                name: &c.name,
                cases: c.cases.iter().map(|&i| results[i].case.as_str()).collect(),
                members: (0..n)
                    .map(|m| {
                        (
                            results[0].members[m].member.as_str().to_owned(),
                            c.force(results, m),
                        )
                    })
                    .collect(),
            })
            .collect(),
        envelope: envelope(results, rule),
    };
    serde_json::to_string_pretty(&all).expect("plain data")
}
