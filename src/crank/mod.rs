//! The straight slider-crank (*gerader Schubkurbeltrieb*): piston path, piston velocity and the
//! forces in rod, guide and crank pin, constructed with ruler and compass (LH II.B–E,
//! KG XIV B.1–4) and checked against the closed forms of [`closed_form`].
//!
//! # Conventions
//! The crank shaft O is at the origin of the sheet, the piston line (*Kolbenweglinie*) is the
//! x axis, the cylinder lies to the left. The full crank angle θ counts from the inner dead
//! centre (crank pointing to the cylinder, θ = 0) and the crank pin runs over the upper half
//! during the outstroke (θ < 180°), so the crosshead moves in +x. Signed results:
//! piston path x from the inner dead centre; piston velocity c in +x; rod force S positive in
//! compression; guide force N positive on the lower guide; tangential force T positive when it
//! drives the shaft; radial force K positive towards the shaft.
//!
//! # Lazy evaluation
//! [`construct`] builds only what the [`Request`] asks for: each quantity is a method that first
//! demands the constructions it depends on (memoised per crank angle), so a request for the
//! piston path alone draws no velocity and no force steps.
//!
//! ```
//! use graphostatik::crank::*;
//! use graphostatik::protocol::{Board, Topic};
//! let drive = CrankDrive { crank_radius: 400.0, rod_length: 2000.0, finite_rod: true,
//!     crank_pin_speed: 2.094, piston_force: PistonForce::Constant(1000.0) };
//! let drawing = Drawing { length_scale: 20.0, force_scale: 50.0, velocity_scale: 0.1,
//!     acceleration_scale: 1.0 };
//! let request = Request { piston_path: true, ..Request::default() };
//! let mut board = Board::recording().with_figure_size(200.0);
//! let res = construct(&mut board, &drive, &drawing, &Angles::Divisions(12), &request).unwrap();
//! // KG (285): at φ = 90° on the outstroke x = R + L(1 − cos ψ).
//! let x = res.rows[3].x.unwrap();
//! assert!((x - (400.0 + 2000.0 * (1.0 - (1.0f64 - 0.04).sqrt()))).abs() < 1e-9);
//! assert!(board.steps().iter().all(|s| s.topic != Topic::Forces && s.topic != Topic::Velocity));
//! assert!(board.steps().iter().flat_map(|s| &s.checks).all(|c| c.passed));
//! ```

pub mod closed_form;
mod construction;
pub(crate) mod tolle;

pub use construction::{
    close_over_turn, construct, construct_at, position_name, position_pen, shown_position,
    spans_full_turn, AngleRow, CrankResults, MaxVelocity,
};

use serde::Serialize;

/// The mechanism and its state of motion, in machine units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CrankDrive {
    /// Crank radius R (mm).
    pub crank_radius: f64,
    /// Rod length L (mm); ignored when `finite_rod` is false.
    pub rod_length: f64,
    /// The effect "finite rod length": false treats the rod as infinitely long
    /// (LH Gl. 23, Abb. 48, 54, 60; KG (289), (295)).
    pub finite_rod: bool,
    /// Crank-pin speed v (m/s).
    pub crank_pin_speed: f64,
    /// The driving piston force P (kg).
    pub piston_force: PistonForce,
}

impl CrankDrive {
    /// The centripetal acceleration of the crank pin v²/R (m/s²), the unit of the piston
    /// acceleration (KG 291: "v²/R = ω²R").
    pub fn v2_over_r(&self) -> f64 {
        self.crank_pin_speed * self.crank_pin_speed / (self.crank_radius / 1000.0)
    }

    /// R/L, 0 for the infinitely long rod.
    pub fn lambda(&self) -> f64 {
        if self.finite_rod {
            self.crank_radius / self.rod_length
        } else {
            0.0
        }
    }

    /// The rod length, `None` for the infinitely long rod.
    pub fn rod(&self) -> Option<f64> {
        self.finite_rod.then_some(self.rod_length)
    }

    /// Angular speed ω = v/R (1/s).
    pub fn omega(&self) -> f64 {
        self.crank_pin_speed / (self.crank_radius / 1000.0)
    }
}

/// The driving piston force: positive when it pushes the piston the way it moves.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PistonForce {
    /// The same force at every crank angle (kg), e.g. full admission pressure × piston area.
    Constant(f64),
    /// One force per crank angle (kg), in the order of the angles (from a net-pressure diagram).
    PerAngle(Vec<f64>),
}

