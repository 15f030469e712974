//! What accuracy costs, drawn: error against time on log-log axes, a curve per knob, and the
//! same as a table.

use crate::fmt::{num, sci};
use crate::kernel::construct::clip_to_rect;
use crate::kernel::Point;
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

/// The plot's frame: decades spanned on each axis, whether a row for exact zeros is drawn
/// under them, and the size of the sheet (the legend's column as wide as its longest line).
struct Frame {
    x: [f64; 2],
    y: [f64; 2],
    zeros: bool,
    width: f64,
    height: f64,
    title: Vec<String>,
}

/// The plotting area (px) and the margins around it.
const PLOT_W: f64 = 360.0;
const PLOT_H: f64 = 340.0;
const LEFT: f64 = 70.0;
const BOTTOM: f64 = 50.0;
/// The gap between the plot and the legend, and the legend's line height (px).
const LEGEND_GAP: f64 = 16.0;
const LINE: f64 = 13.0;
/// Advance of a character of the 11 px and 8 px sans-serif text (px, DejaVu Sans's mean).
const CHAR_11: f64 = 6.4;
const CHAR_8: f64 = 4.7;
/// The longest line of the title and of a legend entry (characters); longer text is wrapped
/// at a space, never cut off.
const TITLE_COLUMNS: usize = 90;
const LEGEND_COLUMNS: usize = 44;

use crate::fmt::wrap;

/// The legend of one sweep: the knob, then its quantity (subscripts set as such), wrapped.
fn legend_lines(s: &Sweep) -> (Vec<String>, Vec<String>) {
    (
        wrap(&s.knob, LEGEND_COLUMNS),
        wrap(&crate::fmt::subscripts(&s.quantity), LEGEND_COLUMNS),
    )
}

impl Frame {
    fn new(title: &str, sweeps: &[Sweep]) -> Frame {
        let (mut x, mut y) = (
            [f64::INFINITY, f64::NEG_INFINITY],
            [f64::INFINITY, f64::NEG_INFINITY],
        );
        let mut zeros = false;
        for s in sweeps {
            for p in &s.points {
                let tx = p.seconds.max(1e-9).log10();
                x = [x[0].min(tx), x[1].max(tx)];
                let rel = s.relative(p);
                if rel > 0.0 {
                    let ty = rel.max(FLOOR).log10();
                    y = [y[0].min(ty), y[1].max(ty)];
                } else {
                    zeros = true;
                }
            }
        }
        let span = |r: [f64; 2]| {
            if r[0].is_finite() {
                [r[0].floor(), r[1].ceil().max(r[0].floor() + 1.0)]
            } else {
                [0.0, 1.0]
            }
        };
        let legend_w = (sweeps.iter().map(legend_lines))
            .flat_map(|(a, b)| {
                let a = a.into_iter().map(|l| l.chars().count() as f64 * CHAR_11);
                a.chain(
                    b.into_iter()
                        .map(|l| l.chars().count() as f64 * CHAR_8 * 9.0 / 8.0),
                )
            })
            .fold(0.0, f64::max);
        let legend_h: f64 = (sweeps.iter().map(legend_lines))
            .map(|(a, b)| (a.len() + b.len()) as f64 * LINE + 6.0)
            .sum();
        let title = wrap(title, TITLE_COLUMNS);
        let title_w = (title.iter())
            .map(|l| l.chars().count() as f64 * CHAR_11 * 12.0 / 11.0)
            .fold(0.0, f64::max);
        let top = 16.0 + LINE * title.len() as f64;
        let width =
            (LEFT + PLOT_W + LEGEND_GAP + 24.0 + legend_w + 10.0).max(LEFT + title_w + 10.0);
        let height = (top + PLOT_H + BOTTOM).max(top + legend_h + 10.0);
        Frame {
            x: span(x),
            y: span(y),
            zeros,
            width: width.ceil(),
            height: height.ceil(),
            title,
        }
    }
    fn top(&self) -> f64 {
        16.0 + LINE * self.title.len() as f64
    }
    fn px(&self, secs: f64) -> f64 {
        let t = (secs.max(1e-9).log10() - self.x[0]) / (self.x[1] - self.x[0]);
        LEFT + t * PLOT_W
    }
    /// The decades drawn, the row of exact zeros (one decade under them) included.
    fn decades(&self) -> [f64; 2] {
        [self.y[0] - f64::from(u8::from(self.zeros)), self.y[1]]
    }
    fn py(&self, rel: f64) -> f64 {
        let [y0, y1] = self.decades();
        let v = if rel > 0.0 {
            rel.max(FLOOR).log10()
        } else {
            y0
        };
        let t = (v - y0) / (y1 - y0);
        self.top() + PLOT_H - t * PLOT_H
    }
}

