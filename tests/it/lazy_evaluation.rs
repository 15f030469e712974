//! "Simulate only the effects a scene calls for": a request constructs only the steps its
//! outputs depend on. Counted by topic and by kind.

use graphostatik::crank::*;
use graphostatik::protocol::BoardConfig;
use graphostatik::protocol::{Board, ObjId, StepKind, Topic, H};
use std::collections::BTreeMap;

fn run(request: Request, finite_rod: bool) -> Board {
    let d = CrankDrive {
        crank_radius: 300.0,
        rod_length: 1500.0,
        finite_rod,
        crank_pin_speed: 5.0,
        piston_force: PistonForce::Constant(8700.0),
    };
    let mut b = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
    construct(
        &mut b,
        &d,
        &Drawing {
            length_scale: 10.0,
            force_scale: 200.0,
            velocity_scale: 0.2,
            acceleration_scale: 10.0,
        },
        &Angles::Divisions(12),
        &request,
    )
    .unwrap();
    b
}

fn by_topic(b: &Board) -> BTreeMap<Topic, usize> {
    let mut m = BTreeMap::new();
    for s in b.steps() {
        *m.entry(s.topic).or_insert(0) += 1;
    }
    m
}

fn count(b: &Board, quantity: &str) -> usize {
    b.steps()
        .iter()
        .flat_map(|s| &s.checks)
        .filter(|c| c.quantity.starts_with(quantity))
        .count()
}

#[test]
fn piston_path_alone_constructs_no_velocity_and_no_force_step() {
    let b = run(
        Request {
            piston_path: true,
            ..Request::default()
        },
        true,
    );
    let t = by_topic(&b);
    assert_eq!(t.get(&Topic::Velocity), None);
    assert_eq!(t.get(&Topic::Forces), None);
    // Setup: O, piston line, vertical, crank circle, dead centre, rod arc, crosshead dead
    // centre, guide = 8. Division of the crank circle = 1. Per angle: crank, rod arc,
    // crosshead, rod, measure = 5. The difference u of the two strokes' paths at 90° (LH
    // Gl. 22), reckoned once = 1.
    assert_eq!(t[&Topic::Setup], 8);
    assert_eq!(t[&Topic::PistonPath], 1 + 12 * 5 + 1);
    assert_eq!(count(&b, "piston path"), 12);
    let measures = b
        .steps()
        .iter()
        .filter(|s| s.kind == StepKind::Measure)
        .count();
    assert_eq!(measures, 12);
}

#[test]
fn velocity_alone_reuses_the_crosshead_but_constructs_no_force_and_no_path_measure() {
    let b = run(
        Request {
            velocity_parallel: true,
            ..Request::default()
        },
        true,
    );
    let t = by_topic(&b);
    assert_eq!(t.get(&Topic::Forces), None);
    assert_eq!(count(&b, "piston path"), 0);
    assert_eq!(count(&b, "piston velocity c (parallel)"), 12);
    assert_eq!(count(&b, "piston velocity c = ω·y"), 0);
    // The crosshead is constructed once per angle even though the rod line and the velocity
    // ordinate both need it.
    let crossheads = b
        .steps()
        .iter()
        .filter(|s| s.kind == StepKind::IntersectLineCircle && s.topic == Topic::PistonPath)
        .count();
    assert_eq!(crossheads, 12);
}

#[test]
fn tangential_force_alone_needs_no_parallelogram_at_the_crosshead() {
    let b = run(
        Request {
            tangential_force: true,
            ..Request::default()
        },
        true,
    );
    assert_eq!(count(&b, "tangential force T (polar)"), 12);
    assert_eq!(count(&b, "rod force"), 0);
    assert_eq!(count(&b, "guide force"), 0);
    assert_eq!(count(&b, "radial force"), 0);
    assert_eq!(count(&b, "piston path"), 0);
    assert_eq!(count(&b, "piston velocity"), 0);
}

#[test]
fn radial_force_pulls_in_the_rod_force_but_not_the_polar_figure() {
    let b = run(
        Request {
            radial_force: true,
            ..Request::default()
        },
        true,
    );
    assert_eq!(count(&b, "radial force"), 12);
    assert_eq!(count(&b, "rod force"), 12);
    assert_eq!(count(&b, "tangential force T (at the pin)"), 12);
    assert_eq!(count(&b, "tangential force T (polar)"), 0);
}

