//! Error against run time, adaptive beside uniform, on the seed scene
//! (docs/method.md §8), and beside CalculiX's uniform CPE4 meshes at equal
//! accuracy.

use std::fmt::Write as _;
use std::time::Instant;

use serde_json::Value;
use tfem::ContactOptions;
use tfem::model::adapt::{AdaptOptions, Goal};
use tfem::scenes::{TwoBlocks, TwoBlocksResult};
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::{Curve, failure, figure, reference};

/// The four outputs of the reference file with their relative errors.
fn errors(r: &TwoBlocksResult, case: &Value) -> [f64; 4] {
    let rel = |v: f64, k: &str| case[k]["value"].as_f64().map_or(f64::NAN, |x| (v - x) / x);
    [
        rel(r.compliance, "compliance"),
        rel(r.v_top, "v_top"),
        rel(r.gap_edge, "gap_edge"),
        rel(r.lc, "lc"),
    ]
}

pub(crate) fn adaptive(report: &mut String, a: &Args) {
    writeln!(
        report,
        "## Error against run time: adaptive beside uniform\n"
    )
    .unwrap();
    writeln!(
        report,
        "The seed scene (canonical parameters), frictionless. *Adaptive*: from h = 1/16, refined by \
         newest-vertex bisection where the stress-recovery estimate is (Dörfler, θ = ½), to a tolerance on the \
         compliance's estimated relative error; time of the whole adaptive solve (every cycle's assembly, \
         factorisation, contact solve, estimate and refinement), one thread. *Uniform*: one solve on the \
         structured mesh of size h, one thread. Relative errors against the reference (GetFEM, \
         docs/reference/; its error bars: compliance 1.8e-4, v_top 1.8e-4, gap_edge 1.4e-3, ℓc 1.2e-3 \
         at 2C/L = 0.2). The estimate is of the energy norm: it drives the compliance and v_top; ℓc \
         (the contact zone's edge), which the energy does not see, is located by refining the interface \
         edges pressed at one end only until they are shorter than the tolerance times ℓc.\n"
    )
    .unwrap();
    let Some(refs) = reference(a) else {
        writeln!(report, "Skipped: no reference file.\n").unwrap();
        return;
    };
    let (tolerances, sizes): (&[f64], &[f64]) = if a.quick {
        (&[1e-2, 1e-3], &[1.0 / 32.0, 1.0 / 64.0])
    } else {
        (
            &[1e-2, 1e-3, 3e-4, 1e-4],
            &[1.0 / 64.0, 1.0 / 128.0, 1.0 / 256.0, 1.0 / 512.0],
        )
    };
    let widths: &[f64] = if a.quick { &[0.1] } else { &[0.1, 0.2, 0.3] };
    let mut curves = Vec::new();
    for &c in widths {
        let key = format!("canonical_{:.1}", 2.0 * c);
        let case = &refs["cases"][key.as_str()];
        writeln!(
            report,
            "### 2C/L = {:.1}\n\n| run | unknowns | cycles | estimate | time [s] | compliance | v_top | gap_edge | ℓc |\n\
             |---|---|---|---|---|---|---|---|---|",
            2.0 * c
        )
        .unwrap();
        let mut adaptive_points = Vec::new();
        let mut final_solves = Vec::new();
        // (tolerance, time, errors) and (time, errors), for the targets.
        let (mut adaptive_errors, mut uniform_errors) = (Vec::new(), Vec::new());
        let (mut adaptive_n, mut uniform_n) = (Vec::new(), Vec::new());
        for &tol in tolerances {
            match adapt_run(c, tol) {
                Ok(run) => {
                    let e = errors(&run.result, case);
                    writeln!(
                        report,
                        "| adaptive, tol {tol:.0e} | {} | {} | {:.2e} | {:.3} | {:+.2e} | {:+.2e} | {:+.2e} | {:+.2e} |",
                        run.unknowns, run.cycles, run.estimate, run.seconds, e[0], e[1], e[2], e[3]
                    )
                    .unwrap();
                    adaptive_points.push((run.seconds, e[0].abs()));
                    adaptive_errors.push((tol, run.seconds, e));
                    adaptive_n.push((run.unknowns as f64, e[0].abs()));
                    final_solves.push(run.final_solve);
                }
                Err(e) => {
                    writeln!(report, "| adaptive, tol {tol:.0e} | {} |", failure(&e)).unwrap()
                }
            }
        }
        let mut uniform_points = Vec::new();
        for &h in sizes {
            match uniform_run(c, h) {
                Ok((r, unknowns, t)) => {
                    let e = errors(&r, case);
                    writeln!(
                        report,
                        "| uniform, h = 1/{:.0} | {unknowns} | 1 | | {t:.3} | {:+.2e} | {:+.2e} | {:+.2e} | {:+.2e} |",
                        1.0 / h,
                        e[0],
                        e[1],
                        e[2],
                        e[3]
                    )
                    .unwrap();
                    uniform_points.push((t, e[0].abs()));
                    uniform_errors.push((t, e));
                    uniform_n.push((unknowns as f64, e[0].abs()));
                }
                Err(e) => writeln!(
                    report,
                    "| uniform, h = 1/{:.0} | {} |",
                    1.0 / h,
                    failure(&e)
                )
                .unwrap(),
            }
        }
        let order = |p: &[(f64, f64)]| {
            let n: Vec<f64> = p.iter().map(|q| q.0).collect();
            let e: Vec<f64> = p.iter().map(|q| q.1).collect();
            -fitted_rate(&n, &e)
        };
        writeln!(
            report,
            "\nCompliance error against unknowns N: adaptive N^-{:.2}, uniform N^-{:.2}.",
            order(&adaptive_n),
            order(&uniform_n)
        )
        .unwrap();
        speedup(report, &adaptive_points, &final_solves, &uniform_points);
        targets(report, case, &adaptive_errors, &uniform_errors);
        if c == 0.1 {
            calculix(report, &adaptive_points, case);
        }
        curves.push(Curve {
            label: format!("adaptive, 2C/L = {:.1}", 2.0 * c),
            points: adaptive_points,
        });
        curves.push(Curve {
            label: format!("uniform, 2C/L = {:.1}", 2.0 * c),
            points: uniform_points,
        });
    }
    curves.extend(punch(report, a));
    curves.extend(crate::adaptive_curved::lame(report, a));
    curves.extend(crate::adaptive_curved::hertz(report, a));
    curves.extend(corner(report, a));
    figure(
        report,
        a,
        "adaptive_error_time.svg",
        "Seed scene: compliance error against run time",
        "time [s]",
        "|compliance error|",
        &curves,
        "The compliance's error against run time, adaptive and uniform",
    );
}

