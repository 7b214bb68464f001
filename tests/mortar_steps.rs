//! Load steps under the mortar weighting (`Model::step` with
//! `ContactWeighting::Mortar`, docs/method.md §6.11): each step is the
//! contact solve of its scaled loads, warm-started from the step before,
//! and one factorisation serves the history while the stiffness and the
//! options are unchanged.

use tfem::scenes::TwoBlocks;
use tfem::scenes::hertz::{Hertz, TAG_LOAD};
use tfem::{Component, ContactOptions, ContactWeighting, Model, Status};

/// The Hertz scene at h = a/8, its cylinder 100× stiffer and meshed 2.5×
/// coarser (a non-matching interface read from the cylinder), under the
/// mortar weighting: the contact grows with the load.
fn hertz() -> Model {
    let hz = Hertz {
        mesh_size: 0.02 / 8.0,
        cylinder_mesh_ratio: 2.5,
        e_cylinder: 2e13,
        ..Hertz::default()
    };
    let mut model = hz.build().unwrap().model;
    model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    model
}

/// The seed's two blocks, the upper meshed 7/3 as coarse (no interface
/// node lines up) and lifted by `gap`, under the mortar weighting.
fn blocks(p: f64, gap: f64) -> Model {
    let mut model = TwoBlocks {
        c: 0.2,
        p,
        gap,
        mesh_size: 1.0 / 24.0,
        upper_mesh_size: Some(7.0 / 72.0),
        ..Default::default()
    }
    .build()
    .unwrap()
    .model;
    model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    model
}

/// The largest difference of `a` and `b`, over the largest |b|.
fn relative_difference(a: &[[f64; 2]], b: &[[f64; 2]]) -> f64 {
    let (a, b) = (a.as_flattened(), b.as_flattened());
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let diff = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    diff / scale
}

/// The largest difference of two models' displacements, over the second's
/// largest.
fn field_difference(a: &Model, b: &Model) -> f64 {
    relative_difference(&a.displacements().unwrap(), &b.displacements().unwrap())
}

fn active_nodes(model: &Model) -> Vec<bool> {
    let nodes = model.contact_slave_nodes().unwrap();
    nodes.iter().map(|n| n.active).collect()
}

fn bits(model: &Model) -> Vec<u64> {
    let u = model.displacements().unwrap();
    u.iter().flatten().map(|v| v.to_bits()).collect()
}

#[test]
fn a_mortar_history_ends_at_the_one_solve_answer_with_one_factorisation() {
    let options = ContactOptions::default();
    let mut one = hertz();
    one.solve_contact(&options).unwrap();
    let mut model = hertz();
    let (mut factorisations, mut actives) = (0, Vec::new());
    for k in 1..=10 {
        let report = model.step(k as f64 / 10.0, &options).unwrap();
        factorisations += report.info.factorizations;
        actives.push(report.active);
    }
    assert_eq!(factorisations, 1, "the first step's K₁ serves the history");
    assert!(
        actives.windows(2).all(|w| w[0] <= w[1]) && actives[0] < actives[9],
        "the contact grows with the load: {actives:?}"
    );
    let d = field_difference(&model, &one);
    assert!(d < 1e-10, "{d:e}");
    assert_eq!(active_nodes(&model), active_nodes(&one));
}

/// [`hertz`] with its loads scaled by `t` (as nodal forces).
fn scaled_hertz(t: f64) -> Model {
    let mut model = hertz();
    let f = model.load_vector().unwrap();
    model.clear_loads();
    for (v, fv) in f.chunks(2).enumerate().filter(|(_, f)| f != &[0.0, 0.0]) {
        model.add_nodal_force(v, [t * fv[0], t * fv[1]]).unwrap();
    }
    model
}

#[test]
fn a_mortar_step_is_the_contact_solve_of_its_scaled_loads() {
    let options = ContactOptions::default();
    let mut model = hertz();
    for t in [0.2, 1.0, 0.5] {
        let report = model.step(t, &options).unwrap();
        let mut fresh = scaled_hertz(t);
        fresh.solve_contact(&options).unwrap();
        let d = field_difference(&model, &fresh);
        assert!(d < 1e-10, "t = {t}: {d:e}");
        let first = t == 0.2;
        assert_eq!(report.info.factorizations, usize::from(first), "t = {t}");
        assert_eq!(active_nodes(&model), active_nodes(&fresh), "t = {t}");
    }
}

