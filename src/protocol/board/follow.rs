//! How an object follows from its step's inputs: its bound and its reference.

use super::*;
impl Board {
    /// The propagated error bound of an object (mm for a point, its unit for a number) and
    /// the worst cut it depends on; `None` on a board that does not record.
    pub fn bound(&self, id: ObjId) -> Option<(f64, Option<WorstCut>)> {
        let t = self.tracks.get((id.0 as usize).wrapping_sub(1))?;
        Some((t.err, t.worst))
    }

    pub(super) fn tr(&self, id: ObjId) -> Track {
        self.tracks
            .get((id.0 as usize).wrapping_sub(1))
            .unwrap_or_default()
    }

    /// Sets an object's bound on a recording board: the guard inlined, the bound reckoned
    /// apart, so that a board that does not record pays a test for it.
    #[inline(always)]
    pub(super) fn set_tr(&mut self, id: ObjId, t: impl FnOnce(&Board) -> Track) {
        if self.recording && id != ObjId::NONE {
            self.set_tr_recorded(id, t);
        }
    }

    #[inline(never)]
    pub(super) fn set_tr_recorded(&mut self, id: ObjId, t: impl FnOnce(&Board) -> Track) {
        let t = t(self);
        self.tracks.set(id.0 as usize - 1, t);
    }

    pub(super) fn shadow(&self, id: ObjId) -> Shadow {
        self.shadows
            .as_ref()
            .and_then(|s| s.get((id.0 as usize).wrapping_sub(1)).copied())
            .unwrap_or_default()
    }

    #[inline]
    pub(super) fn set_shadow(&mut self, id: ObjId, f: impl FnOnce(&Board) -> Shadow) {
        if self.shadows.is_some() && id != ObjId::NONE {
            self.set_shadow_replayed(id, f);
        }
    }

    #[inline(never)]
    pub(super) fn set_shadow_replayed(&mut self, id: ObjId, f: impl FnOnce(&Board) -> Shadow) {
        let v = f(self);
        if let Some(s) = self.shadows.as_mut() {
            s[id.0 as usize - 1] = v;
        }
    }

    // The reference of a handle is its object's, unless a procedure made the handle with an
    // object's id but geometry of its own (a line's normal, a value's magnitude): then the
    // handle's f64 geometry is taken as given.

    pub(super) fn sp(&self, h: &H<Point>) -> DP {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Point(p), Some(Geom::Point { at })) if *at == h.g => p,
            _ => DP::of(&h.g),
        }
    }

    pub(super) fn sl(&self, h: &H<Line>) -> (DP, DP) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Line { o, d }, Some(Geom::Line { line, .. })) if *line == h.g => (o, d),
            _ => (DP::of(&h.g.origin), DP::of_vec(&h.g.dir)),
        }
    }

    pub(super) fn sc(&self, h: &H<Circle>) -> (DP, twofloat::TwoFloat) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Circle { c, r }, Some(Geom::Circle { circle, .. })) if *circle == h.g => {
                (c, r)
            }
            _ => (DP::of(&h.g.center), h.g.radius.into()),
        }
    }

    pub(super) fn sv(&self, h: &H<f64>) -> twofloat::TwoFloat {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Scalar(v), Some(Geom::Scalar { value, .. })) if *value == h.g => v,
            _ => h.g.into(),
        }
    }
}
