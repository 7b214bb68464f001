//! The 3D model (`tfem::model::solid`): a tetrahedral mesh with tagged
//! faces, materials, constraints, loads and contact pairs between tagged
//! surfaces, solved by the product's loop — held to exact solutions, to the
//! 3D study's independent prototype, to equilibrium, and to its refusals.

use tfem::fem::solid_mesh::{Brick, SolidMesh};
use tfem::model::solid::{Axis, SolidMaterial, SolidModel};
use tfem::studies::tet_contact::ContactLoop;
use tfem::studies::tet_scenes::TwoBlocks3d;
use tfem::{ContactOptions, Tempering};

/// A unit cube of body 1 (sides tagged 1…6: x = 0, x = 1, y = 0, y = 1,
/// z = 0, z = 1), E = 200, ν = 0.3, on rollers on x = 0, y = 0, z = 0.
fn cube(cells: usize) -> SolidModel {
    let mesh = SolidMesh::bricks(&[Brick::uniform([0.0; 3], [1.0; 3], [cells; 3], 1)]).unwrap();
    let mut model = SolidModel::new();
    model.set_mesh(mesh);
    model.set_material(1, SolidMaterial::new(200.0, 0.3).unwrap());
    model.fix_faces(1, Axis::X, 0.0).unwrap();
    model.fix_faces(3, Axis::Y, 0.0).unwrap();
    model.fix_faces(5, Axis::Z, 0.0).unwrap();
    model
}

#[test]
fn a_cube_under_uniform_pressure_is_exact_to_round_off() {
    let mut model = cube(3);
    model.add_pressure(6, 2.0).unwrap();
    let info = model.solve().unwrap();
    assert_eq!(info.interface_unknowns, 0);
    // σ_zz = −2 alone: ε_zz = −2/200, ε_xx = ε_yy = −ν ε_zz.
    let (e, nu, p) = (200.0, 0.3, 2.0);
    let mesh = model.mesh().unwrap();
    for (x, u) in mesh.nodes().iter().zip(model.displacements().unwrap()) {
        let exact = [nu * p / e * x[0], nu * p / e * x[1], -p / e * x[2]];
        for c in 0..3 {
            assert!(
                (u[c] - exact[c]).abs() < 1e-14,
                "{x:?}: {u:?} against {exact:?}"
            );
        }
    }
    for s in model.element_stresses().unwrap() {
        let want = [0.0, 0.0, -p, 0.0, 0.0, 0.0];
        assert!((0..6).all(|c| (s[c] - want[c]).abs() < 1e-12), "{s:?}");
    }
}

#[test]
fn without_contact_pairs_the_solve_builds_no_contact_structure() {
    let mut model = cube(2);
    model.add_traction(2, [1.0, 0.0, 0.0]).unwrap();
    let info = model.solve().unwrap();
    assert_eq!(model.contact_tetrahedra().unwrap().len(), 0);
    assert_eq!(model.iterations().unwrap(), 1);
    let history = model.contact_history().unwrap();
    assert!(
        history.len() == 1 && history[0].active + history[0].switched_on == 0,
        "{history:?}"
    );
    assert_eq!(info.factorizations, 1);
    let area = model.contact_area().unwrap();
    assert!(area == 0.0 && area.is_sign_positive(), "{area:?}");
}

#[test]
fn reactions_balance_the_loads() {
    let mut model = cube(2);
    model.add_pressure(6, 3.0).unwrap();
    model.add_nodal_force(26, [0.0, 0.0, -0.5]).unwrap();
    model.solve().unwrap();
    let total: [f64; 3] = (model.reactions().unwrap().iter())
        .fold([0.0; 3], |a, r| [a[0] + r[0], a[1] + r[1], a[2] + r[2]]);
    // The support carries p·A plus the nodal force, upwards.
    assert!((total[2] - 3.5).abs() < 1e-12, "{total:?}");
    assert!(
        total[0].abs() < 1e-12 && total[1].abs() < 1e-12,
        "{total:?}"
    );
}

/// The seed scene in 3D at h = 1/20, as the study builds it.
fn seed(contact_loop: ContactLoop) -> TwoBlocks3d {
    TwoBlocks3d {
        h: 0.05,
        contact_loop,
        ..TwoBlocks3d::default()
    }
}

#[test]
fn the_seed_scene_through_the_model_equals_the_studys_prototype() {
    let model = seed(ContactLoop::Product).solve_model().unwrap();
    let study = seed(ContactLoop::Study).solve().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-10 * b.abs();
    assert!(
        close(model.contact_area, study.contact_area),
        "{model:?}\n{study:?}"
    );
    assert!(
        close(model.gap_corner, study.gap_corner),
        "{model:?}\n{study:?}"
    );
    assert!(close(model.v_top, study.v_top), "{model:?}\n{study:?}");
    assert!(
        close(model.compliance, study.compliance),
        "{model:?}\n{study:?}"
    );
    assert_eq!(model.unknowns, study.unknowns);
}

