//! The moment area M = y·H (LH C.5, Gl. 11): the ordinate from the funicular polygon to the
//! closing line (to the outer string on an overhang), the parabola of a uniform load by its
//! tangents (Abb. 36), sections asked for, and the zero moments.

use super::build::{BeamConstruction, Kind, Parabola};
use super::notes::*;
use super::types::SectionRow;
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{ConstructionError, Cut, Label, Role, Scale, Trace, H};

impl BeamConstruction<'_, '_> {
    /// How many forces of the polygon lie left of x: the string active at x.
    pub(super) fn string_at(&self, x: f64) -> usize {
        self.forces.iter().filter(|f| f.x < x).count()
    }

    /// The line the moment at x is measured to: the closing line between the supports, the
    /// first or last string on an overhang (the undercut moment area of LH Abb. 34).
    fn reference_at(&self, x: f64) -> H<Line> {
        let (_, _, f) = self.drawn();
        if x < self.beam.supports[0] {
            f.strings[0]
        } else if x > self.beam.supports[1] {
            f.strings[f.strings.len() - 1]
        } else {
            self.reactions_drawn().closing
        }
    }

    /// The moment at x: the ordinate from the polygon point `poly` on `vertical` to the
    /// reference line, measured at the moment scale (H times the ordinate) and checked by the
    /// method of sections.
    pub(super) fn moment_at(
        &mut self,
        x: f64,
        poly: &H<Point>,
        vertical: &H<Line>,
    ) -> Result<H<f64>, ConstructionError> {
        let refl = self.reference_at(x);
        let (scale, mref, cf) = (self.moment_scale, self.mref, &self.cf);
        let b = &mut *self.b;
        let z = b.meet_point(&refl, vertical, Label::NONE, N_REF_AT)?;
        b.segment(poly, &z, Role::Construction, N_ORDINATE);
        let up = H {
            id: vertical.id,
            g: Line {
                origin: vertical.g.origin,
                dir: Vector::new(0.0, 1.0),
            },
        };
        let m = b.measure(poly, &z, &up, scale, Label::NONE, N_MOMENT);
        let formula = "LH Gl. 11; method of sections";
        b.check(
            &m,
            "bending moment M = y·H",
            "kg·m",
            formula,
            mref,
            || cf.moment(x),
        );
        Ok(m)
    }

    /// Records a section's moment.
    pub(super) fn push_section(&mut self, x: f64, what: String, m: H<f64>) {
        self.sections.push(SectionRow {
            x,
            what,
            moment: m.g,
        });
        self.handles.push(m);
    }

    /// The moments at the supports, under the point loads, and along each uniform load's
    /// parabola.
    pub(super) fn moment_area(&mut self) -> Result<(), ConstructionError> {
        let r = self.reactions()?;
        let sv = self.drawn().0.support_verticals.clone();
        for (i, vertical) in sv.iter().enumerate() {
            let x = self.beam.supports[i];
            let kstr = self.string_at(x);
            let poly = if kstr == 0 && i == 0 {
                r.ia
            } else {
                let s = self.drawn().2.strings[kstr];
                self.b.meet_point(&s, vertical, Label::NONE, N_POLY_AT)?
            };
            let m = self.moment_at(x, &poly, vertical)?;
            self.push_section(x, if i == 0 { "A" } else { "B" }.into(), m);
        }
        for j in 0..self.forces.len() {
            let f = self.forces[j];
            match f.kind {
                Kind::Point(i) => {
                    let (corner, vertical) =
                        (self.drawn().2.corners[j], self.drawn().0.verticals[j]);
                    let m = self.moment_at(f.x, &corner, &vertical)?;
                    // "P" and the load's number, without the formatting machinery: a
                    // beam of a million loads names a million sections.
                    let mut what = String::with_capacity(8);
                    what.push('P');
                    crate::fmt::push_uint_padded(
                        &mut what,
                        u64::from(self.first_load) + i as u64 + 1,
                        1,
                    );
                    self.push_section(f.x, what, m);
                }
                Kind::Uniform(i) => self.parabola(j, i)?,
            }
        }
        Ok(())
    }

