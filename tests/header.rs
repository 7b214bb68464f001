//! The committed C header must be exactly what cbindgen generates from the
//! current sources. Regenerate with `TFEM_BLESS=1 cargo test --test header`.

use std::path::PathBuf;

fn generate() -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(&root)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    with_sections(&String::from_utf8(out).expect("utf-8 header"))
}

/// The header's groups, in the order the entry points stand in the sources
/// (`src/ffi/entry.rs`, then `src/ffi/host.rs`, `src/ffi/solid.rs` and
/// `src/ffi/solid_contact.rs`): the first entry point of each and the head
/// put before it. cbindgen carries the items' own documentation only, so
/// the heads are put in here.
const SECTIONS: &[(&str, &str)] = &[
    (
        "tfem_version",
        "Lifecycle, errors and warnings: a model is created, used from one \
         thread at a time, and destroyed; every call returns a tfem_status, \
         the message of the last failed one is tfem_last_error's, and \
         warnings (something really wrong that did not stop the call) are \
         kept until the next solve or change.",
    ),
    (
        "tfem_set_mesh",
        "Mesh: nodes, triangles and their bodies (tfem_set_mesh, or a Gmsh \
         file), and the tagged boundary edges that loads, constraints and \
         contact pairs name.",
    ),
    (
        "tfem_set_material",
        "Materials, tempering and ordering: one material per body; the \
         tempering of degenerate triangles; the fill-reducing ordering.",
    ),
    (
        "tfem_fix",
        "Loads and constraints: prescribed displacements per node or per \
         tag, and their values changed along a load history; pressures, \
         tractions, nodal and body forces.",
    ),
    (
        "tfem_add_contact_pair",
        "Contact pairs: the interfaces between bodies (declared, or found by \
         tfem_add_contact_pairs_auto), their friction and weighting, and the \
         contact mesh B the strip weighting makes. These are the model's \
         own contact pairs, solved by tfem_solve_contact and tfem_step; a \
         host code with its own elements and solver uses the contact \
         context (tfem_contact_*) at the end of the header instead.",
    ),
    (
        "tfem_contact_options_default",
        "Solve: without contact (tfem_solve) or with it (tfem_solve_contact, \
         one load; tfem_step for a load history, below).",
    ),
    (
        "tfem_get_displacements",
        "Results of the last solve or step: displacements, strains, \
         stresses, reactions, external work, and the VTU file.",
    ),
    (
        "tfem_get_contact_report",
        "Contact results of the last solve or step. Per node, for every \
         pair: forces, pressures and tractions, gaps. Per element of the \
         contact mesh B (tfem_get_contact_active ... dissipation; pairs \
         weighted by B): element values at each element's apex. Per slave \
         node (pairs under the mortar weighting): tfem_get_contact_slave_nodes.",
    ),
    (
        "tfem_step",
        "Load history: steps on one factorisation, revert, and the contact \
         state saved and restored (restarts).",
    ),
    (
        "tfem_get_system_matrix_size",
        "Utilities: the assembled system matrix, and element stiffness \
         matrices for codes that assemble their own.",
    ),
    (
        "tfem_contact_create",
        "Contact for host codes (tfem_contact_*): a contact context for a \
         code that keeps its own elements and solver. It takes the host's \
         nodes, displacements and contact sides, and gives back the \
         contact's stiffness and forces to add to the host's system, and \
         the contact state per element of B (tfem_contact_get_active, \
         tfem_contact_pressures; not the model's tfem_get_contact_*).",
    ),
    (
        "tfem_solid_create",
        "The 3D model (tfem_solid_*): a handle of its own, tfem_solid_model, \
         with the conventions of tfem_model. Tetrahedra and tagged boundary \
         faces, one isotropic material per body, constraints and loads per \
         node or per face tag, frictionless contact pairs between tagged \
         surfaces (a planar side facing a matching one, docs/method.md §9), \
         a solve, and its results per node, per tetrahedron and per \
         tetrahedron of the contact layer B.",
    ),
    (
        "tfem_solid_contact_create",
        "Contact for 3D host codes (tfem_solid_contact_*): the contact \
         context of tfem_contact_* for a code with its own tetrahedral \
         elements and solver, a handle of its own, tfem_solid_contact. The \
         host gives each side's nodes, coordinates, equations (x, y, z) and \
         triangles, counter-clockwise seen from outside its body; it gets \
         back B's stiffness and forces in its equations, in a pattern fixed \
         once, the verdict of the active-set loop, and the state per \
         tetrahedron of B. Side, pair and tetrahedron numbers are in the \
         context's index base.",
    ),
];

/// `header` with each group's head (SECTIONS) put before the documentation
/// of its first entry point, wrapped at 77 columns.
fn with_sections(header: &str) -> String {
    let mut lines: Vec<String> = header.lines().map(str::to_string).collect();
    for (first, text) in SECTIONS.iter().rev() {
        let declared = format!("{first}(");
        let at = lines
            .iter()
            .position(|l| {
                let l = l.trim_start();
                !l.starts_with('*') && !l.starts_with("/*") && l.contains(&declared)
            })
            .unwrap_or_else(|| panic!("no entry point {first} in the header"));
        let doc = (0..at)
            .rev()
            .find(|&i| lines[i].trim_start().starts_with("/**"))
            .expect("documented");
        let mut head = vec![format!("/{}", "*".repeat(76))];
        let mut line = String::from(" *");
        for word in text.split_whitespace() {
            if line.len() + 1 + word.len() > 77 {
                head.push(std::mem::replace(&mut line, String::from(" *")));
            }
            line.push(' ');
            line.push_str(word);
        }
        head.push(line);
        head.push(format!(" {}/", "*".repeat(75)));
        head.push(String::new());
        lines.splice(doc..doc, head);
    }
    let mut out = lines.join("\n");
    out.push('\n');
    out
}

#[test]
fn committed_header_is_fresh() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("include/tfem.h");
    let fresh = generate();
    if std::env::var_os("TFEM_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("write include/tfem.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/tfem.h is stale: run `TFEM_BLESS=1 cargo test --test header` and commit it"
    );
}

#[test]
fn header_documents_every_function() {
    let fresh = generate();
    let lines: Vec<&str> = fresh.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        if line.contains(" tfem_") && line.contains('(') && !line.trim_start().starts_with('*') {
            let previous = lines[..i]
                .iter()
                .rev()
                .find(|l| !l.trim().is_empty())
                .copied()
                .unwrap_or("");
            assert!(
                previous.trim_end().ends_with("*/"),
                "function without documentation in the header: {line}"
            );
        }
    }
}
