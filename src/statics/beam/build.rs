//! The demand-driven construction of a beam: each part (position plan, force plan, funicular
//! polygon, reactions, moments, parabolas, shear) is built once, when something needs it.

use super::notes::*;
use super::types::{
    BeamDrawing, BeamResults, MaxMoment, Reactions, SectionRow, ShearRow, ARROW_MM, GAP_MM,
    SUPPORT_MM,
};
use crate::kernel::{Line, Point, Vector};
use crate::protocol::{Board, ConstructionError, Label, Role, Scale, Trace, H};
use crate::statics::closed_form as cf;
use crate::statics::funicular::polygon::{self, StringStyle};
use crate::statics::Beam;

/// A force of the funicular polygon: a point load, or a uniform load by its resultant.
#[derive(Clone, Copy)]
pub(super) enum Kind {
    Point(usize),
    Uniform(usize),
}

/// A force of the polygon on its line of action (m), with its load (kg, down positive).
#[derive(Clone, Copy)]
pub(super) struct Force {
    pub(super) x: f64,
    pub(super) p: f64,
    pub(super) kind: Kind,
}

/// The verticals through the two ends of a uniform load.
pub(super) type EndVerticals = (H<Line>, H<Line>);

/// The beam drawn to scale with its supports, loads and their verticals (Lageplan).
pub(super) struct Plan {
    pub(super) left: H<Point>,
    pub(super) axis: H<Line>,
    pub(super) supports: Vec<H<Point>>,
    pub(super) support_verticals: Vec<H<Line>>,
    /// The vertical of each force of the polygon, in the order of the forces.
    pub(super) verticals: Vec<H<Line>>,
    /// The verticals through the ends of each uniform load.
    pub(super) end_verticals: Vec<EndVerticals>,
}

/// The load line with the loads laid off, the pole and its rays (Kräfteplan).
pub(super) struct ForcePlan {
    pub(super) load_line: H<Line>,
    /// Corner k of the load line: after the first k forces.
    pub(super) pts: Vec<H<Point>>,
    pub(super) pole: H<Point>,
    pub(super) rays: Vec<H<Line>>,
}

/// The funicular polygon: its start, strings and corners on the verticals.
pub(super) struct Funicular {
    pub(super) start: H<Point>,
    pub(super) strings: Vec<H<Line>>,
    pub(super) corners: Vec<H<Point>>,
}

/// The closing line, the point C it gives on the load line, and the reactions.
#[derive(Clone, Copy)]
pub(super) struct Reacted {
    pub(super) ia: H<Point>,
    pub(super) ib: H<Point>,
    pub(super) closing: H<Line>,
    pub(super) c: H<Point>,
    pub(super) values: Reactions,
}

/// A uniform load's parabola: its force index, the two tangent points and the polygon corner
/// between them.
#[derive(Clone, Copy)]
pub(super) struct Parabola {
    pub(super) force: usize,
    pub(super) t1: H<Point>,
    pub(super) corner: H<Point>,
    pub(super) t2: H<Point>,
}

/// The drawn shear diagram, kept for the largest moment.
pub(super) struct ShearDiagram {
    pub(super) base0: H<Point>,
    pub(super) base: H<Line>,
    /// The events (m), ordered: ends, supports, point loads, ends of uniform loads.
    pub(super) events: Vec<f64>,
    /// The shear on both sides of each event.
    pub(super) rows: Vec<ShearRow>,
    /// Two ordinate ends per event: left, then right of it.
    pub(super) ordinates: Vec<H<Point>>,
}

