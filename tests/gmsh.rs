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
        e.message()
            .contains("node 3 of surface 1 in physical group 7 has z = 0.5"),
        "{}",
        e.message()
    );
}

// ---------------------------------------------------------------------------
// Hostile and malformed files: every one is an error naming its section,
// returned promptly by a process that survives, without a large allocation
// and without a word on stderr.
// ---------------------------------------------------------------------------

/// A value of an MSH file: `size_t`, `int`, `double`, or raw ASCII text
/// (for garbage; in a binary file, its bytes as they are).
#[derive(Clone, Copy)]
enum V {
    S(u64),
    I(i32),
    F(f64),
    Raw(&'static str),
}
use V::{F, I, Raw, S};

/// An MSH 4.1 file with the given sections, ASCII or binary (little-endian,
/// 8-byte `size_t`), laid out as Gmsh does.
fn msh(binary: bool, sections: &[(&str, Vec<V>)]) -> Vec<u8> {
    let mut out = Vec::new();
    if binary {
        out.extend_from_slice(b"$MeshFormat\n4.1 1 8\n");
        out.extend_from_slice(&1i32.to_le_bytes());
        out.push(b'\n');
    } else {
        out.extend_from_slice(b"$MeshFormat\n4.1 0 8\n");
    }
    out.extend_from_slice(b"$EndMeshFormat\n");
    for (name, values) in sections {
        out.extend_from_slice(format!("${name}\n").as_bytes());
        for (k, v) in values.iter().enumerate() {
            if binary {
                match *v {
                    S(x) => out.extend_from_slice(&x.to_le_bytes()),
                    I(x) => out.extend_from_slice(&x.to_le_bytes()),
                    F(x) => out.extend_from_slice(&x.to_le_bytes()),
                    Raw(x) => out.extend_from_slice(x.as_bytes()),
                }
            } else {
                if k > 0 {
                    out.push(b' ');
                }
                let text = match *v {
                    S(x) => x.to_string(),
                    I(x) => x.to_string(),
                    F(x) => x.to_string(),
                    Raw(x) => x.to_string(),
                };
                out.extend_from_slice(text.as_bytes());
            }
        }
        out.extend_from_slice(format!("\n$End{name}\n").as_bytes());
    }
    out
}

/// Surface 1 in physical group 7.
fn entities() -> Vec<V> {
    vec![
        S(0),
        S(0),
        S(1),
        S(0),
        I(1),
        F(0.0),
        F(0.0),
        F(0.0),
        F(1.0),
        F(1.0),
        F(0.0),
        S(1),
        I(7),
        S(0),
    ]
}

/// Three nodes on surface 1 under the given header (numEntityBlocks,
/// numNodes, minNodeTag, maxNodeTag), with the given tags and block count.
fn nodes(header: [u64; 4], in_block: u64, tags: [u64; 3]) -> Vec<V> {
    let mut v: Vec<V> = header.iter().map(|&x| S(x)).collect();
    v.extend([I(2), I(1), I(0), S(in_block)]);
    v.extend(tags.map(S));
    v.extend([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0].map(F));
    v
}

fn good_nodes() -> Vec<V> {
    nodes([1, 3, 1, 3], 3, [1, 2, 3])
}

/// One triangle on surface 1 under the given header (numEntityBlocks,
/// numElements, minElementTag, maxElementTag) and block count.
fn elements(header: [u64; 4], in_block: u64) -> Vec<V> {
    let mut v: Vec<V> = header.iter().map(|&x| S(x)).collect();
    v.extend([I(2), I(1), I(2), S(in_block), S(1), S(1), S(2), S(3)]);
    v
}

fn good_elements() -> Vec<V> {
    elements([1, 1, 1, 1], 1)
}

fn triangle(binary: bool) -> Vec<u8> {
    msh(
        binary,
        &[
            ("Entities", entities()),
            ("Nodes", good_nodes()),
            ("Elements", good_elements()),
        ],
    )
}

fn write_bytes(name: &str, bytes: &[u8]) -> PathBuf {
    let p = out_dir().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

const CHILD_FILE: &str = "TFEM_GMSH_TEST_CHILD_FILE";
const CHILD_ALLOCATE: &str = "TFEM_GMSH_TEST_CHILD_ALLOCATE";
/// The address-space limit of the child processes: the test binary needs
/// about 30 MiB of it (glibc reserves 64 MiB per thread arena); reading a
/// small file must fit in what is left.
const LIMIT_KIB: u64 = 256 * 1024;
/// Generous: these files are read in microseconds.
const PROMPT_SECONDS: f64 = 2.0;

/// Peak resident and virtual memory of this process, in KiB.
fn peak_memory_kib() -> (u64, u64) {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let field = |name: &str| {
        status
            .lines()
            .find_map(|l| l.strip_prefix(name))
            .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
            .unwrap_or(0)
    };
    (field("VmHWM:"), field("VmPeak:"))
}

/// The body of the child processes spawned by [`in_a_small_address_space`]
/// (does nothing in a normal test run): reads the file named in the
/// environment, or tries the allocation asked for, and reports on stdout.
#[test]
fn child_process_reads_the_file_its_parent_names() {
    if let Some(bytes) = std::env::var_os(CHILD_ALLOCATE) {
        let n: usize = bytes.to_str().unwrap().parse().unwrap();
        let mut v: Vec<u8> = Vec::new();
        println!("ALLOCATED {}", v.try_reserve_exact(n).is_ok());
        return;
    }
    let Some(path) = std::env::var_os(CHILD_FILE) else {
        return;
    };
    let start = std::time::Instant::now();
    let result = read_msh(Path::new(&path), 0);
    let seconds = start.elapsed().as_secs_f64();
    let (rss, vm) = peak_memory_kib();
    let (status, message) = match result {
        Ok(mesh) => (format!("Ok({} nodes)", mesh.nodes().len()), String::new()),
        Err(e) => (format!("{:?}", e.status()), e.message().to_string()),
    };
    println!(
        "STATUS {status}\nSECONDS {seconds}\nPEAK_RSS_KIB {rss}\nPEAK_VM_KIB {vm}\nMESSAGE {message}"
    );
}

/// Runs this test binary's [`child_process_reads_the_file_its_parent_names`]
/// under `ulimit -v` with `env` set, and returns its standard output. The
/// child must exit normally with nothing on stderr (no panic message).
fn in_a_small_address_space(env: (&str, &str)) -> String {
    let exe = std::env::current_exe().unwrap();
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {LIMIT_KIB} && exec \"$0\" \"$@\""))
        .arg(&exe)
        .args([
            "--exact",
            "child_process_reads_the_file_its_parent_names",
            "--nocapture",
            "--test-threads=1",
            "--quiet",
        ])
        .env(env.0, env.1)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(
        out.status.success(),
        "the child died ({}):\n{stdout}\n{stderr}",
        out.status
    );
    assert!(stderr.is_empty(), "the child wrote on stderr:\n{stderr}");
    stdout
}

