//! Friction on stiff and extreme cases (the stability rows rerun under
//! Coulomb friction): μ from 1e-6 to 1e6, stiffness contrasts to 1e9, a
//! thousand tiny load steps — every case solves to finite results with an
//! OK status, or says why.

use tfem::ContactOptions;
use tfem::scenes::{TwoBlocks, TwoBlocksScene};

fn seed(h: f64, mu: f64, e_ratio: f64) -> TwoBlocksScene {
    let base = TwoBlocks::default();
    TwoBlocks {
        c: 0.2,
        mesh_size: h,
        mu,
        e2: base.e1 * e_ratio,
        ..base
    }
    .build()
    .unwrap()
}

fn displacements(scene: &TwoBlocksScene) -> Vec<f64> {
    let u = scene.model.displacements().unwrap();
    u.iter().flat_map(|d| *d).collect()
}

/// max |a − b| / max |b|.
fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let max = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0, |m: f64, x| m.max(x.abs()));
    max(&mut a.iter().zip(b).map(|(x, y)| x - y)) / max(&mut b.iter().copied())
}

/// Displacements, contact forces and nodal tractions are finite.
fn finite_results(scene: &TwoBlocksScene) -> bool {
    let m = &scene.model;
    displacements(scene).iter().all(|x| x.is_finite())
        && m.contact_forces()
            .unwrap()
            .iter()
            .flatten()
            .all(|x| x.is_finite())
        && (m.contact_nodal_tractions().unwrap().iter())
            .flatten()
            .all(|x| x.is_finite())
}

#[test]
fn every_friction_coefficient_from_1e_minus_6_to_1e6_solves_to_finite_results() {
    // Measured against the frictionless solve (max |Δu|/max |u|): 1.40e-6,
    // 1.40e-3 for μ = 1e-6, 1e-3 (linear in μ), 0.284, 0.340 for 0.3, 1,
    // 0.346 for 1e3 and 1e6 alike (the interface tied).
    let options = ContactOptions::default();
    let mut frictionless = seed(1.0 / 16.0, 0.0, 10.0);
    frictionless.model.solve_contact(&options).unwrap();
    let u0 = displacements(&frictionless);
    let mut tied = Vec::new();
    for mu in [1e-6, 1e-3, 0.3, 1.0, 1e3, 1e6] {
        let mut s = seed(1.0 / 16.0, mu, 10.0);
        if let Err(e) = s.model.solve_contact(&options) {
            panic!("μ = {mu}: {e}");
        }
        assert!(finite_results(&s), "μ = {mu}");
        let d = relative_difference(&displacements(&s), &u0);
        if mu <= 1e-3 {
            assert!(d <= 2e-3 * mu / 1e-3, "μ = {mu}: {d:e} from frictionless");
        }
        if mu >= 1e3 {
            tied.push(displacements(&s));
        }
    }
    let d = relative_difference(&tied[1], &tied[0]);
    assert!(d <= 1e-9, "μ = 1e6 against 1e3: {d:e}");
}

#[test]
fn stiffness_contrasts_to_1e9_under_friction_solve_to_finite_results() {
    let options = ContactOptions::default();
    for ratio in [1.0, 1e3, 1e6, 1e9] {
        let mut s = seed(1.0 / 16.0, 0.3, ratio);
        if let Err(e) = s.model.solve_contact(&options) {
            panic!("E2/E1 = {ratio}: {e}");
        }
        assert!(finite_results(&s), "E2/E1 = {ratio}");
    }
}

#[test]
fn a_thousand_tiny_frictional_steps_reach_the_one_step_answer() {
    // A proportional load on the seed's closed interface: the steps' path
    // is the one step's (measured: the same displacements to the bit).
    let options = ContactOptions::default();
    let mut one = seed(1.0 / 8.0, 0.3, 10.0);
    one.model.step(1.0, &options).unwrap();
    let mut many = seed(1.0 / 8.0, 0.3, 10.0);
    for k in 1..=1000 {
        let factor = k as f64 / 1000.0;
        if let Err(e) = many.model.step(factor, &options) {
            panic!("step {k}: {e}");
        }
    }
    assert!(finite_results(&many));
    let d = relative_difference(&displacements(&many), &displacements(&one));
    assert!(d <= 1e-9, "{d:e}");
}
