//! The contact solve under the sampled mortar weighting
//! (`ContactWeighting::Mortar`, docs/method.md §6.11).

use tfem::scenes::TwoBlocks;
use tfem::scenes::hertz::Hertz;
use tfem::scenes::patch::PatchTest;
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, ContactWeighting};

const RATIOS: [f64; 7] = [1.0, 1.5, 2.0 / 3.0, 7.0 / 3.0, 3.0 / 7.0, 1.6, 5.0 / 8.0];

/// Largest element stress error over p of a solved patch test.
fn patch_error(test: &PatchTest) -> (f64, Vec<f64>) {
    let mut s = test.build().unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
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

#[test]
fn the_patch_test_stays_exact_on_fine_non_matching_meshes() {
    // Round-off grows like the system's condition, ~1/h²: 1e-13 n².
    for ratio in [3.0 / 7.0, 7.0 / 3.0, 5.0 / 8.0] {
        let test = PatchTest {
            ratio,
            jitter: 0.3,
            mesh_size: 1.0 / 64.0,
            ..PatchTest::default()
        };
        let (err, p) = patch_error(&test);
        assert!(err < 1e-13 * 64.0 * 64.0, "ratio {ratio:.3}: {err:e}");
        assert!(p.iter().all(|q| (q - 1.0).abs() < 1e-13 * 64.0 * 64.0));
    }
}

/// The seed scene at h with the given weighting: (lc, gap_edge, v_top,
/// compliance, iterations).
fn seed(h: f64, w: ContactWeighting) -> ([f64; 4], usize) {
    let mut s = TwoBlocks {
        mesh_size: h,
        ..TwoBlocks::default()
    }
    .build()
    .unwrap();
    s.model.set_contact_weighting(w).unwrap();
    let r = s.solve(&ContactOptions::default()).unwrap();
    (
        [r.lc, r.gap_edge, r.v_top, r.compliance],
        r.report.iterations,
    )
}

#[test]
fn on_the_matching_seed_interface_the_mortar_weighting_gives_the_strips_answer() {
    // A matching interface: every slave node faces its partner, the dual
    // weights read the node-to-node gap, κ is the strip's — the same
    // penalty, node for node (the active set moves through 5–6 iterations,
    // exercising the condensed updates).
    for h in [1.0 / 20.0, 1.0 / 40.0] {
        let (strip, it_s) = seed(h, ContactWeighting::Strip);
        let (mortar, it_m) = seed(h, ContactWeighting::Mortar);
        assert_eq!(it_s, it_m, "h = {h}");
        for (a, b) in strip.iter().zip(&mortar) {
            assert!(
                (a - b).abs() <= 1e-9 * a.abs(),
                "h = {h}: {strip:?} vs {mortar:?}"
            );
        }
    }
}

/// The Hertz scene, cylinder 100× stiffer than the block: the largest error
/// of the interface pressure (the library's nodal pressures for the
/// mortar, the strip's both-sides recovery) within 0.8a, over p₀.
fn stiff_hertz(
    level: f64,
    ratio: f64,
    w: ContactWeighting,
    refactorize: bool,
) -> (f64, Vec<[f64; 2]>) {
    let hz = Hertz {
        mesh_size: 0.02 / level,
        cylinder_mesh_ratio: ratio,
        e_cylinder: 2e13,
        ..Hertz::default()
    };
    let mut s = hz.build().unwrap();
    s.model.set_contact_weighting(w).unwrap();
    let options = ContactOptions {
        refactorize,
        ..ContactOptions::default()
    };
    let r = s.solve(&hz, &options).unwrap();
    (
        r.inner_error(&r.interface_pressure),
        s.model.displacements().unwrap(),
    )
}

#[test]
fn a_stiff_cylinder_read_by_its_coarser_side_converges_where_the_strip_does_not() {
    // Measured (a/16, a/32, a/64): cylinder 2.5× coarser, mortar 1.09e-2,
    // 4.66e-3, 3.20e-3 against the strip's 3.74e-2, 4.82e-2, 5.11e-2;
    // 2.5× finer (slave = block), 4.32e-2, 2.37e-2, 1.24e-2 against
    // 1.74e-1, 1.85e-1, 2.35e-1 (docs/method.md §6.11).
    let levels = [16.0, 32.0, 64.0];
    for ratio in [2.5, 0.4] {
        let h: Vec<f64> = levels.iter().map(|l| 1.0 / l).collect();
        let mortar: Vec<f64> = levels
            .iter()
            .map(|&l| stiff_hertz(l, ratio, ContactWeighting::Mortar, false).0)
            .collect();
        let strip_finest = stiff_hertz(64.0, ratio, ContactWeighting::Strip, false).0;
        let rate = fitted_rate(&h, &mortar);
        assert!(rate > 0.75, "ratio {ratio}: {mortar:?}, rate {rate}");
        assert!(
            mortar[2] < 0.3 * strip_finest,
            "ratio {ratio}: mortar {:e}, strip {strip_finest:e}",
            mortar[2]
        );
    }
}

#[test]
fn the_condensed_loop_agrees_with_refactorising_at_every_iteration() {
    let (e1, u1) = stiff_hertz(16.0, 2.5, ContactWeighting::Mortar, false);
    let (e2, u2) = stiff_hertz(16.0, 2.5, ContactWeighting::Mortar, true);
    let scale = u1
        .iter()
        .fold(0.0f64, |m, v| m.max(v[0].abs()).max(v[1].abs()));
    // Round-off of the 100× stiffer cylinder: the two solves differ by
    // 6e-12 .. 1.6e-10 of the largest displacement as its modulus moves by
    // ±3–10 % (measured), so 1e-10 failed on unrelated changes.
    for (a, b) in u1.iter().zip(&u2) {
        for c in 0..2 {
            assert!((a[c] - b[c]).abs() <= 1e-9 * scale, "{a:?} vs {b:?}");
        }
    }
    assert!((e1 - e2).abs() < 1e-8, "{e1} vs {e2}");
}

/// A solved 3:7 patch test under the mortar weighting.
fn solved_patch() -> tfem::scenes::patch::PatchScene {
    let test = PatchTest {
        ratio: 7.0 / 3.0,
        ..PatchTest::default()
    };
    let mut s = test.build().unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    s
}

#[test]
fn per_element_outputs_are_refused_under_the_mortar_weighting() {
    let mut s = solved_patch();
    let m = &mut s.model;
    for e in [
        m.contact_active().map(|_| ()),
        m.contact_pressure().map(|_| ()),
        m.contact_shear().map(|_| ()),
        m.contact_friction_state().map(|_| ()),
        m.contact_dissipation().map(|_| ()),
    ] {
        let e = e.unwrap_err();
        assert!(e.message().contains("mortar weighting"), "{}", e.message());
    }
    // The refusals left the results.
    assert!(m.contact_slave_nodes().is_ok());
}

#[test]
fn the_stick_law_is_refused_by_the_solve_by_name_and_leaves_the_results() {
    let mut s = solved_patch();
    let m = &mut s.model;
    let stick = ContactOptions {
        law: tfem::ContactLaw::Stick,
        ..ContactOptions::default()
    };
    let e = m.solve_contact(&stick).unwrap_err();
    assert!(
        e.message().contains("contact pair 0") && e.message().contains("stick law"),
        "{}",
        e.message()
    );
    assert!(m.contact_slave_nodes().is_ok());
}

#[test]
fn friction_under_the_mortar_weighting_is_refused_where_it_is_set() {
    let mut s = solved_patch();
    let m = &mut s.model;
    let e = m.set_friction(0, 0.3).unwrap_err();
    assert!(
        e.message().contains("contact pair 0 has friction"),
        "{}",
        e.message()
    );
    assert_eq!(m.contact_pairs()[0].friction, 0.0);
    assert!(m.contact_slave_nodes().is_ok());
}

#[test]
fn the_mortar_weighting_is_refused_where_it_is_set_on_a_frictional_pair() {
    let mut s = PatchTest::default().build().unwrap();
    s.model.set_friction(0, 0.3).unwrap();
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    let e = s
        .model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap_err();
    assert!(
        e.message().contains("contact pair 0 has friction"),
        "{}",
        e.message()
    );
    assert_eq!(s.model.contact_weighting(), ContactWeighting::Auto);
    assert!(s.model.contact_pressure().is_ok());
}

#[test]
fn a_pair_with_its_own_contact_mesh_is_refused_by_name_where_the_weighting_is_set() {
    let test = PatchTest::default();
    let mut s = test.build().unwrap();
    let b = s.model.contact_mesh().unwrap();
    let tris: Vec<[usize; 3]> = b.iter().map(|e| e.nodes).collect();
    let pair = s.model.contact_pairs()[0].clone();
    s.model.clear_contact_pairs();
    s.model
        .add_contact_pair_with_mesh(pair.tag_a, pair.tag_b, &tris)
        .unwrap();
    let e = s
        .model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap_err();
    assert!(
        e.message().contains("contact pair 0") && e.message().contains("mesh of its own"),
        "{}",
        e.message()
    );
    // And the other way round: under the mortar weighting, a pair with a
    // mesh of its own is refused where it is declared.
    s.model.clear_contact_pairs();
    s.model.add_contact_pair(pair.tag_a, pair.tag_b).unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    s.model.clear_contact_pairs();
    let e = s
        .model
        .add_contact_pair_with_mesh(pair.tag_a, pair.tag_b, &tris)
        .unwrap_err();
    assert!(e.message().contains("mesh of its own"), "{}", e.message());
    assert!(s.model.contact_pairs().is_empty());
}

#[test]
fn the_slave_nodes_are_refused_after_a_strip_solve() {
    let mut s = PatchTest::default().build().unwrap();
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    let e = s.model.contact_slave_nodes().unwrap_err();
    assert!(e.message().contains("strip weighting"), "{}", e.message());
}

/// The bits of the last solve's system matrix.
fn matrix_bits(model: &tfem::Model) -> Vec<u64> {
    let k = model.system_matrix().unwrap();
    k.values.iter().map(|v| v.to_bits()).collect()
}

#[test]
fn a_failed_solve_keeps_the_mortar_solves_matrix_to_the_bit() {
    // The seed scene settles in 5 iterations: capped at 2, the next solve
    // fails, and the matrix of the last good one is rebuilt (its active
    // penalties replayed onto the bodies' part).
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 20.0,
        ..TwoBlocks::default()
    }
    .build()
    .unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    s.model.solve_contact(&ContactOptions::default()).unwrap();
    let before = matrix_bits(&s.model);
    let capped = ContactOptions {
        max_iterations: 2,
        ..ContactOptions::default()
    };
    let e = s.model.solve_contact(&capped).unwrap_err();
    assert_eq!(e.status(), tfem::Status::NotConverged, "{}", e.message());
    let after = matrix_bits(&s.model);
    assert_eq!(before, after);
}