/// Reads `bytes` (written to `name`) in a child process limited to
/// [`LIMIT_KIB`] of address space: the result must be `Status::Io` or
/// `Status::InvalidMesh` with a message containing every one of `needles`
/// (the section first), returned within [`PROMPT_SECONDS`].
fn rejected(name: &str, bytes: &[u8], needles: &[&str]) {
    let path = write_bytes(name, bytes);
    let out = in_a_small_address_space((CHILD_FILE, path.to_str().unwrap()));
    let field = |key: &str| {
        out.lines()
            .find_map(|l| l.strip_prefix(key))
            .unwrap_or_else(|| panic!("{key} missing in:\n{out}"))
            .trim()
            .to_string()
    };
    let (status, message) = (field("STATUS "), field("MESSAGE "));
    let seconds: f64 = field("SECONDS ").parse().unwrap();
    println!(
        "{name}: {status} in {:.3} ms, peak RSS {} KiB, peak VM {} KiB: {message}",
        seconds * 1e3,
        field("PEAK_RSS_KIB "),
        field("PEAK_VM_KIB ")
    );
    assert!(
        status == "Io" || status == "InvalidMesh",
        "{name}: {status}: {message}"
    );
    assert!(
        message.contains(name),
        "{name}: the path is missing: {message}"
    );
    for needle in needles {
        assert!(
            message.contains(needle),
            "{name}: {needle:?} missing: {message}"
        );
    }
    assert!(seconds < PROMPT_SECONDS, "{name}: {seconds} s");
}

/// Both encodings of a file built by `make`.
fn both(name: &str, make: impl Fn(bool) -> Vec<u8>, needles: &[&str]) {
    for binary in [false, true] {
        let kind = if binary { "bin" } else { "ascii" };
        rejected(&format!("{name}_{kind}.msh"), &make(binary), needles);
    }
}

const E15: u64 = 1_000_000_000_000_000;
const P62: u64 = 1 << 62;

#[test]
fn the_child_address_space_limit_refuses_a_512_mib_allocation_and_allows_a_small_one() {
    let big = in_a_small_address_space((CHILD_ALLOCATE, &(512usize << 20).to_string()));
    assert!(big.contains("ALLOCATED false"), "{big}");
    let small = in_a_small_address_space((CHILD_ALLOCATE, &(16usize << 20).to_string()));
    assert!(small.contains("ALLOCATED true"), "{small}");
}

#[test]
fn the_hand_written_triangle_files_are_read() {
    for binary in [false, true] {
        let path = write_bytes(&format!("triangle_{binary}.msh"), &triangle(binary));
        let mesh = read_msh(&path, 0).unwrap();
        assert_eq!(mesh.nodes().len(), 3);
        assert_eq!(mesh.triangles().len(), 1);
        assert_eq!(mesh.bodies(), &[7]);
    }
}

#[test]
fn a_nodes_header_claiming_10_15_nodes_is_an_io_error_naming_nodes_and_the_count() {
    both(
        "nodes_1e15",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, E15, 1, 3], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "the number of nodes is 1000000000000000"],
    );
}

#[test]
fn a_nodes_header_claiming_2_62_nodes_is_an_io_error_naming_nodes_and_the_count() {
    both(
        "nodes_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, P62, 1, 3], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "the number of nodes is 4611686018427387904"],
    );
}

#[test]
fn a_node_block_claiming_10_15_nodes_is_an_io_error_naming_nodes() {
    both(
        "node_block_1e15",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, 3, 1, 3], E15, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "entity block 1 of 1", "1000000000000000"],
    );
}

#[test]
fn a_nodes_header_claiming_2_62_entity_blocks_is_an_io_error_naming_nodes() {
    both(
        "node_blocks_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([P62, 3, 1, 3], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &[
            "$Nodes",
            "the number of entity blocks is 4611686018427387904",
        ],
    );
}

#[test]
fn a_nodes_header_claiming_a_max_node_tag_of_2_62_is_an_io_error_naming_nodes() {
    both(
        "max_node_tag_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, 3, 1, P62], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "from 1 to 4611686018427387904"],
    );
}

