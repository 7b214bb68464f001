//! Speed and memory of the seed scene in 3D through the product's
//! `SolidModel`, each size in its own process so that its peak memory is
//! its own: the phases, fill and peak memory per unknown, one thread
//! against two, and CalculiX side by side at equal accuracy.

use std::fmt::Write as _;

use serde_json::Value;

use tfem::studies::tet_scenes::TwoBlocks3d;

use crate::Args;
use crate::common::peak_rss;
use crate::tetrahedra::extrapolate;

/// `report --seed3d-run N`: solves the 3D seed scene at h = 1/N through
/// [`TwoBlocks3d::solve_model`] and prints one JSON line (threads from
/// `RAYON_NUM_THREADS`, set by the parent).
pub(crate) fn seed3d_run(n: usize) -> ! {
    let load = load_average();
    let scene = TwoBlocks3d {
        h: 1.0 / n as f64,
        ..Default::default()
    };
    let r = scene.solve_model().expect("the 3D seed scene");
    let t = r.timings;
    println!(
        "{}",
        serde_json::json!({
            "unknowns": r.unknowns, "iterations": r.iterations,
            "factorizations": r.factorizations, "factor_nnz": r.factor_nnz,
            "factorization_bytes": r.factorization_bytes,
            "assembly": t.assembly, "analysis": t.analysis, "factorization": t.factorization,
            "solve": t.solve, "total": r.seconds,
            "contact_area": r.contact_area, "gap_corner": r.gap_corner, "v_top": r.v_top,
            "compliance": r.compliance, "transmitted": r.transmitted,
            "switches": r.switches, "threads": rayon_threads(), "rss_peak": peak_rss(), "load_before": load,
        })
    );
    std::process::exit(0)
}

