//! The truss drawing as a plane graph: the members around every joint in angular order, the
//! faces (the triangles of the truss and the outside), and the walk around the outside along
//! which the external forces are named.
//!
//! This is the frame of Bow's notation: every face of the truss and every space between two
//! external forces gets a letter, every member and force is named by the two spaces it
//! separates, and the Cremona plan has one point per space (the reciprocal figure).
//!
//! Half-edge `2m` runs along member m from its first joint to its second, `2m + 1` back.
//! Faces are traced with the face on the left: bounded faces counter-clockwise (positive
//! area), the outside clockwise (negative area). A drawing whose members cross gives a
//! tracing that violates Euler's formula k − s + f = 2, and is refused.

use super::Truss;
use std::f64::consts::TAU;
use std::ops::{Index, IndexMut};

/// Lists of indices kept end to end in one allocation, each read as a slice (`lists[i]`): a
/// girder of 10,000 joints has 10,000 lists of members round a joint and as many faces,
/// which as a `Vec` each took some 20,000 allocations and their growth.
///
/// ```
/// use graphostatik::truss::faces::Lists;
/// // The members at each of three joints, given as (joint, member) in member order.
/// let at = Lists::grouped(3, [(0, 7), (2, 8), (0, 9)].into_iter());
/// assert_eq!((&at[0], &at[1], &at[2]), (&[7, 9][..], &[][..], &[8][..]));
/// assert_eq!(at.iter().map(<[usize]>::len).collect::<Vec<_>>(), [2, 0, 1]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Lists {
    start: Vec<usize>,
    items: Vec<usize>,
}