/// A beam's construction on a board, built part by part on demand.
pub(super) struct BeamConstruction<'a, 'b> {
    pub(super) b: &'b mut Board,
    pub(super) beam: &'a Beam,
    pub(super) dr: &'a BeamDrawing,
    /// Sheet mm per m of beam.
    pub(super) k: f64,
    pub(super) kg: Scale,
    pub(super) moment_scale: Scale,
    pub(super) ra: f64,
    pub(super) rb: f64,
    pub(super) cf: cf::Sections<'a>,
    pub(super) total: f64,
    /// The largest load or reaction: the reference of the force checks.
    pub(super) pref: f64,
    pub(super) span: f64,
    /// `pref × span`: the reference of the moment checks.
    pub(super) mref: f64,
    pub(super) forces: Vec<Force>,
    plan: Option<Plan>,
    force_plan: Option<ForcePlan>,
    funicular: Option<Funicular>,
    reacted: Option<Reacted>,
    pub(super) sections: Vec<SectionRow>,
    /// The measured moment of each section, to attach further checks to.
    pub(super) handles: Vec<H<f64>>,
    pub(super) zero_moments: Vec<f64>,
    pub(super) parabolas: Vec<Parabola>,
    pub(super) shear_diagram: Option<ShearDiagram>,
    /// The number of the first point load less one: a shaft's second plane goes on from the
    /// first's (LH Abb. 26: P₁ in one plane, P₂ in the other).
    pub(super) first_load: u32,
}

impl<'a, 'b> BeamConstruction<'a, 'b> {
    /// The closed forms and scales of the beam; nothing is drawn yet.
    pub(super) fn new(b: &'b mut Board, beam: &'a Beam, dr: &'a BeamDrawing) -> Self {
        let (ra, rb) = cf::reactions(beam);
        let total: f64 = beam.point_loads.iter().map(|l| l.p).sum::<f64>()
            + beam
                .uniform_loads
                .iter()
                .map(|u| u.resultant())
                .sum::<f64>();
        let pref = beam
            .point_loads
            .iter()
            .map(|l| l.p.abs())
            .chain(beam.uniform_loads.iter().map(|u| u.resultant().abs()))
            .fold(0.0, f64::max)
            .max(ra.abs())
            .max(rb.abs());
        let span = beam.ends[1] - beam.ends[0];
        BeamConstruction {
            b,
            beam,
            dr,
            k: 1000.0 / dr.length_scale,
            kg: Scale::kg(dr.force_scale),
            moment_scale: Scale::new(dr.length_scale / 1000.0 * dr.pole_distance, "kg·m"),
            ra,
            rb,
            cf: cf::Sections::new(beam),
            total,
            pref,
            span,
            mref: pref * span,
            forces: polygon_forces(beam),
            plan: None,
            force_plan: None,
            funicular: None,
            reacted: None,
            sections: Vec::new(),
            handles: Vec::new(),
            zero_moments: Vec::new(),
            parabolas: Vec::new(),
            shear_diagram: None,
            first_load: 0,
        }
    }

    /// Sheet x of the beam's x (m).
    pub(super) fn sx(&self, x: f64) -> f64 {
        x * self.k + self.dr.origin.x
    }

    /// Sheet y of a height above the beam (mm).
    pub(super) fn sy(&self, y: f64) -> f64 {
        y + self.dr.origin.y
    }

    /// The position plan, drawn on first demand.
    pub(super) fn plan(&mut self) -> Result<&Plan, ConstructionError> {
        if self.plan.is_none() {
            let p = self.draw_plan()?;
            self.plan = Some(p);
        }
        Ok(self.plan.as_ref().expect("just drawn"))
    }

    fn draw_plan(&mut self) -> Result<Plan, ConstructionError> {
        let (beam, y0) = (self.beam, self.sy(0.0));
        let (x0, x1) = (self.sx(beam.ends[0]), self.sx(beam.ends[1]));
        let b = &mut *self.b;
        let left = b.point(Point::new(x0, y0), Role::Given, N_BEAM_START);
        let axis = b.line_dir(&left, Vector::new(1.0, 0.0), Role::Axis, N_BEAM_AXIS)?;
        let right = b.point(Point::new(x1, y0), Role::Given, N_BEAM_END);
        b.segment(&left, &right, Role::Result, N_BEAM);
        let mut supports = Vec::new();
        let mut support_verticals = Vec::new();
        for (i, &x) in beam.supports.iter().enumerate() {
            let (p, v) = self.draw_support(i, x)?;
            supports.push(p);
            support_verticals.push(v);
        }
        let mut verticals = Vec::with_capacity(self.forces.len());
        let mut end_verticals = Vec::new();
        for j in 0..self.forces.len() {
            let (v, ends) = self.draw_load(j)?;
            verticals.push(v);
            end_verticals.extend(ends);
        }
        Ok(Plan {
            left,
            axis,
            supports,
            support_verticals,
            verticals,
            end_verticals,
        })
    }