const COLOURS: [&str; 8] = [
    "#000000", "#b03030", "#3050b0", "#308030", "#a06000", "#7030a0", "#008080", "#707070",
];

/// The sweeps as an SVG log-log plot of relative error against time per run. An exact zero
/// (the double-double replay against itself, a rule exact for the curve) stands on a row of
/// its own under the decades, marked "0"; the settings are written at their points where
/// there is room, clear of each other (the table has them all).
pub fn accuracy_plot_svg(title: &str, sweeps: &[Sweep]) -> String {
    let f = Frame::new(title, sweeps);
    let (w, h) = (f.width, f.height);
    let mut o = String::new();
    let _ = write!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {w} {h}" width="{w}" height="{h}" font-family="DejaVu Sans, sans-serif" font-size="11"><rect width="{w}" height="{h}" fill="white"/>"#
    );
    for (k, line) in f.title.iter().enumerate() {
        let _ = write!(
            o,
            r#"<text x="{LEFT}" y="{}" font-size="12">{}</text>"#,
            18.0 + LINE * k as f64,
            super::walkthrough::html_text(line)
        );
    }
    axes(&mut o, &f);
    // Every curve and mark first, then the settings' texts, each clear of every mark, line
    // and text before it, whichever curve they belong to.
    let mut marks = Marks::default();
    let points: Vec<_> = (sweeps.iter().enumerate())
        .map(|(k, s)| curve(&mut o, &f, s, COLOURS[k % COLOURS.len()], &mut marks))
        .collect();
    for (k, pts) in points.iter().enumerate() {
        settings(&mut o, &f, pts, COLOURS[k % COLOURS.len()], &mut marks);
    }
    let mut legend_y = f.top() + 14.0;
    for (k, s) in sweeps.iter().enumerate() {
        legend_y = legend(&mut o, &f, s, COLOURS[k % COLOURS.len()], legend_y);
    }
    o.push_str("</svg>\n");
    o
}

fn axes(o: &mut String, f: &Frame) {
    let (x0, x1, y0, y1) = (LEFT, LEFT + PLOT_W, f.top() + PLOT_H, f.top());
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
    let [d0, d1] = f.decades();
    for d in (d0 as i32)..=(d1 as i32) {
        let zero = f.zeros && d == d0 as i32;
        let y = if zero { f.py(0.0) } else { f.py(10f64.powi(d)) };
        let tick = if zero {
            "0".to_string()
        } else {
            format!("1e{d}")
        };
        let _ = write!(
            o,
            r##"<path d="M{x0} {y:.1}h-5" stroke="black"/><path d="M{x0} {y:.1}H{x1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">{tick}</text>"##,
            x0 - 8.0,
            y + 4.0
        );
    }
    let _ = write!(
        o,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">time per run (construction, recording, checks)</text>"#,
        (x0 + x1) / 2.0,
        y0 + 38.0
    );
    let _ = write!(
        o,
        r#"<text transform="translate(16 {:.1}) rotate(-90)" text-anchor="middle">relative error</text>"#,
        (y0 + y1) / 2.0
    );
}

/// The box of a setting's text at baseline-left `(x, y)` (px).
fn text_box(x: f64, y: f64, text: &str) -> [f64; 4] {
    [
        x,
        y - 7.0,
        x + text.chars().count() as f64 * CHAR_8,
        y + 2.0,
    ]
}

fn overlaps(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Whether the segment p–q crosses the box b: the kernel's clipping of a segment to a
/// rectangle leaves a piece of it inside (a touch at a corner or an edge is no crossing).
fn crosses(b: &[f64; 4], p: (f64, f64), q: (f64, f64)) -> bool {
    let (p, q) = (Point::new(p.0, p.1), Point::new(q.0, q.1));
    clip_to_rect(p, q, *b).is_some_and(|(t0, t1)| t0 < t1)
}

/// What the plot holds that a setting's text must keep clear of (px): the boxes of the marks
/// and of the texts written, and the curves' segments.
#[derive(Default)]
struct Marks {
    boxes: Vec<[f64; 4]>,
    segments: Vec<((f64, f64), (f64, f64))>,
}

impl Marks {
    fn clear(&self, b: &[f64; 4]) -> bool {
        !self.boxes.iter().any(|t| overlaps(t, b))
            && !self.segments.iter().any(|&(p, q)| crosses(b, p, q))
    }
}

/// Where a setting's text goes beside its point: the first of six places (right above,
/// right below, left above, left below, above, below), then the same six twice as far out,
/// inside the plot and clear of every mark, curve and text already on it; `None` where none
/// is (the table has every setting).
fn free_place(f: &Frame, (x, y): (f64, f64), text: &str, marks: &Marks) -> Option<(f64, f64)> {
    let w = text.chars().count() as f64 * CHAR_8;
    let places = |d: f64| {
        [
            (x + d, y - d),
            (x + d, y + 6.0 + d),
            (x - d - w, y - d),
            (x - d - w, y + 6.0 + d),
            (x - w / 2.0, y - 2.0 - d),
            (x - w / 2.0, y + 9.0 + d),
        ]
    };
    let inside =
        |b: &[f64; 4]| b[0] >= LEFT && b[2] <= LEFT + PLOT_W + 30.0 && b[1] >= f.top() - 10.0;
    (places(4.0).into_iter().chain(places(9.0))).find(|&(px, py)| {
        let b = text_box(px, py, text);
        inside(&b) && marks.clear(&b)
    })
}

/// One sweep's points on the plot (px): x, y, the setting, whether the error is exactly 0.
type PlotPoints<'a> = Vec<(f64, f64, &'a str, bool)>;

