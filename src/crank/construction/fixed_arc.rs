//! The piston path by one arc drawn once (LH B.1, Abb. 49; KG "CE"): about the crosshead's
//! dead position T an arc with the rod length through the crank's dead centre, and about the
//! other dead position T₁ its twin for the return stroke. The horizontal through any crank
//! pin A cuts the arc at C, and AC is the piston path: the rod's arc about A, shifted along
//! the piston line until it passes through T. For the infinite rod the arcs become the
//! perpendiculars through the crank's dead centres (LH Abb. 48).

use super::super::closed_form as cf;
use super::{Builder, Fixed};
use crate::kernel::Branch;
use crate::protocol::{note, ConstructionError, Drawn, Label, Note, Role, Scale, Topic};

const N_ARC: Note = note(
    "arc with the rod length about the crosshead’s dead position, drawn once",
    Some("Schubstangenkreisbogen TT′"),
    "LH Abb. 49",
    Topic::PistonPath,
);
const N_LINE: Note = note(
    "infinite rod: perpendicular through the crank’s dead centre",
    Some("senkrechte Gerade"),
    "LH Abb. 48",
    Topic::PistonPath,
);
const N_OUTER: Note = note(
    "the crosshead’s other dead position, a stroke on",
    Some("Kreuzkopftotpunkt T₁"),
    "LH Abb. 49",
    Topic::PistonPath,
);
const N_HORIZONTAL: Note = note(
    "horizontal through the crank pin",
    Some("Waagerechte durch A"),
    "LH Abb. 49",
    Topic::PistonPath,
);
const N_CUT: Note = note(
    "it cuts the fixed arc at C",
    Some("Punkt C"),
    "LH Abb. 49",
    Topic::PistonPath,
);
const N_MEASURE: Note = note(
    "piston path x = AC, measured from the dead centre where the stroke began",
    Some("Kolbenweg"),
    "LH Abb. 49; KG (285)",
    Topic::PistonPath,
);

impl Builder<'_> {
    fn fixed(&mut self) -> Result<Fixed, ConstructionError> {
        if let Some(f) = self.fixed {
            return Ok(f);
        }
        let f = self.frame()?;
        let (x0, axis, dead) = (f.x0, f.piston_line, f.dead);
        self.base_context();
        let fixed = if self.d.finite_rod {
            let x1 = self.b.lay_off(
                &x0,
                &axis,
                2.0 * self.r,
                Role::Construction.named("T₁"),
                N_OUTER,
            )?;
            let a0 = self
                .b
                .circle(&x0, self.l, Drawn::Marks, Role::Construction, N_ARC)?;
            let a1 = self
                .b
                .circle(&x1, self.l, Drawn::Marks, Role::Construction, N_ARC)?;
            Fixed::Arcs([a0, a1])
        } else {
            let d1 = self
                .b
                .lay_off(&dead, &axis, 2.0 * self.r, Role::Construction, N_OUTER)?;
            let l0 = self
                .b
                .perpendicular(&axis, &dead, Role::Construction, N_LINE);
            let l1 = self.b.perpendicular(&axis, &d1, Role::Construction, N_LINE);
            Fixed::Lines([l0, l1])
        };
        self.fixed = Some(fixed);
        Ok(fixed)
    }

    /// The piston path at angle i by the fixed arc; the engine's coordinate (from the inner
    /// dead centre) is returned, the measured AC is checked against the book's path (KG 285
    /// with its double sign).
    pub(super) fn x_fixed_arc(&mut self, i: usize) -> Result<f64, ConstructionError> {
        if let Some(x) = self.cache[i].x_fixed {
            return Ok(x);
        }
        let first = self.fixed.is_none();
        let fixed = self.fixed()?;
        let theta = self.thetas[i];
        if first {
            self.angle_context(theta);
        }
        let pin = self.pin(i)?;
        let axis = self.frame()?.piston_line;
        let (stroke, phi) = cf::book_angle(theta);
        let k = (stroke == cf::Stroke::Return) as usize;
        let horizontal = self
            .b
            .parallel(&axis, &pin, Role::Construction, N_HORIZONTAL);
        let label = Label::quiet("C", i as u32);
        let c = match fixed {
            // The branch towards the crank: the second point along the piston line.
            Fixed::Arcs(arcs) => {
                self.b
                    .cut_line_circle(&horizontal, &arcs[k], Branch::Second, label, N_CUT)?
            }
            Fixed::Lines(lines) => self.b.meet_point(&horizontal, &lines[k], label, N_CUT)?,
        };
        let scale = Scale {
            per_mm: self.scales.length_scale,
            unit: "mm",
        };
        // Outstroke: from C to A; return stroke: from A back to C (the way the piston moves).
        let (from, to) = if k == 0 { (c, pin) } else { (pin, c) };
        let x = self.b.measure(
            &from,
            &to,
            &axis,
            scale,
            Label::quiet("x", i as u32),
            N_MEASURE,
        );
        let (r, rod) = (self.d.crank_radius, self.d.rod());
        self.b.check(
            &x,
            "piston path x (fixed arc)",
            "mm",
            "KG (285); LH Gl. 20, Abb. 49",
            r,
            || cf::piston_path_book(r, rod, phi, stroke),
        );
        let engine = if k == 0 { x.g } else { 2.0 * r - x.g };
        self.cache[i].x_fixed = Some(engine);
        Ok(engine)
    }
}
