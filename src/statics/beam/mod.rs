//! Beams by the funicular polygon: reactions by the closing line (LH C.4, Abb. 24), the moment
//! area M = y·H (C.5, Gl. 11), the shear diagram from the force plan (C.6, Abb. 25), overhangs
//! with their undercut moment area (Aufgabe 6, Abb. 34), and the parabola of a uniform load
//! drawn by its tangents (Abb. 36, 37).
//!
//! # The construction
//! The loads are laid off head to tail on the load line; the pole O lies at the pole distance
//! H to the right of it. The strings of the funicular polygon run parallel to the pole rays
//! between the verticals of the loads (a uniform load acts, for the polygon, as its resultant
//! at its centre). The **first** string (before every load), extended, cuts the vertical of
//! support A, and the **last** string cuts the vertical of support B: the line through these
//! two points is the closing line. Its parallel through O cuts the load line in C, which divides
//! it into A and B. The moment at a section is H times the ordinate from the polygon to the
//! closing line — on an overhang, to the first or last string instead, so that with overhangs
//! the moment area is undercut (*hinterschnitten*). Over a uniform load the polygon's corner is
//! replaced by the parabola that touches the two strings at the verticals of the load's ends:
//! both tangents are divided into equal parts, the joins 1–1, 2–2, … are tangents of the
//! parabola, and each touches it at the point dividing it in the same ratio.

mod build;
mod indirect;
mod moment;
mod notes;
mod shear;
mod types;

pub use indirect::{construct_beam_indirect, panel_loads};
pub use types::{
    BeamDrawing, BeamRequest, BeamResults, MaxMoment, Reactions, SectionRow, ShearRow,
};

use super::Beam;
use crate::kernel::tolerance::REL_LOCAL_FRAME;
use crate::protocol::{Board, ConstructionError};
use build::BeamConstruction;

/// Constructs reactions, moment area and shear diagram of a beam on `board`.
///
/// # Errors
/// A [`ConstructionError`] if a step has no solution (a pole on the load line); a validated
/// scene never produces one.
///
/// ```
/// use graphostatik::statics::*;
/// use graphostatik::protocol::Board;
/// use graphostatik::kernel::Point;
/// let beam = Beam { supports: [0.0, 6.0], ends: [0.0, 6.0],
///     point_loads: vec![PointLoad { x: 2.0, p: 600.0 }], uniform_loads: vec![] };
/// let drawing = BeamDrawing { length_scale: 50.0, force_scale: 20.0, pole_distance: 500.0,
///     parabola_divisions: 8, origin: Point::origin() };
/// let mut board = Board::recording();
/// let r = construct_beam(&mut board, &beam, &drawing,
///     &BeamRequest { reactions: true, moment_area: true, shear_diagram: true }).unwrap();
/// assert!((r.reactions.a - 400.0).abs() < 1e-9 && (r.reactions.b - 200.0).abs() < 1e-9);
/// // M under the load = A·a = 400 kg · 2 m (LH Gl. 11).
/// assert!((r.max_moment.unwrap().moment - 800.0).abs() < 1e-9);
/// assert!(board.all_passed());
/// ```
pub fn construct_beam(
    b: &mut Board,
    beam: &Beam,
    dr: &BeamDrawing,
    req: &BeamRequest,
) -> Result<BeamResults, ConstructionError> {
    construct_beam_at(b, beam, dr, req, &[])
}

/// [`construct_beam`], with the moment also measured at the given sections (m): a vertical
/// through the section cuts the polygon and the closing line (LH Abb. 24, section C). Sections
/// at a load or support are there already; sections inside a uniform load are refused (its
/// moment line is the parabola, read off at its division points).
///
/// # Errors
/// As [`construct_beam`], and [`ConstructionError::Unsupported`] for a section off the beam or
/// inside a uniform load.
pub fn construct_beam_at(
    b: &mut Board,
    beam: &Beam,
    dr: &BeamDrawing,
    req: &BeamRequest,
    extra_sections: &[f64],
) -> Result<BeamResults, ConstructionError> {
    construct_beam_numbered(b, beam, dr, req, extra_sections, 0)
}

