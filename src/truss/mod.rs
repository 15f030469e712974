//! Trusses (LH I B): the joint-equilibrium model, determinacy and stability (B.2, Gl. 2), the
//! support reactions by the funicular polygon, and the Cremona force plan (B.4, Abb. 17).
//!
//! Positions are in m, forces in kg (the books' technical units). A member force is positive
//! in tension (Zug, +) and negative in compression (Druck, −), as in the books' tables.
//!
//! # Modules
//! - [`builder`]: a truss built in code by the names of its joints and members
//!   ([`Truss::builder`]), load cases by joint name, the scales a drafter would choose;
//! - [`matrix`]: the equilibrium matrix of the joints, its rank (is the truss a mechanism,
//!   determinate or over-determinate?) and the sparse solve that every plan is checked against;
//! - [`faces`]: the truss drawn as a plane graph, its faces, and the outer boundary along
//!   which the external forces are named (Bow's notation);
//! - [`cremona`]: the procedure: determinacy, and per load case (a row of the sheet) the
//!   truss drawing, the reactions, the plan and the table of member forces. Privately it
//!   draws on `graphic_reactions` (the reactions by the closing line, or by Culmann's line
//!   for three rollers), `plan` (the context shared by `bow` for Bow's notation, `joints` for
//!   the joint polygons one by one, and `ritter` for Ritter's sections), `layout`, `labels`
//!   and `notes`;
//! - [`reactions`]: the reactions by the moment equations, the check on the graphic ones;
//! - [`redundant`]: pairs of diagonals, as two systems with half the loads each or as
//!   tension-only counter-diagonals (LH B.5);
//! - [`envelope`]: the largest and smallest force of every member over the load cases;
//! - [`roof`]: the roof loads of LH Gl. 3-10;
//! - [`generate`]: Warren, Pratt and Howe girders of any size.

mod bow;
pub mod builder;
pub mod cremona;
pub mod envelope;
pub mod faces;
pub mod generate;
mod graphic_reactions;
mod joints;
mod labels;
mod layout;
pub mod matrix;
mod notes;
pub mod pebble;
mod plan;
pub mod positions;
pub mod reactions;
pub mod redundant;
mod ritter;
pub mod roof;

pub use builder::{TrussBuilder, TrussError};

use crate::kernel::{Point, Vector};
use serde::Serialize;
pub use smol_str::SmolStr;
use std::any::Any;
use std::sync::{Arc, Mutex};

/// A joint (Knotenpunkt).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Joint {
    /// Its name ("I", "II", … as in the books).
    pub name: SmolStr,
    /// Position (m).
    pub at: Point,
}

/// A member (Stab) between two joints, by index.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Member {
    /// Its name ("1", "2", … as in the books).
    pub name: SmolStr,
    /// The joints it joins (indices into [`Truss::joints`]).
    pub ends: [usize; 2],
}

/// How a support holds its joint.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SupportKind {
    /// A pin (festes Auflager): the reaction may take any direction (two unknowns).
    Pinned,
    /// A roller (bewegliches Auflager): the reaction acts along the given unit direction only.
    Roller {
        /// Direction of the reaction (unit vector).
        dir: Vector,
    },
}

/// A support at a joint.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Support {
    /// The joint (index).
    pub joint: usize,
    /// Pin or roller.
    pub kind: SupportKind,
    /// The reaction's name in tables and the plan ("A", "B", or the book's own, e.g. "G" for
    /// the counterweight of LH Aufgabe 3).
    pub name: String,
}

impl Support {
    /// A pin (festes Auflager) at `joint`.
    pub fn pinned(joint: usize, name: impl Into<String>) -> Support {
        Support {
            joint,
            kind: SupportKind::Pinned,
            name: name.into(),
        }
    }

    /// A roller (bewegliches Auflager) at `joint` whose reaction acts along the unit vector
    /// `dir`.
    pub fn roller(joint: usize, dir: Vector, name: impl Into<String>) -> Support {
        Support {
            joint,
            kind: SupportKind::Roller { dir },
            name: name.into(),
        }
    }
}

/// Capital letters: the books' names of supports (A, B) and of some joints (W, a winch).
pub(crate) const LETTERS: [&str; 26] = [
    "A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K", "L", "M", "N", "O", "P", "Q", "R", "S",
    "T", "U", "V", "W", "X", "Y", "Z",
];

/// The book's names for the reactions of supports that have none of their own: A, B, C, …
/// in the order of the supports (LH B.4: A the left support, B the right), R27 on.
pub fn default_support_name(i: usize) -> String {
    match LETTERS.get(i) {
        Some(l) => l.to_string(),
        None => format!("R{}", i + 1),
    }
}

/// A load at a joint (kg), x to the right, y up.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JointLoad {
    /// The joint (index).
    pub joint: usize,
    /// The force (kg).
    pub force: Vector,
}