    /// Support A (`i = 0`) or B at x: its point, symbol and vertical.
    fn draw_support(&mut self, i: usize, x: f64) -> Result<(H<Point>, H<Line>), ConstructionError> {
        let name = if i == 0 { "A" } else { "B" };
        let (xs, y0, yl) = (self.sx(x), self.sy(0.0), self.sy(-1.5));
        let b = &mut *self.b;
        let p = b.point(
            Point::new(xs, y0),
            Role::Given.labelled(Label::plain(name)),
            N_SUPPORT,
        );
        let l = b_point(b, xs - SUPPORT_MM, yl, N_SUPPORT_SYMBOL);
        let r = b_point(b, xs + SUPPORT_MM, yl, N_SUPPORT_SYMBOL);
        b.segment(&l, &r, Role::Guide, N_SUPPORT_SYMBOL);
        let down = Vector::new(0.0, -1.0);
        let v = b.line_dir(&p, down, Role::Construction, N_SUPPORT_VERTICAL)?;
        Ok((p, v))
    }

    /// Force `j` of the polygon drawn at its place: a point load's arrow, or a uniform load's
    /// outline, resultant and end verticals; then its vertical.
    fn draw_load(
        &mut self,
        j: usize,
    ) -> Result<(H<Line>, Option<EndVerticals>), ConstructionError> {
        let f = self.forces[j];
        let (xs, y0) = (self.sx(f.x), self.sy(0.0));
        let down = Vector::new(0.0, -1.0);
        let at = self.b.point(
            Point::new(xs, y0),
            Role::Given.labelled(Label::quiet("L", j as u32 + 1)),
            N_LOAD,
        );
        let ends = match f.kind {
            Kind::Point(i) => {
                let y = self.sy(ARROW_MM * f.p.signum());
                let b = &mut *self.b;
                let label = Label::indexed("P", self.first_load + i as u32 + 1);
                let tail = b.point(Point::new(xs, y), Role::Given.labelled(label), N_LOAD_ARROW);
                b.segment(&tail, &at, Role::Force, N_LOAD_ARROW);
                None
            }
            Kind::Uniform(i) => Some(self.draw_uniform(i, &at)?),
        };
        let v = self
            .b
            .line_dir(&at, down, Role::Construction, N_LOAD_VERTICAL)?;
        Ok((v, ends))
    }

    /// Uniform load `i`: its outline, its resultant Q at `at`, the verticals of its ends.
    fn draw_uniform(
        &mut self,
        i: usize,
        at: &H<Point>,
    ) -> Result<(H<Line>, H<Line>), ConstructionError> {
        let u = self.beam.uniform_loads[i];
        let hgt = 0.5 * ARROW_MM;
        let (xa, xb, y0, yh) = (self.sx(u.from), self.sx(u.to), self.sy(0.0), self.sy(hgt));
        let corners = [
            Point::new(xa, y0),
            Point::new(xa, yh),
            Point::new(xb, yh),
            Point::new(xb, y0),
        ];
        let outline: Vec<H<Point>> = corners
            .iter()
            .map(|c| H {
                id: crate::protocol::ObjId::NONE,
                g: *c,
            })
            .collect();
        let ytail = self.sy(ARROW_MM * 1.4);
        let b = &mut *self.b;
        let a = b.point(corners[0], Role::Given, N_UNIFORM);
        let bb = b.point(corners[3], Role::Given, N_UNIFORM);
        let q = Label::indexed("q", i as u32 + 1);
        b.curve(&outline, Trace::Polygon, Role::Given.labelled(q), N_UNIFORM);
        let label = Label::indexed("Q", i as u32 + 1);
        let tail = b.point(
            Point::new(at.g.x, ytail),
            Role::Given.labelled(label),
            N_UNIFORM_RESULTANT,
        );
        b.segment(&tail, at, Role::Auxiliary, N_UNIFORM_RESULTANT);
        let down = Vector::new(0.0, -1.0);
        let va = b.line_dir(&a, down, Role::Construction, N_END_VERTICAL)?;
        let vb = b.line_dir(&bb, down, Role::Construction, N_END_VERTICAL)?;
        Ok((va, vb))
    }

