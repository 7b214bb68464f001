//! The study of Jmin in three dimensions (docs/method.md §9): a
//! manufactured elasticity solution on the unit cube with tempered linear
//! tetrahedra, on regular Kuhn meshes and on bands of flat tetrahedra
//! (eps = 1e-9, far below every Jmin).

use tfem::Tempering;
use tfem::studies::tet_study::{TetPoint, TetStudy, TetTempering};
use tfem::studies::tetmesh::{Band, TetMesh};
use tfem::verification::fitted_rate;

const EPS: f64 = 1e-9;

fn study(tempering: TetTempering) -> TetStudy {
    TetStudy {
        young: 1.0,
        poisson: 0.3,
        tempering,
        layer: tempering,
    }
}

fn auto() -> TetTempering {
    TetTempering::Policy(Tempering::Auto)
}

fn run(tempering: TetTempering, band: Option<Band>, levels: &[usize]) -> Vec<TetPoint> {
    levels
        .iter()
        .map(|&n| {
            study(tempering)
                .run(&TetMesh::unit_cube(n, band), 1.0 / n as f64)
                .unwrap()
        })
        .collect()
}

fn l2_rate(points: &[TetPoint]) -> f64 {
    let h: Vec<f64> = points.iter().map(|p| p.point.h).collect();
    let e: Vec<f64> = points.iter().map(|p| p.point.l2).collect();
    fitted_rate(&h, &e)
}

#[test]
fn tetrahedra_converge_at_rate_two_in_l2_and_one_in_energy_on_a_regular_mesh() {
    let points = run(auto(), None, &[8, 12, 16]);
    let h: Vec<f64> = points.iter().map(|p| p.point.h).collect();
    let energy: Vec<f64> = points.iter().map(|p| p.point.energy).collect();
    let (l2, en) = (l2_rate(&points), fitted_rate(&h, &energy));
    assert!((1.85..=2.15).contains(&l2), "L2 rate {l2}: {points:?}");
    assert!((0.9..=1.1).contains(&en), "energy rate {en}: {points:?}");
}

#[test]
fn the_automatic_rule_leaves_a_regular_kuhn_mesh_plain() {
    let levels = [4, 8];
    let (auto, plain) = (
        run(auto(), None, &levels),
        run(TetTempering::Off, None, &levels),
    );
    for (a, p) in auto.iter().zip(&plain) {
        assert_eq!(a.point.l2, p.point.l2);
    }
}

#[test]
fn plain_fem_locks_on_a_staggered_band_of_caps_and_slivers() {
    let points = run(TetTempering::Off, Some(Band::Staggered(EPS)), &[4, 8, 16]);
    assert!(
        l2_rate(&points) < 0.5,
        "plain FEM should stop converging: {points:?}"
    );
    assert!(
        points[2].point.l2 > 0.5,
        "the band ties the field to a linear one along it: {points:?}"
    );
}

/// L2 errors on a band within `ratio` of the band-free mesh's, level by
/// level, and the fitted rate at least 1.8.
fn assert_band_harmless(band: Band, ratio: f64) {
    let levels = [8, 12, 16];
    let (with, without) = (run(auto(), Some(band), &levels), run(auto(), None, &levels));
    let rate = l2_rate(&with);
    assert!(rate >= 1.8, "{band:?}: L2 rate {rate}: {with:?}");
    for (b, r) in with.iter().zip(&without) {
        assert!(
            b.point.l2 <= ratio * r.point.l2,
            "{band:?} at h = {}: L2 {:e} against {:e} without the band",
            b.point.h,
            b.point.l2,
            r.point.l2
        );
    }
}

#[test]
fn tempering_keeps_rate_two_on_the_staggered_band() {
    assert_band_harmless(Band::Staggered(EPS), 1.1);
}

#[test]
fn tempering_keeps_rate_two_on_the_prism_layer_of_a_closed_gap() {
    assert_band_harmless(Band::Prisms(EPS), 1.1);
}

#[test]
fn tempering_keeps_rate_two_across_a_row_of_needles() {
    assert_band_harmless(Band::Needles(EPS), 1.1);
}

#[test]
fn plain_fem_ties_the_prism_layer_node_to_node() {
    // A layer of matching prisms does not constrain the field beyond tying
    // its two faces: plain FEM gives the band-free mesh's error.
    let levels = [8];
    let with = run(TetTempering::Off, Some(Band::Prisms(EPS)), &levels);
    let without = run(TetTempering::Off, None, &levels);
    let (a, b) = (with[0].point.l2, without[0].point.l2);
    assert!((a - b).abs() <= 1e-6 * b, "{a:e} against {b:e}");
}

#[test]
fn a_band_of_zero_thickness_is_refused_by_plain_fem_and_solved_tempered() {
    let mesh = TetMesh::unit_cube(4, Some(Band::Staggered(0.0)));
    let err = study(TetTempering::Off).run(&mesh, 0.25).unwrap_err();
    assert_eq!(
        err.status(),
        tfem::Status::DegenerateElement,
        "{}",
        err.message()
    );
    let point = study(auto()).run(&mesh, 0.25).unwrap().point;
    assert!(point.l2.is_finite() && point.l2 < 0.5, "{point:?}");
}
