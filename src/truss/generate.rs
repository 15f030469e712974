//! Parallel-chord trusses of any size (Warren, Pratt, Howe), on a pin at the left and a
//! roller at the right: for tests, benchmarks and scenes that want a long girder.
//!
//! Joints are named B0 … Bn along the bottom chord and T… along the top; members are
//! numbered from 1.

use super::{Joint, Member, Support, Truss};
use crate::kernel::{Point, Vector};

/// The web of a parallel-chord truss.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Web {
    /// Diagonals only, alternating (no verticals).
    Warren,
    /// Verticals, diagonals falling towards mid-span (in tension under gravity loads).
    Pratt,
    /// Verticals, diagonals rising towards mid-span (in compression under gravity loads).
    Howe,
}

/// A truss of `n ≥ 2` panels of length `panel` (m) and height `height` (m).
///
/// Warren: k = 2n + 1 joints, s = 4n − 1 members. Pratt and Howe: k = 2n, s = 4n − 3. All
/// are determinate (s = 2k − 3).
pub fn parallel_chord(web: Web, n: usize, panel: f64, height: f64) -> Truss {
    let n = n.max(2);
    let mut joints: Vec<Joint> = (0..=n)
        .map(|i| Joint {
            name: format!("B{i}").into(),
            at: Point::new(i as f64 * panel, 0.0),
        })
        .collect();
    let mut members = Vec::new();
    let add = |members: &mut Vec<Member>, a: usize, b: usize| {
        let name = (members.len() + 1).to_string();
        members.push(Member {
            name: name.into(),
            ends: [a, b],
        });
    };
    for i in 0..n {
        add(&mut members, i, i + 1);
    }
    match web {
        Web::Warren => {
            // Top joints over the middle of each panel.
            let t0 = joints.len();
            for i in 0..n {
                joints.push(Joint {
                    name: format!("T{i}").into(),
                    at: Point::new((i as f64 + 0.5) * panel, height),
                });
            }
            for i in 0..n {
                add(&mut members, i, t0 + i);
                add(&mut members, t0 + i, i + 1);
                if i + 1 < n {
                    add(&mut members, t0 + i, t0 + i + 1);
                }
            }
        }
        Web::Pratt | Web::Howe => {
            // Top joints over the inner bottom joints 1 … n−1; T(i) has index t0 + i − 1.
            let t0 = joints.len();
            for i in 1..n {
                joints.push(Joint {
                    name: format!("T{i}").into(),
                    at: Point::new(i as f64 * panel, height),
                });
            }
            let top = |i: usize| t0 + i - 1;
            add(&mut members, 0, top(1));
            add(&mut members, n, top(n - 1));
            for i in 1..n {
                add(&mut members, i, top(i));
                if i + 1 < n {
                    add(&mut members, top(i), top(i + 1));
                }
            }
            // Inner panels j = 1 … n−2, between the verticals at j and j + 1.
            for j in 1..n.saturating_sub(1) {
                let left_half = 2 * j + 1 < n;
                let falls_inward = (web == Web::Pratt) == left_half;
                if falls_inward {
                    add(&mut members, top(j), j + 1);
                } else {
                    add(&mut members, j, top(j + 1));
                }
            }
        }
    }
    Truss::new(
        joints,
        members,
        vec![
            Support::pinned(0, "A"),
            Support::roller(n, Vector::new(0.0, 1.0), "B"),
        ],
    )
}
