//! The error bounds of a board's objects, packed: 28 bytes an object (its bound, a line's
//! turn or a point's error across its axis, the place of its axis, its worst cut and the
//! step that made it); a point's axis (16 bytes) is kept only for the points that have one,
//! and each cut's step, conditioning and amplification once per cut. In chunks, so that a
//! board of millions of objects neither doubles its memory when it grows nor copies what it
//! holds.

use super::accuracy::{Track, Worst, WorstCut};
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

    /// Appends an item: where the last chunk has room, one test and the write.
    #[inline]
    pub fn push(&mut self, x: T) {
        match self.chunks.last_mut() {
            Some(c) if c.len() < c.capacity() => c.push(x),
            _ => self.push_growing(x),
        }
        self.len += 1;
    }

    /// [`Chunked::push`] where the last chunk is full: the first chunk grows as a `Vec` does
    /// (a small board stays small), by doubling up to a whole chunk; the others are made
    /// whole.
    #[cold]
    fn push_growing(&mut self, x: T) {
        match self.chunks.last_mut() {
            Some(c) if c.len() < CHUNK => {
                let room = c.len().max(4).min(CHUNK - c.len());
                c.reserve_exact(room);
                c.push(x);
            }
            Some(_) => {
                let mut c = Vec::with_capacity(CHUNK);
                c.push(x);
                self.chunks.push(c);
            }
            None => self.chunks.push(vec![x]),
        }
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

    #[inline]
    pub fn get(&self, i: usize) -> Option<&T> {
        self.chunks.get(i / CHUNK)?.get(i % CHUNK)
    }

    #[inline]
    pub fn get_mut(&mut self, i: usize) -> Option<&mut T> {
        self.chunks.get_mut(i / CHUNK)?.get_mut(i % CHUNK)
    }

    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.chunks.iter().flatten()
    }
}

/// One object's track. A line's track has no axis and a point's with an axis no turn (a
/// cut point is not turned), so one number holds either: `more` is the turn where `axis`
/// is 0, and the error across the axis where there is one (where there is none, that error
/// is the whole error, `err`).
#[derive(Debug, Clone, Copy, Default)]
#[repr(C, packed(4))]
struct Packed {
    err: f64,
    more: f64,
    /// The axis: its place in [`Tracks::axes`] plus one (0: none).
    axis: u32,
    /// The worst cut: its place in [`Tracks::cuts`] plus one (0: none).
    worst: u32,
    /// The step that made the object.
    step: u32,
}

/// A cut an object names as its worst: its step, its conditioning and its amplification.
#[derive(Debug, Clone, Copy)]
struct Cut {
    step: StepId,
    conditioning: Conditioning,
    amp: f64,
}

/// Every object's track, in object order.
#[derive(Debug, Clone, Default)]
pub(crate) struct Tracks {
    packed: Chunked<Packed>,
    /// The axes of the points that have one, in the order set.
    axes: Chunked<[f64; 2]>,
    /// The cuts objects name as their worst, in the order first named.
    cuts: Vec<Cut>,
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
    #[inline]
    pub fn push(&mut self, step: StepId) {
        self.packed.push(Packed {
            step: step.0,
            ..Packed::default()
        });
    }

    /// The track of object `i` (from 0).
    #[inline]
    pub fn get(&self, i: usize) -> Option<Track> {
        let p = *self.packed.get(i)?;
        let worst = match (p.worst as usize).checked_sub(1) {
            Some(k) => Worst {
                amp: self.cuts[k].amp,
                place: p.worst,
            },
            None => Worst::NONE,
        };
        let (err, more) = (p.err, p.more);
        let axis = (p.axis as usize)
            .checked_sub(1)
            .and_then(|k| self.axes.get(k));
        Some(match axis {
            Some(&[x, y]) => Track {
                err,
                turn: 0.0,
                worst,
                axis: Vector::new(x, y),
                off: more,
            },
            None => Track {
                err,
                turn: more,
                worst,
                axis: Vector::zeros(),
                off: err,
            },
        })
    }

    /// The worst cut a track names, as its step and conditioning.
    pub fn worst_cut(&self, w: Worst) -> Option<WorstCut> {
        let k = (w.place as usize).checked_sub(1)?;
        self.cuts.get(k).map(|c| WorstCut {
            step: c.step,
            conditioning: c.conditioning,
        })
    }

    /// The step that made object `i`.
    #[inline]
    pub fn step(&self, i: usize) -> Option<StepId> {
        self.packed.get(i).map(|p| StepId(p.step))
    }

