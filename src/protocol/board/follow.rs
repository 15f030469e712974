//! How an object follows from its step's inputs: stated once by the step ([`Derived`]), and
//! read by each follower the board keeps: the propagated error bound ([`Board::bound`]) and
//! the double-double reference of a board made
//! [`with_reference`](super::BoardConfig::with_reference).
//!
//! A step method says what it drew and from what (`self.made(mark, p, geom, Derived::Foot
//! { .. })`); which followers run is the board's setting, not the step's: a silent board pays
//! one test, a recording board files the bound, a reference board the bound and the replay.

use super::*;

/// How an object follows from the inputs of the step that made it.
#[derive(Clone, Copy)]
pub(super) enum Derived<'a> {
    /// A given point.
    Given(Point),
    /// The line through a point in a given direction.
    Ray { at: &'a H<Point>, dir: Vector },
    /// The line through two points (the ruler).
    Ruled(&'a H<Point>, &'a H<Point>),
    /// The set square slid along a line to a point; `turned`: the perpendicular.
    Slid {
        line: &'a H<Line>,
        through: &'a H<Point>,
        turned: bool,
    },
    /// A circle about a centre, its radius set on the compass.
    Compass {
        center: &'a H<Point>,
        circle: Circle,
    },
    /// The point `at` of a circle in the direction `dir` from its centre.
    OnCircle {
        circle: &'a H<Circle>,
        at: Point,
        dir: SinCos,
    },
    /// The point `at`, `length` mm laid off from a point along a line; `carried`: a value read
    /// earlier and its units per mm, which the length was taken from (the dividers).
    Laid {
        from: &'a H<Point>,
        along: &'a H<Line>,
        length: f64,
        carried: Option<(&'a H<f64>, f64)>,
        at: Point,
    },
    /// The foot `at` of the perpendicular from a point on a line.
    Foot {
        line: &'a H<Line>,
        from: &'a H<Point>,
        at: Point,
    },
    /// The point `at` dividing `a`–`b` at the ratio `t`.
    Between {
        a: &'a H<Point>,
        b: &'a H<Point>,
        t: f64,
        at: Point,
    },
    /// The point `at` where two curves cut at `cond` (before the hand marks it).
    Cut {
        of: Cutting<'a>,
        at: Point,
        cond: Conditioning,
    },
    /// A distance read along a line's direction, `mm` on the sheet, at a scale.
    Measured {
        from: &'a H<Point>,
        to: &'a H<Point>,
        axis: &'a H<Line>,
        mm: f64,
        scale: Scale,
    },
    /// The angle `value` (degrees) at a vertex, read with the protractor.
    Angle {
        vertex: &'a H<Point>,
        from: &'a H<Point>,
        to: &'a H<Point>,
        value: f64,
    },
    /// A number reckoned from weighted inputs (no reference: it is not drawn).
    Reckoned { inputs: Weighted<'a>, value: f64 },
}

/// The two curves a cut intersects.
#[derive(Clone, Copy)]
pub(super) enum Cutting<'a> {
    /// Two lines.
    Lines(&'a H<Line>, &'a H<Line>),
    /// A line and a circle.
    LineCircle(&'a H<Line>, &'a H<Circle>),
    /// Two circles.
    Circles(&'a H<Circle>, &'a H<Circle>),
}

impl Board {
    /// Files the object a step made, lettered and drawn as `mark` says, with how it follows
    /// from the step's inputs: the one call a step method makes per object it computes.
    #[inline(always)]
    pub(super) fn made<T>(
        &mut self,
        mark: Mark,
        g: T,
        geom: impl FnOnce() -> Geom,
        how: Derived<'_>,
    ) -> H<T> {
        let id = self.add(mark.label, mark.role, geom);
        self.follow(id, how);
        H { id, g }
    }

    /// [`Board::made`] for a point drawn as a given point, lettered `label`.
    #[inline(always)]
    pub(super) fn made_point(&mut self, label: Label, at: Point, how: Derived<'_>) -> H<Point> {
        let mark = Mark {
            label,
            role: Role::Given,
        };
        self.made(mark, at, || Geom::Point { at }, how)
    }

    /// [`Board::made`] for a number read or reckoned: a result, with its unit.
    #[inline(always)]
    pub(super) fn made_number(
        &mut self,
        label: Label,
        (value, unit): (f64, &'static str),
        how: Derived<'_>,
    ) -> H<f64> {
        let id = self.add_number(label, value, unit);
        self.follow(id, how);
        H { id, g: value }
    }

    /// Files how the object `id` follows from its step's inputs. Inlined, so that a board
    /// that does not record pays one test for it (the construction's hot path).
    #[inline(always)]
    pub(super) fn follow(&mut self, id: ObjId, how: Derived<'_>) {
        if self.recording && id != ObjId::NONE {
            self.follow_recorded(id, &how);
        }
    }

    #[inline(never)]
    fn follow_recorded(&mut self, id: ObjId, how: &Derived<'_>) {
        let t = self.bound_of(how);
        let own = match *how {
            Derived::Cut { cond, .. } => Some((StepId(self.next_step), cond)),
            _ => None,
        };
        self.tracks.set(id.0 as usize - 1, t, own);
        if self.shadows.is_some() {
            if let Some(v) = self.reference_of(how) {
                if let Some(s) = self.shadows.as_mut() {
                    s[id.0 as usize - 1] = v;
                }
            }
        }
    }

    /// The propagated error bound of what a step made, from its inputs' bounds.
    fn bound_of(&self, how: &Derived<'_>) -> Track {
        let m = &self.model;
        match *how {
            Derived::Given(p) => m.given(&p),
            Derived::Ray { at, dir } => m.line_at(&self.tr(at.id), &dir),
            Derived::Ruled(a, b) => m.ruled(&self.tr(a.id), &self.tr(b.id), (b.g - a.g).norm()),
            Derived::Slid {
                line,
                through,
                turned,
            } => {
                let dir = if turned { line.g.normal() } else { line.g.dir };
                m.slid(&self.tr(line.id), &self.tr(through.id), &dir)
            }
            Derived::Compass { center, circle } => {
                m.compass(&self.tr(center.id), &circle.center, circle.radius)
            }
            Derived::OnCircle { circle, at, .. } => {
                m.on_circle(&self.tr(circle.id), &at, circle.g.radius)
            }
            Derived::Laid {
                from,
                along,
                length,
                carried,
                at,
            } => {
                let mut c = carried.map_or(Track::default(), |(v, _)| self.tr(v.id));
                c.err /= carried.map_or(1.0, |(_, per_mm)| per_mm.abs());
                m.laid(&self.tr(from.id), &self.tr(along.id), length, &at, &c)
            }
            Derived::Foot { line, from, at } => m.foot(
                &self.tr(line.id),
                &line.g,
                (&self.tr(from.id), &from.g),
                &at,
            ),
            Derived::Between { a, b, t, at } => m.between(&self.tr(a.id), &self.tr(b.id), t, &at),
            Derived::Cut {
                of: Cutting::Lines(a, b),
                at,
                cond,
            } => self.lines_bound(a, b, &at, cond),
            Derived::Cut {
                of: Cutting::LineCircle(line, circle),
                at,
                cond,
            } => self.line_circle_bound(line, circle, &at, cond),
            Derived::Cut {
                of: Cutting::Circles(a, b),
                at,
                cond,
            } => self.circles_bound(a, b, &at, cond),
            Derived::Measured {
                from,
                to,
                axis,
                mm,
                scale,
            } => {
                let ends = (&self.tr(from.id), &self.tr(to.id));
                m.measured(ends, &self.tr(axis.id), mm, scale.per_mm, (&from.g, &to.g))
            }
            Derived::Angle {
                vertex,
                from,
                to,
                value,
            } => {
                let (u, v) = (from.g - vertex.g, to.g - vertex.g);
                let (tv, tf, tt) = (self.tr(vertex.id), self.tr(from.id), self.tr(to.id));
                m.angle(&tv, &tf, &tt, (u.norm(), v.norm()), value)
            }
            Derived::Reckoned { inputs, value } => self.reckoned_bound(inputs, value),
        }
    }

    /// The bound of the point `p` where lines `a` and `b` met at `cond`.
    fn lines_bound(&self, a: &H<Line>, b: &H<Line>, p: &Point, cond: Conditioning) -> Track {
        let (ta, tb) = (self.tr(a.id), self.tr(b.id));
        let across = ((ta.across(&a.g, p), a.g.dir), (tb.across(&b.g, p), b.g.dir));
        let extent = p.coords.norm() + a.g.origin.coords.norm() + b.g.origin.coords.norm();
        let worst = ta.worst.or_worse(tb.worst);
        self.model
            .cut_lines(Worst::own(cond), across, extent, worst)
    }

    /// The bound of the point `p` where `line` cut `circle` at `cond`.
    fn line_circle_bound(
        &self,
        line: &H<Line>,
        circle: &H<Circle>,
        p: &Point,
        cond: Conditioning,
    ) -> Track {
        let (tl, tc) = (self.tr(line.id), self.tr(circle.id));
        let delta = tl.across(&line.g, p) + tc.err + self.snapped(cond);
        let (c, r) = (circle.g.center, circle.g.radius);
        let extent = p.coords.norm() + r + c.coords.norm() + line.g.origin.coords.norm();
        let worst = tl.worst.or_worse(tc.worst);
        self.model.cut(Worst::own(cond), (delta, extent, r), worst)
    }

    /// The bound of the point `p` where circles `a` and `b` cut at `cond`.
    fn circles_bound(&self, a: &H<Circle>, b: &H<Circle>, p: &Point, cond: Conditioning) -> Track {
        let (ta, tb) = (self.tr(a.id), self.tr(b.id));
        let (ga, gb) = (&a.g, &b.g);
        let extent = p.coords.norm()
            + ga.radius
            + gb.radius
            + ga.center.coords.norm()
            + gb.center.coords.norm();
        let worst = ta.worst.or_worse(tb.worst);
        let delta = ta.err + tb.err + self.snapped(cond);
        let geom = (delta, extent, ga.radius.max(gb.radius));
        self.model.cut(Worst::own(cond), geom, worst)
    }

    /// How far a curve of a touching cut may have stood from touching: the kernel takes
    /// curves within its length tolerance of each other as touching and puts the point
    /// where they would touch, so the point may lie √(2r·tolerance) from where the curves
    /// as drawn meet (the crank-rocker near μ = 0 stood 18 times outside a bound without it).
    fn snapped(&self, cond: Conditioning) -> f64 {
        if cond.amplification().is_finite() {
            0.0
        } else {
            self.tolerance.length
        }
    }

    /// The bound of a number reckoned from weighted inputs.
    fn reckoned_bound(&self, weighted: Weighted<'_>, value: f64) -> Track {
        let Weighted { inputs, weight } = weighted;
        let t: Vec<(Track, f64)> = inputs
            .iter()
            .map(|i| {
                let mut t = self.tr(*i);
                t.err *= weight.abs();
                (t, self.number(*i).map_or(0.0, |v| v * weight))
            })
            .collect();
        self.model.reckoned(t.iter(), value)
    }

    /// The double-double reference of what a step made, replayed from its inputs'
    /// references; `None` for what has none (a reckoned number).
    fn reference_of(&self, how: &Derived<'_>) -> Option<Shadow> {
        Some(match *how {
            Derived::Given(p) => Shadow::Point(DP::of(&p)),
            Derived::Ray { at, dir } => Shadow::Line {
                o: self.sp(at),
                d: DP::of_vec(&dir).unit(),
            },
            Derived::Ruled(a, b) => {
                let (pa, pb) = (self.sp(a), self.sp(b));
                Shadow::Line {
                    o: pa,
                    d: pb.sub(&pa).unit(),
                }
            }
            Derived::Slid {
                line,
                through,
                turned,
            } => {
                let d = self.sl(line).1;
                Shadow::Line {
                    o: self.sp(through),
                    d: if turned { d.normal() } else { d },
                }
            }
            Derived::Compass { center, circle } => Shadow::Circle {
                c: self.sp(center),
                r: circle.radius.into(),
            },
            Derived::OnCircle { circle, dir, .. } => {
                let (cc, r) = self.sc(circle);
                Shadow::Point(DP {
                    x: cc.x + r * dir.cos,
                    y: cc.y + r * dir.sin,
                })
            }
            Derived::Laid {
                from,
                along,
                length,
                carried,
                ..
            } => {
                let len = carried.map_or(length.into(), |(v, per_mm)| self.sv(v) / per_mm);
                Shadow::Point(self.sp(from).add(&self.sl(along).1.scale(len)))
            }
            Derived::Foot { line, from, .. } => {
                let ((o, d), q) = (self.sl(line), self.sp(from));
                Shadow::Point(o.add(&d.scale(q.sub(&o).dot(&d))))
            }
            Derived::Between { a, b, t, .. } => {
                Shadow::Point(DP::between(&self.sp(a), &self.sp(b), t))
            }
            Derived::Cut { of, at, .. } => Shadow::Point(self.cut_reference(of, &at)),
            Derived::Measured {
                from,
                to,
                axis,
                scale,
                ..
            } => {
                let mm = self.sp(to).sub(&self.sp(from)).dot(&self.sl(axis).1);
                Shadow::Scalar(mm * scale.per_mm)
            }
            Derived::Angle {
                vertex, from, to, ..
            } => Shadow::Scalar(refr::angle_deg(
                &self.sp(vertex),
                &self.sp(from),
                &self.sp(to),
            )),
            Derived::Reckoned { .. } => return None,
        })
    }

    /// The double-double reference of the point where two curves cut, near the f64 point.
    fn cut_reference(&self, of: Cutting<'_>, near: &Point) -> DP {
        match of {
            Cutting::Lines(a, b) => {
                let ((ao, ad), (bo, bdir)) = (self.sl(a), self.sl(b));
                refr::meet(&ao, &ad, &bo, &bdir)
            }
            Cutting::LineCircle(line, circle) => {
                let ((o, d), (c, r)) = (self.sl(line), self.sc(circle));
                refr::line_circle(&o, &d, &c, r, near)
            }
            Cutting::Circles(a, b) => {
                let ((c1, r1), (c2, r2)) = (self.sc(a), self.sc(b));
                refr::circle_circle(&c1, r1, &c2, r2, near)
            }
        }
    }

    /// The propagated error bound of an object (mm for a point, its unit for a number) and
    /// the worst cut it depends on; `None` on a board that does not record.
    pub fn bound(&self, id: ObjId) -> Option<(f64, Option<WorstCut>)> {
        let t = self.tracks.get((id.0 as usize).wrapping_sub(1))?;
        Some((t.err, self.tracks.worst_cut(t.worst)))
    }

    #[inline]
    pub(super) fn tr(&self, id: ObjId) -> Track {
        self.tracks
            .get((id.0 as usize).wrapping_sub(1))
            .unwrap_or_default()
    }

    pub(super) fn shadow(&self, id: ObjId) -> Shadow {
        self.shadows
            .as_ref()
            .and_then(|s| s.get((id.0 as usize).wrapping_sub(1)).copied())
            .unwrap_or_default()
    }

    // The reference of a handle is its object's, unless a procedure made the handle with an
    // object's id but geometry of its own (a line's normal, a value's magnitude): then the
    // handle's f64 geometry is taken as given.

    fn sp(&self, h: &H<Point>) -> DP {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Point(p), Some(Geom::Point { at })) if *at == h.g => p,
            _ => DP::of(&h.g),
        }
    }

    fn sl(&self, h: &H<Line>) -> (DP, DP) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Line { o, d }, Some(Geom::Line { line, .. })) if *line == h.g => (o, d),
            _ => (DP::of(&h.g.origin), DP::of_vec(&h.g.dir)),
        }
    }

    fn sc(&self, h: &H<Circle>) -> (DP, twofloat::TwoFloat) {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Circle { c, r }, Some(Geom::Circle { circle, .. })) if *circle == h.g => {
                (c, r)
            }
            _ => (DP::of(&h.g.center), h.g.radius.into()),
        }
    }

    fn sv(&self, h: &H<f64>) -> twofloat::TwoFloat {
        match (self.shadow(h.id), self.object(h.id).map(|o| &o.geom)) {
            (Shadow::Scalar(v), Some(Geom::Scalar { value, .. })) if *value == h.g => v,
            _ => h.g.into(),
        }
    }
}
