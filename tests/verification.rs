//! Verification of the tempered P1 discretisation: patch tests, convergence
//! rates on manufactured solutions, and the locking study of the TFEM paper
//! (bands of flattened triangles).

use tfem::meshgen::{Diagonal, MeshBuilder, unit_square};
use tfem::verification::{
    StudyPoint, fitted_rate, run_manufactured_elasticity, run_manufactured_laplace,
};
use tfem::{Component, Material, Model, PlaneMode, Tempering, TriGeometry};

fn steel_like() -> Material {
    Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").unwrap()
}

/// An irregular mesh of the unit square: a 6x6 grid whose interior nodes
/// are moved by up to 30 % of the spacing (deterministically).
fn irregular_square() -> MeshBuilder {
    let xs: Vec<f64> = (0..=6).map(|i| i as f64 / 6.0).collect();
    let mut b = MeshBuilder::new();
    b.add_grid(&xs, &xs, 1, Diagonal::MirroredAt(0.5));
    let mut state = 12345u64;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for p in b.nodes.iter_mut() {
        if p[0] > 0.0 && p[0] < 1.0 && p[1] > 0.0 && p[1] < 1.0 {
            p[0] += 0.3 / 6.0 * 2.0 * next();
            p[1] += 0.3 / 6.0 * 2.0 * next();
        }
    }
    b
}

fn rates(points: &[StudyPoint]) -> (f64, f64) {
    let h: Vec<f64> = points.iter().map(|p| p.h).collect();
    let l2: Vec<f64> = points.iter().map(|p| p.l2).collect();
    let en: Vec<f64> = points.iter().map(|p| p.energy).collect();
    (fitted_rate(&h, &l2), fitted_rate(&h, &en))
}

#[test]
fn patch_test_reproduces_a_linear_field_to_round_off_on_an_irregular_mesh() {
    let b = irregular_square();
    let boundary: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
    let mesh = b.build().unwrap();
    let exact = |p: [f64; 2]| {
        [
            1e-3 + 2e-3 * p[0] - 1e-3 * p[1],
            -5e-4 + 1e-3 * p[0] + 3e-3 * p[1],
        ]
    };
    let mut model = Model::new();
    let nodes = mesh.nodes().to_vec();
    model.set_mesh(mesh);
    model.set_material(1, steel_like()).unwrap();
    // λ ≫ h: no element is tempered, plain consistency is what is tested.
    model.set_tempering(Tempering::Lambda(1e3)).unwrap();
    for &v in &boundary {
        let u = exact(nodes[v]);
        model.fix(v, Component::X, u[0]).unwrap();
        model.fix(v, Component::Y, u[1]).unwrap();
    }
    model.solve().unwrap();
    assert!(model.warnings().is_empty(), "{:?}", model.warnings());
    let u = model.displacements().unwrap();
    let err = u
        .iter()
        .zip(&nodes)
        .map(|(u, p)| (u[0] - exact(*p)[0]).abs().max((u[1] - exact(*p)[1]).abs()))
        .fold(0.0, f64::max);
    assert!(err < 1e-15, "nodal error {err}");
    // Uniform strain [2e-3, 3e-3, 0] and the matching uniform stress.
    let d = steel_like().d_matrix();
    let sigma = [
        d[0][0] * 2e-3 + d[0][1] * 3e-3,
        d[1][0] * 2e-3 + d[1][1] * 3e-3,
        0.0,
    ];
    for s in model.element_stresses().unwrap() {
        for k in 0..3 {
            assert!((s[k] - sigma[k]).abs() < 1e-14, "{s:?} vs {sigma:?}");
        }
    }
}

