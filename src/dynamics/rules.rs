//! The books' ways to find the mean height of a diagram (LH G, Gl. 52-59): the trapezoid
//! rule, Simpson's rule, the 3/8 rule, counting millimetre squares, and the polar planimeter
//! (simulated: its wheel rolled along the traced outline).

/// Mean height by the trapezoid rule over `n` equal strips, `n + 1` ordinates (LH Gl. 55).
///
/// ```
/// use graphostatik::dynamics::rules::trapezoid;
/// assert_eq!(trapezoid(&[0.0, 1.0, 2.0]), 1.0);
/// ```
pub fn trapezoid(a: &[f64]) -> f64 {
    let n = a.len().saturating_sub(1);
    if n == 0 {
        return a.first().copied().unwrap_or(0.0);
    }
    let inner: f64 = a[1..n].iter().sum();
    (0.5 * (a[0] + a[n]) + inner) / n as f64
}

/// Mean height by the trapezoid rule over strips of any width: the points (x, y) in order
/// along the axis (the turning-force diagram over rays found by rod-length arcs, whose
/// abscissae are unequal, LH F).
///
/// ```
/// use graphostatik::dynamics::rules::trapezoid_xy;
/// assert_eq!(trapezoid_xy(&[(0.0, 0.0), (1.0, 2.0), (4.0, 2.0)]), 1.75);
/// ```
pub fn trapezoid_xy(p: &[(f64, f64)]) -> f64 {
    let (Some(first), Some(last)) = (p.first(), p.last()) else {
        return 0.0;
    };
    let width = last.0 - first.0;
    if width == 0.0 {
        return first.1;
    }
    p.windows(2)
        .map(|w| 0.5 * (w[1].0 - w[0].0) * (w[0].1 + w[1].1))
        .sum::<f64>()
        / width
}

/// Mean height by the trapezoid rule over a whole revolution: the ordinates (θ in degrees, y)
/// from 0° on, closed at 360° by the first, the curve being periodic.
///
/// ```
/// use graphostatik::dynamics::rules::trapezoid_revolution;
/// assert_eq!(trapezoid_revolution(&[(0.0, 2.0), (180.0, 0.0)]), 1.0);
/// ```
pub fn trapezoid_revolution(p: &[(f64, f64)]) -> f64 {
    let closed: Vec<(f64, f64)> = (p.iter().copied())
        .chain(p.first().map(|q| (360.0, q.1)))
        .collect();
    trapezoid_xy(&closed)
}

/// Mean height by Simpson's rule (LH Gl. 56-58); `None` unless the number of strips is even.
pub fn simpson(a: &[f64]) -> Option<f64> {
    // Weights 1, 4, 2, 4, …, 4, 1 over 3n.
    composite(a, 2, |k| if k % 2 == 1 { 4.0 } else { 2.0 }, 1.0 / 3.0)
}

/// Mean height by the 3/8 rule; `None` unless the number of strips n is a multiple of 3.
/// The weights are 1, 3, 3, 2, 3, 3, 2, …, 3, 3, 1 times 3/(8n) (LH Gl. 59 prints the factor
/// 3/80, which is 3/(8n) for n = 10 strips, a number of strips the rule does not allow).
pub fn three_eighths(a: &[f64]) -> Option<f64> {
    composite(a, 3, |k| if k % 3 == 0 { 2.0 } else { 3.0 }, 3.0 / 8.0)
}

/// A closed Newton-Cotes rule repeated over groups of `group` strips: the ends weigh 1, an
/// inner ordinate `inner(k)`, the sum times `factor`/n is the mean height; `None` unless the
/// number of strips is a positive multiple of `group`.
fn composite(a: &[f64], group: usize, inner: impl Fn(usize) -> f64, factor: f64) -> Option<f64> {
    let n = a.len().checked_sub(1)?;
    if n == 0 || n % group != 0 {
        return None;
    }
    let s: f64 = a
        .iter()
        .enumerate()
        .map(|(k, y)| if k == 0 || k == n { *y } else { inner(k) * y })
        .sum();
    Some(factor * s / n as f64)
}

/// The area between a drawn curve and its axis counted in squares of side `cell` (mm), as on
/// millimetre paper (LH G.c): a square counts when its centre lies between curve and axis,
/// with the curve's sign. `curve` is the polyline (x rising, sheet mm, ordinates from the
/// axis). Returns the counted area (mm²).
pub fn count_squares(curve: &[(f64, f64)], cell: f64) -> f64 {
    if curve.len() < 2 || cell.is_nan() || cell <= 0.0 {
        return 0.0;
    }
    let (x0, x1) = (curve[0].0, curve[curve.len() - 1].0);
    let mut total = 0.0;
    let mut i = 0usize;
    let mut x = x0 + 0.5 * cell;
    while x < x1 {
        while i + 2 < curve.len() && curve[i + 1].0 < x {
            i += 1;
        }
        let ((xa, ya), (xb, yb)) = (curve[i], curve[i + 1]);
        let y = if xb > xa {
            ya + (yb - ya) * (x - xa) / (xb - xa)
        } else {
            yb
        };
        // Squares whose centre lies between 0 and y, counted with the sign of y.
        let count = ((y.abs() / cell) + 0.5).floor();
        total += y.signum() * count * cell * cell;
        x += cell;
    }
    total
}

