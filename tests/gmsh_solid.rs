//! Tetrahedral Gmsh meshes in (`read_solid_msh`): a hand-written file read
//! exactly; a box and two stacked boxes meshed by Debian's gmsh at run
//! time (ASCII and binary MSH 4.1) whose volume, tagged sides' areas and
//! outward normals are the geometry's; and what a solid mesh cannot take
//! refused with the file's own element and node tags.
#![cfg(feature = "gmsh")]

use std::path::PathBuf;
use std::process::Command;

use tfem::Status;
use tfem::fem::solid_mesh::{BoundaryFace, SolidMesh};
use tfem::io::gmsh::{read_msh, read_solid_msh};

fn out_dir() -> PathBuf {
    let d = std::env::current_exe()
        .unwrap()
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("gmsh_solid");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn write(name: &str, text: &str) -> PathBuf {
    let p = out_dir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Meshes `geo` (the text of a .geo file) in 3D with gmsh into MSH 4.1,
/// ASCII or binary, with any further arguments.
fn mesh_with_gmsh(name: &str, geo: &str, binary: bool, args: &[&str]) -> PathBuf {
    let geo_path = write(&format!("{name}.geo"), geo);
    let out = out_dir().join(format!(
        "{name}_{}.msh",
        if binary { "bin" } else { "ascii" }
    ));
    let mut cmd = Command::new("gmsh");
    cmd.args(["-3", "-format", "msh41"]).args(args);
    if binary {
        cmd.arg("-bin");
    }
    let run = cmd
        .arg(&geo_path)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("gmsh is installed (Debian package gmsh; scripts/test.sh installs it)");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    out
}

fn volume(mesh: &SolidMesh) -> f64 {
    (0..mesh.tets().len())
        .map(|e| mesh.geometry(e).j / 6.0)
        .sum()
}

fn faces(mesh: &SolidMesh, tag: i32) -> Vec<BoundaryFace> {
    (mesh.boundary_faces().iter())
        .filter(|f| f.tag == tag)
        .copied()
        .collect()
}

fn area(mesh: &SolidMesh, tag: i32) -> f64 {
    (faces(mesh, tag).iter())
        .map(|f| mesh.face_geometry(f).area)
        .sum()
}

/// Every face tagged `tag` has the outward normal `normal`, to rounding.
fn check_normals(mesh: &SolidMesh, tag: i32, normal: [f64; 3]) {
    let faces = faces(mesh, tag);
    assert!(!faces.is_empty(), "side {tag} has faces");
    for f in faces {
        let n = mesh.face_geometry(&f).normal;
        let off = (0..3).map(|i| (n[i] - normal[i]).abs()).fold(0.0, f64::max);
        assert!(off < 1e-12, "side {tag}: normal {n:?}, expected {normal:?}");
    }
}

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-12 * b.abs(),
        "{what}: {a} against {b} ({:.1e} relative)",
        (a - b) / b
    );
}

// ---------------------------------------------------------------------------
// (a) A hand-written file, read exactly.
// ---------------------------------------------------------------------------

const HEADER: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

const NAMES: &str = "$PhysicalNames\n4\n3 1 \"steel\"\n2 10 \"bottom\"\n2 20 \"slant\"\n\
                     2 99 \"all\"\n$EndPhysicalNames\n";

/// Surface 1 in groups 10 and 99, surface 2 in group 20, volume 1 in
/// group 1 (`volume_groups` replaces "1 1" with its own count and tags).
fn entities(volume_groups: &str) -> String {
    format!(
        "$Entities\n0 0 2 1\n1 0 0 0 1 1 0 2 10 99 0\n2 0 0 0 1 1 1 1 20 0\n\
         1 0 0 0 1 1 1 {volume_groups} 0\n$EndEntities\n"
    )
}

/// Nodes 101 to 105 of volume 1: A = (0,0,0), B = (1,0,0), C = (0,1,0),
/// D = (0,0,1), E = (1,1,1).
const NODES: &str = "$Nodes\n1 5 101 105\n3 1 0 5\n101\n102\n103\n104\n105\n\
                     0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n";