#[test]
fn patch_test_transmits_uniform_traction_on_an_irregular_mesh() {
    // σ_xx = 1 by tractions on x = 0 and x = 1, minimal supports.
    let b = irregular_square();
    let left = b.boundary_edges_where(|p| p[0] == 0.0);
    let right = b.boundary_edges_where(|p| p[0] == 1.0);
    let mesh = b.build().unwrap();
    let origin = mesh.nodes().iter().position(|p| *p == [0.0, 0.0]).unwrap();
    let top_left = mesh.nodes().iter().position(|p| *p == [0.0, 1.0]).unwrap();
    let mut model = Model::new();
    model.set_mesh(mesh);
    model.set_material(1, steel_like()).unwrap();
    let tags: Vec<i32> = left
        .iter()
        .map(|_| 1)
        .chain(right.iter().map(|_| 2))
        .collect();
    let edges: Vec<[usize; 2]> = left.iter().chain(&right).copied().collect();
    model.set_boundary_edges(&edges, &tags).unwrap();
    model.set_tempering(Tempering::Lambda(1e3)).unwrap();
    model.add_pressure(1, -1.0).unwrap();
    model.add_pressure(2, -1.0).unwrap();
    model.fix(origin, Component::X, 0.0).unwrap();
    model.fix(origin, Component::Y, 0.0).unwrap();
    model.fix(top_left, Component::X, 0.0).unwrap();
    model.solve().unwrap();
    for s in model.element_stresses().unwrap() {
        assert!(
            (s[0] - 1.0).abs() < 1e-12 && s[1].abs() < 1e-12 && s[2].abs() < 1e-12,
            "{s:?}"
        );
    }
    let r = model.reactions().unwrap();
    let total: f64 = r.iter().map(|r| r[0].abs() + r[1].abs()).sum();
    assert!(
        total < 1e-12,
        "self-equilibrated load needs no reaction, got {total}"
    );
}

/// The mesh of `b`, clamped on x = 0 and loaded by a body-force-like nodal
/// load, solved with `tempering`: displacements and warnings.
fn clamped(b: MeshBuilder, tempering: Tempering) -> (Vec<[f64; 2]>, Vec<String>) {
    let n = b.nodes.len();
    let left: Vec<usize> = (0..n).filter(|&v| b.nodes[v][0] == 0.0).collect();
    let mut model = Model::new();
    model.set_mesh(b.build().unwrap());
    model.set_material(1, steel_like()).unwrap();
    model.set_tempering(tempering).unwrap();
    for &v in &left {
        model.fix(v, Component::X, 0.0).unwrap();
        model.fix(v, Component::Y, 0.0).unwrap();
    }
    for v in 0..n {
        model.add_nodal_force(v, [1e-3, -2e-3]).unwrap();
    }
    model.solve().unwrap();
    (model.displacements().unwrap(), model.warnings())
}

#[test]
fn tempering_that_softens_well_shaped_elements_is_warned_about() {
    // h = 1/6 of the model: with λ = the model size, Jmin = h³/λ exceeds
    // the J of the flatter, still healthy, elements.
    let (_, warnings) = clamped(irregular_square(), Tempering::Lambda(1.0));
    let w = warnings.join("\n");
    assert!(w.contains("softens") && w.contains("increase λ"), "{w}");
}

#[test]
fn default_tempering_leaves_well_shaped_elements_of_a_coarse_mesh_alone() {
    // A 2 × 3 grid of the unit square (cells 0.5 × 0.2 and 0.5 × 0.4):
    // h_e ≈ λ/2, so the seed's Jmin = h³/λ exceeds every J, but every
    // element stands at least h_e/10 tall and the default caps Jmin at
    // h_e²/10: plain FEM to the last bit.
    let coarse = || {
        let mut b = MeshBuilder::new();
        b.add_grid(
            &[0.0, 0.5, 1.0],
            &[0.0, 0.4, 0.6, 1.0],
            1,
            Diagonal::MirroredAt(0.5),
        );
        b
    };
    let mesh = coarse().build().unwrap();
    for t in mesh.triangles() {
        let g = TriGeometry::new(&mesh.corners(t));
        assert!(g.j >= 0.1 * g.h * g.h && g.j < g.h * g.h * g.h, "{g:?}");
    }
    let (auto, warnings) = clamped(coarse(), Tempering::Auto);
    let (plain, _) = clamped(coarse(), Tempering::Off);
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(auto, plain);
    let (softened, _) = clamped(coarse(), Tempering::Lambda(1.0));
    assert_ne!(softened, plain);
}

