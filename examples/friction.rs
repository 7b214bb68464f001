//! Coulomb friction on the seed scene (docs/method.md §6.15): the outputs
//! against h for several μ, one step against 4 and 10, a load–unload path,
//! the independent frictional oracle on the same mesh, the cost of a
//! 100-step history against one solve, and the stability rows (μ from 1e-6
//! to 1e6, stiffness contrasts to 1e9, 1000 tiny steps).
//!
//! `cargo run --release --features studies --example friction -- [--cost-h H…]`
//! (the cost table at element sizes H; default 1/256).

use std::time::Instant;

use tfem::oracle::frictional::{FrictionalOracle, LoadCase};
use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TwoBlocks, TwoBlocksResult};
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, Result};

fn scene(c: f64, h: f64, mu: f64) -> TwoBlocks {
    TwoBlocks {
        c,
        mesh_size: h,
        mu,
        ..TwoBlocks::default()
    }
}

/// One solve (or `steps` proportional steps): the outputs, time, and
/// factorisations.
fn run(s: TwoBlocks, steps: usize) -> Result<(TwoBlocksResult, f64, usize)> {
    let mut sc = s.build()?;
    let t0 = Instant::now();
    let options = ContactOptions::default();
    let (r, f) = if steps == 1 {
        let r = sc.solve(&options)?;
        let f = r.report.info.factorizations;
        (r, f)
    } else {
        let mut f = 0;
        let mut last = None;
        for k in 1..=steps {
            let rep = sc.model.step(k as f64 / steps as f64, &options)?;
            f += rep.info.factorizations;
            last = Some(rep);
        }
        (sc.measure(last.expect("a step"))?, f)
    };
    Ok((r, t0.elapsed().as_secs_f64(), f))
}