    /// The force plan: the loads laid off on the load line, the pole at the pole distance H
    /// right of it at mid-height of the loads (so that the polygon sags), and its rays.
    pub(super) fn force_plan(&mut self) -> Result<&ForcePlan, ConstructionError> {
        if self.force_plan.is_none() {
            self.plan()?;
            let p = self.draw_force_plan()?;
            self.force_plan = Some(p);
        }
        Ok(self.force_plan.as_ref().expect("just drawn"))
    }

    fn draw_force_plan(&mut self) -> Result<ForcePlan, ConstructionError> {
        let fs = self.dr.force_scale;
        let total_mm = self.forces.iter().map(|f| f.p.abs()).sum::<f64>() / fs;
        let x_fp = self.sx(self.beam.ends[1]) + GAP_MM;
        let top = self.sy(0.5 * total_mm);
        let b = &mut *self.b;
        let p0 = b.point(
            Point::new(x_fp, top),
            Role::Given.named("0"),
            N_LOAD_LINE_START,
        );
        let down = Vector::new(0.0, -1.0);
        let load_line = b.line_dir(&p0, down, Role::Construction, N_LOAD_LINE)?;
        let mut pts = vec![p0];
        for (j, f) in self.forces.iter().enumerate() {
            let label = Label::indexed("", j as u32 + 1);
            let next = b.lay_off(
                &pts[j],
                &load_line,
                f.p / fs,
                Role::Force.labelled(label),
                N_LAY_OFF,
            )?;
            pts.push(next);
        }
        let pole_at = Point::new(
            x_fp + self.dr.pole_distance / fs,
            top - 0.5 * self.total / fs,
        );
        let polygon::Rays { pole, rays } = polygon::pole_and_rays(b, pole_at, &pts)?;
        Ok(ForcePlan {
            load_line,
            pts,
            pole,
            rays,
        })
    }

    /// The funicular polygon below the beam, from the leftmost vertical (support or load).
    pub(super) fn funicular(&mut self) -> Result<&Funicular, ConstructionError> {
        if self.funicular.is_none() {
            let rays = self.force_plan()?.rays.clone();
            let verticals = self.plan()?.verticals.clone();
            let y_f = self.sy(-(GAP_MM + 0.5 * ARROW_MM));
            let x_first = self
                .forces
                .first()
                .map_or(self.beam.supports[0], |f| f.x)
                .min(self.beam.supports[0]);
            let start = self.b.point(
                Point::new(self.sx(x_first), y_f),
                Role::Given.named("I"),
                N_START,
            );
            // A load left of A (an overhang) has the polygon start on its own vertical: the
            // start is the first corner, I, not a point of its own beside it.
            let on_first = (self.forces.first()).is_some_and(|f| f.x <= self.beam.supports[0]);
            let style = StringStyle::RESULT;
            let s = polygon::strings(self.b, &rays, &start, on_first, style, |_, j| {
                Ok(verticals[j])
            })?;
            self.funicular = Some(Funicular {
                start,
                strings: s.strings,
                corners: s.corners,
            });
        }
        Ok(self.funicular.as_ref().expect("just drawn"))
    }

