//! The cost of many contact interfaces: the condensed active-set loop
//! (docs/method.md §6.10: a dense interface Schur complement of n_I²
//! entries, n_I³/3 flops per dense refactorisation) against the loop that
//! refactorises the sparse matrix at every iteration
//! (`ContactOptions::refactorize`), on scenes of growing interface size.
//!
//! * Family A, "long interface": the seed's two blocks (load and support
//!   over 2C = 0.2 L, docs/method.md §4) with n_x cells across and blocks
//!   thin enough to stay affordable but thick enough that tfem condenses
//!   (`Condensed::worthwhile`: n_I ≤ 8192 and n_I² ≤ 4 nnz).
//! * Family B, "many interfaces": a stack of thin blocks (256 cells across,
//!   16 rows each) under the same loading, from 2 to 41 blocks: n_I from 514
//!   to 20 560, beyond the dense limits, where tfem refactorises by itself.
//! * The dense kernel alone: faer's Cholesky of an n × n matrix, the cost
//!   of one dense refactorisation of the interface at n_I = n.
//!
//! Run: `cargo run --release --example interface_cost` (about 4 minutes on
//! 2 cores; `-- --quick` for a smoke run, `-- --large` adds n_x = 4000,
//! n_I = 8002, 2.7M unknowns: ~9 more minutes, 4.7 GB). Times are medians of 3 runs
//! where marked, wall clock, analysis included.
//!
//! Measured (2 shared cores, one quiet run): inside tfem's switch
//! (`Condensed::worthwhile`) the condensed loop is 3.0–3.9 × faster on
//! family A (n_I = 502 … 4002; 2.1 × at n_I = 8002 with `--large`, a run
//! disturbed by a compilation, at 1.5 × the memory: 4.3 GB against 2.9)
//! and 6.7 × on the stack of 2. Beyond it (the stacks of 5 … 41 blocks,
//! n_I = 2072 … 20 720, n_I² = 3.3 … 160 × 4 nnz) tfem refactorises, with
//! the same times for both options (ratios 0.99–1.11): no cliff, the time
//! follows the unknowns (0.9 s at 44k, 10.6 s at 360k). What the dense loop
//! would have cost there, from the dense kernel (23–27 GFLOP/s: 0.11 s at
//! n = 2048, 0.98 s at 4096, 6.7 s at 8192) times the iterations: ~1.1 s
//! against 0.90 s for the stack of 5 (break-even), ~7 s against 1.5 s for
//! 9 blocks, ~48 s against 3.6 s for 17, ~870 s and 3.4 GB against 10.6 s
//! for 41: the n_I² ≤ 4 nnz rule stops the dense loop about where it stops
//! paying, and the cap of 8192 where its memory becomes the larger cost.

use std::time::Instant;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{cholesky_in_place, cholesky_in_place_scratch};
use faer::{Mat, Par};
use tfem::scenes::TwoBlocks;
use tfem::scenes::stack::{Layer, Pairing, Stack};
use tfem::{ContactOptions, Model};

/// One solve's figures.
struct Run {
    seconds: f64,
    iterations: usize,
    factorizations: usize,
    interface: usize,
    unknowns: usize,
    nnz: usize,
    memory_mb: f64,
}

fn solve(mut model: Model, refactorize: bool) -> Run {
    // Thin blocks release their contact zone slowly: room beyond the
    // default cap of 50 iterations.
    let options = ContactOptions {
        refactorize,
        max_iterations: 400,
        ..Default::default()
    };
    let t = Instant::now();
    let r = model.solve_contact(&options).expect("contact solve");
    let seconds = t.elapsed().as_secs_f64();
    Run {
        seconds,
        iterations: r.iterations,
        factorizations: r.info.factorizations,
        interface: r.info.interface_unknowns,
        unknowns: r.info.unknowns,
        nnz: r.info.matrix_nnz,
        memory_mb: r.info.memory_bytes as f64 / 1e6,
    }
}

/// Median of `reps` runs of a freshly built model (the first run's other
/// figures).
fn median(reps: usize, build: &dyn Fn() -> Model, refactorize: bool) -> Run {
    let mut runs: Vec<Run> = (0..reps).map(|_| solve(build(), refactorize)).collect();
    let mut t: Vec<f64> = runs.iter().map(|r| r.seconds).collect();
    t.sort_by(f64::total_cmp);
    let mut first = runs.swap_remove(0);
    first.seconds = t[t.len() / 2];
    first
}