/// A sweep's line and marks; its points, for [`settings`].
fn curve<'a>(
    o: &mut String,
    f: &Frame,
    s: &'a Sweep,
    colour: &str,
    marks: &mut Marks,
) -> PlotPoints<'a> {
    let pts: PlotPoints = (s.points.iter())
        .map(|p| {
            let rel = s.relative(p);
            (f.px(p.seconds), f.py(rel), p.setting.as_str(), rel <= 0.0)
        })
        .collect();
    // The line joins the points with an error; an exact zero is a point on its row.
    let on_line: Vec<(f64, f64)> = (pts.iter()).filter(|p| !p.3).map(|p| (p.0, p.1)).collect();
    marks
        .segments
        .extend(on_line.windows(2).map(|w| (w[0], w[1])));
    let d: Vec<String> = (on_line.iter())
        .map(|(x, y)| format!("{x:.1} {y:.1}"))
        .collect();
    if d.len() > 1 {
        let _ = write!(
            o,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="1.4"/>"#,
            d.join(" ")
        );
    }
    for (x, y, _, zero) in &pts {
        let fill = if *zero { "white" } else { colour };
        let _ = write!(
            o,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="2.6" fill="{fill}" stroke="{colour}"/>"#
        );
        marks.boxes.push([x - 3.0, y - 3.0, x + 3.0, y + 3.0]);
    }
    pts
}

/// The settings' texts at a sweep's points, where there is room.
fn settings(o: &mut String, f: &Frame, pts: &PlotPoints, colour: &str, marks: &mut Marks) {
    for (x, y, label, _) in pts {
        if let Some((lx, ly)) = free_place(f, (*x, *y), label, marks) {
            marks.boxes.push(text_box(lx, ly, label));
            let _ = write!(
                o,
                r#"<text x="{lx:.1}" y="{ly:.1}" font-size="8" fill="{colour}">{}</text>"#,
                super::walkthrough::html_text(label)
            );
        }
    }
}