    /// Uniform load `i` (force `j` of the polygon): the two tangent points where the strings
    /// before and after it cut the verticals of its ends, both tangents divided into equal
    /// parts, the joins 1–1, 2–2, … (tangents of the parabola) each touched at the point
    /// dividing it in the same ratio (LH Abb. 36); the moment at each parabola point.
    fn parabola(&mut self, j: usize, i: usize) -> Result<(), ConstructionError> {
        let (va, vb) = self.drawn().0.end_verticals[i];
        let (sj, sk, corner) = {
            let f = self.drawn().2;
            (f.strings[j], f.strings[j + 1], f.corners[j])
        };
        let m = self.dr.parabola_divisions.max(2);
        let b = &mut *self.b;
        let t1 = b.meet_point(&sj, &va, Label::quiet("T", 2 * i as u32), N_TANGENT_POINT)?;
        let t2 = b.meet_point(
            &sk,
            &vb,
            Label::quiet("T", 2 * i as u32 + 1),
            N_TANGENT_POINT,
        )?;
        let d1 = b.divide_segment(&t1, &corner, m, "t", N_DIVIDE_TANGENT);
        let d2 = b.divide_segment(&corner, &t2, m, "u", N_DIVIDE_TANGENT);
        let mut points = vec![t1];
        for kk in 1..m {
            let join = b.line_through(&d1[kk], &d2[kk], Role::Construction, N_ENVELOPE)?;
            let len = (d2[kk].g - d1[kk].g).norm() * kk as f64 / m as f64;
            points.push(b.lay_off(&d1[kk], &join, len, Role::Construction, N_TOUCH)?);
        }
        points.push(t2);
        b.curve(&points, Trace::Smooth, Role::Result, N_PARABOLA);
        let u = self.beam.uniform_loads[i];
        for (kk, pt) in points.iter().enumerate() {
            let x = u.from + (u.to - u.from) * kk as f64 / m as f64;
            let vert = if kk == 0 {
                va
            } else if kk == m {
                vb
            } else {
                self.section_vertical(pt)
            };
            let mm = self.moment_at(x, pt, &down(vert))?;
            self.push_section(x, format!("q{} {kk}/{m}", i + 1), mm);
        }
        self.parabolas.push(Parabola {
            force: j,
            t1,
            corner,
            t2,
        });
        Ok(())
    }

    /// The vertical through a point of the moment area, dropped on the beam axis.
    pub(super) fn section_vertical(&mut self, pt: &H<Point>) -> H<Line> {
        let axis = self.drawn().0.axis;
        self.b
            .perpendicular(&axis, pt, Role::Auxiliary, N_SECTION_VERTICAL)
    }

    /// The moment at a section asked for besides the loads and supports (LH Abb. 24, section
    /// C): a vertical through it cuts the polygon. Nothing is drawn where a support, a point
    /// load or an earlier section is there already.
    pub(super) fn section(&mut self, x: f64) -> Result<(), ConstructionError> {
        let tol_x = crate::kernel::tolerance::REL_POSITION_EPS * self.span.max(1.0);
        let known = self.beam.supports.iter().any(|s| (s - x).abs() <= tol_x)
            || self
                .forces
                .iter()
                .any(|f| matches!(f.kind, Kind::Point(_)) && (f.x - x).abs() <= tol_x)
            || self.sections.iter().any(|s| (s.x - x).abs() <= tol_x);
        if known {
            return Ok(());
        }
        let at = Point::new(self.sx(x), self.sy(0.0));
        let s = self.drawn().2.strings[self.string_at(x)];
        let b = &mut *self.b;
        let on = b.point(
            at,
            Role::Given.labelled(Label::quiet("x", 0)),
            N_SECTION_VERTICAL,
        );
        let d = Vector::new(0.0, -1.0);
        let vertical = b.line_dir(&on, d, Role::Auxiliary, N_SECTION_VERTICAL)?;
        let poly = b.meet_point(&s, &vertical, Label::NONE, N_POLY_AT)?;
        let m = self.moment_at(x, &poly, &vertical)?;
        self.push_section(x, "x".into(), m);
        Ok(())
    }

    /// The zero moments between the supports: where a string of the polygon cuts the closing
    /// line inside its own stretch (not over a uniform load, where the parabola is the moment
    /// line), read off and checked against the interpolated zero of the linear M.
    pub(super) fn zero_moments(&mut self) -> Result<(), ConstructionError> {
        let n = self.forces.len();
        // The uniform loads by their starts; they do not overlap (the layout was checked), so
        // their ends come in the same order, and the first that ends after `lo` is the only
        // one that may reach into a stretch (lo, hi).
        let mut spans: Vec<(f64, f64)> = (self.beam.uniform_loads.iter())
            .map(|u| (u.from, u.to))
            .collect();
        spans.sort_by(|a, b| a.0.total_cmp(&b.0));
        let loaded = |lo: f64, hi: f64| {
            let k = spans.partition_point(|s| s.1 <= lo);
            spans.get(k).is_some_and(|s| s.0 < hi)
        };
        for kstr in 0..=n {
            let lo = if kstr == 0 {
                f64::NEG_INFINITY
            } else {
                self.forces[kstr - 1].x
            };
            let hi = if kstr == n {
                f64::INFINITY
            } else {
                self.forces[kstr].x
            };
            let (lo, hi) = (lo.max(self.beam.supports[0]), hi.min(self.beam.supports[1]));
            if lo >= hi || loaded(lo, hi) {
                continue;
            }
            self.zero_moment_on(kstr, lo, hi);
        }
        Ok(())
    }

