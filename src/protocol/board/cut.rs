//! The cuts: line with line, line with circle, circle with circle.

use super::follow::{Cutting, Derived};
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
                let of = Cutting::Lines(a, b);
                let how = Derived::Cut {
                    of,
                    at: point,
                    cond: conditioning,
                };
                let h = self.made_point(label, point, how);
                self.touch(a.id, &point);
                self.touch(b.id, &point);
                Cut::Point(h, conditioning)
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
        let of = Cutting::LineCircle(line, circle);
        let how = Derived::Cut { of, at: p, cond };
        Ok(self.finish_cut((p, cond, br), [line.id, circle.id], label, how))
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

    /// Records the point `p` of a cut: conditioning, branch (none for a tangency), the point
    /// as it follows from the curves cut (`how`), and the marks on the two curves it lies on.
    pub(super) fn finish_cut(
        &mut self,
        (p, cond, br): (Point, Conditioning, Option<Branch>),
        on: [ObjId; 2],
        label: Label,
        how: Derived<'_>,
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
        let h = self.made_point(label, p, how);
        self.touch(on[0], &p);
        self.touch(on[1], &p);
        h
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
        let of = Cutting::Circles(a, b);
        let how = Derived::Cut { of, at: p, cond };
        Ok(self.finish_cut((p, cond, br), [a.id, b.id], label, how))
    }
}
