//! Contact for 3D host codes (`tfem::contact::host_solid`): a host with
//! its own assembly, its own dense solver and its own active-set loop,
//! taking only B's contributions from tfem in its 1-based equations, must
//! land on the 3D model's solution of the same scene.

use nalgebra::{DMatrix, DVector};
use tfem::ContactOptions;
use tfem::contact::host_solid::{HostSurface, SolidHostContact};
use tfem::fem::solid_assembly::SolidBodies;
use tfem::fem::solid_mesh::SolidMesh;
use tfem::fem::tet::isotropic_d;
use tfem::model::solid::{Axis, SolidModel};
use tfem::studies::tet_scenes::{TwoBlocks3d, tags};
use tfem::{Error, Tempering};

/// A coarse seed scene whose contact lifts off at the corner.
fn scene() -> TwoBlocks3d {
    TwoBlocks3d {
        c: 0.25,
        h: 0.125,
        ..TwoBlocks3d::default()
    }
}

/// The host's numbering: node v is host node v + 1; each free DOF gets
/// the next equation from 1, a prescribed (zero) one gets 0.
struct Host {
    equations: Vec<[i64; 3]>,
    n: usize,
}

impl Host {
    fn new(model: &SolidModel) -> Host {
        let mesh = model.mesh().unwrap();
        let fixed: std::collections::BTreeSet<(usize, Axis)> =
            model.constraints().map(|(v, a, _)| (v, a)).collect();
        let mut n = 0;
        let equations = (0..mesh.nodes().len())
            .map(|v| {
                [Axis::X, Axis::Y, Axis::Z].map(|a| match fixed.contains(&(v, a)) {
                    true => 0,
                    false => {
                        n += 1;
                        n as i64
                    }
                })
            })
            .collect();
        Host { equations, n }
    }
}

/// The faces tagged `tag`, numbered counter-clockwise seen from outside,
/// in host node numbers.
fn outward_triangles(mesh: &SolidMesh, tag: i32) -> Vec<[i64; 3]> {
    (mesh.boundary_faces().iter())
        .filter(|f| f.tag == tag)
        .map(|f| {
            let x = f.nodes.map(|v| mesh.nodes()[v]);
            let (u, w) = (
                [0, 1, 2].map(|c| x[1][c] - x[0][c]),
                [0, 1, 2].map(|c| x[2][c] - x[0][c]),
            );
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            let out = mesh.face_geometry(f).normal;
            let [a, b, c] = f.nodes.map(|v| v as i64 + 1);
            match n[0] * out[0] + n[1] * out[1] + n[2] * out[2] > 0.0 {
                true => [a, b, c],
                false => [a, c, b],
            }
        })
        .collect()
}

/// A side's arrays in the host's numbering.
struct SideData {
    tag: i32,
    body: i32,
    young: f64,
    nodes: Vec<i64>,
    xyz: Vec<[f64; 3]>,
    equations: Vec<[i64; 3]>,
    triangles: Vec<[i64; 3]>,
}

impl SideData {
    /// The side of the faces tagged `tag` of body `body`.
    fn new(mesh: &SolidMesh, host: &Host, tag: i32, body: i32, young: f64) -> SideData {
        let triangles = outward_triangles(mesh, tag);
        let mut nodes: Vec<i64> = triangles.iter().flatten().copied().collect();
        nodes.sort_unstable();
        nodes.dedup();
        SideData {
            tag,
            body,
            young,
            xyz: nodes
                .iter()
                .map(|&v| mesh.nodes()[v as usize - 1])
                .collect(),
            equations: nodes
                .iter()
                .map(|&v| host.equations[v as usize - 1])
                .collect(),
            nodes,
            triangles,
        }
    }

    fn surface(&self) -> HostSurface<'_> {
        HostSurface {
            tag: self.tag,
            body: self.body,
            young: self.young,
            nodes: &self.nodes,
            xyz: &self.xyz,
            equations: &self.equations,
            triangles: &self.triangles,
        }
    }
}

fn contact(mesh: &SolidMesh, host: &Host, scene: &TwoBlocks3d) -> SolidHostContact {
    let options = ContactOptions {
        lambda: Some(scene.l),
        ..ContactOptions::default()
    };
    let mut contact = SolidHostContact::new(1, options).unwrap();
    let a = SideData::new(mesh, host, tags::LOWER_SIDES[5], 1, scene.young[0]);
    let b = SideData::new(mesh, host, tags::UPPER_SIDES[4], 2, scene.young[1]);
    let a = contact.add_side(&a.surface()).unwrap();
    let b = contact.add_side(&b.surface()).unwrap();
    contact.add_pair(a, b).unwrap();
    contact
}