    /// The zero moment of string `kstr` on its stretch `(lo, hi)`, if it crosses the closing
    /// line there.
    fn zero_moment_on(&mut self, kstr: usize, lo: f64, hi: f64) {
        let string = self.drawn().2.strings[kstr];
        let (left, axis) = (self.drawn().0.left, self.drawn().0.axis);
        let closing = self.reactions_drawn().closing;
        // Where would they cross? Only a crossing inside the stretch is drawn.
        let inside =
            match crate::kernel::intersect_line_line(&string.g, &closing.g, &self.b.tolerance()) {
                crate::kernel::LineLine::Point { point, .. } => {
                    let x = (point.x - self.dr.origin.x) / self.k;
                    let eps = crate::kernel::tolerance::REL_STRETCH_EPS * self.span;
                    x > lo + eps && x < hi - eps
                }
                _ => false,
            };
        if !inside {
            return;
        }
        let Cut::Point(p, _) = self.b.meet(&string, &closing, Label::NONE, N_INFLECTION) else {
            return;
        };
        let metres = Scale::new(1.0 / self.k, "m");
        let xm = self
            .b
            .measure(&left, &p, &axis, metres, Label::NONE, N_INFLECTION_X);
        let x0 = xm.g + self.beam.ends[0];
        // M is linear on this stretch: its zero by interpolation.
        let closed = || {
            let (mlo, mhi) = (self.cf.moment(lo), self.cf.moment(hi));
            lo - mlo * (hi - lo) / (mhi - mlo)
        };
        let xm = H { id: xm.id, g: x0 };
        let what = "position of the zero moment";
        self.b
            .check(&xm, what, "m", "method of sections", self.span, closed);
        self.zero_moments.push(x0);
    }
}

/// A vertical turned to point down, the sense the moments are measured from.
fn down(vert: H<Line>) -> H<Line> {
    H {
        id: vert.id,
        g: Line {
            origin: vert.g.origin,
            dir: Vector::new(0.0, -1.0),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::super::types::BeamDrawing;
    use super::*;
    use crate::protocol::Board;
    use crate::statics::{Beam, PointLoad};

    fn run(f: impl FnOnce(&mut BeamConstruction)) {
        let bm = Beam {
            supports: [0.0, 6.0],
            ends: [0.0, 6.0],
            point_loads: vec![PointLoad { x: 2.0, p: 600.0 }],
            uniform_loads: vec![],
        };
        let dr = BeamDrawing {
            length_scale: 50.0,
            force_scale: 20.0,
            pole_distance: 500.0,
            parabola_divisions: 4,
            origin: Point::origin(),
        };
        let mut b = Board::recording();
        let mut c = BeamConstruction::new(&mut b, &bm, &dr);
        c.reactions().unwrap();
        f(&mut c);
        assert!(c.b.all_passed());
    }

    #[test]
    fn the_string_at_a_section_counts_the_loads_left_of_it() {
        run(|c| {
            assert_eq!(c.string_at(1.0), 0);
            assert_eq!(c.string_at(2.0), 0); // at the load: the string before it
            assert_eq!(c.string_at(2.5), 1);
        });
    }

    #[test]
    fn a_section_is_measured_once_and_checked() {
        run(|c| {
            c.moment_area().unwrap();
            let before = c.sections.len();
            c.section(4.0).unwrap();
            c.section(4.0).unwrap(); // known now: nothing drawn
            c.section(2.0).unwrap(); // the load's own section
            assert_eq!(c.sections.len(), before + 1);
            let s = c.sections.last().unwrap();
            // M(4) = B·2 = 200·2 kg·m.
            assert!((s.moment - 400.0).abs() < 1e-9, "{}", s.moment);
        });
    }

    #[test]
    fn no_zero_moment_inside_a_simple_beam_under_one_load() {
        run(|c| {
            c.moment_area().unwrap();
            c.zero_moments().unwrap();
            assert!(c.zero_moments.is_empty());
        });
    }
}