/// One adaptive solve of the seed scene, measured.
struct AdaptRun {
    /// The outputs on the adapted mesh.
    result: TwoBlocksResult,
    unknowns: usize,
    cycles: usize,
    /// The last estimate.
    estimate: f64,
    /// The whole adaptive solve.
    seconds: f64,
    /// The last cycle's solve and estimate: the least any adaptive
    /// strategy that ends on this mesh and certifies it pays.
    final_solve: f64,
}

/// The adaptive solve to `tol`.
fn adapt_run(c: f64, tol: f64) -> tfem::Result<AdaptRun> {
    let mut s = TwoBlocks {
        c,
        mesh_size: 1.0 / 16.0,
        ..Default::default()
    }
    .build()?;
    s.model.set_threads(1)?;
    let options = AdaptOptions {
        tolerance: tol,
        goal: Goal::Compliance,
        ..Default::default()
    };
    let t0 = Instant::now();
    let r = s.model.solve_adaptive(&options)?;
    let seconds = t0.elapsed().as_secs_f64();
    let last = r.cycles.last().copied().expect("a cycle");
    let result = s.measure(s.model.contact_report()?.clone())?;
    Ok(AdaptRun {
        result,
        unknowns: last.unknowns,
        cycles: r.cycles.len(),
        estimate: last.estimate,
        seconds,
        final_solve: last.seconds,
    })
}

fn uniform_run(c: f64, h: f64) -> tfem::Result<(TwoBlocksResult, usize, f64)> {
    let mut s = TwoBlocks {
        c,
        mesh_size: h,
        ..Default::default()
    }
    .build()?;
    s.model.set_threads(1)?;
    let t0 = Instant::now();
    let r = s.solve(&ContactOptions::default())?;
    let unknowns = r.report.info.unknowns;
    Ok((r, unknowns, t0.elapsed().as_secs_f64()))
}

