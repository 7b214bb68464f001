//! Frictionless contact by activating inverted contact elements, checked
//! against an exact frictionless oracle (node-to-node Lagrange multipliers,
//! primal-dual active set, on the same conforming mesh; `tfem::oracle`, which
//! shares nothing with the TFEM contact path), and on the seed scene.

use std::collections::{BTreeSet, HashMap};

use tfem::element::TriGeometry;
use tfem::scenes::{
    TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TwoBlocks, TwoBlocksResult, TwoBlocksScene,
};
use tfem::verification::fitted_rate;
use tfem::{ContactLaw, ContactOptions, InversionTest, Model, Status};

fn solve(scene: &TwoBlocks) -> (TwoBlocksScene, TwoBlocksResult) {
    let mut s = scene.build().unwrap();
    let r = s.solve(&ContactOptions::default()).unwrap();
    (s, r)
}

fn interface_pairs(model: &Model) -> Vec<(usize, usize)> {
    tfem::oracle::interface_pairs(model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap()
}

/// The exact frictionless oracle (`tfem::oracle`: node-to-node multipliers,
/// primal-dual active set, sparse LU; it shares only the body stiffness
/// with TFEM): displacements and active node pairs.
fn oracle(model: &Model) -> (Vec<f64>, BTreeSet<(usize, usize)>) {
    let o = tfem::oracle::frictionless_oracle(model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    (o.u, o.active)
}

/// The node pairs tested by the active contact elements: on a flat
/// conforming interface each element is a spring between the two nodes
/// whose gradient has a normal component.
fn tfem_active_pairs(model: &Model) -> BTreeSet<(usize, usize)> {
    let mesh = model.mesh().unwrap();
    let lower: BTreeSet<usize> = interface_pairs(model).into_iter().map(|p| p.0).collect();
    let mut set = BTreeSet::new();
    for (el, &on) in model
        .contact_elements()
        .unwrap()
        .iter()
        .zip(model.contact_active().unwrap())
    {
        if !on {
            continue;
        }
        let geo = TriGeometry::new(&mesh.corners(&el.nodes));
        let nodes: Vec<usize> = (0..3)
            .filter(|&i| {
                (geo.g[i][0] * el.normal[0] + geo.g[i][1] * el.normal[1]).abs() > 1e-9 * geo.h
            })
            .map(|i| el.nodes[i])
            .collect();
        assert_eq!(nodes.len(), 2, "a flat element couples one node pair");
        let (a, b) = if lower.contains(&nodes[0]) {
            (nodes[0], nodes[1])
        } else {
            (nodes[1], nodes[0])
        };
        set.insert((a, b));
    }
    set
}

fn max_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(x.abs()))
}

#[test]
fn contact_set_equals_the_exact_oracles_and_the_penalty_error_shrinks_at_rate_two() {
    for c in [0.1, 0.2, 0.3] {
        let (mut hs, mut errs) = (Vec::new(), Vec::new());
        for n in [16, 32, 64, 128] {
            let (s, _) = solve(&TwoBlocks {
                c,
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            });
            let (u_exact, set_exact) = oracle(&s.model);
            assert_eq!(
                tfem_active_pairs(&s.model),
                set_exact,
                "2C/L = {}, h = 1/{n}",
                2.0 * c
            );
            let u: Vec<f64> = s
                .model
                .displacements()
                .unwrap()
                .into_iter()
                .flatten()
                .collect();
            let diff: Vec<f64> = u.iter().zip(&u_exact).map(|(a, b)| a - b).collect();
            hs.push(1.0 / n as f64);
            errs.push(max_abs(&diff) / max_abs(&u_exact));
        }
        let rate = fitted_rate(&hs, &errs);
        assert!(
            rate >= 1.7,
            "2C/L = {}: penalty error {errs:?}, rate {rate}",
            2.0 * c
        );
    }
}

