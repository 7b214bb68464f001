//! Stage 2 of three dimensions (docs/method.md §9): two blocks with
//! matching interface triangulations tied by a layer of zero-volume prisms,
//! each split into three flat tetrahedra, all assembled with TFEM's
//! tempered stiffness and the layer's tie T_e = A_e h_c²/λ.

use tfem::Tempering;
use tfem::studies::tet_study::{TetStudy, TetTempering, tied_patch_test};
use tfem::studies::tetmesh::{Split, TetMesh};
use tfem::verification::fitted_rate;

/// Young's moduli of the lower and upper blocks: a stiffness contrast.
const YOUNG: [f64; 2] = [1.0, 10.0];

/// The tie of a mesh with n boxes per side: h_c its interface edge.
fn tie(n: usize) -> TetTempering {
    TetTempering::Tie {
        h_c: 1.0 / n as f64,
        lambda: 1.0,
    }
}

/// A tied mesh whose interface nodes are moved by up to 20 % of h (both
/// copies alike): interface triangles of unequal areas and edges. (At 30 %
/// some block tetrahedra fall below 0.1 h³ and are tempered, which no
/// patch test survives, in 2D either.)
fn jittered(n: usize, split: Split) -> TetMesh {
    let mut mesh = TetMesh::tied_blocks(n, split);
    mesh.jitter_interface(0.5, 1.0 / n as f64, 0.2, 99);
    mesh
}

fn assert_patch_exact(split: Split) {
    for n in [2, 4, 6] {
        for mesh in [TetMesh::tied_blocks(n, split), jittered(n, split)] {
            // h_c: any one length for the whole interface will do.
            let r = tied_patch_test(&mesh, YOUNG, 0.3, tie(n)).unwrap();
            assert!(r.stress_error < 1e-12, "{split:?}, n = {n}: {r:?}");
            assert!(r.jump_spread < 1e-10, "{split:?}, n = {n}: {r:?}");
        }
    }
}

#[test]
fn the_tied_patch_test_is_exact_with_the_split_by_node_index() {
    assert_patch_exact(Split::ByIndex);
}

#[test]
fn the_tied_patch_test_is_exact_for_any_consistent_split() {
    for seed in 1..=6 {
        assert_patch_exact(Split::Shuffled(seed));
    }
}

#[test]
fn the_layer_opens_by_the_traction_over_its_penalty() {
    // Halving h_c quarters the jump: κ ∝ λ/h_c².
    let mesh = TetMesh::tied_blocks(4, Split::Shuffled(2));
    let jump = |h_c: f64| {
        let t = TetTempering::Tie { h_c, lambda: 1.0 };
        tied_patch_test(&mesh, YOUNG, 0.3, t).unwrap().jump
    };
    let (a, b) = (jump(0.25), jump(0.125));
    for i in 0..3 {
        assert!(
            (a[i] - 4.0 * b[i]).abs() <= 1e-9 * a[i].abs().max(1e-30),
            "{a:?} against 4 × {b:?}"
        );
    }
}

#[test]
fn the_blocks_rule_on_the_layer_fails_the_patch_test_on_an_uneven_interface() {
    // Jmin = min(h⁴/λ, 0.1 h³) follows each tetrahedron's own longest edge,
    // not its share of the interface: the pairs are tied unevenly.
    let mesh = jittered(4, Split::Shuffled(3));
    let r = tied_patch_test(&mesh, YOUNG, 0.3, TetTempering::Policy(Tempering::Auto)).unwrap();
    assert!(r.stress_error > 1e-3, "{r:?}");
}

#[test]
fn plain_fem_cannot_assemble_the_zero_volume_layer() {
    let mesh = TetMesh::tied_blocks(2, Split::ByIndex);
    let err = tied_patch_test(&mesh, YOUNG, 0.3, TetTempering::Off).unwrap_err();
    assert_eq!(err.status(), tfem::Status::DegenerateElement);
    assert!(
        err.message().starts_with("tetrahedron "),
        "{}",
        err.message()
    );
}

#[test]
fn a_manufactured_field_converges_across_the_tied_interface_as_in_one_body() {
    let levels = [8, 12, 16];
    let run = |tied: bool| -> Vec<(f64, f64)> {
        levels
            .iter()
            .map(|&n| {
                let study = TetStudy {
                    young: 1.0,
                    poisson: 0.3,
                    tempering: TetTempering::Policy(Tempering::Auto),
                    layer: tie(n),
                };
                let mesh = if tied {
                    TetMesh::tied_blocks(n, Split::Shuffled(5))
                } else {
                    TetMesh::unit_cube(n, None)
                };
                let p = study.run(&mesh, 1.0 / n as f64).unwrap();
                (p.point.h, p.point.l2)
            })
            .collect()
    };
    let (tied, single) = (run(true), run(false));
    let (h, e): (Vec<f64>, Vec<f64>) = tied.iter().copied().unzip();
    let rate = fitted_rate(&h, &e);
    assert!(rate >= 1.85, "L2 rate {rate}: {tied:?}");
    for (t, s) in tied.iter().zip(&single) {
        assert!(
            (t.1 - s.1).abs() <= 0.05 * s.1,
            "h = {}: tied {:e} against one body {:e}",
            t.0,
            t.1,
            s.1
        );
    }
}