fn rayon_threads() -> usize {
    std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// One run in a child process with `threads` threads (0: the machine's).
fn child(n: usize, threads: usize) -> Option<Value> {
    let mut command = std::process::Command::new(std::env::current_exe().ok()?);
    command.args(["--seed3d-run", &n.to_string()]);
    if threads > 0 {
        command.env("RAYON_NUM_THREADS", threads.to_string());
    }
    let out = command.output().ok()?;
    if !out.status.success() {
        eprintln!(
            "speed_3d: h = 1/{n}: {}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.lines().last()?).ok()
}

/// The 1-minute load average, where Linux gives it.
fn load_average() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    text.split_whitespace().next()?.parse().ok()
}

/// A measured run: its mesh divisor, threads and the child's values.
struct Run {
    n: usize,
    v: Value,
}

impl Run {
    fn f(&self, key: &str) -> f64 {
        self.v[key].as_f64().unwrap_or(f64::NAN)
    }
    fn threads(&self) -> u64 {
        self.v["threads"].as_u64().unwrap_or(0)
    }
}

pub(crate) fn speed_3d(report: &mut String, a: &Args) {
    // (N, threads; 0: the machine's): the machine's threads over the sizes,
    // one thread where CalculiX (one thread) is met at equal accuracy. The
    // grid must fall on the loaded square's edge: N a multiple of 20.
    let plan: &[(usize, usize)] = if a.quick {
        &[(20, 0), (40, 0), (20, 1)]
    } else {
        &[
            (40, 0),
            (60, 0),
            (60, 1),
            (80, 0),
            (80, 1),
            (100, 0),
            (100, 1),
            (120, 0),
        ]
    };
    let runs: Vec<Run> = plan
        .iter()
        .filter_map(|&(n, threads)| {
            let v = child(n, threads);
            if v.is_none() {
                eprintln!("speed_3d: the run at h = 1/{n} failed");
            }
            v.map(|v| Run { n, v })
        })
        .collect();
    writeln!(report, "## Speed and memory in three dimensions\n").unwrap();
    phases(report, &runs);
    memory_fit(report, &runs);
    equal_accuracy(report, &runs);
}

/// The phases of each run and its memory.
fn phases(report: &mut String, runs: &[Run]) {
    writeln!(
        report,
        "The seed scene in 3D (the scene of the tetrahedra section's contact tables) through the \
         product's `SolidModel` (`TwoBlocks3d::solve_model`, what `examples/two_blocks_3d` runs), \
         each size in its own process (`report --seed3d-run N`); nested dissection; seconds summed \
         over the active-set solves, each of which refactorises (the 3D interface is not condensed). \
         *peak factorisation*: what one numeric factorisation holds at its peak (factor values, \
         structure, faer's workspace); *peak RSS*: the whole process's (mesh, model, matrix, \
         factor, results). *switches*: B's tetrahedra the inversion test switched after each solve \
         (of 3 per interface triangle), a bound on the rank of the change from one solve's matrix to \
         the next's; *load before*: the machine's 1-minute load average when the run started.\n\n\
         | h | unknowns | threads | solves | assembly | analysis | factorisations | triangular solves | total [s] | factor entries per unknown | peak factorisation [MB] | peak RSS [MB] | peak RSS per unknown [kB] | switches | load before |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for r in runs {
        let unknowns = r.f("unknowns");
        let switches = (r.v["switches"].as_array().into_iter().flatten())
            .map(|k| k.to_string())
            .collect::<Vec<_>>()
            .join(", ");
        writeln!(
            report,
            "| 1/{} | {} | {} | {} | {:.2} | {:.2} | {:.1} ({:.1} each) | {:.2} | {:.1} | {:.0} | {:.0} | {:.0} | {:.1} | {} | {} |",
            r.n,
            unknowns,
            r.threads(),
            r.v["iterations"],
            r.f("assembly"),
            r.f("analysis"),
            r.f("factorization"),
            r.f("factorization") / r.f("factorizations"),
            r.f("solve"),
            r.f("total"),
            r.f("factor_nnz") / unknowns,
            r.f("factorization_bytes") / 1e6,
            r.f("rss_peak") / 1e6,
            r.f("rss_peak") / unknowns / 1e3,
            switches,
            r.v["load_before"]
                .as_f64()
                .map_or("–".into(), |l| format!("{l:.2}")),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

/// Least-squares slope and intercept of y against x.
fn line_fit(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0, a.1 + p.1));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| (sxy / sxx, my - sxy / sxx * mx))
}

/// The runs on the machine's threads, by size, one per size.
fn machine_runs(runs: &[Run]) -> Vec<&Run> {
    let mut machine: Vec<&Run> = runs.iter().filter(|r| r.threads() != 1).collect();
    machine.sort_by_key(|r| r.n);
    machine.dedup_by_key(|r| r.n);
    machine
}

/// Growth of time, fill and memory with the unknowns (the machine's
/// threads), over every size and between the two largest, and the size at
/// which peak memory reaches 24 GB on the latter, the steeper, trend.
fn memory_fit(report: &mut String, runs: &[Run]) {
    let machine = machine_runs(runs);
    let fit = |runs: &[&Run], key: &str, per_factorisation: bool| {
        let points: Vec<(f64, f64)> = (runs.iter())
            .map(|r| {
                let per = if per_factorisation {
                    r.f("factorizations")
                } else {
                    1.0
                };
                (r.f("unknowns").ln(), (r.f(key) / per).ln())
            })
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        line_fit(&points)
    };
    let largest = &machine[machine.len().saturating_sub(2)..];
    let (Some(nnz), Some(time), Some(rss), Some(time2), Some(rss2), Some(last)) = (
        fit(&machine, "factor_nnz", false),
        fit(&machine, "factorization", true),
        fit(&machine, "rss_peak", false),
        fit(largest, "factorization", true),
        fit(largest, "rss_peak", false),
        machine.last(),
    ) else {
        return;
    };
    let limit = ((24e9f64).ln() - rss2.1) / rss2.0;
    writeln!(
        report,
        "Fitted over the runs on the machine's threads against the unknowns N: factor entries ∝ \
         N^{:.2}, one factorisation's time ∝ N^{:.2}, peak RSS ∝ N^{:.2} (nested dissection on a 3D \
         grid: N^(4/3), N² and N^(4/3) in theory). Between the two largest sizes the growth is \
         steeper: one factorisation ∝ N^{:.2}, peak RSS ∝ N^{:.2}. On that trend the peak RSS \
         reaches 24 GB at about {:.2e} unknowns (h ≈ 1/{:.0}; this scene's meshes exist for h = \
         1/N with N a multiple of 20), where one factorisation would take about {:.0} s.\n",
        nnz.0,
        time.0,
        rss.0,
        time2.0,
        rss2.0,
        limit.exp(),
        last.n as f64 * (limit.exp() / last.f("unknowns")).cbrt(),
        (time2.0 * limit + time2.1).exp(),
    )
    .unwrap();
}

/// CalculiX's converged C3D8 runs (scripts/calculix/seed3d/results.jsonl).
fn calculix_runs() -> Vec<Value> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scripts/calculix/seed3d/results.jsonl"
    );
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut runs: Vec<Value> = (text.lines())
        .filter_map(|l| serde_json::from_str(l).ok())
        .filter(|v: &Value| {
            v["contact"] == "n2s" && v["converged"] != false && v["retimed"] != true
        })
        .collect();
    let h = |v: &Value| v["h"].as_f64().unwrap_or(f64::NAN);
    runs.sort_by(|a, b| h(b).total_cmp(&h(a)));
    runs
}

/// A converged value and its uncertainty: the mean of the two codes'
/// extrapolations from their three finest meshes (tfem's from its runs on
/// the machine's threads), ± half their difference; CalculiX's alone, with
/// a NaN spread, when tfem has no fit.
fn converged(ccx: &[Value], runs: &[Run], key: &str) -> Option<(f64, f64)> {
    let finest = |q: Vec<(f64, f64)>| -> Option<f64> {
        (q.len() >= 3)
            .then(|| extrapolate(&q[q.len() - 3..]))
            .flatten()
            .map(|(value, _)| value)
    };
    let field = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    let theirs = finest(ccx.iter().map(|v| (field(v, "h"), field(v, key))).collect())?;
    let ours = finest(
        (machine_runs(runs).iter())
            .map(|r| (1.0 / r.n as f64, r.f(key)))
            .collect(),
    );
    Some(ours.map_or((theirs, f64::NAN), |ours| {
        (0.5 * (ours + theirs), 0.5 * (ours - theirs).abs())
    }))
}

