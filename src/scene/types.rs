//! The serde types of a scene. Doc comments here become the JSON Schema's descriptions.

use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A slider-crank scene: mechanism, speed, piston force, crank angles, effects and outputs.
    pub struct SliderCrankScene {
        /// The mechanism.
        pub mechanism: Mechanism,
        /// How fast the crank turns.
        pub speed: Speed,
        /// The driving piston force; required when a force is among the outputs.
        #[serde(default)]
        pub piston_force: Option<PistonForceSpec>,
        /// Which crank positions to construct.
        pub angles: AngleSpec,
        /// The physical effects to include.
        #[serde(default)]
        pub effects: Option<Effects>,
        /// What to construct; only what these depend on is constructed.
        pub outputs: Vec<CrankOutput>,
        /// Construction(s) of the piston path, default `["rod_arc"]`.
        #[serde(default)]
        pub piston_path_methods: Option<Vec<PistonPathMethod>>,
        /// Construction(s) of the piston velocity, default `["parallel"]`.
        #[serde(default)]
        pub velocity_methods: Option<Vec<VelocityMethod>>,
        /// Scales of the drawing; any left out are chosen to give a figure about 250 mm wide.
        #[serde(default)]
        pub drawing: Option<DrawingSpec>,
    }
}

/// The straight slider-crank (gerader Schubkurbeltrieb).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Mechanism {
    /// Crank radius R in mm (give this or `stroke_mm`).
    #[serde(default)]
    pub crank_radius_mm: Option<f64>,
    /// Piston stroke s = 2R in mm (give this or `crank_radius_mm`).
    #[serde(default)]
    pub stroke_mm: Option<f64>,
    /// The connecting rod.
    pub rod: Rod,
}

/// The connecting rod: its length, or its length in crank radii (the books' R/L = 1/5 is
/// `{"l_over_r": 5}`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum Rod {
    /// Rod length L in mm.
    #[serde(rename = "length_mm")]
    LengthMm(f64),
    /// L/R, the inverse of the books' Schubstangenverhältnis λ = R/L.
    #[serde(rename = "l_over_r")]
    LOverR(f64),
}

/// The speed of the crank.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum Speed {
    /// Revolutions per minute n.
    #[serde(rename = "rpm")]
    Rpm(f64),
    /// Crank-pin speed v in m/s.
    #[serde(rename = "crank_pin_m_s")]
    CrankPinMS(f64),
    /// A locomotive: train speed and driving-wheel diameter (LH Abb. 43: v = v₁·s/D₁).
    #[serde(rename = "train")]
    Train {
        /// Train speed in km/h.
        km_h: f64,
        /// Driving-wheel diameter D₁ in mm.
        wheel_diameter_mm: f64,
    },
}

/// The driving piston force P, positive when it pushes the piston the way it moves.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum PistonForceSpec {
    /// A constant force in kg.
    #[serde(rename = "kg")]
    Kg(f64),
    /// Pressure on a piston: P = π/4 (D² − d²) · p.
    #[serde(rename = "pressure")]
    Pressure(Pressure),
    /// One force in kg per crank angle, in the order of the angles.
    #[serde(rename = "per_angle_kg")]
    PerAngleKg(Vec<f64>),
}

/// Pressure on a piston.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Pressure {
    /// Net pressure p in at (kg/cm²).
    pub at: f64,
    /// Cylinder bore D in mm.
    pub bore_mm: f64,
    /// Diameter d of a piston rod passing through this side, mm (default 0).
    #[serde(default)]
    pub rod_diameter_mm: f64,
}

impl Pressure {
    /// P = π/4 (D² − d²) · p, with D and d in cm.
    pub fn force_kg(&self) -> f64 {
        let (d, dr) = (self.bore_mm / 10.0, self.rod_diameter_mm / 10.0);
        std::f64::consts::PI / 4.0 * (d * d - dr * dr) * self.at
    }
}

