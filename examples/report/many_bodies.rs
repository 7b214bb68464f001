//! Many bodies: a stack, a ring in a ring (SSNP167), a running-bond wall, automatic pairing.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::failure;

/// Issue: many bodies — a stack, SSNP167's ring in a ring, a running-bond
/// wall, and automatic pairing against declared pairs.
pub(crate) fn many_bodies(report: &mut String, a: &Args) {
    use tfem::scenes::ring::Rings;
    use tfem::scenes::stack::{Pairing, Stack};
    use tfem::scenes::wall::Wall;
    let options = ContactOptions::default();
    writeln!(
        report,
        "## Many bodies\n\n\
         ### A stack of n blocks\n\n\
         n blocks of height 0.25, alternating E = 1e10/1e11 and ν = 0.3/0.2, cells across cycling \
         through m × (16, 24, 10) (every interface non-matching), pairs found by \
         `add_contact_pairs_auto`, uniform pressure p on the top (`tfem::scenes::stack`): the exact \
         stress is σ_yy = −p, σ_xx = τ_xy = 0 in every block. Max stress error over every element / p \
         (a patch test: round-off, no rate).\n\n\
         | blocks | m | pairs found | unknowns | iterations | time [s] | max stress error / p | released |\n|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let scales: &[usize] = if a.quick { &[1, 2] } else { &[1, 2, 4, 8] };
    for n in [3usize, 4, 5] {
        for &m in scales {
            let cells: Vec<usize> = [16, 24, 10].iter().map(|c| c * m).collect();
            let stack = Stack {
                pairing: Pairing::Auto { tolerance: 1e-9 },
                ..Stack::alternating(n, 0.25, &cells)
            };
            let t0 = Instant::now();
            let r = stack.build().and_then(|mut s| {
                let pairs = s.pairs.len();
                s.solve(stack.p, &options).map(|r| (pairs, r))
            });
            let t = t0.elapsed().as_secs_f64();
            match r {
                Ok((pairs, r)) => writeln!(
                    report,
                    "| {n} | {m} | {pairs} of {} | {} | {} | {t:.3} | {:.1e} | {} |",
                    n - 1,
                    r.report.info.unknowns,
                    r.report.iterations,
                    r.max_error,
                    r.released
                )
                .unwrap(),
                Err(e) => writeln!(report, "| {n} | {m} | {} | | | | | |", failure(&e)).unwrap(),
            }
        }
    }

    // Automatic against declared pairs: the same pairs in the same order
    // must give the same system, hence the same displacements.
    let declared = Stack::alternating(4, 0.25, &[16, 24, 10]);
    let auto = Stack {
        pairing: Pairing::Auto { tolerance: 1e-9 },
        ..declared.clone()
    };
    let solve = |s: &Stack| {
        let mut sc = s.build()?;
        let t0 = Instant::now();
        let pairing = |m: &tfem::Model| {
            m.contact_pairs()
                .iter()
                .map(|p| (p.tag_a, p.tag_b))
                .collect::<Vec<_>>()
        };
        let pairs = pairing(&sc.model);
        sc.model.solve_contact(&options)?;
        let t = t0.elapsed().as_secs_f64();
        Ok::<_, tfem::Error>((pairs, sc.model.displacements()?, t))
    };
    match (solve(&declared), solve(&auto)) {
        (Ok((pd, ud, td)), Ok((pa, ua, ta))) => {
            let scale = ud
                .iter()
                .flat_map(|u| u.iter())
                .fold(0.0f64, |m, v| m.max(v.abs()));
            let diff = ud
                .iter()
                .zip(&ua)
                .flat_map(|(p, q)| [(p[0] - q[0]).abs(), (p[1] - q[1]).abs()])
                .fold(0.0f64, f64::max);
            writeln!(
                report,
                "\nAutomatic pairing against declared pairs (stack of 4, m = 1): {} declared, {} found, \
                 {}; max |u_auto − u_declared| / max |u| = {:.1e}; solve {td:.3} s declared, {ta:.3} s automatic.\n",
                pd.len(),
                pa.len(),
                if pd == pa {
                    "the same (tag, tag) pairs in the same order"
                } else {
                    "DIFFERENT pairs"
                },
                diff / scale
            )
            .unwrap();
        }
        (d, au) => writeln!(
            report,
            "\nAutomatic against declared pairs: declared {}, automatic {}.\n",
            d.err().map_or("ok".into(), |e| failure(&e)),
            au.err().map_or("ok".into(), |e| failure(&e))
        )
        .unwrap(),
    }

    let ring_levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256]
    };
    let exact = Rings::default().build().map(|s| s.exact);
    writeln!(
        report,
        "### Ring in a ring (Code_Aster SSNP167)\n\n\
         A ring in a ring, plane strain, E = 1e9, ν = 0.2, pressure 1e7 + 1e6 cos 2θ on r = 1, \
         frictionless interface at r = 0.6, the full disk's displacements imposed at r = 0.2 \
         (`tfem::scenes::ring`, quarter model, matching polar meshes, N cells along the quarter). \
         Against Michell's analytic solution p_c(θ) = p0 + p2 cos 2θ{}: *max error*, the largest \
         nodal pressure error / max p_c; *amplitude*, the fitted cos 2θ amplitude against p2; *released*, elements of B not active \
         at convergence, of all of B (the interface stays closed all round, but it slips, and on \
         a curved matching interface the elements whose chord normal turns the slip into an \
         opening are released: about half, docs/method.md).\n\n\
         | N | unknowns | iterations | time [s] | max pressure error | amplitude error | released / elements of B |\n|---|---|---|---|---|---|---|",
        match &exact {
            Ok(x) => format!(" (p0 = {:.6e}, p2 = {:.6e})", x.p0, x.p2),
            Err(e) => format!(" (analytic solution: {})", failure(e)),
        }
    )
    .unwrap();
    let (mut hs, mut em, mut ea) = (vec![], vec![], vec![]);
    for &cells in &ring_levels {
        let rings = Rings {
            cells,
            ..Default::default()
        };
        let t0 = Instant::now();
        let r = rings.build().and_then(|mut s| s.solve(&options));
        let t = t0.elapsed().as_secs_f64();
        match r {
            Ok(r) => {
                writeln!(
                    report,
                    "| {cells} | {} | {} | {t:.3} | {:.2e} | {:.2e} | {} / {} |",
                    r.report.info.unknowns,
                    r.report.iterations,
                    r.max_error,
                    r.amplitude_error,
                    r.released,
                    r.report.elements
                )
                .unwrap();
                hs.push(1.0 / cells as f64);
                em.push(r.max_error);
                ea.push(r.amplitude_error);
            }
            Err(e) => writeln!(report, "| {cells} | {} | | | | | |", failure(&e)).unwrap(),
        }
    }
    if hs.len() >= 2 {
        let tail = hs.len().min(3);
        writeln!(
            report,
            "\nFitted rates in 1/N: max error {:.2} (over the last {tail} levels {:.2}), amplitude {:.2}.\n",
            fitted_rate(&hs, &em),
            fitted_rate(&hs[hs.len() - tail..], &em[em.len() - tail..]),
            fitted_rate(&hs, &ea)
        )
        .unwrap();
    }

    let wall_levels: Vec<usize> = if a.quick {
        vec![8, 16, 32]
    } else {
        vec![8, 16, 32, 64]
    };
    let w0 = Wall::default();
    writeln!(
        report,
        "### A running-bond wall\n\n\
         {} courses of {} blocks ({} × {}) in running bond, each block its own body, pairs found by \
         `add_contact_pairs_auto` (checked against the facing faces of the layout), rollers under \
         the first course, u = 0 at both ends (`tfem::scenes::wall`). *Uniform*: pressure p over the \
         whole top, no weight; exact σ_yy = −p, σ_xx = −ν/(1 − ν) p; max stress error / p, rate \
         fitted in h; time: the contact solve alone; *nodal pressure error*: the largest |p_node − p_joints| / p over the nodes \
         of B (`Model::contact_nodal_pressures`), p_joints the mean of the exact pressures of the \
         joints the node lies on (a block's corner lies on a bed and a head joint, a node where a \
         head joint ends on a bed face on two bed joints). *Eccentric*: p over the left third and the self-weight: joints open under \
         the unloaded part; the loop must reach a fixed point (a revisited active set is refused \
         as NotConverged), every block balance its loads, reactions and contact forces (largest \
         |Σ| / total load), the contact forces cancel overall, and the course below carry the whole \
         top course (ratio 1).\n",
        w0.rows, w0.blocks, w0.width, w0.height
    )
    .unwrap();
    writeln!(
        report,
        "| load | h | pairs = facing faces | unknowns | status | iterations | time [s] | max stress error / p | nodal pressure error / p | released | block imbalance | contact imbalance | top course support |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let (mut hs, mut es, mut ps) = (vec![], vec![], vec![]);
    for eccentric in [false, true] {
        for &n in &wall_levels {
            let wall = if eccentric {
                Wall {
                    load_width: 1.0,
                    weight: 2e4,
                    mesh_size: 1.0 / n as f64,
                    ..w0
                }
            } else {
                Wall {
                    mesh_size: 1.0 / n as f64,
                    ..w0
                }
            };
            let name = if eccentric { "eccentric" } else { "uniform" };
            let mut scene = match wall.build() {
                Ok(s) => s,
                Err(e) => {
                    writeln!(
                        report,
                        "| {name} | 1/{n} | {} | | | | | | | | | | |",
                        failure(&e)
                    )
                    .unwrap();
                    continue;
                }
            };
            let matches = scene.pairs == Wall::expected_pairs(&scene.blocks);
            // The solve alone is timed, not its checks.
            let t0 = Instant::now();
            let solved = scene.model.solve_contact(&options);
            let t = t0.elapsed().as_secs_f64();
            let r = solved.and_then(|report| scene.measure(&wall, report));
            match r {
                Ok(r) => {
                    writeln!(
                        report,
                        "| {name} | 1/{n} | {} ({}) | {} | Converged | {} | {t:.3} | {} | {} | {} | {:.1e} | {:.1e} | {:.12} |",
                        if matches { "yes" } else { "NO" },
                        scene.pairs.len(),
                        r.report.info.unknowns,
                        r.report.iterations,
                        if eccentric {
                            "–".to_string()
                        } else {
                            format!("{:.2e}", r.max_uniform_error)
                        },
                        if eccentric {
                            "–".to_string()
                        } else {
                            format!("{:.2e}", r.max_nodal_pressure_error)
                        },
                        r.released,
                        r.block_imbalance,
                        r.contact_imbalance,
                        r.top_course_support
                    )
                    .unwrap();
                    if !eccentric {
                        hs.push(wall.mesh_size);
                        es.push(r.max_uniform_error);
                        ps.push(r.max_nodal_pressure_error);
                    }
                }
                Err(e) => writeln!(
                    report,
                    "| {name} | 1/{n} | {} | | {} | | {t:.3} | | | | | | |",
                    if matches { "yes" } else { "NO" },
                    failure(&e)
                )
                .unwrap(),
            }
        }
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nUniform load: fitted rates in h of the stress error {:.2}, of the nodal pressure \
             error {:.2}.\n",
            fitted_rate(&hs, &es),
            fitted_rate(&hs, &ps)
        )
        .unwrap();
    }
}