/// tfem's time at the v_top error `target` on one thread (`one`) or the
/// machine's: the first run, in order of time, at least as accurate,
/// interpolated log-log against the run before it; "≤ t" when that run
/// has no such neighbour, "not reached" when no run is as accurate.
fn time_at_accuracy(runs: &[Run], v_top: f64, target: f64, one: bool) -> String {
    let mut points: Vec<(f64, f64)> = (runs.iter())
        .filter(|r| (r.threads() == 1) == one)
        .map(|r| (r.f("v_top") / v_top - 1.0, r.f("total")))
        .collect();
    points.sort_by(|a, b| a.1.total_cmp(&b.1));
    let Some(k) = points.iter().position(|p| p.0.abs() <= target) else {
        return "not reached".into();
    };
    let (e1, t1) = points[k];
    let bracket = k
        .checked_sub(1)
        .map(|j| points[j])
        .filter(|&(e0, _)| e0.signum() == e1.signum() && e1 != 0.0 && e0.abs() > e1.abs());
    match bracket {
        Some((e0, t0)) => {
            let s = (target / e0.abs()).ln() / (e1 / e0).ln();
            format!("{:.0}", (t0.ln() + s * (t1 / t0).ln()).exp())
        }
        None => format!("≤ {t1:.1}"),
    }
}

/// The error of each code's runs against the converged values, and
/// tfem's time at each CalculiX run's accuracy.
fn equal_accuracy(report: &mut String, runs: &[Run]) {
    let ccx = calculix_runs();
    if ccx.is_empty() || runs.is_empty() {
        return;
    }
    let (Some(v_top), Some(compliance)) = (
        converged(&ccx, runs, "v_top"),
        converged(&ccx, runs, "compliance"),
    ) else {
        return;
    };
    let spread = |(_, spread): (f64, f64)| {
        if spread.is_finite() {
            format!(" ± {spread:.1e}")
        } else {
            " (CalculiX's alone: tfem has no fit)".to_string()
        }
    };
    writeln!(
        report,
        "At equal accuracy against CalculiX (its C3D8 runs of the tetrahedra section, one thread, \
         ccx's wall time measured on a loaded machine). The converged values are the means of the \
         two codes' extrapolations from their three finest meshes (q = q∞ + K h^s; ± half their \
         difference): v_top {:.5e}{} and compliance {:.3}{}. *tfem at \
         CalculiX's accuracy*: the time interpolated, log-log in error, between the two runs of the \
         same thread count that bracket CalculiX's v_top error; *≤ t* when tfem's cheapest run is \
         already as accurate; *not reached* when no run is.\n\n\
         | code | h | unknowns | threads | time [s] | v_top error | compliance error |\n\
         |---|---|---|---|---|---|---|",
        v_top.0,
        spread(v_top),
        compliance.0,
        spread(compliance)
    )
    .unwrap();
    error_rows(report, &ccx, runs, [v_top.0, compliance.0]);
    writeln!(
        report,
        "\n| CalculiX h | its v_top error | CalculiX [s] | tfem at its accuracy, 1 thread [s] | tfem at its accuracy, the machine's threads [s] |\n|---|---|---|---|---|"
    )
    .unwrap();
    for v in &ccx {
        let f = |key: &str| v[key].as_f64().unwrap_or(f64::NAN);
        let error = f("v_top") / v_top.0 - 1.0;
        writeln!(
            report,
            "| 1/{:.0} | {:+.2e} | {:.1} | {} | {} |",
            1.0 / f("h"),
            error,
            f("ccx_seconds"),
            time_at_accuracy(runs, v_top.0, error.abs(), true),
            time_at_accuracy(runs, v_top.0, error.abs(), false),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

/// Each run's v_top and compliance errors against `reference`.
fn error_rows(report: &mut String, ccx: &[Value], runs: &[Run], reference: [f64; 2]) {
    let error = |k: usize, value: f64| value / reference[k] - 1.0;
    for v in ccx {
        let f = |key: &str| v[key].as_f64().unwrap_or(f64::NAN);
        writeln!(
            report,
            "| CalculiX C3D8 | 1/{:.0} | {} | 1 | {:.1} | {:+.2e} | {:+.2e} |",
            1.0 / f("h"),
            v["equations"],
            f("ccx_seconds"),
            error(0, f("v_top")),
            error(1, f("compliance")),
        )
        .unwrap();
    }
    for r in runs {
        writeln!(
            report,
            "| tfem P1 | 1/{} | {} | {} | {:.1} | {:+.2e} | {:+.2e} |",
            r.n,
            r.f("unknowns"),
            r.threads(),
            r.f("total"),
            error(0, r.f("v_top")),
            error(1, r.f("compliance")),
        )
        .unwrap();
    }
}
