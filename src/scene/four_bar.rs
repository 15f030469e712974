//! The four-bar scene (`"procedure": "four_bar"`, KG XIV, Abb. 1043, 1045): the crank-rocker
//! and the parallel crank.

use super::error::SceneError;
use super::fields::Fields;
use super::procedure::ReadContext;
use super::types::AngleSpec;
use crate::mechanisms::four_bar::{self, Assembly, FourBar, FourBarRequest, FourBarResults};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A four-bar linkage driven by its crank: `"procedure": "four_bar"`.
    pub struct FourBarScene {
        /// The link lengths.
        pub links: LinksSpec,
        /// Which closure B takes: `left` (default) or `right` of the ray from the pin to the
        /// rocker's pivot A, or `parallel` (a parallel crank's parallelogram).
        #[serde(default)]
        pub assembly: Option<Assembly>,
        /// Crank angles (`divisions` or `degrees`), counter-clockwise from OA.
        pub angles: AngleSpec,
        /// What to construct besides the positions: `dead_positions`, `transmission`.
        #[serde(default)]
        pub outputs: FourBarRequest,
        /// The transmission angle below which a position is flagged (degrees, default 40).
        #[serde(default)]
        pub min_transmission_deg: Option<f64>,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<FourBarDrawingSpec>,
    }
}

/// The link lengths of a four-bar (mm).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LinksSpec {
    /// Frame OA, the distance of the two pivots.
    pub frame_mm: f64,
    /// Crank OP.
    pub crank_mm: f64,
    /// Coupler PB.
    pub coupler_mm: f64,
    /// Rocker AB.
    pub rocker_mm: f64,
}

/// Scales of a four-bar scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct FourBarDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
}

/// A validated four-bar scene.
#[derive(Debug, Clone, PartialEq)]
pub struct FourBarProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The linkage.
    pub linkage: FourBar,
    /// Length scale 1 : n.
    pub length_scale: f64,
    /// Crank angles (degrees).
    pub thetas: Vec<f64>,
    /// What to construct.
    pub request: FourBarRequest,
}

impl FourBarScene {
    fn linkage(&self) -> FourBar {
        let l = &self.links;
        FourBar {
            frame: l.frame_mm,
            crank: l.crank_mm,
            coupler: l.coupler_mm,
            rocker: l.rocker_mm,
            assembly: self.assembly.unwrap_or(Assembly::Left),
            min_transmission: self.min_transmission_deg.unwrap_or(40.0),
        }
    }

    /// The linkage, every value checked.
    fn checked_linkage(&self, origin: &str) -> Result<FourBar, SceneError> {
        let f = Fields { origin };
        for (name, v) in [
            ("links.frame_mm", self.links.frame_mm),
            ("links.crank_mm", self.links.crank_mm),
            ("links.coupler_mm", self.links.coupler_mm),
            ("links.rocker_mm", self.links.rocker_mm),
        ] {
            f.positive(name, v)?;
        }
        let linkage = self.linkage();
        if let Err(e) = linkage.validate() {
            let (input, reason) = e.describe();
            let field = match input {
                "assembly" => "assembly".to_string(),
                link => format!("links.{link}_mm"),
            };
            return Err(f.bad(&field, reason));
        }
        if let Some(m) = self.min_transmission_deg {
            if !(m.is_finite() && (0.0..=90.0).contains(&m)) {
                return Err(f.bad(
                    "min_transmission_deg",
                    format!("must lie in [0°, 90°], got {m}"),
                ));
            }
        }
        self.angles.check_divisions_or_degrees(f)?;
        if let Some(s) = self.drawing.and_then(|d| d.length_scale) {
            f.positive("drawing.length_scale", s)?;
        }
        Ok(linkage)
    }

    /// The problem of checked values, with the length scale chosen where none is given: the
    /// frame about 100 mm.
    fn to_problem(&self, linkage: FourBar) -> FourBarProblem {
        let nice = super::defaults::nice_at_least;
        let reach = linkage.frame + linkage.crank.max(linkage.rocker);
        let thetas = self.angles.degrees();
        FourBarProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            linkage,
            length_scale: self
                .drawing
                .and_then(|d| d.length_scale)
                .unwrap_or_else(|| nice(reach / 100.0)),
            thetas,
            request: self.outputs,
        }
    }
}

impl super::Procedure for FourBarScene {
    const NAME: &'static str = "four_bar";
    const SIZED_BY: &'static str = "angles (crank positions)";
    const ABOUT: &'static str = "the crank-rocker (Bogenschubkurbel) and the parallel crank: positions by two circles with the branch named, the rocker's dead positions, the transmission angle flagged below a limit, Grashof's rule (KG XIV, Abb. 1043, 1045)";
    const OUTPUTS: &'static [&'static str] = FourBarRequest::NAMES;
    const GEOMETRY_FIELD: &'static str = "links";
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("frame", "links.frame_mm"),
        ("crank", "links.crank_mm"),
        ("coupler", "links.coupler_mm"),
        ("rocker", "links.rocker_mm"),
    ];
    type Problem = FourBarProblem;
    type Results = FourBarResults;

    fn sheet_extent(p: &FourBarProblem) -> (f64, &'static str) {
        let k = &p.linkage;
        (
            (k.frame + k.coupler + k.crank + k.rocker) / p.length_scale,
            "drawing.length_scale",
        )
    }
    fn smallest_part(p: &FourBarProblem) -> Option<(f64, &'static str)> {
        let k = &p.linkage;
        let s = k.crank.min(k.rocker).min(k.frame).min(k.coupler);
        Some((s / p.length_scale, "drawing.length_scale"))
    }
    fn problem(&self, ctx: &ReadContext) -> Result<FourBarProblem, SceneError> {
        Ok(self.to_problem(self.checked_linkage(ctx.origin)?))
    }
    fn construct(
        p: &FourBarProblem,
        config: BoardConfig,
    ) -> Result<(Board, FourBarResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = four_bar::construct(&mut board, &p.linkage, p.length_scale, &p.thetas, p.request)?;
        Ok((board, r))
    }
    fn figure_meta(p: &FourBarProblem) -> FigureMeta {
        FigureMeta {
            title: p.title.clone(),
            source: p.source.clone(),
            scales: vec![ScaleBar::length(p.length_scale, "m")],
            plate: Vec::new(),
        }
    }
}