#[test]
fn a_step_scales_the_prescribed_displacements_too() {
    // The cylinder pushed down by a prescribed motion of its centre line
    // instead of its load: the step at t is the solve at t times it.
    let options = ContactOptions::default();
    let pushed = |depth: f64| {
        let mut model = hertz();
        model.clear_loads();
        let centre = centre_nodes(&model);
        for &v in &centre {
            model.fix(v, Component::Y, -depth).unwrap();
        }
        model
    };
    let mut model = pushed(2e-4);
    model.step(1.0, &options).unwrap();
    model.step(0.5, &options).unwrap();
    let mut fresh = pushed(1e-4);
    fresh.solve_contact(&options).unwrap();
    let d = field_difference(&model, &fresh);
    assert!(d < 1e-10, "{d:e}");
    assert!(model.contact_report().unwrap().active > 0);
}

/// The nodes of the Hertz cylinder's loaded centre line.
fn centre_nodes(model: &Model) -> Vec<usize> {
    let mesh = model.mesh().unwrap();
    let mut nodes: Vec<usize> = mesh
        .boundary_edges()
        .iter()
        .filter(|e| e.tag == TAG_LOAD)
        .flat_map(|e| e.nodes)
        .collect();
    nodes.sort_unstable();
    nodes.dedup();
    nodes
}

#[test]
fn new_loads_between_mortar_steps_cost_no_factorisation() {
    let options = ContactOptions::default();
    let mut model = blocks(1e7, 2e-4);
    model.step(1.0, &options).unwrap();
    model.clear_loads();
    model.add_pressure(tfem::scenes::TAG_LOAD, 2.5e7).unwrap();
    let report = model.step(1.0, &options).unwrap();
    assert_eq!(report.info.factorizations, 0, "the stiffness is the same");
    let mut fresh = blocks(2.5e7, 2e-4);
    fresh.solve_contact(&options).unwrap();
    let d = field_difference(&model, &fresh);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn new_options_or_materials_start_a_new_factor() {
    let options = ContactOptions::default();
    let mut model = blocks(1e7, 0.0);
    model.step(0.5, &options).unwrap();
    let other = ContactOptions {
        lambda: Some(0.5),
        ..options
    };
    assert_eq!(model.step(1.0, &other).unwrap().info.factorizations, 1);
    assert_eq!(model.step(1.0, &other).unwrap().info.factorizations, 0);
    let stiffer = tfem::Material::new(4e11, 0.3, tfem::PlaneMode::Strain, "stiffer").unwrap();
    model.set_material(2, stiffer).unwrap();
    assert_eq!(model.step(1.0, &other).unwrap().info.factorizations, 1);
}

#[test]
fn a_refactorising_history_ends_at_the_same_answer() {
    let mut one = hertz();
    one.solve_contact(&ContactOptions::default()).unwrap();
    let options = ContactOptions {
        refactorize: true,
        ..ContactOptions::default()
    };
    let mut model = hertz();
    for k in 1..=4 {
        let report = model.step(k as f64 / 4.0, &options).unwrap();
        assert_eq!(
            report.info.factorizations, report.iterations,
            "one factorisation per iteration"
        );
    }
    let d = field_difference(&model, &one);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn a_reverted_mortar_step_brings_back_its_results_and_the_next_step_repeats_to_the_bit() {
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.3, &options).unwrap();
    let first = bits(&model);
    model.step(1.0, &options).unwrap();
    let second = bits(&model);
    model.revert_step().unwrap();
    assert_eq!(bits(&model), first);
    let again = model.revert_step().unwrap_err();
    assert_eq!(again.status(), Status::InvalidState);
    model.step(1.0, &options).unwrap();
    assert_eq!(bits(&model), second);
}

#[test]
fn a_solve_between_steps_ends_the_history() {
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.5, &options).unwrap();
    model.solve_contact(&options).unwrap();
    let report = model.step(0.5, &options).unwrap();
    assert_eq!(
        report.info.factorizations, 1,
        "a solve refactorises: K₁ gone"
    );
}

#[test]
fn a_mortar_contact_state_continues_bit_for_bit_in_a_new_model() {
    let options = ContactOptions::default();
    let mut model = hertz();
    for t in [0.3, 0.6] {
        model.step(t, &options).unwrap();
    }
    let state = model.contact_state().unwrap();
    model.step(1.0, &options).unwrap();
    let expected = bits(&model);
    let report = model.contact_report().unwrap().clone();
    let mut other = hertz();
    other.set_contact_state(&state).unwrap();
    let again = other.step(1.0, &options).unwrap();
    assert_eq!(bits(&other), expected);
    assert_eq!(again.active, report.active);
    assert_eq!(again.info.factorizations, 1, "the new model's own K₁");
}

