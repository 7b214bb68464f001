//! Normal and tangential load together (docs/method.md §6.15): a cylinder
//! pressed on a block of the same material by a rigid platen moved along
//! (δₜ, −δₙ) proportionally, μ = 0.3 (`scenes::cattaneo`,
//! `CattaneoScene::combined`). With Dundurs' β = 0 and Q/P < μ, Mindlin's
//! answer for proportional loading is no slip anywhere and a shear traction
//! proportional to the pressure, q(x) = (Q/P)·p(x) (Johnson, *Contact
//! Mechanics*, §7.1: each point that comes into contact sticks with the
//! ratio of the load increments). Contact forms along the load: each
//! element of B that closes sticks from where it closed, which a load step
//! locates by sub-steps, so that one step, five or a hundred give one
//! answer.

use tfem::scenes::cattaneo::{CattaneoMindlin, CombinedLoad, CombinedResult};
use tfem::verification::fitted_rate;

/// The platen's sideways move per unit of its normal move, for Q/P = 0.107
/// < μ (measured).
const STICKING: f64 = 0.15;

/// The scene at h = a/`k` under `load`.
fn combined(k: f64, ratio: f64, steps: usize) -> CombinedResult {
    let base = CattaneoMindlin::default();
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / k,
        ..base
    };
    let mut scene = cm.build().expect("scene");
    match scene.combined(&cm, CombinedLoad { ratio, steps }) {
        Ok(result) => result,
        Err(e) => panic!("a/{k}, ratio {ratio}, {steps} steps: {e}"),
    }
}

#[test]
fn one_step_of_a_proportional_load_sticks_everywhere() {
    let run = combined(32.0, STICKING, 1);
    assert_eq!(run.slipping, 0);
    assert!(
        run.q_over_p > 0.1 && run.q_over_p < 0.3,
        "Q/P = {}",
        run.q_over_p
    );
}

#[test]
fn one_five_twenty_and_a_hundred_steps_give_one_shear() {
    // Measured: 3.3e-6, 6.4e-7, 1.3e-7 μp₀ from the hundred steps' (a/16).
    let runs: Vec<CombinedResult> = [1, 5, 20, 100]
        .iter()
        .map(|&n| combined(16.0, STICKING, n))
        .collect();
    for (n, run) in [1, 5, 20].iter().zip(&runs) {
        let d = run.shear_difference(&runs[3]);
        assert!(d <= 1e-3, "{n} steps: {d:.3e} μp₀ from a hundred's");
    }
}

#[test]
fn the_shear_of_one_step_converges_to_mindlins_proportional_traction() {
    // Measured ‖q − (Q/P)p‖/‖(Q/P)p‖: 0.214, 0.130, 0.070 at a/16, 32, 64
    // (rate 0.8: the edges of the contact zone, where p and q vanish, are
    // resolved to first order).
    let ks = [16.0, 32.0, 64.0];
    let off: Vec<f64> = ks
        .iter()
        .map(|&k| combined(k, STICKING, 1).off_proportional())
        .collect();
    let h: Vec<f64> = ks.iter().map(|k| 1.0 / k).collect();
    let rate = fitted_rate(&h, &off);
    assert!(rate > 0.6, "rate {rate:.2} ({off:.3?})");
    assert!(off[2] < 0.08, "{off:.3?}");
}

#[test]
fn a_shear_beyond_mu_slides_at_mu_p_in_one_step() {
    let mu = CattaneoMindlin::default().mu;
    for steps in [1, 5] {
        let run = combined(16.0, 1.0, steps);
        assert!(
            (run.q_over_p - mu).abs() <= 1e-9 * mu,
            "{steps} steps: Q/P = {}",
            run.q_over_p
        );
        assert!(run.slipping > 0);
    }
}

#[test]
fn a_contact_solve_gives_the_one_step_history() {
    let (solve, step) = (combined(16.0, STICKING, 0), combined(16.0, STICKING, 1));
    // The solve settles from the step's state with a factorisation of its
    // own: measured 1.6e-8 μp₀ apart.
    let d = solve.shear_difference(&step);
    assert!(d <= 1e-6, "{d:.3e} μp₀");
    assert_eq!(solve.slipping, 0);
}

#[test]
fn a_frictional_history_unloads_to_nothing_in_bounded_sub_steps() {
    // Unloading to zero passes through no contact at all: the warm start
    // leads nowhere, sub-steps halve, and the rest of the step is then
    // tried from the initial set once, as a step of its own would be.
    let base = CattaneoMindlin::default();
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / 16.0,
        ..base
    };
    let mut scene = cm.build().expect("scene");
    let load = CombinedLoad {
        ratio: STICKING,
        steps: 1,
    };
    scene.combined(&cm, load).expect("loaded");
    let report = scene
        .model
        .step(0.0, &tfem::ContactOptions::default())
        .expect("unloaded");
    assert!(
        report.iterations < 10_000,
        "{} iterations",
        report.iterations
    );
    let f = scene.model.contact_forces().expect("forces");
    let largest = f.iter().map(|v| v[0].hypot(v[1])).fold(0.0, f64::max);
    assert_eq!(largest, 0.0);
}
