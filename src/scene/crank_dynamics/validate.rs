//! The checks of a dynamics scene's values; every error names its field.

use super::super::fields::Fields;
use super::super::SceneError;
use super::{CylinderSpec, DynamicsScene, IndicatorSpec, MassSpec, SidePoints, SteamSpec};
use crate::kernel::tolerance::MAX_DIVISIONS;

/// At most this many cylinders on one shaft.
const MAX_CYLINDERS: usize = 64;
/// The largest and the smallest card the output `reduction` draws (mm, length or height).
const MAX_CARD_MM: f64 = 1000.0;
const MIN_CARD_MM: f64 = 1.0;
/// At most this many digitised points per curve.
const MAX_POINTS: usize = 100_000;

impl DynamicsScene {
    pub(super) fn check(&self, f: Fields) -> Result<(), SceneError> {
        let r = self.mechanism.check(f)?;
        self.mechanism.check_rod(f, r)?;
        self.speed.check(f)?;
        self.speed.check_revolutions(f, r)?;
        self.check_rays(f)?;
        if self.outputs.is_empty() {
            return Err(f.bad("outputs", "ask for at least one output".into()));
        }
        if self.cylinders.is_empty() || self.cylinders.len() > MAX_CYLINDERS {
            return Err(f.bad(
                "cylinders",
                format!(
                    "{} cylinders: give 1 to {MAX_CYLINDERS}",
                    self.cylinders.len()
                ),
            ));
        }
        let inertia = self.check_effects(f)?;
        for (i, c) in self.cylinders.iter().enumerate() {
            check_cylinder(f, &format!("cylinders[{i}]"), c, 2.0 * r, inertia)?;
        }
        self.check_pumps(f)?;
        self.check_cards(f)?;
        if let Some(fw) = &self.flywheel {
            if !(fw.irregularity.is_finite() && fw.irregularity > 0.0 && fw.irregularity < 1.0) {
                return Err(f.bad(
                    "flywheel.irregularity",
                    format!("δ = {}: give 0 < δ < 1 (e.g. 1/50 = 0.02)", fw.irregularity),
                ));
            }
        }
        Ok(())
    }

    /// Either `divisions` (2 to MAX_DIVISIONS) or `stroke_parts` (1 to half that, the first
    /// cylinder's crank at offset 0).
    fn check_rays(&self, f: Fields) -> Result<(), SceneError> {
        match (self.divisions, self.stroke_parts) {
            (Some(_), Some(_)) => Err(f.bad(
                "stroke_parts",
                "give either divisions or stroke_parts, not both".into(),
            )),
            (None, None) => Err(f.bad(
                "divisions",
                "missing: give divisions (equal crank angles) or stroke_parts".into(),
            )),
            (Some(n), None) if !(2..=MAX_DIVISIONS).contains(&n) => Err(f.bad(
                "divisions",
                format!("{n} divisions: give between 2 and {MAX_DIVISIONS}"),
            )),
            (None, Some(n)) if !(1..=MAX_DIVISIONS / 2).contains(&n) => Err(f.bad(
                "stroke_parts",
                format!("{n} parts: give between 1 and {}", MAX_DIVISIONS / 2),
            )),
            (None, Some(_))
                if self
                    .cylinders
                    .first()
                    .is_some_and(|c| c.crank_offset_deg != 0.0) =>
            {
                Err(f.bad(
                    "cylinders[0].crank_offset_deg",
                    "with stroke_parts the first cylinder's crank is the reference: its \
                     offset must be 0"
                        .into(),
                ))
            }
            _ => Ok(()),
        }
    }

