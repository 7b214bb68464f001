//! `Model::system_matrix` lends the matrix of the last solve: the system
//! whose solution the reported displacements are, so K u = f holds on the
//! unknowns to the solve's own residual, for a plain solve and for a
//! contact solve (final active set). It exists only while the results of a
//! successful solve do, and outlives a failed solve as they do.

use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;
use tfem::{Component, ContactOptions, Material, Model, PlaneMode, Status, SystemMatrix};

const N: usize = 8;

/// The unit square, bottom row clamped, under its own weight.
fn clamped_square() -> Model {
    let mut model = Model::new();
    model.set_mesh(unit_square(N, None).build().unwrap());
    let m = Material::new(200e9, 0.3, PlaneMode::Strain, "steel").unwrap();
    model.set_material(1, m).unwrap();
    for v in 0..=N {
        model.fix(v, Component::X, 0.0).unwrap();
        model.fix(v, Component::Y, 0.0).unwrap();
    }
    model.set_body_force(1, [0.0, -7.8e4]).unwrap();
    model
}

fn coarse_two_blocks() -> Model {
    TwoBlocks {
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    }
    .build()
    .unwrap()
    .model
}

/// ‖K u − f‖ / ‖f‖ over the matrix's unknowns, f the assembled loads.
fn load_residual(model: &Model, k: &SystemMatrix<'_>) -> f64 {
    let u: Vec<f64> = model
        .displacements()
        .unwrap()
        .iter()
        .flatten()
        .copied()
        .collect();
    let f = model.load_vector().unwrap();
    let x: Vec<f64> = k.unknowns.iter().map(|&g| u[g]).collect();
    let ku = k.mul_vec(&x);
    let (mut r2, mut f2) = (0.0, 0.0);
    for (i, &g) in k.unknowns.iter().enumerate() {
        r2 += (ku[i] - f[g]).powi(2);
        f2 += f[g].powi(2);
    }
    (r2 / f2).sqrt()
}

#[test]
fn the_matrix_of_a_plain_solve_maps_the_displacements_to_the_loads() {
    let mut model = clamped_square();
    let info = model.solve().unwrap();
    let k = model.system_matrix().unwrap();
    assert_eq!(k.n(), info.unknowns);
    assert_eq!(k.values.len(), info.matrix_nnz);
    // The clamped row's 2(N + 1) DOFs are eliminated.
    assert_eq!(k.n(), 2 * (N + 1) * (N + 1) - 2 * (N + 1));
    let r = load_residual(&model, &k);
    assert!(r < 1e-12, "‖Ku − f‖/‖f‖ = {r:e}");
}

#[test]
fn the_matrix_of_a_contact_solve_holds_the_final_active_elements() {
    // Touching blocks (no gap load) and homogeneous supports: f is the
    // pressure alone, and only K with the final active set maps u to it.
    let mut model = coarse_two_blocks();
    let report = model.solve_contact(&ContactOptions::default()).unwrap();
    assert!(report.active > 0 && report.active < report.elements);
    let k = model.system_matrix().unwrap();
    let r = load_residual(&model, &k);
    assert!(r < 1e-10, "‖Ku − f‖/‖f‖ = {r:e}");
}

#[test]
fn the_refactorising_loop_lends_the_final_matrix_too() {
    let mut model = coarse_two_blocks();
    let options = ContactOptions {
        refactorize: true,
        ..Default::default()
    };
    let report = model.solve_contact(&options).unwrap();
    assert!(report.iterations > 1);
    let r = load_residual(&model, &model.system_matrix().unwrap());
    assert!(r < 1e-10, "‖Ku − f‖/‖f‖ = {r:e}");
}

#[test]
fn the_matrix_is_an_upper_triangle_with_ascending_rows() {
    let mut model = clamped_square();
    model.solve().unwrap();
    let k = model.system_matrix().unwrap();
    assert_eq!(k.col_ptr.len(), k.n() + 1);
    for (j, w) in k.col_ptr.windows(2).enumerate() {
        let rows = &k.row_idx[w[0]..w[1]];
        assert!(rows.windows(2).all(|p| p[0] < p[1]), "column {j}");
        // The diagonal is stored, last, and positive.
        assert_eq!(rows.last(), Some(&j), "column {j}");
        assert!(k.values[w[1] - 1] > 0.0, "column {j}");
    }
}

#[test]
fn there_is_no_matrix_before_a_solve() {
    let model = clamped_square();
    let err = model.system_matrix().unwrap_err();
    assert_eq!(err.status(), Status::InvalidState, "{err}");
}

#[test]
fn a_change_to_the_model_discards_the_matrix() {
    let mut model = clamped_square();
    model.solve().unwrap();
    let m = Material::new(70e9, 0.33, PlaneMode::Strain, "aluminium").unwrap();
    model.set_material(1, m).unwrap();
    let err = model.system_matrix().unwrap_err();
    assert_eq!(err.status(), Status::InvalidState, "{err}");
}

#[test]
fn a_failed_solve_leaves_the_results_and_their_matrix_bit_for_bit() {
    for refactorize in [false, true] {
        let mut model = coarse_two_blocks();
        let options = ContactOptions {
            refactorize,
            ..Default::default()
        };
        model.solve_contact(&options).unwrap();
        let before = model.displacements().unwrap();
        let bits = |m: &Model| -> Vec<u64> {
            let k = m.system_matrix().unwrap();
            k.values.iter().map(|v| v.to_bits()).collect()
        };
        let matrix = bits(&model);
        let one_iteration = ContactOptions {
            max_iterations: 1,
            ..Default::default()
        };
        let err = model.solve_contact(&one_iteration).unwrap_err();
        assert_eq!(err.status(), Status::NotConverged, "{err}");
        assert_eq!(model.displacements().unwrap(), before);
        assert_eq!(bits(&model), matrix, "refactorize = {refactorize}");
        assert!(load_residual(&model, &model.system_matrix().unwrap()) < 1e-10);
    }
}
