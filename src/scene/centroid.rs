//! The centroid scene: a polygon whose centroid is found by two funicular polygons
//! (LH C.3, Abb. 23).

use super::defaults::nice_at_least;
use super::error::SceneError;
use super::fields::optional_positive;
use super::procedure::ReadContext;
use crate::kernel::Point;
use crate::protocol::{Board, BoardConfig, ConstructionError, FigureMeta, ScaleBar};
use crate::statics::centroid::{self, CentroidDrawing, CentroidResults};
use serde::{Deserialize, Serialize};

super::header::scene_struct! {
    /// A centroid scene: `"procedure": "centroid"`.
    pub struct CentroidScene {
        /// The vertices [x, y] (m), in order round the polygon; it must not cross itself.
        pub polygon_m: Vec<[f64; 2]>,
        /// The vertex (from 0) the triangles fan out from; default 0.
        #[serde(default)]
        pub fan_from: usize,
        /// Scales; any left out are chosen.
        #[serde(default)]
        pub drawing: Option<CentroidDrawingSpec>,
    }
}

/// Scales of a centroid scene.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct CentroidDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Area scale, m² per mm of sheet.
    #[serde(default)]
    pub area_scale_m2_per_mm: Option<f64>,
}

/// A validated centroid scene.
#[derive(Debug, Clone, PartialEq)]
pub struct CentroidProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// Vertices (m).
    pub polygon: Vec<Point>,
    /// Scales.
    pub drawing: CentroidDrawing,
}

impl CentroidScene {
    fn check_values(&self, origin: &str) -> Result<(), SceneError> {
        let bad = |field: &str, message: String| SceneError::Invalid {
            origin: origin.to_string(),
            field: field.to_string(),
            message,
        };
        let n = self.polygon_m.len();
        if !(3..=1000).contains(&n) {
            return Err(bad("polygon_m", format!("{n} vertices: give 3 to 1000")));
        }
        for (i, p) in self.polygon_m.iter().enumerate() {
            if !p.iter().all(|v| v.is_finite()) {
                return Err(bad(
                    &format!("polygon_m[{i}]"),
                    "must be finite numbers".into(),
                ));
            }
            if *p == self.polygon_m[(i + 1) % n] {
                return Err(bad(
                    &format!("polygon_m[{i}]"),
                    "repeats the next vertex".into(),
                ));
            }
        }
        if let Some((i, j)) = centroid::self_intersection(&self.points()) {
            return Err(bad(
                "polygon_m",
                format!(
                    "the polygon crosses itself: edge {i}-{} meets edge {j}-{}",
                    (i + 1) % n,
                    (j + 1) % n
                ),
            ));
        }
        let pts = self.points();
        let size = pts
            .iter()
            .flat_map(|a| pts.iter().map(move |b| (a - b).norm()))
            .fold(0.0, f64::max);
        let area = centroid::polygon_centroid(&pts).map_or(0.0, |(a, _)| a);
        // The construction leaves out fan triangles thinner than REL_AREA_EPS of the size²:
        // a polygon that is all such slivers has nothing to construct.
        if area <= crate::kernel::tolerance::REL_AREA_EPS * size * size {
            return Err(bad(
                "polygon_m",
                format!(
                    "the polygon has (next to) zero area: {} m² for a size of {} m",
                    crate::fmt::sci(area),
                    crate::fmt::num(size, 6)
                ),
            ));
        }
        if self.fan_from >= n {
            return Err(bad("fan_from", format!("vertex {} of {n}", self.fan_from)));
        }
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.area_scale_m2_per_mm", d.area_scale_m2_per_mm),
                ],
            )?;
        }
        Ok(())
    }

    /// The vertices as points (m).
    fn points(&self) -> Vec<Point> {
        self.polygon_m
            .iter()
            .map(|&[x, y]| Point::new(x, y))
            .collect()
    }

    /// The problem the scene describes.
    fn to_problem(&self) -> CentroidProblem {
        let (area, _) =
            centroid::polygon_centroid(&self.points()).unwrap_or((1.0, Point::origin()));
        let size = self
            .polygon_m
            .iter()
            .flat_map(|p| {
                self.polygon_m
                    .iter()
                    .map(move |q| (p[0] - q[0]).hypot(p[1] - q[1]))
            })
            .fold(0.0, f64::max);
        let d = self.drawing.unwrap_or(CentroidDrawingSpec {
            length_scale: None,
            area_scale_m2_per_mm: None,
        });
        CentroidProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            polygon: self.points(),
            drawing: CentroidDrawing {
                length_scale: d
                    .length_scale
                    .unwrap_or_else(|| nice_at_least(size * 1000.0 / 100.0)),
                area_scale: d
                    .area_scale_m2_per_mm
                    .unwrap_or_else(|| nice_at_least(area / 50.0)),
                fan_from: self.fan_from,
            },
        }
    }
}

impl super::Procedure for CentroidScene {
    const NAME: &'static str = "centroid";
    const ABOUT: &'static str = "the centroid of a polygon by two funicular polygons (LH I C.3)";
    const OUTPUTS: &'static [&'static str] = &[];
    const INPUT_FIELDS: &'static [(&'static str, &'static str)] = &[("polygon", "polygon_m")];
    const GEOMETRY_FIELD: &'static str = "polygon_m";

    fn sheet_extent(p: &CentroidProblem) -> (f64, &'static str) {
        let pts = &p.polygon;
        let size = pts
            .iter()
            .flat_map(|a| pts.iter().map(move |b| (a - b).norm()))
            .fold(0.0, f64::max);
        let area = centroid::polygon_centroid(pts).map_or(0.0, |(a, _)| a);
        let d = &p.drawing;
        let (mm, field) =
            super::fields::larger(size * 1000.0 / d.length_scale, area / d.area_scale);
        let field = if field == "drawing.force_scale_kg_per_mm" {
            "drawing.area_scale_m2_per_mm"
        } else {
            field
        };
        (mm, field)
    }
    type Problem = CentroidProblem;
    type Results = CentroidResults;

    fn problem(&self, ctx: &ReadContext) -> Result<CentroidProblem, SceneError> {
        self.check_values(ctx.origin)?;
        Ok(self.to_problem())
    }
    fn construct(
        problem: &CentroidProblem,
        config: BoardConfig,
    ) -> Result<(Board, CentroidResults), ConstructionError> {
        let mut board = Board::new(config);
        let r = centroid::construct_centroid(&mut board, &problem.polygon, &problem.drawing)?;
        Ok((board, r))
    }
    fn figure_meta(problem: &CentroidProblem) -> FigureMeta {
        let d = &problem.drawing;
        FigureMeta {
            title: problem.title.clone(),
            source: problem.source.clone(),
            scales: vec![
                ScaleBar::length(d.length_scale, "m"),
                ScaleBar::area(d.area_scale),
            ],
            plate: Vec::new(),
        }
    }
}
