//! The shear diagram read off the force plan (LH C.6, Abb. 25) and the largest moment where
//! the shear changes sign: at an event, or inside a uniform load, found on its parabola by the
//! ratio of the zero shear (Abb. 36).

use super::build::{b_point, BeamConstruction, Kind, Parabola, ShearDiagram};
use super::notes::*;
use super::types::{MaxMoment, ShearRow, GAP_MM};
use crate::kernel::tolerance::REL_POSITION_EPS;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{ConstructionError, Label, Role, Scale, Trace, H};

/// Where the force plan's corners stand for the shear: the loads left of a section are a
/// prefix of the load line (no point load lies inside a uniform load), counted by binary
/// search so that long beams stay linear.
struct Depth {
    points: Vec<f64>,
    uniform_ends: Vec<f64>,
}

impl Depth {
    fn new(beam: &crate::statics::Beam) -> Depth {
        let mut points: Vec<f64> = beam.point_loads.iter().map(|l| l.x).collect();
        points.sort_by(f64::total_cmp);
        let mut uniform_ends: Vec<f64> = beam.uniform_loads.iter().map(|u| u.to).collect();
        uniform_ends.sort_by(f64::total_cmp);
        Depth {
            points,
            uniform_ends,
        }
    }

    /// How many forces of the load line lie left of x (at it, too, for the value just right
    /// of it); a uniform load counts once its end is passed (V is continuous).
    fn index(&self, x: f64, right: bool) -> usize {
        let points = if right {
            self.points.partition_point(|&v| v <= x)
        } else {
            self.points.partition_point(|&v| v < x)
        };
        points + self.uniform_ends.partition_point(|&v| v <= x)
    }
}

impl BeamConstruction<'_, '_> {
    /// The events of the shear diagram: ends, supports, point loads, ends of uniform loads,
    /// ordered, those closer than the position tolerance merged.
    fn events(&self) -> Vec<f64> {
        let beam = self.beam;
        let mut events = vec![
            beam.ends[0],
            beam.ends[1],
            beam.supports[0],
            beam.supports[1],
        ];
        events.extend(beam.point_loads.iter().map(|l| l.x));
        for u in &beam.uniform_loads {
            events.push(u.from);
            events.push(u.to);
        }
        events.sort_by(f64::total_cmp);
        let tol = REL_POSITION_EPS * self.span.max(1.0);
        events.dedup_by(|a, b| (*a - *b).abs() <= tol);
        events
    }

    /// The shear base line, below everything drawn so far (the polygon hangs as deep as
    /// M/H) by the largest shear ordinate.
    fn shear_base(&mut self) -> Result<(H<Point>, H<Line>), ConstructionError> {
        let r = self.reactions_drawn();
        let (_, fp, f) = self.drawn();
        let lowest = f
            .corners
            .iter()
            .chain([&f.start, &r.ia, &r.ib])
            .chain(fp.pts.iter())
            .map(|p| p.g.y)
            .fold(f.start.g.y, f64::min);
        let fs = self.dr.force_scale;
        let v_max = self.ra.abs().max(self.rb.abs()).max(self.total.abs()) / fs;
        let at = Point::new(self.sx(self.beam.ends[0]), lowest - GAP_MM - v_max);
        let b = &mut *self.b;
        // The base line's start keeps its name in the protocol: the figure names the
        // diagram V, once.
        let base0 = b.point(
            at,
            Role::Given.labelled(Label::quiet("V", 0)),
            N_SHEAR_BASE_START,
        );
        let x = Vector::new(1.0, 0.0);
        let base = b.line_dir(&base0, x, Role::Axis, N_SHEAR_BASE)?;
        Ok((base0, base))
    }

