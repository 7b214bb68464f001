//! The contact patch test: error against run time, and every interface ratio.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;

use crate::Args;
use crate::common::{Curve, failure, figure, sci_list};

/// The contact patch test: uniform pressure over the whole width, so the
/// exact stress is σ_yy = −p everywhere; conforming and non-matching
/// (upper mesh 7/3 coarser) interfaces.
pub(crate) fn patch_test(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512]
    };
    writeln!(
        report,
        "## Error against run time: the contact patch test\n\n\
         Two blocks pressed together over the whole width (2C = L): the exact stress is uniform, \
         σ_yy = −p, σ_xx = τ_xy = 0. Relative L2 (area-weighted) and max stress error over all \
         elements, and the whole contact solve's time. Non-matching: upper block meshed 7/3 as \
         coarse (almost no interface node matches; B triangulates the strip).\n\n\
         | h | conforming: unknowns | L2 | max | time [s] | non-matching: unknowns | L2 | max | time [s] |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut curves = vec![
        Curve {
            label: "conforming".into(),
            points: vec![],
        },
        Curve {
            label: "non-matching (7:3)".into(),
            points: vec![],
        },
    ];
    let (mut hs, mut l2s) = (Vec::new(), Vec::new());
    for &n in &levels {
        let h = 1.0 / n as f64;
        let mut cells = Vec::new();
        for (k, upper) in [None, Some(h * 7.0 / 3.0)].into_iter().enumerate() {
            let scene = TwoBlocks {
                c: 0.5,
                mesh_size: h,
                upper_mesh_size: upper,
                ..Default::default()
            };
            let mut s = scene.build().expect("scene");
            let t0 = Instant::now();
            let Ok(r) = s.solve(&ContactOptions::default()) else {
                cells.push("failed | – | – | –".to_string());
                continue;
            };
            let total = t0.elapsed().as_secs_f64();
            let mesh = s.model.mesh().expect("mesh");
            let p = scene.p;
            let (mut sum, mut area, mut worst) = (0.0, 0.0, 0.0f64);
            for (t, sig) in mesh
                .triangles()
                .iter()
                .zip(s.model.element_stresses().expect("stresses"))
            {
                let ar = 0.5 * tfem::TriGeometry::new(&mesh.corners(t)).j;
                let e2 = ((sig[1] + p).powi(2) + sig[0].powi(2) + sig[2].powi(2)) / (p * p);
                sum += ar * e2;
                area += ar;
                worst = worst.max(e2.sqrt());
            }
            let l2 = (sum / area).sqrt();
            cells.push(format!(
                "{} | {l2:.2e} | {worst:.2e} | {total:.3}",
                r.report.info.unknowns
            ));
            curves[k].points.push((total, l2.max(1e-16)));
            if k == 1 {
                hs.push(h);
                l2s.push(l2);
            }
        }
        writeln!(report, "| 1/{n} | {} |", cells.join(" | ")).unwrap();
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nLargest non-matching L2 error over the levels: {:.2e}. Both interfaces pass the patch \
             test to round-off (docs/method.md §6.11; `cargo run --release --example patch_test` \
             sweeps ratios, jitter and moduli).\n",
            l2s.iter().fold(0.0f64, |m, &v| m.max(v))
        )
        .unwrap();
    }
    figure(
        report,
        a,
        "patch_error_time.svg",
        "contact patch test: L2 stress error against wall time",
        "time [s]",
        "relative L2 stress error",
        &curves,
        "patch test error against time",
    );
}

