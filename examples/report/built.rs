//! What each scene built: the structures a scene without contact leaves out.

use std::fmt::Write as _;

use tfem::ContactOptions;
use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;

use crate::stability::clamped;

pub(crate) fn built(report: &mut String) {
    writeln!(report, "## What each scene built\n").unwrap();
    writeln!(report, "| scene | contact elements in B | matrix nnz | factor nnz | memory [MB] |\n|---|---|---|---|---|").unwrap();
    // Without contact: the same two blocks glued by nothing but each held on
    // its own (solve, not solve_contact): no contact structure exists.
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 64.0,
        ..Default::default()
    }
    .build()
    .expect("scene");
    let rc = s
        .model
        .solve_contact(&ContactOptions::default())
        .expect("contact");
    writeln!(
        report,
        "| seed scene, contact | {} | {} | {} | {:.1} |",
        rc.elements,
        rc.info.matrix_nnz,
        rc.info.factor_nnz,
        rc.info.memory_bytes as f64 / 1e6
    )
    .unwrap();
    let mut model = clamped(unit_square(128, None));
    let i = model.solve().expect("solve");
    writeln!(
        report,
        "| unit square 128², no contact | {} | {} | {} | {:.1} |\n",
        model.contact_elements().map_or(0, |c| c.len()),
        i.matrix_nnz,
        i.factor_nnz,
        i.memory_bytes as f64 / 1e6
    )
    .unwrap();
    writeln!(
        report,
        "A scene without contact pairs builds no contact mesh, no contact pattern entries and no \
         active-set state (`contact_elements()` is an error: there are none). Strains, stresses, \
         reactions and contact pressures are computed only when asked for (accessors), never during \
         the solve. The core library builds without the optional I/O (`--no-default-features`: no VTU \
         writer, no Gmsh reader, no dependency but faer, nalgebra, libc and rayon; checked in CI).\n"
    )
    .unwrap();
}