/// Steps to p, 2p and back to p: the outputs, the dissipation of the last
/// step, and the factorisations.
fn load_unload(s: TwoBlocks) -> Result<(TwoBlocksResult, f64, usize)> {
    let mut sc = s.build()?;
    let options = ContactOptions::default();
    let mut f = 0;
    let mut last = None;
    for t in [1.0, 2.0, 1.0] {
        let rep = sc.model.step(t, &options)?;
        f += rep.info.factorizations;
        last = Some(rep);
    }
    let r = sc.measure(last.expect("a step"))?;
    let d: f64 = sc.model.contact_dissipation()?.iter().sum();
    Ok((r, d, f))
}

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let cost_h: Vec<f64> = match args.iter().position(|a| a == "--cost-h") {
        Some(i) => args[i + 1..]
            .iter()
            .filter_map(|a| a.parse::<f64>().ok())
            .collect(),
        None => vec![1.0 / 256.0],
    };

    println!("## The seed scene with friction: outputs against h\n");
    println!(
        "| 2C/L | μ | h | gap_edge | v_top | compliance | ℓc | stick_length | slip_edge | max_shear | iterations | time [s] |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    let hs = [1.0 / 16.0, 1.0 / 32.0, 1.0 / 64.0, 1.0 / 128.0, 1.0 / 256.0];
    let mut rates = Vec::new();
    for (c, mu) in [(0.2, 0.1), (0.2, 0.3), (0.2, 1.0), (0.1, 0.3)] {
        let mut outs = Vec::new();
        for &h in &hs {
            let (r, t, _) = run(scene(c, h, mu), 1)?;
            println!(
                "| {} | {mu} | 1/{:.0} | {:.6e} | {:.6e} | {:.6e} | {:.4} | {:.4} | {:.6e} | {:.4e} | {} | {t:.2} |",
                2.0 * c,
                1.0 / h,
                r.gap_edge,
                r.v_top,
                r.compliance,
                r.lc,
                r.stick_length,
                r.slip_edge,
                r.max_shear,
                r.report.iterations
            );
            outs.push([r.gap_edge, r.v_top, r.compliance, r.slip_edge]);
        }
        let rate = |q: usize| {
            let d: Vec<f64> = outs.windows(2).map(|w| (w[1][q] - w[0][q]).abs()).collect();
            fitted_rate(&hs[1..], &d)
        };
        rates.push((c, mu, [rate(0), rate(1), rate(2), rate(3)]));
    }
    println!("\nRates of the differences of successive halvings (h = 1/16 … 1/256):\n");
    println!("| 2C/L | μ | gap_edge | v_top | compliance | slip_edge |");
    println!("|---|---|---|---|---|---|");
    for (c, mu, r) in &rates {
        println!(
            "| {} | {mu} | {:.2} | {:.2} | {:.2} | {:.2} |",
            2.0 * c,
            r[0],
            r[1],
            r[2],
            r[3]
        );
    }

    println!(
        "\n## One step against 4 and 10 proportional steps, and a load–unload path (h = 1/64)\n"
    );
    println!("| 2C/L | μ | path | gap_edge | slip_edge | stick_length | factorisations |");
    println!("|---|---|---|---|---|---|---|");
    for (c, mu) in [(0.2, 0.1), (0.2, 0.3), (0.2, 1.0), (0.1, 0.3)] {
        for steps in [1, 4, 10] {
            let (r, _, f) = run(scene(c, 1.0 / 64.0, mu), steps)?;
            println!(
                "| {} | {mu} | {steps} step(s) to p | {:.9e} | {:.9e} | {:.4} | {f} |",
                2.0 * c,
                r.gap_edge,
                r.slip_edge,
                r.stick_length
            );
        }
        match load_unload(scene(c, 1.0 / 64.0, mu)) {
            Ok((r, d, f)) => println!(
                "| {} | {mu} | p, 2p, back to p (last step dissipates {d:.3e} J/m) | {:.9e} | {:.9e} | {:.4} | {f} |",
                2.0 * c,
                r.gap_edge,
                r.slip_edge,
                r.stick_length
            ),
            Err(e) => println!(
                "| {} | {mu} | p, 2p, back to p: {:?} ({}) | | | | |",
                2.0 * c,
                e.status(),
                e.message().split(';').next().unwrap_or("")
            ),
        }
    }

    println!("\n## TFEM against the frictional oracle on the same mesh (2C/L = 0.4)\n");
    println!(
        "| μ | h | slip_edge TFEM | slip_edge oracle | rel. diff | gap_edge rel. diff | oracle stick/slip pairs |"
    );
    println!("|---|---|---|---|---|---|---|");
    for mu in [0.1, 0.3, 1.0] {
        for h in [1.0 / 16.0, 1.0 / 32.0, 1.0 / 64.0] {
            let mut sc = scene(0.2, h, mu).build()?;
            let oracle = FrictionalOracle::new(&sc.model, TAG_CONTACT_LOWER, TAG_CONTACT_UPPER)?;
            let step = oracle.step(mu, None, &LoadCase::of(&sc.model)?)?;
            let r = sc.solve(&ContactOptions::default())?;
            let (lo, up) = (sc.corner_lower, sc.corner_upper);
            let slip = step.u[2 * up] - step.u[2 * lo];
            let gap = step.u[2 * up + 1] - step.u[2 * lo + 1];
            let [_, stick, slipping] = step.counts();
            println!(
                "| {mu} | 1/{:.0} | {:.6e} | {slip:.6e} | {:.2e} | {:.2e} | {stick}/{slipping} |",
                1.0 / h,
                r.slip_edge,
                (r.slip_edge - slip) / slip,
                (r.gap_edge - gap) / gap
            );
        }
    }

    println!("\n## Cost: 100 proportional steps against one solve (2C/L = 0.4)\n");
    println!(
        "| μ | h | unknowns | one solve [s] | 100 steps [s] | ratio | factorisations | iterations (one solve) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for &h in &cost_h {
        for mu in [0.0, 0.3] {
            let rows = run(scene(0.2, h, mu), 1)
                .and_then(|one| run(scene(0.2, h, mu), 100).map(|many| (one, many)));
            match rows {
                Ok(((r1, t1, _), (_, t100, f))) => println!(
                    "| {mu} | 1/{:.0} | {} | {t1:.3} | {t100:.3} | {:.2}× | {f} | {} |",
                    1.0 / h,
                    r1.report.info.unknowns,
                    t100 / t1,
                    r1.report.iterations
                ),
                Err(e) => println!(
                    "| {mu} | 1/{:.0} | {:?}: {} | | | | | |",
                    1.0 / h,
                    e.status(),
                    e.message().split(';').next().unwrap_or("")
                ),
            }
        }
    }

    println!("\n## Stability (h = 1/32, 2C/L = 0.4): every case a clear status\n");
    println!("| case | status | iterations | slip_edge | stick_length |");
    println!("|---|---|---|---|---|");
    let row = |name: String, s: TwoBlocks, steps: usize| match run(s, steps) {
        Ok((r, _, _)) => println!(
            "| {name} | OK | {} | {:.6e} | {:.4} |",
            r.report.iterations, r.slip_edge, r.stick_length
        ),
        Err(e) => println!("| {name} | {:?}: {} | | | |", e.status(), e.message()),
    };
    for mu in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
        row(format!("μ = {mu:e}"), scene(0.2, 1.0 / 32.0, mu), 1);
    }
    for ratio in [1e3, 1e6, 1e9] {
        let s = TwoBlocks {
            e2: 1e10 * ratio,
            ..scene(0.2, 1.0 / 32.0, 0.3)
        };
        row(format!("E2/E1 = {ratio:e}, μ = 0.3"), s, 1);
    }
    row(
        "1000 steps of 1/1000, μ = 0.3".to_string(),
        scene(0.2, 1.0 / 32.0, 0.3),
        1000,
    );
    Ok(())
}
