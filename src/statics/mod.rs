//! Graphic statics (LH part I, section C): the funicular polygon and its use on beams —
//! support reactions by the closing line, the moment area M = y·H, the shear diagram, the
//! largest moment where the shear changes sign, and the parabola of a uniform load drawn by
//! its tangents.
//!
//! # Modules
//! - [`funicular`]: forces in the plane: the force polygon, resultant, couple, resolution
//!   (LH A, C.1-2), and [`funicular::polygon`], the one funicular polygon every procedure
//!   draws (pole and rays, strings, closing line);
//! - [`beam`]: beams by the funicular polygon (LH C.4-6, Aufgabe 6): reactions, moment area,
//!   shear, the parabola of a uniform load, indirect loading through stringers;
//! - [`centroid`]: the centroid of a polygon by two funicular polygons (LH C.3);
//! - [`shaft`]: moments in two planes, torque and the ideal moment (LH C.7-8);
//! - [`closed_form`]: the closed forms the checks compare with;
//! - [`sizing`]: diameters and heights from the allowed stress (LH Aufgabe 7).
//!
//! Positions along a beam are in m, forces in kg (the books' technical units), moments in
//! kg·m. Loads are positive downwards, reactions positive upwards, moments positive when they
//! sag the beam.

pub mod beam;
pub mod centroid;
pub mod closed_form;
pub mod funicular;
pub mod shaft;
pub mod sizing;

pub use beam::{
    construct_beam, construct_beam_at, construct_beam_indirect, panel_loads, BeamDrawing,
    BeamRequest, BeamResults, MaxMoment, Reactions, SectionRow, ShearRow,
};

use serde::Serialize;

/// A point load P (kg, positive downwards) at x (m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointLoad {
    /// Position along the beam (m).
    pub x: f64,
    /// Load (kg), positive downwards.
    pub p: f64,
}

/// A uniformly distributed load q (kg/m, positive downwards) from `from` to `to` (m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct UniformLoad {
    /// Start (m).
    pub from: f64,
    /// End (m), greater than `from`.
    pub to: f64,
    /// Intensity (kg/m), positive downwards.
    pub q: f64,
}

impl UniformLoad {
    /// Its resultant Q = q·(to − from) (kg).
    pub fn resultant(&self) -> f64 {
        self.q * (self.to - self.from)
    }
    /// Where the resultant acts: the middle (m).
    pub fn centre(&self) -> f64 {
        0.5 * (self.from + self.to)
    }
}

/// A beam on two supports (a pin and a roller), possibly with overhangs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Beam {
    /// Positions of the supports A and B (m), A left of B.
    pub supports: [f64; 2],
    /// Ends of the beam (m); the beam reaches at least over every support and load.
    pub ends: [f64; 2],
    /// Point loads.
    pub point_loads: Vec<PointLoad>,
    /// Uniform loads.
    pub uniform_loads: Vec<UniformLoad>,
}
