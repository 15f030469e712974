//! The error bounds of a board's objects, packed: 48 bytes an object (its bound, its turn,
//! the direction of its error, the step that made it and its worst cut, whose step and
//! conditioning are kept once per cut), in chunks, so that a board of millions of objects
//! neither doubles its memory when it grows nor copies what it holds.

use super::accuracy::{Track, WorstCut};
use super::step::StepId;
use crate::kernel::{Conditioning, Vector};

/// Items per chunk.
const CHUNK: usize = 1 << 14;

/// A growing list kept in chunks of [`CHUNK`] items: it never holds more than one chunk of
/// spare room and never copies more than a chunk to grow (a `Vec` of millions of items may
/// hold twice their size, and three times while it grows).
#[derive(Debug, Clone)]
pub(crate) struct Chunked<T> {
    chunks: Vec<Vec<T>>,
    len: usize,
}

impl<T> Default for Chunked<T> {
    fn default() -> Self {
        Chunked {
            chunks: Vec::new(),
            len: 0,
        }
    }
}

impl<T> Chunked<T> {
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn push(&mut self, x: T) {
        // The first chunk grows as a Vec does (a small board stays small), up to CHUNK (a
        // power of two, where doubling stops exactly); the others are made whole.
        if self.len == self.chunks.len() * CHUNK {
            self.chunks.push(if self.len == 0 {
                Vec::new()
            } else {
                Vec::with_capacity(CHUNK)
            });
        }
        if let Some(c) = self.chunks.last_mut() {
            c.push(x);
        }
        self.len += 1;
    }

    /// Makes room for `n` more items in the first chunk, up to a chunk (the others are made
    /// whole): a construction that knows its size does not copy its first chunk as it grows.
    pub fn reserve(&mut self, n: usize) {
        if self.len < CHUNK {
            if self.chunks.is_empty() {
                self.chunks.push(Vec::new());
            }
            let room = (self.len + n).min(CHUNK) - self.len;
            self.chunks[0].reserve_exact(room);
        }
    }

    pub fn get(&self, i: usize) -> Option<&T> {
        self.chunks.get(i / CHUNK)?.get(i % CHUNK)
    }

    pub fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        self.chunks.get_mut(i / CHUNK)?.get_mut(i % CHUNK)
    }

    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.chunks.iter().flatten()
    }
}

#[derive(Debug, Clone, Copy, Default)]
struct Packed {
    err: f64,
    turn: f64,
    off: f64,
    axis: [f64; 2],
    /// The worst cut: its place in [`Tracks::cuts`] plus one (0: none).
    worst: u32,
    /// The step that made the object.
    step: u32,
}

/// Every object's track, in object order.
#[derive(Debug, Clone, Default)]
pub(crate) struct Tracks {
    packed: Chunked<Packed>,
    /// The cuts objects name as their worst, in the order first named.
    cuts: Vec<(StepId, Conditioning)>,
    /// Each cut's place in `cuts`, by its step.
    places: foldhash::HashMap<StepId, u32>,
}

impl Tracks {
    pub fn len(&self) -> usize {
        self.packed.len()
    }

    /// Makes room for `n` more objects (see [`Chunked::reserve`]).
    pub fn reserve(&mut self, n: usize) {
        self.packed.reserve(n);
    }

    /// A new object made by `step`, with no error yet.
    pub fn push(&mut self, step: StepId) {
        self.packed.push(Packed {
            step: step.0,
            ..Packed::default()
        });
    }

    fn packed(&self, i: usize) -> Option<&Packed> {
        self.packed.get(i)
    }

    /// The track of object `i` (from 0).
    pub fn get(&self, i: usize) -> Option<Track> {
        let p = self.packed(i)?;
        let worst = (p.worst as usize)
            .checked_sub(1)
            .and_then(|k| self.cuts.get(k))
            .map(|&(step, conditioning)| WorstCut { step, conditioning });
        Some(Track {
            err: p.err,
            turn: p.turn,
            worst,
            axis: Vector::new(p.axis[0], p.axis[1]),
            off: p.off,
        })
    }

    /// The step that made object `i`.
    pub fn step(&self, i: usize) -> Option<StepId> {
        self.packed(i).map(|p| StepId(p.step))
    }

    /// The place of a cut in `cuts`, where it is first named: the cut just made (the usual
    /// case) without a lookup. A step's cut keeps the conditioning it was first named with.
    fn place(&mut self, w: WorstCut) -> u32 {
        let n = self.cuts.len() as u32;
        if self.cuts.last().is_some_and(|c| c.0 == w.step) {
            return n - 1;
        }
        *self.places.entry(w.step).or_insert_with(|| {
            self.cuts.push((w.step, w.conditioning));
            n
        })
    }

    /// Sets the track of object `i`.
    pub fn set(&mut self, i: usize, t: Track) {
        let worst = match t.worst {
            None => 0,
            Some(w) => self.place(w) + 1,
        };
        if let Some(p) = self.packed.get_mut(i) {
            *p = Packed {
                err: t.err,
                turn: t.turn,
                off: t.off,
                axis: [t.axis.x, t.axis.y],
                worst,
                step: p.step,
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn room_made_in_the_first_chunk_keeps_every_chunk_whole() {
        for (before, room) in [(0, 10), (0, 5 * CHUNK), (3, CHUNK), (CHUNK, 7)] {
            let mut c = Chunked::default();
            (0..before).for_each(|i| c.push(i));
            c.reserve(room);
            let cap = c.chunks.first().map_or(0, Vec::capacity);
            assert!(
                before >= CHUNK || cap >= (before + room).min(CHUNK),
                "{cap}"
            );
            (before..2 * CHUNK + 3).for_each(|i| c.push(i));
            assert_eq!(c.len(), 2 * CHUNK + 3);
            assert_eq!(c.chunks.len(), 3);
            assert!(c.chunks[..2].iter().all(|k| k.len() == CHUNK));
            assert!(c.iter().copied().eq(0..2 * CHUNK + 3));
            assert_eq!(c.get(CHUNK + 1), Some(&(CHUNK + 1)));
        }
    }

    #[test]
    fn tracks_read_back_as_set_across_chunks() {
        let mut t = Tracks::default();
        let cut = |s: u32, deg: f64| WorstCut {
            step: StepId(s),
            conditioning: Conditioning::from_angle(deg.to_radians()),
        };
        for i in 0..(2 * CHUNK + 5) {
            t.push(StepId(i as u32 / 3 + 1));
        }
        let a = Track {
            err: 1.5,
            turn: 0.25,
            worst: Some(cut(7, 30.0)),
            axis: Vector::new(0.6, 0.8),
            off: 0.5,
        };
        let b = Track {
            worst: Some(cut(3, 10.0)),
            ..a
        };
        t.set(CHUNK + 1, a);
        t.set(2 * CHUNK + 4, b);
        assert_eq!(t.get(CHUNK + 1), Some(a));
        assert_eq!(t.get(2 * CHUNK + 4), Some(b));
        assert_eq!(t.get(0), Some(Track::default()));
        assert_eq!(
            t.step(2 * CHUNK + 4),
            Some(StepId((2 * CHUNK as u32 + 4) / 3 + 1))
        );
        assert_eq!(t.get(2 * CHUNK + 5), None);
        assert_eq!(t.len(), 2 * CHUNK + 5);
        assert_eq!(std::mem::size_of::<Packed>(), 48);
    }
}
