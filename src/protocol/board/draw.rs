//! The drawing steps: points, lines, circles, lengths laid off, curves, tables.

use super::follow::Derived;
use super::*;

impl Board {
    pub(super) fn prim<T>(
        &self,
        r: Result<T, PrimitiveError>,
        note: &Note,
    ) -> Result<T, ConstructionError> {
        r.map_err(|source| ConstructionError::Primitive {
            step: self.step_id_next(),
            caption: note.caption.clone(),
            source,
        })
    }

    /// A length or ratio that must be a finite number for the step `note` would take.
    pub(super) fn finite(&self, x: f64, note: &Note) -> Result<(), ConstructionError> {
        if x.is_finite() {
            Ok(())
        } else {
            Err(ConstructionError::Primitive {
                step: self.step_id_next(),
                caption: note.caption.clone(),
                source: PrimitiveError::NotFinite,
            })
        }
    }

    /// A given point.
    pub fn point(&mut self, p: Point, mark: impl Into<Mark>, note: Note) -> H<Point> {
        let p = self.mark(p);
        self.grow(&p);
        self.begin(StepKind::Given, &note, &[]);
        self.made(mark.into(), p, || Geom::Point { at: p }, Derived::Given(p))
    }

    /// The line through a point in a given direction (a given axis, or a ray laid off with
    /// the protractor).
    pub fn line_dir(
        &mut self,
        p: &H<Point>,
        dir: Vector,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Line>, ConstructionError> {
        let line = self.prim(Line::new(p.g, dir), &note)?;
        let line = self.rule(line);
        let kind = if p.id == ObjId::NONE || note.topic == Topic::Setup {
            StepKind::Given
        } else {
            StepKind::Line
        };
        self.begin(kind, &note, &[p.id]);
        let geom = || Geom::Line {
            line,
            extent: [0.0, 0.0],
        };
        Ok(self.made(mark.into(), line, geom, Derived::Ray { at: p, dir }))
    }

    /// The line through two points (the ruler).
    pub fn line_through(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Line>, ConstructionError> {
        let line = self.prim(Line::through(a.g, b.g, self.tolerance.length), &note)?;
        let line = self.rule(line);
        self.begin(StepKind::Line, &note, &[a.id, b.id]);
        let tb = line.param_of(&b.g);
        let geom = || Geom::Line {
            line,
            extent: [tb.min(0.0), tb.max(0.0)],
        };
        Ok(self.made(mark.into(), line, geom, Derived::Ruled(a, b)))
    }

    /// The parallel to `line` through `p`.
    pub fn parallel(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Line> {
        let g = construct::parallel_through(&line.g, p.g);
        self.slide(StepKind::Parallel, line, p, g, mark.into(), note)
    }

    /// The perpendicular to `line` through `p`.
    pub fn perpendicular(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Line> {
        let g = construct::perpendicular_through(&line.g, p.g);
        self.slide(StepKind::Perpendicular, line, p, g, mark.into(), note)
    }

    /// The set square slid along `line` to `p`, ruling `g` (the parallel, or the
    /// perpendicular: [`StepKind::Perpendicular`]).
    pub(super) fn slide(
        &mut self,
        kind: StepKind,
        line: &H<Line>,
        p: &H<Point>,
        g: Line,
        mark: Mark,
        note: Note,
    ) -> H<Line> {
        let g = self.rule(g);
        self.begin(kind, &note, &[line.id, p.id]);
        let geom = || Geom::Line {
            line: g,
            extent: [0.0, 0.0],
        };
        let turned = kind == StepKind::Perpendicular;
        let how = Derived::Slid {
            line,
            through: p,
            turned,
        };
        self.made(mark, g, geom, how)
    }

    /// The circle about `center` with `radius` mm (the compass), drawn whole or only in the
    /// short arcs where points are constructed on it ([`Drawn`]).
    pub fn circle(
        &mut self,
        center: &H<Point>,
        radius: f64,
        drawn: Drawn,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Circle>, ConstructionError> {
        let radius = self.read(radius);
        let c = self.prim(Circle::new(center.g, radius), &note)?;
        self.grow(&(c.center + Vector::new(c.radius, c.radius)));
        self.grow(&(c.center - Vector::new(c.radius, c.radius)));
        let kind = if note.topic == Topic::Setup {
            StepKind::Given
        } else {
            StepKind::Circle
        };
        self.begin(kind, &note, &[center.id]);
        let geom = || Geom::Circle {
            circle: c,
            full: drawn == Drawn::Whole,
            marks: Vec::new(),
        };
        let how = Derived::Compass { center, circle: c };
        Ok(self.made(mark.into(), c, geom, how))
    }

    /// The point of a circle at the angle `deg` (laid off with the protractor), with the ray
    /// from the centre drawn as a segment of the given role.
    pub fn point_on_circle(
        &mut self,
        circle: &H<Circle>,
        deg: f64,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let dir = SinCos::of_deg(deg);
        self.point_on_circle_dir(circle, dir, mark, note)
    }

    /// The point of a circle in the direction given by its sine and cosine ([`SinCos`]), for an
    /// angle better known by those than by its degrees (180° − θ for a tiny θ: forming
    /// 180 − θ would round θ away), with the ray from the centre drawn.
    pub fn point_on_circle_dir(
        &mut self,
        circle: &H<Circle>,
        dir: SinCos,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let Mark { label, role } = mark.into();
        let SinCos { sin: s, cos: c } = dir;
        let g = &circle.g;
        let p = Point::new(g.center.x + g.radius * c, g.center.y + g.radius * s);
        let p = self.mark(p);
        self.begin(StepKind::Divide, &note, &[circle.id]);
        let at = p;
        let h = self.made_point(label, p, Derived::OnCircle { circle, at, dir });
        let c = circle.g.center;
        self.add_drawing(Label::NONE, role, || Geom::Segment {
            segment: Segment { a: c, b: p },
        });
        self.touch(circle.id, &p);
        h
    }

    /// Divides a circle into `n` equal parts from `start_deg` (one step, `n` points), the
    /// points named `label` with their index from 0 and lettered as a crowd is
    /// ([`Label::of_crowd`]: each of twelve, every second of 24 …); where `start_named`, the
    /// first point (at `start_deg`: a point named already, such as a crank's dead centre A)
    /// is left unlettered, so that it is named once.
    #[allow(clippy::too_many_arguments)]
    pub fn divide_circle(
        &mut self,
        circle: &H<Circle>,
        start_deg: f64,
        n: usize,
        turning: Turning,
        (label, start_named): (&'static str, bool),
        note: Note,
    ) -> Vec<H<Point>> {
        let clockwise = turning == Turning::Clockwise;
        let mut pts = construct::divide_circle(&circle.g, start_deg, n, clockwise);
        pts.iter_mut().for_each(|p| *p = self.mark(*p));
        self.begin(StepKind::Divide, &note, &[circle.id]);
        let mut out = Vec::with_capacity(pts.len());
        let sign = if clockwise { -1.0 } else { 1.0 };
        for (k, p) in pts.into_iter().enumerate() {
            let name = if k == 0 && start_named {
                Label::NONE
            } else {
                Label::of_crowd(label, k as u32, n)
            };
            let id = self.add(name, Role::Given, || Geom::Point { at: p });
            if self.recording {
                let deg = start_deg + sign * 360.0 * k as f64 / n.max(1) as f64;
                let dir = SinCos::of_deg(deg);
                self.follow(id, Derived::OnCircle { circle, at: p, dir });
            }
            self.touch(circle.id, &p);
            out.push(H { id, g: p });
        }
        out
    }

    /// The sign of a fixed pivot under `pivot` (the frame, Gestell): a small triangle on a
    /// hatched ground line, drawn at its size on the sheet whatever the scale.
    pub fn ground(&mut self, pivot: &H<Point>, note: Note) {
        if !self.recording {
            return;
        }
        const HALF: f64 = 3.0;
        const DEPTH: f64 = 4.0;
        let p = pivot.g;
        let (l, r) = (
            Point::new(p.x - HALF, p.y - DEPTH),
            Point::new(p.x + HALF, p.y - DEPTH),
        );
        self.begin(StepKind::Given, &note, &[pivot.id]);
        for (a, b, role) in [(p, l, Role::Given), (p, r, Role::Given)] {
            self.add_drawing(Label::NONE, role, || Geom::Segment {
                segment: Segment { a, b },
            });
        }
        let (a, b) = (l - Vector::new(1.5, 0.0), r + Vector::new(1.5, 0.0));
        // Hatched on the right of a → b: below the line, as the ground is.
        self.add_drawing(Label::NONE, Role::Guide, || Geom::Segment {
            segment: Segment { a, b },
        });
    }

    /// A segment drawn between two points (a crank, a rod).
    pub fn segment(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Segment> {
        let Mark { label, role } = mark.into();
        let s = Segment { a: a.g, b: b.g };
        self.begin(StepKind::LayOff, &note, &[a.id, b.id]);
        let id = self.add_drawing(label, role, || drawn_as(role, s));
        H { id, g: s }
    }

    /// Lays off `length` mm from `from` along the direction of `along` (negative: backwards),
    /// drawing the laid-off length as a vector of the given role (force, velocity) or a segment.
    pub fn lay_off(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        length: f64,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        // The line's direction is a unit vector already: no normalisation needed.
        self.lay_off_carried(from, along, (length, None), mark.into(), note)
    }

    /// Lays off a value read earlier (a force, a velocity measured elsewhere) at `per_mm`
    /// units per mm from `from` along `along`: the dividers' transfer, whose error and
    /// reference follow the value it carries.
    pub fn transfer(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        reading: Reading<'_>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let Reading { value, per_mm } = reading;
        let length = value.g / per_mm;
        self.lay_off_carried(
            from,
            along,
            (length, Some((value, per_mm))),
            mark.into(),
            note,
        )
    }

    pub(super) fn lay_off_carried(
        &mut self,
        from: &H<Point>,
        along: &H<Line>,
        (length, carried): (f64, Option<(&H<f64>, f64)>),
        mark: Mark,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        self.finite(length, &note)?;
        let length = self.read(length);
        let p = from.g + along.g.dir * length;
        self.finite(p.x, &note)?;
        self.finite(p.y, &note)?;
        self.grow(&p);
        match carried {
            Some((v, _)) => self.begin(StepKind::LayOff, &note, &[from.id, along.id, v.id]),
            None => self.begin(StepKind::LayOff, &note, &[from.id, along.id]),
        }
        let how = Derived::Laid {
            from,
            along,
            length,
            carried,
            at: p,
        };
        let h = self.made_point(mark.label, p, how);
        let segment = Segment { a: from.g, b: p };
        self.add_drawing(Label::NONE, mark.role, || drawn_as(mark.role, segment));
        self.touch(along.id, &p);
        Ok(h)
    }

    /// The foot of the perpendicular from `p` on `line`, with the perpendicular drawn.
    pub fn foot(
        &mut self,
        line: &H<Line>,
        p: &H<Point>,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<Point> {
        let Mark { label, role } = mark.into();
        let f = construct::foot_on_line(&line.g, &p.g);
        let f = self.mark(f);
        self.begin(StepKind::Foot, &note, &[line.id, p.id]);
        let how = Derived::Foot {
            line,
            from: p,
            at: f,
        };
        let h = self.made_point(label, f, how);
        let a = p.g;
        self.add_drawing(Label::NONE, role, || Geom::Segment {
            segment: Segment { a, b: f },
        });
        self.touch(line.id, &f);
        h
    }

    /// Writes a table on the sheet with its top-left corner at `at` (the evaluation of a
    /// plan, LH B.4 "Auswertung"); `inputs` are the objects its numbers were read from.
    pub fn table(&mut self, at: Point, rows: Vec<Vec<String>>, inputs: &[ObjId], note: Note) {
        if !self.recording {
            return;
        }
        self.begin(StepKind::Measure, &note, inputs);
        self.add_drawing(Label::NONE, Role::Result, || Geom::Table { at, rows });
    }

    /// Hatches the area inside the polygon through `outline` (its last point joined to its
    /// first) with thin lines `spacing` mm apart, rising at 45° ([`construct::hatch`]): one
    /// step, an area the figure names (LH J's excess areas of the turning force over its
    /// mean). Nothing is constructed on the hatching, so a board that does not record skips
    /// it.
    pub fn hatch(&mut self, outline: &[H<Point>], spacing: f64, note: Note) {
        if !self.recording {
            return;
        }
        let ids: Vec<ObjId> = outline.iter().map(|p| p.id).collect();
        self.begin(StepKind::Curve, &note, &ids);
        let pts: Vec<Point> = outline.iter().map(|p| p.g).collect();
        for segment in construct::hatch(&pts, Vector::new(1.0, 1.0), spacing) {
            self.add_drawing(Label::NONE, Role::Construction, || Geom::Segment {
                segment,
            });
        }
    }

    /// Marks an angle at `vertex` with an arc of `radius` mm that starts in the direction
    /// `start_deg` (degrees from +x) and sweeps `sweep_deg` (counter-clockwise where
    /// positive), lettered by the mark's label beside its middle: the angle a plate names (a
    /// transmission angle μ, a crank's angle 2α). The angle itself is read with
    /// [`Board::measure_angle`]; the arc is drawn only, nothing is constructed on it, so a
    /// board that does not record skips it, and so does an arc too small to be seen.
    pub fn angle_arc(
        &mut self,
        vertex: &H<Point>,
        radius: f64,
        (start_deg, sweep_deg): (f64, f64),
        mark: impl Into<Mark>,
        note: Note,
    ) {
        if !self.recording {
            return;
        }
        let Ok(circle) = Circle::new(vertex.g, radius) else {
            return;
        };
        if !(start_deg.is_finite() && sweep_deg.is_finite()) || sweep_deg.abs() < 1e-6 {
            return;
        }
        let Mark { label, role } = mark.into();
        self.begin(StepKind::Curve, &note, &[vertex.id]);
        let arc = crate::kernel::Arc {
            circle,
            start_deg,
            sweep_deg,
        };
        self.add_drawing(label, role, || Geom::Arc { arc });
    }

    /// Draws a curve through points, smooth or as their polygon ([`Trace`]).
    pub fn curve(
        &mut self,
        points: &[H<Point>],
        trace: Trace,
        mark: impl Into<Mark>,
        note: Note,
    ) -> H<ObjId> {
        let Mark { label, role } = mark.into();
        if !self.recording {
            return H {
                id: ObjId::NONE,
                g: ObjId::NONE,
            };
        }
        let ids: Vec<ObjId> = points.iter().map(|p| p.id).collect();
        self.begin(StepKind::Curve, &note, &ids);
        let pts: Vec<Point> = points.iter().map(|p| p.g).collect();
        let id = self.add_drawing(label, role, || Geom::Curve {
            points: pts,
            smooth: trace == Trace::Smooth,
        });
        H { id, g: id }
    }

    /// Draws a curve the scene gives point by point (an indicator card as the indicator drew
    /// it, LH Abb. 42): given, not constructed, so its points are no objects of the
    /// construction and nothing is read off them but what a later step lays off itself.
    /// Drawn only on a recording board; the figure grows to hold it.
    pub fn given_curve(
        &mut self,
        points: &[Point],
        trace: Trace,
        mark: impl Into<Mark>,
        note: Note,
    ) {
        if !self.recording {
            return;
        }
        let Mark { label, role } = mark.into();
        let pts: Vec<Point> = points.iter().map(|&p| self.mark(p)).collect();
        pts.iter().for_each(|p| self.grow(p));
        self.begin(StepKind::Given, &note, &[]);
        self.add_drawing(label, role, || Geom::Curve {
            points: pts,
            smooth: trace == Trace::Smooth,
        });
    }

    /// Divides the segment from `a` to `b` into `n ≥ 1` equal parts: the `n + 1` division
    /// points, ends included (the ends are the given points themselves).
    pub fn divide_segment(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        n: usize,
        label: &'static str,
        note: Note,
    ) -> Vec<H<Point>> {
        let mut pts = construct::divide_segment(&Segment { a: a.g, b: b.g }, n);
        let last = pts.len() - 1;
        pts[1..last].iter_mut().for_each(|p| *p = self.mark(*p));
        self.begin(StepKind::Divide, &note, &[a.id, b.id]);
        let last = pts.len() - 1;
        let n = n.max(1);
        let mut out = Vec::with_capacity(pts.len());
        for (k, p) in pts.into_iter().enumerate() {
            if k == 0 {
                out.push(*a);
            } else if k == last {
                out.push(*b);
            } else {
                let t = k as f64 / n as f64;
                let how = Derived::Between { a, b, t, at: p };
                out.push(self.made_point(Label::quiet(label, k as u32), p, how));
            }
        }
        out
    }

    /// The point dividing the segment from `a` to `b` in the ratio `t : (1 − t)`, drawn as a
    /// mark on the segment (a tangent of Tolle's parabola divided at the crank angle's
    /// parameter, LH Abb. 55).
    pub fn divide_at(
        &mut self,
        a: &H<Point>,
        b: &H<Point>,
        t: f64,
        label: impl Into<Label>,
        note: Note,
    ) -> Result<H<Point>, ConstructionError> {
        let label = label.into();
        self.finite(t, &note)?;
        let p = construct::point_at_ratio(&Segment { a: a.g, b: b.g }, t);
        let p = self.mark(p);
        self.grow(&p);
        self.begin(StepKind::Divide, &note, &[a.id, b.id]);
        Ok(self.made_point(label, p, Derived::Between { a, b, t, at: p }))
    }
}

/// A segment drawn as its role draws it: a force or a velocity as an arrow.
fn drawn_as(role: Role, segment: Segment) -> Geom {
    match role {
        Role::Force | Role::Velocity => Geom::Vector { segment },
        _ => Geom::Segment { segment },
    }
}