#[test]
fn node_tags_of_2_62_announced_by_the_header_are_read_without_a_dense_table() {
    for binary in [false, true] {
        let bytes = msh(
            binary,
            &[
                ("Entities", entities()),
                (
                    "Nodes",
                    nodes([1, 3, P62, P62 + 2], 3, [P62, P62 + 1, P62 + 2]),
                ),
                (
                    "Elements",
                    vec![
                        S(1),
                        S(1),
                        S(P62),
                        S(P62),
                        I(2),
                        I(1),
                        I(2),
                        S(1),
                        S(P62),
                        S(P62),
                        S(P62 + 1),
                        S(P62 + 2),
                    ],
                ),
            ],
        );
        let path = write_bytes(&format!("tags_2e62_{binary}.msh"), &bytes);
        let out = in_a_small_address_space((CHILD_FILE, path.to_str().unwrap()));
        assert!(out.contains("STATUS Ok(3 nodes)"), "{out}");
    }
}

#[test]
fn a_nodes_header_announcing_fewer_nodes_than_the_blocks_hold_is_an_io_error() {
    both(
        "nodes_too_few",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, 2, 1, 3], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "announces 2 nodes but the blocks hold 3"],
    );
}

#[test]
fn an_elements_header_claiming_10_15_elements_is_an_io_error_naming_elements() {
    both(
        "elements_1e15",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", good_nodes()),
                    ("Elements", elements([1, E15, 1, 1], 1)),
                ],
            )
        },
        &["$Elements", "the number of elements is 1000000000000000"],
    );
}

#[test]
fn an_elements_header_claiming_2_62_entity_blocks_is_an_io_error_naming_elements() {
    both(
        "element_blocks_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", good_nodes()),
                    ("Elements", elements([P62, 1, 1, 1], 1)),
                ],
            )
        },
        &[
            "$Elements",
            "the number of entity blocks is 4611686018427387904",
        ],
    );
}

#[test]
fn an_element_block_claiming_2_62_elements_is_an_io_error_naming_elements() {
    both(
        "element_block_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", good_nodes()),
                    ("Elements", elements([1, 1, 1, 1], P62)),
                ],
            )
        },
        &["$Elements", "entity block 1 of 1", "4611686018427387904"],
    );
}

#[test]
fn an_elements_header_claiming_a_max_element_tag_of_2_62_is_an_io_error_naming_elements() {
    both(
        "max_element_tag_2e62",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", good_nodes()),
                    ("Elements", elements([1, 1, 1, P62], 1)),
                ],
            )
        },
        &["$Elements", "from 1 to 4611686018427387904"],
    );
}

#[test]
fn entity_counts_of_10_15_are_io_errors_naming_entities() {
    both(
        "surfaces_1e15",
        |b| {
            let mut e = entities();
            e[2] = S(E15);
            msh(
                b,
                &[
                    ("Entities", e),
                    ("Nodes", good_nodes()),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Entities", "the number of surfaces is 1000000000000000"],
    );
    both(
        "physical_tags_2e62",
        |b| {
            let mut e = entities();
            e[11] = S(P62);
            msh(
                b,
                &[
                    ("Entities", e),
                    ("Nodes", good_nodes()),
                    ("Elements", good_elements()),
                ],
            )
        },
        &[
            "$Entities",
            "surface 1 of 1",
            "the number of physical tags is 4611686018427387904",
        ],
    );
}

#[test]
fn a_count_of_2_64_minus_1_is_an_io_error_naming_its_section() {
    // What a negative count written as size_t looks like.
    both(
        "nodes_minus_1",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", nodes([1, u64::MAX, 1, 3], 3, [1, 2, 3])),
                    ("Elements", good_elements()),
                ],
            )
        },
        &["$Nodes", "18446744073709551615"],
    );
}

#[test]
fn negative_and_garbage_counts_in_ascii_are_io_errors_naming_the_section_and_the_token() {
    for (k, bad) in ["-5", "abc", "1e3", "0x10", "99999999999999999999999", "+-1"]
        .into_iter()
        .enumerate()
    {
        let mut n = good_nodes();
        n[1] = Raw(bad);
        let bytes = msh(
            false,
            &[
                ("Entities", entities()),
                ("Nodes", n),
                ("Elements", good_elements()),
            ],
        );
        rejected(
            &format!("garbage_count_{k}.msh"),
            &bytes,
            &["$Nodes", "the number of nodes", bad],
        );
    }
}

#[test]
fn malformed_mesh_format_headers_are_io_errors_naming_mesh_format() {
    for (k, header) in [
        "$MeshFormat\n4.1 0 99999999999999999999999\n$EndMeshFormat\n",
        "$MeshFormat\n4.1 1 3\n\x01\x00\x00\x00\n$EndMeshFormat\n",
        "$MeshFormat\nx.y 0 8\n$EndMeshFormat\n",
        "$MeshFormat\n4.1 2 8\n$EndMeshFormat\n",
        "$MeshFormat\n4.1 1 8\n\x02\x00\x00\x00\n$EndMeshFormat\n",
        "$MeshFormat\n4.1 1 8",
        "$MeshFormat\n",
    ]
    .into_iter()
    .enumerate()
    {
        rejected(
            &format!("header_{k}.msh"),
            header.as_bytes(),
            &["$MeshFormat"],
        );
    }
}

#[test]
fn empty_nodes_and_elements_sections_are_errors_not_panics() {
    // mshio computed `num_nodes - 1` here (an overflow panic in debug builds).
    both(
        "empty_sections",
        |b| {
            msh(
                b,
                &[
                    ("Entities", entities()),
                    ("Nodes", vec![S(0), S(0), S(1), S(1)]),
                    ("Elements", vec![S(0), S(0), S(1), S(1)]),
                ],
            )
        },
        &["$Elements", "no triangles"],
    );
}

#[test]
fn a_long_run_of_blanks_in_an_unknown_section_is_skipped_promptly() {
    // Quadratic in mshio: 80 kB took 2 s.
    let mut bytes = triangle(false);
    let mut section = b"$Comments\n".to_vec();
    section.resize(section.len() + 4_000_000, b' ');
    section.extend_from_slice(b"x\n$EndComments\n");
    bytes.extend_from_slice(&section);
    let path = write_bytes("long_blanks.msh", &bytes);
    let start = std::time::Instant::now();
    read_msh(&path, 0).unwrap();
    assert!(start.elapsed().as_secs_f64() < PROMPT_SECONDS);
}

