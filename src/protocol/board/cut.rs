//! The cuts: line with line, line with circle, circle with circle.

use super::*;
impl Board {
    /// Intersects two lines; a parallel or coincident pair is recorded as its named case.
    pub fn meet(&mut self, a: &H<Line>, b: &H<Line>, label: impl Into<Label>, note: Note) -> Cut {
        let label = label.into();
        let r = intersect_line_line(&a.g, &b.g, &self.tolerance);
        self.begin(StepKind::IntersectLineLine, &note, &[a.id, b.id]);
        match r {
            LineLine::Point {
                point,
                conditioning,
                ..
            } => {
                let point = self.mark(point);
                if let Some(s) = self.last_step() {
                    s.conditioning = Some(conditioning);
                }
                let id = self.add(label, Role::Given, || Geom::Point { at: point });
                self.lines_met(id, (a, b), &point, conditioning);
                self.touch(a.id, &point);
                self.touch(b.id, &point);
                Cut::Point(H { id, g: point }, conditioning)
            }
            LineLine::Parallel { distance } => {
                if let Some(s) = self.last_step() {
                    s.outcome = Some(format!(
                        "parallel, {} mm apart: they meet at infinity",
                        crate::fmt::num(distance, 3)
                    ));
                }
                Cut::Parallel { distance }
            }
            LineLine::Coincident => {
                if let Some(s) = self.last_step() {
                    s.outcome = Some("the lines coincide".into());
                }
                Cut::Coincident
            }
        }
    }

    /// The bound and reference of the point where two lines met.
    pub(super) fn lines_met(
        &mut self,
        id: ObjId,
        (a, b): (&H<Line>, &H<Line>),
        p: &Point,
        cond: Conditioning,
    ) {
        let step = StepId(self.next_step);
        self.set_tr(id, |bd| {
            let (ta, tb) = (bd.tr(a.id), bd.tr(b.id));
            let across = ((ta.across(&a.g, p), a.g.dir), (tb.across(&b.g, p), b.g.dir));
            let extent = p.coords.norm() + a.g.origin.coords.norm() + b.g.origin.coords.norm();
            let worst = crate::protocol::accuracy::worse(ta.worst, tb.worst);
            bd.model.cut_lines(step, cond, across, extent, worst)
        });
        self.set_shadow(id, |bd| {
            let ((ao, ad), (bo, bdir)) = (bd.sl(a), bd.sl(b));
            Shadow::Point(refr::meet(&ao, &ad, &bo, &bdir))
        });
    }

    /// Intersects two lines where the construction needs a point: a degenerate case is an error.
    pub fn meet_point(
        &mut self,
        a: &H<Line>,
        b: &H<Line>,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let step = self.step_id_next();
        let caption = note.caption.clone();
        match self.meet(a, b, label, note) {
            Cut::Point(p, _) => Ok(p),
            Cut::Parallel { distance } => Err(ConstructionError::NoIntersection {
                step,
                caption,
                outcome: CutOutcome::Parallel { distance },
            }),
            Cut::Coincident => Err(ConstructionError::NoIntersection {
                step,
                caption,
                outcome: CutOutcome::Coincident,
            }),
        }
    }

    /// Cuts a line with a circle and takes the branch given.
    pub fn cut_line_circle(
        &mut self,
        line: &H<Line>,
        circle: &H<Circle>,
        branch: Branch,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let r = intersect_line_circle(&line.g, &circle.g, &self.tolerance);
        let step = self.step_id_next();
        self.begin(StepKind::IntersectLineCircle, &note, &[line.id, circle.id]);
        let (p, cond, br) = match r {
            LineCircle::Two {
                points,
                conditioning,
            } => {
                let (p, _) = branch.pick(points);
                (p, conditioning, Some(branch))
            }
            LineCircle::Tangent { point } => (point, Conditioning::from_angle(0.0), None),
            LineCircle::Disjoint { gap } => {
                return Err(self.fail_cut(step, &note, CutOutcome::Misses { gap }));
            }
        };
        let h = self.finish_cut(p, cond, br, [line.id, circle.id], label);
        let step = StepId(self.next_step);
        self.set_tr(h.id, |b| {
            let (tl, tc) = (b.tr(line.id), b.tr(circle.id));
            let delta = tl.across(&line.g, &p) + tc.err;
            let (c, r) = (circle.g.center, circle.g.radius);
            let extent = p.coords.norm() + r + c.coords.norm() + line.g.origin.coords.norm();
            let worst = crate::protocol::accuracy::worse(tl.worst, tc.worst);
            b.model.cut(step, cond, (delta, extent, r), worst)
        });
        self.set_shadow(h.id, |b| {
            let ((o, d), (c, r)) = (b.sl(line), b.sc(circle));
            Shadow::Point(refr::line_circle(&o, &d, &c, r, &p))
        });
        Ok(h)
    }