/// Tetrahedra 1 = ABCD and 2 = BCDE (as given by `tets`), triangle 7 on
/// surface 1 and triangle 8 on surface 2 (as given by `triangles`).
fn elements(tets: [&str; 2], triangles: [&str; 2]) -> String {
    format!(
        "$Elements\n3 4 1 8\n3 1 4 2\n1 {}\n2 {}\n2 1 2 1\n7 {}\n2 2 2 1\n8 {}\n$EndElements\n",
        tets[0], tets[1], triangles[0], triangles[1]
    )
}

const TETS: [&str; 2] = ["101 102 103 104", "102 103 104 105"];
/// ABC (tetrahedron 1's side z = 0) and BCE (tetrahedron 2's slanted side).
const TRIANGLES: [&str; 2] = ["101 102 103", "102 103 105"];

fn two_tets(name: &str, volume_groups: &str, tets: [&str; 2], triangles: [&str; 2]) -> PathBuf {
    write(
        name,
        &format!(
            "{HEADER}{NAMES}{}{NODES}{}",
            entities(volume_groups),
            elements(tets, triangles)
        ),
    )
}

#[test]
fn a_hand_written_file_of_two_tetrahedra_is_read_exactly() {
    let path = two_tets("two_tets.msh", "1 1", TETS, TRIANGLES);
    for base in [0, 1] {
        let mesh = read_solid_msh(&path, base).unwrap();
        assert_eq!(
            mesh.nodes(),
            &[
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, 0.0, 1.0],
                [1.0, 1.0, 1.0]
            ]
        );
        assert_eq!(mesh.tets(), &[[0, 1, 2, 3], [1, 2, 3, 4]]);
        assert_eq!(mesh.body_of(), &[1, 1]);
        assert_eq!(mesh.index_base(), base);
        // Surface 1 is in groups 10 and 99: its triangle once per group.
        let face = |nodes, tag, owner| BoundaryFace { nodes, tag, owner };
        assert_eq!(
            mesh.boundary_faces(),
            &[
                face([0, 1, 2], 10, 0),
                face([0, 1, 2], 99, 0),
                face([1, 2, 4], 20, 1)
            ]
        );
        assert!(mesh.warnings().is_empty(), "{:?}", mesh.warnings());
        assert_eq!(volume(&mesh), 0.5);
        check_normals(&mesh, 10, [0.0, 0.0, -1.0]);
        let s = 1.0 / 3f64.sqrt();
        check_normals(&mesh, 20, [s, s, -s]);
    }
}

#[test]
fn a_node_used_by_no_tetrahedron_is_warned_of() {
    let text = format!(
        "{HEADER}{}$Nodes\n1 6 101 106\n3 1 0 6\n101\n102\n103\n104\n105\n106\n\
         0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n5 5 5\n$EndNodes\n{}",
        entities("1 1"),
        elements(TETS, TRIANGLES)
    );
    let mesh = read_solid_msh(&write("unused_node.msh", &text), 0).unwrap();
    assert_eq!(mesh.nodes().len(), 6);
    assert!(
        mesh.warnings().iter().any(|w| w.contains("not used")),
        "{:?}",
        mesh.warnings()
    );
}

// ---------------------------------------------------------------------------
// (b) A box meshed by gmsh.
// ---------------------------------------------------------------------------

/// The box [0, 2] × [0, 1] × [0, 0.5], body 7, its sides x = 0, x = 2,
/// y = 0, y = 1, z = 0, z = 0.5 in groups 1 to 6 (OpenCASCADE numbers a
/// box's surfaces so) and all of them in group 99 too.
const BOX: &str = r#"SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 0.5};
Mesh.MeshSizeMax = 0.2;
Physical Volume("block", 7) = {1};
For k In {1:6}
  Physical Surface(k) = {k};
EndFor
Physical Surface("all", 99) = {1:6};
"#;

