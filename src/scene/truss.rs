//! The truss scene: joints, members, supports and load cases (LH I B, Aufgaben 3-5).

use super::defaults::nice_at_least;
use super::{optional_positive, SceneError};
use crate::kernel::{Point, Vector};
use crate::protocol::{Board, ConstructionError};
use crate::render::forces::Combination;
use crate::truss::cremona::{self, CaseResult, TrussDrawing};
use crate::truss::matrix::{self, Determinacy};
use crate::truss::redundant::{self, PairMode};
use crate::truss::{Joint, JointLoad, LoadCase, Member, Support, SupportKind, Truss};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// Most joints a scene may have (the Cremona plan is linear; this bounds the sheet).
pub const MAX_JOINTS: usize = 20_000;

/// A truss scene: `"procedure": "truss"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrussScene {
    /// Must be `"truss"`.
    pub procedure: String,
    /// Title written on the figure.
    pub title: String,
    /// Book reference written under the title.
    #[serde(default)]
    pub source: Option<String>,
    /// Free notes on where the numbers come from (not drawn).
    #[serde(default)]
    pub notes: Option<String>,
    /// The joints.
    pub joints: Vec<JointSpec>,
    /// The members.
    pub members: Vec<MemberSpec>,
    /// The supports: one pin and one roller.
    pub supports: Vec<SupportSpec>,
    /// The load cases, each with its own reactions and Cremona plan.
    pub load_cases: Vec<LoadCaseSpec>,
    /// Load trains moved joint by joint along a path (LH B.5, T6): each position becomes a
    /// load case of its own, and the table's envelope gives every member's extremes.
    #[serde(default)]
    pub moving_loads: Vec<MovingLoadSpec>,
    /// Pairs of diagonals in one panel (members by name), for a truss with more than 2k − 3
    /// members (LH B.5, Abb. 19-20).
    #[serde(default)]
    pub diagonal_pairs: Vec<[String; 2]>,
    /// How the pairs work: `split_half_loads` (two systems, half the loads each, added) or
    /// `tension_only` (flat bars: per case the diagonal in tension works, the other is slack).
    #[serde(default)]
    pub diagonal_mode: Option<PairMode>,
    /// Sums of load cases for the table of member forces (the book's "Gesamtbelastung").
    #[serde(default)]
    pub combinations: Vec<CombinationSpec>,
    /// Scales; any left out are chosen.
    #[serde(default)]
    pub drawing: Option<TrussDrawingSpec>,
}

/// A joint.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct JointSpec {
    /// Name ("I", "II", …).
    pub name: String,
    /// Position [x, y] (m), y up.
    pub at_m: [f64; 2],
}

/// A member.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MemberSpec {
    /// Name ("1", "2", …).
    pub name: String,
    /// The two joints it joins, by name.
    pub joints: [String; 2],
}

/// A support.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SupportSpec {
    /// The joint, by name.
    pub joint: String,
    /// `pinned` (any direction) or `roller` (along `direction_deg`).
    pub kind: SupportKindSpec,
    /// Direction of a roller's reaction, degrees counter-clockwise from +x (90: vertical).
    #[serde(default)]
    pub direction_deg: Option<f64>,
}

/// Pin or roller.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SupportKindSpec {
    /// Festes Auflager.
    Pinned,
    /// Bewegliches Auflager.
    Roller,
}

/// A load case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadCaseSpec {
    /// Name ("dead load", "wind left", …).
    pub name: String,
    /// Loads at joints.
    pub loads: Vec<JointLoadSpec>,
}

/// A train of vertical loads on consecutive joints of a path, moved one joint at a time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MovingLoadSpec {
    /// Name; the positions are named "name at joint".
    pub name: String,
    /// The joints the train runs over, in order.
    pub path: Vec<String>,
    /// The loads of the train (kg, downwards), on consecutive joints of the path.
    pub loads_kg: Vec<f64>,
}

/// A sum of load cases, by name.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CombinationSpec {
    /// Its name ("total").
    pub name: String,
    /// The load cases added, by name.
    pub cases: Vec<String>,
}

/// A load at a joint: `kg` downwards, or `kg` along `angle_deg`, or components `kg_xy`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct JointLoadSpec {
    /// The joint, by name.
    pub joint: String,
    /// Magnitude (kg).
    #[serde(default)]
    pub kg: Option<f64>,
    /// Direction, degrees counter-clockwise from +x; default 270 (down).
    #[serde(default)]
    pub angle_deg: Option<f64>,
    /// Components [Fx, Fy] (kg), instead of `kg`.
    #[serde(default)]
    pub kg_xy: Option<[f64; 2]>,
}

