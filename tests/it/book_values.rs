//! The numbers the books print, against the engine. Book numbers are rounded to three decimals
//! or carry drawing error; where a printed value disagrees beyond that, the test names it
//! (the OCR and the books have misprints: they are reported, the engine is not bent to them).

use graphostatik::crank::closed_form::{accel_factor, sin_factor, Stroke};
use graphostatik::crank::*;
use graphostatik::protocol::Board;
use graphostatik::protocol::BoardConfig;
use graphostatik::scene::{Procedure, SliderCrankScene};

/// Half a unit of the third decimal: the rounding of the printed table.
const TABLE_ROUNDING: f64 = 0.0005;

/// KG Zusammenstellung 112 (S. 602), as printed (seeds/000, lines 32-34): for R/L = 1/5,
/// 1/4.5, 1/4 and φ = 0°, 10°, …, 80°, the pairs (cos φ + R/L cos 2φ, sin(φ + ψ)/cos ψ).
const TABLE_112: [(f64, [(f64, f64); 9]); 3] = [
    (
        5.0,
        [
            (1.200, 0.0),
            (1.173, 0.206),
            (1.093, 0.405),
            (0.966, 0.585),
            (0.801, 0.740),
            (0.608, 0.865),
            (0.400, 0.953),
            (0.189, 1.005),
            (0.014, 1.021),
        ],
    ),
    (
        4.5,
        [
            (1.222, 0.0),
            (1.194, 0.212),
            (1.110, 0.413),
            (0.977, 0.597),
            (0.805, 0.753),
            (0.604, 0.877),
            (0.389, 0.984),
            (0.172, 1.012),
            (-0.025, 1.024),
        ],
    ),
    (
        4.0,
        [
            (1.250, 0.0),
            (1.220, 0.216),
            (1.131, 0.423),
            (0.981, 0.609),
            (0.809, 0.768),
            (0.599, 0.891),
            (0.375, 0.977),
            (0.151, 1.022),
            (-0.034, 1.029),
        ],
    ),
];

/// Every printed value that differs from the closed form by more than the rounding, as
/// (L/R, φ, which row, printed, closed form rounded to 4 decimals). What they are:
/// - L/R = 5, lower row: 0.0007-0.0021 low at 10°-60°, right at 70°, 0.0013 high at 80° (not
///   "low throughout": a drawing, or a slightly different ψ, rather than one systematic slip);
/// - L/R = 5, 80°, upper row: the sign is lost (0.014 printed, −0.0143 exact);
/// - L/R = 4.5, 60°, lower row: 0.984 printed, 0.9641 exact: a misprint (0.964);
/// - L/R = 4.5, 80°, and L/R = 4, 80°, upper row: −0.025 and −0.034 printed, −0.0352 and
///   −0.0613 exact;
/// - L/R = 4, 30°, upper row: 0.981 printed, 0.991 exact: a misprint;
/// - L/R = 4.5, 20° and 70°, lower row: off by 0.0006 and 0.0007, one unit in the last place.
const TABLE_112_DISAGREEMENTS: [(f64, u32, &str, f64, f64); 13] = [
    (5.0, 10, "sin", 0.206, 0.2079),
    (5.0, 20, "sin", 0.405, 0.4064),
    (5.0, 30, "sin", 0.585, 0.587),
    (5.0, 40, "sin", 0.740, 0.7421),
    (5.0, 50, "sin", 0.865, 0.8657),
    (5.0, 60, "sin", 0.953, 0.954),
    (5.0, 80, "cos", 0.014, -0.0143),
    (5.0, 80, "sin", 1.021, 1.0197),
    (4.5, 20, "sin", 0.413, 0.4136),
    (4.5, 60, "sin", 0.984, 0.9641),
    (4.5, 70, "sin", 1.012, 1.0127),
    (4.5, 80, "cos", -0.025, -0.0352),
    (4.0, 30, "cos", 0.981, 0.991),
];