#[test]
fn the_contact_forces_balance_and_carry_the_load_into_the_supports() {
    let s = solved_patch();
    let m = &s.model;
    let f = m.contact_forces().unwrap();
    let (fx, fy) = f.iter().fold((0.0, 0.0), |(x, y), v| (x + v[0], y + v[1]));
    let p = PatchTest::default().p;
    assert!(fx.abs() < 1e-9 * p && fy.abs() < 1e-9 * p, "{fx} {fy}");
    let upper: f64 = s.upper.iter().map(|&v| f[v][1]).sum();
    assert!((upper / p - 1.0).abs() < 1e-10, "{upper}");
    let r = m.reactions().unwrap();
    let ry: f64 = r.iter().map(|v| v[1]).sum();
    assert!((ry / p - 1.0).abs() < 1e-10, "{ry}");
}

#[test]
fn a_stack_of_non_matching_blocks_carries_the_uniform_stress_exactly() {
    // Five blocks, cells 8, 13, 5, 21, 8 across, alternating E and ν: four
    // pairs, each with its own slave side; the exact stress is uniform.
    let st = tfem::scenes::stack::Stack::alternating(5, 0.2, &[8, 13, 5, 21]);
    let mut s = st.build().unwrap();
    s.model
        .set_contact_weighting(ContactWeighting::Mortar)
        .unwrap();
    let r = s.model.solve_contact(&ContactOptions::default()).unwrap();
    assert_eq!(r.active, r.elements);
    assert!(
        (r.contact_length - 4.0).abs() < 1e-12,
        "{}",
        r.contact_length
    );
    for q in s.model.element_stresses().unwrap() {
        let e = ((q[1] + st.p).abs() + q[0].abs() + q[2].abs()) / st.p;
        assert!(e < 1e-11, "{q:?}");
    }
    for (pair, _) in s.model.contact_pairs().iter().enumerate() {
        for p in s.model.contact_pair_nodal_pressures(pair).unwrap() {
            assert!(
                p == 0.0 || (p / st.p - 1.0).abs() < 1e-11,
                "pair {pair}: {p}"
            );
        }
    }
}

