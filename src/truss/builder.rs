//! A truss built in code, by the names the books give its joints and members.

use super::cremona::{self, CaseResult, TrussDrawing};
use super::{Joint, JointLoad, LoadCase, Member, Support, Truss};
use crate::kernel::{Point, Vector};
use crate::protocol::{nice_at_least, Board, ConstructionError};

/// What is wrong with a truss as built: each names the joint or member.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TrussError {
    /// Two joints, or two members, with one name.
    #[error("{what} `{name}` is named twice")]
    Duplicate {
        /// "joint" or "member".
        what: &'static str,
        /// The name.
        name: String,
    },
    /// A member, support or load names a joint the truss does not have.
    #[error("{by}: no joint `{joint}`")]
    UnknownJoint {
        /// What names it ("member 3", "support A", "load case P").
        by: String,
        /// The name given.
        joint: String,
    },
    /// A member joins a joint to itself, or two joints at one place.
    #[error("member `{member}` has no length")]
    ZeroLength {
        /// The member.
        member: String,
    },
    /// A coordinate, direction or force that is not a finite number, or a zero direction.
    #[error("{what}: {message}")]
    Invalid {
        /// What it is ("joint II", "support B").
        what: String,
        /// Why.
        message: &'static str,
    },
}

/// Builds a [`Truss`] joint by joint and member by member, by name (LH I B).
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
    joints: Vec<(String, [f64; 2])>,
    members: Vec<(String, String, String)>,
    supports: Vec<(String, Option<[f64; 2]>, Option<String>)>,
}

impl TrussBuilder {
    /// A joint (Knotenpunkt) at `(x, y)` m.
    pub fn joint(mut self, name: impl Into<String>, at: (f64, f64)) -> Self {
        self.joints.push((name.into(), [at.0, at.1]));
        self
    }

    /// A member (Stab) from joint `a` to joint `b`.
    pub fn member(
        mut self,
        name: impl Into<String>,
        a: impl Into<String>,
        b: impl Into<String>,
    ) -> Self {
        self.members.push((name.into(), a.into(), b.into()));
        self
    }

    /// A pin (festes Auflager) at the joint; its reaction is named A, B, … in the order of the
    /// supports.
    pub fn pin(mut self, joint: impl Into<String>) -> Self {
        self.supports.push((joint.into(), None, None));
        self
    }

    /// A roller (bewegliches Auflager) at the joint whose reaction acts along `dir`.
    pub fn roller(mut self, joint: impl Into<String>, dir: (f64, f64)) -> Self {
        self.supports
            .push((joint.into(), Some([dir.0, dir.1]), None));
        self
    }

    /// Names the reaction of the last support added (the book's own name, e.g. "G").
    pub fn named(mut self, reaction: impl Into<String>) -> Self {
        if let Some(s) = self.supports.last_mut() {
            s.2 = Some(reaction.into());
        }
        self
    }

    /// The truss, or the first thing wrong with it.
    pub fn build(self) -> Result<Truss, TrussError> {
        let mut joints: Vec<Joint> = Vec::with_capacity(self.joints.len());
        for (name, [x, y]) in self.joints {
            if !(x.is_finite() && y.is_finite()) {
                return Err(invalid(format!("joint {name}"), "not a finite position"));
            }
            if joints.iter().any(|j| j.name == name) {
                return Err(TrussError::Duplicate {
                    what: "joint",
                    name,
                });
            }
            joints.push(Joint {
                name,
                at: Point::new(x, y),
            });
        }
        let index = |by: &str, name: &str| {
            joints
                .iter()
                .position(|j| j.name == name)
                .ok_or_else(|| TrussError::UnknownJoint {
                    by: by.to_string(),
                    joint: name.to_string(),
                })
        };
        let mut members: Vec<Member> = Vec::with_capacity(self.members.len());
        for (name, a, b) in &self.members {
            let by = format!("member {name}");
            let ends = [index(&by, a)?, index(&by, b)?];
            if joints[ends[0]].at == joints[ends[1]].at {
                return Err(TrussError::ZeroLength {
                    member: name.clone(),
                });
            }
            if members.iter().any(|m| &m.name == name) {
                let name = name.clone();
                return Err(TrussError::Duplicate {
                    what: "member",
                    name,
                });
            }
            members.push(Member {
                name: name.clone(),
                ends,
            });
        }
        let mut supports = Vec::with_capacity(self.supports.len());
        for (k, (joint, dir, name)) in self.supports.iter().enumerate() {
            let name = name
                .clone()
                .unwrap_or_else(|| super::default_support_name(k));
            let j = index(&format!("support {name}"), joint)?;
            supports.push(match dir {
                None => Support::pinned(j, name),
                Some([dx, dy]) => {
                    let d = Vector::new(*dx, *dy);
                    let n = d.norm();
                    if !(n.is_finite() && n > 0.0) {
                        return Err(invalid(format!("support {name}"), "needs a direction"));
                    }
                    Support::roller(j, d / n, name)
                }
            });
        }
        Ok(Truss::new(joints, members, supports))
    }
}

fn invalid(what: String, message: &'static str) -> TrussError {
    TrussError::Invalid { what, message }
}

impl Truss {
    /// Starts a truss built by name; see [`TrussBuilder`].
    pub fn builder() -> TrussBuilder {
        TrussBuilder::default()
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
                })?;
            if !(px.is_finite() && py.is_finite()) {
                return Err(invalid(format!("load case {name}"), "a load is not finite"));
            }
            out.push(JointLoad {
                joint: j,
                force: Vector::new(px, py),
            });
        }
        Ok(LoadCase { name, loads: out })
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
    fn a_truss_of_1e_minus_300_m_does_not_hang() {
        // Member lengths whose squares underflow: the directions come from hypot, so the rank
        // test sees finite cosines (it never converged on the NaN the norm gave). Later model
        // steps still lose such a truss (the scene refuses one under a micrometre), but with
        // a typed error, not a hang.
        let s = 1e-300;
        let t = Truss::builder()
            .joint("I", (0.0, 0.0))
            .joint("II", (2.0 * s, 0.0))
            .joint("III", (s, s))
            .member("1", "I", "III")
            .member("2", "III", "II")
            .member("3", "I", "II")
            .pin("I")
            .roller("II", (0.0, 1.0))
            .build()
            .unwrap();
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
