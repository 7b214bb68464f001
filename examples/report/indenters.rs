//! Rigid indenters: a flat punch (Sneddon) and a rigid cylinder (Hertz).

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::failure;

/// Issue: rigid indenters, a flat punch (Sneddon) and a rigid cylinder
/// (Hertz with E* of the block alone).
pub(crate) fn indenters(report: &mut String, a: &Args) {
    use tfem::scenes::hertz::Hertz;
    use tfem::scenes::punch::{FlatPunch, RigidCylinder};
    let options = ContactOptions::default();
    let punch_levels: Vec<f64> = if a.quick {
        vec![8.0, 16.0, 32.0]
    } else {
        vec![8.0, 16.0, 32.0, 64.0, 128.0]
    };
    let base = FlatPunch::default();
    writeln!(
        report,
        "## Rigid indenters\n\n\
         ### Flat punch\n\n\
         A rigid flat punch of half-width a = {} pressed by a prescribed indentation into a block \
         of {}a × {}a (`tfem::scenes::punch`, plane strain, half model, frictionless; the block's \
         contact side extends to 2a so the contact's extent is the method's answer). *ℓc/a*: \
         contact length over the punch's half-width (1 exactly: the whole face, nothing beyond); \
         *pressure error*: the largest error of the block's nodal pressure against Sneddon's \
         P/(π√(a² − x²)) over 0 ≤ x ≤ 0.8a (away from the singular edge), relative to the \
         pressure there, P from the punch's reactions; *balance*: |P − support reaction| / P.\n",
        base.half_width, base.block_size, base.block_size
    )
    .unwrap();
    writeln!(
        report,
        "| h | unknowns | iterations | time [s] | P [N/m] | ℓc/a | active / elements of B | pressure error | balance |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let (mut hs, mut es) = (vec![], vec![]);
    for &k in &punch_levels {
        let punch = FlatPunch {
            mesh_size: base.half_width / k,
            ..base
        };
        let t0 = Instant::now();
        let r = punch.build().and_then(|mut s| s.solve(&punch, &options));
        let t = t0.elapsed().as_secs_f64();
        match r {
            Ok(r) => {
                writeln!(
                    report,
                    "| a/{k} | {} | {} | {t:.3} | {:.4e} | {:.6} | {} / {} | {:.2e} | {:.1e} |",
                    r.report.info.unknowns,
                    r.report.iterations,
                    r.force,
                    r.contact_length / punch.half_width,
                    r.active.0,
                    r.active.1,
                    r.pressure_error,
                    r.balance
                )
                .unwrap();
                hs.push(1.0 / k);
                es.push(r.pressure_error);
            }
            Err(e) => writeln!(report, "| a/{k} | {} | | | | | | | |", failure(&e)).unwrap(),
        }
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nFitted rate of the pressure error in h: {:.2}.\n",
            fitted_rate(&hs, &es)
        )
        .unwrap();
    }
    let cyl_levels: Vec<f64> = if a.quick {
        vec![4.0, 8.0, 16.0]
    } else {
        vec![4.0, 8.0, 16.0, 32.0, 64.0]
    };
    let rc0 = RigidCylinder::default();
    writeln!(
        report,
        "### Rigid cylinder\n\n\
         The Hertz scene's cylinder (R = {}) made rigid: every node translated by {:.3e} downwards \
         (`RigidCylinder`), the block elastic. Hertz for a rigid indenter, E* = E/(1 − ν²) of the \
         block alone: a = √(4PR/(πE*)), p₀ = 2P/(πa), P the cylinder's reaction; *a* and *p₀* \
         measured as in the Hertz section above (nodal, and fitted over the inner 80 %). Relative \
         errors; rates fitted in h.\n",
        rc0.hertz.radius, rc0.indentation
    )
    .unwrap();
    writeln!(
        report,
        "| h | unknowns | iterations | time [s] | P [N/m] | a/R (from P) | err a | err p₀ (fit) | err p₀ (nodal) |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let (mut hs, mut ea, mut ep) = (vec![], vec![], vec![]);
    for &k in &cyl_levels {
        let rc = RigidCylinder {
            hertz: Hertz {
                mesh_size: rc0.hertz.half_width / k,
                ..rc0.hertz
            },
            ..rc0
        };
        let t0 = Instant::now();
        let r = rc.build().and_then(|mut s| s.solve(&rc, &options));
        let t = t0.elapsed().as_secs_f64();
        match r {
            Ok(r) => {
                let h = &r.hertz;
                let rel = |v: f64, e: f64| (v - e) / e;
                writeln!(
                    report,
                    "| a/{k} | {} | {} | {t:.3} | {:.4e} | {:.5} | {:+.2e} | {:+.2e} | {:+.2e} |",
                    h.report.info.unknowns,
                    h.report.iterations,
                    r.force,
                    h.a_exact / rc.hertz.radius,
                    rel(h.a, h.a_exact),
                    rel(h.p0_fit, h.p0_exact),
                    rel(h.p0, h.p0_exact)
                )
                .unwrap();
                hs.push(1.0 / k);
                ea.push(rel(h.a, h.a_exact).abs());
                ep.push(rel(h.p0_fit, h.p0_exact).abs());
            }
            Err(e) => writeln!(report, "| a/{k} | {} | | | | | | | |", failure(&e)).unwrap(),
        }
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nFitted rates in h: a {:.2}, p₀ (fit) {:.2}.\n",
            fitted_rate(&hs, &ea),
            fitted_rate(&hs, &ep)
        )
        .unwrap();
    }
}