#[test]
fn an_error_message_does_not_grow_with_the_file() {
    // mshio's message was a hex dump of the rest of the file.
    let mut text = format!("{HEADER}$Nodes\n1 x");
    text.push_str(&"0".repeat(10_000_000));
    let e = read_msh(&write("long_garbage.msh", &text), 0).unwrap_err();
    assert_eq!(e.status(), Status::Io);
    assert!(e.message().len() < 400, "{} bytes", e.message().len());
    assert!(e.message().contains("$Nodes"), "{}", e.message());
}

#[test]
fn every_truncation_of_a_small_file_is_an_error_naming_a_section() {
    for binary in [false, true] {
        let full = triangle(binary);
        let path = out_dir().join(format!("truncated_{binary}.msh"));
        // The last byte is the final line break, which is optional.
        for len in 0..full.len() - 1 {
            std::fs::write(&path, &full[..len]).unwrap();
            let e = read_msh(&path, 0).unwrap_err();
            assert!(
                matches!(e.status(), Status::Io | Status::InvalidMesh),
                "{len}: {}",
                e.message()
            );
            assert!(
                ["$MeshFormat", "$Entities", "$Nodes", "$Elements"]
                    .iter()
                    .any(|s| e.message().contains(s)),
                "{len}: {}",
                e.message()
            );
        }
    }
}

#[test]
fn truncations_of_a_gmsh_file_are_errors_naming_a_section() {
    for binary in [false, true] {
        let full = std::fs::read(mesh_with_gmsh(0.1, binary)).unwrap();
        let path = out_dir().join(format!("gmsh_truncated_{binary}.msh"));
        for k in 0..200 {
            let len = full.len() * k / 200;
            std::fs::write(&path, &full[..len]).unwrap();
            let e = read_msh(&path, 0).unwrap_err();
            assert!(
                matches!(e.status(), Status::Io | Status::InvalidMesh),
                "{len}: {}",
                e.message()
            );
            assert!(e.message().contains("$"), "{len}: {}", e.message());
        }
    }
}

#[test]
fn no_single_byte_change_of_a_small_file_makes_the_reader_panic() {
    for binary in [false, true] {
        let full = triangle(binary);
        let path = out_dir().join(format!("mutated_{binary}.msh"));
        for at in 0..full.len() {
            for b in [0x00, 0x01, 0x7f, 0x80, 0xff, b'9', b'-', b' ', b'$', b'\n'] {
                let mut bytes = full.clone();
                bytes[at] = b;
                std::fs::write(&path, &bytes).unwrap();
                if let Err(e) = read_msh(&path, 0) {
                    assert!(
                        matches!(e.status(), Status::Io | Status::InvalidMesh),
                        "{at} = {b}: {:?} {}",
                        e.status(),
                        e.message()
                    );
                }
            }
        }
    }
}

#[test]
fn a_directory_or_a_device_is_an_io_error_not_an_endless_read() {
    for path in [out_dir(), PathBuf::from("/dev/zero")] {
        let e = read_msh(&path, 0).unwrap_err();
        assert_eq!(e.status(), Status::Io, "{}", e.message());
    }
}

#[test]
fn a_second_nodes_section_is_an_io_error_naming_nodes() {
    let bytes = msh(
        false,
        &[
            ("Entities", entities()),
            ("Nodes", good_nodes()),
            ("Nodes", good_nodes()),
            ("Elements", good_elements()),
        ],
    );
    let e = read_msh(&write_bytes("two_nodes.msh", &bytes), 0).unwrap_err();
    assert_eq!(e.status(), Status::Io);
    assert!(e.message().contains("a second $Nodes"), "{}", e.message());
}

#[test]
fn a_fifo_is_an_io_error_naming_it_without_waiting_for_a_writer() {
    let path = out_dir().join("fifo.msh");
    let _ = std::fs::remove_file(&path);
    assert!(
        Command::new("mkfifo")
            .arg(&path)
            .status()
            .unwrap()
            .success()
    );
    let (tx, rx) = std::sync::mpsc::channel();
    let p = path.clone();
    std::thread::spawn(move || {
        let got = read_msh(&p, 0).map(|_| ());
        let _ = tx.send(got.map_err(|e| (e.status(), e.message().to_string())));
    });
    let got = rx.recv_timeout(std::time::Duration::from_secs(10));
    if got.is_err() {
        // The reader waits in `open` for a writer: be it, so that the
        // thread ends.
        let _ = std::fs::OpenOptions::new().write(true).open(&path);
    }
    let (status, message) = got
        .expect("the reader returns without a writer")
        .unwrap_err();
    assert_eq!(status, Status::Io, "{message}");
    assert!(message.contains("fifo.msh"), "{message}");
    assert!(
        message.contains("not a regular file but a FIFO"),
        "{message}"
    );
}

#[test]
fn an_empty_path_is_an_io_error_saying_so() {
    let e = read_msh(Path::new(""), 0).unwrap_err();
    assert_eq!(e.status(), Status::Io);
    assert!(e.message().contains("the path is empty"), "{}", e.message());
}

/// Whether a message is fit for a C caller: short, and without control
/// characters (a NUL would cut it, raw binary garble a terminal).
fn printable_and_short(message: &str) -> bool {
    message.len() <= 400 && !message.chars().any(char::is_control)
}

