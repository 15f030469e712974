//! The beam construction's drawing choices and named results.

use crate::kernel::Point;
use crate::protocol::H;
use serde::Serialize;

/// Length of a load arrow in the position plan (mm): the plan shows position and sense only.
pub(super) const ARROW_MM: f64 = 12.0;
/// Gap between the beam and the force plan, and between the figure's parts (mm).
pub(super) const GAP_MM: f64 = 25.0;
/// Half width of a drawn support (mm).
pub(super) const SUPPORT_MM: f64 = 4.0;

/// Scales and choices of the drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BeamDrawing {
    /// Length scale 1 : n (m of beam per m of sheet).
    pub length_scale: f64,
    /// kg per mm of sheet.
    pub force_scale: f64,
    /// Pole distance H (kg).
    pub pole_distance: f64,
    /// Equal parts each tangent of a uniform load's parabola is divided into (≥ 2).
    pub parabola_divisions: usize,
    /// Where x = 0 of the beam lies on the sheet (mm), so that several beams (the two planes
    /// of a shaft) can share one sheet.
    pub origin: Point,
}

crate::protocol::request_set! {
    /// What a beam scene can ask for (its `outputs`); the reactions, which everything
    /// needs, are always constructed.
    pub struct BeamRequest as "BeamOutput" {
        /// The reactions by the closing line: always constructed, named or not.
        reactions,
        /// The moment area M = y·H: M at every load, support and parabola point, zero
        /// moments.
        moment_area,
        /// The shear diagram and the largest moment where the shear changes sign.
        shear_diagram,
    }
}

/// Constructed values at one section of the beam.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionRow {
    /// Position (m).
    pub x: f64,
    /// What is there ("P1", "A", "q1 2/8").
    pub what: String,
    /// Bending moment (kg·m).
    pub moment: f64,
}

/// The support reactions read off the force plan (kg, positive upwards).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Reactions {
    /// Reaction A, at the left support.
    pub a: f64,
    /// Reaction B, at the right support.
    pub b: f64,
}

/// The shear force on either side of an event of the beam (an end, a support, a load, the
/// end of a uniform load).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShearRow {
    /// Position (m).
    pub x: f64,
    /// Shear just left of x (kg); zero left of the beam's left end.
    pub left: f64,
    /// Shear just right of x (kg); zero right of the beam's right end.
    pub right: f64,
}

/// The largest bending moment in magnitude, found where the shear changes sign (LH C.6).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaxMoment {
    /// The moment (kg·m), with its sign.
    pub moment: f64,
    /// Where it acts (m).
    pub x: f64,
}

/// The results of [`construct_beam`](super::construct_beam).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BeamResults {
    /// Reactions A and B (kg).
    pub reactions: Reactions,
    /// Moments at the sections, ordered by x.
    pub sections: Vec<SectionRow>,
    /// Zero moments between the supports (m).
    pub zero_moments: Vec<f64>,
    /// The shear on both sides of each event, if the shear diagram was asked for.
    pub shear: Vec<ShearRow>,
    /// Largest |M| and where, if the shear diagram was asked for.
    pub max_moment: Option<MaxMoment>,
    /// The measured moment of each section, in the order of `sections`, for further checks.
    #[serde(skip)]
    pub moment_handles: Vec<H<f64>>,
}