/// The host's own matrix (dense, 0-based rows for its 1-based equations)
/// and load.
fn host_system(mesh: &SolidMesh, host: &Host, scene: &TwoBlocks3d) -> (DMatrix<f64>, DVector<f64>) {
    let d = [0, 1].map(|b| isotropic_d(scene.young[b], scene.poisson[b]).unwrap());
    let bodies = SolidBodies {
        mesh,
        d: &d,
        tempering: Tempering::Auto,
    };
    let mut k = DMatrix::zeros(host.n, host.n);
    for (e, t) in mesh.tets().iter().enumerate() {
        let ke = bodies.matrix(e).unwrap();
        let eq: Vec<i64> = (0..12).map(|i| host.equations[t[i / 3]][i % 3]).collect();
        for i in 0..12 {
            for j in 0..12 {
                if eq[i] > 0 && eq[j] > 0 {
                    k[(eq[i] as usize - 1, eq[j] as usize - 1)] += ke[12 * i + j];
                }
            }
        }
    }
    let mut f = DVector::zeros(host.n);
    for face in mesh.boundary_faces().iter().filter(|f| f.tag == tags::LOAD) {
        let g = mesh.face_geometry(face);
        for &v in &face.nodes {
            for c in 0..3 {
                let e = host.equations[v][c];
                if e > 0 {
                    f[e as usize - 1] -= scene.pressure * g.normal[c] * g.area / 3.0;
                }
            }
        }
    }
    (k, f)
}

/// The host's loop: solve with B's current contributions, ask tfem which
/// tetrahedra would invert, until the set stands.
fn host_solve(
    contact: &mut SolidHostContact,
    k: &DMatrix<f64>,
    f: &DVector<f64>,
) -> (DVector<f64>, usize) {
    let (rows, cols) = contact.pattern().unwrap();
    let (rows, cols) = (rows.to_vec(), cols.to_vec());
    let n_local = 3 * contact.nodes().len();
    for iteration in 1..=20 {
        let mut values = vec![0.0; rows.len()];
        let mut r0 = vec![0.0; n_local];
        contact
            .evaluate(&vec![0.0; n_local], Some(&mut values), Some(&mut r0))
            .unwrap();
        let mut kt = k.clone();
        for ((&i, &j), v) in rows.iter().zip(&cols).zip(&values) {
            kt[(i as usize - 1, j as usize - 1)] += v;
        }
        // A linear host adds f0 = −(the residual at u = 0) to its load.
        let mut rhs = vec![0.0; f.len()];
        contact.scatter_add(&r0, &mut rhs).unwrap();
        let rhs = f - DVector::from_vec(rhs);
        let u = kt.cholesky().expect("positive definite").solve(&rhs);
        let mut local = vec![0.0; n_local];
        contact.gather(u.as_slice(), &mut local).unwrap();
        if !contact.update(&local).unwrap().changed {
            return (u, iteration);
        }
    }
    panic!("the host's loop did not settle");
}

#[test]
fn a_host_with_its_own_solver_lands_on_the_models_solution() {
    let scene = scene();
    let mut model = scene.model().unwrap();
    model.solve_contact(&scene.options()).unwrap();
    let mesh = model.mesh().unwrap();
    let host = Host::new(&model);
    let mut contact = contact(mesh, &host, &scene);
    let (k, f) = host_system(mesh, &host, &scene);
    let (u, iterations) = host_solve(&mut contact, &k, &f);
    assert!(iterations > 1, "the loop had nothing to do");
    let active = contact.active().unwrap().to_vec();
    assert!(
        active.iter().any(|&a| a) && active.iter().any(|&a| !a),
        "partial contact"
    );
    assert_eq!(active, model.contact_active().unwrap());
    let expected = model.displacements().unwrap();
    let scale = expected
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    for (v, eq) in host.equations.iter().enumerate() {
        for c in 0..3 {
            let got = if eq[c] > 0 {
                u[eq[c] as usize - 1]
            } else {
                0.0
            };
            assert!(
                (got - expected[v][c]).abs() < 1e-9 * scale,
                "node {v} component {c}: host {got}, model {}",
                expected[v][c]
            );
        }
    }
    let area = contact.contact_area().unwrap();
    assert!((area - model.contact_area().unwrap()).abs() < 1e-14);
}