#[test]
fn a_rigid_cylinder_on_a_finer_mesh_reads_hertz_where_the_strip_is_one_sided() {
    // The cylinder's every node prescribed (a rigid tool), its mesh 2.5×
    // finer than the block's: measured at a/32, mortar 2.39e-2 against the
    // strip's both-sides reading 1.84e-1 (the block's own 2.20e-2).
    use tfem::scenes::punch::RigidCylinder;
    let base = RigidCylinder::default();
    let read = |w: ContactWeighting| {
        let rc = RigidCylinder {
            hertz: Hertz {
                mesh_size: base.hertz.half_width / 32.0,
                cylinder_mesh_ratio: 0.4,
                ..base.hertz
            },
            ..base
        };
        let mut s = rc.build().unwrap();
        s.scene.model.set_contact_weighting(w).unwrap();
        let r = s.solve(&rc, &ContactOptions::default()).unwrap();
        r.hertz.inner_error(&r.hertz.interface_pressure)
    };
    let (mortar, strip) = (
        read(ContactWeighting::Mortar),
        read(ContactWeighting::Strip),
    );
    assert!(
        mortar < 3e-2 && mortar < 0.2 * strip,
        "mortar {mortar:e}, strip {strip:e}"
    );
}

#[test]
fn a_shrink_fit_converges_at_second_order_like_the_strip() {
    // Lamé rings (plane strain and stress), radial interference 1e-3 and
    // 1e-6 of the radius: measured (h = 1/16, 1/32, 1/64, plane strain,
    // 1e-3) pressure error 4.3e-4, 1.2e-4, 3.8e-5 and hoop error 1.30e-3,
    // 4.46e-4, 1.28e-4 of p, the strip's 3.9e-4, 9.1e-5, 2.5e-5 and
    // 1.30e-3, 4.45e-4, 1.28e-4 (before every master vertex was sampled on
    // both chords of its slave corner: 5.9e-3 and 9.2e-4 at 1/64, first
    // order).
    use tfem::scenes::lame::Lame;
    let levels = [16.0, 32.0, 64.0];
    for plane in [tfem::PlaneMode::Strain, tfem::PlaneMode::Stress] {
        for interference in [1e-3, 1e-6] {
            let (mut p, mut hoop) = (Vec::new(), Vec::new());
            for l in levels {
                let lame = Lame {
                    interference,
                    plane,
                    mesh_size: 1.0 / l,
                    ..Lame::default()
                };
                let mut s = lame.build().unwrap();
                s.model
                    .set_contact_weighting(ContactWeighting::Mortar)
                    .unwrap();
                let r = s.solve(&lame, &ContactOptions::default()).unwrap();
                p.push(r.pressure_error);
                hoop.push(r.hoop_error);
            }
            let h: Vec<f64> = levels.iter().map(|l| 1.0 / l).collect();
            let name = format!("{plane:?}, δ = {interference:e}");
            assert!(p[2] < 1e-4 && hoop[2] < 2e-4, "{name}: {p:?} {hoop:?}");
            assert!(fitted_rate(&h, &p) > 1.5, "{name}: pressure {p:?}");
            assert!(fitted_rate(&h, &hoop) > 1.5, "{name}: hoop {hoop:?}");
        }
    }
}
