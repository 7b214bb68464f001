//! Coulomb friction on the seed scene.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::failure;

/// A seed-scene run for the friction and CalculiX sections.
pub(crate) struct SeedRun {
    pub(crate) result: tfem::scenes::TwoBlocksResult,
    /// Build and solve (every step), seconds.
    pub(crate) seconds: f64,
    pub(crate) factorizations: usize,
    /// Active-set iterations summed over the steps.
    pub(crate) iterations: usize,
}

/// The seed scene built and loaded in `steps` proportional steps (1: one
/// contact solve). A failed step is reported with its index.
pub(crate) fn seed_steps(scene: TwoBlocks, steps: usize) -> Result<SeedRun, String> {
    let t0 = Instant::now();
    let mut sc = scene.build().map_err(|e| failure(&e))?;
    let options = ContactOptions::default();
    if steps == 1 {
        let result = sc.solve(&options).map_err(|e| failure(&e))?;
        return Ok(SeedRun {
            seconds: t0.elapsed().as_secs_f64(),
            factorizations: result.report.info.factorizations,
            iterations: result.report.iterations,
            result,
        });
    }
    let (mut factorizations, mut iterations, mut last) = (0, 0, None);
    for k in 1..=steps {
        let rep = sc
            .model
            .step(k as f64 / steps as f64, &options)
            .map_err(|e| {
                format!(
                    "step {k}/{steps} (after {:.1} s): {}",
                    t0.elapsed().as_secs_f64(),
                    failure(&e)
                )
            })?;
        factorizations += rep.info.factorizations;
        iterations += rep.iterations;
        last = Some(rep);
    }
    let result = sc.measure(last.expect("a step")).map_err(|e| failure(&e))?;
    Ok(SeedRun {
        seconds: t0.elapsed().as_secs_f64(),
        factorizations,
        iterations,
        result,
    })
}

