//! `HostContact`: a host code with its own P1 assembly, its own (dense)
//! solver and its own active-set loop, taking only the contact
//! contributions from tfem, reproduces tfem's built-in contact solve of the
//! seed scene.

use std::collections::BTreeMap;

use nalgebra::{DMatrix, DVector};
use tfem::contact::HostContact;
use tfem::element::{Jmin, section_stiffness};
use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TwoBlocks};
use tfem::{ContactOptions, Mesh, Model, Status};

/// The host's view of a problem: its equations (one per free DOF, in
/// global DOF order), its stiffness matrix and load vector.
struct Host {
    equation: Vec<Option<usize>>,
    k: DMatrix<f64>,
    f: DVector<f64>,
}

fn host_of(model: &Model) -> Host {
    let mesh = model.mesh().unwrap();
    let fixed: BTreeMap<usize, f64> = model.constraints().collect();
    assert!(fixed.values().all(|&v| v == 0.0), "the scene fixes at zero");
    let mut equation = vec![None; 2 * mesh.nodes().len()];
    let mut n = 0;
    for (g, e) in equation.iter_mut().enumerate() {
        if !fixed.contains_key(&g) && mesh.node_body()[g / 2].is_some() {
            *e = Some(n);
            n += 1;
        }
    }
    let mut k = DMatrix::zeros(n, n);
    for (tri, body) in mesh.triangles().iter().zip(mesh.body_of()) {
        let m = model.material(*body).unwrap();
        // Plain P1 (no tempering): the host's own element (a ring's for
        // axisymmetric bodies).
        let ke =
            section_stiffness(&mesh.corners(tri), &m.d_matrix(), m.section(), Jmin::Off).unwrap();
        for a in 0..6 {
            for b in 0..6 {
                let (ga, gb) = (2 * tri[a / 2] + a % 2, 2 * tri[b / 2] + b % 2);
                if let (Some(i), Some(j)) = (equation[ga], equation[gb]) {
                    k[(i, j)] += ke[a][b];
                }
            }
        }
    }
    let load = model.load_vector().unwrap();
    let mut f = DVector::zeros(n);
    for (g, e) in equation.iter().enumerate() {
        if let Some(i) = e {
            f[*i] += load[g];
        }
    }
    Host { equation, k, f }
}

/// A contact side from the mesh's edges tagged `tag`, in the host's
/// numbering, each edge turned so that its body lies on its left.
fn add_side(hc: &mut HostContact, model: &Model, host: &Host, tag: i32) -> usize {
    add_side_based(hc, model, host, tag, 0)
}

/// [`add_side`] with the equations given in index base `base`.
fn add_side_based(hc: &mut HostContact, model: &Model, host: &Host, tag: i32, base: i64) -> usize {
    side_args(model, host, tag, base, |_| false)
        .add(hc)
        .unwrap()
}

/// What [`HostContact::add_side`] is given for the mesh edges tagged `tag`;
/// the edges for which `reverse(k)` holds are turned to have their body on
/// the right (a host's mistake).
struct SideArgs {
    tag: i32,
    body: i32,
    material: tfem::Material,
    ids: Vec<i64>,
    xy: Vec<[f64; 2]>,
    eq: Vec<[i64; 2]>,
    edges: Vec<[i64; 2]>,
}

impl SideArgs {
    fn add(&self, hc: &mut HostContact) -> tfem::Result<usize> {
        hc.add_side(
            self.tag,
            self.body,
            self.material,
            &self.ids,
            &self.xy,
            &self.eq,
            &self.edges,
        )
    }
}

fn side_args(
    model: &Model,
    host: &Host,
    tag: i32,
    base: i64,
    reverse: impl Fn(usize) -> bool,
) -> SideArgs {
    let mesh: &Mesh = model.mesh().unwrap();
    let mut edges = Vec::new();
    let mut nodes = Vec::new();
    for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag) {
        let (_, third) = e.owner.unwrap();
        let [p, q] = e.nodes;
        let (a, b, c) = (mesh.nodes()[p], mesh.nodes()[q], mesh.nodes()[third]);
        let left = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0;
        let flip = reverse(edges.len());
        edges.push(if left != flip {
            [p as i64, q as i64]
        } else {
            [q as i64, p as i64]
        });
        nodes.extend([p, q]);
    }
    nodes.sort_unstable();
    nodes.dedup();
    let body = mesh.body_of()[e_owner(mesh, tag)];
    let xy: Vec<[f64; 2]> = nodes.iter().map(|&v| mesh.nodes()[v]).collect();
    let eq: Vec<[i64; 2]> = nodes
        .iter()
        .map(|&v| [0, 1].map(|c| host.equation[2 * v + c].map_or(base - 1, |e| e as i64 + base)))
        .collect();
    let ids: Vec<i64> = nodes.iter().map(|&v| v as i64).collect();
    let material = *model.material(body).unwrap();
    SideArgs {
        tag,
        body,
        material,
        ids,
        xy,
        eq,
        edges,
    }
}