/// One sweep's entry in the legend at `y` (px): its line, its knob and its quantity, each
/// wrapped; returns where the next entry starts.
fn legend(o: &mut String, _f: &Frame, s: &Sweep, colour: &str, y: f64) -> f64 {
    let lx = LEFT + PLOT_W + LEGEND_GAP;
    let (knob, quantity) = legend_lines(s);
    let _ = write!(
        o,
        r#"<path d="M{lx} {:.1}h18" stroke="{colour}" stroke-width="1.4"/>"#,
        y - 4.0
    );
    let mut y = y;
    for line in &knob {
        let _ = write!(
            o,
            r#"<text x="{:.1}" y="{y:.1}">{}</text>"#,
            lx + 24.0,
            super::walkthrough::html_text(line)
        );
        y += LINE;
    }
    for line in &quantity {
        let _ = write!(
            o,
            r#"<text x="{:.1}" y="{:.1}" font-size="9" fill="{colour}">{}</text>"#,
            lx + 24.0,
            y - 1.0,
            super::walkthrough::html_text(line)
        );
        y += LINE;
    }
    y + 6.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::SweepPoint;

    fn sweep(knob: &str, quantity: &str, points: &[(&str, f64, f64)]) -> Sweep {
        Sweep {
            knob: knob.into(),
            quantity: quantity.into(),
            unit: "kg".into(),
            exact: Some(1.0),
            scale: 1.0,
            points: (points.iter())
                .map(|&(s, error, seconds)| SweepPoint {
                    setting: s.into(),
                    value: 1.0 + error,
                    error,
                    seconds,
                })
                .collect(),
        }
    }

    #[test]
    fn nothing_is_cut_off_and_an_exact_zero_has_its_row() {
        let long = "largest relative error of a step against the double-double replay";
        let s = [
            sweep(
                "divisions",
                "mean turning force T_m",
                &[("12", 1e-2, 1e-2), ("24", 1e-3, 2e-2)],
            ),
            sweep(
                "precision",
                long,
                &[("f64", 1e-15, 1e-2), ("double-double replay", 0.0, 5e-2)],
            ),
        ];
        let svg = accuracy_plot_svg(&"a title of many words ".repeat(8), &s);
        assert!(!svg.contains('…'), "nothing clipped");
        assert!(
            svg.contains(">double-double replay<"),
            "wrapped at a space, whole"
        );
        assert!(svg.contains("Tₘ") && !svg.contains("T_m"));
        assert!(
            svg.contains(r#"text-anchor="end">0</text>"#),
            "the zero row's tick"
        );
        assert!(
            svg.contains(r##"fill="white" stroke="#b03030""##),
            "the zero's open mark"
        );
    }

    /// The value of attribute `key` in each element of `svg` that has it.
    fn attrs<'a>(svg: &'a str, key: &str) -> Vec<&'a str> {
        let pat = format!(" {key}=\"");
        (svg.match_indices(&pat))
            .map(|(i, _)| {
                let rest = &svg[i + pat.len()..];
                &rest[..rest.find('"').unwrap()]
            })
            .collect()
    }

    /// Two curves that cross: every setting written is clear of both lines and of every mark,
    /// not only of the curve it belongs to.
    #[test]
    fn a_setting_keeps_clear_of_every_curve_and_mark() {
        let a = [("1", 1e-1, 1e-4), ("2", 1e-3, 1e-3), ("3", 1e-5, 1e-2)];
        let b = [("x", 1e-5, 1e-4), ("y", 1e-3, 1e-3), ("z", 1e-1, 1e-2)];
        let svg = accuracy_plot_svg("cross", &[sweep("n", "T", &a), sweep("m", "T", &b)]);
        let mut segments = Vec::new();
        for pts in attrs(&svg, "points") {
            let v: Vec<f64> = pts.split(' ').map(|x| x.parse().unwrap()).collect();
            let xy: Vec<(f64, f64)> = v.chunks(2).map(|c| (c[0], c[1])).collect();
            segments.extend(xy.windows(2).map(|w| (w[0], w[1])));
        }
        assert_eq!(segments.len(), 4);
        let num = |v: &str| v.parse::<f64>().unwrap();
        let (cx, cy) = (attrs(&svg, "cx"), attrs(&svg, "cy"));
        let dots: Vec<[f64; 4]> = (cx.iter().zip(&cy))
            .map(|(x, y)| [num(x) - 3.0, num(y) - 3.0, num(x) + 3.0, num(y) + 3.0])
            .collect();
        let settings: Vec<&str> = svg.split(r#"font-size="8""#).skip(1).collect();
        assert!(settings.len() >= 4, "{} of 6 written", settings.len());
        for (i, t) in svg.match_indices("<text x=\"") {
            let tag = &svg[i..];
            if !tag[..tag.find('>').unwrap()].contains(r#"font-size="8""#) {
                continue;
            }
            let label = &tag[tag.find('>').unwrap() + 1..tag.find("</text>").unwrap()];
            let (x, y) = (num(attrs(tag, "x")[0]), num(attrs(tag, "y")[0]));
            let b = text_box(x, y, label);
            assert!(
                segments.iter().all(|&(p, q)| !crosses(&b, p, q)),
                "{label} {t}"
            );
            assert!(dots.iter().all(|d| !overlaps(d, &b)), "{label} on a mark");
        }
    }

    #[test]
    fn the_segment_test_sees_a_crossing_and_a_miss() {
        let b = [0.0, 0.0, 10.0, 5.0];
        assert!(crosses(&b, (-5.0, 2.0), (15.0, 2.0)), "through");
        assert!(crosses(&b, (5.0, 2.0), (50.0, 50.0)), "from inside");
        assert!(!crosses(&b, (-5.0, -1.0), (15.0, -1.0)), "above");
        assert!(!crosses(&b, (11.0, -10.0), (30.0, 10.0)), "beside, slanted");
        assert!(!crosses(&b, (5.0, 6.0), (5.0, 20.0)), "vertical, below");
    }

    #[test]
    fn settings_crowded_at_one_place_are_written_once_each_where_there_is_room() {
        let pts: Vec<(String, f64, f64)> = (0..12)
            .map(|k| (format!("{}", 12 * (k + 1)), 1e-3, 1e-2))
            .collect();
        let pts: Vec<(&str, f64, f64)> = pts.iter().map(|(s, e, t)| (s.as_str(), *e, *t)).collect();
        let svg = accuracy_plot_svg("crowd", &[sweep("divisions", "T", &pts)]);
        let written = svg.matches(r#"font-size="8""#).count();
        assert!((1..=6).contains(&written), "{written} of 12 written");
    }
}
