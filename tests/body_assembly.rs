//! The body assembly runs in two halves of the unknowns at once, each
//! skipping the elements on the other side by their node numbers. Every
//! element is still integrated and checked exactly once: whichever half its
//! unknowns lie in, and also when it has no unknown at all.

use tfem::meshgen::unit_square;
use tfem::{Component, Material, Mesh, Model, PlaneMode, Status, Tempering};

const N: usize = 8;

/// The unit square (N × N cells, 2N² triangles) plus, if given, one flat
/// triangle on three collinear grid nodes, solved as plain FEM, which
/// cannot integrate it; the nodes in `fixed` are clamped.
fn solve_with_flat_triangle(flat: Option<[usize; 3]>, fixed: &[usize]) -> tfem::Result<()> {
    let mesh = unit_square(N, None).build().unwrap();
    let mut triangles = mesh.triangles().to_vec();
    let mut bodies = mesh.body_of().to_vec();
    if let Some(flat) = flat {
        triangles.push(flat);
        bodies.push(1);
    }
    let mesh = Mesh::new(mesh.nodes().to_vec(), triangles, bodies, 0).unwrap();
    let mut model = Model::new();
    model.set_mesh(mesh);
    let steel = Material::new(1.0, 0.3, PlaneMode::Strain, "plate").unwrap();
    model.set_material(1, steel).unwrap();
    model.set_tempering(Tempering::Off).unwrap();
    // The bottom row clamped, so that the healthy square is solvable.
    for v in (0..=N).chain(fixed.iter().copied()) {
        model.fix(v, Component::X, 0.0).unwrap();
        model.fix(v, Component::Y, 0.0).unwrap();
    }
    model.set_body_force(1, [0.0, -1.0]).unwrap();
    model.solve().map(|_| ())
}

fn assert_flat_triangle_is_named(r: tfem::Result<()>) {
    let err = r.expect_err("plain FEM must refuse a zero Jacobian");
    assert_eq!(err.status(), Status::DegenerateElement, "{err}");
    // The flat triangle comes after the square's 2N² triangles.
    let name = format!("triangle {}", 2 * N * N);
    assert!(err.to_string().contains(&name), "{err}");
}

#[test]
fn the_square_without_the_flat_triangle_solves() {
    assert_eq!(
        unit_square(N, None).build().unwrap().triangles().len(),
        2 * N * N
    );
    solve_with_flat_triangle(None, &[]).unwrap();
}

#[test]
fn a_flat_triangle_among_the_first_unknowns_is_named() {
    // The second row of nodes: free, at the start of the numbering.
    let row = N + 1;
    assert_flat_triangle_is_named(solve_with_flat_triangle(Some([row, row + 1, row + 2]), &[]));
}

#[test]
fn a_flat_triangle_among_the_last_unknowns_is_named() {
    let top = N * (N + 1);
    assert_flat_triangle_is_named(solve_with_flat_triangle(Some([top, top + 1, top + 2]), &[]));
}

#[test]
fn a_flat_triangle_without_unknowns_is_named() {
    // On the clamped bottom row: no free unknown at all.
    assert_flat_triangle_is_named(solve_with_flat_triangle(Some([0, 1, 2]), &[]));
    // In the middle of the numbering, clamped there.
    let mid = (N / 2) * (N + 1) + 3;
    let flat = [mid, mid + 1, mid + 2];
    assert_flat_triangle_is_named(solve_with_flat_triangle(Some(flat), &flat));
}
