//! Contact tractions where they act. A frictionless interface transmits no
//! tangential traction, curved or straight, matching or not: every element
//! of B measures along one normal per point of the interface, its first
//! side's (docs/method.md §6.15, "One normal per point"), and its law's
//! force is along that normal.
//! Measured along each element's own edge normal instead, the cylinder
//! pressed on a block below (a/16) carried a horizontal contact force of
//! 8.1e-5, 8.4e-5, 1.5e-4 P under rigid sideways shifts of 0, 0.002a,
//! 0.05a (a user's Gmsh scene: 1.7e-3 P), and a sideways load of 1e-2 P
//! cycled. The nodal tractions
//! (pressure and shear per node) carry the loads, both sides one sign.

use tfem::scenes::cattaneo::{
    CattaneoMindlin, TAG_BLOCK_TOP, TAG_CYLINDER, TAG_PLATEN, TAG_SUPPORT,
};
use tfem::scenes::hertz::Hertz;
use tfem::{Component, ContactOptions, ContactWeighting, Model, Status};

/// The Cattaneo–Mindlin scene (a cylinder on a block, equal moduli) at
/// h = a/16, frictionless, its platen pressed down by `press` and shifted
/// sideways by `shift`: (model, P = the normal contact force).
fn pressed_cylinder(press: f64, shift: f64) -> (Model, f64) {
    let base = CattaneoMindlin::default();
    let cm = CattaneoMindlin {
        mu: 0.0,
        mesh_size: base.half_width / 16.0,
        ..base
    };
    let mut scene = cm.build().expect("scene");
    for &v in &scene.platen {
        scene.model.set_prescribed(v, Component::X, shift).unwrap();
        scene.model.set_prescribed(v, Component::Y, -press).unwrap();
    }
    scene
        .model
        .solve_contact(&ContactOptions::default())
        .unwrap();
    let p = cylinder_resultant(&scene.model, scene.n_block_nodes)[1].abs();
    (scene.model, p)
}

/// The resultant of the contact forces on the cylinder's nodes (those after
/// the block's `n_block` first).
fn cylinder_resultant(model: &Model, n_block: usize) -> [f64; 2] {
    let f = model.contact_forces().unwrap();
    f[n_block..]
        .iter()
        .fold([0.0; 2], |s, f| [s[0] + f[0], s[1] + f[1]])
}

#[test]
fn a_rigid_sideways_shift_of_a_pressed_cylinder_meets_no_horizontal_contact_force() {
    let press = 2e-6;
    let a = CattaneoMindlin::default().half_width;
    for shift in [0.0, 0.002 * a, 0.05 * a] {
        let (model, p) = pressed_cylinder(press, shift);
        let n_block = CattaneoMindlin {
            mesh_size: a / 16.0,
            ..Default::default()
        }
        .build()
        .unwrap()
        .n_block_nodes;
        let [fx, _] = cylinder_resultant(&model, n_block);
        assert!(p > 0.0, "the cylinder is pressed");
        assert!(
            fx.abs() <= 1e-8 * p,
            "shift {shift:e}: horizontal resultant {fx:e} of P = {p:e}"
        );
    }
}

#[test]
fn a_frictionless_interface_reads_no_shear_at_any_node() {
    // Hertz: the block first (straight side a), the cylinder first (the
    // normals turn along its chords), and the cylinder's mesh 2.5× coarser
    // with the strip forced (non-matching).
    let base = Hertz::default();
    let cases: [(&str, Hertz, bool); 3] = [
        ("block first", base, false),
        ("cylinder first", base, true),
        (
            "non-matching",
            Hertz {
                cylinder_mesh_ratio: 2.5,
                ..base
            },
            false,
        ),
    ];
    for (name, hertz, flip) in cases {
        let mut scene = hertz.build().unwrap();
        let model = &mut scene.model;
        if flip {
            model.clear_contact_pairs();
            let (a, b) = (
                tfem::scenes::hertz::TAG_CYLINDER,
                tfem::scenes::hertz::TAG_BLOCK_TOP,
            );
            model.add_contact_pair(a, b).unwrap();
        }
        model
            .set_contact_weighting(ContactWeighting::Strip)
            .unwrap();
        model.solve_contact(&ContactOptions::default()).unwrap();
        let t = model.contact_nodal_tractions().unwrap();
        let p_max = t.iter().map(|t| t[0]).fold(0.0, f64::max);
        let s_max = t.iter().map(|t| t[1].abs()).fold(0.0, f64::max);
        assert!(p_max > 0.0, "{name}: in contact");
        assert!(
            s_max <= 1e-8 * p_max,
            "{name}: shear {s_max:e} against a pressure of {p_max:e}"
        );
        let p: Vec<f64> = t.iter().map(|t| t[0]).collect();
        assert_eq!(p, model.contact_nodal_pressures().unwrap(), "{name}");
    }
}

