//! The VTU writer: the file holds the mesh and every field the model gives,
//! to the bit, in the layout VTK's XML reader (ParaView's) and meshio read:
//! raw appended data, one block per array, each its UInt64 byte count and
//! its little-endian values. The files are read back here by a reader of
//! our own, independent of the writer, and by meshio and VTK's Python
//! bindings where they are installed.
#![cfg(feature = "vtu")]

use std::collections::HashMap;
use std::path::{Path, PathBuf};

mod vtu_reader;

use tfem::mesh::Mesh;
use tfem::scenes::TwoBlocks;
use tfem::{Component, ContactOptions, ContactWeighting, Material, Model, PlaneMode, Status};
use vtu_reader::{Vtu, as_f64, as_i64, python_arrays, read_vtu, same};

fn out_dir() -> PathBuf {
    let dir = std::env::current_exe()
        .unwrap()
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("vtu");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The seed scene at h = 1/16 solved under `weighting`.
fn seed(weighting: ContactWeighting) -> Model {
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    s.model.set_contact_weighting(weighting).unwrap();
    s.solve(&ContactOptions::default()).unwrap();
    s.model
}

fn written(model: &Model, name: &str) -> PathBuf {
    let path = out_dir().join(name);
    tfem::io::vtu::write_vtu(model, &path).unwrap();
    path
}

/// Plane vectors as the file holds them: [x, y, 0] per point.
fn xyz(v: &[[f64; 2]]) -> Vec<f64> {
    v.iter().flat_map(|d| [d[0], d[1], 0.0]).collect()
}

/// The body triangles' values the file should hold, then `extra`.
fn padded(values: Vec<[f64; 3]>, zeros: usize) -> Vec<f64> {
    let mut v: Vec<f64> = values.into_iter().flatten().collect();
    v.extend(std::iter::repeat_n(0.0, 3 * zeros));
    v
}

/// The mesh and every field common to both weightings, against the model:
/// the cells are the triangles, then the elements `b` of B.
fn check_mesh_and_body_fields(vtu: &Vtu, model: &Model, b: &[tfem::contact::ContactElement]) {
    let mesh = model.mesh().unwrap();
    let n_cells = mesh.triangles().len() + b.len();
    assert_eq!(
        (vtu.points, vtu.cells),
        (mesh.nodes().len(), n_cells),
        "points and cells"
    );
    same(
        "points",
        &vtu.f64s("Points", "Points", 3),
        &xyz(mesh.nodes()),
    );
    let connectivity: Vec<i64> = mesh
        .triangles()
        .iter()
        .chain(b.iter().map(|e| &e.nodes))
        .flatten()
        .map(|&v| v as i64)
        .collect();
    assert_eq!(vtu.ints("Cells", "connectivity"), connectivity);
    let offsets: Vec<i64> = (1..=n_cells as i64).map(|k| 3 * k).collect();
    assert_eq!(vtu.ints("Cells", "offsets"), offsets);
    assert!(vtu.ints("Cells", "types").iter().all(|&t| t == 5));
    same(
        "displacement",
        &vtu.f64s("PointData", "displacement", 3),
        &xyz(&model.displacements().unwrap()),
    );
    let mut body: Vec<i64> = mesh.body_of().iter().map(|&b| i64::from(b)).collect();
    body.extend(std::iter::repeat_n(-1, b.len()));
    assert_eq!(vtu.ints("CellData", "body"), body);
    let mut j = model.element_jacobians().unwrap();
    j.extend(b.iter().map(|e| e.j0));
    same("J", &vtu.f64s("CellData", "J", 1), &j);
    same(
        "strain",
        &vtu.f64s("CellData", "strain", 3),
        &padded(model.element_strains().unwrap(), b.len()),
    );
    same(
        "stress",
        &vtu.f64s("CellData", "stress", 3),
        &padded(model.element_stresses().unwrap(), b.len()),
    );
    let mut normal = model.element_out_of_plane_stresses().unwrap();
    normal.extend(std::iter::repeat_n(0.0, b.len()));
    same(
        "out_of_plane_stress",
        &vtu.f64s("CellData", "out_of_plane_stress", 1),
        &normal,
    );
}

/// The nodal contact arrays against the model.
fn check_nodal_contact(vtu: &Vtu, model: &Model) {
    let p = model.contact_nodal_pressures().unwrap();
    assert!(p.iter().any(|&p| p > 0.0), "a pressed interface");
    same(
        "contact_pressure",
        &vtu.f64s("PointData", "contact_pressure", 1),
        &p,
    );
    let shear: Vec<f64> = (model.contact_nodal_tractions().unwrap().iter())
        .map(|t| t[1])
        .collect();
    same(
        "contact_shear",
        &vtu.f64s("PointData", "contact_shear", 1),
        &shear,
    );
    same(
        "contact_force",
        &vtu.f64s("PointData", "contact_force", 3),
        &xyz(&model.contact_forces().unwrap()),
    );
    same(
        "contact_gap",
        &vtu.f64s("PointData", "contact_gap", 1),
        &model.contact_gaps().unwrap(),
    );
}

#[test]
fn the_file_is_a_little_endian_grid_with_uint64_headers() {
    let vtu = read_vtu(&written(&seed(ContactWeighting::Strip), "header.vtu"), 3);
    assert_eq!(vtu.root["type"], "UnstructuredGrid");
    assert_eq!(vtu.root["version"], "1.0");
    assert_eq!(vtu.root["byte_order"], "LittleEndian");
    assert_eq!(vtu.root["header_type"], "UInt64");
    assert!(!vtu.root.contains_key("compressor"));
}

#[test]
fn a_strip_solve_writes_the_mesh_the_fields_and_the_elements_of_b_to_the_bit() {
    check_strip_solve(ContactWeighting::Strip, "strip.vtu");
}

#[test]
fn the_automatic_weighting_writes_the_elements_of_b_of_its_strip_pairs() {
    // The seed's straight interface gets B under the automatic weighting.
    check_strip_solve(ContactWeighting::Auto, "auto.vtu");
}

fn check_strip_solve(weighting: ContactWeighting, name: &str) {
    let model = seed(weighting);
    let vtu = read_vtu(&written(&model, name), 3);
    let b = model.contact_elements().unwrap();
    assert!(!b.is_empty());
    check_mesh_and_body_fields(&vtu, &model, b);
    check_nodal_contact(&vtu, &model);
    let n_body = model.mesh().unwrap().triangles().len();
    let mut active = vec![0; n_body];
    active.extend(
        model
            .contact_active()
            .unwrap()
            .iter()
            .map(|&a| i64::from(a)),
    );
    assert!(active.contains(&1));
    assert_eq!(vtu.ints("CellData", "contact_element_active"), active);
    let mut pressure = vec![0.0; n_body];
    pressure.extend_from_slice(model.contact_pressure().unwrap());
    same(
        "contact_element_pressure",
        &vtu.f64s("CellData", "contact_element_pressure", 1),
        &pressure,
    );
}

#[test]
fn a_mortar_solve_writes_the_nodal_contact_arrays_and_no_cells_of_b() {
    let model = seed(ContactWeighting::Mortar);
    let vtu = read_vtu(&written(&model, "mortar.vtu"), 3);
    check_mesh_and_body_fields(&vtu, &model, &[]);
    check_nodal_contact(&vtu, &model);
    assert_eq!(
        vtu.names("CellData"),
        ["body", "J", "strain", "stress", "out_of_plane_stress"]
    );
}

#[test]
fn a_load_step_writes_the_nodal_contact_arrays_under_either_weighting() {
    for weighting in [ContactWeighting::Strip, ContactWeighting::Mortar] {
        let mut s = TwoBlocks {
            mesh_size: 1.0 / 16.0,
            ..Default::default()
        }
        .build()
        .unwrap();
        s.model.set_contact_weighting(weighting).unwrap();
        s.model.step(0.5, &ContactOptions::default()).unwrap();
        let vtu = read_vtu(&written(&s.model, "step.vtu"), 3);
        check_nodal_contact(&vtu, &s.model);
    }
}

/// The unit square as two triangles, fixed at the bottom, pulled up at the
/// top: a solve without contact.
fn square_without_contact() -> Model {
    let mesh = Mesh::new(
        vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        vec![[0, 1, 2], [0, 2, 3]],
        vec![1, 1],
        0,
    )
    .unwrap();
    let mut model = Model::new();
    model.set_mesh(mesh);
    let steel = Material::new(2e11, 0.3, PlaneMode::Strain, "square").unwrap();
    model.set_material(1, steel).unwrap();
    for node in [0, 1] {
        model.fix(node, Component::X, 0.0).unwrap();
        model.fix(node, Component::Y, 0.0).unwrap();
    }
    for node in [2, 3] {
        model.add_nodal_force(node, [0.0, 1e6]).unwrap();
    }
    model.solve().unwrap();
    model
}

#[test]
fn a_solve_without_contact_writes_no_contact_array() {
    let model = square_without_contact();
    let vtu = read_vtu(&written(&model, "no_contact.vtu"), 3);
    check_mesh_and_body_fields(&vtu, &model, &[]);
    assert_eq!(vtu.names("PointData"), ["displacement"]);
    assert_eq!(
        vtu.names("CellData"),
        ["body", "J", "strain", "stress", "out_of_plane_stress"]
    );
    assert!(!vtu.has("PointData", "contact_pressure"));
}

#[test]
fn writing_before_a_solve_is_an_invalid_state_and_writes_nothing() {
    let s = TwoBlocks {
        mesh_size: 0.25,
        ..Default::default()
    }
    .build()
    .unwrap();
    let path = out_dir().join("never.vtu");
    let _ = std::fs::remove_file(&path);
    let e = tfem::io::vtu::write_vtu(&s.model, &path).unwrap_err();
    assert_eq!(e.status(), Status::InvalidState);
    assert!(!path.exists());
}

#[test]
fn a_file_that_cannot_be_written_is_an_io_error_in_words_naming_it() {
    let model = square_without_contact();
    let path = Path::new("/nonexistent/directory/out.vtu");
    let e = tfem::io::vtu::write_vtu(&model, path).unwrap_err();
    assert_eq!(e.status(), Status::Io);
    let m = e.message();
    assert!(m.contains("/nonexistent/directory/out.vtu"), "{m}");
    assert!(m.contains("No such file or directory"), "{m}");
    // Not Rust's Debug text (`Os { code: 2, kind: NotFound, … }`).
    assert!(!m.contains("Os {") && !m.contains("kind:"), "{m}");
}

// ---------------------------------------------------------------------------
// Other readers, where installed: meshio, and VTK's own XML reader (the
// one ParaView uses) through its Python bindings. Each prints every array
// as the hex of its little-endian bytes, compared with the model's values.
// ---------------------------------------------------------------------------

/// What another reader gave against the model (strip weighting, so that
/// the cells include the elements of B).
fn check_reader(read: &HashMap<String, Vec<u8>>, model: &Model) {
    let mesh = model.mesh().unwrap();
    let b = model.contact_elements().unwrap();
    same("points", &as_f64(&read["points"]), &xyz(mesh.nodes()));
    let connectivity: Vec<i64> = mesh
        .triangles()
        .iter()
        .chain(b.iter().map(|e| &e.nodes))
        .flatten()
        .map(|&v| v as i64)
        .collect();
    assert_eq!(as_i64(&read["connectivity"]), connectivity);
    same(
        "displacement",
        &as_f64(&read["point/displacement"]),
        &xyz(&model.displacements().unwrap()),
    );
    same(
        "contact_pressure",
        &as_f64(&read["point/contact_pressure"]),
        &model.contact_nodal_pressures().unwrap(),
    );
    same(
        "contact_force",
        &as_f64(&read["point/contact_force"]),
        &xyz(&model.contact_forces().unwrap()),
    );
    same(
        "stress",
        &as_f64(&read["cell/stress"]),
        &padded(model.element_stresses().unwrap(), b.len()),
    );
    let mut pressure = vec![0.0; mesh.triangles().len()];
    pressure.extend_from_slice(model.contact_pressure().unwrap());
    same(
        "contact_element_pressure",
        &as_f64(&read["cell/contact_element_pressure"]),
        &pressure,
    );
    let mut body: Vec<i64> = mesh.body_of().iter().map(|&b| i64::from(b)).collect();
    body.extend(std::iter::repeat_n(-1, b.len()));
    assert_eq!(as_i64(&read["cell/body"]), body);
}

const MESHIO: &str = r#"
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1])
def out(name, a, t):
    print(name, np.ascontiguousarray(a, dtype=t).tobytes().hex())