    /// The pumps: named by the effect `pump` and given with it (at least one); a plunger
    /// wider than its rod, a suction underpressure that does not reach below absolute zero
    /// (at most 1 at), a delivery pressure not below zero gauge.
    fn check_pumps(&self, f: Fields) -> Result<(), SceneError> {
        let on = self.effects.is_some_and(|e| e.pump);
        let given = self.cylinders.iter().position(|c| c.pump.is_some());
        match (on, given) {
            (true, None) => return Err(f.bad("effects.pump", "no cylinder has a pump: give a cylinder's `pump`, or leave the effect out".into())),
            (false, Some(i)) => return Err(f.bad(&format!("cylinders[{i}].pump"), "is used only with the effect `pump`: add \"pump\": true to `effects`, or leave the pump out".into())),
            _ => {}
        }
        if !on && self.outputs.resistance_line {
            return Err(f.bad("outputs", "`resistance_line` is the resistance of a pump: give a cylinder's `pump` and the effect `pump`, or leave the output out".into()));
        }
        for (i, c) in self.cylinders.iter().enumerate() {
            let Some(p) = c.pump else { continue };
            let at = format!("cylinders[{i}].pump");
            f.positive(&format!("{at}.plunger_mm"), p.plunger_mm)?;
            if !(p.rod_mm.is_finite() && p.rod_mm >= 0.0 && p.rod_mm < p.plunger_mm) {
                return Err(f.bad(
                    &format!("{at}.rod_mm"),
                    format!(
                        "must lie in [0, plunger) = [0, {}), got {}",
                        p.plunger_mm, p.rod_mm
                    ),
                ));
            }
            if !(p.suction_at.is_finite() && (0.0..=1.0).contains(&p.suction_at)) {
                return Err(f.bad(&format!("{at}.suction_at"), format!("{}: the suction is an underpressure below the atmosphere, between 0 and 1 at (more would be below absolute zero)", p.suction_at)));
            }
            if !(p.delivery_at.is_finite() && p.delivery_at >= 0.0) {
                return Err(f.bad(
                    &format!("{at}.delivery_at"),
                    format!(
                        "{}: give the delivery pressure above the atmosphere, at least 0 at",
                        p.delivery_at
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The cards: every cylinder's given with the output `reduction` and none without it;
    /// a length and spring scales that draw a card of at most a metre.
    fn check_cards(&self, f: Fields) -> Result<(), SceneError> {
        let on = self.outputs.reduction;
        for (i, c) in self.cylinders.iter().enumerate() {
            let at = format!("cylinders[{i}].card");
            let Some(card) = c.card else {
                if on {
                    return Err(f.bad(&at, "missing: the output `reduction` reduces every cylinder's indicator card: give its length_mm and spring_mm_per_at".into()));
                }
                continue;
            };
            if !on {
                return Err(f.bad(&at, "is used only with the output `reduction`: add it to `outputs`, or leave the card out".into()));
            }
            let peak = peak_pressure(c).max(1.0);
            for (name, v, per) in [
                ("length_mm", card.length_mm, 1.0),
                ("spring_mm_per_at", card.spring_mm_per_at, peak),
                (
                    "respring_mm_per_at",
                    card.respring_mm_per_at.unwrap_or(1.0),
                    peak,
                ),
            ] {
                let field = format!("{at}.{name}");
                f.positive(&field, v)?;
                if v * per > MAX_CARD_MM || v * per < MIN_CARD_MM {
                    return Err(f.bad(&field, format!("{v} draws a card {} mm long or high: give one that draws between {MIN_CARD_MM} and {MAX_CARD_MM} mm", crate::fmt::num(v * per, 3))));
                }
            }
        }
        Ok(())
    }

    /// The effects: a share in [0, 1], 0 < η ≤ 1; whether inertia is on.
    fn check_effects(&self, f: Fields) -> Result<bool, SceneError> {
        let Some(e) = &self.effects else {
            return Ok(false);
        };
        if let Some(s) = e.rod_mass_share {
            if !(s.is_finite() && (0.0..=1.0).contains(&s)) {
                return Err(f.bad(
                    "effects.rod_mass_share",
                    format!("{s}: give a share between 0 and 1 (LH: 2/3)"),
                ));
            }
        }
        if let Some(eta) = e.efficiency {
            if !(eta.is_finite() && eta > 0.0 && eta <= 1.0) {
                return Err(f.bad("effects.efficiency", format!("η = {eta}: give 0 < η ≤ 1")));
            }
        }
        Ok(e.inertia)
    }
}

fn check_cylinder(
    f: Fields,
    at: &str,
    c: &CylinderSpec,
    stroke: f64,
    inertia: bool,
) -> Result<(), SceneError> {
    f.positive(&format!("{at}.bore_mm"), c.bore_mm)?;
    for (name, d) in [
        ("rod_crank_side_mm", c.rod_crank_side_mm),
        ("rod_cover_side_mm", c.rod_cover_side_mm),
    ] {
        if !(d.is_finite() && d >= 0.0 && d < c.bore_mm) {
            return Err(f.bad(
                &format!("{at}.{name}"),
                format!("must lie in [0, bore) = [0, {}), got {d}", c.bore_mm),
            ));
        }
    }
    f.finite(&format!("{at}.crank_offset_deg"), c.crank_offset_deg)?;
    if let Some(s) = c.stroke_mm {
        if (s - stroke).abs() > 1e-9 * stroke {
            return Err(f.bad(
                &format!("{at}.stroke_mm"),
                format!(
                    "{s} mm against the shaft's stroke {stroke} mm: cylinders of different \
                     stroke on one shaft need a linkage this procedure does not model"
                ),
            ));
        }
    }
    match &c.indicator {
        IndicatorSpec::Steam(s) => check_steam(f, &format!("{at}.indicator.steam"), s)?,
        IndicatorSpec::Points(p) => {
            for (side, sp) in [("cover", &p.cover), ("crank", &p.crank)] {
                let base = format!("{at}.indicator.points.{side}");
                check_points(f, &format!("{base}.working"), &sp.working, stroke, p.gauge)?;
                check_points(f, &format!("{base}.back"), &sp.back, stroke, p.gauge)?;
                let _: &SidePoints = sp;
            }
        }
    }
    check_masses(f, at, c, inertia)
}

fn check_masses(f: Fields, at: &str, c: &CylinderSpec, inertia: bool) -> Result<(), SceneError> {
    match (&c.masses, inertia) {
        (None, true) => Err(f.bad(
            &format!("{at}.masses"),
            "missing: the effect `inertia` needs the reciprocating masses (weights_kg or \
             radinger)"
                .into(),
        )),
        (
            Some(MassSpec::Radinger {
                q_kg_per_cm2,
                bore_mm,
            }),
            _,
        ) => {
            if !(q_kg_per_cm2.is_finite() && *q_kg_per_cm2 > 0.0) {
                return Err(f.bad(
                    &format!("{at}.masses.radinger.q_kg_per_cm2"),
                    format!("q = {q_kg_per_cm2}: must be positive (LH: 0.28, 0.33, 0.41)"),
                ));
            }
            if let Some(d) = bore_mm {
                f.positive(&format!("{at}.masses.radinger.bore_mm"), *d)?;
            }
            Ok(())
        }
        (Some(MassSpec::Weights(w)), _) => {
            for (name, v) in [
                ("piston", w.piston),
                ("piston_rod", w.piston_rod),
                ("crosshead", w.crosshead),
                ("connecting_rod", w.connecting_rod),
                ("other", w.other),
            ] {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(f.bad(
                        &format!("{at}.masses.weights_kg.{name}"),
                        format!("a weight must be zero or positive, got {v}"),
                    ));
                }
            }
            Ok(())
        }
        (None, false) => Ok(()),
    }
}

fn check_steam(f: Fields, at: &str, s: &SteamSpec) -> Result<(), SceneError> {
    let add = if s.gauge { 1.0 } else { 0.0 };
    for (name, p) in [("admission_at", s.admission_at), ("back_at", s.back_at)] {
        if !(p.is_finite() && p + add > 0.0) {
            return Err(f.bad(
                &format!("{at}.{name}"),
                format!(
                    "{p} at{}: a pressure must lie above absolute zero",
                    if s.gauge { " gauge" } else { "" }
                ),
            ));
        }
    }
    if s.admission_at < s.back_at {
        return Err(f.bad(
            &format!("{at}.admission_at"),
            "the admission pressure must not lie below the back pressure".into(),
        ));
    }
    let release = s.release.unwrap_or(0.95);
    if !(s.cutoff.is_finite() && s.cutoff > 0.0 && s.cutoff <= 1.0) {
        return Err(f.bad(
            &format!("{at}.cutoff"),
            format!(
                "cut-off {}: give a fraction of the stroke, 0 < ε ≤ 1",
                s.cutoff
            ),
        ));
    }
    if !(release.is_finite() && release >= s.cutoff && release <= 1.0) {
        return Err(f.bad(
            &format!("{at}.release"),
            format!("release {release}: give cut-off ≤ release ≤ 1"),
        ));
    }
    let n = s.exponent.unwrap_or(1.0);
    if !(n.is_finite() && n > 0.0 && n <= 3.0) {
        return Err(f.bad(
            &format!("{at}.exponent"),
            format!("n = {n}: give 0 < n ≤ 3"),
        ));
    }
    let comp = s.compression.unwrap_or(0.0);
    if !(comp.is_finite() && (0.0..1.0).contains(&comp)) {
        return Err(f.bad(
            &format!("{at}.compression"),
            format!("{comp}: give a fraction of the stroke, 0 ≤ c < 1"),
        ));
    }
    let clear = s.clearance.unwrap_or(0.05);
    if !(clear.is_finite() && (0.0..=1.0).contains(&clear)) || (comp > 0.0 && clear <= 0.0) {
        return Err(f.bad(
            &format!("{at}.clearance"),
            format!(
                "{clear}: give 0 ≤ clearance ≤ 1, and a positive clearance when steam is \
                 compressed (else the compression line runs to infinity)"
            ),
        ));
    }
    Ok(())
}

fn check_points(
    f: Fields,
    at: &str,
    pts: &[[f64; 2]],
    stroke: f64,
    gauge: bool,
) -> Result<(), SceneError> {
    if pts.len() < 2 || pts.len() > MAX_POINTS {
        return Err(f.bad(
            at,
            format!(
                "{} points: give 2 to {MAX_POINTS}, from x = 0 to the stroke",
                pts.len()
            ),
        ));
    }
    let add = if gauge { 1.0 } else { 0.0 };
    let slack = 1e-9 * stroke;
    for (k, p) in pts.iter().enumerate() {
        let [x, pr] = *p;
        if !(x.is_finite() && pr.is_finite()) {
            return Err(f.bad(&format!("{at}[{k}]"), "must be finite numbers".into()));
        }
        if pr + add < 0.0 {
            return Err(f.bad(
                &format!("{at}[{k}]"),
                format!(
                    "pressure {pr} at{} lies below absolute zero",
                    if gauge { " gauge" } else { "" }
                ),
            ));
        }
        if k > 0 && x < pts[k - 1][0] {
            return Err(f.bad(
                &format!("{at}[{k}]"),
                format!(
                    "x = {x} mm comes after x = {} mm: give the points in order along the stroke",
                    pts[k - 1][0]
                ),
            ));
        }
    }
    let (first, last) = (pts[0][0], pts[pts.len() - 1][0]);
    if first.abs() > slack || (last - stroke).abs() > slack {
        return Err(f.bad(
            at,
            format!("the points run from x = {first} to {last} mm: give the whole stroke, 0 to {stroke} mm"),
        ));
    }
    Ok(())
}

/// The highest absolute pressure of a cylinder's diagrams (at), read at the scene's own
/// values: what a card's spring scale draws as its height.
fn peak_pressure(c: &CylinderSpec) -> f64 {
    match &c.indicator {
        IndicatorSpec::Steam(s) => s.admission_at.max(s.back_at) + if s.gauge { 1.0 } else { 0.0 },
        IndicatorSpec::Points(p) => {
            let add = if p.gauge { 1.0 } else { 0.0 };
            [&p.cover, &p.crank]
                .iter()
                .flat_map(|s| s.working.iter().chain(&s.back))
                .map(|q| q[1] + add)
                .fold(0.0, f64::max)
        }
    }
}