    /// Records a cut that has no point and returns the error naming its case.
    pub(super) fn fail_cut(
        &mut self,
        step: StepId,
        note: &Note,
        outcome: CutOutcome,
    ) -> ConstructionError {
        if let Some(s) = self.last_step() {
            s.outcome = Some(outcome.to_string());
        }
        ConstructionError::NoIntersection {
            step,
            caption: note.caption.clone(),
            outcome,
        }
    }

    /// Records the point of a cut: conditioning, branch (none for a tangency), the point, and
    /// the marks on the two curves it lies on.
    pub(super) fn finish_cut(
        &mut self,
        p: Point,
        cond: Conditioning,
        br: Option<Branch>,
        on: [ObjId; 2],
        label: Label,
    ) -> H<Point> {
        self.last_touched = br.is_none();
        if let Some(s) = self.last_step() {
            s.conditioning = Some(cond);
            s.branch = br;
            if br.is_none() {
                s.outcome = Some("tangent: one double point".into());
            }
        }
        let p = self.mark(p);
        let id = self.add(label, Role::Given, || Geom::Point { at: p });
        self.touch(on[0], &p);
        self.touch(on[1], &p);
        H { id, g: p }
    }

    /// Whether the last cut of a line or circle with a circle found the two touching: one
    /// double point, no branch to choose (a linkage whose links fall into one line). Typed,
    /// on silent boards too.
    pub fn last_cut_touched(&self) -> bool {
        self.last_touched
    }

    /// Cuts two circles and takes the branch given (`First`/`Second` mean right/left of the
    /// line from the first centre to the second).
    pub fn cut_circle_circle(
        &mut self,
        a: &H<Circle>,
        b: &H<Circle>,
        branch: Branch,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        let r = intersect_circle_circle(&a.g, &b.g, &self.tolerance);
        let step = self.step_id_next();
        self.begin(StepKind::IntersectCircleCircle, &note, &[a.id, b.id]);
        let (p, cond, br) = match r {
            CircleCircle::Two {
                points,
                conditioning,
            } => (branch.pick(points).0, conditioning, Some(branch)),
            CircleCircle::TangentExternal { point } | CircleCircle::TangentInternal { point } => {
                (point, Conditioning::from_angle(0.0), None)
            }
            other => {
                let outcome = match other {
                    CircleCircle::Separate { gap } => CutOutcome::CirclesApart { gap },
                    CircleCircle::Contained { gap } => CutOutcome::CircleInside { gap },
                    CircleCircle::Concentric => CutOutcome::Concentric,
                    _ => CutOutcome::CirclesCoincide,
                };
                return Err(self.fail_cut(step, &note, outcome));
            }
        };
        let h = self.finish_cut(p, cond, br, [a.id, b.id], label);
        let step = StepId(self.next_step);
        self.set_tr(h.id, |bd| {
            let (ta, tb) = (bd.tr(a.id), bd.tr(b.id));
            let (ga, gb) = (&a.g, &b.g);
            let extent = p.coords.norm()
                + ga.radius
                + gb.radius
                + ga.center.coords.norm()
                + gb.center.coords.norm();
            let worst = crate::protocol::accuracy::worse(ta.worst, tb.worst);
            let geom = (ta.err + tb.err, extent, ga.radius.max(gb.radius));
            bd.model.cut(step, cond, geom, worst)
        });
        self.set_shadow(h.id, |bd| {
            let ((c1, r1), (c2, r2)) = (bd.sc(a), bd.sc(b));
            Shadow::Point(refr::circle_circle(&c1, r1, &c2, r2, &p))
        });
        Ok(h)
    }
}
