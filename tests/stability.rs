//! Stiff and extreme cases of the seed scene: each either solves with
//! finite, balanced results within bounds derived from its conditioning,
//! or ends with a clear status — never with NaN or Inf.

use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;
use tfem::verification::run_manufactured_laplace;
use tfem::{ContactOptions, Status, Tempering};

fn base() -> TwoBlocks {
    TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    }
}

fn finite(s: &tfem::scenes::TwoBlocksScene) -> bool {
    s.model
        .displacements()
        .unwrap()
        .iter()
        .flatten()
        .all(|v| v.is_finite())
        && s.model
            .contact_pressure()
            .unwrap()
            .iter()
            .all(|v| v.is_finite())
}

#[test]
fn stiffness_contrast_up_to_1e9_solves_with_balance_within_its_conditioning() {
    for ratio in [1.0, 1e3, 1e6, 1e9] {
        let scene = TwoBlocks {
            e2: base().e1 * ratio,
            ..base()
        };
        let mut s = scene.build().unwrap();
        let r = s.solve(&ContactOptions::default()).unwrap();
        assert!(finite(&s));
        let load = scene.p * 2.0 * scene.c;
        let cond = r.report.info.condition_estimate;
        // Backward-stable solve: relative error ≲ cond · eps (with margin 10).
        let bound = (10.0 * cond * f64::EPSILON).max(1e-10);
        assert!(
            (r.support_reaction - load).abs() <= bound * load,
            "ratio {ratio}: balance {} vs bound {bound}",
            r.support_reaction / load - 1.0
        );
        assert!(r.gap_edge > 0.0 && r.lc < scene.length, "ratio {ratio}");
    }
}

#[test]
fn a_stiffness_contrast_beyond_double_precision_is_reported_not_returned() {
    let mut s = TwoBlocks { e2: 1e22, ..base() }.build().unwrap();
    match s.solve(&ContactOptions::default()) {
        Err(e) => {
            assert_eq!(e.status(), Status::Singular);
            assert!(
                e.message().contains("numerically singular"),
                "{}",
                e.message()
            );
        }
        Ok(_) => assert!(finite(&s)),
    }
}

#[test]
fn nearly_incompressible_bodies_give_finite_results() {
    for nu in [0.0, 0.3, 0.49, 0.4999] {
        let scene = TwoBlocks {
            nu1: nu,
            nu2: nu,
            ..base()
        };
        let mut s = scene.build().unwrap();
        let r = s.solve(&ContactOptions::default()).unwrap();
        assert!(finite(&s), "nu = {nu}");
        let load = scene.p * 2.0 * scene.c;
        assert!(
            (r.support_reaction - load).abs() <= 1e-8 * load,
            "nu = {nu}"
        );
    }
}

#[test]
fn interpenetration_scales_as_one_over_lambda() {
    // Penalty ≈ E_c λ / h²: the penetration times λ is constant once the
    // contact set has settled (λ ≫ h).
    let h = base().mesh_size;
    let pen: Vec<(f64, f64)> = [10.0, 100.0, 1e4, 1e6]
        .iter()
        .map(|&lh| {
            let mut s = base().build().unwrap();
            let r = s
                .solve(&ContactOptions {
                    lambda: Some(lh * h),
                    ..Default::default()
                })
                .unwrap();
            (lh * h, r.report.max_penetration)
        })
        .collect();
    let reference = pen[1].0 * pen[1].1;
    for (lambda, p) in &pen[1..] {
        assert!((lambda * p / reference - 1.0).abs() < 0.02, "{pen:?}");
    }
}

#[test]
fn the_model_scaled_by_1e_minus_6_and_1e6_gives_the_same_physical_answer() {
    let m = base();
    let (_, a) = {
        let mut s = m.build().unwrap();
        let r = s.solve(&ContactOptions::default()).unwrap();
        (s, r)
    };
    for k in [1e-6, 1e6] {
        let scaled = TwoBlocks {
            h1: m.h1 * k,
            h2: m.h2 * k,
            length: m.length * k,
            c: m.c * k,
            mesh_size: m.mesh_size * k,
            ..m
        };
        let mut s = scaled.build().unwrap();
        let r = s.solve(&ContactOptions::default()).unwrap();
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs());
        assert!(close(a.lc * k, r.lc), "scale {k}: {} vs {}", a.lc * k, r.lc);
        assert!(close(a.v_top * k, r.v_top), "scale {k}");
        assert!(close(a.gap_edge * k, r.gap_edge), "scale {k}");
    }
}

#[test]
fn a_tiny_initial_gap_changes_the_answer_by_about_the_gap() {
    let mut s0 = base().build().unwrap();
    let r0 = s0.solve(&ContactOptions::default()).unwrap();
    for gap in [1e-12, 1e-9] {
        let mut s = TwoBlocks { gap, ..base() }.build().unwrap();
        let r = s.solve(&ContactOptions::default()).unwrap();
        assert_eq!(r.lc, r0.lc, "gap {gap}");
        assert!(
            (r.v_top - r0.v_top).abs() <= 2.0 * gap + 1e-12 * r0.v_top.abs(),
            "gap {gap}: {} vs {}",
            r.v_top,
            r0.v_top
        );
    }
}

#[test]
fn bands_of_zero_tiny_and_negative_jacobians_stay_finite_and_accurate() {
    // Caps of height 0 (J = 0 exactly), 1e-300 and −1e-9 (inverted).
    for eps in [0.0, 1e-300, -1e-9] {
        let p = run_manufactured_laplace(unit_square(32, Some(eps)), 1.0 / 32.0, Tempering::Auto)
            .unwrap();
        assert!(p.l2.is_finite() && p.l2 < 2e-3, "eps {eps}: {p:?}");
    }
}