/// How far [`count_squares`] can fall from the polyline's own area (mm²): per column, half a
/// square for the rounding of the count, and the column's width times the range of the curve
/// over it (a square is counted at the column's centre; the curve may rise and fall inside
/// it); the last column's overhang past the curve's end counts its whole height. A jagged
/// curve (64 cylinders at 360 divisions: some two vertices a millimetre) is no longer held
/// to one square a column, which its count exceeded.
pub fn count_squares_bound(curve: &[(f64, f64)], cell: f64) -> f64 {
    if curve.len() < 2 || cell.is_nan() || cell <= 0.0 {
        return 0.0;
    }
    let (x0, x1) = (curve[0].0, curve[curve.len() - 1].0);
    let y_at = |i: usize, x: f64| {
        let ((xa, ya), (xb, yb)) = (curve[i], curve[i + 1]);
        if xb > xa {
            ya + (yb - ya) * (x - xa) / (xb - xa)
        } else {
            yb
        }
    };
    let (mut total, mut i) = (0.0, 0usize);
    let mut left = x0;
    while left + 0.5 * cell < x1 {
        let right = (left + cell).min(x1);
        while i + 2 < curve.len() && curve[i + 1].0 < left {
            i += 1;
        }
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut j = i;
        let mut see = |y: f64| {
            lo = lo.min(y);
            hi = hi.max(y);
        };
        see(y_at(i, left));
        while j + 2 < curve.len() && curve[j + 1].0 < right {
            see(curve[j + 1].1);
            j += 1;
        }
        see(y_at(j, right));
        total += 0.5 * cell * cell + cell * (hi - lo);
        if left + cell > x1 {
            total += (left + cell - x1) * lo.abs().max(hi.abs());
        }
        left += cell;
    }
    total
}

/// A polar planimeter (LH G.d, Abb. 71): pole arm `pole_arm` from the pole to the elbow,
/// tracer arm `tracer_arm` from the elbow to the tracing point, the wheel on the tracer arm at
/// `wheel` from the elbow, rolling only across the arm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Planimeter {
    /// Where the pole needle stands (sheet mm), outside the figure.
    pub pole: (f64, f64),
    /// Pole arm (mm).
    pub pole_arm: f64,
    /// Tracer arm (mm).
    pub tracer_arm: f64,
    /// Distance of the wheel from the elbow along the tracer arm (mm).
    pub wheel: f64,
}

impl Planimeter {
    /// The elbow for the tracer at `t`: the cut of the two arm circles on the side of `prev`.
    fn elbow(&self, t: (f64, f64), prev: (f64, f64)) -> Option<(f64, f64)> {
        let (dx, dy) = (t.0 - self.pole.0, t.1 - self.pole.1);
        let d = dx.hypot(dy);
        let (a, b) = (self.pole_arm, self.tracer_arm);
        if d > a + b || d < (a - b).abs() || d == 0.0 {
            return None;
        }
        let along = (a * a - b * b + d * d) / (2.0 * d);
        let h = (a * a - along * along).max(0.0).sqrt();
        let (ux, uy) = (dx / d, dy / d);
        let base = (self.pole.0 + along * ux, self.pole.1 + along * uy);
        let p1 = (base.0 - h * uy, base.1 + h * ux);
        let p2 = (base.0 + h * uy, base.1 - h * ux);
        let dist = |p: (f64, f64)| (p.0 - prev.0).hypot(p.1 - prev.1);
        Some(if dist(p1) <= dist(p2) { p1 } else { p2 })
    }