const SIDES: [(i32, [f64; 3], f64); 6] = [
    (1, [-1.0, 0.0, 0.0], 0.5),
    (2, [1.0, 0.0, 0.0], 0.5),
    (3, [0.0, -1.0, 0.0], 1.0),
    (4, [0.0, 1.0, 0.0], 1.0),
    (5, [0.0, 0.0, -1.0], 2.0),
    (6, [0.0, 0.0, 1.0], 2.0),
];

#[test]
fn a_box_meshed_by_gmsh_has_its_volume_sides_and_outward_normals() {
    let mut read = Vec::new();
    for binary in [false, true] {
        let mesh = read_solid_msh(&mesh_with_gmsh("box", BOX, binary, &[]), 0).unwrap();
        assert!(mesh.tets().len() > 500, "{} tetrahedra", mesh.tets().len());
        assert_eq!(mesh.bodies(), &[7]);
        assert!(mesh.warnings().is_empty(), "{:?}", mesh.warnings());
        for e in 0..mesh.tets().len() {
            assert!(mesh.geometry(e).j > 0.0, "tetrahedron {e}");
        }
        close(volume(&mesh), 1.0, "volume");
        for (tag, normal, a) in SIDES {
            close(area(&mesh, tag), a, &format!("side {tag}"));
            check_normals(&mesh, tag, normal);
        }
        // Every side's triangle is in group 99 too.
        close(area(&mesh, 99), 7.0, "the whole boundary");
        assert_eq!(
            faces(&mesh, 99).len(),
            (1..=6).map(|t| faces(&mesh, t).len()).sum::<usize>()
        );
        read.push(mesh);
    }
    // ASCII files carry 17 significant digits, binary ones the exact
    // doubles: the same mesh.
    let (a, b) = (&read[0], &read[1]);
    assert_eq!(a.tets(), b.tets());
    assert_eq!(a.boundary_faces(), b.boundary_faces());
    assert_eq!(a.nodes().len(), b.nodes().len());
    for (p, q) in a.nodes().iter().zip(b.nodes()) {
        assert!((0..3).all(|i| (p[i] - q[i]).abs() < 1e-15), "{p:?} {q:?}");
    }
}

#[test]
fn a_2d_reading_of_a_3d_file_keeps_its_message() {
    // A file of its own: the tests run in parallel.
    let path = mesh_with_gmsh("box_2d", BOX, false, &[]);
    let e = read_msh(&path, 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh);
    assert!(
        e.message().contains(
            "volume 1 in physical group 7 \"block\" has elements of Gmsh type 4 (4-node \
             tetrahedra): only 2D meshes are supported"
        ),
        "{}",
        e.message()
    );
}

#[test]
fn a_second_order_mesh_is_refused_naming_its_element_type() {
    for binary in [false, true] {
        let path = mesh_with_gmsh("box_order2", BOX, binary, &["-order", "2"]);
        let e = read_solid_msh(&path, 0).unwrap_err();
        assert_eq!(e.status(), Status::InvalidMesh);
        assert!(
            e.message().contains(
                "surface 1 in physical groups 1, 99 \"all\" has elements of Gmsh type 9 \
                 (6-node triangles): only 3-node triangles are supported"
            ),
            "{}",
            e.message()
        );
    }
}

// ---------------------------------------------------------------------------
// (c) Two boxes stacked, not merged.
// ---------------------------------------------------------------------------

/// Box 1 = [0, 1] × [0, 0.5] × [0, 0.3] and box 2 on it up to z = 0.5,
/// two volumes without `Coherence`: each meshed on its own, no node
/// shared. Box 1's top (its 6th surface) is group 11, box 2's bottom (its
/// 5th, surface 11) group 12, box 1's bottom group 1, box 2's top group 2.
const STACK: &str = r#"SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 0.3};
Box(2) = {0, 0, 0.3, 1, 0.5, 0.2};
Mesh.MeshSizeMax = 0.15;
Physical Volume("lower", 1) = {1};
Physical Volume("upper", 2) = {2};
Physical Surface("support", 1) = {5};
Physical Surface("lower top", 11) = {6};
Physical Surface("upper bottom", 12) = {11};
Physical Surface("load", 2) = {12};
"#;

