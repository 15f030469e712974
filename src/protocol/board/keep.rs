//! What a board keeps: its steps and objects, or only its checks (the ledger).

use super::*;

/// The checks of a board that does not keep its drawing: steps and objects are counted, the
/// checks kept with the step and the situation they belong to, and each object's error
/// bound tracked, in some 30 bytes per object that carries a bound (what is only drawn
/// carries none and is only counted) instead of a protocol of some 1 KB per step.
#[derive(Debug, Clone, Default)]
pub(super) struct Ledger {
    /// The value of each number, by its id (in id order): what the bounds of numbers
    /// reckoned from numbers need. The step that made each object is in its track.
    pub(super) numbers: Vec<(ObjId, f64)>,
    /// The checks with the step they are attached to, in the order filed, while there are
    /// at most [`LISTED_CHECKS`](crate::protocol::summary::LISTED_CHECKS) (or every one was asked for).
    pub(super) checks: crate::protocol::tracks::Chunked<(StepId, Check)>,
    /// Every check counted, per kind, with the worst of each kind and every failure.
    pub(super) summary: crate::protocol::summary::CheckSummary,
    /// Keep every check however many ([`Mode::Checks`]'s `every`).
    pub(super) every: bool,
    /// The objects only drawn ([`Board::add_drawing`]), counted.
    pub(super) drawings: usize,
    /// The situation from each step on where it changed, in step order.
    pub(super) contexts: Vec<(StepId, Option<std::sync::Arc<str>>)>,
}

impl Ledger {
    pub(super) fn new(every: bool) -> Ledger {
        Ledger {
            every,
            ..Ledger::default()
        }
    }

    /// Counts a check, and keeps it while the checks are listed one by one.
    pub(super) fn file(&mut self, step: StepId, check: Check) {
        self.summary.add(step, &check);
        if !self.summarised() {
            self.checks.push((step, check));
        } else if self.checks.len() > 0 {
            self.checks = Default::default();
        }
    }

    /// Whether only the summary is kept: more checks than are listed, and not every one asked
    /// for.
    pub(super) fn summarised(&self) -> bool {
        !self.every && self.summary.total > crate::protocol::summary::LISTED_CHECKS as u64
    }

    /// The checks kept whole: every one, or past the list's limit the failures.
    pub(super) fn kept(&self) -> impl Iterator<Item = &(StepId, Check)> {
        let failures = if self.summarised() {
            &self.summary.failures[..]
        } else {
            &[]
        };
        self.checks.iter().chain(failures)
    }

    /// Sets the situation from `step` on; a change for the step the last one was filed for
    /// takes its place (a naming put back before a step was made in it).
    pub(super) fn set_context(&mut self, step: StepId, c: Option<std::sync::Arc<str>>) {
        match self.contexts.last_mut() {
            Some((s, last)) if *s == step => *last = c,
            _ => self.contexts.push((step, c)),
        }
    }

    /// The situation the next step is made in: the last one filed.
    pub(super) fn current(&self) -> Option<&std::sync::Arc<str>> {
        self.contexts.last().and_then(|(_, c)| c.as_ref())
    }

    /// The situation the step was made in.
    pub(super) fn context(&self, step: StepId) -> Option<&str> {
        let i = self.contexts.partition_point(|(s, _)| *s <= step);
        i.checked_sub(1).and_then(|i| self.contexts[i].1.as_deref())
    }
}

impl Board {
    pub(super) fn step_id_next(&self) -> StepId {
        StepId(self.next_step + 1)
    }

    /// Counts a step and, on a recording board, files it. Inlined, so that a board that does
    /// not record pays only the count for it (the construction's hot path).
    #[inline]
    pub(super) fn begin(&mut self, kind: StepKind, note: &Note, inputs: &[ObjId]) {
        self.next_step += 1;
        if self.recording {
            if self.next_step > self.keep_steps {
                self.spill();
                return;
            }
            self.file_step(kind, note, inputs);
        }
    }

    /// Lets go of everything kept and counts on as a board that does not record: the
    /// steps past [`BoardConfig::keep_steps`](crate::protocol::BoardConfig::keep_steps).
    #[cold]
    fn spill(&mut self) {
        self.recording = false;
        self.spilled = true;
        self.steps = Vec::new();
        self.objects = Vec::new();
        self.tracks = Default::default();
        self.shadows = None;
        self.ledger = None;
        self.context = None;
        self.checked_object = None;
    }

