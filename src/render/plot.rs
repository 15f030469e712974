//! What accuracy costs, drawn: error against time on log-log axes, a curve per knob, and the
//! same as a table.

use crate::fmt::{num, sci};
use crate::scene::Sweep;
use std::fmt::Write;

/// Relative errors below this are drawn on the floor of the plot (f64's rounding).
const FLOOR: f64 = 1e-17;

/// The sweeps as a text table: knob, setting, value, error, relative error, time.
pub fn accuracy_table_text(sweeps: &[Sweep]) -> String {
    let mut out = String::new();
    for s in sweeps {
        let exact = s
            .exact
            .map_or(String::new(), |e| format!(", exact {}", num(e, 6)));
        let _ = writeln!(out, "{} — {} [{}{exact}]", s.knob, s.quantity, s.unit);
        let _ = writeln!(
            out,
            "{:>22}  {:>16}  {:>10}  {:>10}  {:>11}",
            "setting", "value", "error", "relative", "time per run"
        );
        for p in &s.points {
            let _ = writeln!(
                out,
                "{:>22}  {:>16}  {:>10}  {:>10}  {:>11}",
                crate::fmt::clip(&p.setting, 22),
                if p.value.abs() >= 1e-3 || p.value == 0.0 {
                    num(p.value, 6)
                } else {
                    sci(p.value)
                },
                sci(p.error),
                sci(s.relative(p)),
                seconds(p.seconds)
            );
        }
        out.push('\n');
    }
    out
}

/// A time in the unit that reads best.
fn seconds(s: f64) -> String {
    if s >= 1.0 {
        format!("{} s", num(s, 2))
    } else if s >= 1e-3 {
        format!("{} ms", num(s * 1e3, 2))
    } else {
        format!("{} µs", num(s * 1e6, 1))
    }
}

/// The plot's frame: decades spanned on each axis and the mapping to the drawing.
struct Frame {
    x: [f64; 2],
    y: [f64; 2],
}

const W: f64 = 640.0;
const H: f64 = 420.0;
const LEFT: f64 = 70.0;
const RIGHT: f64 = 250.0;
const TOP: f64 = 30.0;
const BOTTOM: f64 = 50.0;

impl Frame {
    fn new(sweeps: &[Sweep]) -> Frame {
        let (mut x, mut y) = (
            [f64::INFINITY, f64::NEG_INFINITY],
            [f64::INFINITY, f64::NEG_INFINITY],
        );
        for s in sweeps {
            for p in &s.points {
                let (tx, ty) = (
                    p.seconds.max(1e-9).log10(),
                    s.relative(p).max(FLOOR).log10(),
                );
                x = [x[0].min(tx), x[1].max(tx)];
                y = [y[0].min(ty), y[1].max(ty)];
            }
        }
        let span = |r: [f64; 2]| {
            if r[0].is_finite() {
                [r[0].floor(), r[1].ceil().max(r[0].floor() + 1.0)]
            } else {
                [0.0, 1.0]
            }
        };
        Frame {
            x: span(x),
            y: span(y),
        }
    }
    fn px(&self, secs: f64) -> f64 {
        let t = (secs.max(1e-9).log10() - self.x[0]) / (self.x[1] - self.x[0]);
        LEFT + t * (W - LEFT - RIGHT)
    }
    fn py(&self, rel: f64) -> f64 {
        let t = (rel.max(FLOOR).log10() - self.y[0]) / (self.y[1] - self.y[0]);
        H - BOTTOM - t * (H - TOP - BOTTOM)
    }
}

const COLOURS: [&str; 8] = [
    "#000000", "#b03030", "#3050b0", "#308030", "#a06000", "#7030a0", "#008080", "#707070",
];

/// The sweeps as an SVG log-log plot of relative error against time per run.
pub fn accuracy_plot_svg(title: &str, sweeps: &[Sweep]) -> String {
    let f = Frame::new(sweeps);
    let mut o = String::new();
    let _ = write!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {W} {H}" width="{W}" height="{H}" font-family="DejaVu Sans, sans-serif" font-size="11"><rect width="{W}" height="{H}" fill="white"/>"#
    );
    let _ = write!(
        o,
        r#"<text x="{LEFT}" y="18" font-size="12">{}</text>"#,
        super::walkthrough::html_text(&crate::fmt::clip(title, 80))
    );
    axes(&mut o, &f);
    for (k, s) in sweeps.iter().enumerate() {
        curve(&mut o, &f, s, COLOURS[k % COLOURS.len()], k);
    }
    o.push_str("</svg>\n");
    o
}

fn axes(o: &mut String, f: &Frame) {
    let (x0, x1, y0, y1) = (LEFT, W - RIGHT, H - BOTTOM, TOP);
    let _ = write!(
        o,
        r#"<path d="M{x0} {y1}V{y0}H{x1}" fill="none" stroke="black"/>"#
    );
    for d in (f.x[0] as i32)..=(f.x[1] as i32) {
        let x = f.px(10f64.powi(d));
        let _ = write!(
            o,
            r##"<path d="M{x:.1} {y0}v5" stroke="black"/><path d="M{x:.1} {y0}V{y1}" stroke="#ddd"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
            y0 + 18.0,
            seconds(10f64.powi(d))
        );
    }
    for d in (f.y[0] as i32)..=(f.y[1] as i32) {
        let y = f.py(10f64.powi(d));
        let _ = write!(
            o,
            r##"<path d="M{x0} {y:.1}h-5" stroke="black"/><path d="M{x0} {y:.1}H{x1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">1e{d}</text>"##,
            x0 - 8.0,
            y + 4.0
        );
    }
    let _ = write!(
        o,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">time per run (construction, recording, checks)</text>"#,
        (x0 + x1) / 2.0,
        H - 12.0
    );
    let _ = write!(
        o,
        r#"<text transform="translate(16 {:.1}) rotate(-90)" text-anchor="middle">relative error</text>"#,
        (y0 + y1) / 2.0
    );
}

fn curve(o: &mut String, f: &Frame, s: &Sweep, colour: &str, k: usize) {
    let pts: Vec<(f64, f64, &str)> = s
        .points
        .iter()
        .filter(|p| s.relative(p) > 0.0 || s.knob != "precision")
        .map(|p| (f.px(p.seconds), f.py(s.relative(p)), p.setting.as_str()))
        .collect();
    if pts.is_empty() {
        return;
    }
    let d: Vec<String> = pts
        .iter()
        .map(|(x, y, _)| format!("{x:.1} {y:.1}"))
        .collect();
    let _ = write!(
        o,
        r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="1.4"/>"#,
        d.join(" ")
    );
    for (x, y, label) in &pts {
        let _ = write!(
            o,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="2.6" fill="{colour}"/><text x="{:.1}" y="{:.1}" font-size="8" fill="{colour}">{}</text>"#,
            x + 4.0,
            y - 4.0,
            super::walkthrough::html_text(label)
        );
    }
    let ly = TOP + 14.0 + 30.0 * k as f64;
    let lx = W - RIGHT + 16.0;
    let _ = write!(
        o,
        r#"<path d="M{lx} {ly}h18" stroke="{colour}" stroke-width="1.4"/><text x="{:.1}" y="{:.1}">{}</text><text x="{:.1}" y="{:.1}" font-size="9" fill="{colour}">{}</text>"#,
        lx + 24.0,
        ly + 4.0,
        super::walkthrough::html_text(&crate::fmt::clip(&s.knob, 34)),
        lx + 24.0,
        ly + 16.0,
        super::walkthrough::html_text(&crate::fmt::clip(&s.quantity, 40))
    );
}
