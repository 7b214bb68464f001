//! The VTU writer of tetrahedral meshes (`write_solid_vtu`): the file holds
//! the mesh and every field given, to the bit, in the layout VTK's XML
//! reader and meshio read. The files are read back by a reader of our own,
//! independent of the writer (tests/vtu_reader, shared with tests/vtu.rs), and
//! by meshio and VTK's Python bindings where they are installed.
#![cfg(feature = "vtu")]

use std::collections::HashMap;
use std::path::{Path, PathBuf};

mod vtu_reader;

use tfem::Status;
use tfem::fem::solid_mesh::{Brick, SolidMesh};
use tfem::io::vtu::{SolidFields, write_solid_vtu};
use vtu_reader::{Vtu, as_f64, as_i64, python_arrays, read_vtu, same};

fn out_dir() -> PathBuf {
    let dir = std::env::current_exe()
        .unwrap()
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("vtu_solid");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Two boxes, bodies 1 and 2, the second not a cube of the first's cells.
fn mesh() -> SolidMesh {
    SolidMesh::bricks(&[
        Brick::uniform([0.0; 3], [1.0, 0.5, 0.25], [3, 2, 2], 1),
        Brick::uniform([0.0, 0.0, 0.25], [1.0, 0.5, 0.5], [2, 1, 3], 2),
    ])
    .unwrap()
}

/// Values of every kind of bits: signs, a negative zero, a subnormal,
/// digits no decimal rounding keeps.
fn value(k: usize) -> f64 {
    match k % 7 {
        0 => -0.0,
        1 => f64::MIN_POSITIVE / 3.0,
        _ => (k as f64 * 0.7).sin() * 1e7 / 3.0,
    }
}

struct Fields {
    u: Vec<[f64; 3]>,
    stress: Vec<[f64; 6]>,
    pressure: Vec<f64>,
}

fn fields(mesh: &SolidMesh) -> Fields {
    let (n, e) = (mesh.nodes().len(), mesh.tets().len());
    Fields {
        u: (0..n)
            .map(|i| std::array::from_fn(|c| value(3 * i + c)))
            .collect(),
        stress: (0..e)
            .map(|i| std::array::from_fn(|c| value(6 * i + c + 1)))
            .collect(),
        pressure: (0..n).map(|i| value(i + 2).abs()).collect(),
    }
}

/// The stresses as the file holds them: VTK's order xx, yy, zz, xy, yz,
/// xz of the Voigt xx, yy, zz, yz, xz, xy given.
fn vtk_order(stress: &[[f64; 6]]) -> Vec<f64> {
    stress
        .iter()
        .flat_map(|s| [s[0], s[1], s[2], s[5], s[3], s[4]])
        .collect()
}

fn connectivity(mesh: &SolidMesh) -> Vec<i64> {
    mesh.tets().iter().flatten().map(|&v| v as i64).collect()
}

/// The mesh, `body` and `J`, which every file holds.
fn check_mesh(vtu: &Vtu, mesh: &SolidMesh) {
    assert_eq!(vtu.root["type"], "UnstructuredGrid");
    assert_eq!(vtu.root["byte_order"], "LittleEndian");
    assert_eq!(vtu.root["header_type"], "UInt64");
    assert_eq!(
        (vtu.points, vtu.cells),
        (mesh.nodes().len(), mesh.tets().len())
    );
    let points: Vec<f64> = mesh.nodes().iter().flatten().copied().collect();
    same("points", &vtu.f64s("Points", "Points", 3), &points);
    assert_eq!(vtu.array("Cells", "connectivity").scalar, "Int32");
    assert_eq!(vtu.ints("Cells", "connectivity"), connectivity(mesh));
    let offsets: Vec<i64> = (1..=mesh.tets().len() as i64).map(|k| 4 * k).collect();
    assert_eq!(vtu.ints("Cells", "offsets"), offsets);
    assert_eq!(vtu.array("Cells", "types").scalar, "UInt8");
    assert!(vtu.ints("Cells", "types").iter().all(|&t| t == 10));
    assert_eq!(vtu.array("CellData", "body").scalar, "Int32");
    let body: Vec<i64> = mesh.body_of().iter().map(|&b| i64::from(b)).collect();
    assert_eq!(vtu.ints("CellData", "body"), body);
    let j: Vec<f64> = (0..mesh.tets().len()).map(|e| mesh.geometry(e).j).collect();
    same("J", &vtu.f64s("CellData", "J", 1), &j);
}

#[test]
fn a_solid_mesh_and_every_field_are_written_to_the_bit() {
    let mesh = mesh();
    assert_eq!(mesh.bodies(), &[1, 2]);
    let f = fields(&mesh);
    let path = out_dir().join("all_fields.vtu");
    let given = SolidFields {
        displacement: Some(&f.u),
        stress: Some(&f.stress),
        contact_pressure: Some(&f.pressure),
    };
    write_solid_vtu(&mesh, &given, &path).unwrap();
    let vtu = read_vtu(&path, 4);
    check_mesh(&vtu, &mesh);
    assert_eq!(vtu.names("PointData"), ["displacement", "contact_pressure"]);
    assert_eq!(vtu.names("CellData"), ["body", "J", "stress"]);
    assert_eq!(vtu.sections["PointData"]["Vectors"], "displacement");
    let u: Vec<f64> = f.u.iter().flatten().copied().collect();
    same(
        "displacement",
        &vtu.f64s("PointData", "displacement", 3),
        &u,
    );
    same(
        "contact_pressure",
        &vtu.f64s("PointData", "contact_pressure", 1),
        &f.pressure,
    );
    same(
        "stress",
        &vtu.f64s("CellData", "stress", 6),
        &vtk_order(&f.stress),
    );
    assert_eq!(
        vtu.array("CellData", "stress").component_names,
        ["xx", "yy", "zz", "xy", "yz", "xz"]
    );
    assert_eq!(
        vtu.array("PointData", "displacement").component_names,
        ["x", "y", "z"]
    );
}

#[test]
fn without_fields_the_file_holds_the_mesh_its_bodies_and_j_only() {
    let mesh = mesh();
    let path = out_dir().join("no_fields.vtu");
    write_solid_vtu(&mesh, &SolidFields::default(), &path).unwrap();
    let vtu = read_vtu(&path, 4);
    check_mesh(&vtu, &mesh);
    assert!(vtu.names("PointData").is_empty());
    assert_eq!(vtu.names("CellData"), ["body", "J"]);
    // No active vectors naming an array that is not there.
    assert!(vtu.sections["PointData"].is_empty(), "{:?}", vtu.sections);
}

#[test]
fn fields_of_the_wrong_length_are_refused_by_name_and_nothing_is_written() {
    let mesh = mesh();
    let (n, e) = (mesh.nodes().len(), mesh.tets().len());
    let f = fields(&mesh);
    let path = out_dir().join("refused.vtu");
    let _ = std::fs::remove_file(&path);
    let cases = [
        (
            SolidFields {
                displacement: Some(&f.u[1..]),
                ..Default::default()
            },
            format!("displacement has {} values for the mesh's {n} nodes", n - 1),
        ),
        (
            SolidFields {
                stress: Some(&f.stress[..e - 2]),
                ..Default::default()
            },
            format!("stress has {} values for the mesh's {e} tetrahedra", e - 2),
        ),
        (
            SolidFields {
                displacement: Some(&f.u),
                contact_pressure: Some(&f.stress.iter().map(|s| s[0]).collect::<Vec<_>>()),
                ..Default::default()
            },
            format!("contact_pressure has {e} values for the mesh's {n} nodes"),
        ),
    ];
    for (given, message) in cases {
        let out = write_solid_vtu(&mesh, &given, &path).unwrap_err();
        assert_eq!(out.status(), Status::InvalidArgument);
        assert_eq!(out.message(), message);
        assert!(!path.exists());
    }
}

#[test]
fn a_file_that_cannot_be_written_is_an_io_error_naming_it() {
    let path = Path::new("/nonexistent/dir/solid.vtu");
    let out = write_solid_vtu(&mesh(), &SolidFields::default(), path).unwrap_err();
    assert_eq!(out.status(), Status::Io);
    assert!(
        out.message().contains("/nonexistent/dir/solid.vtu"),
        "{}",
        out.message()
    );
}

// ---------------------------------------------------------------------------
// Other readers, where installed: meshio, and VTK's own XML reader (the
// one ParaView uses) through its Python bindings. Each prints every array
// as the hex of its little-endian bytes.
// ---------------------------------------------------------------------------

/// What another reader gave against the mesh and fields written.
fn check_reader(read: &HashMap<String, Vec<u8>>, mesh: &SolidMesh, f: &Fields) {
    let points: Vec<f64> = mesh.nodes().iter().flatten().copied().collect();
    same("points", &as_f64(&read["points"]), &points);
    assert_eq!(as_i64(&read["connectivity"]), connectivity(mesh));
    let u: Vec<f64> = f.u.iter().flatten().copied().collect();
    same("displacement", &as_f64(&read["point/displacement"]), &u);
    same(
        "contact_pressure",
        &as_f64(&read["point/contact_pressure"]),
        &f.pressure,
    );
    same(
        "stress",
        &as_f64(&read["cell/stress"]),
        &vtk_order(&f.stress),
    );
    let body: Vec<i64> = mesh.body_of().iter().map(|&b| i64::from(b)).collect();
    assert_eq!(as_i64(&read["cell/body"]), body);
}

fn written_with_fields(name: &str) -> (SolidMesh, Fields, PathBuf) {
    let mesh = mesh();
    let f = fields(&mesh);
    let path = out_dir().join(name);
    let given = SolidFields {
        displacement: Some(&f.u),
        stress: Some(&f.stress),
        contact_pressure: Some(&f.pressure),
    };
    write_solid_vtu(&mesh, &given, &path).unwrap();
    (mesh, f, path)
}

const MESHIO: &str = r#"
import sys, meshio, numpy as np
m = meshio.read(sys.argv[1])
def out(name, a, t):
    print(name, np.ascontiguousarray(a, dtype=t).tobytes().hex())
assert [c.type for c in m.cells] == ["tetra"], m.cells
out("points", m.points, "<f8")
out("connectivity", m.cells[0].data, "<i8")
for k, v in m.point_data.items():
    out("point/" + k, v, "<i8" if v.dtype.kind in "iu" else "<f8")
for k, v in m.cell_data.items():
    out("cell/" + k, v[0], "<i8" if v[0].dtype.kind in "iu" else "<f8")
"#;

#[test]
fn meshio_reads_every_array_to_the_bit_where_installed() {
    let (mesh, f, path) = written_with_fields("meshio.vtu");
    if let Some(read) = python_arrays("meshio", MESHIO, &path) {
        check_reader(&read, &mesh, &f);
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
assert all(g.GetCellType(i) == vtk.VTK_TETRA for i in range(g.GetNumberOfCells()))
def out(name, a, t):
    print(name, np.ascontiguousarray(vtk_to_numpy(a), dtype=t).tobytes().hex())
out("points", g.GetPoints().GetData(), "<f8")
out("connectivity", g.GetCells().GetConnectivityArray(), "<i8")
for kind, d in (("point", g.GetPointData()), ("cell", g.GetCellData())):
    for i in range(d.GetNumberOfArrays()):
        a = d.GetArray(i)
        out(kind + "/" + a.GetName(), a, "<i8" if a.GetDataTypeAsString() != "double" else "<f8")
s = g.GetCellData().GetArray("stress")
assert [s.GetComponentName(k) for k in range(6)] == ["xx", "yy", "zz", "xy", "yz", "xz"]
"#;

#[test]
fn vtks_xml_reader_reads_every_array_to_the_bit_where_installed() {
    let (mesh, f, path) = written_with_fields("vtk.vtu");
    if let Some(read) = python_arrays("vtk", VTK, &path) {
        check_reader(&read, &mesh, &f);
    }
}
