//! Coulomb friction in the contact elements (docs/method.md §6.15), checked
//! on the seed scene: μ = 0 is the frictionless solve bit for bit, a huge μ
//! ties the interface like the stick law, every element obeys Coulomb's law
//! and dissipates nothing negative, the independent node-to-node frictional
//! oracle on the same mesh agrees more closely as h shrinks, the outputs
//! converge with h, and load histories stay exact (one factorisation,
//! revert).

use tfem::oracle::frictional::{FrictionalOracle, LoadCase};
use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TwoBlocks, TwoBlocksScene};
use tfem::verification::fitted_rate;
use tfem::{ContactLaw, ContactOptions};

/// The seed scene at 2C/L = 0.4 (the main width) with friction μ.
fn seed(h: f64, mu: f64) -> TwoBlocksScene {
    TwoBlocks {
        c: 0.2,
        mesh_size: h,
        mu,
        ..TwoBlocks::default()
    }
    .build()
    .unwrap()
}

fn displacements(scene: &TwoBlocksScene) -> Vec<f64> {
    let u = scene.model.displacements().unwrap();
    u.iter().flat_map(|d| *d).collect()
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// max |a − b| / max |b|.
fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let d: Vec<f64> = a.iter().zip(b).map(|(x, y)| x - y).collect();
    max_abs(&d) / max_abs(b)
}

#[test]
fn a_friction_coefficient_set_back_to_zero_gives_the_frictionless_solve_bit_for_bit() {
    let mut plain = seed(1.0 / 32.0, 0.0);
    plain
        .model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    let mut back = seed(1.0 / 32.0, 0.3);
    back.model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    back.model.set_friction(0, 0.0).unwrap();
    back.model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    let (a, b) = (displacements(&plain), displacements(&back));
    assert!(a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()));
    assert_eq!(
        plain.model.contact_pressure().unwrap(),
        back.model.contact_pressure().unwrap()
    );
    assert!(
        back.model
            .contact_shear()
            .unwrap()
            .iter()
            .all(|&t| t == 0.0)
    );
}

#[test]
fn a_huge_friction_coefficient_ties_the_interface_like_the_stick_law_as_the_penalty_stiffens() {
    // Both tie the surfaces; they differ only in the normal penalty's
    // modulus (E_c under friction, the isotropic λ + 2G of the stick law),
    // an O(1/λ) difference: ten times λ, about ten times closer.
    let difference = |lambda: f64| {
        let options = ContactOptions {
            lambda: Some(lambda),
            ..Default::default()
        };
        let mut tied = seed(1.0 / 32.0, 1e6);
        tied.model.solve_contact(&options).unwrap();
        assert!(
            tied.model
                .contact_friction_state()
                .unwrap()
                .iter()
                .all(|&s| s != 2),
            "nothing slips at μ = 1e6"
        );
        let mut stick = seed(1.0 / 32.0, 0.0);
        let stick_law = ContactOptions {
            law: ContactLaw::Stick,
            ..options
        };
        stick.model.solve_contact(&stick_law).unwrap();
        relative_difference(&displacements(&tied), &displacements(&stick))
    };
    let (coarse, stiff) = (difference(1.0), difference(10.0));
    assert!(coarse < 5e-2, "{coarse:e}");
    assert!(coarse / stiff > 5.0, "{coarse:e} → {stiff:e}");
}

