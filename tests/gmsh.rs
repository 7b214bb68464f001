//! Gmsh meshes in: the seed scene described by examples/meshes/two_blocks.geo,
//! meshed by Debian's gmsh at two sizes (ASCII and binary MSH 4.1), solved,
//! and compared with the built-in structured mesh within discretisation
//! error; and malformed or unsupported files get clear errors.
#![cfg(feature = "gmsh")]

use std::path::{Path, PathBuf};
use std::process::Command;

use tfem::io::gmsh::read_msh;
use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TAG_LOAD, TAG_SUPPORT, TwoBlocks};
use tfem::{Component, ContactOptions, Material, Model, PlaneMode, Status};

const TAG_SYMMETRY: i32 = 5;

fn out_dir() -> PathBuf {
    let d = std::env::current_exe()
        .unwrap()
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("gmsh");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn mesh_with_gmsh(h: f64, binary: bool) -> PathBuf {
    let geo = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/meshes/two_blocks.geo");
    let out = out_dir().join(format!(
        "two_blocks_{h}_{}.msh",
        if binary { "bin" } else { "ascii" }
    ));
    let mut cmd = Command::new("gmsh");
    cmd.args(["-2", "-format", "msh41", "-setnumber", "h", &h.to_string()]);
    if binary {
        cmd.arg("-bin");
    }
    let status = cmd
        .arg(&geo)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("gmsh is installed (Debian package gmsh; scripts/test.sh installs it)");
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    out
}

/// (ℓc, v_top, compliance) of the seed scene on a Gmsh mesh.
fn solve_gmsh(path: &Path) -> (f64, f64, f64) {
    let mesh = read_msh(path, 0).unwrap();
    let top = mesh
        .nodes()
        .iter()
        .enumerate()
        .filter(|(_, p)| p[0] == 0.5 && p[1] == 0.25)
        .map(|(i, _)| i)
        .next()
        .expect("a node at (L/2, H2)");
    let mut model = Model::new();
    model.set_mesh(mesh);
    model
        .set_material(
            1,
            Material::new(1e10, 0.3, PlaneMode::Strain, "body 1").unwrap(),
        )
        .unwrap();
    model
        .set_material(
            2,
            Material::new(1e11, 0.3, PlaneMode::Strain, "body 2").unwrap(),
        )
        .unwrap();
    model.fix_edges(TAG_SYMMETRY, Component::X, 0.0).unwrap();
    model.fix_edges(TAG_SUPPORT, Component::Y, 0.0).unwrap();
    model.add_pressure(TAG_LOAD, 1e7).unwrap();
    model
        .add_contact_pair(TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)
        .unwrap();
    let r = model.solve_contact(&ContactOptions::default()).unwrap();
    let v_top = model.displacements().unwrap()[top][1];
    (r.contact_length, v_top, model.external_work().unwrap())
}

fn solve_structured(h: f64) -> (f64, f64, f64) {
    let mut s = TwoBlocks {
        mesh_size: h,
        ..Default::default()
    }
    .build()
    .unwrap();
    let r = s.solve(&ContactOptions::default()).unwrap();
    (r.lc, r.v_top, r.compliance)
}

#[test]
fn gmsh_meshes_of_the_seed_scene_match_the_structured_mesh_within_discretisation_error() {
    for h in [1.0 / 16.0, 1.0 / 32.0] {
        let s = solve_structured(h);
        let s_fine = solve_structured(h / 2.0);
        // First-order convergence: |s(h) − s(h/2)| estimates the error of s(h).
        let est_v = (s.1 - s_fine.1).abs();
        let est_c = (s.2 - s_fine.2).abs();
        for binary in [false, true] {
            let g = solve_gmsh(&mesh_with_gmsh(h, binary));
            assert!(
                (g.0 - s.0).abs() <= 2.0 * h,
                "h = {h}: ℓc gmsh {} vs structured {}",
                g.0,
                s.0
            );
            assert!(
                (g.1 - s.1).abs() <= 3.0 * est_v,
                "h = {h}: v_top gmsh {} vs {} (est. error {est_v})",
                g.1,
                s.1
            );
            assert!(
                (g.2 - s.2).abs() <= 3.0 * est_c,
                "h = {h}: compliance gmsh {} vs {} (est. error {est_c})",
                g.2,
                s.2
            );
        }
    }
}

#[test]
fn ascii_and_binary_files_give_the_same_mesh() {
    let a = read_msh(&mesh_with_gmsh(0.1, false), 0).unwrap();
    let b = read_msh(&mesh_with_gmsh(0.1, true), 0).unwrap();
    // ASCII files carry 16 significant digits, binary ones the exact doubles.
    assert_eq!(a.nodes().len(), b.nodes().len());
    for (p, q) in a.nodes().iter().zip(b.nodes()) {
        assert!(
            (p[0] - q[0]).abs() < 1e-14 && (p[1] - q[1]).abs() < 1e-14,
            "{p:?} vs {q:?}"
        );
    }
    assert_eq!(a.triangles(), b.triangles());
    assert_eq!(a.body_of(), b.body_of());
    assert_eq!(a.boundary_edges().len(), b.boundary_edges().len());
    assert_eq!(a.bodies(), &[1, 2]);
    assert!(
        a.warnings().is_empty() || a.warnings().iter().all(|w| !w.contains("clockwise")),
        "{:?}",
        a.warnings()
    );
}

fn write(name: &str, text: &str) -> PathBuf {
    let p = out_dir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

const HEADER: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

#[test]
fn a_missing_file_is_an_io_error_naming_it() {
    let e = read_msh(Path::new("/nonexistent/mesh.msh"), 0).unwrap_err();
    assert_eq!(e.status(), Status::Io);
    assert!(
        e.message().contains("/nonexistent/mesh.msh"),
        "{}",
        e.message()
    );
}

#[test]
fn garbage_is_an_io_error() {
    let e = read_msh(&write("garbage.msh", "hello"), 0).unwrap_err();
    assert_eq!(e.status(), Status::Io, "{}", e.message());
}

#[test]
fn a_mesh_without_physical_groups_is_rejected() {
    // One triangle on surface 1, which has no physical tag.
    let text = format!(
        "{HEADER}$Entities\n0 0 1 0\n1 0 0 0 1 1 0 0 0\n$EndEntities\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n"
    );
    let e = read_msh(&write("nophys.msh", &text), 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh);
    assert!(
        e.message().contains("surface 1 has no physical group"),
        "{}",
        e.message()
    );
}

#[test]
fn quadrangles_and_non_planar_nodes_are_rejected() {
    let quads = format!(
        "{HEADER}$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 4\n$EndElements\n"
    );
    let e = read_msh(&write("quads.msh", &quads), 0).unwrap_err();
    assert!(
        e.message().contains("only 3-node triangles"),
        "{}",
        e.message()
    );
    let tilted = format!(
        "{HEADER}$Entities\n0 0 1 0\n1 0 0 0 1 1 1 1 7 0\n$EndEntities\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0.5\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n"
    );
    let e = read_msh(&write("tilted.msh", &tilted), 0).unwrap_err();
    assert!(
        e.message().contains("node 3 has z = 0.5"),
        "{}",
        e.message()
    );
}
