//! The factorisation split into two concurrent subtrees and a dense
//! separator block gives the same answers as one factorisation of the whole
//! tree, on the paths that use it: the condensed contact loop (the bodies
//! split at their interface), the refactorising loop and a plain solve (a
//! geometric separator), and the detection of a singular system.

use tfem::meshgen::{MeshBuilder, unit_square};
use tfem::scenes::TwoBlocks;
use tfem::{Component, ContactOptions, Material, Model, Ordering, PlaneMode, SolveInfo, Status};

/// Whether the split is expected: it needs two threads.
fn can_split() -> bool {
    rayon::current_num_threads() >= 2
}

/// Largest difference of two displacement fields relative to the largest
/// displacement, and the bound two solutions of relative residuals r₁, r₂
/// of a system of condition κ obey: κ(r₁ + r₂) (κ: the solver's Jacobi-scaled
/// estimate, with a factor 10 for it being an estimate).
fn compare(a: (&[[f64; 2]], &SolveInfo), b: (&[[f64; 2]], &SolveInfo)) -> (f64, f64) {
    let scale = a.0.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let diff =
        a.0.iter()
            .flatten()
            .zip(b.0.iter().flatten())
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    let kappa = a.1.condition_estimate.max(b.1.condition_estimate);
    (
        diff / scale,
        10.0 * kappa * (a.1.relative_residual + b.1.relative_residual),
    )
}

fn seed_scene(split: bool, refactorize: bool) -> (Vec<[f64; 2]>, SolveInfo) {
    // 27 000 unknowns: above the size from which the split is used.
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 160.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    // (Ordering::Auto would pick it too; the test must not depend on that.)
    s.model.set_ordering(Ordering::NestedDissection);
    s.model.set_parallel_subtrees(split);
    let r = s
        .model
        .solve_contact(&ContactOptions {
            refactorize,
            ..Default::default()
        })
        .unwrap();
    (s.model.displacements().unwrap(), r.info)
}

fn square(split: bool, clamp: bool) -> (Model, std::result::Result<SolveInfo, tfem::Error>) {
    // 2 × 129² = 33 282 unknowns.
    let b: MeshBuilder = unit_square(128, None);
    let boundary: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model
        .set_material(
            1,
            Material::new(1.0, 0.3, PlaneMode::Strain, "plate").unwrap(),
        )
        .unwrap();
    if clamp {
        for v in boundary {
            model.fix(v, Component::X, 0.0).unwrap();
            model.fix(v, Component::Y, 0.0).unwrap();
        }
    }
    model.set_body_force(1, [0.3, -1.0]).unwrap();
    model.set_ordering(Ordering::NestedDissection);
    model.set_parallel_subtrees(split);
    let r = model.solve();
    (model, r)
}

#[test]
fn the_condensed_contact_loop_splits_at_the_interface_and_matches_the_whole_factorisation() {
    let (u_split, i_split) = seed_scene(true, false);
    let (u_whole, i_whole) = seed_scene(false, false);
    assert_eq!(i_split.split_factorization, can_split());
    assert!(!i_whole.split_factorization);
    assert!(i_split.interface_unknowns > 0);
    let (diff, bound) = compare((&u_split, &i_split), (&u_whole, &i_whole));
    assert!(
        diff <= bound,
        "relative difference {diff:.2e} > {bound:.2e}"
    );
}

#[test]
fn the_refactorising_loop_splits_at_a_separator_and_matches_the_whole_factorisation() {
    let (u_split, i_split) = seed_scene(true, true);
    let (u_whole, i_whole) = seed_scene(false, true);
    assert_eq!(i_split.split_factorization, can_split());
    assert!(!i_whole.split_factorization);
    let (diff, bound) = compare((&u_split, &i_split), (&u_whole, &i_whole));
    assert!(
        diff <= bound,
        "relative difference {diff:.2e} > {bound:.2e}"
    );
}

#[test]
fn a_plain_solve_splits_and_matches_the_whole_factorisation() {
    let (m_split, i_split) = square(true, true);
    let (m_whole, i_whole) = square(false, true);
    let (i_split, i_whole) = (i_split.unwrap(), i_whole.unwrap());
    assert_eq!(i_split.split_factorization, can_split());
    assert!(!i_whole.split_factorization);
    let (u_split, u_whole) = (
        m_split.displacements().unwrap(),
        m_whole.displacements().unwrap(),
    );
    let (diff, bound) = compare((&u_split, &i_split), (&u_whole, &i_whole));
    assert!(
        diff <= bound,
        "relative difference {diff:.2e} > {bound:.2e}"
    );
    assert!(
        i_split.relative_residual < 1e-12,
        "{}",
        i_split.relative_residual
    );
}

#[test]
fn a_split_factorisation_detects_a_free_body_and_names_it() {
    let (model, r) = square(true, false);
    let err = r.unwrap_err();
    assert_eq!(err.status(), Status::Singular, "{err}");
    assert!(
        err.to_string().contains("body 1 is not restrained"),
        "{err}"
    );
    assert!(model.displacements().is_err());
}

#[test]
fn a_material_change_between_contact_solves_gives_the_answer_of_a_fresh_model() {
    // With ν = 0 some body couplings of the contact surfaces are exact
    // zeros, which the analysis may take as structure; with ν = 0.3 they
    // are not, so the second solve must not reuse that analysis blindly.
    let scene = |nu: f64| {
        let mut s = TwoBlocks {
            mesh_size: 1.0 / 160.0,
            nu1: nu,
            nu2: nu,
            ..Default::default()
        }
        .build()
        .unwrap();
        s.model.set_ordering(Ordering::NestedDissection);
        s
    };
    let options = ContactOptions::default();
    let mut changed = scene(0.0);
    changed.model.solve_contact(&options).unwrap();
    let d = TwoBlocks::default();
    for (body, e, name) in [(1, d.e1, "body 1"), (2, d.e2, "body 2")] {
        let m = Material::new(e, 0.3, PlaneMode::Strain, name).unwrap();
        changed.model.set_material(body, m).unwrap();
    }
    let i_changed = changed.model.solve_contact(&options).unwrap().info;
    let mut fresh = scene(0.3);
    let i_fresh = fresh.model.solve_contact(&options).unwrap().info;
    let (diff, bound) = compare(
        (&changed.model.displacements().unwrap(), &i_changed),
        (&fresh.model.displacements().unwrap(), &i_fresh),
    );
    assert!(
        diff <= bound,
        "relative difference {diff:.2e} > {bound:.2e}"
    );
}
