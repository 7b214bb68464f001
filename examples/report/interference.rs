//! Interference fits: the Lamé shrink fit.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::verification::fitted_rate;
use tfem::{ContactOptions, ContactWeighting, PlaneMode};

use crate::Args;
use crate::common::failure;

/// Issue: Lamé shrink fits, every element of B inverted at the start.
pub(crate) fn interference(report: &mut String, a: &Args) {
    use tfem::scenes::lame::Lame;
    let levels: Vec<f64> = if a.quick {
        vec![8.0, 16.0, 32.0]
    } else {
        vec![8.0, 16.0, 32.0, 64.0, 128.0]
    };
    let base = Lame::default();
    writeln!(
        report,
        "## Interference fits: the Lamé shrink fit\n\n\
         Two concentric rings overlapping by a radial interference δ (`tfem::scenes::lame`: a = {}, \
         b = {}, c = {}, inner E = {:.0e} ν = {}, outer E = {:.0e} ν = {}; quarter model, polar \
         criss-cross mesh of size h), every element of B inverted at the start (J0 < 0), against \
         the closed-form shrink fit of two rings of different materials. Errors relative to the \
         closed-form contact pressure p: *pressure*, the largest nodal contact pressure error on \
         both surfaces; *hoop* and *radial*, the largest error of a grid cell's mean σ_θθ, σ_rr \
         against the closed form at the cell's centre; *bore hoop*, the outer ring's hoop stress \
         along its bore relative to itself. Rates fitted in h. *weighting*: the elements of B \
         (strip, the default) or `ContactWeighting::Mortar` (one weighted gap per node of the \
         coarser side; here the inner ring's, both sides having the same nodes' angles).\n",
        base.inner_radius,
        base.radius,
        base.outer_radius,
        base.e_inner,
        base.nu_inner,
        base.e_outer,
        base.nu_outer
    )
    .unwrap();
    writeln!(
        report,
        "| weighting | plane | δ/b | h | unknowns | iterations | time [s] | p (closed form) [Pa] | pressure error | hoop error | radial error | bore hoop error |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut rates = Vec::new();
    let weightings = [ContactWeighting::Strip, ContactWeighting::Mortar];
    for (weighting, plane) in weightings
        .into_iter()
        .flat_map(|w| [PlaneMode::Strain, PlaneMode::Stress].map(|p| (w, p)))
    {
        let w = format!("{weighting:?}").to_lowercase();
        for delta in [1e-2, 1e-4, 1e-6] {
            let (mut hs, mut ep, mut eh, mut er) = (vec![], vec![], vec![], vec![]);
            for &k in &levels {
                let lame = Lame {
                    interference: delta * base.radius,
                    plane,
                    mesh_size: base.radius / k,
                    ..base
                };
                let t0 = Instant::now();
                let r = lame.build().and_then(|mut s| {
                    s.model.set_contact_weighting(weighting).unwrap();
                    s.solve(&lame, &ContactOptions::default())
                });
                let t = t0.elapsed().as_secs_f64();
                match r {
                    Ok(r) => {
                        writeln!(
                            report,
                            "| {w} | {plane:?} | {delta:.0e} | b/{k} | {} | {} | {t:.3} | {:.4e} | {:.2e} | {:.2e} | {:.2e} | {:.2e} |",
                            r.report.info.unknowns,
                            r.report.iterations,
                            r.exact.pressure,
                            r.pressure_error,
                            r.hoop_error,
                            r.radial_error,
                            r.bore_hoop_error
                        )
                        .unwrap();
                        hs.push(1.0 / k);
                        ep.push(r.pressure_error);
                        eh.push(r.hoop_error);
                        er.push(r.radial_error);
                    }
                    Err(e) => writeln!(
                        report,
                        "| {w} | {plane:?} | {delta:.0e} | b/{k} | {} | | | | | | | |",
                        failure(&e)
                    )
                    .unwrap(),
                }
            }
            if hs.len() >= 2 {
                rates.push(format!(
                    "| {w} | {plane:?} | {delta:.0e} | {:.2} | {:.2} | {:.2} |",
                    fitted_rate(&hs, &ep),
                    fitted_rate(&hs, &eh),
                    fitted_rate(&hs, &er)
                ));
            }
        }
    }
    writeln!(
        report,
        "\nFitted rates in h:\n\n| weighting | plane | δ/b | pressure | hoop | radial |\n|---|---|---|---|---|---|\n{}\n",
        rates.join("\n")
    )
    .unwrap();
}