/// Interface unknowns of a scene: the contact nodes' normal components
/// (the interfaces here are horizontal): 2 per node pair.
fn interface_size(model: &Model) -> usize {
    let mut nodes: Vec<usize> = model
        .contact_mesh()
        .expect("contact mesh")
        .iter()
        .flat_map(|e| e.nodes)
        .collect();
    nodes.sort_unstable();
    nodes.dedup();
    nodes.len()
}

fn row(name: &str, build: &dyn Fn() -> Model, reps: usize) {
    let n_i = interface_size(&build());
    let c = median(reps, build, false);
    let r = median(reps, build, true);
    let condensed = c.interface > 0;
    println!(
        "| {name} | {n_i} | {} | {:.2} | {} | {:.3} | {:.3} | {:.2} | {} / {} | {} / {} | {:.0} / {:.0} |",
        c.unknowns,
        c.nnz as f64 / 1e6,
        if condensed { "dense" } else { "fallback" },
        c.seconds,
        r.seconds,
        r.seconds / c.seconds,
        c.iterations,
        r.iterations,
        c.factorizations,
        r.factorizations,
        c.memory_mb,
        r.memory_mb,
    );
}

/// Seconds of faer's dense Cholesky of an n × n SPD matrix (both cores).
fn dense_cholesky(n: usize) -> f64 {
    let mut a = Mat::<f64>::from_fn(n, n, |i, j| {
        if i == j {
            n as f64
        } else {
            1.0 / (1.0 + (i as f64 - j as f64).abs())
        }
    });
    let par = Par::rayon(0);
    let mut mem = MemBuffer::new(cholesky_in_place_scratch::<f64>(n, par, Default::default()));
    let t = Instant::now();
    cholesky_in_place(
        a.as_mut(),
        Default::default(),
        par,
        MemStack::new(&mut mem),
        Default::default(),
    )
    .expect("SPD");
    t.elapsed().as_secs_f64()
}

fn peak_rss_mb() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb / 1e3)
}

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    // n_x = 4000 (2.7M unknowns, n_I = 8002) alone takes ~9 minutes of
    // the two loops and 4.3 GB: only on request.
    let large = std::env::args().any(|a| a == "--large");
    println!(
        "| scene | n_I | unknowns | nnz (M) | default | t default (s) | t refactorise (s) | ratio | iterations d / r | factorisations d / r | memory MB d / r |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    // Family A: two blocks, h1 = h2 = 1/24 of L (n_I² ≤ 4 nnz up to n_x = 4000).
    let family_a: &[(usize, usize)] = if quick {
        &[(250, 1)]
    } else if large {
        &[(250, 3), (500, 3), (1000, 3), (2000, 1), (4000, 1)]
    } else {
        &[(250, 3), (500, 3), (1000, 3), (2000, 1)]
    };
    for &(nx, reps) in family_a {
        let build = move || {
            TwoBlocks {
                mesh_size: 1.0 / nx as f64,
                h1: 1.0 / 24.0,
                h2: 1.0 / 24.0,
                ..Default::default()
            }
            .build()
            .expect("two blocks")
            .model
        };
        row(&format!("A: 2 blocks, n_x = {nx}"), &build, reps);
    }
    // Family B: stacks of thin blocks, 256 cells across, 16 rows each.
    let family_b: &[(usize, usize)] = if quick {
        &[(2, 1)]
    } else {
        &[(2, 3), (5, 3), (9, 3), (17, 1), (41, 1)]
    };
    for &(n, reps) in family_b {
        let build = move || {
            let nx = 256;
            let layer = |k: usize| Layer {
                height: 16.0 / nx as f64,
                young: if k % 2 == 0 { 1e10 } else { 1e11 },
                poisson: 0.3,
                cells: nx,
            };
            Stack {
                layers: (0..n).map(layer).collect(),
                length: 1.0,
                p: 1e7,
                support_half_width: Some(0.1),
                pairing: Pairing::Declared,
            }
            .build()
            .expect("stack")
            .model
        };
        row(&format!("B: stack of {n}, n_x = 256"), &build, reps);
    }
    println!();
    println!("| n | dense Cholesky (s) | GFLOP/s |");
    println!("|---|---|---|");
    let sizes: &[usize] = if quick {
        &[512]
    } else {
        &[1024, 2048, 4096, 8192]
    };
    for &n in sizes {
        let t = dense_cholesky(n);
        println!(
            "| {n} | {t:.3} | {:.1} |",
            (n as f64).powi(3) / 3.0 / t / 1e9
        );
    }
    if let Some(mb) = peak_rss_mb() {
        println!("\npeak RSS of the whole run: {mb:.0} MB");
    }
}