#[test]
fn a_strip_contact_state_is_refused_by_a_mortar_model_and_changes_nothing() {
    let options = ContactOptions::default();
    let mut strip = hertz();
    strip
        .set_contact_weighting(tfem::ContactWeighting::Strip)
        .unwrap();
    strip.step(0.5, &options).unwrap();
    let state = strip.contact_state().unwrap();
    let mut model = hertz();
    model.step(0.5, &options).unwrap();
    let before = bits(&model);
    let e = model.set_contact_state(&state).unwrap_err();
    assert_eq!(e.status(), Status::InvalidArgument);
    assert!(
        e.message().contains("another contact mesh"),
        "{}",
        e.message()
    );
    assert_eq!(bits(&model), before);
}

#[test]
fn friction_is_refused_in_a_mortar_history_and_the_history_goes_on() {
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.5, &options).unwrap();
    let before = bits(&model);
    let e = model.set_friction(0, 0.3).unwrap_err();
    assert!(e.message().contains("friction"), "{}", e.message());
    // The refusal changed nothing: the history's next step is taken.
    model.step(1.0, &options).unwrap();
    model.revert_step().unwrap();
    assert_eq!(
        bits(&model),
        before,
        "the revert returns to the step before"
    );
}

#[test]
fn a_load_factor_that_is_not_finite_is_refused() {
    let mut model = hertz();
    for t in [f64::NAN, f64::INFINITY, 1e301] {
        let e = model.step(t, &ContactOptions::default()).unwrap_err();
        assert_eq!(e.status(), Status::InvalidArgument, "{t}");
    }
    assert!(model.displacements().is_err(), "nothing was solved");
}

#[test]
fn a_failed_mortar_step_changes_nothing_and_the_history_goes_on() {
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.2, &options).unwrap();
    let before = bits(&model);
    let short = ContactOptions {
        max_iterations: 1,
        ..options
    };
    let e = model.step(1.0, &short).unwrap_err();
    assert_eq!(e.status(), Status::NotConverged, "{}", e.message());
    assert_eq!(bits(&model), before, "the results are the last step's");
    model.revert_step().unwrap();
    assert!(
        model.displacements().is_err(),
        "the step reverted is still the one before the failure"
    );
    let mut one = hertz();
    one.solve_contact(&options).unwrap();
    let report = model.step(1.0, &options).unwrap();
    assert_eq!(report.info.factorizations, 0, "the history survived");
    let d = field_difference(&model, &one);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn a_refused_step_keeps_the_history() {
    // A review's case: refused options must not cost the next step its
    // factor.
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.5, &options).unwrap();
    let before = bits(&model);
    let stick = ContactOptions {
        law: tfem::ContactLaw::Stick,
        ..options
    };
    let e = model.step(1.0, &stick).unwrap_err();
    assert_eq!(e.status(), Status::InvalidArgument);
    assert_eq!(bits(&model), before);
    assert_eq!(model.step(1.0, &options).unwrap().info.factorizations, 0);
}

#[test]
fn a_step_brought_back_unread_recovers_its_own_field() {
    // The field of a step waits until asked for; a revert brings back the
    // step before with its interface factor.
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.3, &options).unwrap();
    model.step(1.0, &options).unwrap();
    model.revert_step().unwrap();
    let mut fresh = scaled_hertz(0.3);
    fresh.solve_contact(&options).unwrap();
    let d = field_difference(&model, &fresh);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn a_history_read_only_at_its_end_recovers_one_field() {
    // Steps that nobody reads cost no sparse solve: their contact outputs
    // come from the interface values alone, and equal a fresh solve's
    // (read from its refined field) to the rounding of a small gap: 1.5e-9
    // of the largest pressure measured here.
    let options = ContactOptions::default();
    let mut model = hertz();
    for k in 1..=5 {
        model.step(k as f64 / 5.0, &options).unwrap();
        let nodes = model.contact_slave_nodes().unwrap();
        let mut fresh = scaled_hertz(k as f64 / 5.0);
        fresh.solve_contact(&options).unwrap();
        let expected = fresh.contact_slave_nodes().unwrap();
        let scale = expected.iter().fold(0.0f64, |m, n| m.max(n.pressure.abs()));
        for (a, b) in nodes.iter().zip(expected.iter()) {
            assert_eq!((a.node, a.active), (b.node, b.active));
            assert!(
                (a.pressure - b.pressure).abs() <= 1e-8 * scale,
                "{a:?} / {b:?}"
            );
        }
    }
    let report = model.contact_report().unwrap();
    assert_eq!(report.info.factorizations, 0);
}