#[test]
fn the_seed_scenes_contact_carries_the_whole_load_and_lifts_off_at_the_corner() {
    let scene = seed(ContactLoop::Product);
    let r = scene.solve_model().unwrap();
    assert!((r.transmitted - 1.0).abs() < 1e-9, "{r:?}");
    assert!(r.gap_corner > 0.0, "the corner opens: {r:?}");
    assert!(r.contact_area > 0.0 && r.contact_area < 1.0, "{r:?}");
}

#[test]
fn the_contact_history_accounts_for_every_switch_to_the_final_set() {
    let scene = seed(ContactLoop::Product);
    let mut model = scene.model().unwrap();
    model.solve_contact(&scene.options()).unwrap();
    let history = model.contact_history().unwrap();
    assert_eq!(history.len(), model.iterations().unwrap());
    assert!(history.len() > 1, "the seed scene lifts off: {history:?}");
    for w in history.windows(2) {
        assert_eq!(
            w[1].active + w[0].switched_off,
            w[0].active + w[0].switched_on,
            "{history:?}"
        );
    }
    let last = history.last().unwrap();
    assert_eq!((last.switched_on, last.switched_off), (0, 0), "{history:?}");
    let on = model
        .contact_active()
        .unwrap()
        .iter()
        .filter(|&&a| a)
        .count();
    assert_eq!(last.active, on);
}

#[test]
fn contact_pressures_integrate_to_the_load() {
    let scene = seed(ContactLoop::Product);
    let mut model = scene.model().unwrap();
    model.solve_contact(&scene.options()).unwrap();
    let mesh = model.mesh().unwrap();
    let pressures = model.contact_nodal_pressures().unwrap();
    // Ω2's bottom (tag 25): Σ p_v A_v over its nodes.
    let mut area = vec![0.0; pressures.len()];
    for f in mesh.boundary_faces().iter().filter(|f| f.tag == 25) {
        let a = mesh.face_geometry(f).area;
        f.nodes.iter().for_each(|&v| area[v] += a / 3.0);
    }
    let force: f64 = (0..area.len()).map(|v| pressures[v] * area[v]).sum();
    let load = scene.pressure * scene.c * scene.c;
    assert!((force - load).abs() < 1e-9 * load, "{force} against {load}");
    assert!(pressures.iter().all(|p| p.is_finite()));
}

#[test]
fn an_unsupported_body_is_named_with_its_free_motion() {
    let mut model = cube(1);
    model.clear_constraints();
    model.add_pressure(6, 1.0).unwrap();
    let err = model.solve().unwrap_err();
    assert!(err.message().contains("body 1"), "{}", err.message());
}

#[test]
fn a_body_without_material_is_refused_by_its_tag() {
    let mesh = SolidMesh::bricks(&[Brick::uniform([0.0; 3], [1.0; 3], [1; 3], 4)]).unwrap();
    let mut model = SolidModel::new();
    model.set_mesh(mesh);
    let err = model.solve().unwrap_err();
    assert!(
        err.message().contains("body 4 has no material"),
        "{}",
        err.message()
    );
}

#[test]
fn bad_constraints_and_loads_are_refused_and_leave_the_model_as_it_was() {
    let mut model = cube(1);
    model.add_pressure(6, 1.0).unwrap();
    model.solve().unwrap();
    let before = model.displacements().unwrap();
    for err in [
        model.fix(8, Axis::X, 0.0).unwrap_err(),
        model.fix(0, Axis::X, f64::NAN).unwrap_err(),
        model.fix_faces(9, Axis::Z, 0.0).unwrap_err(),
        model.add_pressure(6, f64::INFINITY).unwrap_err(),
        model.add_traction(7, [1.0, 0.0, 0.0]).unwrap_err(),
        model.add_contact_pair(6, 6).unwrap_err(),
        model.set_tempering(Tempering::Lambda(-1.0)).unwrap_err(),
    ] {
        assert!(!err.message().is_empty());
    }
    assert_eq!(model.displacements().unwrap(), before);
    assert!(
        model
            .fix(8, Axis::X, 0.0)
            .unwrap_err()
            .message()
            .contains("node 8")
    );
    assert!(
        model
            .fix_faces(9, Axis::Z, 0.0)
            .unwrap_err()
            .message()
            .contains("tag 9")
    );
}