impl PistonForce {
    /// The force at the `i`-th crank angle.
    pub fn at(&self, i: usize) -> f64 {
        match self {
            PistonForce::Constant(p) => *p,
            PistonForce::PerAngle(v) => v.get(i).copied().unwrap_or(0.0),
        }
    }

    /// The largest |P| (kg).
    pub fn max_abs(&self) -> f64 {
        match self {
            PistonForce::Constant(p) => p.abs(),
            PistonForce::PerAngle(v) => v.iter().fold(0.0f64, |m, p| m.max(p.abs())),
        }
    }
}

/// The scales of the drawing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Drawing {
    /// Machine mm per mm of sheet (10 means 1 : 10).
    pub length_scale: f64,
    /// kg per mm of sheet (the book's "1 mm = 200 kg").
    pub force_scale: f64,
    /// m/s per mm of sheet.
    pub velocity_scale: f64,
    /// m/s² per mm of sheet (LH Abb. 55: 1 cm = 150 m/s², i.e. 15).
    pub acceleration_scale: f64,
}

/// Which crank positions to construct.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Angles {
    /// The crank circle divided into n equal parts from the inner dead centre.
    Divisions(usize),
    /// Crank angles θ in degrees from the inner dead centre, each in [0, 360).
    Degrees(Vec<f64>),
    /// The stroke divided into n equal parts and the crank pin found from each division point
    /// by the arc with the rod length (LH C.2, Abb. 59; a perpendicular for the infinite rod,
    /// Abb. 60): 2n rays, the outstroke's n + 1 then the return stroke's n − 1.
    StrokeParts(usize),
}

impl Angles {
    /// The crank angles θ in degrees for the drive (the stroke parts depend on R and L).
    pub fn thetas(&self, drive: &CrankDrive) -> Vec<f64> {
        match self {
            Angles::Divisions(n) => (0..*n).map(|k| 360.0 * k as f64 / *n as f64).collect(),
            Angles::Degrees(v) => v.clone(),
            Angles::StrokeParts(n) => {
                let (r, rod) = (drive.crank_radius, drive.rod());
                let out: Vec<f64> = (0..=*n)
                    .map(|k| closed_form::crank_angle_at(r, rod, 2.0 * r * k as f64 / *n as f64))
                    .collect();
                let back = out[1..*n].iter().rev().map(|t| 360.0 - t);
                out.iter().copied().chain(back).collect()
            }
        }
    }
}

/// What to construct. Each flag pulls in only the constructions it depends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct Request {
    /// Piston path by the arc with the rod length about each crank pin (KG Abb. 1047, LH Abb. 46).
    pub piston_path: bool,
    /// Piston path by one arc with the rod length drawn once about the crosshead's dead
    /// position and cut by the horizontal through each pin (LH Abb. 49).
    pub piston_path_fixed_arc: bool,
    /// Piston velocity by the parallel to the rod through the end of v (KG Abb. 1049).
    pub velocity_parallel: bool,
    /// Piston velocity by the instantaneous centre, c = ω·y (LH Abb. 53).
    pub velocity_instant_centre: bool,
    /// Rod force S (LH Abb. 61, Aufgabe 1 / Abb. 30; KG Abb. 1061).
    pub rod_force: bool,
    /// Guide force N (same parallelogram).
    pub guide_force: bool,
    /// Tangential force T by the parallel to the rod through the end of P on the crank ray
    /// (LH Abb. 65, KG Abb. 1063).
    pub tangential_force: bool,
    /// Radial crank-pin force K by resolving S along the crank and its normal (LH Abb. 61).
    pub radial_force: bool,
    /// Piston acceleration over the stroke by Tolle's parabola, outstroke and return
    /// (LH Abb. 55-57, KG Abb. 1050).
    pub acceleration: bool,
    /// Esselborn's construction of the crank angle of the largest piston velocity
    /// (LH Abb. 52), beside the exact maximum and the book's 79°16'.
    pub max_velocity: bool,
    /// With the tangential force: the polar net-pressure diagram (the ends of P on the crank
    /// rays joined, LH Abb. 59) and the polar turning-force diagram (T laid off on each ray
    /// from the crank circle, outside when it drives, LH F, Abb. 59).
    pub polar_diagrams: bool,
}
