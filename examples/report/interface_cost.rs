//! The cost of the contact interface (n_I³) and the switch to refactorisation.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::failure;

/// One contact solve's figures for the interface-cost table.
struct CostRun {
    seconds: f64,
    iterations: usize,
    factorizations: usize,
    interface: usize,
    unknowns: usize,
    nnz: usize,
    memory_mb: f64,
}

fn cost_run(mut model: tfem::Model, refactorize: bool) -> tfem::Result<CostRun> {
    // Thin blocks release their contact zone slowly: room beyond the
    // default cap of 50 iterations (as probes/interface_cost.rs).
    let options = ContactOptions {
        refactorize,
        max_iterations: 400,
        ..Default::default()
    };
    let t = Instant::now();
    let r = model.solve_contact(&options)?;
    Ok(CostRun {
        seconds: t.elapsed().as_secs_f64(),
        iterations: r.iterations,
        factorizations: r.info.factorizations,
        interface: r.info.interface_unknowns,
        unknowns: r.info.unknowns,
        nnz: r.info.matrix_nnz,
        memory_mb: r.info.memory_bytes as f64 / 1e6,
    })
}

/// Seconds of faer's dense Cholesky of an n × n SPD matrix (both cores):
/// one dense refactorisation of an interface of n unknowns.
fn dense_cholesky_seconds(n: usize) -> f64 {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::cholesky::llt::factor::{cholesky_in_place, cholesky_in_place_scratch};
    let mut m = faer::Mat::<f64>::from_fn(n, n, |i, j| {
        if i == j {
            n as f64
        } else {
            1.0 / (1.0 + (i as f64 - j as f64).abs())
        }
    });
    let par = faer::Par::rayon(0);
    let mut mem = MemBuffer::new(cholesky_in_place_scratch::<f64>(n, par, Default::default()));
    let t = Instant::now();
    cholesky_in_place(
        m.as_mut(),
        Default::default(),
        par,
        MemStack::new(&mut mem),
        Default::default(),
    )
    .expect("SPD");
    t.elapsed().as_secs_f64()
}

/// Issue: the condensed interface's n_I³ cost and tfem's automatic switch to
/// refactorisation (probes/interface_cost.rs, one run per row).
pub(crate) fn interface_cost(report: &mut String, a: &Args) {
    use tfem::scenes::stack::{Layer, Pairing, Stack};
    writeln!(
        report,
        "## The cost of the contact interface (n_I³)\n\n\
         The condensed active-set loop (docs/method.md §6.10: a dense interface Schur complement \
         of n_I² entries, n_I³/3 flops per dense refactorisation) against the loop that \
         refactorises the sparse matrix at every iteration (`ContactOptions::refactorize`), on \
         scenes of growing interface size; one run each. *A*: the seed's two blocks, thin \
         (H1 = H2 = L/24) with n_x cells across; *B*: stacks of thin blocks (256 cells across, 16 \
         rows each) under the seed's loading. *default*: the path tfem chose by itself \
         (`Condensed::worthwhile`: dense while n_I ≤ 8192 and n_I² ≤ 4 nnz, else refactorise). \
         n_I: interface nodes' normal unknowns (what the dense loop would carry). Both loops must \
         reach the same active set: the iterations are printed side by side.\n\n\
         | scene | n_I | unknowns | nnz (M) | default | t default [s] | t refactorise [s] | refactorise / default | iterations d / r | factorisations d / r | memory [MB] d / r |\n|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let interface_size = |m: &tfem::Model| -> usize {
        let mut nodes: Vec<usize> = m
            .contact_mesh()
            .map(|b| b.iter().flat_map(|e| e.nodes).collect())
            .unwrap_or_default();
        nodes.sort_unstable();
        nodes.dedup();
        nodes.len()
    };
    let row = |report: &mut String, name: String, build: &dyn Fn() -> tfem::Result<tfem::Model>| {
        let model = match build() {
            Ok(m) => m,
            Err(e) => {
                writeln!(report, "| {name} | {} | | | | | | | | | |", failure(&e)).unwrap();
                return;
            }
        };
        let n_i = interface_size(&model);
        let c = cost_run(model, false);
        let r = build().and_then(|m| cost_run(m, true));
        match (c, r) {
            (Ok(c), Ok(r)) => writeln!(
                report,
                "| {name} | {n_i} | {} | {:.2} | {} | {:.3} | {:.3} | {:.2} | {} / {} | {} / {} | {:.0} / {:.0} |",
                c.unknowns,
                c.nnz as f64 / 1e6,
                if c.interface > 0 { "dense" } else { "refactorise" },
                c.seconds,
                r.seconds,
                r.seconds / c.seconds,
                c.iterations,
                r.iterations,
                c.factorizations,
                r.factorizations,
                c.memory_mb,
                r.memory_mb
            )
            .unwrap(),
            (c, r) => writeln!(
                report,
                "| {name} | {n_i} | default: {} | refactorise: {} | | | | | | | |",
                c.err().map_or("ok".into(), |e| failure(&e)),
                r.err().map_or("ok".into(), |e| failure(&e))
            )
            .unwrap(),
        }
    };
    let family_a: &[usize] = if a.quick {
        &[250]
    } else {
        // n_x = 2000 (n_I = 4002, 680k unknowns) would add about a minute.
        &[250, 500, 1000]
    };
    for &nx in family_a {
        let build = move || {
            TwoBlocks {
                mesh_size: 1.0 / nx as f64,
                h1: 1.0 / 24.0,
                h2: 1.0 / 24.0,
                ..Default::default()
            }
            .build()
            .map(|s| s.model)
        };
        row(report, format!("A: 2 blocks, n_x = {nx}"), &build);
    }
    let family_b: &[usize] = if a.quick { &[2] } else { &[2, 5, 9, 17, 41] };
    for &n in family_b {
        let build = move || {
            let nx = 256;
            Stack {
                layers: (0..n)
                    .map(|k| Layer {
                        height: 16.0 / nx as f64,
                        young: if k % 2 == 0 { 1e10 } else { 1e11 },
                        poisson: 0.3,
                        cells: nx,
                    })
                    .collect(),
                length: 1.0,
                p: 1e7,
                support_half_width: Some(0.1),
                pairing: Pairing::Declared,
            }
            .build()
            .map(|s| s.model)
        };
        row(report, format!("B: stack of {n}, n_x = 256"), &build);
    }
    let sizes: &[usize] = if a.quick {
        &[512]
    } else {
        &[1024, 2048, 4096, 8192]
    };
    writeln!(
        report,
        "\nThe dense kernel alone: faer's Cholesky of an n × n matrix, one dense refactorisation of \
         an interface of n unknowns (what the condensed loop pays per changed active set when it \
         refactorises the interface). Time against n³: the fitted exponent shows whether the \
         kernel is in its cubic regime.\n\n| n | dense Cholesky [s] | GFLOP/s |\n|---|---|---|"
    )
    .unwrap();
    let (mut ns, mut ts) = (vec![], vec![]);
    for &n in sizes {
        let t = dense_cholesky_seconds(n);
        writeln!(
            report,
            "| {n} | {t:.3} | {:.1} |",
            (n as f64).powi(3) / 3.0 / t / 1e9
        )
        .unwrap();
        ns.push(n as f64);
        ts.push(t);
    }
    if ns.len() >= 2 {
        writeln!(
            report,
            "\nFitted exponent of the dense time in n: {:.2} (3 for n³).\n",
            fitted_rate(&ns, &ts)
        )
        .unwrap();
    } else {
        writeln!(report).unwrap();
    }
}
