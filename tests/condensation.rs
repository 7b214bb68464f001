//! The active-set loop condensed on the contact interface (one sparse
//! factorisation, dense interface updates) against the loop that
//! refactorises the whole matrix at every iteration: same iterations, same
//! active sets, same field to round-off, on every kind of interface.

use std::collections::BTreeSet;

use tfem::scenes::{TAG_LOAD, TwoBlocks};
use tfem::{Component, ContactLaw, ContactOptions, InversionTest, Model, Status};

struct Run {
    u: Vec<[f64; 2]>,
    active: Vec<bool>,
    iterations: usize,
    factorizations: usize,
    interface_unknowns: usize,
    residual: f64,
    condition: f64,
}

fn run(scene: &TwoBlocks, options: ContactOptions) -> Run {
    let mut s = scene.build().unwrap();
    let r = s.model.solve_contact(&options).unwrap();
    Run {
        u: s.model.displacements().unwrap(),
        active: s.model.contact_active().unwrap().to_vec(),
        iterations: r.iterations,
        factorizations: r.info.factorizations,
        interface_unknowns: r.info.interface_unknowns,
        residual: r.info.relative_residual,
        condition: r.info.condition_estimate,
    }
}

/// Runs both loops and checks they agree; returns the condensed run.
fn agree(scene: &TwoBlocks, options: ContactOptions) -> Run {
    let full = run(
        scene,
        ContactOptions {
            refactorize: true,
            ..options
        },
    );
    let cond = run(scene, options);
    assert_eq!(full.interface_unknowns, 0);
    assert_eq!(
        cond.iterations, full.iterations,
        "same number of iterations"
    );
    assert_eq!(cond.active, full.active, "same active set");
    assert_eq!(full.factorizations, full.iterations);
    let scale = full.u.iter().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
    let diff = full
        .u
        .iter()
        .flatten()
        .zip(cond.u.iter().flatten())
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    // Two solutions with relative residuals r₁, r₂ of a system of
    // condition κ differ by at most κ(r₁ + r₂) relatively (κ: the solver's
    // estimate of the scaled matrix, a lower bound, hence the factor 10).
    let bound = 10.0 * full.condition * (full.residual + cond.residual);
    eprintln!(
        "max |Δu| / max |u| = {:.2e}, bound {bound:.2e} (κ ≈ {:.1e}, residuals {:.1e}, {:.1e})",
        diff / scale,
        full.condition,
        full.residual,
        cond.residual
    );
    assert!(
        diff <= bound.min(1e-6) * scale,
        "max |Δu| = {diff:e} of {scale:e}"
    );
    cond
}

fn coarse() -> TwoBlocks {
    TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    }
}

/// Free components of the nodes of B.
fn contact_node_unknowns(model: &Model) -> (usize, usize) {
    let nodes: BTreeSet<usize> = model
        .contact_elements()
        .unwrap()
        .iter()
        .flat_map(|e| e.nodes)
        .collect();
    let fixed: BTreeSet<usize> = model.constraints().map(|(g, _)| g).collect();
    let free_y = nodes
        .iter()
        .filter(|&&n| !fixed.contains(&(2 * n + 1)))
        .count();
    let free = free_y + nodes.iter().filter(|&&n| !fixed.contains(&(2 * n))).count();
    (free_y, free)
}

#[test]
fn the_condensed_loop_factorises_once_and_matches_the_refactorising_loop() {
    let cond = agree(&coarse(), ContactOptions::default());
    assert_eq!(cond.factorizations, 1);
    assert!(cond.iterations >= 4, "a loop with several iterations");
}

#[test]
fn a_straight_touching_interface_condenses_only_the_normal_components() {
    let mut s = coarse().build().unwrap();
    let r = s.model.solve_contact(&ContactOptions::default()).unwrap();
    let (free_y, _) = contact_node_unknowns(&s.model);
    assert_eq!(r.info.interface_unknowns, free_y);
}

#[test]
fn the_literal_test_condenses_every_unknown_of_the_contact_nodes() {
    let options = ContactOptions {
        test: InversionTest::Literal,
        ..Default::default()
    };
    let cond = agree(&coarse(), options);
    let mut s = coarse().build().unwrap();
    s.model.solve_contact(&options).unwrap();
    assert_eq!(cond.interface_unknowns, contact_node_unknowns(&s.model).1);
}

#[test]
fn the_condensed_loop_matches_with_an_initial_gap() {
    let scene = TwoBlocks {
        gap: 1e-6,
        ..coarse()
    };
    let cond = agree(&scene, ContactOptions::default());
    assert_eq!(cond.factorizations, 1);
}

#[test]
fn the_condensed_loop_matches_under_the_stick_law() {
    agree(
        &coarse(),
        ContactOptions {
            law: ContactLaw::Stick,
            ..Default::default()
        },
    );
}

#[test]
fn the_condensed_loop_matches_on_a_non_matching_interface() {
    let scene = TwoBlocks {
        upper_mesh_size: Some(1.0 / 32.0 * 7.0 / 3.0),
        ..coarse()
    };
    let cond = agree(&scene, ContactOptions::default());
    assert_eq!(cond.factorizations, 1);
}

#[test]
fn the_condensed_loop_matches_with_a_stiffness_contrast_of_1e6() {
    let scene = TwoBlocks {
        e2: 1e16,
        ..coarse()
    };
    agree(&scene, ContactOptions::default());
}

#[test]
fn the_condensed_loop_matches_on_a_fine_mesh() {
    // Large enough for the supernodal factorisation (the extraction of the
    // trailing block differs from the simplicial one).
    let scene = TwoBlocks {
        mesh_size: 1.0 / 128.0,
        ..Default::default()
    };
    let cond = agree(&scene, ContactOptions::default());
    assert_eq!(cond.factorizations, 1);
}

#[test]
fn a_body_that_loses_all_contact_is_reported_singular_naming_it() {
    // Pulled away and held by nothing else: the first (bonded) iteration
    // is regular, the second has no active element, and the condensed
    // matrix detects the free body; the full factorisation then names it.
    let mut s = TwoBlocks {
        p: -1e7,
        ..coarse()
    }
    .build()
    .unwrap();
    let e = s
        .model
        .solve_contact(&ContactOptions::default())
        .unwrap_err();
    assert_eq!(e.status(), Status::Singular, "{}", e.message());
    assert!(
        e.message().contains("body 2") && e.message().contains("translation in y"),
        "{}",
        e.message()
    );
    // The model is unchanged: it still solves once held.
    s.model
        .fix_edges(TAG_LOAD, Component::Y, 1e-5)
        .expect("tag exists");
    let r = s.model.solve_contact(&ContactOptions::default()).unwrap();
    assert_eq!(r.active, 0);
}