impl JointLoadSpec {
    fn vector(&self) -> Option<Vector> {
        match (self.kg, self.kg_xy) {
            (Some(k), None) => {
                let (s, c) = crate::kernel::angle::sin_cos_deg(self.angle_deg.unwrap_or(270.0));
                Some(Vector::new(k * c, k * s))
            }
            (None, Some([x, y])) if self.angle_deg.is_none() => Some(Vector::new(x, y)),
            _ => None,
        }
    }
}

/// Scales.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrussDrawingSpec {
    /// Length scale 1 : n.
    #[serde(default)]
    pub length_scale: Option<f64>,
    /// Force scale, kg per mm.
    #[serde(default)]
    pub force_scale_kg_per_mm: Option<f64>,
}

/// A validated truss scene.
#[derive(Debug, Clone, PartialEq)]
pub struct TrussProblem {
    /// Title.
    pub title: String,
    /// Source.
    pub source: String,
    /// The truss.
    pub truss: Truss,
    /// The load cases.
    pub cases: Vec<LoadCase>,
    /// Sums of load cases for the table.
    pub combinations: Vec<Combination>,
    /// Pairs of diagonals (member indices) and how they work.
    pub pairs: Vec<[usize; 2]>,
    /// How the pairs work (with pairs only).
    pub pair_mode: Option<PairMode>,
    /// Scales.
    pub drawing: TrussDrawing,
}