#[test]
fn kg_zusammenstellung_112_reproduced_and_its_misprints_named() {
    let mut found = Vec::new();
    let mut agree = 0;
    for (k, row) in TABLE_112 {
        let lambda = 1.0 / k;
        for (i, (a_book, s_book)) in row.iter().enumerate() {
            let phi = 10.0 * i as f64;
            let a = accel_factor(lambda, phi, Stroke::Out);
            let s = sin_factor(lambda, phi, Stroke::Out);
            for (which, book, exact) in [("cos", *a_book, a), ("sin", *s_book, s)] {
                if (book - exact).abs() > TABLE_ROUNDING + 1e-12 {
                    found.push((k, phi as u32, which, book, (exact * 1e4).round() / 1e4));
                } else {
                    agree += 1;
                }
            }
        }
    }
    // L/R = 4, 80°, upper row is the thirteenth disagreement beyond the list's twelve
    // plus the one below; keep the list exact.
    let mut expected: Vec<_> = TABLE_112_DISAGREEMENTS.to_vec();
    expected.push((4.0, 80, "cos", -0.034, -0.0613));
    expected.sort_by(|a, b| a.partial_cmp(b).unwrap());
    found.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(found, expected);
    assert_eq!(agree, 54 - expected.len());
    // The 1 : 5 lower row is not low throughout: low by 0.0007-0.0021 at 10°-60°, within the
    // rounding at 70°, and 0.0013 high at 80°.
    for (i, (_, printed)) in TABLE_112[0].1.iter().enumerate().skip(1) {
        let d = printed - sin_factor(0.2, 10.0 * i as f64, Stroke::Out);
        match i {
            1..=6 => assert!((-0.0022..=-0.0006).contains(&d), "{}°: {d}", 10 * i),
            7 => assert!(d.abs() <= TABLE_ROUNDING, "70°: {d}"),
            _ => assert!((0.0012..0.0014).contains(&d), "80°: {d}"),
        }
    }
}

#[test]
fn kg_table_values_are_what_the_construction_draws() {
    // The lower row is c/v: construct c at φ = 0..80° and compare with the closed form that
    // the table stands for (tight), then with the printed values (table rounding, except the
    // named disagreements).
    for (k, row) in TABLE_112 {
        let lambda = 1.0 / k;
        let d = CrankDrive {
            crank_radius: 400.0,
            rod_length: 400.0 * k,
            finite_rod: true,
            crank_pin_speed: 1.0,
            piston_force: PistonForce::Constant(1.0),
        };
        let angles: Vec<f64> = (0..9).map(|i| 10.0 * i as f64).collect();
        let mut board = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
        let res = construct(
            &mut board,
            &d,
            &Drawing {
                length_scale: 20.0,
                force_scale: 0.02,
                velocity_scale: 0.05,
                acceleration_scale: 10.0,
            },
            &Angles::Degrees(angles),
            &Request {
                velocity_parallel: true,
                tangential_force: true,
                ..Request::default()
            },
        )
        .unwrap();
        for (i, r) in res.rows.iter().enumerate() {
            let exact = sin_factor(lambda, r.phi, Stroke::Out);
            assert!((r.c_parallel.unwrap() - exact).abs() < 1e-12);
            assert!((r.tangential_force.unwrap() - exact).abs() < 1e-12);
            let listed = TABLE_112_DISAGREEMENTS
                .iter()
                .any(|&(kk, phi, w, _, _)| kk == k && phi == 10 * i as u32 && w == "sin");
            if !listed {
                assert!((r.c_parallel.unwrap() - row[i].1).abs() <= TABLE_ROUNDING + 1e-12);
            }
        }
    }
}