/// Two unit cubes stacked (bodies 1 and 2), meshed alike, sides tagged
/// 1…6 and 11…16.
fn stacked(upper_cells: usize) -> SolidModel {
    let lower = Brick::uniform([0.0, 0.0, -1.0], [1.0, 1.0, 0.0], [2; 3], 1);
    let mut upper = Brick::uniform([0.0; 3], [1.0; 3], [upper_cells; 3], 2);
    upper.side_tags = [11, 12, 13, 14, 15, 16];
    let mut model = SolidModel::new();
    model.set_mesh(SolidMesh::bricks(&[lower, upper]).unwrap());
    for body in [1, 2] {
        model.set_material(body, SolidMaterial::new(1.0, 0.25).unwrap());
    }
    model.fix_faces(5, Axis::Z, 0.0).unwrap();
    for tag in [1, 11] {
        model.fix_faces(tag, Axis::X, 0.0).unwrap();
    }
    for tag in [3, 13] {
        model.fix_faces(tag, Axis::Y, 0.0).unwrap();
    }
    model.add_pressure(16, 0.1).unwrap();
    model
}

#[test]
fn stacked_cubes_in_contact_pass_the_patch_test() {
    let mut model = stacked(2);
    model.add_contact_pair(6, 15).unwrap();
    model.solve().unwrap();
    assert!(model.contact_active().unwrap().iter().all(|&on| on));
    assert!((model.contact_area().unwrap() - 1.0).abs() < 1e-12);
    for s in model.element_stresses().unwrap() {
        let want = [0.0, 0.0, -0.1, 0.0, 0.0, 0.0];
        assert!((0..6).all(|c| (s[c] - want[c]).abs() < 1e-9), "{s:?}");
    }
    let pressures = model.contact_nodal_pressures().unwrap();
    let mesh = model.mesh().unwrap();
    for f in mesh.boundary_faces().iter().filter(|f| f.tag == 15) {
        for &v in &f.nodes {
            assert!(
                (pressures[v] - 0.1).abs() < 1e-9,
                "node {v}: {}",
                pressures[v]
            );
        }
    }
}

#[test]
fn a_pair_whose_meshes_do_not_match_is_refused_by_its_tags() {
    let mut model = stacked(3);
    model.add_contact_pair(6, 15).unwrap();
    let err = model.solve().unwrap_err();
    let m = err.message();
    assert!(m.contains("contact pair 0 (tags 6 and 15)"), "{m}");
}

#[test]
fn a_pair_on_one_body_is_refused() {
    let mut model = stacked(2);
    model.add_contact_pair(6, 5).unwrap();
    let err = model.solve().unwrap_err();
    assert!(err.message().contains("self-contact"), "{}", err.message());
}

#[test]
fn contact_options_that_3d_does_not_read_are_refused() {
    let mut model = stacked(2);
    model.add_contact_pair(6, 15).unwrap();
    let options = ContactOptions {
        law: tfem::ContactLaw::Stick,
        ..ContactOptions::default()
    };
    let err = model.solve_contact(&options).unwrap_err();
    assert!(err.message().contains("frictionless"), "{}", err.message());
}

/// Two unit cubes of body 1 and 2, the upper lifted by `gap`, its top
/// pushed down by `push` (prescribed), both on rollers.
fn pushed_apart(gap: f64, push: f64) -> SolidModel {
    let lower = Brick::uniform([0.0, 0.0, -1.0], [1.0, 1.0, 0.0], [2; 3], 1);
    let mut upper = Brick::uniform([0.0, 0.0, gap], [1.0, 1.0, 1.0 + gap], [2; 3], 2);
    upper.side_tags = [11, 12, 13, 14, 15, 16];
    let mut model = SolidModel::new();
    model.set_mesh(SolidMesh::bricks(&[lower, upper]).unwrap());
    for body in [1, 2] {
        model.set_material(body, SolidMaterial::new(1.0, 0.25).unwrap());
    }
    model.fix_faces(5, Axis::Z, 0.0).unwrap();
    model.fix_faces(16, Axis::Z, -push).unwrap();
    for tag in [1, 11] {
        model.fix_faces(tag, Axis::X, 0.0).unwrap();
    }
    for tag in [3, 13] {
        model.fix_faces(tag, Axis::Y, 0.0).unwrap();
    }
    model.add_contact_pair(6, 15).unwrap();
    model
}

#[test]
fn load_steps_reach_the_direct_solution_and_analyse_once() {
    let scene = seed(ContactLoop::Product);
    let mut direct = scene.model().unwrap();
    direct.solve_contact(&scene.options()).unwrap();
    let mut history = scene.model().unwrap();
    let first = history.step(0.5, &scene.options()).unwrap();
    let last = history.step(1.0, &scene.options()).unwrap();
    assert!(first.timings.analysis > 0.0);
    assert_eq!(last.timings.analysis, 0.0, "the second step analyses again");
    // Without initial gaps the set does not depend on the load's size: the
    // warm-started step settles at once.
    assert_eq!(history.iterations().unwrap(), 1);
    let (a, b) = (
        direct.displacements().unwrap(),
        history.displacements().unwrap(),
    );
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for (p, q) in a.iter().zip(&b) {
        assert!(
            (0..3).all(|c| (p[c] - q[c]).abs() < 1e-10 * scale),
            "{p:?} against {q:?}"
        );
    }
}

