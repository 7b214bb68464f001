//! Speed of the seed scene's contact solve, from 17k to ~1M unknowns: the
//! default loop (one factorisation, condensed on the interface) against the
//! loop that refactorises at every iteration, whose mean iteration gives the
//! cost of one factorisation + solve of the same matrix. Prints a markdown
//! table; wall-clock seconds of one run on this machine (the report,
//! `--example report`, runs each level in its own process and adds memory).
//!
//!   cargo run --release --example bench              # up to h = 1/1024 (~1M unknowns)
//!   cargo run --release --example bench -- --quick   # up to h = 1/256

use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;

fn main() {
    let quick = std::env::args().any(|a| a == "--quick");
    let levels: &[usize] = if quick {
        &[64, 128, 256]
    } else {
        &[128, 256, 512, 1024]
    };
    println!(
        "machine: {} cores; faer sparse Cholesky (LLT), seed scene 2C/L = 0.2, nested dissection",
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    println!();
    println!(
        "| h | unknowns | iterations | fact.+solve [s] | refactorising loop [s] | condensed loop [s] | condensed − analysis | ratio |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for &n in levels {
        let run = |refactorize: bool| {
            let mut s = TwoBlocks {
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .expect("scene");
            let t0 = Instant::now();
            let r = s
                .model
                .solve_contact(&ContactOptions {
                    refactorize,
                    ..Default::default()
                })
                .expect("contact solve");
            (t0.elapsed().as_secs_f64(), r)
        };
        let (t_full, full) = run(true);
        let (t_cond, cond) = run(false);
        let i = full.info;
        let per = (i.timings.factorization + i.timings.solve) / i.factorizations as f64;
        let net = t_cond - cond.info.timings.analysis;
        println!(
            "| 1/{n} | {} | {} | {per:.2} | {t_full:.2} | {t_cond:.2} | {net:.2} | {:.2} |",
            i.unknowns,
            cond.iterations,
            net / per
        );
    }
}
