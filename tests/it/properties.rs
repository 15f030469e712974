//! Property tests: invariants over random mechanisms, angles and geometry.

use graphostatik::crank::*;
use graphostatik::kernel::*;
use graphostatik::protocol::Board;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Any mechanism, any angles: every construction agrees with its closed form.
    #[test]
    fn crank_constructions_match_closed_forms(
        r in 10.0f64..2000.0,
        lambda in 0.005f64..0.995,
        finite in any::<bool>(),
        v in 0.01f64..50.0,
        p in -20000.0f64..20000.0,
        thetas in proptest::collection::vec(0.0f64..360.0, 1..12),
        ls in 0.5f64..50.0,
    ) {
        let d = CrankDrive {
            crank_radius: r,
            rod_length: r / lambda,
            finite_rod: finite,
            crank_pin_speed: v,
            piston_force: PistonForce::Constant(p),
        };
        // Every quantity drawn some 30 mm long, as the scene defaults choose (an ordinate of
        // 5e-6 mm under a 4 m sheet keeps only seven digits).
        let dr = Drawing { length_scale: ls, force_scale: 100.0, velocity_scale: v / 30.0,
            acceleration_scale: d.v2_over_r() / 30.0 };
        let request = Request {
            piston_path: true, velocity_parallel: true, velocity_instant_centre: true,
            rod_force: true, guide_force: true, tangential_force: true, radial_force: true, acceleration: true, max_velocity: true, polar_diagrams: true, piston_path_fixed_arc: true,
        };
        let mut b = Board::recording().with_figure_size((r + r / lambda) / ls);
        construct(&mut b, &d, &dr, &Angles::Degrees(thetas), &request).unwrap();
        for c in b.steps().iter().flat_map(|s| &s.checks) {
            prop_assert!(c.passed, "{} {} vs {} (err {:e}, tol {:e})",
                c.quantity, c.constructed, c.closed_form, c.error, c.tolerance);
        }
    }

    /// Points of a line-circle intersection lie on both curves.
    #[test]
    fn line_circle_points_lie_on_both(
        cx in -100.0f64..100.0, cy in -100.0f64..100.0, rad in 0.1f64..100.0,
        ox in -100.0f64..100.0, oy in -100.0f64..100.0, ang in 0.0f64..360.0,
    ) {
        let tol = Tolerance::for_figure(300.0);
        let c = Circle::new(Point::new(cx, cy), rad).unwrap();
        let (s, co) = angle::sin_cos_deg(ang);
        let l = Line::new(Point::new(ox, oy), Vector::new(co, s)).unwrap();
        match intersect_line_circle(&l, &c, &tol) {
            LineCircle::Two { points, conditioning } => {
                for p in points {
                    prop_assert!(((p - c.center).norm() - rad).abs() < 1e-9 * conditioning.amplification().max(1.0) * 300.0 / rad.max(1.0) + 1e-10);
                    prop_assert!(l.signed_distance(&p).abs() < 1e-12 * 300.0);
                }
                prop_assert!(conditioning.angle() >= 0.0 && conditioning.angle() <= std::f64::consts::FRAC_PI_2);
            }
            LineCircle::Tangent { point } => {
                prop_assert!(((point - c.center).norm() - rad).abs() <= tol.length * 2.0);
            }
            LineCircle::Disjoint { gap } => {
                prop_assert!(gap > 0.0);
                prop_assert!((l.signed_distance(&c.center).abs() - rad - gap).abs() < 1e-9);
            }
        }
    }

    /// Points of a circle-circle intersection lie on both circles; the cases are consistent
    /// with the distance of the centres.
    #[test]
    fn circle_circle_cases_are_consistent(
        x1 in -50.0f64..50.0, y1 in -50.0f64..50.0, r1 in 0.1f64..60.0,
        x2 in -50.0f64..50.0, y2 in -50.0f64..50.0, r2 in 0.1f64..60.0,
    ) {
        let tol = Tolerance::for_figure(200.0);
        let a = Circle::new(Point::new(x1, y1), r1).unwrap();
        let b = Circle::new(Point::new(x2, y2), r2).unwrap();
        let d = (b.center - a.center).norm();
        match intersect_circle_circle(&a, &b, &tol) {
            CircleCircle::Two { points, conditioning } => {
                prop_assert!(d < r1 + r2 && d > (r1 - r2).abs());
                for p in points {
                    let amp = conditioning.amplification().min(1e8);
                    prop_assert!(((p - a.center).norm() - r1).abs() < 1e-11 * 200.0 * amp);
                    prop_assert!(((p - b.center).norm() - r2).abs() < 1e-11 * 200.0 * amp);
                }
            }
            CircleCircle::Separate { gap } => prop_assert!((d - r1 - r2 - gap).abs() < 1e-12 * 200.0),
            CircleCircle::Contained { gap } => prop_assert!(((r1 - r2).abs() - d - gap).abs() < 1e-12 * 200.0),
            CircleCircle::TangentExternal { point } | CircleCircle::TangentInternal { point } => {
                prop_assert!(((point - a.center).norm() - r1).abs() < 1e-9);
            }
            CircleCircle::Concentric | CircleCircle::Coincident => prop_assert!(d <= tol.length),
        }
    }

    /// Line-line: the point lies on both lines, and near-parallel lines stay finite.
    #[test]
    fn line_line_point_on_both(
        ox in -100.0f64..100.0, oy in -100.0f64..100.0, a1 in 0.0f64..180.0,
        px in -100.0f64..100.0, py in -100.0f64..100.0, da in -1.0f64..1.0,
    ) {
        let tol = Tolerance::for_figure(300.0);
        let (s1, c1) = angle::sin_cos_deg(a1);
        let (s2, c2) = angle::sin_cos_deg(a1 + da * da * da * 90.0);
        let l1 = Line::new(Point::new(ox, oy), Vector::new(c1, s1)).unwrap();
        let l2 = Line::new(Point::new(px, py), Vector::new(c2, s2)).unwrap();
        match intersect_line_line(&l1, &l2, &tol) {
            LineLine::Point { point, conditioning, .. } => {
                prop_assert!(point.x.is_finite() && point.y.is_finite());
                let scale = 300.0 + point.coords.norm();
                prop_assert!(l1.signed_distance(&point).abs() < 1e-12 * scale);
                prop_assert!(l2.signed_distance(&point).abs() < 1e-12 * scale * conditioning.amplification().min(1e12));
            }
            LineLine::Parallel { distance } => prop_assert!(distance > 0.0 && distance.is_finite()),
            LineLine::Coincident => {}
        }
    }
}