    /// Sets the track of object `i`, made by `step`; `own` is the conditioning of the cut the
    /// step makes, where it makes one: filed here if the track names it as its worst (once
    /// per step: a step's cut keeps the conditioning it was first named with).
    pub fn set(&mut self, i: usize, t: Track, own: Option<(StepId, Conditioning)>) {
        let worst = match (t.worst.place, own) {
            (Worst::OWN, Some((step, conditioning))) => self.file_cut(step, conditioning, t.worst),
            (Worst::OWN, None) => 0,
            (place, _) => place,
        };
        debug_assert!(t.axis == Vector::zeros() || t.turn == 0.0, "{t:?}");
        let (axis, more) = if t.axis == Vector::zeros() {
            (0, t.turn)
        } else {
            self.axes.push([t.axis.x, t.axis.y]);
            (self.axes.len() as u32, t.off)
        };
        if let Some(p) = self.packed.get_mut(i) {
            *p = Packed {
                err: t.err,
                more,
                axis,
                worst,
                step: p.step,
            };
        }
    }

    /// The place (plus one) of the cut `step` makes, filed if it is not yet: a step's cuts
    /// are followed before the next step's, so a step already filed is the last one.
    fn file_cut(&mut self, step: StepId, conditioning: Conditioning, own: Worst) -> u32 {
        if self.cuts.last().is_none_or(|c| c.step != step) {
            self.cuts.push(Cut {
                step,
                conditioning,
                amp: own.amp,
            });
        }
        self.cuts.len() as u32
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
        let cond = |deg: f64| Conditioning::from_angle(f64::to_radians(deg));
        for i in 0..(2 * CHUNK + 5) {
            t.push(StepId(i as u32 / 3 + 1));
        }
        // A point cut at 30° with an axis, a line turned, a point named after an earlier cut.
        let point = Track {
            err: 1.5,
            turn: 0.0,
            worst: Worst::own(cond(30.0)),
            axis: Vector::new(0.6, 0.8),
            off: 0.5,
        };
        let line = Track {
            err: 2.5,
            turn: 0.25,
            worst: Worst::NONE,
            axis: Vector::zeros(),
            off: 2.5,
        };
        t.set(CHUNK + 1, point, Some((StepId(7), cond(30.0))));
        t.set(CHUNK + 2, line, None);
        let filed = t.get(CHUNK + 1).unwrap();
        assert_eq!(filed.worst.place, 1);
        assert_eq!(filed.worst.amp, cond(30.0).amplification());
        assert_eq!(
            Track {
                worst: point.worst,
                ..filed
            },
            point
        );
        assert_eq!(t.get(CHUNK + 2), Some(line));
        let later = Track {
            axis: Vector::zeros(),
            off: 1.5,
            worst: filed.worst,
            ..point
        };
        t.set(2 * CHUNK + 4, later, Some((StepId(9), cond(10.0))));
        assert_eq!(t.get(2 * CHUNK + 4), Some(later));
        let named = t.worst_cut(later.worst).unwrap();
        assert_eq!((named.step, named.conditioning), (StepId(7), cond(30.0)));
        assert_eq!(t.get(0), Some(Track::default()));
        assert_eq!(
            t.step(2 * CHUNK + 4),
            Some(StepId((2 * CHUNK as u32 + 4) / 3 + 1))
        );
        assert_eq!(t.get(2 * CHUNK + 5), None);
        assert_eq!(t.len(), 2 * CHUNK + 5);
        assert_eq!(t.cuts.len(), 1);
        assert_eq!(std::mem::size_of::<Packed>(), 28);
    }

    #[test]
    fn a_steps_cut_is_filed_once_with_its_first_conditioning() {
        let mut t = Tracks::default();
        let (a, b) = (
            Conditioning::from_angle(0.5),
            Conditioning::from_angle(0.25),
        );
        (0..3).for_each(|_| t.push(StepId(4)));
        let cut = |c: Conditioning| Track {
            err: 1.0,
            worst: Worst::own(c),
            ..Track::default()
        };
        t.set(0, cut(a), Some((StepId(4), a)));
        t.set(1, cut(b), Some((StepId(4), b)));
        let (x, y) = (t.get(0).unwrap().worst, t.get(1).unwrap().worst);
        assert_eq!(x, y);
        assert_eq!(x.amp, a.amplification());
        assert_eq!(t.worst_cut(y).map(|w| w.conditioning), Some(a));
        assert_eq!(t.worst_cut(Worst::NONE), None);
    }
}
