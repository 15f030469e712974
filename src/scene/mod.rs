//! The scene format: what a user writes to get a figure.
//!
//! A scene is JSON (unknown fields are rejected) naming the mechanism, its speed and piston
//! force, the crank angles, the physical **effects** to include and the **outputs** wanted.
//! Only the constructions the outputs depend on are made ("simulate only what the scene calls
//! for"). `graphostatik schema` prints the JSON Schema of this format.
//!
//! ```
//! use graphostatik::scene::{Procedure, SliderCrankScene};
//! let (scene, problem) = SliderCrankScene::read(r#"{
//!   "title": "KG Tafel I",
//!   "mechanism": { "crank_radius_mm": 400, "rod": { "length_mm": 2000 } },
//!   "speed": { "rpm": 50 },
//!   "angles": { "divisions": 12 },
//!   "outputs": ["piston_path"]
//! }"#, "inline").unwrap();
//! assert_eq!(scene.title, "KG Tafel I");
//! assert_eq!(problem.drive.lambda(), 0.2);
//! assert!(problem.request.piston_path && !problem.request.tangential_force);
//! ```

mod accuracy;
mod beam;
mod book;
mod centroid;
mod combustion;
mod crank_dynamics;
mod defaults;
mod drafting;
mod error;
mod fields;
mod force_system;
mod four_bar;
mod handles;
mod header;
mod offset_crank;
mod procedure;
#[cfg(feature = "schema")]
mod reference;
mod registry;
mod scan;
mod scotch_yoke;
mod shaft;
mod slider_crank;
mod slotted_link;
mod sweep;
mod truss;
mod types;

pub use accuracy::sweeps;
pub use beam::{
    BeamDrawingSpec, BeamProblem, BeamScene, BeamSpec, PointLoadSpec, UniformLoadSpec, MAX_LOADS,
};
pub use book::{book_rows, book_table, sheet_rows, BookRow, BookValue, Verdict, SHEET_BOOK_ROWS};
pub use centroid::{CentroidDrawingSpec, CentroidProblem, CentroidScene};
pub use combustion::{
    CombustionProblem, CombustionScene, GasCylindersSpec, GasDrawingSpec, GasEffects, GasSpec,
};
pub use crank_dynamics::{
    CardSpec, CylinderSpec, DynamicsDrawingSpec, DynamicsEffects, DynamicsProblem, DynamicsScene,
    FlywheelSpec, IndicatorSpec, MassSpec, PointsSpec, SidePoints, SteamSpec, Weights,
};
pub use drafting::{
    drafting, drafting_with_progress, DraftedValue, DraftingOptions, DraftingReport,
    MAX_DRAFTING_STEPS,
};
pub use error::SceneError;
pub use force_system::{
    ForceDrawingSpec, ForceSpec, ForceSystemProblem, ForceSystemScene, ResolveSpec,
};
pub use four_bar::{FourBarDrawingSpec, FourBarProblem, FourBarScene, LinksSpec};
pub use handles::{handles, Drag, Handle};
pub use header::{Preview, Slider};
pub use offset_crank::{OffsetDrawingSpec, OffsetProblem, OffsetScene};
pub use procedure::{
    parse_scene, scene_field, Procedure, ReadContext, SceneHeader, SchemaType, Spread, MAX_SHEET_MM,
};
#[cfg(feature = "schema")]
pub use reference::reference_markdown;
#[cfg(feature = "schema")]
pub use registry::schema_json;
pub use registry::{AnyProblem, AnyScene, Entry, MAX_FIGURE_STEPS, REGISTRY};
pub use scotch_yoke::{YokeCrank, YokeDrawingSpec, YokeProblem, YokeScene};
pub use shaft::{ShaftProblem, ShaftScene, TorqueSpec};
pub use slider_crank::SliderCrankProblem;
pub use slotted_link::{LinkDrawingSpec, LinkProblem, LinkScene, LinkSpec};
pub use sweep::{Setting, Sweep, SweepPoint, MAX_SWEEP_STEPS};
pub use truss::{PositionTable, TrussProblem, TrussScene};
pub use types::*;
