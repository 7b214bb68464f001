//! Normal and tangential load together (docs/method.md §6.15): a cylinder
//! pressed on a block of the same material by a rigid platen moved along
//! (δₜ, −δₙ) proportionally, μ = 0.3. With Dundurs' β = 0 and Q/P < μ,
//! Mindlin's answer for proportional loading is no slip anywhere and a
//! shear traction proportional to the pressure, q(x) = (Q/P)·p(x)
//! (Johnson, *Contact Mechanics*, §7.1: each point that comes into contact
//! sticks with the ratio of the load increments, which is Q/P throughout).
//! Contact forms along the load: each element of B that closes sticks
//! from where it closed, which a load step locates by sub-steps, so that
//! one step, five or a hundred give one answer.

use tfem::ContactOptions;
use tfem::scenes::cattaneo::{CattaneoMindlin, TAG_BLOCK_TOP};
use tfem::verification::fitted_rate;

/// The block's top nodes' tractions after the platen moved to
/// (`ratio`·δₙ, −δₙ) in `steps` equal load steps, h = a/`k`.
struct Run {
    /// Q/P of the contact forces.
    q_over_p: f64,
    /// μp₀ (p₀ the largest nodal pressure).
    mu_p0: f64,
    /// Per block top node (by x): pressure and shear along +x.
    tractions: Vec<(f64, f64)>,
    /// Elements of B slipping at the end.
    slipping: usize,
}

fn proportional(k: f64, ratio: f64, steps: usize) -> Run {
    loaded(k, ratio, Some(steps))
}

/// As [`proportional`], by one contact solve instead of load steps when
/// `steps` is `None`.
fn loaded(k: f64, ratio: f64, steps: Option<usize>) -> Run {
    let base = CattaneoMindlin::default();
    let cm = CattaneoMindlin {
        mesh_size: base.half_width / k,
        ..base
    };
    let mut scene = cm.build().expect("scene");
    let m = &mut scene.model;
    m.set_friction(0, cm.mu).expect("friction");
    let dn = scene.load / cm.e_star();
    for &v in &scene.platen {
        m.set_prescribed(v, tfem::Component::X, ratio * dn).unwrap();
        m.set_prescribed(v, tfem::Component::Y, -dn).unwrap();
    }
    match steps {
        Some(steps) => {
            for i in 1..=steps {
                if let Err(e) = m.step(i as f64 / steps as f64, &ContactOptions::default()) {
                    panic!("{steps} steps, step {i}: {e}");
                }
            }
        }
        None => {
            m.solve_contact(&ContactOptions::default()).expect("solve");
        }
    }
    let block_top = tfem::scenes::nodes_by_x(m.mesh().unwrap(), TAG_BLOCK_TOP);
    let f = m.contact_forces().unwrap();
    let (p, q) = block_top
        .iter()
        .fold((0.0, 0.0), |(p, q), &v| (p - f[v][1], q + f[v][0]));
    let t = m.contact_nodal_tractions().unwrap();
    // The block's tangent runs along −x on its top (outward normal +y).
    let tractions: Vec<(f64, f64)> = block_top.iter().map(|&v| (t[v][0], -t[v][1])).collect();
    let p0 = tractions.iter().map(|r| r.0).fold(0.0, f64::max);
    let states = m.contact_friction_state().unwrap();
    Run {
        q_over_p: q / p,
        mu_p0: cm.mu * p0,
        tractions,
        slipping: states.iter().filter(|&&s| s == 2).count(),
    }
}

/// ‖q − (Q/P)p‖ / ‖(Q/P)p‖ over the block's top nodes: how far the shear
/// is from Mindlin's proportional answer.
fn off_proportional(run: &Run) -> f64 {
    let (mut off, mut size) = (0.0, 0.0);
    for &(p, q) in &run.tractions {
        off += (q - run.q_over_p * p).powi(2);
        size += (run.q_over_p * p).powi(2);
    }
    (off / size).sqrt()
}

/// max |q_a − q_b| / (μp₀) over the block's top nodes.
fn shear_difference(a: &Run, b: &Run) -> f64 {
    a.tractions
        .iter()
        .zip(&b.tractions)
        .map(|(x, y)| (x.1 - y.1).abs() / a.mu_p0)
        .fold(0.0, f64::max)
}

/// The platen's sideways move per unit of its normal move, for Q/P = 0.107
/// < μ (measured).
const STICKING: f64 = 0.15;

#[test]
fn one_step_of_a_proportional_load_sticks_everywhere() {
    let run = proportional(32.0, STICKING, 1);
    assert_eq!(run.slipping, 0);
    assert!(
        run.q_over_p > 0.1 && run.q_over_p < 0.3,
        "Q/P = {}",
        run.q_over_p
    );
}

#[test]
fn one_five_twenty_and_a_hundred_steps_give_one_shear() {
    // Measured: 3.3e-6, 6.4e-7, 1.3e-7 μp₀ from the hundred steps' (a/16);
    // before sub-steps, 0.98, 0.31, 0.13 of the cylinder.
    let runs: Vec<Run> = [1, 5, 20, 100]
        .iter()
        .map(|&n| proportional(16.0, STICKING, n))
        .collect();
    for (n, run) in [1, 5, 20].iter().zip(&runs) {
        let d = shear_difference(run, &runs[3]);
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
        .map(|&k| off_proportional(&proportional(k, STICKING, 1)))
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
        let run = proportional(16.0, 1.0, steps);
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
    let (solve, step) = (
        loaded(16.0, STICKING, None),
        proportional(16.0, STICKING, 1),
    );
    // The solve settles from the step's state with a factorisation of its
    // own: measured 1.6e-8 μp₀ apart.
    let d = shear_difference(&solve, &step);
    assert!(d <= 1e-6, "{d:.3e} μp₀");
    assert_eq!(solve.slipping, 0);
}