impl TrussScene {
    pub(super) fn validate(&self, origin: &str) -> Result<(), SceneError> {
        let bad = |field: String, message: String| SceneError::Invalid {
            origin: origin.to_string(),
            field,
            message,
        };
        if self.procedure != "truss" {
            return Err(bad(
                "procedure".into(),
                format!("unknown procedure `{}`", self.procedure),
            ));
        }
        if self.joints.len() < 2 {
            return Err(bad(
                "joints".into(),
                "a truss needs at least two joints".into(),
            ));
        }
        if self.joints.len() > MAX_JOINTS {
            return Err(bad(
                "joints".into(),
                format!("more than {MAX_JOINTS} joints"),
            ));
        }
        let mut index: HashMap<&str, usize> = HashMap::new();
        for (i, j) in self.joints.iter().enumerate() {
            if !(j.at_m[0].is_finite() && j.at_m[1].is_finite()) {
                return Err(bad(
                    format!("joints[{i}].at_m"),
                    "must be finite numbers".into(),
                ));
            }
            if let Some(first) = index.insert(j.name.as_str(), i) {
                return Err(bad(
                    format!("joints[{i}].name"),
                    format!("joint `{}` is named twice (joints[{first}])", j.name),
                ));
            }
        }
        // Coincident joints: sorted by position, neighbours compared (O(k log k)).
        let size = {
            let xs = self.joints.iter().map(|j| j.at_m[0]);
            let ys = self.joints.iter().map(|j| j.at_m[1]);
            let span = |v: Vec<f64>| {
                v.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                    - v.iter().cloned().fold(f64::INFINITY, f64::min)
            };
            span(xs.collect()).max(span(ys.collect()))
        };
        let eps = crate::kernel::tolerance::REL_LENGTH_EPS * size.max(1e-300);
        let mut by_pos: Vec<usize> = (0..self.joints.len()).collect();
        by_pos.sort_by(|&a, &b| {
            let (p, q) = (self.joints[a].at_m, self.joints[b].at_m);
            p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
        });
        for w in by_pos.windows(2) {
            let (p, q) = (self.joints[w[0]].at_m, self.joints[w[1]].at_m);
            // Neighbours by x; equal x within eps and equal y within eps are one point.
            if (p[0] - q[0]).abs() <= eps && (p[1] - q[1]).abs() <= eps {
                let (a, b) = (w[0].min(w[1]), w[0].max(w[1]));
                return Err(bad(
                    format!("joints[{b}]"),
                    format!(
                        "joint `{}` lies on joint `{}`",
                        self.joints[b].name, self.joints[a].name
                    ),
                ));
            }
        }
        let mut pairs: HashMap<(usize, usize), usize> = HashMap::new();
        let mut names: HashMap<&str, usize> = HashMap::new();
        for (m, mem) in self.members.iter().enumerate() {
            let mut ends = [0; 2];
            for (e, name) in mem.joints.iter().enumerate() {
                ends[e] = *index.get(name.as_str()).ok_or_else(|| {
                    bad(
                        format!("members[{m}].joints[{e}]"),
                        format!(
                            "member `{}` refers to joint `{name}`, which does not exist",
                            mem.name
                        ),
                    )
                })?;
            }
            if ends[0] == ends[1] {
                return Err(bad(
                    format!("members[{m}].joints"),
                    format!(
                        "member `{}` joins joint `{}` to itself: zero length",
                        mem.name, mem.joints[0]
                    ),
                ));
            }
            let key = (ends[0].min(ends[1]), ends[0].max(ends[1]));
            if let Some(first) = pairs.insert(key, m) {
                return Err(bad(
                    format!("members[{m}]"),
                    format!(
                        "member `{}` duplicates member `{}` between `{}` and `{}`",
                        mem.name, self.members[first].name, mem.joints[0], mem.joints[1]
                    ),
                ));
            }
            if let Some(first) = names.insert(mem.name.as_str(), m) {
                return Err(bad(
                    format!("members[{m}].name"),
                    format!("member `{}` is named twice (members[{first}])", mem.name),
                ));
            }
        }
        let mut supported: HashMap<usize, usize> = HashMap::new();
        for (s, sup) in self.supports.iter().enumerate() {
            let j = *index.get(sup.joint.as_str()).ok_or_else(|| {
                bad(
                    format!("supports[{s}].joint"),
                    format!("support at joint `{}`, which does not exist", sup.joint),
                )
            })?;
            if supported.insert(j, s).is_some() {
                return Err(bad(
                    format!("supports[{s}].joint"),
                    format!("joint `{}` has two supports", sup.joint),
                ));
            }
            match (sup.kind, sup.direction_deg) {
                (SupportKindSpec::Roller, None) => {
                    return Err(bad(
                        format!("supports[{s}].direction_deg"),
                        "a roller needs the direction of its reaction".into(),
                    ))
                }
                (SupportKindSpec::Roller, Some(a)) if !a.is_finite() => {
                    return Err(bad(
                        format!("supports[{s}].direction_deg"),
                        "must be finite".into(),
                    ))
                }
                (SupportKindSpec::Pinned, Some(_)) => {
                    return Err(bad(
                        format!("supports[{s}].direction_deg"),
                        "a pin takes any direction; give a direction only for a roller".into(),
                    ))
                }
                _ => {}
            }
        }
        let pins = self
            .supports
            .iter()
            .filter(|s| s.kind == SupportKindSpec::Pinned)
            .count();
        let rollers = self.supports.len() - pins;
        if pins != 1 || rollers != 1 {
            return Err(bad(
                "supports".into(),
                format!("give one pin and one roller (found {pins} pin(s), {rollers} roller(s))"),
            ));
        }
        if self.load_cases.is_empty() {
            return Err(bad(
                "load_cases".into(),
                "give at least one load case".into(),
            ));
        }
        for (c, case) in self.load_cases.iter().enumerate() {
            for (l, load) in case.loads.iter().enumerate() {
                if !index.contains_key(load.joint.as_str()) {
                    return Err(bad(
                        format!("load_cases[{c}].loads[{l}].joint"),
                        format!("load at joint `{}`, which does not exist", load.joint),
                    ));
                }
                match load.vector() {
                    Some(v) if v.x.is_finite() && v.y.is_finite() => {}
                    Some(_) => {
                        return Err(bad(
                            format!("load_cases[{c}].loads[{l}]"),
                            "must be finite numbers".into(),
                        ))
                    }
                    None => {
                        return Err(bad(
                            format!("load_cases[{c}].loads[{l}]"),
                            "give `kg` (with an optional `angle_deg`) or `kg_xy`".into(),
                        ))
                    }
                }
            }
        }
        for (i, mv) in self.moving_loads.iter().enumerate() {
            for (k, j) in mv.path.iter().enumerate() {
                if !index.contains_key(j.as_str()) {
                    return Err(bad(
                        format!("moving_loads[{i}].path[{k}]"),
                        format!("joint `{j}` does not exist"),
                    ));
                }
            }
            if mv.loads_kg.is_empty() || mv.loads_kg.len() > mv.path.len() {
                return Err(bad(
                    format!("moving_loads[{i}].loads_kg"),
                    format!("give 1 to {} loads (the length of the path)", mv.path.len()),
                ));
            }
            if let Some(k) = mv.loads_kg.iter().position(|x| !x.is_finite()) {
                return Err(bad(
                    format!("moving_loads[{i}].loads_kg[{k}]"),
                    "must be finite".into(),
                ));
            }
        }
        for (c, combo) in self.combinations.iter().enumerate() {
            for (i, name) in combo.cases.iter().enumerate() {
                if !self.load_cases.iter().any(|l| &l.name == name) {
                    return Err(bad(
                        format!("combinations[{c}].cases[{i}]"),
                        format!("no load case is named `{name}`"),
                    ));
                }
            }
        }
        if let Some(d) = &self.drawing {
            optional_positive(
                origin,
                &[
                    ("drawing.length_scale", d.length_scale),
                    ("drawing.force_scale_kg_per_mm", d.force_scale_kg_per_mm),
                ],
            )?;
        }
        // Pairs of diagonals: each system (one diagonal of every pair) must be determinate.
        let truss = self.truss();
        if !self.diagonal_pairs.is_empty() {
            if self.diagonal_mode.is_none() {
                return Err(bad(
                    "diagonal_mode".into(),
                    "give `split_half_loads` or `tension_only` for the diagonal pairs".into(),
                ));
            }
            let mut seen: HashMap<&str, usize> = HashMap::new();
            for (i, pair) in self.diagonal_pairs.iter().enumerate() {
                for (k, name) in pair.iter().enumerate() {
                    if !names.contains_key(name.as_str()) {
                        return Err(bad(
                            format!("diagonal_pairs[{i}][{k}]"),
                            format!("no member is named `{name}`"),
                        ));
                    }
                    if let Some(first) = seen.insert(name.as_str(), i) {
                        return Err(bad(
                            format!("diagonal_pairs[{i}][{k}]"),
                            format!("member `{name}` is already in pair {first}"),
                        ));
                    }
                }
            }
            let pairs = self.pair_indices();
            for side in 0..2 {
                let drop: Vec<usize> = pairs.iter().map(|p| p[1 - side]).collect();
                let (sub, _) = redundant::without(&truss, &drop);
                let a = matrix::analyse(&sub);
                let why = match a.determinacy {
                    Determinacy::Determinate => continue,
                    Determinacy::OverDeterminate { redundant } => {
                        format!("still over-determinate by {redundant}: pair the other double diagonals too")
                    }
                    Determinacy::Mechanism { joint, .. } => {
                        format!("a mechanism: joint `{}` can move", sub.joints[joint].name)
                    }
                };
                return Err(bad(
                    "diagonal_pairs".into(),
                    format!(
                        "with the {} diagonal of every pair the truss is {why}",
                        if side == 0 { "first" } else { "second" },
                    ),
                ));
            }
            return Ok(());
        }
        if self.diagonal_mode.is_some() {
            return Err(bad(
                "diagonal_mode".into(),
                "a mode without diagonal_pairs".into(),
            ));
        }
        // Stability: the rank of the equilibrium matrix (LH Gl. 2 and more).
        match matrix::analyse(&truss).determinacy {
            Determinacy::Determinate => Ok(()),
            Determinacy::Mechanism { joint, freedoms } => Err(bad(
                format!("joints[{joint}]"),
                format!(
                    "the truss is a mechanism: joint `{}` can move ({freedoms} free motion(s); s = {}, 2k − 3 = {})",
                    truss.joints[joint].name,
                    truss.members.len(),
                    2 * truss.joints.len() as i64 - 3
                ),
            )),
            Determinacy::OverDeterminate { redundant } => Err(bad(
                "members".into(),
                format!(
                    "the truss is over-determinate by {redundant} (s = {}, 2k − 3 = {}): the Cremona plan needs a determinate truss",
                    truss.members.len(),
                    2 * truss.joints.len() as i64 - 3
                ),
            )),
        }
    }

