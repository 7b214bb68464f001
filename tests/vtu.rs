//! The VTU writer: the file ParaView reads back has the mesh, the solved
//! displacement and the per-cell fields, body cells and contact cells.
#![cfg(feature = "vtu")]

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;
use vtkio::model::{Attribute, DataSet, IOBuffer, Piece};

#[test]
fn written_vtu_reads_back_with_every_field() {
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    s.solve(&ContactOptions::default()).unwrap();
    let dir = std::env::current_exe()
        .unwrap()
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("vtu");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("two_blocks.vtu");
    tfem::io::vtu::write_vtu(&s.model, &path).unwrap();

    let vtk = vtkio::Vtk::import(&path).unwrap();
    let DataSet::UnstructuredGrid { pieces, .. } = vtk.data else {
        panic!("not an unstructured grid")
    };
    let Piece::Inline(piece) = &pieces[0] else {
        panic!("not inline")
    };
    let mesh = s.model.mesh().unwrap();
    let n_contact = s.model.contact_elements().unwrap().len();
    assert_eq!(piece.points.len(), 3 * mesh.nodes().len());
    assert_eq!(piece.cells.types.len(), mesh.triangles().len() + n_contact);
    let u = s.model.displacements().unwrap();
    let Attribute::DataArray(d) = &piece.data.point[0] else {
        panic!()
    };
    assert_eq!(d.name, "displacement");
    let IOBuffer::F64(values) = &d.data else {
        panic!("f64 displacement")
    };
    assert_eq!(values[3 * s.top_center + 1], u[s.top_center][1]);
    let names: Vec<&str> = piece.data.cell.iter().map(|a| a.name()).collect();
    for name in [
        "body",
        "J",
        "strain",
        "stress",
        "contact_active",
        "contact_pressure",
    ] {
        assert!(names.contains(&name), "{name} missing in {names:?}");
    }
    let active = piece
        .data
        .cell
        .iter()
        .find(|a| a.name() == "contact_active")
        .unwrap();
    let Attribute::DataArray(a) = active else {
        panic!()
    };
    let IOBuffer::F64(flags) = &a.data else {
        panic!()
    };
    let n_active = flags.iter().filter(|&&f| f == 1.0).count();
    assert_eq!(
        n_active,
        s.model
            .contact_active()
            .unwrap()
            .iter()
            .filter(|&&a| a)
            .count()
    );
}

#[test]
fn writing_before_a_solve_is_an_invalid_state() {
    let s = TwoBlocks {
        mesh_size: 0.25,
        ..Default::default()
    }
    .build()
    .unwrap();
    let e = tfem::io::vtu::write_vtu(&s.model, std::path::Path::new("/tmp/never.vtu")).unwrap_err();
    assert_eq!(e.status(), tfem::Status::InvalidState);
}

#[test]
fn a_file_that_cannot_be_written_is_an_io_error_in_words_naming_it() {
    let mut s = TwoBlocks {
        mesh_size: 0.25,
        ..Default::default()
    }
    .build()
    .unwrap();
    s.solve(&ContactOptions::default()).unwrap();
    let path = std::path::Path::new("/nonexistent/directory/out.vtu");
    let e = tfem::io::vtu::write_vtu(&s.model, path).unwrap_err();
    assert_eq!(e.status(), tfem::Status::Io);
    let m = e.message();
    assert!(m.contains("/nonexistent/directory/out.vtu"), "{m}");
    assert!(m.contains("No such file or directory"), "{m}");
    // Not Rust's Debug text (`Os { code: 2, kind: NotFound, … }`).
    assert!(!m.contains("Os {") && !m.contains("kind:"), "{m}");
}
