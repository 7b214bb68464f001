//! Stage 3 of three dimensions, as a study (docs/method.md §9): two blocks
//! of tempered tetrahedra in frictionless contact through B, the layer of
//! flat tetrahedra between their matching surfaces, each switched on where
//! it would invert.

use tfem::studies::tet_contact::{TetContactProblem, contact_patch_test, solve_contact};
use tfem::studies::tet_scenes::{Hertz3d, TwoBlocks3d};
use tfem::studies::tetmesh::{Split, TetMesh};
use tfem::{Ordering, Tempering};

#[test]
fn the_3d_contact_patch_test_is_exact_for_any_split() {
    for split in [Split::ByIndex, Split::Shuffled(1), Split::Shuffled(2)] {
        for n in [2, 4, 6] {
            let r =
                contact_patch_test(&TetMesh::patch_blocks(n, split, 0.0), [1.0, 10.0], 0.3, 1.0)
                    .unwrap();
            assert!(r.all_active, "{split:?}, n = {n}: {r:?}");
            assert!(r.stress_error < 1e-12, "{split:?}, n = {n}: {r:?}");
            assert!(r.overlap_spread < 1e-10, "{split:?}, n = {n}: {r:?}");
        }
    }
}

#[test]
fn the_3d_contact_patch_test_is_exact_on_a_jittered_interface() {
    for seed in [1, 2] {
        let r = contact_patch_test(
            &TetMesh::patch_blocks(4, Split::Shuffled(seed), 0.2),
            [1.0, 10.0],
            0.3,
            1.0,
        )
        .unwrap();
        assert!(r.stress_error < 1e-12 && r.overlap_spread < 1e-10, "{r:?}");
    }
}

#[test]
fn frictionless_blocks_slide_by_their_different_poisson_expansions() {
    // Under the pressure p the lower block (E = 1) widens by ν p x, the
    // upper (E = 10) by ν p x / 10: the facing nodes at x = 1 part by the
    // difference, which a tied layer would not allow.
    let mesh = TetMesh::patch_blocks(4, Split::Shuffled(4), 0.0);
    let (nu, p) = (0.3, 1.0);
    let r = solve_contact(&TetContactProblem {
        mesh: &mesh,
        materials: [(1.0, nu), (10.0, nu)],
        h_c: 0.25,
        lambda: 1.0,
        tempering: Tempering::Auto,
        ordering: Ordering::Auto,
        fixed: &|_, x| {
            [
                (x[0] == 0.0).then_some(0.0),
                (x[1] == 0.0).then_some(0.0),
                (x[2] == -0.5).then_some(0.0),
            ]
        },
        traction: &|_, c, n| {
            if c[2] == 0.5 && n[2] > 0.5 {
                [0.0, 0.0, -p]
            } else {
                [0.0; 3]
            }
        },
    })
    .unwrap();
    let mut checked = 0;
    for (a, b) in mesh.facing_pairs() {
        let x = mesh.nodes[a][0];
        let slide = r.u[3 * b] - r.u[3 * a];
        let expected = nu * p * x * (1.0 / 10.0 - 1.0);
        assert!(
            (slide - expected).abs() < 1e-12,
            "at x = {x}: {slide} against {expected}"
        );
        checked += 1;
    }
    assert_eq!(checked, 25);
}

#[test]
fn the_3d_seed_scene_lifts_off_at_the_corner_and_transmits_the_load() {
    let r = TwoBlocks3d::default().solve().unwrap();
    assert!((r.transmitted - 1.0).abs() < 1e-9, "{r:?}");
    assert!(
        r.gap_corner > 0.0,
        "the Poisson effect opens the far corner: {r:?}"
    );
    // In contact: more than the supported square, less than the interface.
    assert!(r.contact_area > 0.04 && r.contact_area < 1.0, "{r:?}");
    assert!(r.v_top < 0.0 && r.compliance > 0.0, "{r:?}");
}

#[test]
fn the_3d_seed_scene_refuses_a_mesh_size_that_does_not_divide_it() {
    let e = TwoBlocks3d {
        h: 0.03,
        ..Default::default()
    }
    .solve()
    .unwrap_err();
    assert_eq!(e.status(), tfem::Status::InvalidArgument);
    assert!(e.message().contains("h = 0.03"), "{}", e.message());
}

#[test]
fn a_sphere_on_a_block_transmits_its_load_through_the_initial_gap() {
    // The coarsest mesh, a/2: equilibrium to round-off, a and p0 near
    // Hertz's (the report follows them to a/8).
    let r = Hertz3d {
        refinement: 2.0,
        ..Default::default()
    }
    .solve()
    .unwrap();
    assert!((r.transmitted - 1.0).abs() < 1e-9, "{r:?}");
    assert!(r.a_error.abs() < 0.05 && r.p0_error.abs() < 0.05, "{r:?}");
}

#[test]
fn without_a_load_the_sphere_touches_the_block_at_one_point_only() {
    // Only the elements at the axis have no initial gap; a zero load keeps
    // the others open.
    let h = Hertz3d {
        refinement: 2.0,
        ..Default::default()
    };
    let mesh = h.mesh().unwrap();
    let r = solve_contact(&TetContactProblem {
        mesh: &mesh,
        materials: [(1.0, 0.3); 2],
        h_c: h.a / 2.0,
        lambda: 1.0,
        tempering: Tempering::Off,
        ordering: Ordering::Auto,
        fixed: &|_, x| {
            [
                (x[0] == 0.0).then_some(0.0),
                (x[1] == 0.0).then_some(0.0),
                (x[2] < -0.49).then_some(0.0),
            ]
        },
        traction: &|_, _, _| [0.0; 3],
    })
    .unwrap();
    let on = (0..mesh.tets.len()).filter(|&e| r.active[e]).count();
    assert!(on <= 6, "{on} elements of B on");
    assert!(
        r.transmitted.iter().all(|f| f.abs() < 1e-12),
        "{:?}",
        r.transmitted
    );
}

#[test]
fn a_mesh_without_a_layer_is_refused_not_a_panic() {
    let e = contact_patch_test(&TetMesh::unit_cube(2, None), [1.0, 1.0], 0.3, 1.0).unwrap_err();
    assert_eq!(e.status(), tfem::Status::InvalidArgument);
    assert!(e.message().contains("TetMesh::stacked"), "{}", e.message());
}

#[test]
fn a_block_wider_than_the_sphere_is_refused() {
    let e = Hertz3d {
        extent: 40.0,
        ..Default::default()
    }
    .solve()
    .unwrap_err();
    assert_eq!(e.status(), tfem::Status::InvalidArgument, "{}", e.message());
}
