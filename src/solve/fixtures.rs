//! Small models for the solver's unit tests.

use super::session::Session;
use crate::contact::{ContactElement, ContactOptions, ContactSet, Nodes, element_laws};
use crate::fem::assembly::{DofMap, NOT_FREE};
use crate::fem::material::{Material, PlaneMode};
use crate::fem::mesh::Mesh;
use crate::model::{Component, Problem};

/// Two n×2-cell blocks of unit length stacked at y = 0 (separate
/// nodes), pressed together by a pressure on the first `loaded` top
/// edges of the upper one; the lower one is supported at its bottom,
/// each has u_x = 0 at x = 0.
pub(crate) fn two_blocks(n: usize, loaded: usize) -> Problem {
    let h = 1.0 / n as f64;
    let (mut nodes, mut tris, mut bodies) = (Vec::new(), Vec::new(), Vec::new());
    let mut edges = Vec::new();
    let mut tags = Vec::new();
    for (body, y0) in [(1, -2.0 * h), (2, 0.0)] {
        let first = nodes.len();
        let id = |i: usize, j: usize| first + j * (n + 1) + i;
        for j in 0..3 {
            for i in 0..=n {
                nodes.push([i as f64 * h, y0 + j as f64 * h]);
            }
        }
        for j in 0..2 {
            for i in 0..n {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                tris.extend([[a, b, c], [a, c, d]]);
                bodies.extend([body, body]);
            }
        }
        for i in 0..n {
            let (bottom, top) = ([id(i, 0), id(i + 1, 0)], [id(i, 2), id(i + 1, 2)]);
            edges.extend([bottom, top]);
            let top_tag = if body == 2 && i < loaded {
                22
            } else {
                10 * body + 1
            };
            tags.extend([10 * body, top_tag]);
        }
    }
    let mut mesh = Mesh::new(nodes, tris, bodies, 0).unwrap();
    mesh.set_boundary_edges(&edges, &tags).unwrap();
    let mut p = Problem::new();
    p.set_mesh(mesh);
    for body in [1, 2] {
        let m = Material::new(1e3 * body as f64, 0.3, PlaneMode::Strain, "block").unwrap();
        p.set_material(body, m).unwrap();
    }
    p.fix_edges(10, Component::Y, 0.0).unwrap();
    p.fix(0, Component::X, 0.0).unwrap();
    p.fix(3 * (n + 1), Component::X, 0.0).unwrap();
    p.add_pressure(22, 1.0).unwrap();
    p.add_contact_pair(11, 20).unwrap();
    p
}

/// `p`'s session with the bodies' part assembled, and `p`'s prescribed
/// values.
pub(crate) fn assembled(p: &Problem) -> (Session, Vec<f64>) {
    let mesh = p.mesh().unwrap();
    let prescribed_dof = |g| p.is_prescribed(g);
    let mut session = Session::new(
        0,
        mesh,
        prescribed_dof,
        p.contact_pairs(),
        p.weighting_in_use(),
    )
    .unwrap();
    let elements = p.elements().unwrap();
    let prescribed = p.prescribed_vector().unwrap();
    let f_ext = p.load_vector().unwrap();
    session
        .assemble_body(&elements, &f_ext, &prescribed)
        .unwrap();
    (session, prescribed)
}

/// The contact set of `p`'s `contact` elements over the unknowns `dofs`,
/// E_c that of body 1.
pub(crate) fn contact_set<'a>(
    p: &'a Problem,
    contact: &'a [ContactElement],
    dofs: &DofMap,
    prescribed: &[f64],
    options: &ContactOptions,
) -> ContactSet<'a> {
    let mesh = p.mesh().unwrap();
    let elements = p.elements().unwrap();
    let soft = |_pair: usize| *elements.material(1);
    let laws = element_laws(
        crate::contact::mesh::Nodes::of(mesh),
        contact,
        soft,
        mesh.size(),
        options,
    )
    .unwrap();
    let equation = |g: usize| Some(dofs.free(g)).filter(|&f| f != NOT_FREE);
    ContactSet::new(
        Nodes::of(mesh),
        contact,
        laws,
        equation,
        prescribed,
        options,
    )
    .unwrap()
}