    pub(super) fn file_step(&mut self, kind: StepKind, note: &Note, inputs: &[ObjId]) {
        if self.ledger.is_none() {
            self.steps.push(Step {
                id: StepId(self.next_step),
                kind,
                topic: note.topic,
                caption: note.caption.clone(),
                term_de: note.term_de.clone(),
                book: note.book.clone(),
                context: self.context.clone(),
                inputs: Ids::from_slice(inputs),
                outputs: Ids::new(),
                conditioning: None,
                branch: None,
                outcome: None,
                checks: Vec::new(),
                part: self.part,
            });
        }
    }

    /// Files an object (on a board that keeps only its checks, counts it with its track).
    /// Inlined, so that a board that does not record pays one test for it.
    #[inline(always)]
    pub(super) fn add(&mut self, label: Label, role: Role, geom: impl FnOnce() -> Geom) -> ObjId {
        if !self.recording {
            return ObjId::NONE;
        }
        if self.ledger.is_some() {
            // Not drawn: its geometry is never made ([`Board::add_number`] keeps a number's
            // value).
            return self.count_object(None);
        }
        self.file_object(label, role, geom())
    }

    /// [`Board::add`] for what is only drawn (a segment, a curve, a table, hatching): no
    /// step follows from it, so a board that keeps only its checks counts it and gives it
    /// no id and no track.
    #[inline(always)]
    pub(super) fn add_drawing(
        &mut self,
        label: Label,
        role: Role,
        geom: impl FnOnce() -> Geom,
    ) -> ObjId {
        if !self.recording {
            return ObjId::NONE;
        }
        if let Some(l) = self.ledger.as_mut() {
            l.drawings += 1;
            return ObjId::NONE;
        }
        self.file_object(label, role, geom())
    }

    /// [`Board::add`] for a number: a board that keeps only its checks keeps its value.
    #[inline(always)]
    pub(super) fn add_number(&mut self, label: Label, value: f64, unit: &'static str) -> ObjId {
        if !self.recording {
            return ObjId::NONE;
        }
        if self.ledger.is_some() {
            return self.count_object(Some(value));
        }
        self.file_object(label, Role::Result, Geom::Scalar { value, unit })
    }

    /// An object of a board that keeps only its checks: an id, its bound, its step and,
    /// for a number, its value.
    pub(super) fn count_object(&mut self, number: Option<f64>) -> ObjId {
        let id = ObjId(self.tracks.len() as u32 + 1);
        self.tracks.push(StepId(self.next_step));
        if let (Some(value), Some(l)) = (number, self.ledger.as_mut()) {
            l.numbers.push((id, value));
        }
        id
    }

    /// The value of a number on the board (kept or only counted), `None` for other objects.
    pub(super) fn number(&self, id: ObjId) -> Option<f64> {
        let i = (id.0 as usize).wrapping_sub(1);
        match self.ledger.as_deref() {
            Some(l) => l
                .numbers
                .binary_search_by_key(&id, |n| n.0)
                .ok()
                .map(|k| l.numbers[k].1),
            None => match self.objects.get(i).map(|o| &o.geom) {
                Some(Geom::Scalar { value, .. }) => Some(*value),
                _ => None,
            },
        }
    }

    pub(super) fn file_object(&mut self, label: Label, role: Role, geom: Geom) -> ObjId {
        let id = ObjId(self.tracks.len() as u32 + 1);
        let step = StepId(self.next_step);
        self.tracks.push(step);
        if let Some(s) = self.shadows.as_mut() {
            s.push(Shadow::None);
        }
        self.objects.push(Object {
            id,
            step,
            label,
            role,
            geom,
        });
        if let Some(s) = self.steps.last_mut() {
            s.outputs.push(id);
        }
        id
    }

    #[inline]
    pub(super) fn last_step(&mut self) -> Option<&mut Step> {
        if self.recording {
            self.steps.last_mut()
        } else {
            None
        }
    }

    /// Grows the drawn extent of a line, or adds a compass mark on a circle, so that the
    /// figure shows the line up to the point constructed on it.
    #[inline]
    pub(super) fn touch(&mut self, on: ObjId, p: &Point) {
        if !self.recording || on == ObjId::NONE {
            return;
        }
        self.touch_recorded(on, p);
    }

    pub(super) fn touch_recorded(&mut self, on: ObjId, p: &Point) {
        let idx = on.0 as usize - 1;
        if let Some(obj) = self.objects.get_mut(idx) {
            match &mut obj.geom {
                Geom::Line { line, extent } => {
                    let t = line.param_of(p);
                    extent[0] = extent[0].min(t);
                    extent[1] = extent[1].max(t);
                }
                Geom::Circle { circle, marks, .. } => {
                    let v = p - circle.center;
                    marks.push(v.y.atan2(v.x).to_degrees());
                }
                _ => {}
            }
        }
    }
}