    /// The closing line from the first string on vertical A to the last on vertical B, its
    /// parallel through the pole cutting the load line in C, and the reactions A = 0C and
    /// B = Cn read off and drawn at the supports (LH C.4, Abb. 24).
    pub(super) fn reactions(&mut self) -> Result<Reacted, ConstructionError> {
        if let Some(r) = self.reacted {
            return Ok(r);
        }
        let (first, last) = {
            let f = self.funicular()?;
            (f.strings[0], f.strings[f.strings.len() - 1])
        };
        let (sv, supports) = {
            let p = self.plan()?;
            (p.support_verticals.clone(), p.supports.clone())
        };
        let (load_line, p0, pn, pole) = {
            let fp = self.force_plan()?;
            (fp.load_line, fp.pts[0], fp.pts[fp.pts.len() - 1], fp.pole)
        };
        // The last string's cut with B's vertical is the polygon's last corner (LH Abb. 24's
        // V, after I on A's and one on each load's) where every load stands before B; the
        // first string's cut with A's is I itself where no load stands before A.
        let n = self.forces.len();
        let b_last = self.forces.iter().all(|f| f.x < self.beam.supports[1]);
        let on_first = (self.forces.first()).is_some_and(|f| f.x <= self.beam.supports[0]);
        let ib_name = match b_last {
            true => Label::named(polygon::roman(n + 1 + usize::from(!on_first))),
            false => Label::quiet("IB", 0),
        };
        let b = &mut *self.b;
        let ia = b.meet_point(&first, &sv[0], Label::quiet("IA", 0), N_END_STRING_CUT)?;
        let ib = b.meet_point(&last, &sv[1], ib_name, N_END_STRING_CUT)?;
        let s = (Label::plain("s"), Role::Given);
        let cl = polygon::closing(b, &ia, &ib, &pole, s, n + 1, Role::Auxiliary)?;
        let c = b.meet_point(&cl.ray, &load_line, Label::plain("C"), N_C)?;
        let kg = self.kg;
        let a_val = b.measure(&p0, &c, &load_line, kg, Label::quiet("A", 0), N_REACTION_A);
        let (ra, rb, pref) = (self.ra, self.rb, self.pref);
        b.check(&a_val, "reaction A", "kg", "ΣM_B = 0", pref, || ra);
        let b_val = b.measure(&c, &pn, &load_line, kg, Label::quiet("B", 0), N_REACTION_B);
        b.check(&b_val, "reaction B", "kg", "ΣV = 0", pref, || rb);
        for (i, s) in supports.iter().enumerate() {
            let r = if i == 0 { a_val.g } else { b_val.g };
            let len = ARROW_MM * r.signum();
            let tail = b.lay_off(s, &sv[i], len, Role::Construction, N_REACTION_ARROW)?;
            b.segment(&tail, s, Role::Force, N_REACTION_ARROW);
        }
        let r = Reacted {
            ia,
            ib,
            closing: cl.line,
            c,
            values: Reactions {
                a: a_val.g,
                b: b_val.g,
            },
        };
        self.reacted = Some(r);
        Ok(r)
    }

    /// The reactions, once drawn (every part after them reads them here).
    pub(super) fn reactions_drawn(&self) -> Reacted {
        self.reacted.expect("the reactions are drawn first")
    }

    /// Parts already drawn, for the later parts (each is drawn before it is read here).
    pub(super) fn drawn(&self) -> (&Plan, &ForcePlan, &Funicular) {
        (
            self.plan.as_ref().expect("drawn first"),
            self.force_plan.as_ref().expect("drawn first"),
            self.funicular.as_ref().expect("drawn first"),
        )
    }

    /// The results, the sections ordered by x.
    pub(super) fn finish(
        self,
        reactions: Reactions,
        shear: Vec<ShearRow>,
        max_moment: Option<MaxMoment>,
    ) -> BeamResults {
        let mut order: Vec<usize> = (0..self.sections.len()).collect();
        order.sort_by(|&i, &j| self.sections[i].x.total_cmp(&self.sections[j].x));
        BeamResults {
            reactions,
            sections: order.iter().map(|&i| self.sections[i].clone()).collect(),
            zero_moments: self.zero_moments,
            shear,
            max_moment,
            moment_handles: order.iter().map(|&i| self.handles[i]).collect(),
        }
    }
}