#[test]
fn manufactured_elasticity_converges_at_rate_two_in_l2_and_one_in_energy() {
    let points: Vec<StudyPoint> = [8, 16, 32, 64]
        .iter()
        .map(|&n| {
            run_manufactured_elasticity(
                unit_square(n, None),
                1.0 / n as f64,
                steel_like(),
                Tempering::Auto,
            )
            .unwrap()
        })
        .collect();
    let (l2, energy) = rates(&points);
    assert!((1.9..=2.1).contains(&l2), "L2 rate {l2}: {points:?}");
    assert!(
        (0.9..=1.1).contains(&energy),
        "energy rate {energy}: {points:?}"
    );
}

#[test]
fn manufactured_laplacian_converges_at_rate_two_in_l2_and_one_in_h1() {
    let points: Vec<StudyPoint> = [8, 16, 32, 64]
        .iter()
        .map(|&n| {
            run_manufactured_laplace(unit_square(n, None), 1.0 / n as f64, Tempering::Auto).unwrap()
        })
        .collect();
    let (l2, h1) = rates(&points);
    assert!((1.9..=2.1).contains(&l2), "L2 rate {l2}: {points:?}");
    assert!((0.9..=1.1).contains(&h1), "H1 rate {h1}: {points:?}");
}

/// Height of the caps in the band: far below Jmin/h = h²/λ at every level.
const BAND: f64 = 1e-9;
const LEVELS: [usize; 4] = [8, 16, 32, 64];

#[test]
fn laplacian_locks_with_plain_fem_on_a_band_of_flat_triangles() {
    let points: Vec<StudyPoint> = LEVELS
        .iter()
        .map(|&n| {
            run_manufactured_laplace(unit_square(n, Some(BAND)), 1.0 / n as f64, Tempering::Off)
                .unwrap()
        })
        .collect();
    let (l2, _) = rates(&points);
    assert!(
        l2 < 0.5,
        "plain FEM should stop converging, L2 rate {l2}: {points:?}"
    );
    assert!(
        points[3].l2 > 0.05,
        "the band forces u linear along y = 1/2: {points:?}"
    );
}

#[test]
fn laplacian_keeps_rate_two_with_tempering_on_a_band_of_flat_triangles() {
    let points: Vec<StudyPoint> = LEVELS
        .iter()
        .map(|&n| {
            run_manufactured_laplace(unit_square(n, Some(BAND)), 1.0 / n as f64, Tempering::Auto)
                .unwrap()
        })
        .collect();
    let (l2, _) = rates(&points);
    assert!(l2 >= 1.8, "TFEM L2 rate {l2}: {points:?}");
}

#[test]
fn elasticity_locks_with_plain_fem_on_a_band_of_flat_triangles() {
    let points: Vec<StudyPoint> = LEVELS
        .iter()
        .map(|&n| {
            run_manufactured_elasticity(
                unit_square(n, Some(BAND)),
                1.0 / n as f64,
                steel_like(),
                Tempering::Off,
            )
            .unwrap()
        })
        .collect();
    let (l2, _) = rates(&points);
    assert!(
        l2 < 0.5,
        "plain FEM should stop converging, L2 rate {l2}: {points:?}"
    );
    assert!(points[3].l2 > 0.05, "{points:?}");
}

#[test]
fn elasticity_keeps_rate_two_with_tempering_on_a_band_of_flat_triangles() {
    let points: Vec<StudyPoint> = LEVELS
        .iter()
        .map(|&n| {
            run_manufactured_elasticity(
                unit_square(n, Some(BAND)),
                1.0 / n as f64,
                steel_like(),
                Tempering::Auto,
            )
            .unwrap()
        })
        .collect();
    let (l2, _) = rates(&points);
    assert!(l2 >= 1.8, "TFEM L2 rate {l2}: {points:?}");
}