/// Golden-section search for the largest constructed piston velocity on the outstroke.
fn constructed_c_max(lambda: f64) -> (f64, f64) {
    let d = CrankDrive {
        crank_radius: 400.0,
        rod_length: 400.0 / lambda,
        finite_rod: true,
        crank_pin_speed: 1.0,
        piston_force: PistonForce::Constant(0.0),
    };
    let c_at = |theta: f64| -> f64 {
        let mut b = Board::new(BoardConfig::recording(false)).with_figure_size(300.0);
        construct(
            &mut b,
            &d,
            &Drawing {
                length_scale: 20.0,
                force_scale: 1.0,
                velocity_scale: 0.05,
                acceleration_scale: 10.0,
            },
            &Angles::Degrees(vec![theta]),
            &Request {
                velocity_parallel: true,
                ..Request::default()
            },
        )
        .unwrap()
        .rows[0]
            .c_parallel
            .unwrap()
    };
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (60.0, 100.0);
    while b - a > 1e-7 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if c_at(x1) < c_at(x2) {
            a = x1;
        } else {
            b = x2;
        }
    }
    let t = 0.5 * (a + b);
    (c_at(t), t)
}

#[test]
fn kg_c_max_1_02_1_025_1_031_v() {
    // KG B.2: c_max = 1.02 v, 1.025 v, 1.031 v for R/L = 1/5, 1/4.5, 1/4. Constructed:
    // 1.0198, 1.0244, 1.0309. The middle value is printed one unit high in the last place
    // (1.0244 rounds to 1.024); it is within the books' drawing tolerance of 1 %.
    let expected = [
        (5.0, 1.02, 1.019833),
        (4.5, 1.025, 1.024448),
        (4.0, 1.031, 1.030883),
    ];
    for (k, book, exact) in expected {
        let (c, _) = constructed_c_max(1.0 / k);
        assert!((c - exact).abs() < 1e-6, "L/R = {k}: {c}");
        let tol = if k == 4.5 {
            0.01 * book
        } else {
            TABLE_ROUNDING
        };
        assert!((c - book).abs() <= tol, "L/R = {k}: {c} vs book {book}");
    }
}

