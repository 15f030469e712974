//! The slotted-link scene (`"procedure": "slotted_link"`, KG XIV, Abb. 1071-1072).

use super::error::SceneError;
use super::fields::Fields;
use super::procedure::ReadContext;
use super::types::{AngleSpec, Speed};
use crate::mechanisms::slotted_link::{self, LinkRequest, LinkResults, LinkScales, SlottedLink};
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// An oscillating slotted link (quick return): `"procedure": "slotted_link"`.
    pub struct LinkScene {
        /// The link's lengths.
        pub link: LinkSpec,
        /// The crank's speed (`rpm` or `crank_pin_m_s`).
        pub speed: Speed,
        /// Crank positions: `divisions` or `degrees`, from the start of the working stroke
        /// (the lever's outer position), counter-clockwise.
        pub angles: AngleSpec,
        /// What to draw besides the positions and the angles: `velocity`, the table speed by
        /// KG's parallel through F, its diagram over the stroke, and c₁, c₂.
        #[serde(default)]
        pub outputs: LinkRequest,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<LinkDrawingSpec>,
    }
}

/// The lengths of an oscillating slotted link (KG Abb. 1071), in mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LinkSpec {
    /// Crank radius r = MC.
    pub crank_radius_mm: f64,
    /// Distance e = MD from the crank's centre to the lever's pivot (more than r).
    pub centre_distance_mm: f64,
    /// Lever length R = DE (at least e + r).
    pub lever_mm: f64,
}

/// Scales of a slotted-link scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct LinkDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Velocity scale, m/s per mm of sheet.
    #[serde(default)]
    pub velocity_scale_m_s_per_mm: Option<f64>,
}

/// A validated slotted-link scene.
#[derive(Debug, Clone, PartialEq)]
pub struct LinkProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The link.
    pub link: SlottedLink,
    /// Length scale 1 : n and velocity scale (m/s per mm).
    pub scales: LinkScales,
    /// Crank angles from the start of the working stroke (degrees).
    pub phis: Vec<f64>,
    /// What to draw.
    pub request: LinkRequest,
}

impl LinkScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let f = Fields { origin };
        let l = &self.link;
        f.positive("link.crank_radius_mm", l.crank_radius_mm)?;
        f.positive("link.centre_distance_mm", l.centre_distance_mm)?;
        f.positive("link.lever_mm", l.lever_mm)?;
        if l.centre_distance_mm <= l.crank_radius_mm {
            return Err(f.bad("link.centre_distance_mm", format!(
                "must exceed the crank radius {} mm, got {}: the lever's pivot D must lie outside the crank circle (at e = r the return speed c₂ = vR/(e − r) of KG 305 is infinite)",
                l.crank_radius_mm, l.centre_distance_mm)));
        }
        let reach = l.centre_distance_mm + l.crank_radius_mm;
        if l.lever_mm < reach {
            return Err(f.bad("link.lever_mm", format!(
                "must be at least e + r = {} mm, got {}: the pin would leave the slot at the top of the crank circle",
                reach, l.lever_mm)));
        }
        self.speed.check(f)?;
        self.angles.check_divisions_or_degrees(f)?;
        if let Some(d) = &self.drawing {
            for (name, v) in [
                ("drawing.length_scale", d.length_scale),
                (
                    "drawing.velocity_scale_m_s_per_mm",
                    d.velocity_scale_m_s_per_mm,
                ),
            ] {
                if let Some(v) = v {
                    f.positive(name, v)?;
                }
            }
        }
        Ok(())
    }

    /// The problem the scene describes, with the scales chosen where none are given: the
    /// lever about 100 mm long, c₂ about 40 mm.
    fn to_problem(&self) -> LinkProblem {
        let l = &self.link;
        let r = l.crank_radius_mm;
        let link = SlottedLink {
            crank_radius: r,
            centre_distance: l.centre_distance_mm,
            lever_length: l.lever_mm,
            crank_pin_speed: self.speed.crank_pin_speed(r),
        };
        let d = self.drawing.unwrap_or(LinkDrawingSpec {
            length_scale: None,
            velocity_scale_m_s_per_mm: None,
        });
        let nice = super::defaults::nice_at_least;
        let phis = self.angles.degrees();
        LinkProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            link,
            scales: LinkScales {
                length: d.length_scale.unwrap_or_else(|| nice(l.lever_mm / 100.0)),
                velocity: d
                    .velocity_scale_m_s_per_mm
                    .unwrap_or_else(|| nice(link.c2() / 40.0)),
            },
            phis,
            request: self.outputs,
        }
    }
}

impl super::Procedure for LinkScene {
    const NAME: &'static str = "slotted_link";
    const SIZED_BY: &'static str = "angles (crank positions) or outputs";
    const ABOUT: &'static str = "the oscillating slotted link (schwingende Kurbelschleife, quick return): working and return angles, β/α, the table's path and speed by the parallel through F, c₁ and c₂ (KG XIV, Abb. 1071-1072, eq. 304-305)";
    const OUTPUTS: &'static [&'static str] = LinkRequest::NAMES;
    const GEOMETRY_FIELD: &'static str = "link";
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[
        ("centre_distance", "link.centre_distance_mm"),
        ("lever_length", "link.lever_mm"),
        ("crank_radius", "link.crank_radius_mm"),
    ];
    type Problem = LinkProblem;
    type Results = LinkResults;

    fn sheet_extent(p: &LinkProblem) -> (f64, &'static str) {
        let (ls, vs) = (p.scales.length, p.scales.velocity);
        let length = 2.0 * p.link.lever_length / ls;
        let speed = 2.0 * p.link.c2() / vs;
        if speed > length && p.request.velocity {
            (speed, "drawing.velocity_scale_m_s_per_mm")
        } else {
            (length, "drawing.length_scale")
        }
    }
    fn smallest_part(p: &LinkProblem) -> Option<(f64, &'static str)> {
        let (ls, vs) = (p.scales.length, p.scales.velocity);
        let crank = (p.link.crank_radius / ls, "drawing.length_scale");
        let speed = (p.link.c1() / vs, "drawing.velocity_scale_m_s_per_mm");
        Some(if p.request.velocity && speed.0 < crank.0 {
            speed
        } else {
            crank
        })
    }
    fn spread(p: &LinkProblem) -> Option<super::procedure::Spread> {
        let (e, r) = (p.link.centre_distance, p.link.crank_radius);
        p.request.velocity.then(|| super::procedure::Spread {
            ratio: (e + r) / (e - r),
            between: "the return speed c₂ and the working speed c₁ (c₂/c₁ = (e + r)/(e − r))",
            field: "link.centre_distance_mm",
        })
    }
    fn problem(&self, ctx: &ReadContext) -> Result<LinkProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        p: &LinkProblem,
        config: BoardConfig,
    ) -> Result<(Board, LinkResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = slotted_link::construct(&mut board, &p.link, p.scales, &p.phis, p.request)?;
        Ok((board, r))
    }
    fn figure_meta(p: &LinkProblem) -> FigureMeta {
        let mut scales = vec![ScaleBar::length(p.scales.length, "m")];
        if p.request.velocity {
            scales.push(ScaleBar::velocity(p.scales.velocity));
        }
        FigureMeta {
            title: p.title.clone(),
            source: p.source.clone(),
            scales,
            plate: Vec::new(),
        }
    }
}
