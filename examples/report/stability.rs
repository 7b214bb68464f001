//! Stability on stiff and extreme cases; degenerate and inverted elements.

use std::fmt::Write as _;

use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;
use tfem::{ContactOptions, Material, PlaneMode, Tempering};

use crate::Args;

pub(crate) fn stability(report: &mut String, a: &Args) {
    let base = TwoBlocks {
        mesh_size: if a.quick { 1.0 / 32.0 } else { 1.0 / 64.0 },
        ..Default::default()
    };
    writeln!(report, "## Stability on stiff and extreme cases\n").unwrap();
    writeln!(
        report,
        "The seed scene at h = {:.5} unless stated. Residual: ‖Ku − f‖/‖f‖ of the final system; \
         condition: estimate for the Jacobi-scaled matrix; balance: support reaction / (p·2C) − 1; \
         finite: every displacement and pressure is finite. The same cases are asserted in \
         `tests/stability.rs`.\n",
        base.mesh_size
    )
    .unwrap();
    writeln!(report, "| case | status | iterations | residual | condition | ℓc/L | v_top/L | max penetration/L | balance | finite |\n|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut cases: Vec<(String, TwoBlocks, ContactOptions)> = Vec::new();
    for r in [1.0, 1e3, 1e6, 1e9, 1e12] {
        cases.push((
            format!("E2/E1 = {r:.0e}"),
            TwoBlocks {
                e2: base.e1 * r,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for nu in [0.0, 0.3, 0.49, 0.4999] {
        cases.push((
            format!("ν = {nu}"),
            TwoBlocks {
                nu1: nu,
                nu2: nu,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for lh in [0.1, 1.0, 10.0, 1e2, 1e4, 1e6] {
        cases.push((
            format!("λ/h = {lh:.0e} (contact)"),
            base,
            ContactOptions {
                lambda: Some(lh * base.mesh_size),
                ..Default::default()
            },
        ));
    }
    for k in [1e-6, 1e-3, 1e3, 1e6] {
        cases.push((
            format!("lengths ×{k:.0e}"),
            TwoBlocks {
                h1: base.h1 * k,
                h2: base.h2 * k,
                length: base.length * k,
                c: base.c * k,
                mesh_size: base.mesh_size * k,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for g in [0.0, 1e-12, 1e-9, 1e-6] {
        cases.push((
            format!("initial gap {g:.0e} m"),
            TwoBlocks { gap: g, ..base },
            ContactOptions::default(),
        ));
    }
    if !a.quick {
        cases.push((
            "h = 1/1448 (2.1M unknowns)".into(),
            TwoBlocks {
                mesh_size: 1.0 / 1448.0,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    cases.push((
        "no symmetry condition (free sliding)".into(),
        TwoBlocks {
            symmetry: false,
            ..base
        },
        ContactOptions::default(),
    ));
    cases.push((
        "no support (floating)".into(),
        TwoBlocks {
            support: false,
            ..base
        },
        ContactOptions::default(),
    ));
    for (name, scene, opts) in cases {
        let mut s = scene.build().expect("scene");
        match s.solve(&opts) {
            Ok(r) => {
                let finite = s
                    .model
                    .displacements()
                    .map(|u| u.iter().flatten().all(|v| v.is_finite()))
                    .unwrap_or(false);
                let l = scene.length;
                writeln!(
                    report,
                    "| {name} | ok | {} | {:.1e} | {:.1e} | {:.4} | {:.5e} | {:.2e} | {:+.1e} | {} |",
                    r.report.iterations,
                    r.report.info.relative_residual,
                    r.report.info.condition_estimate,
                    r.lc / l,
                    r.v_top / l,
                    r.report.max_penetration / l,
                    r.support_reaction / (scene.p * 2.0 * scene.c) - 1.0,
                    if finite { "yes" } else { "NO" }
                )
                .unwrap();
            }
            Err(e) => {
                let msg: String = e.message().chars().take(110).collect();
                writeln!(
                    report,
                    "| {name} | {} | – | – | – | – | – | – | – | no output: {msg}… |",
                    e.status().name()
                )
                .unwrap();
            }
        }
    }
    writeln!(report).unwrap();
    degenerate(report);
}

/// One body (E = 1, ν = 0.3, plane strain) clamped on its boundary under a
/// unit downward body force.
pub(crate) fn clamped(b: tfem::meshgen::MeshBuilder) -> tfem::Model {
    let boundary: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
    let mut model = tfem::Model::new();
    model.set_mesh(b.build().expect("mesh"));
    model
        .set_material(
            1,
            Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").expect("material"),
        )
        .expect("material");
    for v in boundary {
        model.fix(v, tfem::Component::X, 0.0).expect("fix");
        model.fix(v, tfem::Component::Y, 0.0).expect("fix");
    }
    model.set_body_force(1, [0.0, -1.0]).expect("load");
    model
}

/// Degenerate and inverted elements, and a tempering λ too small for the
/// mesh: a unit square (16 × 16 cells, edges fixed, body force) with a band
/// of caps of height ε along y = 1/2, TFEM against plain FEM.
fn degenerate(report: &mut String) {
    writeln!(
        report,
        "### Degenerate and inverted elements, λ too small\n\n\
         Square [0, 1] × [−1/2, 1/2], 16 × 16 cells, edges fixed, unit body force, E = 1, ν = 0.3, \
         with a band of caps of height ε along y = 0 (J = ε/16; ε < 0: inverted caps). *max |u|*: relative to \
         the regular mesh without the band. Every case ends with a finite answer or a status naming \
         the element.\n\n\
         | case | status | max |u| vs regular | finite | warnings / message |\n|---|---|---|---|---|"
    )
    .unwrap();
    let solve = |eps: Option<f64>, tempering: Tempering| -> (tfem::Result<f64>, Vec<String>) {
        // Built with the band at y = 1/2 and moved to y = 0, where ε down to
        // 1e-300 is representable (0.5 + 1e-300 rounds to 0.5).
        let mut b = unit_square(16, eps.map(|_| 0.0));
        for p in &mut b.nodes {
            p[1] -= 0.5;
        }
        if let Some(eps) = eps {
            // The band's apex row follows the lower grid's 17 × 9 nodes.
            for p in &mut b.nodes[17 * 9..17 * 9 + 18] {
                p[1] = eps;
            }
        }
        let mut model = clamped(b);
        model.set_tempering(tempering).expect("tempering");
        let r = model.solve().and_then(|_| model.displacements()).map(|u| {
            u.iter().flatten().fold(0.0f64, |m, v| {
                if v.is_finite() {
                    m.max(v.abs())
                } else {
                    f64::NAN
                }
            })
        });
        (r, model.warnings())
    };
    let reference = solve(None, Tempering::Auto).0.unwrap_or(f64::NAN);
    let mut rows: Vec<(String, Option<f64>, Tempering)> = Vec::new();
    for eps in [0.0, 1e-300, -1e-9] {
        rows.push((format!("ε = {eps:.0e}, TFEM"), Some(eps), Tempering::Auto));
        rows.push((
            format!("ε = {eps:.0e}, plain FEM"),
            Some(eps),
            Tempering::Off,
        ));
    }
    rows.push((
        "regular mesh, TFEM with λ = h/10 (too small)".into(),
        None,
        Tempering::Lambda(0.1 / 16.0),
    ));
    for (name, eps, tempering) in rows {
        let (r, warnings) = solve(eps, tempering);
        match r {
            Ok(m) => {
                let w: String = warnings.join("; ").chars().take(140).collect();
                writeln!(
                    report,
                    "| {name} | ok | {:+.2e} | {} | {} |",
                    m / reference - 1.0,
                    if m.is_finite() { "yes" } else { "NO" },
                    if w.is_empty() {
                        "–".into()
                    } else {
                        format!("{w}…")
                    }
                )
                .unwrap();
            }
            Err(e) => {
                let msg: String = e.message().chars().take(140).collect();
                writeln!(report, "| {name} | {} | – | – | {msg} |", e.status().name()).unwrap();
            }
        }
    }
    writeln!(report).unwrap();
}