#[test]
fn a_step_too_large_for_double_precision_is_refused_and_changes_nothing() {
    // A review's case: 1e300 was accepted, and its field then unreadable.
    let options = ContactOptions::default();
    let mut model = hertz();
    model.step(0.5, &options).unwrap();
    let before = bits(&model);
    let e = model.step(1e300, &options).unwrap_err();
    assert_eq!(e.status(), Status::NumericalFailure, "{}", e.message());
    assert_eq!(bits(&model), before);
    for t in [1e20, 1e200] {
        model.step(t, &options).unwrap();
        assert!(model.displacements().is_ok(), "t = {t:e}");
    }
    // Near the edge: refused, or accepted with a readable field.
    for t in [1e280, 1e290, 1e294, 1e296, 1e298, 1e299] {
        if model.step(t, &options).is_ok() {
            let u = model.displacements();
            assert!(u.is_ok(), "t = {t:e}: {:?}", u.err());
        }
    }
}

/// [`hertz`] after steps 0.3, 0.6 and 1.0, none of them read.
fn stepped_unread() -> Model {
    let options = ContactOptions::default();
    let mut model = hertz();
    for t in [0.3, 0.6, 1.0] {
        model.step(t, &options).unwrap();
    }
    model
}

/// The field of the step at `t` brought back by a revert, against a fresh
/// solve of its loads.
fn reverted_field_error(model: &mut Model, t: f64) -> f64 {
    model.revert_step().unwrap();
    let mut fresh = scaled_hertz(t);
    fresh.solve_contact(&ContactOptions::default()).unwrap();
    field_difference(model, &fresh)
}

#[test]
fn a_failed_solve_after_steps_leaves_the_step_before_readable() {
    // A review's case: the failed solve lost the history the unread step
    // waited on.
    let mut model = stepped_unread();
    let short = ContactOptions {
        max_iterations: 1,
        ..ContactOptions::default()
    };
    model.solve_contact(&short).unwrap_err();
    assert!(model.displacements().is_ok());
    let d = reverted_field_error(&mut model, 0.6);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn a_failed_step_of_new_options_leaves_the_step_before_readable() {
    let mut model = stepped_unread();
    let other = ContactOptions {
        lambda: Some(0.5),
        max_iterations: 1,
        ..ContactOptions::default()
    };
    model.step(0.3, &other).unwrap_err();
    let d = reverted_field_error(&mut model, 0.6);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn unloading_to_zero_is_solved_from_a_contact_solves_first_set() {
    // A review's case: warm-started from the loaded set, the loop passed
    // through no contact at all, where the cylinder floats.
    // Unloaded, the bodies come to rest touching. The cylinder's polygon
    // touches the block at a node, whose initial weighted gap the hats read
    // open by the faceting (the sagitta h_c²/8R of its edge h_c): the
    // cylinder settles by about that, measured 6.0e-6 against a sagitta of
    // 4.9e-6 (the loaded field 1.1e-3). With the initial gap read by the
    // dual weights it was −1.7e-24 and it did not move; the hats remove
    // their aliasing of the faceting (docs/method.md §6.11).
    let options = ContactOptions::default();
    let mut model = stepped_unread();
    let loaded = model.displacements().unwrap();
    let scale = loaded
        .as_flattened()
        .iter()
        .fold(0.0f64, |m, u| m.max(u.abs()));
    model.step(0.0, &options).unwrap();
    let rest = model.displacements().unwrap();
    let moved = rest
        .as_flattened()
        .iter()
        .fold(0.0f64, |m, u| m.max(u.abs()));
    let h_c = 2.5 * 0.02 / 8.0;
    let sagitta = h_c * h_c / 8.0;
    assert!(
        moved <= 2.0 * sagitta,
        "{moved:e} against a sagitta of {sagitta:e} ({scale:e} loaded)"
    );
    let d = reverted_field_error(&mut model, 1.0);
    assert!(d < 1e-10, "{d:e}");
}

#[test]
fn after_a_failed_solve_or_new_history_step_the_history_goes_on_to_the_bit() {
    // A review's case: a failed call that reached a fresh solve dropped
    // the history; the next step refactorised and moved in the last bits.
    let options = ContactOptions::default();
    let mut reference = stepped_unread();
    reference.step(0.8, &options).unwrap();
    let expected = bits(&reference);
    let short = ContactOptions {
        max_iterations: 1,
        ..options
    };
    let other = ContactOptions {
        lambda: Some(0.5),
        ..short
    };
    for failing in [0, 1] {
        let mut model = stepped_unread();
        let e = match failing {
            0 => model.solve_contact(&short).unwrap_err(),
            _ => model.step(0.3, &other).unwrap_err(),
        };
        assert_eq!(e.status(), Status::NotConverged);
        let report = model.step(0.8, &options).unwrap();
        assert_eq!(report.info.factorizations, 0, "case {failing}");
        assert_eq!(bits(&model), expected, "case {failing}");
    }
}
