//! The excess areas of the turning-force diagram (LH J; KG Abb. 1064): between the curve T
//! and the mean resistance T_m, where T exceeds T_m the work done exceeds the work taken and
//! the shaft speeds up (+), where it falls short it slows down (−). The areas are hatched
//! and signed, the points where T crosses T_m marked, and the two crossings where the
//! shaft runs fastest and slowest (the extremes of the energy E(θ) = ∫ (T − T_m) r dθ)
//! lettered v_max and v_min. The areas are checked to balance over the revolution, as the
//! mean's definition demands.

use super::Builder;
use crate::kernel::Point;
use crate::protocol::{note, ConstructionError, Label, Note, ObjId, Topic, Weighted, H};

const N_CROSS: Note = note(
    "where the turning force crosses the mean resistance",
    Some("Schnittpunkt mit der Widerstandslinie"),
    "LH J; KG Abb. 1064",
    Topic::Forces,
);
const N_HATCH: Note = note(
    "an excess area between T and T_m hatched",
    Some("Überschußfläche"),
    "LH J; KG Abb. 1064",
    Topic::Forces,
);
const N_SIGN: Note = note(
    "the excess area signed: + the shaft speeds up, − it slows down",
    Some("Arbeitsüberschuß, -mangel"),
    "LH J; KG Abb. 1064",
    Topic::Forces,
);
const N_BALANCE: Note = note(
    "the excess areas summed over the revolution",
    Some("Überschußflächen"),
    "LH J; KG Abb. 1064",
    Topic::Forces,
);
/// Hatch lines' spacing (mm of the sheet).
const HATCH_MM: f64 = 2.0;
/// The least height and width (mm) of an excess area that is signed: a sign must fit in it.
const SIGNED_MM: f64 = 6.0;

/// One excess area: its outline (on the mean line from `from` to `to`, along T between),
/// and its signed area (mm², + above T_m).
struct Area {
    outline: Vec<H<Point>>,
    mm2: f64,
}

impl Builder<'_> {
    /// The excess areas between the turning force's polygon `t` (the ordinates' ends, 0° to
    /// 360°) and the mean line from `start` (at 0°) to `end` (at 360°).
    pub(super) fn excess_areas(
        &mut self,
        t: &[H<Point>],
        (start, end): (&H<Point>, &H<Point>),
    ) -> Result<(), ConstructionError> {
        let y = start.g.y;
        let crossings: Vec<(usize, f64)> = (0..t.len().saturating_sub(1))
            .filter_map(|k| {
                let (fa, fb) = (t[k].g.y - y, t[k + 1].g.y - y);
                ((fa > 0.0) != (fb > 0.0)).then(|| (k, fa / (fa - fb)))
            })
            .collect();
        let names = extremes(t, start.g, &crossings);
        let mut areas = Vec::with_capacity(crossings.len() + 1);
        let mut outline = vec![*start];
        let mut next = crossings.iter().zip(names).peekable();
        for k in 0..t.len() {
            outline.push(t[k]);
            if let Some(((_, r), name)) = next.next_if(|((at, _), _)| *at == k) {
                let cross = self.b.divide_at(&t[k], &t[k + 1], *r, name, N_CROSS)?;
                outline.push(cross);
                areas.push(Area::of(std::mem::replace(&mut outline, vec![cross])));
            }
        }
        outline.push(*end);
        areas.push(Area::of(outline));
        for a in &areas {
            self.b.hatch(&a.outline, HATCH_MM, N_HATCH);
            self.sign(a);
        }
        self.balance(&areas);
        Ok(())
    }

    /// The sign of an excess area written inside it, where it is large enough to hold it.
    fn sign(&mut self, a: &Area) {
        let o = &a.outline;
        let y = o[0].g.y;
        let off = |i: usize| (o[i].g.y - y).abs();
        let Some(k) = (1..o.len().saturating_sub(1)).max_by(|&i, &j| off(i).total_cmp(&off(j)))
        else {
            return;
        };
        let height = o[k].g.y - y;
        let width = o[o.len() - 1].g.x - o[0].g.x;
        if height.abs() < SIGNED_MM || width < SIGNED_MM {
            return;
        }
        // Between the highest ordinate and the higher of its neighbours, clear of both
        // ordinates; a heading's text stands 4 mm under its cell's top, some 2.5 mm wide.
        let side = if off(k - 1) >= off(k + 1) {
            k - 1
        } else {
            k + 1
        };
        let x = 0.5 * (o[k].g.x + o[side].g.x);
        let at = Point::new(x - 1.2, y + 0.5 * height + 2.6);
        let sign = if height > 0.0 { "+" } else { "−" };
        self.b
            .table(at, vec![vec![sign.to_string()]], &[o[k].id], N_SIGN);
    }

    /// The excess areas summed: zero, since T_m is the mean of the same ordinates (the work
    /// done over a revolution is the work taken), within the rounding of the areas.
    fn balance(&mut self, areas: &[Area]) {
        let to_mkg = self.dr.force_scale * self.e.kinematics.r / 1000.0 / self.r_mm;
        let sum: f64 = areas.iter().map(|a| a.mm2).sum::<f64>() * to_mkg;
        let size: f64 = areas.iter().map(|a| a.mm2.abs()).sum::<f64>() * to_mkg;
        // A corner moved by 1 mm changes an area by at most the diagram's width plus height
        // (mm²): the weight by which the corners' bounds follow into the sum.
        let corners: Vec<ObjId> = (areas.iter())
            .flat_map(|a| a.outline.iter().map(|p| p.id))
            .collect();
        let (lo, hi) = (areas.iter().flat_map(|a| &a.outline))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.g.y), hi.max(p.g.y))
            });
        let reach = 2.0 * std::f64::consts::PI * self.r_mm + (hi - lo).max(0.0);
        let weighted = Weighted {
            inputs: &corners,
            weight: reach * to_mkg,
        };
        let t = self
            .b
            .reckon(sum, "m·kg", Label::plain("ΣΔE"), weighted, N_BALANCE);
        self.b.check(
            &t,
            "excess areas over a revolution, + and − balance",
            "m·kg",
            "∮ (T − T_m) r dθ = 0",
            size,
            || 0.0,
        );
    }
}

