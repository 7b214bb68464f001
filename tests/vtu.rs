//! The VTU writer: the file holds the mesh and every field the model gives,
//! to the bit, in the layout VTK's XML reader (ParaView's) and meshio read:
//! raw appended data, one block per array, each its UInt64 byte count and
//! its little-endian values. The files are read back here by a reader of
//! our own, independent of the writer, and by meshio and VTK's Python
//! bindings where they are installed.
#![cfg(feature = "vtu")]

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use tfem::mesh::Mesh;
use tfem::scenes::TwoBlocks;
use tfem::{Component, ContactOptions, ContactWeighting, Material, Model, PlaneMode, Status};

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

// ---------------------------------------------------------------------------
// A reader of our own: the XML up to `<AppendedData encoding="raw">` read
// tag by tag, then each array's block found at its offset from the byte
// after `_`. It checks the layout rules of the VTK XML format as it goes.
// ---------------------------------------------------------------------------

/// One `DataArray` of the file.
#[derive(Debug)]
struct Array {
    /// Its section: `Points`, `Cells`, `PointData` or `CellData`.
    section: String,
    name: String,
    scalar: String,
    components: usize,
    /// Its value bytes (after the byte count).
    bytes: Vec<u8>,
}

struct Vtu {
    root: HashMap<String, String>,
    points: usize,
    cells: usize,
    arrays: Vec<Array>,
}

/// The attributes of the tag text `text` (between `<` and `>`).
fn attributes(text: &str) -> HashMap<String, String> {
    let mut out = HashMap::new();
    let mut rest = text.split_once(char::is_whitespace).map_or("", |s| s.1);
    while let Some((key, after)) = rest.split_once("=\"") {
        let (value, tail) = after.split_once('"').expect("a closing quote");
        let previous = out.insert(key.trim().to_string(), value.to_string());
        assert!(previous.is_none(), "attribute {key} given twice");
        rest = tail;
    }
    out
}

fn scalar_size(scalar: &str) -> usize {
    match scalar {
        "Float64" | "Int64" | "UInt64" => 8,
        "Float32" | "Int32" | "UInt32" => 4,
        "UInt8" | "Int8" => 1,
        other => panic!("unexpected type {other}"),
    }
}

fn read_vtu(path: &Path) -> Vtu {
    let file = std::fs::read(path).unwrap();
    let start_tag = b"<AppendedData encoding=\"raw\">";
    let at = file
        .windows(start_tag.len())
        .position(|w| w == start_tag)
        .expect("<AppendedData encoding=\"raw\">");
    let xml = std::str::from_utf8(&file[..at]).expect("the XML is text");
    let after_tag = at + start_tag.len();
    let underscore = after_tag
        + file[after_tag..]
            .iter()
            .position(|&b| b == b'_')
            .expect("the `_` that opens the data");
    assert!(
        file[after_tag..underscore]
            .iter()
            .all(u8::is_ascii_whitespace),
        "only blanks between <AppendedData> and `_`"
    );
    let data = &file[underscore + 1..];

    let (mut root, mut piece) = (None, None);
    let mut section = String::new();
    let mut headers = Vec::new();
    for tag in xml.split('<').skip(1) {
        let text = tag.split_once('>').expect("a tag ends with >").0;
        let name = text.split_whitespace().next().unwrap_or("");
        match name {
            "?xml" => {}
            "VTKFile" => root = Some(attributes(text)),
            "UnstructuredGrid" | "/UnstructuredGrid" | "/Piece" => {}
            "Piece" => piece = Some(attributes(text)),
            "Points" | "Cells" | "PointData" | "CellData" => {
                assert!(section.is_empty(), "{name} inside {section}");
                section = name.to_string();
            }
            "/Points" | "/Cells" | "/PointData" | "/CellData" => {
                assert_eq!(&name[1..], section, "{name} closes {section}");
                section.clear();
            }
            "DataArray" => {
                assert!(text.ends_with('/'), "an appended DataArray is empty");
                assert!(!section.is_empty(), "a DataArray outside a section");
                headers.push((section.clone(), attributes(text.trim_end_matches('/'))));
            }
            other => panic!("unexpected tag <{other}>"),
        }
    }
    let root = root.expect("<VTKFile>");
    let piece = piece.expect("<Piece>");
    let count = |key: &str| -> usize { piece[key].parse().unwrap() };
    let (points, cells) = (count("NumberOfPoints"), count("NumberOfCells"));

    // The blocks tile the data in the order of the headers, from offset 0.
    let mut next = 0usize;
    let mut arrays = Vec::new();
    for (section, a) in headers {
        assert_eq!(a["format"], "appended", "{a:?}");
        let offset: usize = a["offset"].parse().unwrap();
        assert_eq!(offset, next, "{a:?}: the blocks must follow each other");
        let length = u64::from_le_bytes(data[offset..offset + 8].try_into().unwrap()) as usize;
        let components: usize = a["NumberOfComponents"].parse().unwrap();
        let tuples = match section.as_str() {
            "Points" | "PointData" => points,
            "CellData" => cells,
            _ => match a["Name"].as_str() {
                "connectivity" => 3 * cells,
                _ => cells,
            },
        };
        assert_eq!(
            length,
            tuples * components * scalar_size(&a["type"]),
            "{a:?}: the byte count"
        );
        arrays.push(Array {
            section,
            name: a["Name"].clone(),
            scalar: a["type"].clone(),
            components,
            bytes: data[offset + 8..offset + 8 + length].to_vec(),
        });
        next = offset + 8 + length;
    }
    let tail = std::str::from_utf8(&data[next..]).expect("text after the data");
    let words: Vec<&str> = tail.split_whitespace().collect();
    assert_eq!(words, ["</AppendedData>", "</VTKFile>"]);
    assert!(
        tail.starts_with('\n'),
        "a line break ends the data (meshio cuts the data at the last one)"
    );
    Vtu {
        root,
        points,
        cells,
        arrays,
    }
}