/// For each adaptive point, what uniform refinement would take to reach
/// its error: the uniform points' first-order fit of error against time
/// (error ∝ t^(−s)), extrapolated where the runs do not reach; and the
/// ratio's ceiling, uniform's time over one solve of the adapted mesh.
fn speedup(
    report: &mut String,
    adaptive: &[(f64, f64)],
    final_solves: &[f64],
    uniform: &[(f64, f64)],
) {
    if uniform.len() < 2 {
        writeln!(report).unwrap();
        return;
    }
    let (t0, e0) = uniform[uniform.len() - 2];
    let (t1, e1) = uniform[uniform.len() - 1];
    let slope = (e1 / e0).ln() / (t1 / t0).ln();
    let line: Vec<String> = adaptive
        .iter()
        .zip(final_solves)
        .map(|(&(t, e), &alone)| {
            let needed = t1 * (e / e1).powf(1.0 / slope);
            format!(
                "{e:.1e} in {t:.3} s (uniform: ~{needed:.3e} s, {:.0}×; the last cycle alone \
                 {alone:.3} s: a ceiling of {:.0}×)",
                needed / t,
                needed / alone
            )
        })
        .collect();
    writeln!(
        report,
        "Uniform's compliance error falls as time^{slope:.2}; at the adaptive runs' errors it would take: {}.\n",
        line.join("; ")
    )
    .unwrap();
}

/// The targets on the seed scene — compliance and v_top to 1e-4,
/// gap_edge and ℓc inside the reference's error bars — the first adaptive
/// run that meets them all, and what uniform refinement would take to:
/// each quantity's error against time fitted through the last two uniform
/// runs (error ∝ t^(−s)), the slowest quantity setting the time.
fn targets(
    report: &mut String,
    case: &Value,
    adaptive: &[(f64, f64, [f64; 4])],
    uniform: &[(f64, [f64; 4])],
) {
    let bar = |k: &str| {
        case[k]["err"].as_f64().unwrap_or(f64::NAN)
            / case[k]["value"].as_f64().unwrap_or(f64::NAN).abs()
    };
    let goal = [1e-4, 1e-4, bar("gap_edge"), bar("lc")];
    let names = ["compliance", "v_top", "gap_edge", "ℓc"];
    let met = |e: &[f64; 4]| (0..4).all(|k| e[k].abs() <= goal[k]);
    let Some(&(tol, t, _)) = adaptive.iter().find(|(_, _, e)| met(e)) else {
        writeln!(report, "Targets (compliance and v_top to 1e-4, gap_edge and ℓc inside the reference's bars, {:.1e} and {:.1e}): not all met by the finest adaptive run.\n", goal[2], goal[3]).unwrap();
        return;
    };
    let [.., (t0, e0), (t1, e1)] = uniform else {
        return;
    };
    let needed: Vec<(f64, &str)> = (0..4)
        .map(|k| {
            let (a, b) = (e0[k].abs(), e1[k].abs());
            if b <= goal[k] {
                return (*t1, names[k]);
            }
            let slope = (b / a).ln() / (t1 / t0).ln();
            // A quantity whose error does not fall along the last two runs
            // is not reached by extrapolation.
            let time = if slope < 0.0 {
                t1 * (goal[k] / b).powf(1.0 / slope)
            } else {
                f64::INFINITY
            };
            (time, names[k])
        })
        .collect();
    let (slowest, name) = needed
        .iter()
        .copied()
        .fold((0.0, ""), |m, x| if x.0 > m.0 { x } else { m });
    writeln!(
        report,
        "Targets (compliance and v_top to 1e-4, gap_edge and ℓc inside the reference's bars, {:.1e} and {:.1e}): all four met first by the adaptive run to {tol:.0e}, in {t:.3} s; uniform refinement would need ~{slowest:.3e} s ({name} the slowest, each quantity's error extrapolated along the last two uniform runs): {:.0}×.\n",
        goal[2],
        goal[3],
        slowest / t
    )
    .unwrap();
}

