//! Results as a VTK XML unstructured grid (`.vtu`, for ParaView), written
//! with the `vtkio` crate. Feature `vtu`.

use std::path::Path;

use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataArray, DataSet, UnstructuredGridPiece,
    Version, VertexNumbers, Vtk,
};

use crate::error::{Error, Result, Status};
use crate::fem::element::TriGeometry;
use crate::model::Model;

fn cell_array(name: &str, comps: u32, data: Vec<f64>) -> Attribute {
    Attribute::DataArray(DataArray::scalars(name, comps).with_data(data))
}

/// Writes the mesh in its initial configuration with the solved fields:
/// point data `displacement` (3 components, z = 0); cell data `body`, `J`,
/// `strain` and `stress` (Voigt, 3 components), and for the elements of the
/// contact mesh B (appended after the body triangles, body −1)
/// `contact_active` and `contact_pressure`. Needs a solved model.
pub fn write_vtu(model: &Model, path: &Path) -> Result<()> {
    let mesh = model
        .mesh()
        .ok_or_else(|| Error::state("no mesh to write"))?;
    let u = model.displacements()?;
    let strains = model.element_strains()?;
    let stresses = model.element_stresses()?;
    let contact = model.contact_elements().ok();
    let active = model.contact_active().ok();
    let pressure = model.contact_pressure().ok();

    let points: Vec<f64> = mesh
        .nodes()
        .iter()
        .flat_map(|p| [p[0], p[1], 0.0])
        .collect();
    let mut conn: Vec<u64> = Vec::new();
    let mut body = Vec::new();
    let mut jac = Vec::new();
    for (t, b) in mesh.triangles().iter().zip(mesh.body_of()) {
        conn.extend(t.iter().map(|&v| v as u64));
        body.push(f64::from(*b));
        jac.push(TriGeometry::new(&mesh.corners(t)).j);
    }
    let n_body = mesh.triangles().len();
    let n_contact = contact.map_or(0, |c| c.len());
    let mut strain: Vec<f64> = strains.iter().flatten().copied().collect();
    let mut stress: Vec<f64> = stresses.iter().flatten().copied().collect();
    let mut c_active = vec![0.0; n_body];
    let mut c_pressure = vec![0.0; n_body];
    if let (Some(c), Some(a), Some(p)) = (contact, active, pressure) {
        for (k, e) in c.iter().enumerate() {
            conn.extend(e.nodes.iter().map(|&v| v as u64));
            body.push(-1.0);
            jac.push(e.j0);
            c_active.push(if a[k] { 1.0 } else { 0.0 });
            c_pressure.push(p[k]);
        }
        strain.extend(std::iter::repeat_n(0.0, 3 * n_contact));
        stress.extend(std::iter::repeat_n(0.0, 3 * n_contact));
    }
    let n_cells = n_body + n_contact;
    let offsets: Vec<u64> = (1..=n_cells as u64).map(|k| 3 * k).collect();
    let displacement: Vec<f64> = u.iter().flat_map(|d| [d[0], d[1], 0.0]).collect();
    let vtk = Vtk {
        version: Version::new((1, 0)),
        byte_order: ByteOrder::LittleEndian,
        title: "tfem".to_string(),
        file_path: None,
        data: DataSet::inline(UnstructuredGridPiece {
            points: points.into(),
            cells: Cells {
                cell_verts: VertexNumbers::XML {
                    connectivity: conn,
                    offsets,
                },
                types: vec![CellType::Triangle; n_cells],
            },
            data: Attributes {
                point: vec![Attribute::DataArray(
                    DataArray::vectors("displacement").with_data(displacement),
                )],
                cell: vec![
                    cell_array("body", 1, body),
                    cell_array("J", 1, jac),
                    cell_array("strain", 3, strain),
                    cell_array("stress", 3, stress),
                    cell_array("contact_active", 1, c_active),
                    cell_array("contact_pressure", 1, c_pressure),
                ],
            },
        }),
    };
    vtk.export(path).map_err(|e| {
        Error::new(
            Status::Io,
            format!("cannot write {}: {}", path.display(), reason(&e)),
        )
    })
}

/// Why `vtkio` could not write, in words: its own messages print their
/// causes with `Debug` (`I/O error: Os { code: 2, kind: NotFound, … }`),
/// so the cause is looked for down its chain: the operating system's
/// error if there is one (`No such file or directory (os error 2)`), else
/// the innermost cause.
fn reason(e: &vtkio::Error) -> String {
    let mut cause: &(dyn std::error::Error + 'static) = e;
    loop {
        if let Some(io) = cause.downcast_ref::<std::io::Error>() {
            return io.to_string();
        }
        match cause.source() {
            Some(next) => cause = next,
            None => return cause.to_string(),
        }
    }
}