/// The forces of the polygon by their lines of action: point loads, and uniform loads by
/// their resultants at their middles, ordered by x.
fn polygon_forces(beam: &Beam) -> Vec<Force> {
    let mut forces: Vec<Force> = beam
        .point_loads
        .iter()
        .enumerate()
        .map(|(i, l)| Force {
            x: l.x,
            p: l.p,
            kind: Kind::Point(i),
        })
        .chain(beam.uniform_loads.iter().enumerate().map(|(i, u)| Force {
            x: u.centre(),
            p: u.resultant(),
            kind: Kind::Uniform(i),
        }))
        .collect();
    forces.sort_by(|a, b| a.x.total_cmp(&b.x));
    forces
}

/// A given point of the figure, unnamed.
pub(super) fn b_point(b: &mut Board, x: f64, y: f64, note: crate::protocol::Note) -> H<Point> {
    b.point(
        Point::new(x, y),
        crate::protocol::Role::Given.labelled(crate::protocol::Label::NONE),
        note,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::statics::{PointLoad, UniformLoad};

    fn beam() -> Beam {
        Beam {
            supports: [0.0, 6.0],
            ends: [0.0, 8.0],
            point_loads: vec![
                PointLoad { x: 2.0, p: 600.0 },
                PointLoad { x: 8.0, p: 100.0 },
            ],
            uniform_loads: vec![UniformLoad {
                from: 3.0,
                to: 5.0,
                q: 200.0,
            }],
        }
    }

    fn drawing() -> BeamDrawing {
        BeamDrawing {
            length_scale: 50.0,
            force_scale: 20.0,
            pole_distance: 500.0,
            parabola_divisions: 4,
            origin: Point::new(10.0, -5.0),
        }
    }

    #[test]
    fn the_forces_of_the_polygon_are_ordered_by_their_lines_of_action() {
        let f = polygon_forces(&beam());
        let xs: Vec<f64> = f.iter().map(|f| f.x).collect();
        assert_eq!(xs, [2.0, 4.0, 8.0]); // the uniform load at its middle
        assert!(matches!(f[1].kind, Kind::Uniform(0)) && f[1].p == 400.0);
    }

    #[test]
    fn each_part_is_drawn_once_however_often_it_is_asked_for() {
        let (bm, dr) = (beam(), drawing());
        let mut b = Board::recording();
        let mut c = BeamConstruction::new(&mut b, &bm, &dr);
        let first = c.reactions().unwrap();
        let steps = c.b.steps().len();
        let again = c.reactions().unwrap();
        c.funicular().unwrap();
        c.force_plan().unwrap();
        c.plan().unwrap();
        assert_eq!(c.b.steps().len(), steps);
        assert_eq!(first.values, again.values);
    }

    #[test]
    fn the_plan_sits_at_the_origin_and_the_funicular_corners_on_the_verticals() {
        let (bm, dr) = (beam(), drawing());
        let mut b = Board::recording();
        let mut c = BeamConstruction::new(&mut b, &bm, &dr);
        let left = c.plan().unwrap().left.g;
        assert_eq!(left, Point::new(10.0, -5.0));
        let verticals = c.plan().unwrap().verticals.clone();
        let f = c.funicular().unwrap();
        assert_eq!(f.strings.len(), 4);
        for (corner, v) in f.corners.iter().zip(&verticals) {
            assert!((corner.g.x - v.g.origin.x).abs() < 1e-12);
        }
    }

    #[test]
    fn reactions_balance_the_loads_with_the_overhang() {
        let (bm, dr) = (beam(), drawing());
        let mut b = Board::recording();
        let mut c = BeamConstruction::new(&mut b, &bm, &dr);
        let r = c.reactions().unwrap().values;
        // ΣM_B: A·6 = 600·4 + 400·2 − 100·2.
        assert!((r.a - 500.0).abs() < 1e-9, "{r:?}");
        assert!((r.a + r.b - 1100.0).abs() < 1e-9);
        assert!(c.b.all_passed());
    }
}