/// The crossings' labels: v_max where the energy E(θ) = ∫ (T − T_m) r dθ is largest (the
/// shaft runs fastest, at the end of a + area), v_min where it is least; the others none.
/// Reckoned from the numbers before anything is drawn: E at a crossing is the area between
/// T and the mean line (through `start`, at 0°) up to it, by the trapezoids of the polygon.
fn extremes(t: &[H<Point>], start: Point, crossings: &[(usize, f64)]) -> Vec<Label> {
    let y = start.y;
    let mut names = vec![Label::NONE; crossings.len()];
    let (mut e, mut top, mut low) = (0.0, (0.0, None), (0.0, None));
    let trapezoid = |a: Point, b: Point| 0.5 * (a.y + b.y - 2.0 * y) * (b.x - a.x);
    let mut last = start;
    let mut from = 0;
    for (i, &(k, r)) in crossings.iter().enumerate() {
        let cross = t[k].g + (t[k + 1].g - t[k].g) * r;
        for p in t[from..=k].iter().map(|p| p.g).chain([cross]) {
            e += trapezoid(last, p);
            last = p;
        }
        from = k + 1;
        if e > top.0 {
            top = (e, Some(i));
        }
        if e < low.0 {
            low = (e, Some(i));
        }
    }
    for (at, name) in [(top.1, "v_max"), (low.1, "v_min")] {
        if let Some(i) = at {
            names[i] = Label::named(name);
        }
    }
    names
}

/// The signed area (mm²) of a closed outline that runs along T left to right and back along
/// the mean line: + where T lies above the mean (the outline then turns clockwise, so the
/// shoelace formula's sign is turned).
fn signed_mm2(outline: &[Point]) -> f64 {
    let n = outline.len();
    let o = outline[0];
    let twice: f64 = (0..n)
        .map(|i| {
            let (p, q) = (outline[i] - o, outline[(i + 1) % n] - o);
            p.x * q.y - p.y * q.x
        })
        .sum();
    -0.5 * twice
}

impl Area {
    /// The area with its outline and its signed size ([`signed_mm2`]).
    fn of(outline: Vec<H<Point>>) -> Area {
        let pts: Vec<Point> = outline.iter().map(|p| p.g).collect();
        Area {
            mm2: signed_mm2(&pts),
            outline,
        }
    }
}