#[test]
fn every_element_obeys_coulombs_law_and_no_step_dissipates_negatively() {
    // Loaded to p, to 2p, back to p: the unloading reverses slip.
    for mu in [0.1, 0.3, 1.0] {
        let mut scene = seed(1.0 / 32.0, mu);
        let mut slip_dissipated = 0.0;
        let mut slip_edges = Vec::new();
        for t in [1.0, 2.0, 1.0] {
            scene.model.step(t, &ContactOptions::default()).unwrap();
            let p = scene.model.contact_pressure().unwrap().to_vec();
            let tau = scene.model.contact_shear().unwrap();
            let state = scene.model.contact_friction_state().unwrap();
            let d = scene.model.contact_dissipation().unwrap();
            for k in 0..p.len() {
                let limit = mu * p[k];
                match state[k] {
                    0 => assert_eq!((tau[k], p[k]), (0.0, 0.0)),
                    // Round-off of the interface solve: 1e-9 of μp.
                    1 => assert!(tau[k].abs() <= limit * (1.0 + 1e-9), "stick {k}"),
                    _ => assert!((tau[k].abs() - limit).abs() <= 1e-9 * limit, "slip {k}"),
                }
                assert!(
                    d[k] >= 0.0,
                    "μ = {mu}, t = {t}: element {k} dissipates {}",
                    d[k]
                );
            }
            slip_dissipated += d.iter().sum::<f64>();
            let u = scene.model.displacements().unwrap();
            slip_edges.push(u[scene.corner_upper][0] - u[scene.corner_lower][0]);
        }
        assert!(slip_dissipated > 0.0);
        // Path dependence: back at p after 2p, the edge has not slid back.
        let (first, last) = (slip_edges[0], slip_edges[2]);
        assert!(
            (first - last).abs() > 1e-3 * first.abs(),
            "μ = {mu}: {first:e} and {last:e}"
        );
    }
}

/// The slip and gap at the corner (0, 0) by TFEM and by the frictional
/// oracle (node-to-node multipliers, exact Coulomb) on the same mesh.
fn tfem_and_oracle(h: f64, mu: f64) -> ([f64; 2], [f64; 2]) {
    let mut scene = seed(h, mu);
    let oracle = FrictionalOracle::new(&scene.model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    let loads = LoadCase::of(&scene.model).unwrap();
    let step = oracle.step(mu, None, &loads).unwrap();
    scene
        .model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    let u = scene.model.displacements().unwrap();
    let (lo, up) = (scene.corner_lower, scene.corner_upper);
    let ours = [u[up][0] - u[lo][0], u[up][1] - u[lo][1]];
    let theirs = [
        step.u[2 * up] - step.u[2 * lo],
        step.u[2 * up + 1] - step.u[2 * lo + 1],
    ];
    (ours, theirs)
}

#[test]
fn the_independent_frictional_oracle_agrees_ever_closer_as_h_shrinks() {
    // TFEM's penalty lets the surfaces slide and sink by O(h²)/λ where the
    // oracle's multipliers do not: the difference must shrink with h.
    let hs = [1.0 / 16.0, 1.0 / 32.0, 1.0 / 64.0];
    for mu in [0.1, 0.3] {
        let mut slip = Vec::new();
        for &h in &hs {
            let (ours, theirs) = tfem_and_oracle(h, mu);
            slip.push((ours[0] - theirs[0]).abs() / theirs[0].abs());
        }
        let rate = fitted_rate(&hs, &slip);
        assert!(slip[2] < 2e-2, "μ = {mu}: {slip:?}");
        assert!(
            rate > 0.9,
            "μ = {mu}: slip differences {slip:?}, rate {rate}"
        );
    }
}

#[test]
fn the_seed_outputs_converge_with_h_under_friction() {
    // Differences of successive halvings (no reference exists for the
    // frictional scene): each output settles at least at first order.
    let hs = [1.0 / 16.0, 1.0 / 32.0, 1.0 / 64.0, 1.0 / 128.0];
    let outputs: Vec<[f64; 3]> = hs
        .iter()
        .map(|&h| {
            let mut scene = seed(h, 0.3);
            let r = scene.solve(&ContactOptions::default()).unwrap();
            [r.gap_edge, r.v_top, r.slip_edge]
        })
        .collect();
    for (q, name) in ["gap_edge", "v_top", "slip_edge"].iter().enumerate() {
        let d: Vec<f64> = outputs
            .windows(2)
            .map(|w| (w[1][q] - w[0][q]).abs())
            .collect();
        let rate = fitted_rate(&hs[1..], &d);
        assert!(rate > 0.8, "{name}: differences {d:?}, rate {rate}");
    }
}

#[test]
fn proportional_steps_cost_one_factorisation_and_reach_the_one_step_answer() {
    // Measured: under proportional loading the slip zone only grows, and
    // 1, 4 and 10 steps end in the same state to round-off.
    let mut once = seed(1.0 / 32.0, 0.3);
    once.model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    let reference = displacements(&once);
    for n in [4, 10] {
        let mut scene = seed(1.0 / 32.0, 0.3);
        let mut factorisations = 0;
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let r = scene.model.step(t, &ContactOptions::default()).unwrap();
            factorisations += r.info.factorizations;
        }
        assert_eq!(factorisations, 1);
        let d = relative_difference(&displacements(&scene), &reference);
        assert!(d < 1e-9, "{n} steps: {d:e}");
    }
}