/// Issue 20: Coulomb friction on the seed scene — outputs against h, the
/// independent frictional oracle, proportional steps, and the cost of a
/// history.
pub(crate) fn friction(report: &mut String, a: &Args) {
    use tfem::oracle::frictional::{FrictionalOracle, LoadCase};
    use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER};
    let scene = |c: f64, h: f64, mu: f64| TwoBlocks {
        c,
        mesh_size: h,
        mu,
        ..TwoBlocks::default()
    };
    let levels: Vec<usize> = if a.quick {
        vec![16, 32, 64, 128]
    } else {
        vec![16, 32, 64, 128, 256]
    };
    writeln!(
        report,
        "## Coulomb friction on the seed scene\n\n\
         The seed scene (docs/method.md §4, §6.15) with a Coulomb interface of coefficient μ, one \
         contact solve of the full load. Outputs: *gap_edge* and *slip_edge*, v and u_x of the \
         upper body minus the lower at the corner (0, 0); *v_top*, v at (L/2, H2); *stick*, the \
         length of the contact zone that sticks. No closed form exists: the outputs' rates are \
         those of the differences of successive halvings, and the method is compared below with \
         an independent exact frictional solver on the same mesh.\n\n\
         | 2C/L | μ | h | unknowns | iterations | time [s] | gap_edge [m] | slip_edge [m] | v_top [m] | stick [m] |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let cases = [(0.2, 0.1), (0.2, 0.3), (0.2, 1.0), (0.1, 0.3)];
    let mut rates = Vec::new();
    for (c, mu) in cases {
        let (mut hs, mut outs) = (vec![], vec![]);
        for &n in &levels {
            match seed_steps(scene(c, 1.0 / n as f64, mu), 1) {
                Ok(run) => {
                    let r = &run.result;
                    writeln!(
                        report,
                        "| {} | {mu} | 1/{n} | {} | {} | {:.3} | {:.6e} | {:.6e} | {:.6e} | {:.4} |",
                        2.0 * c,
                        r.report.info.unknowns,
                        r.report.iterations,
                        run.seconds,
                        r.gap_edge,
                        r.slip_edge,
                        r.v_top,
                        r.stick_length
                    )
                    .unwrap();
                    hs.push(1.0 / n as f64);
                    outs.push([r.gap_edge, r.slip_edge, r.v_top, r.stick_length]);
                }
                Err(e) => {
                    writeln!(report, "| {} | {mu} | 1/{n} | {e} | | | | | | |", 2.0 * c).unwrap()
                }
            }
        }
        if outs.len() >= 3 {
            let rate = |q: usize| {
                let d: Vec<f64> = outs
                    .windows(2)
                    .map(|w| (w[1][q] - w[0][q]).abs().max(1e-300))
                    .collect();
                fitted_rate(&hs[1..], &d)
            };
            rates.push(format!(
                "| {} | {mu} | {:.2} | {:.2} | {:.2} | {:.2} |",
                2.0 * c,
                rate(0),
                rate(1),
                rate(2),
                rate(3)
            ));
        }
    }
    writeln!(
        report,
        "\nRates of the differences of successive halvings, fitted in h (a stick length moves by \
         whole interface nodes, so its differences are not smooth in h):\n\n\
         | 2C/L | μ | gap_edge | slip_edge | v_top | stick |\n|---|---|---|---|---|---|\n{}\n",
        rates.join("\n")
    )
    .unwrap();

    let oracle_levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128]
    };
    writeln!(
        report,
        "### Against the independent frictional oracle (2C/L = 0.4)\n\n\
         `tfem::oracle::frictional`: node-to-node multipliers on the same mesh's interface pairs, \
         a primal-dual active set on open/stick/slip, no TFEM element at all. Relative \
         differences (TFEM − oracle)/oracle; the two discretise the interface differently, so \
         the differences should fall with h.\n\n\
         | μ | h | slip_edge TFEM | slip_edge oracle | slip_edge diff | gap_edge diff | v_top diff | TFEM [s] | oracle [s] | oracle stick / slip pairs |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut oracle_rates = Vec::new();
    for mu in [0.1, 0.3, 1.0] {
        let (mut hs, mut ds) = (vec![], vec![]);
        for &n in &oracle_levels {
            let s = scene(0.2, 1.0 / n as f64, mu);
            let run = (|| -> Result<_, String> {
                let sc = s.build().map_err(|e| failure(&e))?;
                let t0 = Instant::now();
                let oracle = FrictionalOracle::new(&sc.model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)
                    .map_err(|e| failure(&e))?;
                let load = LoadCase::of(&sc.model).map_err(|e| failure(&e))?;
                let step = oracle
                    .step(mu, None, &load)
                    .map_err(|e| format!("oracle {}", failure(&e)))?;
                let t_oracle = t0.elapsed().as_secs_f64();
                let tfem_run = seed_steps(s, 1)?;
                let (lo, up, top) = (sc.corner_lower, sc.corner_upper, sc.top_center);
                Ok((step, tfem_run, t_oracle, lo, up, top))
            })();
            match run {
                Ok((step, t, t_oracle, lo, up, top)) => {
                    let slip = step.u[2 * up] - step.u[2 * lo];
                    let gap = step.u[2 * up + 1] - step.u[2 * lo + 1];
                    let v_top = step.u[2 * top + 1];
                    let r = &t.result;
                    let [_, stick, slipping] = step.counts();
                    let ds_slip = (r.slip_edge - slip) / slip;
                    writeln!(
                        report,
                        "| {mu} | 1/{n} | {:.6e} | {slip:.6e} | {ds_slip:+.2e} | {:+.2e} | {:+.2e} | {:.3} | {t_oracle:.3} | {stick} / {slipping} |",
                        r.slip_edge,
                        (r.gap_edge - gap) / gap,
                        (r.v_top - v_top) / v_top,
                        t.seconds
                    )
                    .unwrap();
                    hs.push(1.0 / n as f64);
                    ds.push(ds_slip.abs());
                }
                Err(e) => writeln!(report, "| {mu} | 1/{n} | {e} | | | | | | | |").unwrap(),
            }
        }
        if hs.len() >= 2 {
            oracle_rates.push(format!("μ = {mu}: {:.2}", fitted_rate(&hs, &ds)));
        }
    }
    writeln!(
        report,
        "\nFitted rate of the slip_edge difference in h: {}.\n",
        oracle_rates.join(", ")
    )
    .unwrap();

    let n_steps = if a.quick { 32 } else { 64 };
    writeln!(
        report,
        "### One step against 4 and 10 proportional steps (h = 1/{n_steps})\n\n\
         Under proportional loading a Coulomb interface's final state does not depend on the \
         number of steps (`Model::step` with factors k/N, each step starting from the state \
         before): the difference is measured, the largest relative change of gap_edge, slip_edge \
         and v_top against the one-step solve.\n\n\
         | 2C/L | μ | steps | gap_edge [m] | slip_edge [m] | stick [m] | max rel. diff to 1 step | iterations (all steps) | factorisations | time [s] |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (c, mu) in cases {
        let mut one: Option<[f64; 3]> = None;
        for steps in [1, 4, 10] {
            match seed_steps(scene(c, 1.0 / n_steps as f64, mu), steps) {
                Ok(run) => {
                    let r = &run.result;
                    let q = [r.gap_edge, r.slip_edge, r.v_top];
                    let diff = one.map_or("–".to_string(), |o| {
                        format!(
                            "{:.1e}",
                            o.iter()
                                .zip(&q)
                                .map(|(x, y)| ((y - x) / x).abs())
                                .fold(0.0f64, f64::max)
                        )
                    });
                    if steps == 1 {
                        one = Some(q);
                    }
                    writeln!(
                        report,
                        "| {} | {mu} | {steps} | {:.9e} | {:.9e} | {:.4} | {diff} | {} | {} | {:.3} |",
                        2.0 * c,
                        r.gap_edge,
                        r.slip_edge,
                        r.stick_length,
                        run.iterations,
                        run.factorizations,
                        run.seconds
                    )
                    .unwrap();
                }
                Err(e) => {
                    writeln!(report, "| {} | {mu} | {steps} | {e} | | | | | | |", 2.0 * c).unwrap()
                }
            }
        }
    }

    let cost_levels: Vec<usize> = if a.quick {
        vec![128]
    } else {
        vec![256, 512, 1024]
    };
    writeln!(
        report,
        "\n### Cost of a 100-step history (2C/L = 0.4)\n\n\
         100 proportional steps against one contact solve of the full load, both including the \
         build, in this process; frictionless beside μ = 0.3. A run that fails says so with its \
         status (and the step it failed at).\n\n\
         | μ | h | unknowns | one solve [s] | iterations | 100 steps [s] | iterations (all steps) | factorisations | 100 steps / one solve |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for &n in &cost_levels {
        for mu in [0.0, 0.3] {
            let one = seed_steps(scene(0.2, 1.0 / n as f64, mu), 1);
            let many = seed_steps(scene(0.2, 1.0 / n as f64, mu), 100);
            let unknowns = match (&one, &many) {
                (Ok(r), _) | (_, Ok(r)) => r.result.report.info.unknowns.to_string(),
                _ => "–".into(),
            };
            let cell = |r: &Result<SeedRun, String>| match r {
                Ok(r) => (format!("{:.3}", r.seconds), r.iterations.to_string()),
                Err(e) => (e.clone(), "–".into()),
            };
            let ((t1, i1), (t100, i100)) = (cell(&one), cell(&many));
            let (f, ratio) = match (&one, &many) {
                (Ok(o), Ok(m)) => (
                    m.factorizations.to_string(),
                    format!("{:.2}×", m.seconds / o.seconds),
                ),
                (_, Ok(m)) => (m.factorizations.to_string(), "–".into()),
                _ => ("–".into(), "–".into()),
            };
            writeln!(
                report,
                "| {mu} | 1/{n} | {unknowns} | {t1} | {i1} | {t100} | {i100} | {f} | {ratio} |"
            )
            .unwrap();
        }
    }
    writeln!(report).unwrap();
}