#[test]
fn the_pattern_holds_every_block_of_dofs_with_equations() {
    let scene = scene();
    let model = scene.model().unwrap();
    let mesh = model.mesh().unwrap();
    let host = Host::new(&model);
    let mut contact = contact(mesh, &host, &scene);
    let n_tets = contact.tetrahedra().unwrap().len();
    let mut expected = 0;
    for k in 0..n_tets {
        let free = contact
            .element_equations(k)
            .unwrap()
            .iter()
            .flatten()
            .count();
        expected += free * free;
    }
    assert_eq!(contact.pattern().unwrap().0.len(), expected);
    assert!(contact.element_equations(n_tets).is_err());
}

fn refusal(result: Result<usize, Error>) -> String {
    result.unwrap_err().message().to_string()
}

#[test]
fn bad_sides_are_refused_by_name_and_leave_the_context_unchanged() {
    let mut contact = SolidHostContact::new(1, ContactOptions::default()).unwrap();
    let xyz = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let equations = [[1, 2, 3], [4, 5, 6], [7, 8, 9]];
    let good = HostSurface {
        tag: 5,
        body: 1,
        young: 1.0,
        nodes: &[1, 2, 3],
        xyz: &xyz,
        equations: &equations,
        triangles: &[[1, 2, 3]],
    };
    let message = refusal(contact.add_side(&HostSurface {
        triangles: &[[1, 2, 4]],
        ..good
    }));
    assert!(message.contains("uses node 4"), "{message}");
    let message = refusal(contact.add_side(&HostSurface {
        nodes: &[0, 2, 3],
        ..good
    }));
    assert!(message.contains("below the index base"), "{message}");
    let message = refusal(contact.add_side(&HostSurface {
        young: f64::NAN,
        ..good
    }));
    assert!(message.contains("Young"), "{message}");
    let twice = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 1.0, 0.0]];
    let message = refusal(contact.add_side(&HostSurface {
        nodes: &[1, 2, 1],
        xyz: &twice,
        triangles: &[[1, 2, 1]],
        ..good
    }));
    assert!(message.contains("node 1 is given twice"), "{message}");
    assert!(contact.nodes().is_empty());
    let a = contact.add_side(&good).unwrap();
    let message = refusal(contact.add_pair(a, a));
    assert!(message.contains("self-contact"), "{message}");
    let message = refusal(contact.add_pair(a, 7));
    assert!(message.contains("side 8 does not exist"), "{message}");
}

#[test]
fn sides_that_do_not_face_each_other_are_refused() {
    let mut contact = SolidHostContact::new(0, ContactOptions::default()).unwrap();
    let below = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let equations = [[0, 1, 2], [3, 4, 5], [6, 7, 8]];
    let above_eq = [[9, 10, 11], [12, 13, 14], [15, 16, 17]];
    let lower = HostSurface {
        tag: 1,
        body: 1,
        young: 1.0,
        nodes: &[0, 1, 2],
        xyz: &below,
        equations: &equations,
        triangles: &[[0, 1, 2]],
    };
    // The upper side numbered counter-clockwise seen from below would be
    // [3, 5, 4]; [3, 4, 5] faces up, the way the lower side does.
    let upper = HostSurface {
        tag: 2,
        body: 2,
        nodes: &[3, 4, 5],
        equations: &above_eq,
        triangles: &[[3, 4, 5]],
        ..lower
    };
    let a = contact.add_side(&lower).unwrap();
    let b = contact.add_side(&upper).unwrap();
    contact.add_pair(a, b).unwrap();
    let err = contact.setup().unwrap_err();
    assert!(
        err.message().contains("do not face each other"),
        "{}",
        err.message()
    );
}

