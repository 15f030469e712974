//! A truss built in code, by the names the books give its joints and members.

use super::cremona::{self, CaseResult, TrussDrawing};
use super::{Joint, JointLoad, LoadCase, Member, SmolStr, Support, Truss};
use crate::kernel::{Point, Vector};
use crate::protocol::{nice_at_least, Board, ConstructionError};
use foldhash::{HashMap, HashMapExt};

/// What a member, support or load is, where an error names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// A joint, by its place in the order added.
    Joint(usize),
    /// A member, by its place in the order added.
    Member(usize),
    /// A support, by its place in the order added.
    Support(usize),
}

/// What is wrong with a truss as built: each names the joint, member or support by its name
/// and its place in the order added, so that a scene can name its field.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TrussError {
    /// Two joints, two members or two reactions with one name.
    #[error("{what} `{name}` is named twice")]
    Duplicate {
        /// "joint", "member" or "reaction".
        what: &'static str,
        /// The name.
        name: String,
        /// The second of the two.
        at: Part,
        /// The first of the two.
        first: Part,
    },
    /// A member, support or load names a joint the truss does not have.
    #[error("{by}: no joint `{joint}`")]
    UnknownJoint {
        /// What names it ("member 3", "support A", "load case P").
        by: String,
        /// The name given.
        joint: String,
        /// The member (with which of its two ends) or support that names it; `None` for a load.
        at: Option<(Part, usize)>,
    },
    /// A member joins a joint to itself.
    #[error("member `{member}` has no length")]
    ZeroLength {
        /// The member.
        member: String,
        /// Its place.
        at: Part,
    },
    /// Two joints at one place (within the truss's length tolerance).
    #[error("joint `{joint}` lies on joint `{on}`")]
    Coincident {
        /// The later joint.
        joint: String,
        /// The joint it lies on.
        on: String,
        /// The later joint's place.
        at: Part,
    },
    /// Two members between the same two joints.
    #[error("member `{member}` duplicates member `{first}`")]
    DuplicateMember {
        /// The later member.
        member: String,
        /// The member it duplicates.
        first: String,
        /// The later member's place.
        at: Part,
    },
    /// The truss's size (its larger span, m) lies outside the range the builder was given.
    #[error("the truss spans {size:e} m, outside {min:e} to {max:e} m")]
    Size {
        /// Its larger span.
        size: f64,
        /// The least span allowed.
        min: f64,
        /// The largest span allowed.
        max: f64,
    },
    /// A support its caller refused before it was built (a scene's roller without a
    /// direction), reported in its turn among the supports.
    #[error("support {}: {message}", match at { Part::Support(k) => k + 1, _ => 0 })]
    Refused {
        /// The support's place.
        at: Part,
        /// Why.
        message: &'static str,
    },
    /// Two supports at one joint.
    #[error("joint `{joint}` has two supports")]
    TwoSupports {
        /// The joint.
        joint: String,
        /// The second support's place.
        at: Part,
    },
    /// A coordinate, direction or force that is not a finite number, a zero direction, or an
    /// empty name.
    #[error("{what}: {message}")]
    Invalid {
        /// What it is ("joint II", "support B").
        what: String,
        /// Why.
        message: &'static str,
        /// The joint or support at fault, where it is one.
        at: Option<Part>,
    },
}

/// A support as added: its joint, a roller's direction (and whether it is a unit vector
/// already), the reaction's name.
#[derive(Debug, Clone)]
struct SupportSpec {
    joint: String,
    roller: Option<(Vector, bool)>,
    name: Option<String>,
    refused: Option<&'static str>,
}