#[test]
fn an_unknown_section_name_is_quoted_short_and_printable() {
    let mut long = format!("{HEADER}$");
    long.push_str(&"x".repeat(10_000_000));
    long.push('\n');
    let mut binary = format!("{HEADER}$Elements").into_bytes();
    binary.extend_from_slice(b"\x00\x01\xff\x05");
    binary.extend((0..=255u8).cycle().take(300));
    binary.extend_from_slice(b"\n$EndElements\n");
    for (name, bytes) in [
        ("long_section_name.msh", long.into_bytes()),
        ("binary_section_name.msh", binary),
    ] {
        let e = read_msh(&write_bytes(name, &bytes), 0).unwrap_err();
        assert_eq!(e.status(), Status::Io, "{}", e.message());
        assert!(
            printable_and_short(e.message()),
            "{} bytes: {:?}",
            e.message().len(),
            e.message()
        );
    }
}

#[test]
fn every_message_from_a_corrupt_file_is_short_and_printable() {
    for binary in [false, true] {
        let full = triangle(binary);
        let path = out_dir().join(format!("corrupt_{binary}.msh"));
        for at in 0..full.len() {
            for b in [0x00, 0x01, 0x1b, 0x7f, 0x80, 0xff, b'$', b'\n'] {
                let mut bytes = full.clone();
                bytes[at] = b;
                std::fs::write(&path, &bytes).unwrap();
                if let Err(e) = read_msh(&path, 0) {
                    assert!(
                        printable_and_short(e.message()),
                        "{at} = {b}: {:?}",
                        e.message()
                    );
                }
            }
        }
    }
}

/// The unit square as two triangles (Gmsh elements 21, 22) on surface 1
/// (body 7), its corners Gmsh nodes 1001–1004 counter-clockwise from the
/// origin (1003 at `corner_1003`), then the nodes `extra`; curve 1 (group
/// 11) holds the bottom side (element 31) and the lines `lines` (elements
/// 32, …).
fn renumbered_square(corner_1003: &str, extra: &[(u64, &str)], lines: &[[u64; 2]]) -> String {
    let n = 4 + extra.len();
    let max_node = extra.iter().map(|e| e.0).fold(1004, u64::max);
    let mut text = format!(
        "{HEADER}$Entities\n0 1 1 0\n1 0 0 0 1 1 0 1 11 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n\
         $Nodes\n1 {n} 1001 {max_node}\n2 1 0 {n}\n1001\n1002\n1003\n1004\n"
    );
    for (tag, _) in extra {
        text.push_str(&format!("{tag}\n"));
    }
    text.push_str(&format!("0 0 0\n1 0 0\n{corner_1003}\n0 1 0\n"));
    for (_, xyz) in extra {
        text.push_str(&format!("{xyz}\n"));
    }
    text.push_str(&format!(
        "$EndNodes\n$Elements\n2 {} 21 {}\n2 1 2 2\n21 1001 1002 1003\n22 1001 1003 1004\n\
         1 1 1 {}\n31 1001 1002\n",
        3 + lines.len(),
        31 + lines.len(),
        1 + lines.len()
    ));
    for (k, [p, q]) in lines.iter().enumerate() {
        text.push_str(&format!("{} {p} {q}\n", 32 + k));
    }
    text.push_str("$EndElements\n");
    text
}

#[test]
fn the_renumbered_square_is_read() {
    let mesh = read_msh(
        &write("renumbered.msh", &renumbered_square("1 1 0", &[], &[])),
        0,
    )
    .unwrap();
    assert_eq!(mesh.nodes().len(), 4);
    assert_eq!(mesh.boundary_edges().len(), 1);
}

#[test]
fn a_line_that_is_no_side_names_its_gmsh_element_and_nodes() {
    let text = renumbered_square("1 1 0", &[], &[[1002, 1004]]);
    let e = read_msh(&write("renumbered_badline.msh", &text), 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh);
    assert!(
        e.message()
            .contains("Gmsh line element 32 of curve 1 in physical group 11 (Gmsh nodes 1002, 1004) is not a side of any triangle"),
        "{}",
        e.message()
    );
}

#[test]
fn a_non_finite_coordinate_names_the_gmsh_node() {
    let text = renumbered_square("inf 1 0", &[], &[]);
    let e = read_msh(&write("renumbered_inf.msh", &text), 1).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh);
    assert!(
        e.message().contains(
            "node 3 (Gmsh node 1003 of surface 1 in physical group 7): coordinates (inf, 1.0)"
        ),
        "{}",
        e.message()
    );
}

#[test]
fn an_unused_node_is_named_by_its_gmsh_tag_in_the_warning() {
    let text = renumbered_square("1 1 0", &[(1007, "0.5 0.5 0")], &[]);
    let mesh = read_msh(&write("renumbered_unused.msh", &text), 0).unwrap();
    assert!(
        mesh.warnings()
            .iter()
            .any(|w| w.contains("not used by any triangle") && w.contains("4 (Gmsh node 1007)")),
        "{:?}",
        mesh.warnings()
    );
}

#[test]
fn an_element_naming_an_undefined_node_is_named_by_its_tag_and_physical_group() {
    let text = renumbered_square("1 1 0", &[], &[[1002, 1009]]);
    let e = read_msh(&write("renumbered_undefined.msh", &text), 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh);
    assert!(
        e.message()
            .contains("element 32 of curve 1 in physical group 11 refers to node 1009"),
        "{}",
        e.message()
    );
}