fn e_owner(mesh: &Mesh, tag: i32) -> usize {
    let e = mesh.boundary_edges().iter().find(|e| e.tag == tag).unwrap();
    e.owner.unwrap().0
}

#[test]
fn a_host_loop_with_its_own_assembly_reproduces_the_built_in_contact_solve() {
    for c in [0.1, 0.3] {
        let scene = TwoBlocks {
            c,
            mesh_size: 1.0 / 32.0,
            ..Default::default()
        };
        let mut built_in = scene.build().unwrap();
        built_in
            .model
            .solve_contact(&ContactOptions::default())
            .unwrap();
        let expected = built_in.model.displacements().unwrap();
        let (u, active, iterations) =
            host_loop(&built_in.model, [TAG_CONTACT_LOWER, TAG_CONTACT_UPPER]);
        assert!(iterations > 1, "the set changes in the seed scene");
        let (mut err, mut scale) = (0.0f64, 0.0f64);
        for (g, mine) in u.iter().enumerate() {
            err = err.max((mine - expected[g / 2][g % 2]).abs());
            scale = scale.max(expected[g / 2][g % 2].abs());
        }
        assert!(
            err <= 1e-10 * scale,
            "2C/L = {}: host vs built-in {err:e} of {scale:e}",
            2.0 * c
        );
        assert_eq!(
            active,
            built_in.model.contact_active().unwrap(),
            "the same active set"
        );
    }
}

/// The host's own loop (linear host: K + K_c and f − r_c(0), tfem's
/// contact contributions) on `model`'s pair of tags: its displacements
/// over every global DOF, the context's final active set and the number of
/// solves.
fn host_loop(model: &Model, tags: [i32; 2]) -> (Vec<f64>, Vec<bool>, usize) {
    let host = host_of(model);
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    let a = add_side(&mut hc, model, &host, tags[0]);
    let b = add_side(&mut hc, model, &host, tags[1]);
    hc.add_pair(a, b).unwrap();
    let (rows, cols) = hc.pattern().unwrap();
    let (rows, cols) = (rows.to_vec(), cols.to_vec());
    let n_if = hc.nodes().len();
    let mut values = vec![0.0; rows.len()];
    let (mut u_if, mut r0) = (vec![0.0; 2 * n_if], vec![0.0; 2 * n_if]);
    let mut iterations = 0;
    let u = loop {
        iterations += 1;
        hc.evaluate(&vec![0.0; 2 * n_if], Some(&mut values), Some(&mut r0))
            .unwrap();
        let mut k = host.k.clone();
        for ((&i, &j), &v) in rows.iter().zip(&cols).zip(&values) {
            k[(i as usize, j as usize)] += v;
        }
        let mut f = host.f.clone();
        for (v, eq) in hc.nodes().iter().map(|&v| v as usize).enumerate() {
            for comp in 0..2 {
                if let Some(e) = host.equation[2 * eq + comp] {
                    f[e] -= r0[2 * v + comp];
                }
            }
        }
        let u = k.cholesky().expect("positive definite").solve(&f);
        hc.gather(u.as_slice(), &mut u_if).unwrap();
        if !hc.update(&u_if).unwrap().changed {
            break u;
        }
    };
    let global = host
        .equation
        .iter()
        .map(|e| e.map_or(0.0, |e| u[e]))
        .collect();
    (global, hc.active().unwrap().to_vec(), iterations)
}

#[test]
fn an_axisymmetric_host_loop_reproduces_the_built_in_shrink_fit() {
    use tfem::scenes::revolution::{ShaftHub, TAG_HUB_BORE, TAG_SHAFT};
    for ratio in [(1, 1), (3, 2)] {
        let fit = ShaftHub {
            cells: 4,
            ratio,
            ..Default::default()
        };
        let (scene, _) = fit.solve().unwrap();
        let expected: Vec<f64> = scene.model.displacements().unwrap().concat();
        let (u, active, _) = host_loop(&scene.model, [TAG_SHAFT, TAG_HUB_BORE]);
        let scale = expected.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let err = u
            .iter()
            .zip(&expected)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(
            err <= 1e-10 * scale,
            "{ratio:?}: host vs built-in {err:e} of {scale:e}"
        );
        assert_eq!(active, scene.model.contact_active().unwrap(), "{ratio:?}");
    }
}