#[test]
fn reverting_a_frictional_step_restores_its_slip_state_bit_for_bit() {
    let mut scene = seed(1.0 / 32.0, 0.3);
    let options = ContactOptions::default();
    scene.model.step(1.0, &options).unwrap();
    scene.model.step(2.0, &options).unwrap();
    let after = displacements(&scene);
    scene.model.revert_step().unwrap();
    scene.model.step(0.5, &options).unwrap();
    scene.model.revert_step().unwrap();
    scene.model.step(2.0, &options).unwrap();
    let again = displacements(&scene);
    assert!(
        after
            .iter()
            .zip(&again)
            .all(|(a, b)| a.to_bits() == b.to_bits())
    );
}

#[test]
fn each_proportional_step_after_the_first_settles_in_one_iteration() {
    // The slip loads are implicit in the condensed solve: a step whose
    // stick/slip state does not change is one solve, as without friction.
    for mu in [0.1, 0.3, 1.0] {
        let mut scene = seed(1.0 / 64.0, mu);
        for k in 1..=10 {
            let r = scene
                .model
                .step(k as f64 / 10.0, &ContactOptions::default())
                .unwrap();
            if k > 1 {
                assert_eq!(r.iterations, 1, "μ = {mu}, step {k}");
            }
        }
    }
}

#[test]
fn a_step_that_repeats_the_last_loads_settles_at_once_without_slip() {
    // Zero slip and |τ| = μp exactly: round-off must not switch the slip
    // zone between stick and slip (it cycled before the switch tolerance).
    let mut scene = seed(1.0 / 32.0, 0.3);
    scene.model.step(1.0, &ContactOptions::default()).unwrap();
    let before = displacements(&scene);
    let r = scene.model.step(1.0, &ContactOptions::default()).unwrap();
    assert_eq!(r.iterations, 1);
    let d = relative_difference(&displacements(&scene), &before);
    assert!(d < 1e-9, "{d:e}");
    let slip_energy: f64 = scene.model.contact_dissipation().unwrap().iter().sum();
    assert!(slip_energy.abs() < 1e-12, "{slip_energy:e}");
}

#[test]
fn unloading_from_twice_the_load_at_mu_one_settles_with_positive_dissipation() {
    // It cycled before (docs/method.md §6.15): an edge element opened while
    // its neighbours stuck and closed again sticking, with the shear of the
    // slip its nodes made while it was open, which opened it again. Closing
    // again, it now slips along that shear.
    for h in [1.0 / 64.0, 1.0 / 256.0] {
        let mut s = seed(h, 1.0);
        let options = ContactOptions::default();
        let mut slip = Vec::new();
        for t in [1.0, 2.0, 1.0] {
            let report = s.model.step(t, &options).unwrap();
            slip.push(s.measure(report).unwrap().slip_edge);
        }
        let d: Vec<f64> = s.model.contact_dissipation().unwrap();
        assert!(d.iter().all(|&v| v >= 0.0));
        // Measured: the unloading step dissipates 0.10 (h = 1/64) and 0.083
        // J/m (1/256), and leaves the corner slid by 1.26 and 1.24 times
        // its first-step value (path dependence).
        let total: f64 = d.iter().sum();
        assert!(total > 0.05, "h = {h}: dissipation {total}");
        assert!(slip[2] > 1.1 * slip[0], "h = {h}: slip_edge {slip:?}");
    }
}