#[test]
fn infinite_rod_draws_no_rod_arcs() {
    let b = run(
        Request {
            piston_path: true,
            ..Request::default()
        },
        false,
    );
    assert_eq!(
        b.steps()
            .iter()
            .filter(|s| s.kind == StepKind::Circle)
            .count(),
        0
    );
    assert_eq!(
        b.steps()
            .iter()
            .filter(|s| s.kind == StepKind::Foot)
            .count(),
        12
    );
}

#[test]
fn a_board_that_does_not_record_keeps_nothing_and_gives_the_same_values() {
    let full = Request {
        piston_path: true,
        velocity_parallel: true,
        velocity_instant_centre: true,
        rod_force: true,
        guide_force: true,
        tangential_force: true,
        radial_force: true,
        acceleration: true,
        max_velocity: true,
        polar_diagrams: true,
        piston_path_fixed_arc: true,
    };
    let d = CrankDrive {
        crank_radius: 300.0,
        rod_length: 1500.0,
        finite_rod: true,
        crank_pin_speed: 5.0,
        piston_force: PistonForce::Constant(8700.0),
    };
    let dr = Drawing {
        length_scale: 10.0,
        force_scale: 200.0,
        velocity_scale: 0.2,
        acceleration_scale: 10.0,
    };
    let mut on = Board::new(BoardConfig::recording(true)).with_figure_size(400.0);
    let mut off = Board::new(BoardConfig::recording(false)).with_figure_size(400.0);
    let a = construct(&mut on, &d, &dr, &Angles::Divisions(24), &full).unwrap();
    let b = construct(&mut off, &d, &dr, &Angles::Divisions(24), &full).unwrap();
    // The same values; the handles of what was read differ (a board that does not record
    // gives none).
    let values = |mut r: CrankResults| {
        for row in &mut r.rows {
            row.tangential_read = row.tangential_read.map(|h| H {
                id: ObjId::NONE,
                ..h
            });
        }
        r
    };
    assert_eq!(values(a), values(b));
    assert!(off.steps().is_empty() && off.objects().is_empty());
}

#[test]
fn acceleration_alone_draws_no_velocity_and_no_force_and_only_the_frame_it_stands_under() {
    let b = run(
        Request {
            acceleration: true,
            ..Request::default()
        },
        true,
    );
    let t = by_topic(&b);
    assert_eq!(t.get(&Topic::Velocity), None);
    assert_eq!(t.get(&Topic::Forces), None);
    // The crank positions are not drawn: the parabola is reached from the crank angle alone.
    assert_eq!(t.get(&Topic::PistonPath), None);
    // The axis (O, axis, vertical, two ends, their ordinates, C and its ordinate: 9); each
    // curve T, T₁, D, two tangents, chord, its cut, OC read off (8), the two tangents divided,
    // 9 joining lines with their points of contact, the curve (21); then one point per crank
    // angle: 7 steps (two divisions, the joining line, the point, its foot, two readings).
    // The axis now holds O, the axis, the vertical, the ends with their ordinates (7) and C
    // with its ordinate (2); each curve adds the balance of its areas (a tally), and the
    // outstroke's CD is taken off again (1).
    let fixed = 9 + 2 * (8 + 1 + 2 + 9 * 2 + 1) + 1;
    assert_eq!(t[&Topic::Acceleration], fixed + 12 * 7, "{t:?}");
    assert_eq!(count(&b, "piston acceleration b"), 12);
    assert_eq!(count(&b, "b against the finite rod"), 12);
    assert_eq!(count(&b, "chord TT₁"), 2);
    // Asking for it twice adds nothing (memoised per angle and for the diagram).
    let silent = run(Request::default(), true);
    assert!(silent.steps().is_empty());
}

#[test]
fn esselborn_alone_constructs_one_position_and_no_crank_division() {
    let b = run(
        Request {
            max_velocity: true,
            ..Request::default()
        },
        true,
    );
    let t = by_topic(&b);
    assert_eq!(t.get(&Topic::PistonPath), None);
    assert_eq!(t.get(&Topic::Forces), None);
    // On the outstroke and on the return (LH B.2: 79°16′ and 100°44′).
    assert_eq!(count(&b, "crank angle of the rod perpendicular"), 2);
    assert_eq!(count(&b, "piston velocity at Esselborn"), 1);
    // No velocities constructed, no mean piston speed read off them (LH Gl. 26).
    assert_eq!(count(&b, "v / c_m"), 0);
}