#[test]
fn a_host_context_is_axisymmetric_in_every_side_or_in_none() {
    use tfem::scenes::revolution::{ShaftHub, TAG_HUB_BORE, TAG_SHAFT};
    let (scene, _) = ShaftHub {
        cells: 4,
        ..Default::default()
    }
    .solve()
    .unwrap();
    let host = host_of(&scene.model);
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    add_side(&mut hc, &scene.model, &host, TAG_SHAFT);
    let before = hc.nodes().len();
    let mut other = side_args(&scene.model, &host, TAG_HUB_BORE, 0, |_| false);
    other.material = tfem::Material::new(1.0, 0.3, tfem::PlaneMode::Strain, "hub").unwrap();
    let e = other.add(&mut hc).unwrap_err();
    assert!(
        e.message().contains("side 0") && e.message().contains("axisymmetric"),
        "{}",
        e.message()
    );
    assert_eq!(hc.nodes().len(), before);
}

#[test]
fn the_pattern_holds_each_element_block_row_by_row_in_the_hosts_numbering() {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 8.0,
        ..Default::default()
    };
    let built = scene.build().unwrap();
    let host = host_of(&built.model);
    // 1-based equations (0 marks a DOF without one).
    let mut hc = HostContact::new(1, ContactOptions::default()).unwrap();
    let model = &built.model;
    let a = add_side_based(&mut hc, model, &host, TAG_CONTACT_LOWER, 1);
    let b = add_side_based(&mut hc, model, &host, TAG_CONTACT_UPPER, 1);
    hc.add_pair(a, b).unwrap();
    let n = hc.elements().unwrap().len();
    let (rows, cols) = hc.pattern().unwrap();
    let (rows, cols) = (rows.to_vec(), cols.to_vec());
    let mut at = 0;
    for k in 0..n {
        let eq = hc.element_equations(k).unwrap();
        for ea in eq.iter() {
            for eb in eq.iter() {
                if let (Some(i), Some(j)) = (ea, eb) {
                    assert_eq!((rows[at], cols[at]), (*i, *j), "entry {at}");
                    at += 1;
                }
            }
        }
    }
    assert_eq!(at, rows.len());
    assert!(rows.iter().chain(&cols).all(|&r| r >= 1));
    let fixed_dofs = (0..n)
        .flat_map(|k| hc.element_equations(k).unwrap())
        .filter(Option::is_none)
        .count();
    assert!(
        fixed_dofs > 0,
        "the symmetry line's x DOFs have no equation"
    );
}

#[test]
fn bad_host_input_names_the_node_the_side_or_the_buffer() {
    let material = tfem::Material::new(1e3, 0.3, tfem::PlaneMode::Strain, "side").unwrap();
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    let xy = [[0.0, 0.0], [1.0, 0.0]];
    let eq = [[0, 1], [2, 3]];
    let err = hc
        .add_side(5, 1, material, &[10, 11], &xy, &eq, &[[10, 12]])
        .unwrap_err();
    assert!(err.message().contains("node 12"), "{}", err.message());
    let err = hc
        .add_side(
            5,
            1,
            material,
            &[10, 11],
            &[[0.0, 0.0], [0.0, 0.0]],
            &eq,
            &[[10, 11]],
        )
        .unwrap_err();
    assert!(err.message().contains("zero length"), "{}", err.message());
    let s0 = hc
        .add_side(5, 1, material, &[10, 11], &xy, &eq, &[[10, 11]])
        .unwrap();
    let err = hc
        .add_side(6, 2, material, &[10], &[[0.5, 0.0]], &[[0, 1]], &[])
        .unwrap_err();
    assert!(err.message().contains("node 10"), "{}", err.message());
    let err = hc.add_pair(s0, s0).unwrap_err();
    assert_eq!(err.status(), Status::InvalidContact);
    let err = hc.add_pair(s0, 3).unwrap_err();
    assert!(err.message().contains("side 3"), "{}", err.message());
    assert_eq!(hc.pattern().unwrap_err().status(), Status::InvalidState);
}