#[test]
fn a_gap_closes_at_the_step_whose_push_exceeds_it() {
    let (gap, push) = (0.01, 0.03);
    let mut model = pushed_apart(gap, push);
    let options = ContactOptions::default();
    model.step(0.25, &options).unwrap();
    assert!(model.contact_active().unwrap().iter().all(|&on| !on));
    let lower_still = (model.displacements().unwrap().iter())
        .zip(model.mesh().unwrap().node_body())
        .filter(|(_, b)| **b == Some(1))
        .all(|(u, _)| u.iter().all(|x| x.abs() < 1e-15));
    assert!(lower_still, "the lower cube moves before the gap closes");
    model.step(1.0, &options).unwrap();
    assert!(model.contact_active().unwrap().iter().all(|&on| on));
    let mut direct = pushed_apart(gap, push);
    direct.solve().unwrap();
    let (a, b) = (
        direct.displacements().unwrap(),
        model.displacements().unwrap(),
    );
    for (p, q) in a.iter().zip(&b) {
        assert!(
            (0..3).all(|c| (p[c] - q[c]).abs() < 1e-12 * push),
            "{p:?} against {q:?}"
        );
    }
}

#[test]
fn reverting_a_step_brings_back_the_one_before() {
    let mut model = pushed_apart(0.01, 0.03);
    let options = ContactOptions::default();
    model.step(0.25, &options).unwrap();
    let before = model.displacements().unwrap();
    model.step(1.0, &options).unwrap();
    model.revert_step().unwrap();
    assert_eq!(model.displacements().unwrap(), before);
    assert!(model.revert_step().is_err(), "only one step back");
    assert!(model.step(f64::NAN, &options).is_err());
    assert_eq!(model.displacements().unwrap(), before);
}

#[test]
fn a_pair_given_twice_is_refused_at_the_solve() {
    let mut model = stacked(2);
    model.add_contact_pair(6, 15).unwrap();
    model.add_contact_pair(6, 15).unwrap();
    let err = model.solve().unwrap_err();
    assert!(err.message().contains("pairs 0 and 1"), "{}", err.message());
}

#[test]
fn two_tools_on_one_surface_read_the_pressure_of_each() {
    // Two cubes side by side on a block's top (tag 6): the block's top is
    // side b of both pairs (each cube's bottom, planar, is side a), and
    // each of its faces faces one cube.
    let block = Brick::uniform([0.0, 0.0, -1.0], [2.0, 1.0, 0.0], [4, 2, 2], 1);
    let mut left = Brick::uniform([0.0; 3], [1.0, 1.0, 1.0], [2; 3], 2);
    left.side_tags = [21, 22, 23, 24, 25, 26];
    let mut right = Brick::uniform([1.0, 0.0, 0.0], [2.0, 1.0, 1.0], [2; 3], 3);
    right.side_tags = [31, 32, 33, 34, 35, 36];
    let mut model = SolidModel::new();
    model.set_mesh(SolidMesh::bricks(&[block, left, right]).unwrap());
    for body in [1, 2, 3] {
        model.set_material(body, SolidMaterial::new(1.0, 0.25).unwrap());
    }
    model.fix_faces(5, Axis::Z, 0.0).unwrap();
    for tag in [1, 21, 31] {
        model.fix_faces(tag, Axis::X, 0.0).unwrap();
    }
    for tag in [3, 23, 33] {
        model.fix_faces(tag, Axis::Y, 0.0).unwrap();
    }
    // Each tool on rollers against its neighbour's side too.
    model.fix_faces(22, Axis::X, 0.0).unwrap();
    model.fix_faces(32, Axis::X, 0.0).unwrap();
    model.fix_faces(2, Axis::X, 0.0).unwrap();
    model.add_pressure(26, 0.1).unwrap();
    model.add_pressure(36, 0.1).unwrap();
    model.add_contact_pair(25, 6).unwrap();
    model.add_contact_pair(35, 6).unwrap();
    model.solve().unwrap();
    assert!((model.contact_area().unwrap() - 2.0).abs() < 1e-12);
    let pressures = model.contact_nodal_pressures().unwrap();
    let mesh = model.mesh().unwrap();
    for f in mesh.boundary_faces().iter().filter(|f| f.tag == 6) {
        for &v in &f.nodes {
            assert!(
                (pressures[v] - 0.1).abs() < 1e-9,
                "block node {v}: {}",
                pressures[v]
            );
        }
    }
}