/// Builds a [`Truss`] joint by joint and member by member, by name (LH I B), and checks it
/// on [`build`](TrussBuilder::build): the one validator of the truss model, which a truss
/// scene uses too.
///
/// ```
/// use graphostatik::prelude::*;
/// // LH B.3: a triangle, span 2 m, height 1 m, pin at I, roller at II.
/// let truss = Truss::builder()
///     .joint("I", (0.0, 0.0)).joint("II", (2.0, 0.0)).joint("III", (1.0, 1.0))
///     .member("1", "I", "III").member("2", "III", "II").member("3", "I", "II")
///     .pin("I").roller("II", (0.0, 1.0))
///     .build()?;
/// let p = truss.load_case("P", &[("III", (0.0, -1000.0))])?;
/// let mut board = Board::recording();
/// let r = truss.cremona(&mut board, &[p])?;
/// assert!((r[0].members[2].force - 500.0).abs() < 1e-9); // the tie pulls with 500 kg
/// assert!(board.all_passed());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Default)]
pub struct TrussBuilder {
    joints: Vec<(SmolStr, [f64; 2])>,
    members: Vec<(SmolStr, [SmolStr; 2])>,
    supports: Vec<SupportSpec>,
    /// Subtracted from every joint's position once the truss is checked (a scene far from
    /// its origin is built in its own frame).
    origin: [f64; 2],
    /// The least and largest span the truss may have (m), where the caller sets them.
    size_range: Option<(f64, f64)>,
}

type Names<'a> = HashMap<&'a str, usize>;

impl TrussBuilder {
    /// A joint (Knotenpunkt) at `(x, y)` m.
    pub fn joint(mut self, name: impl Into<SmolStr>, at: (f64, f64)) -> Self {
        self.joints.push((name.into(), [at.0, at.1]));
        self
    }

    /// A member (Stab) from joint `a` to joint `b`.
    pub fn member(
        mut self,
        name: impl Into<SmolStr>,
        a: impl Into<SmolStr>,
        b: impl Into<SmolStr>,
    ) -> Self {
        self.members.push((name.into(), [a.into(), b.into()]));
        self
    }

    /// A pin (festes Auflager) at the joint; its reaction is named A, B, … in the order of the
    /// supports.
    pub fn pin(mut self, joint: impl Into<String>) -> Self {
        self.supports.push(SupportSpec {
            joint: joint.into(),
            roller: None,
            name: None,
            refused: None,
        });
        self
    }

    /// A roller (bewegliches Auflager) at the joint whose reaction acts along `dir`.
    pub fn roller(mut self, joint: impl Into<String>, dir: (f64, f64)) -> Self {
        self.supports.push(SupportSpec {
            joint: joint.into(),
            roller: Some((Vector::new(dir.0, dir.1), false)),
            name: None,
            refused: None,
        });
        self
    }

    /// A roller whose direction is a unit vector already (taken as it is, bit for bit).
    pub(crate) fn roller_unit(mut self, joint: impl Into<String>, dir: Vector) -> Self {
        self.supports.push(SupportSpec {
            joint: joint.into(),
            roller: Some((dir, true)),
            name: None,
            refused: None,
        });
        self
    }

    /// Refuses the last support added, for `why`: the error is reported in its turn, after
    /// its joint is checked, as [`TrussError::Refused`].
    pub(crate) fn refused(mut self, why: &'static str) -> Self {
        if let Some(s) = self.supports.last_mut() {
            s.refused = Some(why);
        }
        self
    }