/// CalculiX's uniform CPE4 runs of the seed scene (scripts/calculix/
/// results.jsonl, measured by scripts/calculix/table.sh: one thread, ccx's
/// wall time) beside the adaptive runs at equal compliance error: its
/// error and time fitted as a power of h through its runs, read at the
/// adaptive errors (an extrapolation beyond its finest run, said so).
fn calculix(report: &mut String, adaptive: &[(f64, f64)], case: &Value) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scripts/calculix/results.jsonl"
    );
    let Ok(text) = std::fs::read_to_string(path) else {
        return;
    };
    let exact = case["compliance"]["value"].as_f64().unwrap_or(f64::NAN);
    let mut runs: Vec<(f64, f64, f64)> = text
        .lines()
        .filter_map(|l| serde_json::from_str::<Value>(l).ok())
        .filter(|d| d["label"] == "cpe4" && d["mu"].as_f64() == Some(0.0))
        .filter_map(|d| {
            let h = d["h"].as_f64()?;
            let e = (d["compliance"].as_f64()? - exact).abs() / exact;
            Some((h, e, d["time_s"].as_f64()?))
        })
        .collect();
    runs.sort_by(|a, b| b.0.total_cmp(&a.0));
    if runs.len() < 2 {
        return;
    }
    let (a, b) = (runs[0], runs[runs.len() - 1]);
    let error_order = (b.1 / a.1).ln() / (b.0 / a.0).ln();
    let time_order = (b.2 / a.2).ln() / (b.0 / a.0).ln();
    let listed: Vec<String> = runs
        .iter()
        .map(|r| format!("h = 1/{:.0}: {:.2e} in {:.2} s", 1.0 / r.0, r.1, r.2))
        .collect();
    let at: Vec<String> = adaptive
        .iter()
        .map(|&(t, e)| {
            let h = b.0 * (e / b.1).powf(1.0 / error_order);
            let time = b.2 * (h / b.0).powf(time_order);
            let beyond = if h < b.0 { ", extrapolated" } else { "" };
            format!(
                "{e:.1e}: CalculiX h ≈ 1/{:.0}, ~{time:.3e} s{beyond}; tfem {t:.3} s ({:.0}×)",
                1.0 / h,
                time / t
            )
        })
        .collect();
    writeln!(
        report,
        "CalculiX 2.20, uniform CPE4 with its node-to-surface penalty contact (docs/calculix.md; its runs: {}): \
         its compliance error falls as h^{error_order:.2} and its time grows as h^{time_order:.2}. At the \
         adaptive runs' errors: {}. (CalculiX's time is ccx's wall time with its deck already written; \
         tfem's is the adaptive solve in the process, one thread.)\n",
        listed.join(", "),
        at.join("; ")
    )
    .unwrap();
}

/// The rigid flat cylindrical punch (axisymmetric, `scenes::sphere`):
/// adapted from h = a/4 beside the scene's mesh graded by hand towards the
/// punch's edge; P against Boussinesq's 2aE*δ.
fn punch(report: &mut String, a: &Args) -> Vec<Curve> {
    use tfem::scenes::sphere::CylindricalPunch;
    writeln!(
        report,
        "### A rigid flat cylindrical punch (axisymmetric)\n\nBoussinesq: P = 2aE*δ; a block of 500a (refined, P levels off \
         near +1.6e-3: the finite block's share, as we read it; a 40a block adds 1.4 %). *Adaptive*: from h = a/4, tolerance on the energy's relative error. \
         *Graded*: the scene's own mesh, h under the punch and graded by hand towards its edge.\n\n\
         | run | unknowns | cycles | estimate | time [s] | P | p(r), r ≤ 0.8a |\n|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let tolerances: &[f64] = if a.quick {
        &[0.1, 0.05]
    } else {
        &[0.1, 0.05, 0.03, 0.02]
    };
    let (mut adaptive, mut graded) = (Vec::new(), Vec::new());
    for &tol in tolerances {
        let p = CylindricalPunch {
            mesh_size: 0.25,
            ..Default::default()
        };
        let t0 = Instant::now();
        let run = p.build().and_then(|mut scene| {
            scene.model.set_threads(1)?;
            let options = AdaptOptions {
                tolerance: tol,
                ..Default::default()
            };
            let r = scene.model.solve_adaptive(&options)?;
            let m = scene.measure(&p, scene.model.contact_report()?.clone())?;
            Ok((r, m))
        });
        let t = t0.elapsed().as_secs_f64();
        match run {
            Ok((r, m)) => {
                let last = r.cycles.last().copied().expect("a cycle");
                let e = m.force / m.force_exact - 1.0;
                writeln!(
                    report,
                    "| adaptive, tol {tol} | {} | {} | {:.2e} | {t:.3} | {e:+.2e} | {:.2e} |",
                    last.unknowns,
                    r.cycles.len(),
                    last.estimate,
                    m.pressure_error
                )
                .unwrap();
                adaptive.push((t, e.abs()));
            }
            Err(e) => writeln!(report, "| adaptive, tol {tol} | {} |", failure(&e)).unwrap(),
        }
    }
    for k in [8.0, 16.0, 32.0] {
        let p = CylindricalPunch {
            mesh_size: 1.0 / k,
            ..Default::default()
        };
        let t0 = Instant::now();
        let run = p.build().and_then(|mut scene| {
            scene.model.set_threads(1)?;
            let m = scene.solve(&p, &ContactOptions::default())?;
            let est = scene.model.error_estimate()?.relative();
            Ok((m, est))
        });
        let t = t0.elapsed().as_secs_f64();
        match run {
            Ok((m, est)) => {
                let e = m.force / m.force_exact - 1.0;
                writeln!(
                    report,
                    "| graded, a/{k} | {} | 1 | {est:.2e} | {t:.3} | {e:+.2e} | {:.2e} |",
                    m.report.info.unknowns, m.pressure_error
                )
                .unwrap();
                graded.push((t, e.abs()));
            }
            Err(e) => writeln!(report, "| graded, a/{k} | {} |", failure(&e)).unwrap(),
        }
    }
    writeln!(
        report,
        "\nThe adapted interfaces are non-matching (each side refines on its own): the nodal pressure reads to ~1 % \
         there, against 3.6e-3 on the graded matching one.\n"
    )
    .unwrap();
    vec![
        Curve {
            label: "punch P, adaptive".to_string(),
            points: adaptive,
        },
        Curve {
            label: "punch P, graded".to_string(),
            points: graded,
        },
    ]
}