/// [`construct_beam_at`] with the point loads numbered from `first_load + 1` (a shaft's
/// second plane goes on from the first's).
pub(crate) fn construct_beam_numbered(
    b: &mut Board,
    beam: &Beam,
    dr: &BeamDrawing,
    req: &BeamRequest,
    extra_sections: &[f64],
    first_load: u32,
) -> Result<BeamResults, ConstructionError> {
    let frame = LocalFrame::of(beam);
    if frame.dx != 0.0 {
        let sections: Vec<f64> = extra_sections.iter().map(|x| x - frame.dx).collect();
        let local = frame.to_local(beam);
        let r = construct_beam_numbered(b, &local, dr, req, &sections, first_load)?;
        return Ok(frame.to_global(r));
    }
    check_sections(beam, extra_sections)?;
    check_layout(beam)?;
    // About 40 steps and 60 objects per load when everything is drawn.
    let nloads = beam.point_loads.len() + beam.uniform_loads.len() * (dr.parabola_divisions + 4);
    b.reserve(64 + 40 * nloads, 64 + 60 * nloads);
    let mut c = BeamConstruction::new(b, beam, dr);
    c.first_load = first_load;
    let reactions = c.reactions()?.values;
    if req.moment_area || req.shear_diagram {
        c.moment_area()?;
        for &x in extra_sections {
            c.section(x)?;
        }
        c.zero_moments()?;
    }
    let (shear, max_moment) = if req.shear_diagram {
        let rows = c.shear()?;
        (rows, c.max_moment()?)
    } else {
        (Vec::new(), None)
    };
    Ok(c.finish(reactions, shear, max_moment))
}

/// The beam's own frame: where the beam lies far from the origin (farther than
/// [`REL_LOCAL_FRAME`] times its length), x is measured from support A, so that neither the
/// construction on the sheet nor the closed forms (prefix sums of P·x) carry the offset's
/// digits; the results are given back at the scene's x.
#[derive(Debug, Clone, Copy)]
pub(super) struct LocalFrame {
    /// The x (m) the local frame starts at; 0 for a beam near the origin.
    pub(super) dx: f64,
}

impl LocalFrame {
    pub(super) fn of(beam: &Beam) -> LocalFrame {
        let length = (beam.ends[1] - beam.ends[0]).abs();
        let reach = beam.ends[0].abs().max(beam.ends[1].abs());
        let far = reach > REL_LOCAL_FRAME * length && beam.supports[0].is_finite();
        LocalFrame {
            dx: if far { beam.supports[0] } else { 0.0 },
        }
    }

    /// The beam with x measured from `dx`.
    pub(super) fn to_local(self, beam: &Beam) -> Beam {
        let x = |v: f64| v - self.dx;
        Beam {
            supports: beam.supports.map(x),
            ends: beam.ends.map(x),
            point_loads: beam
                .point_loads
                .iter()
                .map(|l| super::PointLoad { x: x(l.x), p: l.p })
                .collect(),
            uniform_loads: beam
                .uniform_loads
                .iter()
                .map(|u| super::UniformLoad {
                    from: x(u.from),
                    to: x(u.to),
                    q: u.q,
                })
                .collect(),
        }
    }

    /// The results at the scene's x.
    pub(super) fn to_global(self, mut r: BeamResults) -> BeamResults {
        for s in &mut r.sections {
            s.x += self.dx;
        }
        for z in &mut r.zero_moments {
            *z += self.dx;
        }
        for s in &mut r.shear {
            s.x += self.dx;
        }
        if let Some(m) = &mut r.max_moment {
            m.x += self.dx;
        }
        r
    }
}

/// Sections must lie on the beam and outside the uniform loads.
fn check_sections(beam: &Beam, extra_sections: &[f64]) -> Result<(), ConstructionError> {
    // Each section against every uniform load: the sections are a shaft's few, or a stringer
    // beam's panel points, whose beam carries point loads only.
    for &x in extra_sections {
        if !(x >= beam.ends[0] && x <= beam.ends[1]) {
            return Err(ConstructionError::unsupported(
                "sections",
                format!("section x = {x} m lies off the beam"),
            ));
        }
        if beam.uniform_loads.iter().any(|u| x > u.from && x < u.to) {
            return Err(ConstructionError::unsupported("sections", format!(
                "section x = {x} m lies inside a uniform load: its moments are read off the parabola"
            )));
        }
    }
    Ok(())
}