#[test]
fn two_stacked_boxes_are_two_bodies_with_their_facing_sides_tagged_apart() {
    for binary in [false, true] {
        let mesh = read_solid_msh(&mesh_with_gmsh("stack", STACK, binary, &[]), 0).unwrap();
        assert_eq!(mesh.bodies(), &[1, 2]);
        assert!(mesh.warnings().is_empty(), "{:?}", mesh.warnings());
        let of = |body: i32| -> f64 {
            (0..mesh.tets().len())
                .filter(|&e| mesh.body_of()[e] == body)
                .map(|e| mesh.geometry(e).j / 6.0)
                .sum()
        };
        close(of(1), 0.15, "the lower box's volume");
        close(of(2), 0.1, "the upper box's volume");
        // No node is shared: every node of a tetrahedron is its body's.
        for (t, &body) in mesh.tets().iter().zip(mesh.body_of()) {
            assert!(t.iter().all(|&v| mesh.node_body()[v] == Some(body)));
        }
        for (tag, normal, body) in [
            (1, [0.0, 0.0, -1.0], 1),
            (11, [0.0, 0.0, 1.0], 1),
            (12, [0.0, 0.0, -1.0], 2),
            (2, [0.0, 0.0, 1.0], 2),
        ] {
            close(area(&mesh, tag), 0.5, &format!("side {tag}"));
            check_normals(&mesh, tag, normal);
            for f in faces(&mesh, tag) {
                assert_eq!(mesh.body_of()[f.owner], body, "side {tag}");
                assert!(f.nodes.iter().all(|&v| {
                    let z = mesh.nodes()[v][2];
                    z == [0.0, 0.3, 0.3, 0.5]
                        [[1, 11, 12, 2].iter().position(|&t| t == tag).unwrap()]
                }));
            }
        }
    }
}

// ---------------------------------------------------------------------------
// (d) What a solid mesh cannot take, named as the file names it.
// ---------------------------------------------------------------------------

/// Asserts reading `name` (`text`) fails as InvalidMesh with a message
/// holding every one of `needles`.
fn refused(name: &str, text: &str, needles: &[&str]) {
    let e = read_solid_msh(&write(name, text), 1).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh, "{}", e.message());
    for needle in needles {
        assert!(
            e.message().contains(needle),
            "{needle:?} in {}",
            e.message()
        );
    }
}

fn two_tets_text(volume_groups: &str, tets: [&str; 2], triangles: [&str; 2]) -> String {
    format!(
        "{HEADER}{NAMES}{}{NODES}{}",
        entities(volume_groups),
        elements(tets, triangles)
    )
}

#[test]
fn a_tetrahedron_using_an_undeclared_node_is_refused_naming_both() {
    refused(
        "undeclared_node.msh",
        &two_tets_text("1 1", ["101 102 103 104", "102 103 104 106"], TRIANGLES),
        &[
            "$Elements: element 2 of volume 1 in physical group 1 \"steel\" refers to node 106, \
             which is not defined in $Nodes",
        ],
    );
}

#[test]
fn a_tagged_triangle_that_is_no_tetrahedrons_face_is_refused_naming_it() {
    // ABE: no tetrahedron has it.
    refused(
        "not_a_face.msh",
        &two_tets_text("1 1", TETS, ["101 102 103", "101 102 105"]),
        &[
            "Gmsh triangle element 8 of surface 2 in physical group 20 \"slant\" (Gmsh nodes \
             101, 102, 105)",
            "is not a face of any tetrahedron",
        ],
    );
    // BCD: the face the two tetrahedra share, inside the mesh.
    refused(
        "inner_face.msh",
        &two_tets_text("1 1", TETS, ["102 103 104", "102 103 105"]),
        &[
            "Gmsh triangle element 7 of surface 1 in physical group 10 \"bottom\" (Gmsh nodes \
             102, 103, 104)",
            "shared by 2 tetrahedra",
        ],
    );
}