/// Issue: the contact patch test on every interface ratio, both ways, on
/// uniform and jittered grids and two material pairs.
pub(crate) fn patch_ratios(report: &mut String, a: &Args) {
    use tfem::scenes::patch::PatchTest;
    let levels: Vec<usize> = if a.quick {
        vec![8, 16, 32]
    } else {
        vec![8, 16, 32, 64, 128]
    };
    let finest = *levels.last().expect("levels");
    writeln!(
        report,
        "## The contact patch test on every interface ratio\n\n\
         Two blocks under a uniform pressure p over the whole top (`tfem::scenes::patch`): the exact \
         solution is σ_yy = −p, σ_xx = τ_xy = 0 and a contact pressure p everywhere. Ratio: upper \
         cell width over lower (2:3 means 1.5, its reverse 3:2); jitter 0.3: every interior grid \
         column moved by up to 0.3 of a cell, so no interface nodes line up. Max stress error: over \
         every element, √Σ(σ − σ_exact)² / p, at each h = {}; nodal pressure error: the largest \
         |p_node/p − 1| over both interface sides and every h; released: elements of B not active \
         at convergence over every h (all should be active); times: building the scene and its contact solve, at each h.\n",
        levels
            .iter()
            .map(|n| format!("1/{n}"))
            .collect::<Vec<_>>()
            .join(", ")
    )
    .unwrap();
    writeln!(
        report,
        "| E2/E1 | ratio | jitter | max stress error / p (h = 1/{} … 1/{finest}) | nodal pressure error | released | iterations (max) | times [s] (h = 1/{} … 1/{finest}) |\n|---|---|---|---|---|---|---|---|",
        levels[0], levels[0]
    )
    .unwrap();
    let ratios: [(&str, f64); 7] = [
        ("1:1", 1.0),
        ("2:3", 1.5),
        ("3:2", 2.0 / 3.0),
        ("3:7", 7.0 / 3.0),
        ("7:3", 3.0 / 7.0),
        ("5:8", 1.6),
        ("8:5", 5.0 / 8.0),
    ];
    let (mut worst, mut worst_nodal, mut releases, mut failures) = (0.0f64, 0.0f64, 0, 0);
    // Round-off grows like the condition number, ~1/h²: 1e-8 p is far
    // above it at h = 1/128 and far below any discretisation error.
    let mut above = Vec::new();
    for (e_ratio, e1, e2) in [(1.0, 1e10, 1e10), (10.0, 1e10, 1e11)] {
        for &(name, ratio) in &ratios {
            for jitter in [0.0, 0.3] {
                let (mut errs, mut nodal, mut released, mut iters, mut times) =
                    (Vec::new(), 0.0f64, 0, 0, Vec::new());
                let mut failed = Vec::new();
                for &n in &levels {
                    let test = PatchTest {
                        e_lower: e1,
                        e_upper: e2,
                        mesh_size: 1.0 / n as f64,
                        ratio,
                        jitter,
                        ..Default::default()
                    };
                    let t0 = Instant::now();
                    let r = test
                        .build()
                        .and_then(|mut s| s.solve(&test, &ContactOptions::default()));
                    let t = t0.elapsed().as_secs_f64();
                    match r {
                        Ok(r) => {
                            errs.push(r.max_error);
                            nodal = nodal
                                .max((r.nodal_pressure.0 - 1.0).abs())
                                .max((r.nodal_pressure.1 - 1.0).abs());
                            released += r.released;
                            iters = iters.max(r.report.iterations);
                            times.push(format!("{t:.3}"));
                        }
                        Err(e) => failed.push(format!("1/{n} {}", failure(&e))),
                    }
                }
                for (&n, &e) in levels.iter().zip(&errs) {
                    if e > 1e-8 {
                        above.push(format!(
                            "E2/E1 = {e_ratio}, {name}, jitter {jitter}, h = 1/{n}: {e:.1e}"
                        ));
                    }
                }
                worst = errs.iter().fold(worst, |m, &v| m.max(v));
                worst_nodal = worst_nodal.max(nodal);
                releases += released;
                failures += failed.len();
                let case = (e_ratio, name, ratio, jitter);
                ratio_row(
                    report,
                    case,
                    (&errs, nodal, released, iters),
                    (&failed, &times),
                );
            }
        }
    }
    writeln!(
        report,
        "\nOver all {} solves: largest max stress error {worst:.1e} p, largest nodal pressure \
         error {worst_nodal:.1e} p, {releases} false release(s), {failures} failed solve(s). \
         Max stress errors above 1e-8 p (not round-off): {}.\n",
        2 * ratios.len() * 2 * levels.len(),
        if above.is_empty() {
            "none".to_string()
        } else {
            above.join("; ")
        }
    )
    .unwrap();
    patch_ratios_mortar(report, &levels, &ratios);
}

