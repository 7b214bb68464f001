//! Non-conforming interfaces (docs/method.md §5): the contact mesh B triangulates
//! the strip between two interface polylines whose nodes do not match; the
//! activation of inverted elements applies unchanged.

use tfem::meshgen::{Diagonal, MeshBuilder};
use tfem::scenes::TwoBlocks;
use tfem::{ContactOptions, Model, Status};

fn solve(scene: TwoBlocks) -> (tfem::scenes::TwoBlocksScene, tfem::scenes::TwoBlocksResult) {
    let mut s = scene.build().unwrap();
    let r = s.solve(&ContactOptions::default()).unwrap();
    (s, r)
}

#[test]
fn uniform_pressure_is_transmitted_across_non_matching_meshes_to_round_off() {
    // docs/method.md §6.11: with T_e = ℓ_e h_c²/λ every element of the strip
    // carries κ ℓ_e/2 on the gap at its apex, and the nodal forces of a
    // uniform gap are the consistent loads of a uniform traction on both
    // sides: the patch test passes exactly. (Before, with T_e = h_e³/λ: L2
    // error 3.1e-2 → 5.2e-3 of p from h = 1/16 to 1/128, maximum 10 % → 4 %.)
    // Measured: max 2.2e-14 … 3.2e-12, L2 9.0e-15 … 5.9e-13.
    for n in [16, 32, 64, 128] {
        let h = 1.0 / n as f64;
        // Upper block 7/3 as coarse: almost no interface node matches.
        let scene = TwoBlocks {
            c: 0.5,
            mesh_size: h,
            upper_mesh_size: Some(h * 7.0 / 3.0),
            ..Default::default()
        };
        let (s, r) = solve(scene);
        assert!((r.lc - 1.0).abs() < 1e-9, "h = 1/{n}: ℓc = {}", r.lc);
        let load = scene.p * scene.length;
        assert!(
            (r.support_reaction - load).abs() < 1e-9 * load,
            "the whole load is transmitted"
        );
        let p = scene.p;
        let mesh = s.model.mesh().unwrap();
        let (mut sum, mut area, mut worst) = (0.0, 0.0, 0.0f64);
        for (t, sig) in mesh
            .triangles()
            .iter()
            .zip(s.model.element_stresses().unwrap())
        {
            let a = 0.5 * tfem::TriGeometry::new(&mesh.corners(t)).j;
            let e2 = ((sig[1] + p).powi(2) + sig[0].powi(2) + sig[2].powi(2)) / (p * p);
            sum += a * e2;
            area += a;
            worst = worst.max(e2.sqrt());
        }
        let l2 = (sum / area).sqrt();
        println!("h = 1/{n}: stress error / p: L2 {l2:.2e}, max {worst:.2e}");
        assert!(
            worst < 1e-10 && l2 < 1e-11,
            "h = 1/{n}: max {worst}, L2 {l2}"
        );
        // Every element pushes with the traction p.
        for (q, on) in s
            .model
            .contact_pressure()
            .unwrap()
            .iter()
            .zip(s.model.contact_active().unwrap())
        {
            assert!(*on && (q / p - 1.0).abs() < 1e-9, "pressure {q}");
        }
    }
}

#[test]
fn seed_scene_on_non_matching_meshes_agrees_with_the_conforming_run_within_discretisation_error() {
    let h = 1.0 / 96.0;
    let (_, conf) = solve(TwoBlocks {
        mesh_size: h,
        ..Default::default()
    });
    let (_, coarse) = solve(TwoBlocks {
        mesh_size: 3.0 * h,
        ..Default::default()
    });
    let (_, nc) = solve(TwoBlocks {
        mesh_size: h,
        upper_mesh_size: Some(3.0 * h),
        ..Default::default()
    });
    // Error estimate of the conforming run: its distance to the run 3x coarser.
    for (name, a, b, est) in [
        (
            "gap_edge",
            nc.gap_edge,
            conf.gap_edge,
            (coarse.gap_edge - conf.gap_edge).abs(),
        ),
        (
            "v_top",
            nc.v_top,
            conf.v_top,
            (coarse.v_top - conf.v_top).abs(),
        ),
        (
            "compliance",
            nc.compliance,
            conf.compliance,
            (coarse.compliance - conf.compliance).abs(),
        ),
    ] {
        assert!(
            (a - b).abs() <= est,
            "{name}: non-matching {a} vs conforming {b} (estimate {est})"
        );
    }
    assert!(
        (nc.lc - conf.lc).abs() <= 3.0 * 3.0 * h,
        "ℓc {} vs {}",
        nc.lc,
        conf.lc
    );
    assert!(nc.gap_edge > 0.0 && nc.lc < 1.0);
}

