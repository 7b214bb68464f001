//! The contact patch test on non-matching interfaces (docs/method.md
//! §6.11): two blocks under a uniform pressure, interface ratios 2:3, 3:7,
//! 5:8 both ways, uniform and jittered grids, equal moduli and a 10×
//! stiffer upper block. The exact stress is uniform; the strip of B with
//! T_e = ℓ_e h_c²/λ transmits it to round-off.
//!
//! Measured (`cargo run --release --example patch_test`, h = 1/8 … 1/128):
//! max stress error 5.6e-15 … 1.9e-10 of p, L2 2.8e-15 … 2.6e-11; every
//! element active with pressure p, nodal pressures p, reported
//! interpenetration equal to the actual one. Before (T_e = h_e³/λ): max
//! 9.5e-3 … 6.2e-1 of p on non-matching interfaces (and up to 0.13 on
//! jittered matching ones), element pressures 0.002 p … 7.5 p, up to 6
//! elements released.

use tfem::ContactOptions;
use tfem::scenes::patch::{PatchResult, PatchTest};

const RATIOS: [f64; 7] = [1.0, 1.5, 2.0 / 3.0, 7.0 / 3.0, 3.0 / 7.0, 1.6, 5.0 / 8.0];

fn run(test: PatchTest) -> (PatchResult, Vec<String>) {
    let mut s = test.build().unwrap();
    let r = s.solve(&test, &ContactOptions::default()).unwrap();
    (r, s.model.warnings())
}

fn check(test: &PatchTest, r: &PatchResult) {
    let name = format!(
        "ratio {:.3}, jitter {}, h = {}, E = {:e}/{:e}",
        test.ratio, test.jitter, test.mesh_size, test.e_lower, test.e_upper
    );
    let n = test.length / test.mesh_size;
    // Round-off grows like the condition of the system, ~1/h².
    let tol = 1e-13 * n * n;
    assert!(
        r.max_error < tol && r.l2_error < tol,
        "{name}: max {:e}, L2 {:e}",
        r.max_error,
        r.l2_error
    );
    assert_eq!(r.released, 0, "{name}: released elements");
    // The pressures read the overlap p/κ, ~1e-6 of the displacements it
    // is the difference of.
    let ptol = 1e-12 * n * n;
    let within = |(lo, hi): (f64, f64)| (lo - 1.0).abs() < ptol && (hi - 1.0).abs() < ptol;
    assert!(
        within(r.element_pressure),
        "{name}: {:?}",
        r.element_pressure
    );
    assert!(within(r.nodal_pressure), "{name}: {:?}", r.nodal_pressure);
    assert!(within(r.traction), "{name}: {:?}", r.traction);
    assert!(
        within(r.interface_traction),
        "{name}: {:?}",
        r.interface_traction
    );
    // One uniform overlap: the report's, the harness's and the library's.
    let pen = r.penetration;
    assert!(pen > 0.0, "{name}");
    for other in [r.reported_penetration, r.overlap] {
        assert!((other - pen).abs() < 1e-6 * pen, "{name}: {other} vs {pen}");
    }
}

#[test]
fn every_ratio_both_ways_jittered_or_not_passes_to_round_off() {
    for (e_lower, e_upper) in [(1e10, 1e10), (1e10, 1e11)] {
        for ratio in RATIOS {
            for jitter in [0.0, 0.3] {
                for n in [8, 16, 32, 64] {
                    let test = PatchTest {
                        e_lower,
                        e_upper,
                        mesh_size: 1.0 / n as f64,
                        ratio,
                        jitter,
                        ..Default::default()
                    };
                    // Including 3:7 jittered at h = 1/8, whose upper block
                    // has three cells of 0.4 × 0.25 across (h ≈ λ/2): the
                    // seed's Jmin = h³/λ softened two of them (3.5e-2 of p).
                    let (r, warnings) = run(test);
                    assert!(warnings.is_empty(), "{warnings:?}");
                    check(&test, &r);
                }
            }
        }
    }
}

#[test]
fn the_finest_level_passes_too() {
    // The user's worst case: 3:7, the finer side 10× stiffer, h = 1/128
    // (before: max error 0.12 of p).
    for (ratio, jitter) in [(7.0 / 3.0, 0.0), (3.0 / 7.0, 0.3), (1.5, 0.3)] {
        let test = PatchTest {
            e_lower: 1e10,
            e_upper: 1e11,
            mesh_size: 1.0 / 128.0,
            ratio,
            jitter,
            ..Default::default()
        };
        let (r, warnings) = run(test);
        assert!(warnings.is_empty(), "{warnings:?}");
        check(&test, &r);
    }
}

/// The strip of a non-matching interface at length scales far from 1:
/// its degeneracy test compared a length with an area, and refused every
/// strip triangle beyond ~1e12 length units.
#[test]
fn a_non_matching_patch_passes_at_any_length_scale() {
    for scale in [1e-9, 1e13] {
        let test = PatchTest {
            length: scale,
            h1: 0.25 * scale,
            h2: 0.25 * scale,
            mesh_size: scale / 8.0,
            ratio: 7.0 / 3.0,
            ..Default::default()
        };
        let (r, _) = run(test);
        check(&test, &r);
    }
}