#[test]
fn a_tetrahedron_with_a_repeated_node_or_given_twice_is_refused_naming_it() {
    refused(
        "repeated_node.msh",
        &two_tets_text("1 1", ["101 102 103 104", "102 103 102 105"], TRIANGLES),
        &[
            "tetrahedron 2 (Gmsh element 2 of volume 1 in physical group 1 \"steel\"): node 2 \
             (Gmsh node 102) is repeated",
        ],
    );
    refused(
        "tet_twice.msh",
        &two_tets_text("1 1", ["101 102 103 104", "104 103 102 101"], TRIANGLES),
        &[
            "tetrahedron 2 (Gmsh element 2 of volume 1 in physical group 1 \"steel\") has the \
             nodes of tetrahedron 1 (Gmsh element 1",
        ],
    );
}

#[test]
fn a_volume_in_no_or_several_physical_groups_is_refused() {
    refused(
        "no_body.msh",
        &two_tets_text("0", TETS, TRIANGLES),
        &["volume 1 has no physical group in $Entities: every volume must be a body"],
    );
    refused(
        "two_bodies.msh",
        &two_tets_text("2 1 5", TETS, TRIANGLES),
        &["volume 1 in physical groups 1 \"steel\", 5: a tetrahedron has one body"],
    );
}

#[test]
fn higher_order_tetrahedra_are_refused_naming_the_type() {
    // The block is refused at its header, before its elements.
    let text = format!(
        "{HEADER}{}{NODES}$Elements\n1 1 1 1\n3 1 11 1\n\
         1 101 102 103 104 105 101 102 103 104 105\n$EndElements\n",
        entities("1 1")
    );
    refused(
        "tet10.msh",
        &text,
        &[
            "volume 1 in physical group 1 has elements of Gmsh type 11 (10-node tetrahedra): \
           only 4-node tetrahedra are supported",
        ],
    );
}

#[test]
fn a_non_finite_coordinate_is_refused_naming_the_gmsh_node() {
    let text = format!(
        "{HEADER}{}$Nodes\n1 5 101 105\n3 1 0 5\n101\n102\n103\n104\n105\n\
         0 0 0\n1 0 0\n0 1 0\n0 0 inf\n1 1 1\n$EndNodes\n{}",
        entities("1 1"),
        elements(TETS, TRIANGLES)
    );
    refused(
        "inf.msh",
        &text,
        &[
            "node 4 (Gmsh node 104 of volume 1 in physical group 1): coordinates (0.0, 0.0, inf) \
           are not finite",
        ],
    );
}

#[test]
fn a_2d_file_is_refused_as_a_solid_mesh_in_words() {
    // One triangle of surface 1 in physical group 7, in the plane z = 0.
    let text = format!(
        "{HEADER}$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n$Nodes\n1 3 1 3\n\
         2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n\
         1 1 2 3\n$EndElements\n"
    );
    // The 2D reader takes it.
    read_msh(&write("plane.msh", &text), 0).unwrap();
    refused(
        "plane.msh",
        &text,
        &["no tetrahedra in a physical volume", "a 2D mesh?"],
    );
}

#[test]
fn lines_and_points_are_not_used() {
    // A physical point, and a physical curve with a line, besides the
    // tetrahedra: read, and nothing of them in the mesh.
    let text = format!(
        "{HEADER}$Entities\n1 1 0 1\n1 0 0 0 1 3\n1 0 0 0 1 0 0 1 4 0\n\
         1 0 0 0 1 1 1 1 1 0\n$EndEntities\n{NODES}$Elements\n3 4 1 4\n0 1 15 1\n4 101\n\
         1 1 1 1\n3 101 102\n3 1 4 2\n1 101 102 103 104\n2 102 103 104 105\n$EndElements\n"
    );
    let mesh = read_solid_msh(&write("lines.msh", &text), 0).unwrap();
    assert_eq!(mesh.tets().len(), 2);
    assert!(mesh.boundary_faces().is_empty());
}