#[test]
fn very_different_mesh_sizes_build_and_solve() {
    // 1:20 between the two sides of the interface.
    let (_, r) = solve(TwoBlocks {
        mesh_size: 1.0 / 200.0,
        upper_mesh_size: Some(1.0 / 10.0),
        ..Default::default()
    });
    assert!(r.gap_edge > 0.0 && r.lc > 0.2 && r.lc < 1.0, "{r:?}");
}

/// Two rectangles stacked along y = 0: the lower one [0, 1] with `n1` cells,
/// the upper one [x0, x1] with `n2` cells, interfaces tagged 1 and 2.
fn stacked(n1: usize, x0: f64, x1: f64, n2: usize) -> Model {
    let mut b = MeshBuilder::new();
    let xs1: Vec<f64> = (0..=n1).map(|i| i as f64 / n1 as f64).collect();
    let xs2: Vec<f64> = (0..=n2)
        .map(|i| x0 + (x1 - x0) * i as f64 / n2 as f64)
        .collect();
    b.add_grid(&xs1, &[-0.2, 0.0], 1, Diagonal::Forward);
    let n_lower = b.nodes.len();
    b.add_grid(&xs2, &[0.0, 0.2], 2, Diagonal::Forward);
    let (mut edges, mut tags) = (Vec::new(), Vec::new());
    for e in b.boundary_edges() {
        let (p, q) = (b.nodes[e[0]], b.nodes[e[1]]);
        if p[1] == 0.0 && q[1] == 0.0 {
            edges.push(e);
            tags.push(if e[0] < n_lower { 1 } else { 2 });
        }
    }
    let mut m = Model::new();
    m.set_mesh(b.build().unwrap());
    m.set_boundary_edges(&edges, &tags).unwrap();
    m
}

#[test]
fn the_strip_covers_only_where_the_interfaces_face_each_other() {
    // The upper block spans [0.3, 0.7] only, with offset nodes.
    let mut m = stacked(10, 0.3, 0.7, 7);
    m.add_contact_pair(1, 2).unwrap();
    let mesh = m.mesh().unwrap().clone();
    let elements = tfem::contact::build(&mesh, 0, 1, 2).unwrap();
    for e in &elements {
        for &v in &e.nodes {
            let x = mesh.nodes()[v][0];
            assert!(
                (0.2 - 1e-12..=0.8 + 1e-12).contains(&x),
                "node at x = {x} outside the facing range ± one edge"
            );
        }
        // Oriented so that J grows when the gap opens (upper nodes move up).
        let geo = tfem::TriGeometry::new(&mesh.corners(&e.nodes));
        let opening: f64 = (0..3)
            .filter(|&k| mesh.node_body()[e.nodes[k]] == Some(2))
            .map(|k| geo.g[k][1])
            .sum();
        assert!(opening > 0.0);
    }
    let covered: f64 = elements.iter().map(|e| 0.5 * e.edge_length).sum();
    assert!(
        (0.4 - 1e-12..=0.4 + 0.2 + 1e-12).contains(&covered),
        "{covered}"
    );
}

#[test]
fn coincident_and_nearly_coincident_nodes_are_handled() {
    // 10 vs 10 cells shifted by 1e-9: nearly coincident, not matching within
    // the conforming tolerance only when the shift is tangential enough.
    let mut m = stacked(10, 1e-9, 1.0 + 1e-9, 10);
    m.add_contact_pair(1, 2).unwrap();
    let mesh = m.mesh().unwrap().clone();
    let elements = tfem::contact::build(&mesh, 0, 1, 2).unwrap();
    assert_eq!(elements.len(), 20);
}

#[test]
fn a_closed_or_branching_interface_is_rejected_naming_it() {
    let mut m = stacked(4, 0.0, 1.0, 3);
    let mesh = m.mesh().unwrap().clone();
    let mut edges: Vec<[usize; 2]> = mesh.boundary_edges().iter().map(|e| e.nodes).collect();
    let mut tags: Vec<i32> = mesh.boundary_edges().iter().map(|e| e.tag).collect();
    // Tag an edge of the upper block's top as interface 2 too: two pieces.
    let side = mesh
        .triangles()
        .iter()
        .zip(mesh.body_of())
        .filter(|(_, b)| **b == 2)
        .flat_map(|(t, _)| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
        .find(|e| mesh.nodes()[e[0]][1] == 0.2 && mesh.nodes()[e[1]][1] == 0.2)
        .unwrap();
    edges.push(side);
    tags.push(2);
    m.set_boundary_edges(&edges, &tags).unwrap();
    let e = m.add_contact_pair(1, 2).unwrap_err();
    assert_eq!(e.status(), Status::InvalidContact);
    assert!(
        e.message().contains("tag 2 has 2 separate pieces"),
        "{}",
        e.message()
    );
}
