//! The contact solve under the sampled mortar weighting
//! (`ContactWeighting::Mortar`, docs/method.md §6.11).

use tfem::scenes::patch::PatchTest;
use tfem::{ContactOptions, ContactWeighting};

const RATIOS: [f64; 7] = [1.0, 1.5, 2.0 / 3.0, 7.0 / 3.0, 3.0 / 7.0, 1.6, 5.0 / 8.0];

/// Largest element stress error over p of a solved patch test.
fn patch_error(test: &PatchTest) -> (f64, Vec<f64>) {
    let mut s = test.build().unwrap();
    s.model.set_contact_weighting(ContactWeighting::Mortar);
    let report = s.model.solve_contact(&ContactOptions::default()).unwrap();
    let r = s.stress_errors(test).unwrap().max;
    let _ = report;
    let pressures = s
        .model
        .contact_slave_nodes()
        .unwrap()
        .iter()
        .map(|n| n.pressure / test.p)
        .collect();
    (r, pressures)
}

#[test]
fn the_mortar_weighting_passes_the_contact_patch_test_on_every_interface_ratio() {
    for ratio in RATIOS {
        for jitter in [0.0, 0.3] {
            for (e_lower, e_upper) in [(1.0, 1.0), (1.0, 10.0)] {
                let test = PatchTest {
                    ratio,
                    jitter,
                    e_lower,
                    e_upper,
                    mesh_size: 1.0 / 16.0,
                    ..PatchTest::default()
                };
                let (err, p) = patch_error(&test);
                let name = format!("ratio {ratio:.3}, jitter {jitter}, E {e_lower}/{e_upper}");
                assert!(err < 1e-10, "{name}: max stress error {err:e}");
                for q in p {
                    assert!((q - 1.0).abs() < 1e-9, "{name}: slave pressure {q}");
                }
            }
        }
    }
}