    fn pair_indices(&self) -> Vec<[usize; 2]> {
        let pos = |n: &str| self.members.iter().position(|m| m.name == n).unwrap_or(0);
        self.diagonal_pairs
            .iter()
            .map(|[a, b]| [pos(a), pos(b)])
            .collect()
    }

    fn truss(&self) -> Truss {
        let index: HashMap<&str, usize> = self
            .joints
            .iter()
            .enumerate()
            .map(|(i, j)| (j.name.as_str(), i))
            .collect();
        Truss {
            joints: self
                .joints
                .iter()
                .map(|j| Joint {
                    name: j.name.clone(),
                    at: Point::new(j.at_m[0], j.at_m[1]),
                })
                .collect(),
            members: self
                .members
                .iter()
                .map(|m| Member {
                    name: m.name.clone(),
                    ends: [index[m.joints[0].as_str()], index[m.joints[1].as_str()]],
                })
                .collect(),
            supports: self
                .supports
                .iter()
                .map(|s| Support {
                    joint: index[s.joint.as_str()],
                    kind: match s.kind {
                        SupportKindSpec::Pinned => SupportKind::Pinned,
                        SupportKindSpec::Roller => {
                            let (sn, c) =
                                crate::kernel::angle::sin_cos_deg(s.direction_deg.unwrap_or(90.0));
                            SupportKind::Roller {
                                dir: Vector::new(c, sn),
                            }
                        }
                    },
                })
                .collect(),
        }
    }