    /// Makes room for `joints` more joints and `members` more members, where the caller
    /// knows how many it adds (a girder generated panel by panel, a scene's truss): its
    /// lists are then made once, not doubled as they grow. The truss built is the same.
    ///
    /// ```
    /// use graphostatik::prelude::*;
    /// // A Warren girder of 100 panels (LH I B): 201 joints, 399 members.
    /// let n = 100;
    /// let mut b = Truss::builder().reserve(2 * n + 1, 4 * n - 1);
    /// for i in 0..=n {
    ///     b = b.joint(format!("U{i}"), (2.0 * i as f64, 0.0));
    /// }
    /// for i in 0..n {
    ///     b = b.joint(format!("O{i}"), (2.0 * i as f64 + 1.0, 1.0));
    ///     b = b.member(format!("D{i}a"), format!("U{i}"), format!("O{i}"));
    ///     b = b.member(format!("D{i}b"), format!("O{i}"), format!("U{}", i + 1));
    ///     b = b.member(format!("U{i}-{}", i + 1), format!("U{i}"), format!("U{}", i + 1));
    ///     if i > 0 {
    ///         b = b.member(format!("O{}-{i}", i - 1), format!("O{}", i - 1), format!("O{i}"));
    ///     }
    /// }
    /// let truss = b.pin("U0").roller(format!("U{n}"), (0.0, 1.0)).build()?;
    /// assert_eq!((truss.joints.len(), truss.members.len()), (201, 399));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn reserve(mut self, joints: usize, members: usize) -> Self {
        self.joints.reserve(joints);
        self.members.reserve(members);
        self
    }

    /// Refuses a truss whose larger span (m) lies outside `[min, max]`, as
    /// [`TrussError::Size`], once its joints are known to be finite.
    pub(crate) fn size_within(mut self, min: f64, max: f64) -> Self {
        self.size_range = Some((min, max));
        self
    }

    /// Names the reaction of the last support added (the book's own name, e.g. "G").
    pub fn named(mut self, reaction: impl Into<String>) -> Self {
        if let Some(s) = self.supports.last_mut() {
            s.name = Some(reaction.into());
        }
        self
    }

    /// The truss built with every position less `origin` (checked as given).
    pub(crate) fn in_frame_of(mut self, origin: [f64; 2]) -> Self {
        self.origin = origin;
        self
    }

    /// The truss, or the first thing wrong with it, in this order: each joint at a finite
    /// place and named once; no two joints at one place; each member between two known,
    /// distinct joints, no two members between the same pair, each named once; each support
    /// at a known joint, one a joint, a roller's direction finite and not zero, each reaction
    /// named, once. Linear in the size of the truss (names hashed, coincidence by a grid).
    pub fn build(self) -> Result<Truss, TrussError> {
        let joints = self.check_joints()?;
        self.check_coincident()?;
        let ends = self.check_members(&joints)?;
        let supports = self.check_supports(&joints)?;
        drop(joints);
        // The names move into the truss, checked: no copy of them.
        let members = (self.members.into_iter().zip(ends))
            .map(|((name, _), ends)| Member { name, ends })
            .collect();
        let [ox, oy] = self.origin;
        let joints = self
            .joints
            .into_iter()
            .map(|(name, [x, y])| Joint {
                name,
                at: Point::new(x - ox, y - oy),
            })
            .collect();
        Ok(Truss::new(joints, members, supports))
    }

    /// Every joint at a finite place and named once: the index of the names.
    fn check_joints(&self) -> Result<Names<'_>, TrussError> {
        let mut index = Names::with_capacity(self.joints.len());
        for (i, (name, [x, y])) in self.joints.iter().enumerate() {
            if !(x.is_finite() && y.is_finite()) {
                return Err(TrussError::Invalid {
                    what: format!("joint {name}"),
                    message: "not a finite position",
                    at: Some(Part::Joint(i)),
                });
            }
            if let Some(first) = index.insert(name.as_str(), i) {
                return Err(TrussError::Duplicate {
                    what: "joint",
                    name: name.to_string(),
                    at: Part::Joint(i),
                    first: Part::Joint(first),
                });
            }
        }
        Ok(index)
    }

    /// No two joints within the length tolerance of the truss's size: a grid of cells as
    /// wide as the tolerance, each joint compared with its own cell and the eight around it
    /// (O(k) for k joints; −0.0 and 0.0 are one coordinate).
    fn check_coincident(&self) -> Result<(), TrussError> {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for (_, p) in &self.joints {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        if let Some((min, max)) = self.size_range {
            if !(min..=max).contains(&size) {
                return Err(TrussError::Size { size, min, max });
            }
        }
        let eps = crate::kernel::tolerance::REL_LENGTH_EPS * size.max(f64::MIN_POSITIVE);
        let cell = |v: f64| ((v + 0.0) / eps).floor() as i64;
        // Each cell's joints in the order added, as a chain: the cell keeps its first and
        // last, `next` the one after each (no list of its own a cell).
        let mut grid: HashMap<(i64, i64), (usize, usize)> =
            HashMap::with_capacity(self.joints.len());
        let mut next = vec![usize::MAX; self.joints.len()];
        for (b, (name, [x, y])) in self.joints.iter().enumerate() {
            let (cx, cy) = (cell(*x), cell(*y));
            for dx in -1..=1i64 {
                for dy in -1..=1i64 {
                    let key = (cx.saturating_add(dx), cy.saturating_add(dy));
                    let mut a = grid.get(&key).map_or(usize::MAX, |&(first, _)| first);
                    while a != usize::MAX {
                        let [ax, ay] = self.joints[a].1;
                        if (ax - x).abs() <= eps && (ay - y).abs() <= eps {
                            return Err(TrussError::Coincident {
                                joint: name.to_string(),
                                on: self.joints[a].0.to_string(),
                                at: Part::Joint(b),
                            });
                        }
                        a = next[a];
                    }
                }
            }
            match grid.entry((cx, cy)) {
                std::collections::hash_map::Entry::Occupied(mut e) => {
                    next[e.get().1] = b;
                    e.get_mut().1 = b;
                }
                std::collections::hash_map::Entry::Vacant(e) => {
                    e.insert((b, b));
                }
            }
        }
        Ok(())
    }

    /// Every member between two known, distinct joints, no two between the same pair, each
    /// named once: the joints each joins.
    fn check_members(&self, joints: &Names<'_>) -> Result<Vec<[usize; 2]>, TrussError> {
        let mut pairs: HashMap<(usize, usize), usize> = HashMap::with_capacity(self.members.len());
        let mut names = Names::with_capacity(self.members.len());
        let mut out = Vec::with_capacity(self.members.len());
        for (m, (name, ends)) in self.members.iter().enumerate() {
            let mut at = [0; 2];
            for (e, joint) in ends.iter().enumerate() {
                at[e] = *joints
                    .get(joint.as_str())
                    .ok_or_else(|| TrussError::UnknownJoint {
                        by: format!("member {name}"),
                        joint: joint.to_string(),
                        at: Some((Part::Member(m), e)),
                    })?;
            }
            if at[0] == at[1] {
                return Err(TrussError::ZeroLength {
                    member: name.to_string(),
                    at: Part::Member(m),
                });
            }
            if let Some(first) = pairs.insert((at[0].min(at[1]), at[0].max(at[1])), m) {
                return Err(TrussError::DuplicateMember {
                    member: name.to_string(),
                    first: self.members[first].0.to_string(),
                    at: Part::Member(m),
                });
            }
            if let Some(first) = names.insert(name.as_str(), m) {
                return Err(TrussError::Duplicate {
                    what: "member",
                    name: name.to_string(),
                    at: Part::Member(m),
                    first: Part::Member(first),
                });
            }
            out.push(at);
        }
        Ok(out)
    }

    /// Every support at a known joint, one a joint, a roller's direction finite and not zero;
    /// then every reaction named, once.
    fn check_supports(&self, joints: &Names<'_>) -> Result<Vec<Support>, TrussError> {
        let mut supported: HashMap<usize, usize> = HashMap::new();
        let mut out = Vec::with_capacity(self.supports.len());
        for (k, s) in self.supports.iter().enumerate() {
            let name = s
                .name
                .clone()
                .unwrap_or_else(|| super::default_support_name(k));
            let j = *joints
                .get(s.joint.as_str())
                .ok_or_else(|| TrussError::UnknownJoint {
                    by: format!("support {name}"),
                    joint: s.joint.clone(),
                    at: Some((Part::Support(k), 0)),
                })?;
            if supported.insert(j, k).is_some() {
                return Err(TrussError::TwoSupports {
                    joint: s.joint.clone(),
                    at: Part::Support(k),
                });
            }
            if let Some(message) = s.refused {
                return Err(TrussError::Refused {
                    at: Part::Support(k),
                    message,
                });
            }
            out.push(match s.roller {
                None => Support::pinned(j, name),
                Some((d, true)) if d.x.is_finite() && d.y.is_finite() => {
                    Support::roller(j, d, name)
                }
                Some((d, unit)) => {
                    let n = d.norm();
                    if unit || !(n.is_finite() && n > 0.0) {
                        return Err(TrussError::Invalid {
                            what: format!("support {name}"),
                            message: "needs a direction",
                            at: Some(Part::Support(k)),
                        });
                    }
                    Support::roller(j, d / n, name)
                }
            });
        }
        let mut names = Names::with_capacity(out.len());
        for (k, s) in out.iter().enumerate() {
            if s.name.trim().is_empty() {
                return Err(TrussError::Invalid {
                    what: format!("support {}", k + 1),
                    message: "a support's name must not be empty",
                    at: Some(Part::Support(k)),
                });
            }
            if let Some(first) = names.insert(s.name.as_str(), k) {
                return Err(TrussError::Duplicate {
                    what: "reaction",
                    name: s.name.clone(),
                    at: Part::Support(k),
                    first: Part::Support(first),
                });
            }
        }
        Ok(out)
    }
}