/// The unit square as two triangles of body 7, its sides in physical
/// curves 11 (bottom), 12 (right), 13 (top) and 14 (left), every side also
/// in group 99 (the whole boundary) and the top also in group 50;
/// `surface_groups` and `points` (the `$Entities` lines of the points) as
/// given.
fn square_in_groups(surface_groups: &str, points: &[&str]) -> String {
    let mut text = format!("{HEADER}$Entities\n{} 4 1 0\n", points.len());
    for p in points {
        text.push_str(&format!("{p}\n"));
    }
    text.push_str(&format!(
        "1 0 0 0 1 0 0 2 11 99 0\n2 1 0 0 1 1 0 2 12 99 0\n3 0 1 0 1 1 0 3 13 99 50 0\n\
         4 0 0 0 0 1 0 2 14 99 0\n1 0 0 0 1 1 0 {surface_groups} 0\n$EndEntities\n\
         $Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n$EndNodes\n\
         $Elements\n5 6 1 6\n1 1 1 1\n1 1 2\n1 2 1 1\n2 2 3\n1 3 1 1\n3 3 4\n1 4 1 1\n4 4 1\n\
         2 1 2 2\n5 1 2 3\n6 1 3 4\n$EndElements\n"
    ));
    text
}

const NU: f64 = 0.3;
const P: f64 = 1e6;

/// The element stresses of the square in groups (plane strain, E = 1e9,
/// ν = 0.3) under pressure `P` on `pressed`, with x fixed on `fix_x` and y
/// on `fix_y`.
fn square_stresses(pressed: i32, fix_x: i32, fix_y: i32) -> Vec<[f64; 3]> {
    // A file of its own per call: the tests run in parallel, and one read
    // another's file while it was being written (a failed run).
    let name = format!("square_in_groups_{pressed}_{fix_x}_{fix_y}.msh");
    let path = write(&name, &square_in_groups("1 7", &[]));
    let mut model = Model::new();
    model.set_mesh(read_msh(&path, 0).unwrap());
    model
        .set_material(
            7,
            Material::new(1e9, NU, PlaneMode::Strain, "body 7").unwrap(),
        )
        .unwrap();
    model.fix_edges(fix_x, Component::X, 0.0).unwrap();
    model.fix_edges(fix_y, Component::Y, 0.0).unwrap();
    model.add_pressure(pressed, P).unwrap();
    model.solve().unwrap();
    model.element_stresses().unwrap()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * P
}

#[test]
fn every_physical_group_of_a_curve_tags_its_edges() {
    let mesh = read_msh(&write("square_tags.msh", &square_in_groups("1 7", &[])), 0).unwrap();
    let mut tags: Vec<i32> = mesh.boundary_edges().iter().map(|e| e.tag).collect();
    tags.sort_unstable();
    assert_eq!(tags, [11, 12, 13, 14, 50, 99, 99, 99, 99]);
    assert!(mesh.warnings().is_empty(), "{:?}", mesh.warnings());
}

#[test]
fn a_pressure_on_a_curves_second_group_acts() {
    // The top is loaded through group 50 only: uniaxial σ_yy = −p.
    for s in square_stresses(50, 14, 11) {
        assert!(
            close(s[0], 0.0) && close(s[1], -P) && close(s[2], 0.0),
            "{s:?}"
        );
    }
}

#[test]
fn a_pressure_on_a_curves_first_group_still_acts() {
    for s in square_stresses(11, 14, 13) {
        assert!(
            close(s[0], 0.0) && close(s[1], -P) && close(s[2], 0.0),
            "{s:?}"
        );
    }
}

#[test]
fn fixing_a_group_of_every_curve_fixes_the_whole_boundary() {
    // x fixed on all four sides through group 99: ε_xx = 0, so in plane
    // strain σ_xx = ν/(1 − ν) σ_yy (it would be 0 with the left side only).
    for s in square_stresses(50, 99, 11) {
        assert!(
            close(s[0], -P * NU / (1.0 - NU)) && close(s[1], -P) && close(s[2], 0.0),
            "{s:?}"
        );
    }
}

#[test]
fn a_surface_in_two_groups_is_the_first_groups_body_with_a_warning() {
    let text = square_in_groups("2 7 8", &[]);
    let mesh = read_msh(&write("square_two_bodies.msh", &text), 0).unwrap();
    assert_eq!(mesh.bodies(), [7]);
    assert!(
        mesh.warnings()
            .iter()
            .any(|w| w.contains("surface 1 (body 7; dropped 8)")),
        "{:?}",
        mesh.warnings()
    );
}

/// A point and a surface in 1500 physical groups: the warnings name the
/// entity, the first ten groups and how many there are, in a few hundred
/// bytes (they listed every group: 8 KB for the point).
#[test]
fn an_entity_in_thousands_of_groups_gives_a_bounded_warning() {
    let groups = |first: i32| -> String {
        let tags: Vec<String> = (first..first + 1500).map(|t| t.to_string()).collect();
        format!("1500 {}", tags.join(" "))
    };
    let point = format!("5 0.5 0.5 0 {}", groups(101));
    let text = square_in_groups(&groups(7), &[&point]);
    let mesh = read_msh(&write("square_in_1500_groups.msh", &text), 0).unwrap();
    assert_eq!(mesh.bodies(), [7]);
    let warning = |needle: &str| -> String {
        mesh.warnings()
            .iter()
            .find(|w| w.contains(needle))
            .unwrap_or_else(|| panic!("no warning with {needle:?}: {:?}", mesh.warnings()))
            .clone()
    };
    let p = warning("point 5");
    assert!(
        p.contains("point 5 (group 101, 102, 103, 104, 105, 106, 107, 108, 109, 110 and 1490 more, 1500 in all)")
            && p.contains("not used"),
        "{p}"
    );
    let s = warning("surface 1");
    assert!(
        s.contains("surface 1 (body 7; dropped 8, 9, 10, 11, 12, 13, 14, 15, 16, 17 and 1489 more, 1499 in all)"),
        "{s}"
    );
    for w in [&p, &s] {
        assert!(w.len() < 512, "{} bytes: {w}", w.len());
        assert!(!w.contains("1506"), "a group past the tenth is listed: {w}");
    }
}

