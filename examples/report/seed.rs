//! The seed scene: outputs against h, Richardson extrapolation, the reference.

use std::fmt::Write as _;
use std::time::Instant;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;

use crate::Args;
use crate::common::{Curve, figure, outputs, reference};

/// Richardson extrapolation from the last three values of a sequence with
/// h halving: the observed order p and the extrapolated value.
fn richardson(q: &[f64]) -> Option<(f64, f64)> {
    let [a, b, c] = q[q.len().checked_sub(3)?..] else {
        return None;
    };
    let p = ((a - b) / (b - c)).abs().log2();
    let p = if p.is_finite() && p > 0.2 { p } else { 1.0 };
    Some((p, c + (c - b) / (2f64.powf(p) - 1.0)))
}

pub(crate) fn seed(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512, 1024]
    };
    // The oracle's sparse LU of the saddle-point system is the expensive
    // part of this section; it runs up to 1/256.
    let oracle_max = if a.quick { 64 } else { 256 };
    let refs = reference(a);
    writeln!(report, "## Error against run time: the seed scene\n").unwrap();
    writeln!(
        report,
        "Canonical parameters (docs/method.md §4), frictionless law, defaults. Relative errors against the \
         independent reference (GetFEM, exact frictionless contact, extrapolated; `{}`), when found, \
         and against the exact frictionless oracle on the same mesh (`tfem::oracle`: node-to-node \
         multipliers, sparse LU; up to h = 1/{oracle_max}): *same set* says whether its contact node \
         pairs are exactly TFEM's. Times: mesh (generation and model set-up), analysis (pattern, \
         ordering, symbolic), assembly, the one numeric factorisation, solves, dense interface work, \
         whole contact solve (without the mesh). Memory: allocated by pattern, values, factor and \
         interface (peak process memory: the speed section).\n",
        // Inside the repository, the path relative to it: the report is
        // committed, so it names no directory of the machine it ran on.
        a.reference
            .strip_prefix(env!("CARGO_MANIFEST_DIR"))
            .unwrap_or(&a.reference)
            .display()
    )
    .unwrap();
    let mut curves = Vec::new();
    for c in [0.1, 0.2, 0.3] {
        let key = format!("canonical_{:.1}", 2.0 * c);
        let case = refs.as_ref().map(|r| r["cases"][&key].clone());
        writeln!(report, "### 2C/L = {:.1}\n", 2.0 * c).unwrap();
        writeln!(
            report,
            "| h | unknowns | iterations | mesh | analysis | assembly | factorisation | solves | dense | total [s] | memory [MB] | ℓc | err ℓc | err gap_edge | err v_top | err compliance | same set as oracle | vs oracle: gap_edge | v_top | compliance | max penetration |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
        )
        .unwrap();
        let mut pts = Vec::new();
        let mut seq: Vec<[f64; 4]> = Vec::new();
        for &n in &levels {
            let t_mesh = Instant::now();
            let mut s = TwoBlocks {
                c,
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .expect("scene");
            let t_mesh = t_mesh.elapsed().as_secs_f64();
            let t0 = Instant::now();
            let r = match s.solve(&ContactOptions::default()) {
                Ok(r) => r,
                Err(e) => {
                    writeln!(report, "| 1/{n} | {e} |").unwrap();
                    continue;
                }
            };
            let total = t0.elapsed().as_secs_f64();
            let rel = |name: &str, v: f64| -> String {
                case.as_ref()
                    .and_then(|cs| cs[name]["value"].as_f64())
                    .map_or("–".into(), |rv| format!("{:+.2e}", (v - rv) / rv))
            };
            let vs_oracle = if n <= oracle_max {
                match tfem::oracle::frictionless_oracle(
                    &s.model,
                    tfem::scenes::TAG_CONTACT_LOWER,
                    tfem::scenes::TAG_CONTACT_UPPER,
                ) {
                    Ok(o) => {
                        let ours = [r.gap_edge, r.v_top, r.compliance];
                        let exact = outputs(&s, &o.u);
                        let same = active_pairs(&s) == o.active;
                        format!(
                            "{} | {:+.2e} | {:+.2e} | {:+.2e}",
                            if same { "yes" } else { "no" },
                            (ours[0] - exact[0]) / exact[0],
                            (ours[1] - exact[1]) / exact[1],
                            (ours[2] - exact[2]) / exact[2]
                        )
                    }
                    Err(e) => format!("{} | – | – | –", e.status().name()),
                }
            } else {
                "– | – | – | –".into()
            };
            let i = r.report.info;
            writeln!(
                report,
                "| 1/{n} | {} | {} | {t_mesh:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.0} | {:.4} | {} | {} | {} | {} | {vs_oracle} | {:.2e} |",
                i.unknowns,
                r.report.iterations,
                i.timings.analysis,
                i.timings.assembly,
                i.timings.factorization,
                i.timings.solve,
                i.timings.interface,
                total,
                i.memory_bytes as f64 / 1e6,
                r.lc,
                rel("lc", r.lc),
                rel("gap_edge", r.gap_edge),
                rel("v_top", r.v_top),
                rel("compliance", r.compliance),
                r.report.max_penetration
            )
            .unwrap();
            seq.push([r.lc, r.gap_edge, r.v_top, r.compliance]);
            if let Some(rv) = case
                .as_ref()
                .and_then(|cs| cs["compliance"]["value"].as_f64())
            {
                pts.push((total, ((r.compliance - rv) / rv).abs()));
            }
        }
        writeln!(report).unwrap();
        // Our own extrapolation, as a second yardstick independent of the
        // reference code.
        let names = ["lc", "gap_edge", "v_top", "compliance"];
        let mut rows = String::new();
        for (k, name) in names.iter().enumerate() {
            let q: Vec<f64> = seq.iter().map(|v| v[k]).collect();
            if let Some((p, x)) = richardson(&q) {
                let last = q[q.len() - 1];
                let cmp = case
                    .as_ref()
                    .and_then(|cs| Some((cs[name]["value"].as_f64()?, cs[name]["err"].as_f64()?)))
                    .map_or("– | –".into(), |(rv, re)| {
                        format!(
                            "{rv:.6e} ± {re:.1e} | {:+.2e} ({:.1} error bars)",
                            (x - rv) / rv,
                            (x - rv).abs() / re
                        )
                    });
                writeln!(
                    rows,
                    "| {name} | {p:.2} | {x:.6e} | {:+.2e} | {cmp} |",
                    (last - x) / x
                )
                .unwrap();
            }
        }
        if !rows.is_empty() {
            writeln!(
                report,
                "Richardson extrapolation from the three finest levels: observed order p, extrapolated \
                 value, the finest level's relative distance to it, and the extrapolation against the \
                 reference (relative, and in units of the reference's error bar).\n\n\
                 | quantity | p | extrapolated | finest vs extrapolated | reference | extrapolated vs reference |\n|---|---|---|---|---|---|\n{rows}"
            )
            .unwrap();
        }
        if !pts.is_empty() {
            curves.push(Curve {
                label: format!("2C/L = {:.1}: frictionless", 2.0 * c),
                points: pts,
            });
        }
    }
    // Options, 2C/L = 0.2: the stick law and the contact λ.
    let case = refs.as_ref().map(|r| r["cases"]["canonical_0.2"].clone());
    let option_levels: Vec<usize> = levels.iter().copied().filter(|&n| n <= 512).collect();
    writeln!(
        report,
        "### Options (2C/L = 0.2): compliance error against the reference\n\n| option | {} |\n|---|{}",
        option_levels.iter().map(|n| format!("h = 1/{n}")).collect::<Vec<_>>().join(" | "),
        "---|".repeat(option_levels.len())
    )
    .unwrap();
    let options: [(&str, ContactOptions); 4] = [
        ("frictionless, λ = 1 (default)", ContactOptions::default()),
        (
            "stick",
            ContactOptions {
                law: tfem::ContactLaw::Stick,
                ..Default::default()
            },
        ),
        (
            "frictionless, λ = 0.1",
            ContactOptions {
                lambda: Some(0.1),
                ..Default::default()
            },
        ),
        (
            "frictionless, λ = 10",
            ContactOptions {
                lambda: Some(10.0),
                ..Default::default()
            },
        ),
    ];
    for (label, opts) in options {
        let mut cells = Vec::new();
        let mut pts = Vec::new();
        for &n in &option_levels {
            let mut s = TwoBlocks {
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .expect("scene");
            let t0 = Instant::now();
            match s.solve(&opts) {
                Ok(r) => {
                    let total = t0.elapsed().as_secs_f64();
                    let err = case
                        .as_ref()
                        .and_then(|cs| cs["compliance"]["value"].as_f64())
                        .map(|rv| (r.compliance - rv) / rv);
                    cells.push(err.map_or("–".into(), |e| format!("{e:+.2e} ({total:.2} s)")));
                    if let Some(e) = err {
                        pts.push((total, e.abs()));
                    }
                }
                Err(e) => cells.push(e.status().name().to_string()),
            }
        }
        writeln!(report, "| {label} | {} |", cells.join(" | ")).unwrap();
        if label != "frictionless, λ = 1 (default)" {
            curves.push(Curve {
                label: format!("2C/L = 0.2: {label}"),
                points: pts,
            });
        }
    }
    writeln!(report).unwrap();
    figure(
        report,
        a,
        "seed_error_time.svg",
        "seed scene: relative error of the compliance against wall time",
        "time [s]",
        "relative error",
        &curves,
        "seed scene error against time",
    );
}

/// TFEM's active contact elements as node pairs (lower, upper): on a flat
/// conforming interface each couples the two nodes its opening depends on.
fn active_pairs(s: &tfem::scenes::TwoBlocksScene) -> std::collections::BTreeSet<(usize, usize)> {
    let mesh = s.model.mesh().expect("mesh");
    let mut set = std::collections::BTreeSet::new();
    for (el, &on) in s
        .model
        .contact_elements()
        .expect("contact")
        .iter()
        .zip(s.model.contact_active().expect("contact"))
    {
        if !on {
            continue;
        }
        let geo = tfem::TriGeometry::new(&mesh.corners(&el.nodes));
        let nodes: Vec<usize> = (0..3)
            .filter(|&i| {
                (geo.g[i][0] * el.normal[0] + geo.g[i][1] * el.normal[1]).abs() > 1e-9 * geo.h
            })
            .map(|i| el.nodes[i])
            .collect();
        if let [p, q] = nodes[..] {
            set.insert(if p < s.n_lower_nodes { (p, q) } else { (q, p) });
        }
    }
    set
}