    /// The shear just left or right of x, read off the load line: from the corner after the
    /// loads left of x to the start 0, to C or to the end n, by where x lies; checked by the
    /// method of sections.
    fn shear_at(&mut self, depth: &Depth, x: f64, right: bool) -> f64 {
        let c = self.reactions_drawn().c;
        let (_, fp, _) = self.drawn();
        let [sa, sb] = self.beam.supports;
        let past_a = if right { x >= sa } else { x > sa };
        let past_b = if right { x >= sb } else { x > sb };
        let anchor = if past_b {
            fp.pts[fp.pts.len() - 1]
        } else if past_a {
            c
        } else {
            fp.pts[0]
        };
        let (from, line) = (fp.pts[depth.index(x, right)], fp.load_line);
        let (kg, pref, cf) = (self.kg, self.pref, &self.cf);
        let b = &mut *self.b;
        let m = b.measure(&from, &anchor, &line, kg, Label::NONE, N_SHEAR_MEASURE);
        let side = if right {
            "shear force V (right of the section)"
        } else {
            "shear force V (left of the section)"
        };
        b.check(&m, side, "kg", "method of sections", pref, || {
            cf.shear(x, !right)
        });
        m.g
    }

    /// The shear diagram: at every event the shear on both sides, laid off from the base
    /// line, and the diagram through the ordinates.
    pub(super) fn shear(&mut self) -> Result<Vec<ShearRow>, ConstructionError> {
        let (base0, base) = self.shear_base()?;
        let events = self.events();
        let depth = Depth::new(self.beam);
        let (mut ordinates, mut rows) = (Vec::new(), Vec::new());
        for (e, &x) in events.iter().enumerate() {
            let (sx, sy) = (self.sx(x), self.sy(0.0));
            let on_beam = b_point(self.b, sx, sy, N_SHEAR_FOOT);
            let down = Vector::new(0.0, -1.0);
            let foot_v = self
                .b
                .line_dir(&on_beam, down, Role::Auxiliary, N_SECTION_VERTICAL)?;
            let foot = self
                .b
                .meet_point(&foot_v, &base, Label::NONE, N_SHEAR_FOOT)?;
            // None outside the ends of the beam.
            let left = if e == 0 {
                0.0
            } else {
                self.shear_at(&depth, x, false)
            };
            let last = e + 1 == events.len();
            let right = if last {
                0.0
            } else {
                self.shear_at(&depth, x, true)
            };
            let up = H {
                id: foot_v.id,
                g: Line {
                    origin: foot.g,
                    dir: Vector::new(0.0, 1.0),
                },
            };
            let fs = self.dr.force_scale;
            for v in [left, right] {
                let o = self
                    .b
                    .lay_off(&foot, &up, v / fs, Role::Construction, N_SHEAR_ORDINATE)?;
                ordinates.push(o);
            }
            rows.push(ShearRow { x, left, right });
        }
        let v = Label::plain("V");
        self.b.curve(
            &ordinates,
            Trace::Polygon,
            Role::Result.labelled(v),
            N_SHEAR_DIAGRAM,
        );
        self.shear_signs(&rows, &ordinates);
        self.shear_diagram = Some(ShearDiagram {
            base0,
            base,
            events,
            rows: rows.clone(),
            ordinates,
        });
        Ok(rows)
    }

