//! Reading values off the drawing, and the checks against their closed forms.

use super::follow::Derived;
use super::*;

impl Board {
    /// Measures the signed distance from `from` to `to` along the direction of `axis` and
    /// reads it off at `scale`: the drafter's dividers on the scale rule.
    pub fn measure(
        &mut self,
        from: &H<Point>,
        to: &H<Point>,
        axis: &H<Line>,
        scale: Scale,
        label: impl Into<Label>,
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let mm = (to.g - from.g).dot(&axis.g.dir);
        let mm = self.read(mm);
        let value = mm * scale.per_mm;
        self.begin(StepKind::Measure, &note, &[from.id, to.id, axis.id]);
        let how = Derived::Measured {
            from,
            to,
            axis,
            mm,
            scale,
        };
        self.made_number(label, (value, scale.unit), how)
    }

    /// Records a number reckoned from constructed values (`inputs`), not drawn: a value the
    /// checks can hold against its closed form, as the balance of the joints under a plan's
    /// forces is held against zero. Its error bound is the sum of its number inputs' bounds
    /// and the rounding of summing them.
    pub fn tally(
        &mut self,
        value: f64,
        unit: &'static str,
        label: impl Into<Label>,
        inputs: &[ObjId],
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let inputs = Weighted {
            inputs,
            weight: 1.0,
        };
        self.reckon(value, unit, label, inputs, note)
    }

    /// [`Board::tally`] with the weight of its inputs: `weight` is how much the number
    /// changes when one of its inputs moves by one unit (a number input) or one mm (a point
    /// input), so that their bounds follow into it: `1/n` for a mean of n ordinates, the
    /// sheet's width plus height for an area reckoned from points of a curve.
    pub fn reckon(
        &mut self,
        value: f64,
        unit: &'static str,
        label: impl Into<Label>,
        weighted: Weighted<'_>,
        note: Note,
    ) -> H<f64> {
        self.begin(StepKind::Tally, &note, weighted.inputs);
        let how = Derived::Reckoned {
            inputs: weighted,
            value,
        };
        self.made_number(label.into(), (value, unit), how)
    }

    /// The angle at `vertex` from the ray through `from` to the ray through `to`, in degrees
    /// in [0°, 180°]: the protractor laid on the drawing.
    pub fn measure_angle(
        &mut self,
        vertex: &H<Point>,
        from: &H<Point>,
        to: &H<Point>,
        label: impl Into<Label>,
        note: Note,
    ) -> H<f64> {
        let label = label.into();
        let (u, v) = (from.g - vertex.g, to.g - vertex.g);
        // atan2 of cross and dot keeps every digit near 0° and 180°, where acos loses half.
        let value = u.perp(&v).abs().atan2(u.dot(&v)).to_degrees();
        self.begin(StepKind::Measure, &note, &[vertex.id, from.id, to.id]);
        let how = Derived::Angle {
            vertex,
            from,
            to,
            value,
        };
        self.made_number(label, (value, "°"), how)
    }

    /// Attaches a check whose tolerance is a stated bound on top of the rounding of the
    /// construction: a model's difference from the exact value (Tolle's parabola against the
    /// finite rod's exact acceleration is within its truncation bound at that angle), and
    /// [`CHECK_REL`] × max(|closed form|, `reference`) for the construction itself. The closed
    /// form and the bound are evaluated only on a recording board.
    #[inline]
    pub fn check_within(
        &mut self,
        value: &H<f64>,
        quantity: impl Into<Text>,
        unit: impl Into<Text>,
        formula: impl Into<Text>,
        reference: f64,
        closed_and_bound: impl FnOnce() -> (f64, f64),
    ) {
        if self.recording {
            self.check_recorded(
                value,
                [quantity.into(), unit.into(), formula.into()],
                reference,
                closed_and_bound,
            );
        }
    }