#[test]
fn lh_angle_of_c_max_79_16_and_the_rod_perpendicular_to_the_crank() {
    // LH B.2: c_max at α = 79°16' for r/l = 1/5, "where the rod stands perpendicular to the
    // crank". The constructed maximum lies at 79.10° (79°06'); the rod is perpendicular to the
    // crank at atan(5) = 78.69° (78°41'), where c is 0.003 % below c_max: the perpendicular
    // rule is an approximation (KG says "annähernd"), and a very good one.
    let (c, theta) = constructed_c_max(0.2);
    assert!((theta - 79.10).abs() < 0.01, "{theta}");
    let perp = 5f64.atan().to_degrees();
    let c_perp = sin_factor(0.2, perp, Stroke::Out);
    assert!((c_perp - (1.0f64 + 0.04).sqrt()).abs() < 1e-12); // = 1/cos ψ there
    let below = (c - c_perp) / c;
    assert!((0.000025..0.000035).contains(&below), "{below}");
    // The book's 79°16' is not a misplaced maximum: it is the exact root of its own
    // approximate acceleration, Gl. 29 with p = 0 (LH: "Setzt man in Gl. 29 p = 0, so erhält
    // man ... α = 79°16'"): cos α + λ cos 2α = 0 at 79.272° = 79°16.3'.
    let gl29 = |a: f64| a.to_radians().cos() + 0.2 * (2.0 * a.to_radians()).cos();
    let (mut lo, mut hi) = (60.0f64, 90.0f64);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if gl29(lo) * gl29(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let book = 79.0 + 16.0 / 60.0;
    assert!(
        (lo - book).abs() < 0.5 / 60.0,
        "Gl. 29 root {lo}° against 79°16'"
    );
    // And its return-stroke twin 100°44' is the root of cos α − λ cos 2α.
    let back: f64 = 100.0 + 44.0 / 60.0;
    let r = back.to_radians();
    assert!((r.cos() - 0.2 * (2.0 * r).cos()).abs() < 2e-4);
}

fn scene(text: &str) -> graphostatik::scene::SliderCrankProblem {
    SliderCrankScene::read(text, "test").unwrap().1
}

#[test]
fn lh_locomotive_speeds() {
    // LH Abb. 43: v1 = 60000/3600 = 16.7 m/s, v = v1 · s/D1 = 7 m/s, v/r = 22.2.
    let p = scene(include_str!("../../scenes/lh_abb43_locomotive.json"));
    assert!((p.drive.crank_pin_speed - 7.0).abs() < 1e-12);
    assert!((p.drive.omega() - 22.2).abs() < 0.05);
    assert!((p.drive.lambda() - 1.0 / 6.0).abs() < 1e-15);
}

#[test]
fn kg_tafel_1_crank_pin_speed() {
    // KG B.4b: v = 2.095 m/s for R = 0.4 m, n = 50/min (2π · 0.4 · 50/60 = 2.0944).
    let p = scene(include_str!("../../scenes/kg_tafel1.json"));
    assert!((p.drive.crank_pin_speed - 2.095).abs() < 0.001);
}

#[test]
fn lh_aufgabe_1_piston_force() {
    // LH Aufgabe 1: K = π·43²/4 · 6 = 1450 · 6 ≈ 8700 kg (exact 8713 kg: the book rounds the
    // area to 1450 cm², 0.15 %).
    let p = scene(include_str!("../../scenes/lh_aufgabe1_forces.json"));
    let k = p.drive.piston_force.max_abs();
    assert!((k - std::f64::consts::PI / 4.0 * 43.0 * 43.0 * 6.0).abs() < 1e-9);
    assert!((k - 8700.0).abs() / 8700.0 < 0.0016);
    assert_eq!(p.drawing.force_scale, 200.0);
}

#[test]
fn lh_aufgabe_1_printed_forces_do_not_belong_to_one_crank_angle() {
    // LH Aufgabe 1 prints, for K = 8700 kg and r/L = 1/5 at the position of Abb. 30:
    // S = 8800, V = 900, T = 8500, D = 1300 kg. S alone fixes the rod angle:
    let (k, lambda) = (8700.0f64, 0.2f64);
    let psi = (k / 8800.0).acos();
    assert!((psi.to_degrees() - 8.646).abs() < 1e-3);
    assert!(
        (k * psi.tan() - 1322.9).abs() < 0.1,
        "S = 8800 means V = 1323, not 900"
    );
    // But that inference is ill-conditioned: S = 8750 and 8850 (the book's drawing error of
    // ±0.6 %) give V = 934 and 1622. The printed T and D fix the angle well instead: T/D =
    // tan(φ + ψ) gives φ = 70.4° (±0.4° for ±50 kg on either), and there V = 1670 kg, with
    // S = 8859. V = 900 would need φ = 31°, where T = 5250 and D = 7000 kg. So the conflict
    // is T and D against V, and V looks misprinted.
    for (s_book, v_lo, v_hi) in [(8750.0f64, 930.0, 940.0), (8850.0, 1620.0, 1625.0)] {
        let v = k * (k / s_book).acos().tan();
        assert!((v_lo..v_hi).contains(&v), "S = {s_book}: V = {v}");
    }
    let phi_from_td = |t: f64, d: f64| {
        let sum = t.atan2(d); // φ + ψ
        let (mut lo, mut hi) = (0.0f64, std::f64::consts::FRAC_PI_2);
        for _ in 0..100 {
            let m = 0.5 * (lo + hi);
            if m + (lambda * m.sin()).asin() < sum {
                lo = m;
            } else {
                hi = m;
            }
        }
        lo.to_degrees()
    };
    for (t, d) in [(8500.0, 1300.0), (8450.0, 1250.0), (8550.0, 1350.0)] {
        let phi = phi_from_td(t, d);
        let v = graphostatik::crank::closed_form::guide_force(k, lambda, phi);
        assert!(
            (70.0..70.8).contains(&phi) && (1660.0..1680.0).contains(&v),
            "{phi} {v}"
        );
    }
    // The crank angle that fits the four printed values best (least squares, 0.01° steps):
    let fit = |phi: f64| {
        let book = [8800.0, 900.0, 8500.0, 1300.0];
        let (s, n, t, d) = (
            graphostatik::crank::closed_form::rod_force(k, lambda, phi),
            graphostatik::crank::closed_form::guide_force(k, lambda, phi),
            graphostatik::crank::closed_form::tangential_force(k, lambda, phi),
            graphostatik::crank::closed_form::radial_force(k, lambda, phi),
        );
        [s, n, t, d]
            .iter()
            .zip(book)
            .map(|(c, b)| ((c - b) / 8800.0).powi(2))
            .sum::<f64>()
    };
    let best = (0..18000)
        .map(|i| i as f64 / 100.0)
        .min_by(|a, b| fit(*a).total_cmp(&fit(*b)))
        .unwrap();
    assert!((best - 70.1).abs() < 0.011, "{best}");
    // The bundled scene constructs that position; S and T agree with the book within the
    // books' drawing error (3.5 %), D is 7.3 % off, and V 85 %.
    let p = scene(include_str!("../../scenes/lh_aufgabe1_abb30.json"));
    let (board, res) = SliderCrankScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
    let r = &res.rows[0];
    let rel = |c: f64, b: f64| (c - b).abs() / b;
    assert!(rel(r.rod_force.unwrap(), 8800.0) < 0.035);
    assert!(rel(r.tangential_force.unwrap(), 8500.0) < 0.035);
    assert!((0.0725..0.0735).contains(&rel(r.radial_force.unwrap(), 1300.0)));
    assert!(rel(r.guide_force.unwrap(), 900.0) > 0.8);
}

#[test]
fn lh_aufgabe_7_crankshaft_sizing() {
    use graphostatik::statics::sizing::*;
    // P_max = π·17²/4 · 20 = 227 · 20 = 4540 kg (exact 4539.6).
    let pmax = std::f64::consts::PI * 17.0 * 17.0 / 4.0 * 20.0;
    assert!((pmax - 4540.0).abs() < 0.5);
    // K' = P_max·r/R: the book writes 4550·11/55 = "~900" (910); with its own 4540 it is 908.
    assert!((pmax * 11.0 / 55.0 - 908.0).abs() < 0.1);
    // Pole distance h = 25 mm, 1 mm = 100 kg, 1 : 10.
    let cd = diameter_constant(25.0, 100.0, 10.0, 1000.0);
    assert!((cd - 2.92).abs() < 0.005, "{cd}");
    // Crank pin, y'' = 25 mm: d = 2.92·∛25 = 8.5 cm; bearing A, y''' = 17 mm: 7.5 cm.
    for (y, book_mm) in [(25.0, 85.0), (17.0, 75.0)] {
        let d = shaft_diameter_cm(ordinate_moment_kgcm(y, 25.0, 100.0, 10.0), 1000.0);
        assert!((d * 10.0 - book_mm).abs() < 0.6, "y = {y}: {} mm", d * 10.0);
    }
    // Arms: k_b = 500, b = 5.5 cm: const = 2.34; y = 25, 25, 19 mm give 117, 117, 102 mm as
    // printed. For y = 21 mm the book prints 108, but 2.34·√21 = 107.2 gives 107 mm (and so
    // does the unrounded constant 2.3355: 107.0): an arithmetic slip of one millimetre.
    let ch = height_constant(25.0, 100.0, 10.0, 5.5, 500.0);
    assert!((ch - 2.34).abs() < 0.005, "{ch}");
    for (y, book_mm) in [(25.0, 117.0), (19.0, 102.0)] {
        let h = arm_height_cm(ordinate_moment_kgcm(y, 25.0, 100.0, 10.0), 5.5, 500.0);
        assert_eq!((h * 10.0).round(), book_mm, "y = {y}: {} mm", h * 10.0);
    }
    let h21 = arm_height_cm(ordinate_moment_kgcm(21.0, 25.0, 100.0, 10.0), 5.5, 500.0);
    assert_eq!((h21 * 10.0).round(), 107.0, "{} mm", h21 * 10.0);
    assert_eq!((2.34 * 21f64.sqrt() * 10.0).round(), 107.0);
}

/// One unit in the last printed place of LH's accelerations (m/s², one decimal).
const LH_ONE_UNIT: f64 = 0.1;

#[test]
fn lh_b3_accelerations_of_the_locomotive_by_tolles_parabola() {
    // LH B.3 (s = 630 mm, λ = 1/6, v = 7 m/s): v²/r = 155.5, p0 = 181.5, p180 = 129.7,
    // OC = 3.125 mm, CD = 77.7 m/s² = 0.52 cm at 1 cm = 150 m/s² over 2r = 37.5 mm.
    let p = scene(include_str!("../../scenes/lh_abb55_acceleration.json"));
    let (board, res) = SliderCrankScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
    let a = p.drive.v2_over_r();
    // 49/0.315 = 155.556: the book truncates to 155.5 (rounding would print 155.6).
    assert!(
        (a - 155.5).abs() < LH_ONE_UNIT && (a - 155.556).abs() < 1e-3,
        "{a}"
    );
    let rows = &res.rows;
    let at = |theta: f64| rows.iter().find(|r| r.theta == theta).unwrap();
    // p0 on the outstroke at the inner dead centre: 181.48 → 181.5.
    let p0 = at(0.0).acceleration.unwrap();
    assert!((p0 - 181.5).abs() <= 0.05, "{p0}");
    // p180, the acceleration at the start of the return stroke: 129.63. The book's 129.7 is
    // 0.07 high, one unit in its last place: 155.6 · 5/6 = 129.67 would print it, so the book
    // seems to have carried 155.6 here while it printed 155.5 above (an arithmetic slip far
    // below drawing accuracy, 0.05 %).
    let p180 = at(180.0).acceleration.unwrap();
    assert!(
        (p180 - 129.63).abs() < 0.005 && (p180 - 129.7).abs() <= LH_ONE_UNIT,
        "{p180}"
    );
    // The sheet lengths the book prints at 1 cm = 150 m/s² (one unit of 0.01 cm; 0.005 cm for
    // the three-decimal 0.865): 1.21 cm, 0.865 cm (0.864 from the exact 129.63), and
    // CD = 3λ·v²/r = 77.78 m/s² = 0.52 cm (the book's 77.7 = 155.5/2 truncated).
    assert!((p0 / 150.0 - 1.21).abs() < 0.005);
    assert!((p180 / 150.0 - 0.865).abs() < 0.001);
    let cd = 3.0 / 6.0 * a;
    assert!((cd - 77.7).abs() <= LH_ONE_UNIT && (cd / 150.0 - 0.52).abs() < 0.005);
    // OC = λ·r = 315/6 mm on the machine = 3.125 mm on the 37.5 mm diagram: the chord TT₁
    // cuts the axis there (the book's control), constructed.
    let oc: Vec<f64> = board
        .checks()
        .filter(|c| c.quantity.starts_with("chord TT₁"))
        .map(|c| c.constructed)
        .collect();
    assert_eq!(oc.len(), 2);
    for v in oc {
        assert!((v / 16.8 - 3.125).abs() < 1e-9, "{v}");
    }
    // Return stroke, mirrored: at 360° − θ the same point of the stroke, the opposite sign.
    for r in rows.iter().filter(|r| r.theta > 180.0) {
        let twin = at(360.0 - r.theta);
        assert!((r.acceleration.unwrap() + twin.acceleration.unwrap()).abs() < 1e-9);
        assert!((r.acceleration_x.unwrap() - twin.acceleration_x.unwrap()).abs() < 1e-9);
    }
}

#[test]
fn lh_gl34_infinite_rod_acceleration_is_a_straight_line() {
    // LH Gl. 34, Abb. 56: p0 = p180 = v²/r = 155.5 m/s² = 1.04 cm; the curve is the straight
    // line through the middle O, so b is linear in the piston path x.
    let p = scene(include_str!(
        "../../scenes/lh_abb56_acceleration_infinite_rod.json"
    ));
    let (board, res) = SliderCrankScene::construct(&p, BoardConfig::DRAWING).unwrap();
    assert!(board.all_passed());
    let rows = &res.rows;
    let a = rows[0].acceleration.unwrap();
    assert!((a / 150.0 - 1.04).abs() < 0.005);
    for r in rows.iter().filter(|r| r.theta < 180.0) {
        let (x, b) = (r.acceleration_x.unwrap(), r.acceleration.unwrap());
        assert!(
            (b - a * (1.0 - x / 315.0)).abs() < 1e-9 * a,
            "θ = {}",
            r.theta
        );
    }
}

#[test]
fn kg_zusammenstellung_112_upper_row_by_tolles_construction() {
    // The upper row is b/(v²/R): read off the constructed parabola at φ = 0..80° and compare
    // with the printed values (table rounding, except the disagreements named above).
    for (k, row) in TABLE_112 {
        let lambda = 1.0 / k;
        let d = CrankDrive {
            crank_radius: 400.0,
            rod_length: 400.0 * k,
            finite_rod: true,
            crank_pin_speed: 2.0, // v²/R = 10 m/s²
            piston_force: PistonForce::Constant(0.0),
        };
        let angles: Vec<f64> = (0..9).map(|i| 10.0 * i as f64).collect();
        let mut board = Board::new(BoardConfig::recording(true)).with_figure_size(300.0);
        let drawing = Drawing {
            length_scale: 20.0,
            force_scale: 1.0,
            velocity_scale: 0.05,
            acceleration_scale: 0.5,
        };
        let request = Request {
            acceleration: true,
            ..Request::default()
        };
        let res = construct(&mut board, &d, &drawing, &Angles::Degrees(angles), &request).unwrap();
        assert!(board.all_passed());
        for (i, r) in res.rows.iter().enumerate() {
            let factor = r.acceleration.unwrap() / d.v2_over_r();
            assert!((factor - accel_factor(lambda, r.phi, Stroke::Out)).abs() < 1e-12);
            let listed = TABLE_112_DISAGREEMENTS
                .iter()
                .any(|&(kk, phi, w, _, _)| kk == k && phi == 10 * i as u32 && w == "cos")
                || (k == 4.0 && i == 8);
            if !listed {
                assert!(
                    (factor - row[i].0).abs() <= TABLE_ROUNDING + 1e-12,
                    "L/R = {k}, φ = {}: {factor} vs {}",
                    10 * i,
                    row[i].0
                );
            }
        }
    }
}

#[test]
fn kg_1_20_times_is_one_plus_one_fifth_not_the_ratio_of_abb_1050() {
    // KG B.3: "bei R/L = 1/2.8 das 1,20fache". (1 + R/L) at R/L = 1/2.8 is 1.357; 1.20 is
    // (1 + R/L) at 1/5, the first entry of Zusammenstellung 112. The engine draws 1.357 for
    // the ratio of Abb. 1050; the printed factor belongs to R/L = 1/5 (a slip of the text or
    // of the OCR, which we cannot tell apart: the second OCR does not cover B.3).
    let b0 = |lambda: f64| graphostatik::crank::closed_form::acceleration_exact(1.0, lambda, 0.0);
    assert!((b0(1.0 / 2.8) - 1.357).abs() < 0.0005);
    assert!((b0(0.2) - 1.20).abs() < 1e-12);
}

/// Every book value a bundled scene carries is reproduced or differs for the cause it names;
/// the counts are the ones README gives.
#[test]
fn the_book_rows_of_the_bundled_scenes_are_reproduced_or_explained() {
    use graphostatik::protocol::{BoardConfig, Mode};
    let (mut shown, mut explained) = (0, 0);
    for p in super::support::bundled_scenes() {
        let any = graphostatik::scene::AnyScene::load(&p).unwrap();
        if any.book().is_empty() {
            continue;
        }
        let config = BoardConfig {
            mode: Mode::Checks { every: true },
            ..BoardConfig::DRAWING
        };
        let board = any.problem().construct(config).unwrap();
        for r in graphostatik::render::book_rows(&board, any.book()) {
            assert!(r.passed(), "{}: {r:?}", p.display());
            shown += 1;
            explained += usize::from(r.verdict == graphostatik::render::Verdict::Explained);
        }
    }
    assert_eq!((shown, explained), (183, 53));
}