#[test]
fn small_initial_gap_matches_the_oracle_without_cycling() {
    // A gap of the order of the penalty penetration (~1e-7 m at h = 1/64).
    for gap in [2e-8, 2e-7, 2e-6] {
        let scene = TwoBlocks {
            gap,
            ..Default::default()
        };
        let (s, r) = solve(&scene);
        let (u_exact, set_exact) = oracle(&s.model);
        assert_eq!(tfem_active_pairs(&s.model), set_exact, "gap {gap}");
        let u: Vec<f64> = s
            .model
            .displacements()
            .unwrap()
            .into_iter()
            .flatten()
            .collect();
        let diff: Vec<f64> = u.iter().zip(&u_exact).map(|(a, b)| a - b).collect();
        assert!(
            max_abs(&diff) < 0.01 * max_abs(&u_exact),
            "gap {gap}: {}",
            max_abs(&diff)
        );
        assert!(r.report.iterations <= 10, "{:?}", r.report.history);
    }
}

#[test]
fn uniform_pressure_over_the_whole_width_gives_uniform_stress_and_full_contact() {
    let scene = TwoBlocks {
        c: 0.5,
        nu1: 0.2,
        nu2: 0.35,
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    };
    let (s, r) = solve(&scene);
    assert!((r.lc - 1.0).abs() < 1e-12, "lc = {}", r.lc);
    let p = scene.p;
    for (k, sig) in s.model.element_stresses().unwrap().iter().enumerate() {
        assert!(
            (sig[1] + p).abs() < 1e-8 * p && sig[0].abs() < 1e-8 * p && sig[2].abs() < 1e-8 * p,
            "element {k}: {sig:?}"
        );
    }
    let pressure = s.model.contact_pressure().unwrap();
    assert!(
        pressure.iter().all(|q| (q - p).abs() < 1e-8 * p),
        "contact pressure = p everywhere"
    );
}

#[test]
fn pulling_the_bodies_apart_activates_nothing() {
    let scene = TwoBlocks {
        p: -1e7,
        c: 0.5,
        support: true,
        ..Default::default()
    };
    let mut s = scene.build().unwrap();
    // The upper body is held by its own support (its top edge lifted), so
    // that it is restrained without contact.
    s.model
        .fix_edges(tfem::scenes::TAG_LOAD, tfem::Component::Y, 1e-5)
        .unwrap();
    let r = s.solve(&ContactOptions::default()).unwrap();
    assert_eq!(r.report.active, 0);
    assert_eq!(r.lc, 0.0);
    assert!(r.gap_edge > 0.0);
}

#[test]
fn seed_scene_opens_at_the_edges_is_symmetric_and_balances_the_support() {
    let scene = TwoBlocks::default();
    let (s, r) = solve(&scene);
    assert!(
        r.gap_edge > 0.0,
        "Poisson effect opens the interface: {}",
        r.gap_edge
    );
    assert!(r.lc < scene.length && r.lc > 2.0 * scene.c, "lc = {}", r.lc);
    let load = scene.p * 2.0 * scene.c;
    assert!(
        (r.support_reaction - load).abs() <= 1e-10 * load,
        "{} vs {load}",
        r.support_reaction
    );
    // Mirror symmetry about x = L/2: v(x) = v(L − x), u(x) = −u(L − x).
    let mesh = s.model.mesh().unwrap();
    let u = s.model.displacements().unwrap();
    let mut at: HashMap<(u64, u64, bool), usize> = HashMap::new();
    for (v, p) in mesh.nodes().iter().enumerate() {
        at.insert((p[0].to_bits(), p[1].to_bits(), v < s.n_lower_nodes), v);
    }
    let scale = max_abs(&u.iter().flatten().copied().collect::<Vec<_>>());
    let mut worst = 0.0f64;
    for (v, p) in mesh.nodes().iter().enumerate() {
        let mirror = [scene.length - p[0], p[1]];
        if let Some(&w) = at.get(&(
            mirror[0].to_bits(),
            mirror[1].to_bits(),
            v < s.n_lower_nodes,
        )) {
            worst = worst
                .max((u[v][1] - u[w][1]).abs())
                .max((u[v][0] + u[w][0]).abs());
        }
    }
    assert!(worst < 1e-9 * scale, "asymmetry {worst} of {scale}");
}