/// The seed scene's host (h = 1/8) and its two sides, the lower one built
/// with `reverse_lower` deciding which of its edges are turned around.
fn reversed_scene(
    reverse_lower: impl Fn(usize) -> bool,
    reverse_upper: impl Fn(usize) -> bool,
) -> (HostContact, tfem::Result<usize>, tfem::Result<usize>) {
    let scene = TwoBlocks {
        mesh_size: 1.0 / 8.0,
        ..Default::default()
    };
    let built = scene.build().unwrap();
    let host = host_of(&built.model);
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    let a = side_args(&built.model, &host, TAG_CONTACT_LOWER, 0, reverse_lower).add(&mut hc);
    let b = side_args(&built.model, &host, TAG_CONTACT_UPPER, 0, reverse_upper).add(&mut hc);
    (hc, a, b)
}

#[test]
fn a_side_given_clockwise_is_refused_naming_both_sides() {
    for (lower, upper) in [(true, false), (false, true)] {
        let (mut hc, a, b) = reversed_scene(move |_| lower, move |_| upper);
        let err = hc.add_pair(a.unwrap(), b.unwrap()).unwrap_err();
        assert_eq!(err.status(), Status::InvalidContact);
        let m = err.message();
        assert!(
            m.contains(&format!("side 0 (tag {TAG_CONTACT_LOWER})"))
                && m.contains(&format!("side 1 (tag {TAG_CONTACT_UPPER})"))
                && m.contains("left"),
            "{m}"
        );
        // Nothing was added: the context still has no pair.
        assert_eq!(hc.pattern().unwrap_err().status(), Status::InvalidState);
    }
}

#[test]
fn a_side_with_one_edge_turned_around_is_refused_naming_the_edge() {
    let (_, a, _) = reversed_scene(|k| k == 3, |_| false);
    let err = a.unwrap_err();
    assert_eq!(err.status(), Status::InvalidContact);
    let m = err.message();
    assert!(
        m.contains(&format!("side 0 (tag {TAG_CONTACT_LOWER})")) && m.contains("edge 3"),
        "{m}"
    );
}

/// Side a (body 1, below) over x ∈ [−3, 2] on y = 0, side b (body 2,
/// above) over [0, 2] on y = 0.5: the nodes of a at x = −3, −2, −1 face
/// nothing and are in no element of B. They read a gap of 0 (documented:
/// no gap, not in contact), the nodes that face b read the gap 0.5.
#[test]
fn a_node_facing_nothing_is_in_no_element_and_reads_a_zero_gap() {
    let material = tfem::Material::new(1e9, 0.3, tfem::PlaneMode::Strain, "side").unwrap();
    let mut hc = HostContact::new(0, ContactOptions::default()).unwrap();
    let ids_a: Vec<i64> = (40..46).collect();
    let xy_a: Vec<[f64; 2]> = (0..6).map(|i| [i as f64 - 3.0, 0.0]).collect();
    let eq_a: Vec<[i64; 2]> = (0..6).map(|i| [2 * i, 2 * i + 1]).collect();
    let edges_a: Vec<[i64; 2]> = (40..45).map(|v| [v + 1, v]).collect();
    let a = hc
        .add_side(1, 1, material, &ids_a, &xy_a, &eq_a, &edges_a)
        .unwrap();
    let xy_b = [[0.0, 0.5], [1.0, 0.5], [2.0, 0.5]];
    let eq_b = [[12, 13], [14, 15], [16, 17]];
    let b = hc
        .add_side(
            2,
            2,
            material,
            &[20, 21, 22],
            &xy_b,
            &eq_b,
            &[[20, 21], [21, 22]],
        )
        .unwrap();
    hc.add_pair(a, b).unwrap();
    let n = hc.n_nodes();
    let mut gaps = vec![f64::NAN; n];
    hc.gaps(&vec![0.0; 2 * n], &mut gaps).unwrap();
    let in_b: Vec<bool> = {
        let elements = hc.elements().unwrap();
        (0..n)
            .map(|v| elements.iter().any(|e| e.nodes.contains(&v)))
            .collect()
    };
    for (v, &id) in hc.nodes().iter().enumerate() {
        let facing_nothing = [40, 41, 42].contains(&id);
        assert_eq!(in_b[v], !facing_nothing, "node {id}");
        let expected = if facing_nothing { 0.0 } else { 0.5 };
        assert!((gaps[v] - expected).abs() < 1e-12, "node {id}: {}", gaps[v]);
    }
}

