//! The table of member forces of a truss (LH B.4, "Auswertung"): per load case the length of
//! the member's segment in the plan and its force, tension + and compression −, and the
//! combinations the scene asks for (the book's "Gesamtbelastung"). As Markdown, CSV or JSON.

use crate::fmt::num;
use crate::truss::cremona::CaseResult;
use serde::Serialize;

/// A named sum of load cases.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Combination {
    /// Its name ("total").
    pub name: String,
    /// Indices of the cases added.
    pub cases: Vec<usize>,
}

/// A force below this many kg is written as 0 and classed as a zero-force member: the plan
/// is exact to about 1e-12 of the loads, so anything below a gram is rounding.
pub const ZERO_KG: f64 = 1e-3;

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

fn combined(results: &[CaseResult], c: &Combination, m: usize) -> f64 {
    c.cases.iter().map(|&i| results[i].members[m].force).sum()
}

/// The extremes of one member over all load cases (LH B.5, T6): the largest tension and the
/// largest compression, with the case where each occurs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Extremes {
    /// Member name.
    pub member: String,
    /// Largest tension (kg, ≥ 0) and its case.
    pub tension: (f64, String),
    /// Largest compression (kg, ≤ 0) and its case.
    pub compression: (f64, String),
}

/// The envelope over all cases: the first case reaching each extreme names it; "-" where the
/// member is never in tension (or compression).
pub fn envelope(results: &[CaseResult]) -> Vec<Extremes> {
    let n = results.first().map_or(0, |r| r.members.len());
    (0..n)
        .map(|m| {
            let mut t = (0.0, "-".to_string());
            let mut c = (0.0, "-".to_string());
            for r in results {
                let f = r.members[m].force;
                if f > t.0 && f > ZERO_KG {
                    t = (f, r.case.clone());
                }
                if f < c.0 && f < -ZERO_KG {
                    c = (f, r.case.clone());
                }
            }
            Extremes {
                member: results[0].members[m].member.clone(),
                tension: t,
                compression: c,
            }
        })
        .collect()
}

/// The envelope as a Markdown table.
pub fn envelope_markdown(results: &[CaseResult]) -> String {
    let mut out = String::from(
        "| member | max tension (kg) | in case | max compression (kg) | in case |\n|---|---:|---|---:|---|\n",
    );
    for e in envelope(results) {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            e.member,
            signed(e.tension.0),
            e.tension.1,
            signed(e.compression.0),
            e.compression.1
        ));
    }
    out
}

/// The table as Markdown: member, then per case the plan length (mm) and force (kg), then the
/// combinations, then tension or compression of the last column.
pub fn markdown(results: &[CaseResult], combos: &[Combination]) -> String {
    let mut head = vec!["member".to_string()];
    for r in results {
        head.push(format!("{} plan (mm)", r.case));
        head.push(format!("{} (kg)", r.case));
    }
    for c in combos {
        head.push(format!("{} (kg)", c.name));
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
        let mut row = vec![results[0].members[m].member.clone()];
        let mut last = 0.0;
        for r in results {
            row.push(num(r.members[m].plan_mm, 1));
            row.push(signed(r.members[m].force));
            last = r.members[m].force;
        }
        for c in combos {
            last = combined(results, c, m);
            row.push(signed(last));
        }
        row.push(kind(last).into());
        out.push_str(&format!("| {} |\n", row.join(" | ")));
    }
    out
}

/// The same as CSV (comma-separated, plain minus signs, one header line).
pub fn csv(results: &[CaseResult], combos: &[Combination]) -> String {
    let q = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
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
            row.push(num(r.members[m].plan_mm, 3));
            row.push(num(r.members[m].force, 3));
        }
        for c in combos {
            row.push(num(combined(results, c, m), 3));
        }
        out.push_str(&(row.join(",") + "\n"));
    }
    out
}

/// The cases and combinations as JSON.
pub fn json(results: &[CaseResult], combos: &[Combination]) -> String {
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
                            results[0].members[m].member.clone(),
                            combined(results, c, m),
                        )
                    })
                    .collect(),
            })
            .collect(),
        envelope: envelope(results),
    };
    serde_json::to_string_pretty(&all).expect("plain data")
}