#[test]
fn a_rigid_tool_prescribed_at_the_interface_reaches_the_host_through_u() {
    use tfem::fem::solid_mesh::Brick;
    use tfem::model::solid::SolidMaterial;
    let delta = 0.01;
    let lower = Brick::uniform([0.0, 0.0, -1.0], [1.0, 1.0, 0.0], [2; 3], 1);
    let mut tool = Brick::uniform([0.0; 3], [1.0, 1.0, 0.25], [2, 2, 1], 2);
    tool.side_tags = [11, 12, 13, 14, 15, 16];
    let mut model = SolidModel::new();
    model.set_mesh(SolidMesh::bricks(&[lower, tool]).unwrap());
    for body in [1, 2] {
        model.set_material(body, SolidMaterial::new(1.0, 0.25).unwrap());
    }
    model.fix_faces(5, Axis::Z, 0.0).unwrap();
    model.fix_faces(1, Axis::X, 0.0).unwrap();
    model.fix_faces(3, Axis::Y, 0.0).unwrap();
    let n = model.mesh().unwrap().nodes().len();
    for v in 0..n {
        if model.mesh().unwrap().node_body()[v] == Some(2) {
            model.fix(v, Axis::X, 0.0).unwrap();
            model.fix(v, Axis::Y, 0.0).unwrap();
            model.fix(v, Axis::Z, -delta).unwrap();
        }
    }
    model.add_contact_pair(6, 15).unwrap();
    let options = ContactOptions {
        lambda: Some(1.0),
        ..ContactOptions::default()
    };
    model.solve_contact(&options).unwrap();
    let mesh = model.mesh().unwrap();
    let host = Host::new(&model);
    let mut contact = SolidHostContact::new(1, options).unwrap();
    let a = SideData::new(mesh, &host, 6, 1, 1.0);
    let b = SideData::new(mesh, &host, 15, 2, 1.0);
    let (a, b) = (
        contact.add_side(&a.surface()).unwrap(),
        contact.add_side(&b.surface()).unwrap(),
    );
    contact.add_pair(a, b).unwrap();
    // The host's own matrix of the lower block (the tool is rigid).
    let d = [0, 1].map(|_| isotropic_d(1.0, 0.25).unwrap());
    let bodies = SolidBodies {
        mesh,
        d: &d,
        tempering: Tempering::Auto,
    };
    let mut k = DMatrix::zeros(host.n, host.n);
    for (e, t) in mesh.tets().iter().enumerate() {
        let ke = bodies.matrix(e).unwrap();
        for i in 0..12 {
            for j in 0..12 {
                let (p, q) = (
                    host.equations[t[i / 3]][i % 3],
                    host.equations[t[j / 3]][j % 3],
                );
                if p > 0 && q > 0 {
                    k[(p as usize - 1, q as usize - 1)] += ke[12 * i + j];
                }
            }
        }
    }
    // u₀: the tool's prescribed values at its interface nodes.
    let nodes = contact.nodes().to_vec();
    let prescribed = |id: i64| match mesh.node_body()[id as usize - 1] {
        Some(2) => [0.0, 0.0, -delta],
        _ => [0.0; 3],
    };
    let u0: Vec<f64> = nodes.iter().flat_map(|&id| prescribed(id)).collect();
    let (rows, cols) = contact
        .pattern()
        .map(|(r, c)| (r.to_vec(), c.to_vec()))
        .unwrap();
    let mut u = DVector::zeros(host.n);
    for _ in 0..20 {
        let mut values = vec![0.0; rows.len()];
        let mut r0 = vec![0.0; u0.len()];
        contact
            .evaluate(&u0, Some(&mut values), Some(&mut r0))
            .unwrap();
        let mut kt = k.clone();
        for ((&i, &j), v) in rows.iter().zip(&cols).zip(&values) {
            kt[(i as usize - 1, j as usize - 1)] += v;
        }
        let mut rhs = vec![0.0; host.n];
        contact.scatter_add(&r0, &mut rhs).unwrap();
        u = kt.cholesky().unwrap().solve(&(-DVector::from_vec(rhs)));
        let mut local = vec![0.0; u0.len()];
        contact.gather(u.as_slice(), &mut local).unwrap();
        for (i, &id) in nodes.iter().enumerate() {
            if mesh.node_body()[id as usize - 1] == Some(2) {
                local[3 * i..3 * i + 3].copy_from_slice(&prescribed(id));
            }
        }
        if !contact.update(&local).unwrap().changed {
            break;
        }
    }
    let expected = model.displacements().unwrap();
    let mut largest = 0.0f64;
    for (v, eq) in host.equations.iter().enumerate() {
        for c in 0..3 {
            if eq[c] > 0 {
                let got = u[eq[c] as usize - 1];
                largest = largest.max(got.abs());
                assert!(
                    (got - expected[v][c]).abs() < 1e-9 * delta,
                    "node {v}: {got}"
                );
            }
        }
    }
    assert!(largest > 0.1 * delta, "the tool pressed nothing: {largest}");
}
