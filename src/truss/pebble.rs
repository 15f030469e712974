//! Generic rigidity of a truss on its supports by the (2,3) pebble game (Jacobs & Hendrickson,
//! 1997): a combinatorial test of the books' count that needs no linear algebra.
//!
//! LH Gl. 2 counts s = 2k − 3; the count alone misses a truss with the right number of members
//! where one panel has too many and another too few. Laman's theorem makes the count exact
//! for *generic* joint positions: a plane bar framework is rigid iff it has 2k − 3 independent
//! bars and no subset of k′ joints carries more than 2k′ − 3. The pebble game decides this bar
//! by bar: every joint holds two pebbles (its two freedoms), and a bar is independent iff four
//! pebbles can be gathered on its two ends; each bar then keeps one pebble.
//!
//! The supports are bars to the ground, a rigid triangle of three extra vertices: a pin is two
//! bars, a roller one. Then the truss with its supports is determinate (generically) iff every
//! member and reaction is independent and exactly three pebbles stay free (the ground's own).
//!
//! Generic is not geometric: three joints in a line or parallel bars can make a generically
//! rigid truss a mechanism. That is found by the sparse LU (see [`super::matrix`]).
//!
//! Time: each bar searches the directed graph for pebbles; on the girders and roofs of the
//! books the searches stay local, and the game is linear in practice (O(k·s) at worst).

use super::{SupportKind, Truss};

/// What the pebble game finds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Generic {
    /// Members and reaction components that are not independent (a generic redundancy).
    pub redundant: usize,
    /// Free motions left over (0 for a rigid truss on its supports).
    pub freedoms: usize,
    /// A joint that still holds a pebble once the ground has gathered its own: it can move
    /// (the first such joint), if there is one.
    pub loose_joint: Option<usize>,
}

struct Game {
    pebbles: Vec<u8>,
    out: Vec<Out>,
    stamp: Vec<u32>,
    epoch: u32,
    stack: Vec<usize>,
    parent: Vec<usize>,
    /// Joints visited by all searches so far, and the most they may visit.
    visits: u64,
    budget: u64,
}

/// The bars directed out of a vertex, kept in place: a vertex's pebbles and its bars out
/// are two (a bar takes its pebble from its tail, and turning a path round hands the bars
/// along), so no vertex has more than two, and no list of its own is needed.
#[derive(Clone, Copy, Default)]
struct Out {
    to: [usize; 2],
    len: u8,
}

impl Out {
    fn len(&self) -> usize {
        usize::from(self.len)
    }

    fn push(&mut self, w: usize) {
        assert!(self.len < 2, "a vertex holds two pebbles or bars out");
        self.to[usize::from(self.len)] = w;
        self.len += 1;
    }

    /// Takes out the bar to `w`, if there is one.
    fn remove(&mut self, w: usize) {
        if let Some(pos) = self.to[..self.len()].iter().position(|&x| x == w) {
            self.to[pos] = self.to[self.len() - 1];
            self.len -= 1;
        }
    }
}

impl Game {
    fn new(n: usize) -> Game {
        Game {
            pebbles: vec![2; n],
            out: vec![Out::default(); n],
            stamp: vec![0; n],
            epoch: 0,
            stack: Vec::new(),
            parent: vec![usize::MAX; n],
            visits: 0,
            budget: u64::MAX,
        }
    }

    /// Brings one free pebble to `u` along the directed bars (reversing the path it came by),
    /// not taking it from `blocked`; false if none can be reached.
    fn fetch(&mut self, u: usize, blocked: &[usize]) -> bool {
        self.epoch += 1;
        let e = self.epoch;
        self.stamp[u] = e;
        for &b in blocked {
            self.stamp[b] = e;
        }
        self.stack.clear();
        self.stack.push(u);
        while let Some(a) = self.stack.pop() {
            for i in 0..self.out[a].len() {
                let w = self.out[a].to[i];
                if self.stamp[w] == e {
                    continue;
                }
                self.stamp[w] = e;
                self.visits += 1;
                self.parent[w] = a;
                if self.pebbles[w] > 0 {
                    self.pebbles[w] -= 1;
                    self.reverse_path(u, w);
                    self.pebbles[u] += 1;
                    return true;
                }
                self.stack.push(w);
            }
        }
        false
    }

    /// Turns round every bar on the path from `u` to `w` (found by `fetch`).
    fn reverse_path(&mut self, u: usize, mut w: usize) {
        while w != u {
            let a = self.parent[w];
            self.out[a].remove(w);
            self.out[w].push(a);
            w = a;
        }
    }

    /// Tries the bar (u, v): independent if four pebbles gather on its ends.
    fn bar(&mut self, u: usize, v: usize) -> bool {
        if u == v {
            return false;
        }
        while self.pebbles[u] < 2 {
            if self.visits > self.budget || !self.fetch(u, &[v]) {
                return false;
            }
        }
        while self.pebbles[v] < 2 {
            if self.visits > self.budget || !self.fetch(v, &[u]) {
                return false;
            }
        }
        self.pebbles[u] -= 1;
        self.out[u].push(v);
        true
    }
}

/// The pebble game on the truss, its supports as bars to a rigid ground.
///
/// ```
/// use graphostatik::truss::generate::{parallel_chord, Web};
/// use graphostatik::truss::pebble::generic;
/// let mut t = parallel_chord(Web::Pratt, 6, 1.0, 1.0);
/// assert_eq!(generic(&t).freedoms, 0);
/// // A diagonal taken out: one panel can shear.
/// let d = t.members.len() - 1;
/// t.members.remove(d);
/// let g = generic(&t);
/// assert_eq!((g.freedoms, g.redundant), (1, 0));
/// assert!(g.loose_joint.is_some());
/// ```
pub fn generic(t: &Truss) -> Generic {
    generic_within(t, u64::MAX).expect("no budget to run out of")
}

/// [`generic`], its searches visiting at most `budget` joints in all; `None` if they would
/// visit more (the game is quadratic on a graph of members joined at random, where a
/// girder's searches stay local: some ten visits per member).
pub fn generic_within(t: &Truss, budget: u64) -> Option<Generic> {
    let k = t.joints.len();
    let ground = [k, k + 1, k + 2];
    let mut g = Game::new(k + 3);
    g.budget = budget;
    let mut redundant = 0usize;
    for (a, b) in [(0, 1), (1, 2), (2, 0)] {
        g.bar(ground[a], ground[b]);
    }
    for m in &t.members {
        let [i, j] = m.ends;
        redundant += usize::from(!(i < k && j < k && g.bar(i, j)));
    }
    for sup in &t.supports {
        let j = sup.joint;
        if j >= k {
            continue;
        }
        match sup.kind {
            SupportKind::Pinned => {
                redundant += usize::from(!g.bar(j, ground[0]));
                redundant += usize::from(!g.bar(j, ground[1]));
            }
            SupportKind::Roller { .. } => redundant += usize::from(!g.bar(j, ground[2])),
        }
    }
    let free: usize = g.pebbles.iter().map(|&p| usize::from(p)).sum();
    // The ground gathers the three pebbles of its own rigid body; a joint left holding one
    // lies in a part that can move against the ground.
    for (i, &v) in ground.iter().enumerate() {
        while g.pebbles[v] < 2 && g.fetch(v, &ground[..i]) {}
    }
    if g.visits > g.budget {
        return None;
    }
    let loose_joint = (0..k).find(|&j| g.pebbles[j] > 0);
    Some(Generic {
        redundant,
        freedoms: free.saturating_sub(3),
        loose_joint: if free > 3 { loose_joint } else { None },
    })
}