assert [c.type for c in m.cells] == ["triangle"], m.cells
out("points", m.points, "<f8")
out("connectivity", m.cells[0].data, "<i8")
for k, v in m.point_data.items():
    out("point/" + k, v, "<i8" if v.dtype.kind in "iu" else "<f8")
for k, v in m.cell_data.items():
    out("cell/" + k, v[0], "<i8" if v[0].dtype.kind in "iu" else "<f8")
"#;

#[test]
fn meshio_reads_every_array_to_the_bit_where_installed() {
    let model = seed(ContactWeighting::Strip);
    let path = written(&model, "meshio.vtu");
    if let Some(read) = python_arrays("meshio", MESHIO, &path) {
        check_reader(&read, &model);
    }
}

const VTK: &str = r#"
import sys, vtk, numpy as np
from vtk.util.numpy_support import vtk_to_numpy
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(sys.argv[1])
r.Update()
assert r.GetErrorCode() == 0, r.GetErrorCode()
g = r.GetOutput()
def out(name, a, t):
    print(name, np.ascontiguousarray(vtk_to_numpy(a), dtype=t).tobytes().hex())
out("points", g.GetPoints().GetData(), "<f8")
out("connectivity", g.GetCells().GetConnectivityArray(), "<i8")
for kind, d in (("point", g.GetPointData()), ("cell", g.GetCellData())):
    for i in range(d.GetNumberOfArrays()):
        a = d.GetArray(i)
        out(kind + "/" + a.GetName(), a, "<i8" if a.GetDataTypeAsString() != "double" else "<f8")
s = g.GetCellData().GetArray("stress")
assert [s.GetComponentName(k) for k in range(3)] == ["xx", "yy", "xy"]
"#;

#[test]
fn vtks_xml_reader_reads_every_array_to_the_bit_where_installed() {
    let model = seed(ContactWeighting::Strip);
    let path = written(&model, "vtk.vtu");
    if let Some(read) = python_arrays("vtk", VTK, &path) {
        check_reader(&read, &model);
    }
}