    /// The problem the scene describes.
    pub fn problem(&self) -> TrussProblem {
        let truss = self.truss();
        let index: HashMap<&str, usize> = self
            .joints
            .iter()
            .enumerate()
            .map(|(i, j)| (j.name.as_str(), i))
            .collect();
        let mut cases: Vec<LoadCase> = self
            .load_cases
            .iter()
            .map(|c| LoadCase {
                name: c.name.clone(),
                loads: c
                    .loads
                    .iter()
                    .map(|l| JointLoad {
                        joint: index[l.joint.as_str()],
                        force: l.vector().unwrap_or_else(Vector::zeros),
                    })
                    .collect(),
            })
            .collect();
        for mv in &self.moving_loads {
            for p in 0..=mv.path.len() - mv.loads_kg.len() {
                cases.push(LoadCase {
                    name: format!("{} at {}", mv.name, mv.path[p]),
                    loads: mv
                        .loads_kg
                        .iter()
                        .enumerate()
                        .map(|(i, &kg)| JointLoad {
                            joint: index[mv.path[p + i].as_str()],
                            force: Vector::new(0.0, -kg),
                        })
                        .collect(),
                });
            }
        }
        let maxload = cases
            .iter()
            .map(|c| c.loads.iter().map(|l| l.force.norm()).sum::<f64>())
            .fold(0.0, f64::max);
        let d = self.drawing.unwrap_or(TrussDrawingSpec {
            length_scale: None,
            force_scale_kg_per_mm: None,
        });
        let drawing = TrussDrawing {
            length_scale: d
                .length_scale
                .unwrap_or_else(|| nice_at_least(truss.size() * 1000.0 / 150.0)),
            force_scale: d
                .force_scale_kg_per_mm
                .unwrap_or_else(|| nice_at_least(maxload / 80.0)),
        };
        let combinations = self
            .combinations
            .iter()
            .map(|c| Combination {
                name: c.name.clone(),
                cases: c
                    .cases
                    .iter()
                    .filter_map(|n| self.load_cases.iter().position(|l| &l.name == n))
                    .collect(),
            })
            .collect();
        TrussProblem {
            title: self.title.clone(),
            source: self.source.clone().unwrap_or_default(),
            truss,
            cases,
            combinations,
            pairs: self.pair_indices(),
            pair_mode: self.diagonal_mode,
            drawing,
        }
    }
}

impl TrussProblem {
    /// Constructs every load case on a fresh board.
    pub fn construct(
        &self,
        recording: bool,
    ) -> Result<(Board, Vec<CaseResult>), ConstructionError> {
        let mut board = Board::new(
            self.truss.size() * 1000.0 / self.drawing.length_scale,
            recording,
        );
        let r = match self.pair_mode {
            Some(mode) if !self.pairs.is_empty() => redundant::construct_pairs(
                &mut board,
                &self.truss,
                &self.pairs,
                mode,
                &self.cases,
                &self.drawing,
            )?,
            _ => cremona::construct_truss(&mut board, &self.truss, &self.cases, &self.drawing)?,
        };
        Ok((board, r))
    }

    /// Title, source and scale bars.
    pub fn figure_meta(&self) -> crate::render::FigureMeta {
        let d = &self.drawing;
        crate::render::FigureMeta {
            title: self.title.clone(),
            source: format!(
                "{}{}Cremona plan, tension +, compression −",
                self.source,
                if self.source.is_empty() { "" } else { " — " },
            ),
            scales: vec![
                super::bars::length(d.length_scale, "m"),
                super::bars::force(d.force_scale),
            ],
        }
    }
}