    /// The signs of the shear diagram's fields, as LH marks them ("die positiven Querkräfte
    /// (mit + bezeichnet) nach oben …, die negativen (mit − bezeichnet) nach unten", C.5,
    /// Abb. 25): in the middle of each field between two events, halfway up its ordinate,
    /// where the field is wide and high enough for the sign (a heading's 4 mm type).
    fn shear_signs(&mut self, rows: &[ShearRow], ordinates: &[H<Point>]) {
        /// The least width and height (mm) of a field that takes a sign.
        const SIGNED_MM: f64 = 6.0;
        let fs = self.dr.force_scale;
        for (e, pair) in rows.windows(2).enumerate() {
            // The field's two ordinates: right of event e, left of event e + 1; under a
            // distributed load it runs straight between them and may cross the base line,
            // where it is two fields, each signed.
            let (a, b) = (ordinates[2 * e + 1], ordinates[2 * e + 2]);
            let (v0, v1) = (pair[0].right / fs, pair[1].left / fs);
            let (x0, x1) = (self.sx(pair[0].x), self.sx(pair[1].x));
            let base_y = a.g.y - v0;
            let mut parts = vec![(x0, v0, x1, v1)];
            if v0 * v1 < 0.0 {
                let xz = x0 + (x1 - x0) * v0 / (v0 - v1);
                parts = vec![(x0, v0, xz, 0.0), (xz, 0.0, x1, v1)];
            }
            for (xa, va, xb, vb) in parts {
                // At the part's centroid across, halfway up its ordinate there.
                let t = (va.abs() + 2.0 * vb.abs()) / (3.0 * (va.abs() + vb.abs()));
                let (x, v) = (xa + t * (xb - xa), va + t * (vb - va));
                if xb - xa < SIGNED_MM || v.abs() < SIGNED_MM {
                    continue;
                }
                // A heading's text stands 4 mm under its cell's top, some 2.5 mm wide.
                let at = Point::new(x - 1.2, base_y + 0.5 * v + 2.6);
                let sign = if v > 0.0 { "+" } else { "−" };
                let text = vec![vec![sign.to_string()]];
                (self.b).table(at, text, &[a.id, b.id], N_SHEAR_SIGN);
            }
        }
    }

    /// The event at x, if there is one.
    fn event_at(events: &[f64], x: f64, tol_x: f64) -> Option<usize> {
        let i = events.partition_point(|e| *e < x - tol_x);
        (i < events.len() && (events[i] - x).abs() <= tol_x).then_some(i)
    }

    /// The largest |M|, where the shear changes sign: at an event, or inside a uniform load
    /// (its point found on the parabola), checked against the closed form.
    pub(super) fn max_moment(&mut self) -> Result<Option<MaxMoment>, ConstructionError> {
        let d = self
            .shear_diagram
            .take()
            .expect("the shear diagram is drawn first");
        let tol_x = REL_POSITION_EPS * self.span.max(1.0);
        let mut best: Option<(H<f64>, f64)> = None;
        for (s, h) in self.sections.iter().zip(&self.handles) {
            if let Some(e) = Self::event_at(&d.events, s.x, tol_x) {
                if d.rows[e].left * d.rows[e].right <= 0.0 {
                    consider(&mut best, *h, s.x, self.mref);
                }
            }
        }
        for p in self.parabolas.clone() {
            if let Some((m, x0)) = self.parabola_maximum(&d, p, tol_x)? {
                consider(&mut best, m, x0, self.mref);
            }
        }
        let Some((m, x)) = best else {
            return Ok(None);
        };
        // The check is on |M|: where the largest moments are equal and opposite, the
        // construction and the closed form may name either.
        let what = "largest |M|, where the shear changes sign";
        let sections = &self.cf;
        let closed = || sections.max_abs_moment().0.abs();
        let abs = H {
            id: m.id,
            g: m.g.abs(),
        };
        self.b
            .check(&abs, what, "kg·m", "method of sections", self.mref, closed);
        Ok(Some(MaxMoment { moment: m.g, x }))
    }

