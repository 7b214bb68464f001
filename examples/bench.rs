//! Speed of the seed scene from 10k to ~1M unknowns: symbolic analysis, one
//! factorisation + solve, and the whole contact solve, with AMD and with
//! geometric nested dissection (ND). Prints a markdown table; times are
//! wall-clock seconds of one run on this machine.
//!
//!   cargo run --release --example bench              # up to h = 1/1024 (~1M unknowns)
//!   cargo run --release --example bench -- --quick   # up to h = 1/256

use std::time::Instant;

use tfem::scenes::TwoBlocks;
use tfem::{ContactOptions, Ordering};

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let levels: &[usize] = if quick {
        &[64, 128, 256]
    } else {
        &[128, 256, 512, 724, 1024]
    };
    println!(
        "machine: {} cores; faer sparse Cholesky (LLT), seed scene 2C/L = 0.2",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    println!();
    println!(
        "| h | unknowns | ordering | factor nnz | analysis | 1 factorisation + solve | contact solve | iterations | contact / (fact.+solve) | assembly / fact. |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for &n in levels {
        for ordering in [Ordering::Amd, Ordering::NestedDissection] {
            let scene = TwoBlocks {
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            };
            let mut s = scene.build().expect("scene");
            s.model.set_ordering(ordering);
            let t0 = Instant::now();
            let r = s
                .model
                .solve_contact(&ContactOptions::default())
                .expect("contact solve");
            let total = t0.elapsed().as_secs_f64();
            let i = r.info;
            let per_fact = i.timings.factorization / i.factorizations as f64;
            let per_solve = i.timings.solve / i.factorizations as f64;
            println!(
                "| 1/{n} | {} | {:?} | {:.3e} | {:.2} | {:.2} | {:.2} | {} | {:.1} | {:.3} |",
                i.unknowns,
                ordering,
                i.factor_nnz as f64,
                i.timings.analysis,
                per_fact + per_solve,
                total,
                r.iterations,
                total / (per_fact + per_solve),
                (i.timings.assembly / i.factorizations as f64) / per_fact
            );
        }
    }
}