/// One row of the patch-test tables: the case (E2/E1, ratio's name and
/// value, jitter), its max stress errors per h, pressure error, releases
/// and iterations, the failed levels and the times.
fn ratio_row(
    report: &mut String,
    (e_ratio, name, ratio, jitter): (f64, &str, f64, f64),
    (errs, pressure, released, iters): (&[f64], f64, usize, usize),
    (failed, times): (&[String], &[String]),
) {
    let failed = match failed.is_empty() {
        true => String::new(),
        false => format!("; failed: {}", failed.join(", ")),
    };
    writeln!(
        report,
        "| {e_ratio} | {name} ({ratio:.3}) | {jitter} | {}{failed} | {pressure:.1e} | {released} | {iters} | {} |",
        sci_list(errs),
        times.join(", ")
    )
    .unwrap();
}

/// The same patch tests under the mortar weighting
/// (`ContactWeighting::Mortar`).
fn patch_ratios_mortar(report: &mut String, levels: &[usize], ratios: &[(&str, f64)]) {
    use tfem::ContactWeighting;
    use tfem::scenes::patch::PatchTest;
    let finest = *levels.last().expect("levels");
    writeln!(
        report,
        "### The same under the mortar weighting\n\n\
         `ContactWeighting::Mortar` (one weighted gap per node of the coarser side, \
         docs/method.md §6.11): max stress error as above; slave pressure error: the largest \
         |p_i/p − 1| of the slave nodes' −κG_i/m_i over every h; released: slave nodes not \
         active.\n\n\
         | E2/E1 | ratio | jitter | max stress error / p (h = 1/{} … 1/{finest}) | slave pressure error | released | iterations (max) | times [s] |\n|---|---|---|---|---|---|---|---|",
        levels[0]
    )
    .unwrap();
    let (mut worst, mut worst_p, mut releases) = (0.0f64, 0.0f64, 0);
    for (e_ratio, e1, e2) in [(1.0, 1e10, 1e10), (10.0, 1e10, 1e11)] {
        for &(name, ratio) in ratios {
            for jitter in [0.0, 0.3] {
                let (mut errs, mut perr, mut released, mut iters, mut times) =
                    (Vec::new(), 0.0f64, 0, 0, Vec::new());
                let mut failed = Vec::new();
                for &n in levels {
                    let test = PatchTest {
                        e_lower: e1,
                        e_upper: e2,
                        mesh_size: 1.0 / n as f64,
                        ratio,
                        jitter,
                        ..Default::default()
                    };
                    let t0 = Instant::now();
                    let r = test.build().and_then(|mut s| {
                        s.model
                            .set_contact_weighting(ContactWeighting::Mortar)
                            .unwrap();
                        let report = s.model.solve_contact(&ContactOptions::default())?;
                        let e = s.stress_errors(&test)?;
                        let nodes = s.model.contact_slave_nodes()?.to_vec();
                        Ok((report, e, nodes))
                    });
                    let t = t0.elapsed().as_secs_f64();
                    match r {
                        Ok((rep, e, nodes)) => {
                            errs.push(e.max);
                            for q in &nodes {
                                perr = perr.max((q.pressure / test.p - 1.0).abs());
                            }
                            released += nodes.iter().filter(|q| !q.active).count();
                            iters = iters.max(rep.iterations);
                            times.push(format!("{t:.3}"));
                        }
                        Err(e) => failed.push(format!("1/{n} {}", failure(&e))),
                    }
                }
                worst = errs.iter().fold(worst, |m, &v| m.max(v));
                worst_p = worst_p.max(perr);
                releases += released;
                let case = (e_ratio, name, ratio, jitter);
                ratio_row(
                    report,
                    case,
                    (&errs, perr, released, iters),
                    (&failed, &times),
                );
            }
        }
    }
    writeln!(
        report,
        "\nUnder the mortar weighting: largest max stress error {worst:.1e} p, largest slave \
         pressure error {worst_p:.1e} p, {releases} released slave node(s).\n"
    )
    .unwrap();
}
