//! The piston acceleration on Tolle's parabola (LH B.3, Abb. 55-57; KG Abb. 1050).

use super::super::closed_form as cf;
use super::super::tolle;
use super::{Builder, Tolle};
use crate::kernel::Point;
use crate::protocol::{note, ConstructionError, Label, Note, Role, Scale, Topic, Trace, H};

const N_TOLLE_OC: Note = note(
    "OC read off where the chord cuts the axis",
    Some("Kontrolle: Sehne durch C"),
    "LH B.3, Abb. 55",
    Topic::Acceleration,
);
const N_TOLLE_CURVE: Note = note(
    "the parabola enveloped by the joining lines",
    Some("Beschleunigungsparabel"),
    "LH Abb. 55-57; KG Abb. 1050",
    Topic::Acceleration,
);
/// Equal parts of each tangent in the drawn envelope (the book's figure has about eight).
const ENVELOPE_PARTS: usize = 10;

impl Builder<'_> {
    /// Tolle's diagram under the crosshead's stroke (LH Abb. 55): axis, both curves with their
    /// controls, and the envelopes drawn.
    fn tolle(&mut self) -> Result<&Tolle, ConstructionError> {
        if self.tolle.is_none() {
            let x0 = self.frame()?.x0.g;
            let lam = self.lambda();
            let a_mm = self.d.v2_over_r() / self.scales.acceleration_scale;
            let below = self.r + 0.15 * (self.r + self.l) + (1.0 + lam) * a_mm;
            self.base_context();
            let ax = tolle::axis(
                self.b,
                Point::new(x0.x + self.r, x0.y - below),
                self.r,
                Topic::Acceleration,
            )?;
            let c_pt = tolle::point_c(self.b, &ax, self.r, lam)?;
            let mut curves = Vec::with_capacity(2);
            let base = self.b.context();
            for (sense, name, stroke) in [
                // LH II D: T the outer dead centre, T₁ the inner.
                (1.0, Label::plain("T"), tolle::OUTSTROKE),
                (-1.0, Label::indexed("T", 1), tolle::RETURN_STROKE),
            ] {
                // The situation: the caller's (a cylinder), and the stroke.
                self.b.set_context(|| match &base {
                    Some(c) => format!("{c}, {stroke}"),
                    None => stroke.to_string(),
                });
                let (c, cut) = tolle::curve(self.b, &ax, &c_pt, a_mm, lam, sense, name)?;
                let oc = self.b.measure(
                    &ax.o,
                    &cut,
                    &ax.axis,
                    Scale {
                        per_mm: self.scales.length_scale,
                        unit: "mm",
                    },
                    Label::NONE,
                    N_TOLLE_OC,
                );
                let r = self.d.crank_radius;
                self.b.check(
                    &oc,
                    "chord TT₁ cuts the axis at OC = λ·r",
                    "mm",
                    "LH B.3 (Tolle)",
                    r,
                    || lam * r,
                );
                if sense > 0.0 && lam > 0.0 {
                    self.check_cd(&ax, &c_pt, &c);
                }
                tolle::balance(self.b, &ax, &c);
                let pts = tolle::envelope(self.b, &c, ENVELOPE_PARTS);
                if pts.len() >= 2 {
                    self.b
                        .curve(&pts, Trace::Smooth, Role::Result.named("b"), N_TOLLE_CURVE);
                }
                curves.push(c);
            }
            self.b.set_context_to(base);
            self.tolle = Some(Tolle {
                axis: ax,
                curves: [curves[0], curves[1]],
            });
        }
        Ok(self.tolle.as_ref().expect("set above"))
    }

    /// CD read off the outstroke's curve and held to Tolle's 3λ·v²/r (LH B.3).
    fn check_cd(&mut self, ax: &tolle::TolleAxis, c: &tolle::TolleC, curve: &tolle::TolleCurve) {
        let ys = Scale {
            per_mm: self.scales.acceleration_scale,
            unit: "m/s²",
        };
        let cd = tolle::read_cd(self.b, ax, c, curve, ys);
        let (lam, a) = (self.lambda(), self.d.v2_over_r());
        self.b.check(
            &cd,
            "CD = 3λ·v²/r, taken off between C and D (Tolle)",
            "m/s²",
            "LH B.3, Abb. 55",
            a * (1.0 + lam),
            || 3.0 * lam * a,
        );
    }

    /// The piston acceleration at angle i on Tolle's parabola, read off and checked against
    /// the book's formula (tight) and the finite rod’s exact value (within Tolle's bound).
    pub(super) fn acceleration(&mut self, i: usize) -> Result<(H<f64>, H<f64>), ConstructionError> {
        if let Some(a) = self.cache[i].accel {
            return Ok(a);
        }
        let theta = self.thetas[i];
        let (stroke, _) = cf::book_angle(theta);
        if self.tolle.is_none() {
            self.tolle()?;
            self.angle_context(theta);
        }
        let t = self.tolle()?;
        let (ax, curve) = (t.axis, t.curves[(stroke == cf::Stroke::Return) as usize]);
        // s = sin²(θ/2): the same point of the stroke for θ and 360° − θ.
        let s = crate::kernel::angle::sin_cos_deg(theta / 2.0).0.powi(2);
        let q = tolle::point_at(self.b, &curve, s, Label::quiet("b", i as u32))?;
        let xs = Scale {
            per_mm: self.scales.length_scale,
            unit: "mm",
        };
        let ys = Scale {
            per_mm: self.scales.acceleration_scale,
            unit: "m/s²",
        };
        let labels = (Label::quiet("x", i as u32), Label::quiet("b", i as u32));
        let (x, b) = tolle::read(self.b, &ax, &q, xs, ys, labels);
        let (r, lam, a) = (self.d.crank_radius, self.lambda(), self.d.v2_over_r());
        self.b.check(
            &x,
            "abscissa of the parabola point",
            "mm",
            "LH Gl. 21",
            r,
            || cf::piston_path_approx(r, lam, theta),
        );
        let sign = stroke.sign();
        let reference = a * (1.0 + lam);
        self.b.check(
            &b,
            "piston acceleration b (Tolle’s parabola)",
            "m/s²",
            "KG (291); LH Gl. 29, 34",
            reference,
            || sign * cf::acceleration_approx(a, lam, theta),
        );
        self.b.check_within(
            &b,
            "b against the finite rod’s exact acceleration (within Tolle’s bound at θ)",
            "m/s²",
            "KG (285) differentiated twice",
            reference,
            || {
                (
                    sign * cf::acceleration_exact(a, lam, theta),
                    cf::tolle_bound_at(lam, theta) * a,
                )
            },
        );
        self.cache[i].accel = Some((x, b));
        Ok((x, b))
    }
}