/// A load case (dead load, snow, wind from the left, …).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadCase {
    /// Its name.
    pub name: String,
    /// The loads.
    pub loads: Vec<JointLoad>,
    /// Its own force scale (kg per mm), where its plan is drawn at another scale than the
    /// figure's: a light moving load's plans larger than the dead load's, each read "unter
    /// Berücksichtigung des jeweiligen Kräftemaßstabes" (LH B.5, Aufgabe 5).
    pub force_scale: Option<f64>,
    /// Whether its plan is drawn. A case not drawn is constructed and checked as any other,
    /// and its results reported, but the figure leaves it out ([`Board::unseen`]): LH
    /// Aufgabe 5 draws the plans of the dead load and of crane positions I, II and III, and
    /// computes the other positions (Tabelle 2).
    ///
    /// [`Board::unseen`]: crate::protocol::Board::unseen
    pub drawn: bool,
    /// The book's name of the case, where the book numbers it: LH Aufgabe 5 calls the crane
    /// positions I to X (Tabelle 2). Headings and tables write it before the name ("I (crane
    /// at O9)").
    pub book_name: Option<String>,
}

impl LoadCase {
    /// The case as headings and tables name it: the book's name first where it has one
    /// ("I (crane at O9)"), else its name.
    pub fn title(&self) -> String {
        match &self.book_name {
            Some(b) => format!("{b} ({})", self.name),
            None => self.name.clone(),
        }
    }
}

/// A plane truss with its supports.
///
/// It carries what is known of its equilibrium matrix (its sparse LU and rank test, made
/// when first asked for): the scene's validation, the construction's rank test and the
/// solve its checks are made with ask about the same matrix, which is factorised once. The
/// memo checks the geometry bit for bit before it answers, so a truss changed in place is
/// analysed afresh.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Truss {
    /// The joints.
    pub joints: Vec<Joint>,
    /// The members.
    pub members: Vec<Member>,
    /// The supports.
    pub supports: Vec<Support>,
    /// What is known of its equilibrium matrix.
    #[serde(skip)]
    pub(crate) memo: AnalysisCache,
}

/// A slot for what the analyses of a truss know of it (its matrix's LU and rank test): opaque
/// here, filled and read by the module that makes them. Clones of a truss share it; it is no
/// part of what a truss is (equal, debug-printed and serialised without it).
#[derive(Clone, Default)]
pub(crate) struct AnalysisCache(Arc<Mutex<Option<Box<dyn Any + Send>>>>);

impl AnalysisCache {
    /// `f` on the value of type `T` kept here (made by `T::default()` where there is none).
    pub(crate) fn with<T: Default + Send + 'static, R>(&self, f: impl FnOnce(&mut T) -> R) -> R {
        // A panic while it was held leaves at worst a value not yet complete, which the
        // analyses check (by the truss's geometry) before they use it.
        let mut slot = self.0.lock().unwrap_or_else(|e| e.into_inner());
        let v = slot.get_or_insert_with(|| Box::new(T::default()));
        if !v.is::<T>() {
            *v = Box::new(T::default());
        }
        f(v.downcast_mut::<T>()
            .expect("a value of this type was just put here"))
    }

    fn clear(&self) {
        *self.0.lock().unwrap_or_else(|e| e.into_inner()) = None;
    }
}

impl std::fmt::Debug for AnalysisCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("AnalysisCache")
    }
}

impl PartialEq for AnalysisCache {
    fn eq(&self, _: &AnalysisCache) -> bool {
        true
    }
}

impl Truss {
    /// A truss of these joints, members (by joint index) and supports.
    pub fn new(joints: Vec<Joint>, members: Vec<Member>, supports: Vec<Support>) -> Truss {
        Truss {
            joints,
            members,
            supports,
            memo: Default::default(),
        }
    }

    /// Forgets what is known of the truss's matrix (its LU, its rank test), so that the
    /// next question makes them afresh: for a benchmark that times the whole path again and
    /// again on one truss.
    pub fn forget_matrix(&self) {
        self.memo.clear();
    }

    /// Number of reaction unknowns: two per pin, one per roller.
    pub fn reaction_unknowns(&self) -> usize {
        self.supports
            .iter()
            .map(|s| match s.kind {
                SupportKind::Pinned => 2,
                SupportKind::Roller { .. } => 1,
            })
            .sum()
    }

    /// The member's unit direction from its first joint to its second, and its length (m).
    pub fn member_dir(&self, m: usize) -> (Vector, f64) {
        let [a, b] = self.members[m].ends;
        let d = self.joints[b].at - self.joints[a].at;
        let l = d.norm();
        // x² + y² underflows for a member shorter than 1e-154 m: hypot does not.
        let l = if (1e-150..1e150).contains(&l) {
            l
        } else {
            d.x.hypot(d.y)
        };
        (d / l, l)
    }

    /// The size of the truss: the larger side of its bounding box (m), the scale of every
    /// length tolerance.
    pub fn size(&self) -> f64 {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for j in &self.joints {
            lo = [lo[0].min(j.at.x), lo[1].min(j.at.y)];
            hi = [hi[0].max(j.at.x), hi[1].max(j.at.y)];
        }
        (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE)
    }
}

/// The force of one member in one load case.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MemberForce {
    /// Member name.
    pub member: smol_str::SmolStr,
    /// Length of its segment in the plan (mm).
    pub plan_mm: f64,
    /// Force (kg): tension +, compression −.
    pub force: f64,
    /// The force the joint-equilibrium solve gives (kg), where it was made.
    pub matrix: Option<f64>,
}

impl MemberForce {
    /// "Zug", "Druck" or "0" (a zero-force member, |S| below `zero`).
    pub fn kind(&self, zero: f64) -> &'static str {
        if self.force.abs() <= zero {
            "0"
        } else if self.force > 0.0 {
            "Zug"
        } else {
            "Druck"
        }
    }
}