#[test]
fn a_sideways_load_on_a_frictionless_curved_contact_is_refused_as_singular_naming_the_body() {
    // The cylinder's platen free sideways: only friction could hold it.
    let base = CattaneoMindlin::default();
    let scene = CattaneoMindlin {
        mu: 0.0,
        mesh_size: base.half_width / 16.0,
        ..base
    }
    .build()
    .unwrap();
    let mesh = scene.model.mesh().unwrap().clone();
    let (edges, tags): (Vec<[usize; 2]>, Vec<i32>) = mesh
        .boundary_edges()
        .iter()
        .map(|e| (e.nodes, e.tag))
        .unzip();
    let mut model = Model::new();
    model.set_mesh(mesh);
    model.set_boundary_edges(&edges, &tags).unwrap();
    for body in [1, 2] {
        let m = *scene.model.material(body).unwrap();
        model.set_material(body, m).unwrap();
    }
    model.fix_edges(TAG_SUPPORT, Component::X, 0.0).unwrap();
    model.fix_edges(TAG_SUPPORT, Component::Y, 0.0).unwrap();
    model.fix_edges(TAG_PLATEN, Component::Y, -2e-6).unwrap();
    let p = CattaneoMindlin::default().load();
    for &v in &scene.platen {
        let share = 1e-2 * p / scene.platen.len() as f64;
        model.add_nodal_force(v, [share, 0.0]).unwrap();
    }
    model.add_contact_pair(TAG_BLOCK_TOP, TAG_CYLINDER).unwrap();
    let e = model.solve_contact(&ContactOptions::default()).unwrap_err();
    assert_eq!(e.status(), Status::Singular, "{}", e.message());
    assert!(
        e.message().contains("body 2") && e.message().contains("translation in x"),
        "{}",
        e.message()
    );
}

#[test]
fn the_nodal_shear_carries_the_tangential_load_with_one_sign_on_both_sides() {
    // Cattaneo–Mindlin at a/16, μ = 0.3: pressed, then shifted sideways by
    // a tenth of the press. Measured: Σ τ m over the block's top = the
    // tangential contact force within 7.4e-8; |τ|/p = 0.3 at the slipping
    // edges, ~0.03 in the sticking centre.
    let mu = 0.3;
    let base = CattaneoMindlin::default();
    let mut scene = CattaneoMindlin {
        mesh_size: base.half_width / 16.0,
        ..base
    }
    .build()
    .unwrap();
    scene.model.set_friction(0, mu).unwrap();
    let press = 2e-6;
    for shift in [0.0, 0.1 * press] {
        for &v in &scene.platen {
            scene.model.set_prescribed(v, Component::X, shift).unwrap();
            scene.model.set_prescribed(v, Component::Y, -press).unwrap();
        }
        scene.model.step(1.0, &ContactOptions::default()).unwrap();
    }
    let n_block = scene.n_block_nodes;
    let [q, _] = cylinder_resultant(&scene.model, n_block);
    let xy = scene.model.mesh().unwrap().nodes();
    let t = scene.model.contact_nodal_tractions().unwrap();
    let mut top: Vec<usize> = (0..n_block).filter(|&v| xy[v][1] == 0.0).collect();
    top.sort_by(|a, b| xy[*a][0].total_cmp(&xy[*b][0]));
    // The block's top is straight: a node's tributary is half its edges.
    let length = |k: usize, j: usize| (xy[top[j]][0] - xy[top[k]][0]).abs();
    let carried: f64 = (0..top.len())
        .map(|k| {
            let left = if k > 0 { length(k - 1, k) } else { 0.0 };
            let right = if k + 1 < top.len() {
                length(k, k + 1)
            } else {
                0.0
            };
            t[top[k]][1] * 0.5 * (left + right)
        })
        .sum();
    assert!(q.abs() > 0.0);
    assert!(
        (carried - q).abs() <= 1e-6 * q.abs(),
        "Σ τ m = {carried:e}, Q = {q:e}"
    );
    let in_contact = |v: &usize| t[*v][0] > 0.0;
    let slip = (top.iter().filter(|v| in_contact(v)))
        .map(|&v| t[v][1].abs() / t[v][0])
        .fold(0.0, f64::max);
    assert!((slip - mu).abs() <= 1e-6 * mu, "largest |τ|/p {slip}");
    // Both sides read one traction with one sign: each cylinder node in
    // contact reads the shear of the block node under it (the meshes
    // match), wherever that shear is more than rounding. (Not the sign of
    // Q at every node: the press itself leaves a shear of either sign,
    // which each element keeps from where it closed.)
    let p0 = top.iter().map(|&v| t[v][0]).fold(0.0, f64::max);
    let cylinder: Vec<usize> = (n_block..xy.len()).filter(in_contact).collect();
    assert!(!cylinder.is_empty());
    for v in cylinder {
        let Some(&under) = top.iter().find(|&&b| xy[b][0] == xy[v][0]) else {
            continue;
        };
        if t[under][1].abs() > 1e-3 * mu * p0 {
            assert!(
                t[v][1] * t[under][1] > 0.0,
                "node {v}: {} against {}",
                t[v][1],
                t[under][1]
            );
        }
    }
}