/// The manufactured corner singularity (`scenes::corner`): energy error
/// and the estimate, uniform beside adaptive.
fn corner(report: &mut String, a: &Args) -> Vec<Curve> {
    use tfem::scenes::corner::{CornerRun, adapt, l_shape, solve};
    writeln!(
        report,
        "### A re-entrant corner (manufactured)\n\nThe L-shape [−1, 1]² without a quadrant, u = ∇(r^(4/3) sin(4θ/3)), \
         an exact elasticity solution with no body force, singular at the corner (∇u ~ r^(−2/3)); u prescribed on \
         the boundary, the new boundary nodes given the exact u. Energy error against the exact gradient, and \
         the estimate's effectivity; time: that cycle's solve and estimate.\n\n| run | unknowns | time [s] | energy error | effectivity |\n|---|---|---|---|---|"
    )
    .unwrap();
    let (levels, max): (&[usize], usize) = if a.quick {
        (&[4, 8, 16, 32], 6_000)
    } else {
        (&[4, 8, 16, 32, 64, 128, 256], 1_000_000)
    };
    let rows = |name: &str, runs: &[&CornerRun], report: &mut String| -> Vec<(f64, f64)> {
        let mut points = Vec::new();
        for r in runs {
            writeln!(
                report,
                "| {name} | {} | {:.3} | {:.3e} | {:.3} |",
                r.unknowns,
                r.seconds,
                r.error,
                r.estimate / r.error
            )
            .unwrap();
            points.push((r.unknowns as f64, r.error));
        }
        points
    };
    let uniform: Vec<CornerRun> = levels
        .iter()
        .filter_map(|&n| l_shape(n).build().and_then(solve).ok())
        .collect();
    let adapted = adapt(4, max).unwrap_or_default();
    let shown: Vec<&CornerRun> = adapted.iter().step_by(4).collect();
    let u = rows("uniform", &uniform.iter().collect::<Vec<_>>(), report);
    let ad = rows("adaptive", &shown, report);
    let order = |p: &[(f64, f64)]| {
        let n: Vec<f64> = p.iter().map(|q| q.0).collect();
        let e: Vec<f64> = p.iter().map(|q| q.1).collect();
        -fitted_rate(&n, &e)
    };
    writeln!(
        report,
        "\nEnergy error against unknowns: uniform N^-{:.2} (h^(1/3) expected), adaptive N^-{:.2} (N^(−1/2), the \
         order of smooth solutions).\n",
        order(&u),
        order(&ad[ad.len().saturating_sub(4)..])
    )
    .unwrap();
    let to_time = |runs: &[CornerRun]| {
        runs.iter()
            .map(|r| (r.seconds.max(1e-6), r.error))
            .collect()
    };
    vec![
        Curve {
            label: "corner, uniform (energy)".to_string(),
            points: to_time(&uniform),
        },
        Curve {
            // Every cycle up to this one counts.
            label: "corner, adaptive (energy)".to_string(),
            points: adapted
                .iter()
                .scan(0.0, |t, r| {
                    *t += r.seconds;
                    Some((t.max(1e-6), r.error))
                })
                .collect(),
        },
    ]
}