#[test]
fn a_physical_point_group_is_named_in_a_warning() {
    let text = square_in_groups("1 7", &["5 0.5 0.5 0 1 30"]);
    let mesh = read_msh(&write("square_point_group.msh", &text), 0).unwrap();
    assert!(
        mesh.warnings()
            .iter()
            .any(|w| w.contains("point 5 (group 30)") && w.contains("not used")),
        "{:?}",
        mesh.warnings()
    );
}

// ---------------------------------------------------------------------------
// Versions of the format other than 4.1: well-formed content tfem cannot
// use (TFEM_STATUS_INVALID_MESH, as the header promises for unsupported
// content), with the way to convert the file.
// ---------------------------------------------------------------------------

/// A triangle in MSH 2.2, as Gmsh writes it (physical group 7).
const MSH22: &str = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n\
                     $EndNodes\n$Elements\n1\n1 2 2 7 1 1 2 3\n$EndElements\n";

fn assert_unsupported_version(e: &tfem::Error, version: &str) {
    assert_eq!(e.status(), Status::InvalidMesh, "{}", e.message());
    for needle in [
        "$MeshFormat".to_string(),
        format!("MSH {version} is not supported"),
        "gmsh old.msh -save -format msh41 -o new.msh".to_string(),
        "Mesh.MshFileVersion = 4.1".to_string(),
    ] {
        assert!(e.message().contains(&needle), "{needle}: {}", e.message());
    }
}

#[test]
fn an_msh_2_2_file_is_unsupported_content_saying_how_to_convert_it() {
    let e = read_msh(&write("msh22.msh", MSH22), 0).unwrap_err();
    assert_unsupported_version(&e, "2.2");
}

#[test]
fn a_binary_msh_2_2_file_is_unsupported_content_too() {
    let mut bytes = b"$MeshFormat\n2.2 1 8\n".to_vec();
    bytes.extend_from_slice(&1i32.to_le_bytes());
    bytes.extend_from_slice(b"\n$EndMeshFormat\n");
    let e = read_msh(&write_bytes("msh22_bin.msh", &bytes), 0).unwrap_err();
    assert_unsupported_version(&e, "2.2");
}

#[test]
fn every_other_version_of_the_format_is_unsupported_content_naming_it() {
    for version in ["4.0", "4", "3.0", "2.1", "1.0", "5.0"] {
        let text = format!("$MeshFormat\n{version} 0 8\n$EndMeshFormat\n");
        let e = read_msh(&write("version.msh", &text), 0).unwrap_err();
        assert_unsupported_version(&e, version);
    }
}

#[test]
fn a_version_that_is_not_a_positive_number_is_a_malformed_header() {
    for version in ["x.y", "nan", "inf", "-4.1", "0"] {
        let text = format!("$MeshFormat\n{version} 0 8\n$EndMeshFormat\n");
        let e = read_msh(&write("bad_version.msh", &text), 0).unwrap_err();
        assert_eq!(e.status(), Status::Io, "{version}: {}", e.message());
        assert!(
            e.message()
                .contains("$MeshFormat: the format version must be a number such as 4.1"),
            "{}",
            e.message()
        );
    }
}