/// Found by a review: a host node number below the index base (0 at base
/// 1, or negative) was accepted and read back as if it named a node. It is
/// refused, naming the side, the entry and the number, and the context is
/// as it was: the side, given right, is then side 0.
#[test]
fn a_host_node_below_the_index_base_is_refused_leaving_the_context_unchanged() {
    let material = tfem::Material::new(1e3, 0.3, tfem::PlaneMode::Strain, "side").unwrap();
    let xy = [[0.0, 0.0], [1.0, 0.0]];
    for (base, bad) in [(1, 0), (1, -3), (0, -1)] {
        let mut hc = HostContact::new(base, ContactOptions::default()).unwrap();
        let eq = [
            [base as i64, base as i64 + 1],
            [base as i64 + 2, base as i64 + 3],
        ];
        let err = hc
            .add_side(5, 1, material, &[7, bad], &xy, &eq, &[[7, bad]])
            .unwrap_err();
        assert_eq!(err.status(), Status::InvalidArgument);
        let expected = format!(
            "side 0 (tag 5): node {bad} (entry {}) is below the index base {base}",
            1 + base
        );
        assert!(err.message().contains(&expected), "{}", err.message());
        assert_eq!(hc.n_nodes(), 0);
        let side = hc.add_side(5, 1, material, &[7, 8], &xy, &eq, &[[7, 8]]);
        assert_eq!(side.unwrap(), 0);
    }
}

/// The same for a node of a contact triangle the host gives: named with
/// its pair, its triangle and its place there, the context unchanged.
#[test]
fn a_contact_triangle_node_below_the_index_base_is_refused_naming_the_pair() {
    let material = tfem::Material::new(1e3, 0.3, tfem::PlaneMode::Strain, "side").unwrap();
    let mut hc = HostContact::new(1, ContactOptions::default()).unwrap();
    let (lower, upper) = ([[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [0.0, 0.0]]);
    let a = hc
        .add_side(
            1,
            1,
            material,
            &[1, 2],
            &lower,
            &[[1, 2], [3, 4]],
            &[[1, 2]],
        )
        .unwrap();
    let b = hc
        .add_side(
            2,
            2,
            material,
            &[3, 4],
            &upper,
            &[[5, 6], [7, 8]],
            &[[3, 4]],
        )
        .unwrap();
    let err = hc
        .add_pair_with_mesh(a, b, &[[1, 2, 4], [2, 0, 4]])
        .unwrap_err();
    assert_eq!(err.status(), Status::InvalidArgument);
    let expected = "pair 0 (sides 0 and 1), contact triangle 2: node 0 (its second) is below \
                    the index base 1";
    assert!(err.message().contains(expected), "{}", err.message());
    assert_eq!(hc.add_pair(a, b).unwrap(), 0);
}

/// Found by a review: equation numbers up to i64::MAX were accepted by
/// add_side and refused only at gather. No host vector of f64 holds more
/// than isize::MAX bytes, so an equation from index_base + isize::MAX / 8
/// on is refused at declaration, naming the node, the unknown and the
/// equation; one below it is accepted (the host's own size, not known
/// before, is checked at gather and scatter_add), and so is any number
/// below the base (a DOF without an equation).
#[test]
fn an_equation_no_host_vector_can_hold_is_refused_at_declaration() {
    let material = tfem::Material::new(1e3, 0.3, tfem::PlaneMode::Strain, "side").unwrap();
    let xy = [[0.0, 0.0], [1.0, 0.0]];
    let vectors = (isize::MAX as usize / std::mem::size_of::<f64>()) as i64;
    for base in [0, 1] {
        let last = vectors - 1 + base;
        for bad in [i64::MAX, last + 1] {
            let mut hc = HostContact::new(base as usize, ContactOptions::default()).unwrap();
            let err = hc
                .add_side(
                    5,
                    1,
                    material,
                    &[7, 8],
                    &xy,
                    &[[base, base + 1], [bad, base - 1]],
                    &[[7, 8]],
                )
                .unwrap_err();
            assert_eq!(err.status(), Status::InvalidArgument);
            let expected = format!(
                "side 0 (tag 5): node 8 (entry {}) has equation {bad} for its x unknown, beyond \
                 any host vector (equations run from the index base {base} to at most {last})",
                1 + base
            );
            assert!(err.message().contains(&expected), "{}", err.message());
            assert_eq!(hc.n_nodes(), 0);
        }
        let mut hc = HostContact::new(base as usize, ContactOptions::default()).unwrap();
        let eq = [[base, base + 1], [last, i64::MIN]];
        assert_eq!(
            hc.add_side(5, 1, material, &[7, 8], &xy, &eq, &[[7, 8]])
                .unwrap(),
            0
        );
    }
}