    /// Where the shear changes sign inside a uniform load: the zero of the shear diagram's
    /// straight stretch on the base line, then the parabola point in the same ratio of both
    /// tangents and their join (LH Abb. 36), and the moment there.
    fn parabola_maximum(
        &mut self,
        d: &ShearDiagram,
        p: Parabola,
        tol_x: f64,
    ) -> Result<Option<(H<f64>, f64)>, ConstructionError> {
        let Kind::Uniform(i) = self.forces[p.force].kind else {
            return Ok(None);
        };
        let u = self.beam.uniform_loads[i];
        let (Some(ea), Some(eb)) = (
            Self::event_at(&d.events, u.from, tol_x),
            Self::event_at(&d.events, u.to, tol_x),
        ) else {
            return Ok(None);
        };
        if d.rows[ea].right * d.rows[eb].left >= 0.0 {
            return Ok(None);
        }
        let (pa, pb) = (d.ordinates[2 * ea + 1], d.ordinates[2 * eb]);
        let metres = Scale::new(1.0 / self.k, "m");
        let b = &mut *self.b;
        let sl = b.line_through(&pa, &pb, Role::Construction, N_SHEAR_ZERO)?;
        let z = b.meet_point(&sl, &d.base, Label::indexed("x", 0), N_SHEAR_ZERO)?;
        let xm = b.measure(&d.base0, &z, &d.base, metres, Label::NONE, N_SHEAR_ZERO_X);
        let x0 = self.beam.ends[0] + xm.g;
        let pp = self.ratio_point(p, (x0 - u.from) / (u.to - u.from))?;
        let vert = self.section_vertical(&pp);
        let down = H {
            id: vert.id,
            g: Line {
                origin: vert.g.origin,
                dir: Vector::new(0.0, -1.0),
            },
        };
        let m = self.moment_at(x0, &pp, &down)?;
        self.push_section(x0, format!("q{} max", i + 1), m);
        Ok(Some((m, x0)))
    }

    /// The parabola point at the ratio t of a uniform load: t laid off on both tangents, their
    /// join, and t laid off on the join (the same ratio, LH Abb. 36).
    fn ratio_point(&mut self, p: Parabola, t: f64) -> Result<H<Point>, ConstructionError> {
        let (t1, d, t2) = (p.t1, p.corner, p.t2);
        let (con, aux) = (Role::Construction, Role::Auxiliary);
        let b = &mut *self.b;
        let l1 = b.line_through(&t1, &d, aux, N_RATIO_1)?;
        let q1 = b.lay_off(&t1, &l1, t * (d.g - t1.g).norm(), con, N_RATIO_1)?;
        let l2 = b.line_through(&d, &t2, aux, N_RATIO_2)?;
        let q2 = b.lay_off(&d, &l2, t * (t2.g - d.g).norm(), con, N_RATIO_2)?;
        let lj = b.line_through(&q1, &q2, con, N_RATIO_JOIN)?;
        let len = t * (q2.g - q1.g).norm();
        b.lay_off(&q1, &lj, len, con.named("M"), N_RATIO_POINT)
    }
}

/// Keeps the larger |M|; a tie within the relative tolerance keeps the first found.
fn consider(best: &mut Option<(H<f64>, f64)>, m: H<f64>, x: f64, mref: f64) {
    let tie = crate::kernel::tolerance::REL_TIE_EPS * mref;
    if best.is_none_or(|(bm, _)| m.g.abs() > bm.g.abs() + tie) {
        *best = Some((m, x));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statics::{Beam, PointLoad, UniformLoad};

    #[test]
    fn depth_counts_point_loads_at_the_section_only_on_its_right() {
        let beam = Beam {
            supports: [0.0, 10.0],
            ends: [0.0, 10.0],
            point_loads: vec![PointLoad { x: 2.0, p: 1.0 }, PointLoad { x: 7.0, p: 1.0 }],
            uniform_loads: vec![UniformLoad {
                from: 3.0,
                to: 5.0,
                q: 1.0,
            }],
        };
        let d = Depth::new(&beam);
        assert_eq!(d.index(2.0, false), 0);
        assert_eq!(d.index(2.0, true), 1);
        assert_eq!(d.index(4.0, true), 1); // inside the uniform load: not passed yet
        assert_eq!(d.index(5.0, false), 2); // its end passed: V is continuous there
        assert_eq!(d.index(9.0, true), 3);
    }

    #[test]
    fn a_tie_keeps_the_first_largest_moment() {
        let h = |g: f64| H {
            id: crate::protocol::ObjId::NONE,
            g,
        };
        let mut best = None;
        consider(&mut best, h(100.0), 1.0, 100.0);
        consider(&mut best, h(-100.0 - 1e-11), 2.0, 100.0);
        assert_eq!(best.map(|(_, x)| x), Some(1.0));
        consider(&mut best, h(-101.0), 3.0, 100.0);
        assert_eq!(best.map(|(_, x)| x), Some(3.0));
    }
}