impl Vtu {
    fn array(&self, section: &str, name: &str) -> &Array {
        self.arrays
            .iter()
            .find(|a| a.section == section && a.name == name)
            .unwrap_or_else(|| panic!("{section}/{name} missing"))
    }

    fn has(&self, section: &str, name: &str) -> bool {
        self.arrays
            .iter()
            .any(|a| a.section == section && a.name == name)
    }

    fn names(&self, section: &str) -> Vec<&str> {
        self.arrays
            .iter()
            .filter(|a| a.section == section)
            .map(|a| a.name.as_str())
            .collect()
    }

    fn f64s(&self, section: &str, name: &str, components: usize) -> Vec<f64> {
        let a = self.array(section, name);
        assert_eq!((a.scalar.as_str(), a.components), ("Float64", components));
        a.bytes
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
            .collect()
    }

    fn ints(&self, section: &str, name: &str) -> Vec<i64> {
        let a = self.array(section, name);
        assert_eq!(a.components, 1);
        match a.scalar.as_str() {
            "Int32" => a
                .bytes
                .chunks_exact(4)
                .map(|b| i64::from(i32::from_le_bytes(b.try_into().unwrap())))
                .collect(),
            "Int64" => a
                .bytes
                .chunks_exact(8)
                .map(|b| i64::from_le_bytes(b.try_into().unwrap()))
                .collect(),
            "UInt8" => a.bytes.iter().map(|&b| i64::from(b)).collect(),
            other => panic!("{name} is {other}"),
        }
    }
}

/// Plane vectors as the file holds them: [x, y, 0] per point.
fn xyz(v: &[[f64; 2]]) -> Vec<f64> {
    v.iter().flat_map(|d| [d[0], d[1], 0.0]).collect()
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Asserts `read` and `model` are the same values, bit for bit.
fn same(what: &str, read: &[f64], model: &[f64]) {
    assert_eq!(read.len(), model.len(), "{what}: lengths");
    assert!(bits(read) == bits(model), "{what}: values differ");
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
    let vtu = read_vtu(&written(&seed(ContactWeighting::Strip), "header.vtu"));
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
    let vtu = read_vtu(&written(&model, name));
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
    let vtu = read_vtu(&written(&model, "mortar.vtu"));
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
        let vtu = read_vtu(&written(&s.model, "step.vtu"));
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
    let vtu = read_vtu(&written(&model, "no_contact.vtu"));
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

/// Runs `script` (Python, given the file's path) if `python3` can import
/// `module`; None, with a note on stdout, where it cannot.
fn python_arrays(module: &str, script: &str, path: &Path) -> Option<HashMap<String, Vec<u8>>> {
    let probe = Command::new("python3")
        .args(["-c", &format!("import {module}")])
        .output();
    if !probe.is_ok_and(|o| o.status.success()) {
        println!("note: skipped: python3 cannot import {module} (pip install {module} to run it)");
        return None;
    }
    let out = Command::new("python3")
        .args(["-c", script])
        .arg(path)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{module} failed:\n{stderr}");
    assert!(stderr.trim().is_empty(), "{module} complained:\n{stderr}");
    let text = String::from_utf8(out.stdout).unwrap();
    let hex = |s: &str| -> Vec<u8> {
        (0..s.len())
            .step_by(2)
            .map(|k| u8::from_str_radix(&s[k..k + 2], 16).unwrap())
            .collect()
    };
    Some(
        text.lines()
            .map(|l| {
                let (name, bytes) = l.split_once(' ').unwrap_or((l, ""));
                (name.to_string(), hex(bytes))
            })
            .collect(),
    )
}

fn as_f64(bytes: &[u8]) -> Vec<f64> {
    bytes
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

fn as_i64(bytes: &[u8]) -> Vec<i64> {
    bytes
        .chunks_exact(8)
        .map(|b| i64::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

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