#[test]
fn interpenetration_shrinks_at_rate_two() {
    let (mut hs, mut pens) = (Vec::new(), Vec::new());
    for n in [16, 32, 64, 128, 256] {
        let (_, r) = solve(&TwoBlocks {
            mesh_size: 1.0 / n as f64,
            ..Default::default()
        });
        hs.push(1.0 / n as f64);
        pens.push(r.report.max_penetration);
    }
    let rate = fitted_rate(&hs, &pens);
    assert!(
        (1.7..=2.3).contains(&rate),
        "penetration {pens:?}, rate {rate}"
    );
}

#[test]
fn the_loop_converges_without_cycling_down_to_h_1_over_256_for_every_load_width() {
    for c in [0.1, 0.2, 0.3] {
        for n in [32, 64, 128, 256] {
            let mut s = TwoBlocks {
                c,
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .unwrap();
            let r = s.solve(&ContactOptions::default());
            let r = r.unwrap_or_else(|e| panic!("2C/L = {}, h = 1/{n}: {e}", 2.0 * c));
            assert!(r.report.iterations < 20, "{:?}", r.report.history);
        }
    }
}

#[test]
fn a_floating_body_is_reported_as_singular_naming_it() {
    let mut s = TwoBlocks {
        support: false,
        ..Default::default()
    }
    .build()
    .unwrap();
    let e = s.solve(&ContactOptions::default()).unwrap_err();
    assert_eq!(e.status(), Status::Singular);
    assert!(
        e.message().contains("body 1") && e.message().contains("translation in y"),
        "{}",
        e.message()
    );
}

#[test]
fn a_free_sliding_mode_is_reported_as_singular_naming_the_body() {
    // No symmetry condition: frictionless contact lets the upper body slide
    // (and the lower one too: it is only supported vertically).
    let mut s = TwoBlocks {
        symmetry: false,
        ..Default::default()
    }
    .build()
    .unwrap();
    let before = s.model.contact_pairs().len();
    let e = s.solve(&ContactOptions::default()).unwrap_err();
    assert_eq!(e.status(), Status::Singular);
    assert!(e.message().contains("translation in x"), "{}", e.message());
    assert!(
        e.message().contains("body 2") || e.message().contains("body 1"),
        "{}",
        e.message()
    );
    // The model is unchanged and still usable.
    assert_eq!(s.model.contact_pairs().len(), before);
    assert_eq!(
        s.model.displacements().unwrap_err().status(),
        Status::InvalidState
    );
}

#[test]
fn results_do_not_depend_on_the_unit_system() {
    let m = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    };
    // Millimetres and megapascals: lengths ×1000, stresses ×1e-6.
    let mm = TwoBlocks {
        e1: m.e1 * 1e-6,
        e2: m.e2 * 1e-6,
        h1: m.h1 * 1e3,
        h2: m.h2 * 1e3,
        length: m.length * 1e3,
        c: m.c * 1e3,
        p: m.p * 1e-6,
        mesh_size: m.mesh_size * 1e3,
        ..m
    };
    let (_, a) = solve(&m);
    let (_, b) = solve(&mm);
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs());
    assert!(close(a.lc * 1e3, b.lc), "{} {}", a.lc, b.lc);
    assert!(close(a.v_top * 1e3, b.v_top), "{} {}", a.v_top, b.v_top);
    assert!(
        close(a.gap_edge * 1e3, b.gap_edge),
        "{} {}",
        a.gap_edge,
        b.gap_edge
    );
    // Work per unit thickness is a force: N in both systems.
    assert!(
        close(a.compliance, b.compliance),
        "{} {}",
        a.compliance,
        b.compliance
    );
}

#[test]
fn the_literal_inversion_test_is_available_and_agrees_on_a_coarse_mesh() {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    };
    let (_, lin) = solve(&scene);
    let mut s = scene.build().unwrap();
    let lit = s
        .solve(&ContactOptions {
            test: InversionTest::Literal,
            ..Default::default()
        })
        .unwrap();
    assert!(
        (lit.lc - lin.lc).abs() <= 1.0 / 32.0,
        "{} vs {}",
        lit.lc,
        lin.lc
    );
}

#[test]
fn the_stick_law_ties_the_surfaces_and_changes_the_contact_length() {
    let scene = TwoBlocks::default();
    let (_, free) = solve(&scene);
    let mut s = scene.build().unwrap();
    let stick = s
        .solve(&ContactOptions {
            law: ContactLaw::Stick,
            ..Default::default()
        })
        .unwrap();
    assert!(
        (stick.lc - free.lc).abs() > 0.1 * free.lc,
        "stick ℓc {} vs frictionless {}",
        stick.lc,
        free.lc
    );
}