/// Crank positions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub enum AngleSpec {
    /// Divide the crank circle into n equal parts from the inner dead centre (2 ≤ n ≤ 3600).
    #[serde(rename = "divisions")]
    Divisions(usize),
    /// Crank angles θ in degrees from the inner dead centre, 0 ≤ θ < 360; θ < 180 is the
    /// outstroke (Hingang), θ ≥ 180 the return stroke (Rückgang).
    #[serde(rename = "degrees")]
    Degrees(Vec<f64>),
    /// The stroke divided into n equal parts (LH: 10, giving 11 ordinates per stroke) and the
    /// crank rays found by arcs with the rod length through the division points (LH C.2,
    /// Abb. 59): 2n rays, 1 ≤ n ≤ 1800.
    #[serde(rename = "stroke_parts")]
    StrokeParts(usize),
}

/// Physical effects to include.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Effects {
    /// Finite rod length (default true); false treats the rod as infinitely long
    /// (LH Gl. 23, Abb. 48, 54; KG (289)).
    #[serde(default = "yes")]
    pub finite_rod: bool,
}

fn yes() -> bool {
    true
}

impl Default for Effects {
    fn default() -> Self {
        Effects { finite_rod: true }
    }
}

super::header::output_enum! {
    /// An output of the slider-crank procedures.
    pub enum CrankOutput {
        /// Piston path by the arc with the rod length (KG Abb. 1047, LH Abb. 49).
        PistonPath = "piston_path",
        /// Piston velocity (KG Abb. 1049, LH Abb. 53), by the `velocity_methods`.
        Velocity = "velocity",
        /// Rod force S (LH Abb. 61, KG (300)).
        RodForce = "rod_force",
        /// Guide force N (LH Abb. 61, KG (301)).
        GuideForce = "guide_force",
        /// Tangential force T (LH Abb. 65, KG Abb. 1063).
        TangentialForce = "tangential_force",
        /// Radial crank-pin force K (LH Abb. 61, KG (302)).
        RadialForce = "radial_force",
        /// Piston acceleration over the stroke by Tolle's parabola, outstroke and return
        /// (LH Abb. 55-57, KG Abb. 1050).
        Acceleration = "acceleration",
        /// Esselborn's construction of the crank angle of the largest piston velocity (LH Abb. 52),
        /// beside the exact maximum and the book's 79°16'.
        MaxVelocity = "max_velocity",
        /// The polar net-pressure diagram and the polar turning-force diagram on the crank rays
        /// (LH C.2, F, Abb. 59), with the tangential force they need.
        PolarDiagrams = "polar_diagrams",
    }
}

impl CrankOutput {
    /// Whether the output is a force (needs `piston_force`).
    pub fn is_force(&self) -> bool {
        matches!(
            self,
            CrankOutput::RodForce
                | CrankOutput::GuideForce
                | CrankOutput::TangentialForce
                | CrankOutput::RadialForce
                | CrankOutput::PolarDiagrams
        )
    }
}

/// A construction of the piston path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PistonPathMethod {
    /// The arc with the rod length about each crank pin (KG Abb. 1047, LH Abb. 46).
    RodArc,
    /// One arc drawn once about the crosshead's dead position, cut by the horizontal through
    /// each pin (LH Abb. 49).
    FixedArc,
}

/// A construction of the piston velocity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum VelocityMethod {
    /// Parallel to the rod through the end of v laid off on the crank ray (KG Abb. 1049).
    Parallel,
    /// The rod line cuts y on the vertical through O, c = ω·y (LH Abb. 53).
    InstantCentre,
}

/// Scales of the drawing. Any left out are chosen (1, 2, 2.5 or 5 times a power of ten).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct DrawingSpec {
    /// Length scale 1 : n, machine mm per mm of sheet.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm of sheet (LH: "1 mm = 200 kg").
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
    /// Velocity scale, m/s per mm of sheet.
    #[serde(default)]
    pub velocity_scale_m_s_per_mm: Option<f64>,
    /// Acceleration scale, m/s² per mm of sheet (LH Abb. 55: 1 cm = 150 m/s² is 15).
    #[serde(default)]
    pub acceleration_scale_m_s2_per_mm: Option<f64>,
}