impl Truss {
    /// Starts a truss built by name; see [`TrussBuilder`].
    pub fn builder() -> TrussBuilder {
        TrussBuilder::default()
    }

    /// The tests' triangle: joints I (0, 0), II (`w`, 0) and III (`w`/2, `h`), members
    /// 1 = I-III, 2 = III-II, 3 = I-II, a pin at I and a vertical roller at II.
    #[cfg(test)]
    pub(crate) fn triangle(w: f64, h: f64) -> Truss {
        Truss::builder()
            .joint("I", (0.0, 0.0))
            .joint("II", (w, 0.0))
            .joint("III", (w / 2.0, h))
            .member("1", "I", "III")
            .member("2", "III", "II")
            .member("3", "I", "II")
            .pin("I")
            .roller("II", (0.0, 1.0))
            .build()
            .unwrap()
    }

    /// The index of the joint with this name.
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }

    /// A load case by joint names: `(joint, (Px, Py))` in kg, x to the right, y up.
    pub fn load_case(
        &self,
        name: impl Into<String>,
        loads: &[(&str, (f64, f64))],
    ) -> Result<LoadCase, TrussError> {
        let name = name.into();
        let mut out = Vec::with_capacity(loads.len());
        for &(joint, (px, py)) in loads {
            let j = self
                .joint_index(joint)
                .ok_or_else(|| TrussError::UnknownJoint {
                    by: format!("load case {name}"),
                    joint: joint.to_string(),
                    at: None,
                })?;
            if !(px.is_finite() && py.is_finite()) {
                return Err(TrussError::Invalid {
                    what: format!("load case {name}"),
                    message: "a load is not finite",
                    at: None,
                });
            }
            out.push(JointLoad {
                joint: j,
                force: Vector::new(px, py),
            });
        }
        Ok(LoadCase {
            name,
            loads: out,
            force_scale: None,
            drawn: true,
            book_name: None,
        })
    }

    /// Scales a drafter would choose: the truss about 150 mm across, the largest load case
    /// about 80 mm long in the force plan, each rounded up to a nice value.
    pub fn drawing_for(&self, cases: &[LoadCase]) -> TrussDrawing {
        let maxload = cases
            .iter()
            .map(|c| c.loads.iter().map(|l| l.force.norm()).sum::<f64>())
            .fold(0.0, f64::max);
        TrussDrawing {
            length_scale: nice_at_least(self.size() * 1000.0 / 150.0),
            force_scale: nice_at_least(maxload / 80.0),
        }
    }

    /// The reactions and the Cremona plan of every load case on `board`, at the scales of
    /// [`Truss::drawing_for`] (LH B.4, Abb. 17); see [`cremona::construct_truss`].
    pub fn cremona(
        &self,
        board: &mut Board,
        cases: &[LoadCase],
    ) -> Result<Vec<CaseResult>, ConstructionError> {
        cremona::construct_truss(board, self, cases, &self.drawing_for(cases))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle() -> TrussBuilder {
        Truss::builder()
            .joint("I", (0.0, 0.0))
            .joint("II", (2.0, 0.0))
            .joint("III", (1.0, 1.0))
            .member("1", "I", "III")
            .member("2", "III", "II")
    }

    #[test]
    fn names_resolve_to_indices_and_reactions_take_letters() {
        let t = triangle()
            .member("3", "I", "II")
            .pin("I")
            .roller("II", (0.0, 2.0))
            .named("Q")
            .build()
            .unwrap();
        assert_eq!(t.members[1].ends, [2, 1]);
        assert_eq!(t.supports[0].name, "A");
        assert_eq!(t.supports[1].name, "Q");
        let super::super::SupportKind::Roller { dir } = t.supports[1].kind else {
            panic!()
        };
        assert_eq!(dir, Vector::new(0.0, 1.0));
    }

    #[test]
    fn errors_name_what_is_wrong() {
        let e = triangle().member("3", "I", "IV").build().unwrap_err();
        assert_eq!(e.to_string(), "member 3: no joint `IV`");
        let e = triangle().member("1", "I", "II").build().unwrap_err();
        assert_eq!(e.to_string(), "member `1` is named twice");
        let e = triangle().member("3", "I", "I").build().unwrap_err();
        assert_eq!(e.to_string(), "member `3` has no length");
        let e = triangle().roller("II", (0.0, 0.0)).build().unwrap_err();
        assert_eq!(e.to_string(), "support A: needs a direction");
        let t = triangle().build().unwrap();
        let e = t.load_case("P", &[("V", (0.0, -1.0))]).unwrap_err();
        assert_eq!(e.to_string(), "load case P: no joint `V`");
    }

    #[test]
    fn the_model_is_checked_whole_and_each_error_names_its_place() {
        let e = triangle().joint("IV", (1.0, 1.0)).build().unwrap_err();
        assert!(
            matches!(
                &e,
                TrussError::Coincident {
                    at: Part::Joint(3),
                    ..
                }
            ),
            "{e}"
        );
        assert_eq!(e.to_string(), "joint `IV` lies on joint `III`");
        let e = triangle().member("3", "II", "III").build().unwrap_err();
        assert_eq!(e.to_string(), "member `3` duplicates member `2`");
        let e = triangle()
            .member("3", "I", "II")
            .pin("I")
            .pin("I")
            .build()
            .unwrap_err();
        assert!(matches!(
            e,
            TrussError::TwoSupports {
                at: Part::Support(1),
                ..
            }
        ));
        let e = (triangle().member("3", "I", "II").pin("I").named("A"))
            .roller("II", (0.0, 1.0))
            .named("A")
            .build()
            .unwrap_err();
        assert_eq!(e.to_string(), "reaction `A` is named twice");
        let e = triangle().size_within(3.0, 10.0).build().unwrap_err();
        assert!(matches!(e, TrussError::Size { size, .. } if size == 2.0));
        let e = (triangle().member("3", "I", "II").pin("I"))
            .roller("II", (0.0, 1.0))
            .refused("why")
            .build()
            .unwrap_err();
        assert_eq!(e.to_string(), "support 2: why");
        // A joint out of place is reported before anything about members.
        let e = triangle()
            .joint("I", (9.0, 9.0))
            .member("9", "I", "X")
            .build()
            .unwrap_err();
        assert_eq!(e.to_string(), "joint `I` is named twice");
        // Checked as given, built in the frame asked for.
        let t = triangle().in_frame_of([1.0, 0.0]).build().unwrap();
        assert_eq!(t.joints[0].at, Point::new(-1.0, 0.0));
    }

    #[test]
    fn a_truss_of_1e_minus_300_m_does_not_hang() {
        // Member lengths whose squares underflow: the directions come from hypot, so the rank
        // test sees finite cosines (it never converged on the NaN the norm gave). Later model
        // steps still lose such a truss (the scene refuses one under a micrometre), but with
        // a typed error, not a hang.
        let s = 1e-300;
        let t = Truss::triangle(2.0 * s, s);
        let d = t.member_dir(0).0;
        assert!(
            (d - Vector::new(1.0, 1.0) / 2f64.sqrt()).norm() < 1e-15,
            "{d}"
        );
        assert!(crate::truss::matrix::analyse(&t).rank.is_some());
        let p = t.load_case("P", &[("III", (0.0, -1000.0))]).unwrap();
        match t.cremona(&mut Board::silent(), &[p]) {
            Ok(r) => assert!((r[0].members[2].force - 500.0).abs() < 1e-9),
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    }

    #[test]
    fn a_mechanism_is_refused_with_its_joint() {
        // A square on two pins: s + r = 4 + 4 = 2k, and still a four-bar linkage (LH B.2).
        let t = Truss::builder()
            .joint("I", (0.0, 0.0))
            .joint("II", (2.0, 0.0))
            .joint("III", (2.0, 1.0))
            .joint("IV", (0.0, 1.0))
            .member("1", "I", "II")
            .member("2", "II", "III")
            .member("3", "III", "IV")
            .member("4", "IV", "I")
            .pin("I")
            .pin("II")
            .build()
            .unwrap();
        let p = t.load_case("P", &[("III", (0.0, -1000.0))]).unwrap();
        let e = t.cremona(&mut Board::silent(), &[p]).unwrap_err();
        let ConstructionError::Mechanism { joint, freedoms } = e else {
            panic!("{e}")
        };
        assert_eq!(freedoms, 1);
        assert!(["III", "IV"].contains(&joint.as_str()), "{joint}");
    }
}