#[test]
fn a_user_contact_mesh_is_checked_and_reoriented() {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    };
    let (auto, r_auto) = solve(&scene);
    // The same triangles, every other one given with the wrong orientation.
    let mut tris: Vec<[usize; 3]> = auto
        .model
        .contact_elements()
        .unwrap()
        .iter()
        .map(|e| e.nodes)
        .collect();
    for t in tris.iter_mut().step_by(2) {
        t.swap(0, 1);
    }
    let mut s = scene.build().unwrap();
    s.model.clear_contact_pairs();
    let (_, flipped) = s
        .model
        .add_contact_pair_with_mesh(TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, &tris)
        .unwrap();
    assert_eq!(flipped, tris.len().div_ceil(2));
    let r = s.solve(&ContactOptions::default()).unwrap();
    assert!(
        (r.lc - r_auto.lc).abs() < 1e-12
            && (r.v_top - r_auto.v_top).abs() < 1e-12 * r_auto.v_top.abs()
    );
}

#[test]
fn a_contact_mesh_triangle_on_one_side_only_is_rejected_naming_it() {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    };
    let mut s = scene.build().unwrap();
    let lower: Vec<usize> = interface_pairs(&s.model)
        .iter()
        .map(|p| p.0)
        .take(3)
        .collect();
    s.model.clear_contact_pairs();
    let e = s
        .model
        .add_contact_pair_with_mesh(
            TAG_CONTACT_LOWER,
            TAG_CONTACT_UPPER,
            &[[lower[0], lower[1], lower[2]]],
        )
        .unwrap_err();
    assert_eq!(e.status(), Status::InvalidContact);
    assert!(
        e.message().contains("contact triangle 0"),
        "{}",
        e.message()
    );
}

#[test]
fn a_non_matching_interface_node_switches_to_the_strip_triangulation() {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    };
    let mut s = scene.build().unwrap();
    let conforming = {
        let mut c = scene.build().unwrap();
        c.solve(&ContactOptions::default()).unwrap();
        c.model.contact_elements().unwrap().len()
    };
    s.model.clear_contact_pairs();
    // Shift one upper interface node sideways by a tenth of an element.
    let (_, b) = interface_pairs(&s.model)[5];
    let mesh = s.model.mesh().unwrap().clone();
    let mut nodes = mesh.nodes().to_vec();
    nodes[b][0] += 0.1 / 16.0;
    let edges: Vec<[usize; 2]> = mesh.boundary_edges().iter().map(|e| e.nodes).collect();
    let tags: Vec<i32> = mesh.boundary_edges().iter().map(|e| e.tag).collect();
    let mut shifted =
        tfem::Mesh::new(nodes, mesh.triangles().to_vec(), mesh.body_of().to_vec(), 0).unwrap();
    shifted.set_boundary_edges(&edges, &tags).unwrap();
    let elements = tfem::contact::build(&shifted, 0, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER).unwrap();
    // The zipper makes one triangle per interface edge of either side.
    assert_eq!(elements.len(), conforming);
    let conforming_err =
        tfem::contact::build_conforming(&shifted, 0, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)
            .unwrap_err();
    // The message names the node, its nearest partner and how far off it
    // is, and points to what handles such an interface.
    let message = conforming_err.message();
    assert!(
        message.contains(&format!("node {b}"))
            && message.contains("along the interface")
            && message.contains("strip triangulation")
            && !message.contains("not supported"),
        "{message}"
    );
}

#[test]
fn a_cycling_or_capped_loop_ends_with_not_converged_and_its_history() {
    let mut s = TwoBlocks::default().build().unwrap();
    let e = s
        .solve(&ContactOptions {
            max_iterations: 2,
            ..Default::default()
        })
        .unwrap_err();
    assert_eq!(e.status(), Status::NotConverged);
    assert!(
        e.message().contains("history") && e.message().contains("active"),
        "{}",
        e.message()
    );
    assert_eq!(
        s.model.contact_report().unwrap_err().status(),
        Status::InvalidState
    );
}