    /// [`Board::check_within`] on a recording board.
    #[inline(never)]
    pub(super) fn check_recorded(
        &mut self,
        value: &H<f64>,
        [quantity, unit, formula]: [Text; 3],
        reference: f64,
        closed_and_bound: impl FnOnce() -> (f64, f64),
    ) {
        let (closed, model_bound) = closed_and_bound();
        // The model's own error (a rule's, an approximation's) and the construction's allowance
        // on top of it: where the model's bound is its error exactly, rounding must not fail it.
        let tolerance = model_bound + CHECK_REL * closed.abs().max(reference.abs());
        let error = (value.g - closed).abs();
        let (bound, worst_cut) = self
            .bound(value.id)
            .unwrap_or((self.model.rel * value.g.abs(), None));
        self.push_check(
            value.id,
            Check {
                quantity,
                object: self.checked_object.clone(),
                unit,
                constructed: value.g,
                closed_form: closed,
                formula,
                error,
                tolerance,
                reference,
                // An error within a bound that exceeds the tolerance is what the rounding at
                // this conditioning may give: not judged ([`Check::judged`]), not failed.
                passed: error <= tolerance || (bound > tolerance && error <= bound),
                bound,
                worst_cut,
            },
        );
    }

    /// Attaches an analytic check to the step that made `value`. The closed form is evaluated
    /// only on a recording board. The tolerance is [`CHECK_REL`] × max(|closed form|, `reference`).
    #[inline]
    pub fn check(
        &mut self,
        value: &H<f64>,
        quantity: impl Into<Text>,
        unit: impl Into<Text>,
        formula: impl Into<Text>,
        reference: f64,
        closed_form: impl FnOnce() -> f64,
    ) {
        self.check_within(value, quantity, unit, formula, reference, || {
            (closed_form(), 0.0)
        });
    }

    /// Files a check with the step that made the object `id` (every recording board's
    /// tracks know it, whether it keeps its steps or only its checks).
    pub(super) fn push_check(&mut self, id: ObjId, check: Check) {
        let Some(step) = self.tracks.step((id.0 as usize).wrapping_sub(1)) else {
            return;
        };
        match self.ledger.as_mut() {
            Some(l) => l.file(step, check),
            None => {
                if let Some(s) = self.steps.get_mut((step.0 as usize).wrapping_sub(1)) {
                    s.checks.push(check);
                }
            }
        }
    }

    /// Per step with a point or a number among its results: how far f64 strayed from the
    /// double-double replay and what the propagated bound predicted (empty unless the board
    /// was made with [`BoardConfig::with_reference`]).
    pub fn reference_report(&self) -> Vec<ReferenceRow> {
        let figure = self.tolerance.length / crate::kernel::tolerance::REL_LENGTH_EPS;
        let mut rows = Vec::new();
        for step in &self.steps {
            let checked = step
                .checks
                .iter()
                .map(|c| c.reference.abs())
                .fold(0.0, f64::max);
            let mut row: Option<ReferenceRow> = None;
            let mut worst = Worst::NONE;
            for id in &step.outputs {
                let (Some(obj), t) = (self.object(*id), self.tr(*id)) else {
                    continue;
                };
                let (observed, scale) = match (self.shadow(*id), &obj.geom) {
                    (Shadow::Point(r), Geom::Point { at }) => (r.off(at), figure),
                    (Shadow::Scalar(r), Geom::Scalar { value, .. }) => {
                        let dev = (twofloat::TwoFloat::from(*value) - r).hi().abs();
                        (dev, r.hi().abs().max(checked))
                    }
                    _ => continue,
                };
                let r = row.get_or_insert(ReferenceRow {
                    step: step.id,
                    observed: 0.0,
                    bound: 0.0,
                    scale,
                    worst_cut: None,
                });
                r.observed = r.observed.max(observed);
                r.bound = r.bound.max(t.err);
                r.scale = r.scale.max(scale);
                worst = worst.or_worse(t.worst);
            }
            rows.extend(row.map(|r| ReferenceRow {
                worst_cut: self.tracks.worst_cut(worst),
                ..r
            }));
        }
        rows
    }
}