    /// Traces the closed outline (sheet mm) in steps of at most `step` mm and returns the
    /// area the instrument reads: tracer arm × the wheel's rolling (signed, positive for a
    /// counter-clockwise trace). `None` if the outline leaves the instrument's reach.
    pub fn trace(&self, outline: &[(f64, f64)], step: f64) -> Option<f64> {
        let start = *outline.first()?;
        // The elbow starts on the side of the pole arm's first position to the left.
        let guess = (self.pole.0, self.pole.1 + self.pole_arm);
        let mut e = self.elbow(start, guess)?;
        let mut t = start;
        let mut roll = 0.0;
        let mut wheel = self.wheel_at(e, t);
        for k in 1..=outline.len() {
            let next = outline[k % outline.len()];
            let len = (next.0 - t.0).hypot(next.1 - t.1);
            let n = (len / step).ceil().max(1.0) as usize;
            let from = t;
            for j in 1..=n {
                let s = j as f64 / n as f64;
                let tj = (
                    from.0 + (next.0 - from.0) * s,
                    from.1 + (next.1 - from.1) * s,
                );
                let ej = self.elbow(tj, e)?;
                let wj = self.wheel_at(ej, tj);
                // The wheel rolls by its motion across the arm, taken at the arm's middle
                // position of the step.
                let (ax, ay) = (tj.0 - ej.0 + t.0 - e.0, tj.1 - ej.1 + t.1 - e.1);
                let al = ax.hypot(ay);
                let normal = (-ay / al, ax / al);
                roll += (wj.0 - wheel.0) * normal.0 + (wj.1 - wheel.1) * normal.1;
                e = ej;
                t = tj;
                wheel = wj;
            }
        }
        Some(self.tracer_arm * roll)
    }

    fn wheel_at(&self, e: (f64, f64), t: (f64, f64)) -> (f64, f64) {
        let f = self.wheel / self.tracer_arm;
        (e.0 + (t.0 - e.0) * f, e.1 + (t.1 - e.1) * f)
    }
}

/// The signed area of a closed polygon (shoelace), positive counter-clockwise.
pub fn polygon_area(poly: &[(f64, f64)]) -> f64 {
    let n = poly.len();
    (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_are_exact_where_the_books_say() {
        // Trapezoid exact for straight lines, Simpson and 3/8 for cubics.
        let cubic = |x: f64| 1.0 + x - 2.0 * x * x + 0.5 * x * x * x;
        let exact = 1.0 + 0.5 - 2.0 / 3.0 + 0.125; // mean over [0, 1]
        let pts = |n: usize| {
            (0..=n)
                .map(|k| cubic(k as f64 / n as f64))
                .collect::<Vec<_>>()
        };
        assert!((simpson(&pts(10)).unwrap() - exact).abs() < 1e-14);
        assert!((three_eighths(&pts(9)).unwrap() - exact).abs() < 1e-14);
        assert!(simpson(&pts(9)).is_none() && three_eighths(&pts(10)).is_none());
        let line: Vec<f64> = (0..=10).map(|k| 2.0 + 0.3 * k as f64).collect();
        assert!((trapezoid(&line) - 3.5).abs() < 1e-14);
    }

    #[test]
    fn the_planimeter_reads_the_area_whatever_the_wheel_position() {
        // A 30 × 20 mm rectangle, traced counter-clockwise from a pole 80 mm away.
        let rect = [(0.0, 0.0), (30.0, 0.0), (30.0, 20.0), (0.0, 20.0)];
        for wheel in [20.0, 50.0, 80.0] {
            let p = Planimeter {
                pole: (15.0, -80.0),
                pole_arm: 90.0,
                tracer_arm: 100.0,
                wheel,
            };
            let a = p.trace(&rect, 0.01).unwrap();
            assert!((a - 600.0).abs() < 0.05, "wheel at {wheel}: {a}");
        }
        assert_eq!(polygon_area(&rect), 600.0);
    }

    #[test]
    fn squares_count_the_area_with_its_sign() {
        let tri = [
            (0.0, 0.0),
            (10.0, 10.0),
            (20.0, 0.0),
            (30.0, -10.0),
            (40.0, 0.0),
        ];
        let a = count_squares(&tri, 1.0);
        assert!(a.abs() < 1e-12, "{a}");
        let up = [(0.0, 10.0), (25.0, 10.0)];
        assert_eq!(count_squares(&up, 1.0), 250.0);
    }

    /// The count stays within its bound on a saw-tooth with two teeth a millimetre, where
    /// one square a column did not hold it.
    #[test]
    fn counted_squares_stay_within_their_bound_on_a_jagged_curve() {
        let saw: Vec<(f64, f64)> = (0..=400)
            .map(|k| (0.25 * k as f64, if k % 2 == 0 { 10.0 } else { 30.0 }))
            .collect();
        let mut closed = saw.clone();
        closed.push((100.0, 0.0));
        closed.push((0.0, 0.0));
        let area = -polygon_area(&closed);
        let counted = count_squares(&saw, 1.0);
        let bound = count_squares_bound(&saw, 1.0);
        assert!((counted - area).abs() <= bound, "{counted} {area} {bound}");
        // A straight line: only the half squares of rounding.
        let flat = [(0.0, 2.3), (10.0, 2.3)];
        assert_eq!(count_squares_bound(&flat, 1.0), 5.0);
    }
}