impl Lists {
    /// `n` lists, each value in the list its key names, in the order given.
    pub fn grouped(n: usize, pairs: impl Iterator<Item = (usize, usize)> + Clone) -> Lists {
        let mut start = vec![0; n + 1];
        for (k, _) in pairs.clone() {
            start[k + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut items = vec![0; start[n]];
        for (k, v) in pairs {
            items[fill[k]] = v;
            fill[k] += 1;
        }
        Lists { start, items }
    }

    /// No lists, with room for `items` values.
    pub(crate) fn with_capacity(items: usize) -> Lists {
        Lists {
            start: vec![0],
            items: Vec::with_capacity(items),
        }
    }

    /// Appends a list.
    pub(crate) fn push(&mut self, list: impl IntoIterator<Item = usize>) {
        self.items.extend(list);
        self.start.push(self.items.len());
    }

    /// How many lists.
    pub fn len(&self) -> usize {
        self.start.len() - 1
    }

    /// Whether there is no list.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The lists in order.
    pub fn iter(&self) -> impl Iterator<Item = &[usize]> {
        self.start.windows(2).map(|w| &self.items[w[0]..w[1]])
    }
}

impl Index<usize> for Lists {
    type Output = [usize];
    fn index(&self, i: usize) -> &[usize] {
        &self.items[self.start[i]..self.start[i + 1]]
    }
}

impl IndexMut<usize> for Lists {
    fn index_mut(&mut self, i: usize) -> &mut [usize] {
        &mut self.items[self.start[i]..self.start[i + 1]]
    }
}

/// The plane graph of a truss.
#[derive(Debug, Clone, PartialEq)]
pub struct PlaneGraph {
    /// Outgoing half-edges of every joint, counter-clockwise by angle.
    pub around: Lists,
    /// Angle of every half-edge (radians, in (−π, π]).
    pub angle: Vec<f64>,
    /// The next half-edge along the same face.
    pub next: Vec<usize>,
    /// The face left of every half-edge.
    pub face_of: Vec<usize>,
    /// Every face as its cycle of half-edges.
    pub faces: Lists,
    /// The outside face.
    pub outer: usize,
}

/// Joint at the start of half-edge `h`.
pub fn origin(t: &Truss, h: usize) -> usize {
    t.members[h / 2].ends[h % 2]
}

/// Joint at the end of half-edge `h`.
pub fn dest(t: &Truss, h: usize) -> usize {
    t.members[h / 2].ends[1 - h % 2]
}

/// Why a truss has no plane graph.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GraphError {
    /// Some joint cannot be reached from the first one.
    Disconnected {
        /// A joint not reached.
        joint: usize,
    },
    /// Members cross each other (Euler's formula fails).
    Crossing,
}

/// Builds the plane graph, O(s log s).
pub fn plane_graph(t: &Truss) -> Result<PlaneGraph, GraphError> {
    let (angle, around) = half_edges(t);
    if let Some(joint) = unreached(t, &around) {
        return Err(GraphError::Disconnected { joint });
    }
    let next = next_half_edges(t, &around);
    let (face_of, faces) = trace_faces(&next);
    let areas: Vec<f64> = faces.iter().map(|c| signed_area(t, c)).collect();
    let outer = (0..faces.len())
        .min_by(|&a, &b| areas[a].total_cmp(&areas[b]).then(a.cmp(&b)))
        .unwrap_or(0);
    // Euler: k − s + f = 2 for a connected plane drawing (a single joint has one face).
    let k = t.joints.len() as i64;
    if !faces.is_empty() && k - t.members.len() as i64 + faces.len() as i64 != 2 {
        return Err(GraphError::Crossing);
    }
    // A bounded face traced clockwise means the drawing folds over itself.
    if areas
        .iter()
        .enumerate()
        .any(|(f, &a)| f != outer && a <= 0.0)
    {
        return Err(GraphError::Crossing);
    }
    Ok(PlaneGraph {
        around,
        angle,
        next,
        face_of,
        faces,
        outer,
    })
}

/// The direction angle of every half-edge, and the half-edges leaving each joint ordered
/// counter-clockwise.
fn half_edges(t: &Truss) -> (Vec<f64>, Lists) {
    let nh = 2 * t.members.len();
    let angle: Vec<f64> = (0..nh)
        .map(|h| {
            let d = t.joints[dest(t, h)].at - t.joints[origin(t, h)].at;
            d.y.atan2(d.x)
        })
        .collect();
    let mut around = Lists::grouped(t.joints.len(), (0..nh).map(|h| (origin(t, h), h)));
    for j in 0..around.len() {
        around[j].sort_by(|&a, &b| angle[a].total_cmp(&angle[b]).then(a.cmp(&b)));
    }
    (angle, around)
}

/// A joint the members do not reach from the first one, if there is one.
fn unreached(t: &Truss, around: &Lists) -> Option<usize> {
    let k = t.joints.len();
    let mut seen = vec![false; k];
    let mut stack = vec![0];
    if k > 0 {
        seen[0] = true;
    }
    while let Some(v) = stack.pop() {
        for &h in &around[v] {
            let w = dest(t, h);
            if !seen[w] {
                seen[w] = true;
                stack.push(w);
            }
        }
    }
    seen.iter().position(|s| !s)
}

/// next(u→v) = the half-edge leaving v clockwise next to v→u: walking it traces a face.
fn next_half_edges(t: &Truss, around: &Lists) -> Vec<usize> {
    let nh = 2 * t.members.len();
    let mut pos = vec![0; nh];
    for list in around.iter() {
        for (i, &h) in list.iter().enumerate() {
            pos[h] = i;
        }
    }
    (0..nh)
        .map(|h| {
            let back = h ^ 1;
            let list = &around[origin(t, back)];
            list[(pos[back] + list.len() - 1) % list.len()]
        })
        .collect()
}

/// The faces, each the cycle of half-edges that `next` walks, and the face of every
/// half-edge.
fn trace_faces(next: &[usize]) -> (Vec<usize>, Lists) {
    let mut face_of = vec![usize::MAX; next.len()];
    let mut faces = Lists::with_capacity(next.len());
    let mut cycle = Vec::new();
    for h0 in 0..next.len() {
        if face_of[h0] != usize::MAX {
            continue;
        }
        let f = faces.len();
        let mut h = h0;
        while face_of[h] == usize::MAX {
            face_of[h] = f;
            cycle.push(h);
            h = next[h];
        }
        faces.push(cycle.drain(..));
    }
    (face_of, faces)
}

/// The signed area of a face (counter-clockwise positive), by the shoelace formula.
fn signed_area(t: &Truss, cycle: &[usize]) -> f64 {
    cycle
        .iter()
        .map(|&h| {
            let a = t.joints[origin(t, h)].at;
            let b = t.joints[dest(t, h)].at;
            a.x * b.y - a.y * b.x
        })
        .sum::<f64>()
        * 0.5
}

/// Clockwise angle from `from` to `to` (radians, in [0, 2π)).
pub fn cw(from: f64, to: f64) -> f64 {
    (from - to).rem_euclid(TAU)
}