/// The layouts the construction handles: A left of B, uniform loads that neither overlap nor
/// straddle a support nor hold a point load (split them there: the result is the same).
/// O(n log n) in the loads.
fn check_layout(beam: &Beam) -> Result<(), ConstructionError> {
    let [a, b] = beam.supports;
    if a.partial_cmp(&b) != Some(std::cmp::Ordering::Less) {
        return Err(ConstructionError::unsupported(
            "supports",
            format!("support A ({a} m) must lie left of support B ({b} m)"),
        ));
    }
    for (i, u) in beam.uniform_loads.iter().enumerate() {
        let inside = |x: f64| x > u.from && x < u.to;
        if u.from.partial_cmp(&u.to) != Some(std::cmp::Ordering::Less) {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("uniform load {i} must end after it starts"),
            ));
        }
        if inside(a) || inside(b) {
            return Err(ConstructionError::unsupported(
                format!("uniform_loads[{i}]"),
                format!("uniform load {i} straddles a support: split it there"),
            ));
        }
    }
    let spans: Vec<(f64, f64)> = beam.uniform_loads.iter().map(|u| (u.from, u.to)).collect();
    let xs: Vec<f64> = beam.point_loads.iter().map(|l| l.x).collect();
    if let Some((i, _)) = point_inside_span(&spans, &xs) {
        return Err(ConstructionError::unsupported(
            format!("uniform_loads[{i}]"),
            format!("a point load lies inside uniform load {i}: split the uniform load there"),
        ));
    }
    if let Some((i, _)) = overlapping_spans(&spans) {
        return Err(ConstructionError::unsupported(
            format!("uniform_loads[{i}]"),
            format!("uniform load {i} overlaps another: add their intensities"),
        ));
    }
    Ok(())
}

/// The first span (from, to), by index, with a point strictly inside it, and that point (the
/// first by position, then by index): O((spans + points) log points).
///
/// ```
/// use graphostatik::statics::beam::point_inside_span;
/// let spans = [(0.0, 1.0), (2.0, 4.0), (5.0, 6.0)];
/// assert_eq!(point_inside_span(&spans, &[1.0, 3.5, 2.5]), Some((1, 2)));
/// assert_eq!(point_inside_span(&spans, &[1.0, 2.0, 6.0]), None);
/// ```
pub fn point_inside_span(spans: &[(f64, f64)], points: &[f64]) -> Option<(usize, usize)> {
    if spans.is_empty() {
        return None;
    }
    let mut by_x: Vec<(f64, usize)> = points.iter().copied().zip(0..).collect();
    by_x.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)));
    spans.iter().enumerate().find_map(|(i, &(from, to))| {
        let first = by_x.partition_point(|p| p.0 <= from);
        by_x.get(first).filter(|p| p.0 < to).map(|p| (i, p.1))
    })
}

/// Two spans (from, to) that overlap (touching is allowed), as (earlier index, later index),
/// found by sweeping them in the order of their starts, each against the one reaching
/// furthest before it: O(n log n). `None` if no two overlap.
///
/// ```
/// use graphostatik::statics::beam::overlapping_spans;
/// assert_eq!(overlapping_spans(&[(4.0, 6.0), (0.0, 2.0), (2.0, 4.0)]), None);
/// assert_eq!(overlapping_spans(&[(4.0, 6.0), (0.0, 2.0), (1.0, 3.0)]), Some((1, 2)));
/// ```
pub fn overlapping_spans(spans: &[(f64, f64)]) -> Option<(usize, usize)> {
    let mut order: Vec<usize> = (0..spans.len()).collect();
    order.sort_by(|&p, &q| spans[p].0.total_cmp(&spans[q].0).then(p.cmp(&q)));
    let mut reach: Option<usize> = None;
    for &j in &order {
        if let Some(r) = reach.filter(|&r| spans[j].0 < spans[r].1) {
            return Some((r.min(j), r.max(j)));
        }
        if reach.is_none_or(|r| spans[j].1 > spans[r].1) {
            reach = Some(j);
        }
    }
    None
}