#[test]
fn the_conversion_the_message_gives_makes_a_file_tfem_reads() {
    let geo = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/meshes/two_blocks.geo");
    let (old, new) = (
        out_dir().join("seed_22.msh"),
        out_dir().join("seed_22_to_41.msh"),
    );
    let gmsh = |args: &[&std::ffi::OsStr]| {
        let out = Command::new("gmsh").args(args).output().expect("gmsh");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    gmsh(&[
        "-2".as_ref(),
        "-format".as_ref(),
        "msh22".as_ref(),
        geo.as_os_str(),
        "-o".as_ref(),
        old.as_os_str(),
    ]);
    assert_unsupported_version(&read_msh(&old, 0).unwrap_err(), "2.2");
    // As the message says: gmsh old.msh -save -format msh41 -o new.msh
    gmsh(&[
        old.as_os_str(),
        "-save".as_ref(),
        "-format".as_ref(),
        "msh41".as_ref(),
        "-o".as_ref(),
        new.as_os_str(),
    ]);
    let converted = read_msh(&new, 0).unwrap();
    let direct = read_msh(&mesh_with_gmsh(1.0 / 32.0, false), 0).unwrap();
    assert_eq!(converted.nodes().len(), direct.nodes().len());
    assert_eq!(converted.triangles().len(), direct.triangles().len());
    assert_eq!(converted.body_of(), direct.body_of());
    let tags = |m: &tfem::Mesh| {
        let mut t: Vec<i32> = m.boundary_edges().iter().map(|e| e.tag).collect();
        t.sort_unstable();
        t
    };
    assert_eq!(tags(&converted), tags(&direct));
}

// ---------------------------------------------------------------------------
// An error about an element or a node names its entity and physical
// group, by tag and by the name `$PhysicalNames` gives it.
// ---------------------------------------------------------------------------

/// Surface group 7 is "plate", curve group 11 "bottom edge".
const NAMES: &str = "$PhysicalNames\n2\n2 7 \"plate\"\n1 11 \"bottom edge\"\n$EndPhysicalNames\n";

/// One element of Gmsh type `ty` with `nodes` on surface 1 (physical
/// groups `groups`), over four nodes, the third at height `z3`.
fn one_element(names: &str, groups: &str, ty: u32, nodes: &str, z3: f64) -> String {
    format!(
        "{HEADER}{names}$Entities\n0 0 1 0\n1 0 0 0 1 1 0 {groups} 0\n$EndEntities\n\
         $Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 {z3}\n0 1 0\n$EndNodes\n\
         $Elements\n1 1 1 1\n2 1 {ty} 1\n1 {nodes}\n$EndElements\n"
    )
}

fn message_of(name: &str, text: &str) -> String {
    let e = read_msh(&write(name, text), 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh, "{}", e.message());
    e.message().to_string()
}

#[test]
fn an_unsupported_element_type_names_its_surface_and_physical_group() {
    let m = message_of(
        "named_quads.msh",
        &one_element(NAMES, "1 7", 3, "1 2 3 4", 0.0),
    );
    assert!(
        m.contains(
            "$Elements: entity block 1 of 1: surface 1 in physical group 7 \"plate\" has elements \
             of Gmsh type 3 (4-node quadrangles): only 3-node triangles are supported"
        ),
        "{m}"
    );
}

#[test]
fn an_entity_in_several_groups_is_named_with_each() {
    let m = message_of(
        "two_groups.msh",
        &one_element(NAMES, "2 7 8", 3, "1 2 3 4", 0.0),
    );
    assert!(
        m.contains("surface 1 in physical groups 7 \"plate\", 8 has elements"),
        "{m}"
    );
}

#[test]
fn a_group_without_a_name_is_named_by_its_tag() {
    let m = message_of(
        "unnamed_quads.msh",
        &one_element("", "1 7", 3, "1 2 3 4", 0.0),
    );
    assert!(
        m.contains("surface 1 in physical group 7 has elements"),
        "{m}"
    );
}

#[test]
fn a_triangle_with_a_repeated_node_names_its_physical_group() {
    let m = message_of(
        "named_degenerate.msh",
        &one_element(NAMES, "1 7", 2, "1 2 2", 0.0),
    );
    assert!(
        m.contains(
            "triangle 0 (Gmsh element 1 of surface 1 in physical group 7 \"plate\"): node 1 \
             (Gmsh node 2) is repeated"
        ),
        "{m}"
    );
}

#[test]
fn a_node_out_of_the_plane_names_its_surface_and_physical_group() {
    let m = message_of(
        "named_tilted.msh",
        &one_element(NAMES, "1 7", 2, "1 2 3", 0.5),
    );
    assert!(
        m.contains("$Nodes: node 3 of surface 1 in physical group 7 \"plate\" has z = 0.5"),
        "{m}"
    );
}

#[test]
fn a_line_that_is_no_side_names_its_curve_and_named_group() {
    let text = renumbered_square("1 1 0", &[], &[[1002, 1004]]).replacen(
        "$EndMeshFormat\n",
        &format!("$EndMeshFormat\n{NAMES}"),
        1,
    );
    let m = message_of("named_badline.msh", &text);
    assert!(
        m.contains(
            "Gmsh line element 32 of curve 1 in physical group 11 \"bottom edge\" (Gmsh nodes \
             1002, 1004) is not a side of any triangle"
        ),
        "{m}"
    );
}

#[test]
fn physical_names_are_read_in_a_binary_file_too() {
    // `$PhysicalNames` is ASCII in a binary file.
    let mut tilted = good_nodes();
    let z3 = tilted.len() - 1;
    tilted[z3] = F(0.5);
    let bytes = msh(
        true,
        &[
            ("PhysicalNames", vec![Raw("1\n2 7 \"plate\"")]),
            ("Entities", entities()),
            ("Nodes", tilted),
            ("Elements", good_elements()),
        ],
    );
    let e = read_msh(&write_bytes("named_tilted_bin.msh", &bytes), 0).unwrap_err();
    assert_eq!(e.status(), Status::InvalidMesh, "{}", e.message());
    assert!(
        e.message()
            .contains("node 3 of surface 1 in physical group 7 \"plate\" has z = 0.5"),
        "{}",
        e.message()
    );
}

#[test]
fn a_file_with_physical_names_is_read_as_without_them() {
    let with = read_msh(
        &write(
            "named_square.msh",
            &renumbered_square("1 1 0", &[], &[]).replacen(
                "$EndMeshFormat\n",
                &format!("$EndMeshFormat\n{NAMES}"),
                1,
            ),
        ),
        0,
    )
    .unwrap();
    let without = read_msh(
        &write("unnamed_square.msh", &renumbered_square("1 1 0", &[], &[])),
        0,
    )
    .unwrap();
    assert_eq!(with.nodes(), without.nodes());
    assert_eq!(with.triangles(), without.triangles());
    assert_eq!(with.body_of(), without.body_of());
}

#[test]
fn a_physical_name_without_its_closing_quote_is_an_io_error_naming_physical_names() {
    both(
        "unclosed_name",
        |binary| {
            msh(
                binary,
                &[
                    ("PhysicalNames", vec![Raw("1\n2 7 \"plate\n")]),
                    ("Entities", entities()),
                ],
            )
        },
        &["$PhysicalNames", "physical name 1 of 1", "no closing quote"],
    );
}

#[test]
fn a_physical_names_count_the_file_cannot_hold_is_an_io_error() {
    both(
        "names_count",
        |binary| msh(binary, &[("PhysicalNames", vec![Raw("1000000000000000")])]),
        &[
            "$PhysicalNames",
            "the number of physical names is 1000000000000000",
        ],
    );
}

#[test]
fn a_long_or_binary_group_name_is_quoted_short_and_printable() {
    let mut name = "x".repeat(100_000);
    name.insert_str(0, "\u{1b}[31m\u{7}");
    let names = format!("$PhysicalNames\n1\n2 7 \"{name}\"\n$EndPhysicalNames\n");
    let m = message_of(
        "long_name.msh",
        &one_element(&names, "1 7", 3, "1 2 3 4", 0.0),
    );
    assert!(printable_and_short(&m), "{} bytes: {m:.300}", m.len());
    assert!(m.contains("physical group 7 \"\\u{1b}[31m\\u{7}xxx"), "{m}");
}
