//! Hertz contact: error against run time, matching and non-matching meshes.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::verification::fitted_rate;
use tfem::{ContactOptions, ContactWeighting};

use crate::Args;
use crate::common::{Curve, figure};

/// Hertz contact: the curved, gapped, possibly non-matching interface.
pub(crate) fn hertz(report: &mut String, a: &Args) {
    use tfem::scenes::hertz::Hertz;
    let levels: Vec<f64> = if a.quick {
        vec![4.0, 8.0, 16.0]
    } else {
        vec![4.0, 8.0, 16.0, 32.0, 64.0]
    };
    let base = Hertz::default();
    writeln!(
        report,
        "## Error against run time: Hertz contact\n\n\
         A cylinder (R = {}) pressed on a block, plane strain, frictionless, half model; the load \
         is chosen for a = {} R (`tfem::scenes::hertz`: graded built-in mesh, the cylinder's part \
         near the contact spans 40a, the block 100a). B is the strip triangulation of the curved gap. \
         *a*: where the block's nodal contact pressure ends; *p₀*: the block's nodal pressure on the \
         axis; *both sides*: the nodal pressure read from both sides of the interface \
         (`contact::traction::interface_pressures`, docs/method.md §6.11); *max inside 0.8a*: the \
         largest |p_node − p(x)|/p₀ over the block's nodes within 0.8a, for the block's own \
         reading and for both sides'; *fit*: least squares \
         of p² = p₀²(1 − x²/a²) over the inner 80 % of the contact. \
         Cases marked *mortar weighting* solve with `ContactWeighting::Mortar` (one weighted gap \
         per node of the coarser side, docs/method.md §6.11); their *both sides* columns read \
         the library's nodal pressures (the slave's −κG_i/m_i, interpolated at the master's \
         nodes). Relative errors against a = √(4PR/(πE*)), p₀ = 2P/(πa); rates fitted in h.\n",
        base.radius, base.half_width
    )
    .unwrap();
    let strip = ContactWeighting::Strip;
    let mortar = ContactWeighting::Mortar;
    let stiff_coarse = Hertz {
        e_cylinder: 100.0 * base.e_block,
        cylinder_mesh_ratio: 2.5,
        ..base
    };
    let stiff_fine = Hertz {
        cylinder_mesh_ratio: 0.4,
        ..stiff_coarse
    };
    let cases = [
        ("equal moduli", Hertz::default(), strip),
        (
            "cylinder 100× stiffer",
            Hertz {
                e_cylinder: 100.0 * base.e_block,
                ..base
            },
            strip,
        ),
        (
            "cylinder 100× softer",
            Hertz {
                e_cylinder: 0.01 * base.e_block,
                ..base
            },
            strip,
        ),
        (
            "non-matching (cylinder mesh 2.5× coarser)",
            Hertz {
                cylinder_mesh_ratio: 2.5,
                ..base
            },
            strip,
        ),
        (
            "non-matching (cylinder mesh 2.5× coarser), mortar weighting",
            Hertz {
                cylinder_mesh_ratio: 2.5,
                ..base
            },
            mortar,
        ),
        (
            "non-matching (cylinder mesh 2.5× finer)",
            Hertz {
                cylinder_mesh_ratio: 0.4,
                ..base
            },
            strip,
        ),
        (
            "non-matching (cylinder mesh 2.5× finer), mortar weighting",
            Hertz {
                cylinder_mesh_ratio: 0.4,
                ..base
            },
            mortar,
        ),
        (
            "cylinder 100× stiffer, its mesh 2.5× coarser",
            stiff_coarse,
            strip,
        ),
        (
            "cylinder 100× stiffer, its mesh 2.5× coarser, mortar weighting",
            stiff_coarse,
            mortar,
        ),
        (
            "cylinder 100× stiffer, its mesh 2.5× finer",
            stiff_fine,
            strip,
        ),
        (
            "cylinder 100× stiffer, its mesh 2.5× finer, mortar weighting",
            stiff_fine,
            mortar,
        ),
    ];
    let mut curves = Vec::new();
    for (label, case, weighting) in cases {
        writeln!(
            report,
            "### {label}\n\n| h | unknowns | iterations | time [s] | err a | err p₀ | err p₀ (both sides) | max inside 0.8a | max inside 0.8a (both sides) | err a (fit) | err p₀ (fit) |\n|---|---|---|---|---|---|---|---|---|---|---|"
        )
        .unwrap();
        let (mut hs, mut ea, mut ep, mut eb, mut ef, mut pts) = (
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
        );
        for &k in &levels {
            let hz = Hertz {
                mesh_size: case.half_width / k,
                ..case
            };
            let mut s = hz.build().expect("scene");
            s.model.set_contact_weighting(weighting).unwrap();
            let t0 = Instant::now();
            match s.solve(&hz, &ContactOptions::default()) {
                Ok(r) => {
                    let t = t0.elapsed().as_secs_f64();
                    let rel = |v: f64, e: f64| (v - e) / e;
                    writeln!(
                        report,
                        "| a/{k} | {} | {} | {t:.3} | {:+.2e} | {:+.2e} | {:+.2e} | {:.2e} | {:.2e} | {:+.2e} | {:+.2e} |",
                        r.report.info.unknowns,
                        r.report.iterations,
                        rel(r.a, r.a_exact),
                        rel(r.p0, r.p0_exact),
                        rel(r.p0_interface, r.p0_exact),
                        r.inner_error(&r.pressure),
                        r.inner_error(&r.interface_pressure),
                        rel(r.a_fit, r.a_exact),
                        rel(r.p0_fit, r.p0_exact)
                    )
                    .unwrap();
                    hs.push(1.0 / k);
                    ea.push(rel(r.a, r.a_exact).abs());
                    ep.push(rel(r.p0, r.p0_exact).abs());
                    eb.push(rel(r.p0_interface, r.p0_exact).abs());
                    ef.push(rel(r.p0_fit, r.p0_exact).abs());
                    pts.push((t, rel(r.p0_fit, r.p0_exact).abs()));
                }
                Err(e) => {
                    writeln!(report, "| a/{k} | {}: {} |", e.status().name(), e.message()).unwrap()
                }
            }
        }
        if hs.len() >= 2 {
            writeln!(
                report,
                "\nFitted rates in h: a {:.2}, p₀ {:.2}, p₀ (both sides) {:.2}, p₀ (fit) {:.2}.\n",
                fitted_rate(&hs, &ea),
                fitted_rate(&hs, &ep),
                fitted_rate(&hs, &eb),
                fitted_rate(&hs, &ef)
            )
            .unwrap();
        }
        curves.push(Curve {
            label: format!("{label}: p₀ (fit)"),
            points: pts,
        });
    }
    figure(
        report,
        a,
        "hertz_error_time.svg",
        "Hertz contact: relative error of the peak pressure (fit) against wall time",
        "time [s]",
        "relative error",
        &curves,
        "Hertz error against time",
    );
}
