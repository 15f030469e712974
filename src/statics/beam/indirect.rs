//! Indirect loading: stringers carry the loads to the cross beams (LH Aufgabe 6, Abb. 35).

use super::construct_beam_at;
use super::notes::*;
use super::types::{BeamDrawing, BeamRequest, BeamResults, ARROW_MM};
use crate::kernel::tolerance::REL_POSITION_EPS;
use crate::kernel::Point;
use crate::protocol::{Board, ConstructionError, Label, Role, Trace, H};
use crate::statics::closed_form as cf;
use crate::statics::Beam;

/// Height of the stringers above the beam in the position plan (mm).
const STRINGER_MM: f64 = 18.0;

/// The loads that reach the beam through stringers spanning between the panel points: each
/// stringer, simply supported on its two cross beams, hands its loads on by the lever rule
/// (LH Abb. 35). Panel points must be increasing and every load must lie between the first and
/// the last.
pub fn panel_loads(
    beam: &Beam,
    panel_points: &[f64],
) -> Result<Vec<crate::statics::PointLoad>, ConstructionError> {
    if panel_points.len() < 2
        || panel_points
            .windows(2)
            .any(|w| w[0].partial_cmp(&w[1]) != Some(std::cmp::Ordering::Less))
    {
        return Err(ConstructionError::unsupported(
            "stringers",
            "panel points: give at least two, increasing",
        ));
    }
    let (first, last) = (panel_points[0], panel_points[panel_points.len() - 1]);
    let mut out: Vec<f64> = vec![0.0; panel_points.len()];
    let mut carry = |x: f64, p: f64| -> Result<(), ConstructionError> {
        if x < first || x > last {
            return Err(ConstructionError::unsupported(
                "point_loads",
                format!("a load at {x} m lies outside the stringers [{first}, {last}] m"),
            ));
        }
        let i = panel_points
            .partition_point(|&s| s <= x)
            .clamp(1, panel_points.len() - 1)
            - 1;
        let (s0, s1) = (panel_points[i], panel_points[i + 1]);
        let t = (x - s0) / (s1 - s0);
        out[i] += p * (1.0 - t);
        out[i + 1] += p * t;
        Ok(())
    };
    for l in &beam.point_loads {
        carry(l.x, l.p)?;
    }
    for u in &beam.uniform_loads {
        if u.from < first || u.to > last {
            return Err(ConstructionError::unsupported(
                "uniform_loads",
                format!(
                "a uniform load over [{}, {}] m reaches outside the stringers [{first}, {last}] m",
                u.from, u.to
            ),
            ));
        }
        // Each panel's share of the uniform load, as its resultant at the share's middle.
        for w in panel_points.windows(2) {
            let (a, b) = (u.from.max(w[0]), u.to.min(w[1]));
            if b > a {
                carry(0.5 * (a + b), u.q * (b - a))?;
            }
        }
    }
    Ok(panel_points
        .iter()
        .zip(out)
        .map(|(&x, p)| crate::statics::PointLoad { x, p })
        .collect())
}

/// A beam loaded indirectly through stringers (LH Aufgabe 6, Abb. 35): the stringers and cross
/// beams are drawn, the loads reach the beam at the panel points (by [`panel_loads`]), and the
/// beam is constructed under those. At every panel point the moment is checked once more
/// against the *direct* loading: the indirect moment area touches the direct one there.
///
/// # Errors
/// As [`construct_beam`](super::construct_beam), and for panel points that do not cover the loads.
pub fn construct_beam_indirect(
    b: &mut Board,
    beam: &Beam,
    panel_points: &[f64],
    dr: &BeamDrawing,
    req: &BeamRequest,
) -> Result<BeamResults, ConstructionError> {
    let frame = super::LocalFrame::of(beam);
    if frame.dx != 0.0 {
        let panels: Vec<f64> = panel_points.iter().map(|x| x - frame.dx).collect();
        let local = frame.to_local(beam);
        let r = construct_beam_indirect(b, &local, &panels, dr, req)?;
        return Ok(frame.to_global(r));
    }
    let loads = panel_loads(beam, panel_points)?;
    draw_stringers(b, beam, panel_points, dr);
    let on_beam = Beam {
        supports: beam.supports,
        ends: beam.ends,
        point_loads: loads,
        uniform_loads: vec![],
    };
    let r = construct_beam_at(b, &on_beam, dr, req, panel_points)?;
    check_cross_beams(b, beam, panel_points, &r);
    Ok(r)
}

/// Stringers and cross beams above the beam, the given loads on the stringers.
fn draw_stringers(b: &mut Board, beam: &Beam, panel_points: &[f64], dr: &BeamDrawing) {
    let k = 1000.0 / dr.length_scale;
    let (ox, oy) = (dr.origin.x, dr.origin.y);
    let sx = |x: f64| x * k + ox;
    // Stringers and cross beams above the beam, the given loads on the stringers.
    let mut tops = Vec::new();
    for &x in panel_points {
        let foot = b.point(Point::new(sx(x), oy), Role::Given, N_CROSS_BEAM);
        let top = b.point(
            Point::new(sx(x), oy + STRINGER_MM),
            Role::Given,
            N_CROSS_BEAM,
        );
        b.segment(&foot, &top, Role::Given, N_CROSS_BEAM);
        tops.push(top);
    }
    for w in tops.windows(2) {
        b.segment(&w[0], &w[1], Role::Given, N_STRINGER);
    }
    for l in &beam.point_loads {
        let at = b.point(
            Point::new(sx(l.x), oy + STRINGER_MM),
            Role::Given,
            N_PANEL_LOAD,
        );
        let tail = b.point(
            Point::new(sx(l.x), oy + STRINGER_MM + ARROW_MM * l.p.signum()),
            Role::Given,
            N_PANEL_LOAD,
        );
        b.segment(&tail, &at, Role::Force, N_PANEL_LOAD);
    }
    for (i, u) in beam.uniform_loads.iter().enumerate() {
        let h = 0.5 * ARROW_MM;
        let outline: Vec<H<Point>> = [(u.from, 0.0), (u.from, h), (u.to, h), (u.to, 0.0)]
            .iter()
            .map(|&(x, y)| H {
                id: crate::protocol::ObjId::NONE,
                g: Point::new(sx(x), oy + STRINGER_MM + y),
            })
            .collect();
        b.curve(
            &outline,
            Trace::Polygon,
            Role::Given.labelled(Label::indexed("q", i as u32 + 1)),
            N_PANEL_LOAD,
        );
    }
}

/// The indirect moment area touches the direct one at the cross beams: the moment at every
/// panel point checked against the direct loading.
fn check_cross_beams(b: &mut Board, beam: &Beam, panel_points: &[f64], r: &BeamResults) {
    let direct = cf::Sections::new(beam);
    let pref = r
        .sections
        .iter()
        .map(|s| s.moment.abs())
        .fold(0.0, f64::max)
        .max(1.0);
    for (s, h) in r.sections.iter().zip(&r.moment_handles) {
        if panel_points
            .iter()
            .any(|&p| (p - s.x).abs() <= REL_POSITION_EPS * (beam.ends[1] - beam.ends[0]).max(1.0))
        {
            b.check(
                h,
                "moment at a cross beam = moment of the direct load",
                "kg·m",
                "LH Abb. 35; method of sections",
                pref,
                || direct.moment(s.x),
            );
        }
    }
}
