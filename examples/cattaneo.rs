//! Cattaneo–Mindlin with the exact frictional oracle, then with TFEM's
//! frictional elements: a cylinder pressed on a block (Hertz half-width
//! a = 0.005R by default), then sheared by Q < μP in steps; stick
//! half-width c and shear traction q(x) against Johnson §7.1 as the mesh
//! is refined.
//!
//! `cargo run --release --example cattaneo -- [levels…]` (levels k: h = a/k,
//! default 8 16 32 64).

use tfem::scenes::cattaneo::CattaneoMindlin;
use tfem::verification::fitted_rate;

fn main() {
    let levels: Vec<f64> = {
        let v: Vec<f64> = std::env::args()
            .skip(1)
            .filter_map(|a| a.parse().ok())
            .collect();
        if v.is_empty() {
            vec![8.0, 16.0, 32.0, 64.0]
        } else {
            v
        }
    };
    // Q/(μP) of the tangential steps (CATTANEO_RATIOS, comma-separated).
    let ratios: Vec<f64> = std::env::var("CATTANEO_RATIOS")
        .ok()
        .map(|v| v.split(',').filter_map(|r| r.trim().parse().ok()).collect())
        .unwrap_or_else(|| vec![0.15, 0.3, 0.45, 0.6]);
    // a/R from the environment (CATTANEO_A_OVER_R), default the scene's.
    let base = CattaneoMindlin {
        half_width: std::env::var("CATTANEO_A_OVER_R")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(CattaneoMindlin::default().half_width),
        ..CattaneoMindlin::default()
    };
    // E_cylinder / E_block from the environment (CATTANEO_E_RATIO), default 1:
    // β ≠ 0 shows how far the β = 0 solution is then.
    let base = CattaneoMindlin {
        e_cylinder: base.e_block
            * std::env::var("CATTANEO_E_RATIO")
                .ok()
                .and_then(|v| v.parse().ok())
                .unwrap_or(1.0),
        ..base
    };
    println!(
        "Cattaneo–Mindlin, plane strain, E_cylinder/E_block = {}, Dundurs β = {:.3}, μ = {}, a = {}R; tangential steps Q/(μP) = {ratios:?}\n",
        base.e_cylinder / base.e_block,
        base.dundurs_beta(),
        base.mu,
        base.half_width / base.radius
    );
    println!(
        "| h | nodes | pairs | setup [s] | step | Q/(μP) | trials | iterations | time [s] | open/stick/slip | err a | err c | err c (fit) | c left, right / c | err q (L2) | err q (max/μp₀) | misclassified | min dissipation |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut table: Vec<Vec<[f64; 5]>> = Vec::new();
    for &k in &levels {
        let cm = CattaneoMindlin {
            mesh_size: base.half_width / k,
            ..base
        };
        let scene = cm.build().unwrap();
        let sol = scene.solve(&cm, &ratios).unwrap();
        let p_drift = sol
            .tangential
            .iter()
            .map(|s| ((s.p - sol.normal.p) / sol.normal.p).abs())
            .fold(0.0, f64::max);
        eprintln!("a/{k}: P drift over the tangential steps {p_drift:.1e}");
        let mut row = Vec::new();
        for (i, s) in std::iter::once(&sol.normal)
            .chain(&sol.tangential)
            .enumerate()
        {
            let ea = (s.a - s.analytic.a) / s.analytic.a;
            let ec = (s.c - s.analytic.c) / s.analytic.a;
            let ef = (s.c_fit - s.analytic.c) / s.analytic.a;
            let [o, st, sl] = s.step.counts();
            let dmin = s
                .step
                .pairs
                .iter()
                .map(|p| p.dissipation())
                .fold(f64::INFINITY, f64::min);
            // The normal step has no shear: its analytic q is zero and a
            // relative q error means nothing.
            let (ql2, qmax) = match i {
                0 => ("–".to_string(), "–".to_string()),
                _ => (
                    format!("{:.2e}", s.q_error_l2),
                    format!("{:.2e}", s.q_error_max),
                ),
            };
            println!(
                "| a/{k} | {} | {} | {:.2} | {i} | {:.3} | {} | {} | {:.2} | {o}/{st}/{sl} | {ea:+.2e} | {ec:+.2e} | {ef:+.2e} | {:.4}, {:.4} | {ql2} | {qmax} | {} | {dmin:.1e} |",
                sol.nodes,
                sol.pairs,
                sol.setup_seconds,
                s.q / (cm.mu * s.p),
                s.trials,
                s.step.iterations,
                s.seconds,
                s.c_sides[0] / s.analytic.c,
                s.c_sides[1] / s.analytic.c,
                s.misclassified,
            );
            row.push([ea.abs(), ec.abs(), ef.abs(), s.q_error_l2, s.q_error_max]);
        }
        table.push(row);
    }
    if levels.len() >= 2 {
        let h: Vec<f64> = levels.iter().map(|k| 1.0 / k).collect();
        println!("\nfitted rates over the levels:\n");
        println!("| step | a | c | c (fit) | q (L2) | q (max) |\n|---|---|---|---|---|---|");
        for i in 0..table[0].len() {
            let rate = |j: usize| {
                let e: Vec<f64> = table.iter().map(|r| r[i][j]).collect();
                fitted_rate(&h, &e)
            };
            let q = |j: usize| match i {
                0 => "–".to_string(),
                _ => format!("{:.2}", rate(j)),
            };
            println!(
                "| {i} | {:.2} | {:.2} | {:.2} | {} | {} |",
                rate(0),
                rate(1),
                rate(2),
                q(3),
                q(4)
            );
        }
    }

    // TFEM on the same meshes: the normal step, then the same tangential
    // steps, each hit by a secant on the platen's displacement.
    println!(
        "\nTFEM's frictional elements (docs/method.md §6.15) on the same meshes:\n\n\
         | h | step | Q/(μP) | trials | contact iterations | time [s] | err a | err c (fit) | err q (L2) | err q (max/μp₀) |\n\
         |---|---|---|---|---|---|---|---|---|---|"
    );
    let mut table: Vec<Vec<[f64; 2]>> = Vec::new();
    for &k in &levels {
        let cm = CattaneoMindlin {
            mesh_size: base.half_width / k,
            ..base
        };
        let mut scene = cm.build().unwrap();
        let out = match scene.solve_tfem(&cm, &ratios) {
            Ok(out) => out,
            Err(e) => {
                println!("| a/{k} | {e} | | | | | | | | |");
                continue;
            }
        };
        let mut row = Vec::new();
        for (i, s) in out.steps.iter().enumerate() {
            let ea = (s.a - s.analytic.a) / s.analytic.a;
            let ef = (s.c_fit - s.analytic.c) / s.analytic.a;
            let (ql2, qmax) = match i {
                0 => ("–".to_string(), format!("{:.2e}", s.q_error_max)),
                _ => (
                    format!("{:.2e}", s.q_error_l2),
                    format!("{:.2e}", s.q_error_max),
                ),
            };
            println!(
                "| a/{k} | {i} | {:.3} | {} | {} | {:.2} | {ea:+.2e} | {ef:+.2e} | {ql2} | {qmax} |",
                s.q / (cm.mu * s.p),
                s.trials,
                s.step.iterations,
                s.seconds,
            );
            row.push([ef.abs(), s.q_error_l2]);
        }
        println!(
            "| a/{k} | all | | | {} | {:.2} | factorisations {} | min dissipation {:.1e} | | |",
            out.iterations, out.seconds, out.factorisations, out.min_dissipation
        );
        table.push(row);
    }
    if table.len() >= 2 && table.len() == levels.len() {
        let h: Vec<f64> = levels.iter().map(|k| 1.0 / k).collect();
        println!(
            "\nTFEM's fitted rates over the levels:\n\n| step | c (fit) | q (L2) |\n|---|---|---|"
        );
        for i in 1..table[0].len() {
            let rate = |j: usize| {
                let e: Vec<f64> = table.iter().map(|r| r[i][j]).collect();
                fitted_rate(&h, &e)
            };
            println!("| {i} | {:.2} | {:.2} |", rate(0), rate(1));
        }
    }
}
