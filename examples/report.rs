//! Regenerates `docs/report.md` and its pictures: error against run time for
//! the verification scenes and the seed scene, stability on stiff and
//! extreme cases, speed with both orderings, and what each scene built.
//!
//!   cargo run --release --example report               # full, up to ~1M unknowns (~10 min)
//!   cargo run --release --example report -- --quick    # small sizes, for CI
//!   cargo run --release --example report -- --calculix # also CalculiX beside tfem (~6 more min)
//!   cargo run --release --example report -- --only friction,many_bodies --out /tmp/r
//!
//! `--only` runs the named sections alone (comma-separated; the names are
//! [`SECTIONS`], e.g. `patch_ratios`, `interference`, `indenters`,
//! `many_bodies`, `interface_cost`, `friction`, `calculix`) into
//! `OUT/report.md`: for testing a section, not for the published report.
//! The CalculiX section runs only with `--calculix` (or `--only calculix`)
//! and never with `--quick`: it needs `ccx` (Debian's `calculix-ccx`),
//! which CI does not install; without `ccx` on the PATH it says so.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use plotters::prelude::*;
use serde_json::Value;
use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;
use tfem::verification::{StudyPoint, fitted_rate, run_manufactured_elasticity};
use tfem::{ContactOptions, Material, Ordering, PlaneMode, Tempering};

/// The reference values shipped in the repository (see
/// `docs/reference/README.md`), found from any working directory.
const REFERENCE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/docs/reference/two_blocks_canonical.json"
);

struct Args {
    quick: bool,
    out: PathBuf,
    reference: PathBuf,
    /// Run CalculiX beside tfem (`--calculix`).
    calculix: bool,
    /// Only these sections (`--only a,b`); empty: every section.
    only: Vec<String>,
}

/// Every section's name, in the report's order (`--only` takes these).
const SECTIONS: &[&str] = &[
    "manufactured",
    "seed",
    "patch_test",
    "patch_ratios",
    "hertz",
    "interference",
    "indenters",
    "many_bodies",
    "stability",
    "speed",
    "histories",
    "interface_cost",
    "friction",
    "cattaneo",
    "calculix",
    "host_codes",
    "q4_host",
    "built",
];

impl Args {
    /// Whether the section `name` is to be run.
    fn wants(&self, name: &str) -> bool {
        self.only.is_empty() || self.only.iter().any(|o| o == name)
    }
}

fn args() -> Args {
    let mut a = Args {
        quick: false,
        out: PathBuf::from("docs"),
        reference: PathBuf::from(REFERENCE),
        calculix: false,
        only: Vec::new(),
    };
    let mut it = std::env::args().skip(1);
    while let Some(x) = it.next() {
        match x.as_str() {
            "--quick" => a.quick = true,
            "--calculix" => a.calculix = true,
            "--only" => {
                a.only = it
                    .next()
                    .expect("--only SECTION[,SECTION…]")
                    .split(',')
                    .map(str::to_string)
                    .collect();
                if let Some(bad) = a.only.iter().find(|o| !SECTIONS.contains(&o.as_str())) {
                    eprintln!("unknown section {bad}; sections: {}", SECTIONS.join(", "));
                    std::process::exit(2);
                }
            }
            "--speed-run" => {
                let n = it
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--speed-run N");
                let ordering = it.next().expect("--speed-run N ORDERING MODE");
                let mode = it.next().expect("--speed-run N ORDERING MODE");
                speed_run(n, &ordering, &mode);
            }
            "--export-matrix" => {
                let n = it
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--export-matrix N FILE");
                export_matrix(n, Path::new(&it.next().expect("--export-matrix N FILE")));
            }
            "--faer-alone" => faer_alone(Path::new(&it.next().expect("--faer-alone FILE"))),
            "--out" => a.out = PathBuf::from(it.next().expect("--out DIR")),
            "--reference" => a.reference = PathBuf::from(it.next().expect("--reference FILE")),
            other => {
                eprintln!(
                    "unknown argument {other}; use --quick, --calculix, --only SECTION[,…], --out DIR, --reference FILE"
                );
                std::process::exit(2);
            }
        }
    }
    a
}

/// A curve of (time, error) points with a label, for the log-log plots.
struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
}

fn plot(
    path: &Path,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    curves: &[Curve],
) -> Result<(), Box<dyn std::error::Error>> {
    let all: Vec<(f64, f64)> = curves
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .filter(|p| p.0 > 0.0 && p.1 > 0.0)
        .collect();
    if all.is_empty() {
        return Ok(());
    }
    let (x0, x1) = all.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.0), b.max(p.0))
    });
    let (y0, y1) = all.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.1), b.max(p.1))
    });
    let root = SVGBackend::new(path, (820, 540)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (x0 / 1.5..x1 * 1.5).log_scale(),
            (y0 / 2.0..y1 * 2.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc(xlabel)
        .y_desc(ylabel)
        .draw()?;
    let palette = [RED, BLUE, GREEN, MAGENTA, CYAN, BLACK];
    for (c, col) in curves.iter().zip(palette.iter().cycle()) {
        let col = *col;
        chart
            .draw_series(LineSeries::new(c.points.clone(), col.stroke_width(2)))?
            .label(c.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2)));
        chart.draw_series(c.points.iter().map(|&p| Circle::new(p, 3, col.filled())))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

fn manufactured(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![8, 16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512, 724]
    };
    let mat = Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").expect("material");
    writeln!(
        report,
        "## Error against run time: manufactured elasticity\n"
    )
    .unwrap();
    writeln!(
        report,
        "u = (sin πx sin πy, sin 2πx sin πy) on the unit square, plane strain ν = 0.3, u prescribed on the \
         boundary. *Band*: the mesh contains a row of flattened caps of height 1e-9 along y = 1/2 \
         (docs/method.md §1). Energy error over the elements with J > 0 (the caps' true gradients are what \
         TFEM tempers, so on band meshes it measures the discrete function, not the tempered energy).\n"
    )
    .unwrap();
    let mut curves = Vec::new();
    for (name, band, tempering) in [
        ("regular, TFEM", None, Tempering::Auto),
        ("band, plain FEM", Some(1e-9), Tempering::Off),
        ("band, TFEM", Some(1e-9), Tempering::Auto),
    ] {
        writeln!(report, "### {name}\n\n| h | unknowns | time [s] | L2 error | energy error |\n|---|---|---|---|---|").unwrap();
        let mut pts: Vec<StudyPoint> = Vec::new();
        for &n in &levels {
            let n = if band.is_some() && n % 2 == 1 {
                n + 1
            } else {
                n
            };
            match run_manufactured_elasticity(unit_square(n, band), 1.0 / n as f64, mat, tempering)
            {
                Ok(p) => {
                    writeln!(
                        report,
                        "| 1/{n} | {} | {:.3} | {:.3e} | {:.3e} |",
                        p.unknowns, p.seconds, p.l2, p.energy
                    )
                    .unwrap();
                    pts.push(p);
                }
                Err(e) => writeln!(report, "| 1/{n} | – | – | {e} | |").unwrap(),
            }
        }
        let h: Vec<f64> = pts.iter().map(|p| p.h).collect();
        let l2: Vec<f64> = pts.iter().map(|p| p.l2).collect();
        let en: Vec<f64> = pts.iter().map(|p| p.energy).collect();
        let t: Vec<f64> = pts.iter().map(|p| p.seconds.max(1e-6)).collect();
        writeln!(
            report,
            "\nFitted rates in h: L2 {:.2}, energy {:.2}; L2 error against time: slope {:.2}.\n",
            fitted_rate(&h, &l2),
            fitted_rate(&h, &en),
            fitted_rate(&t, &l2)
        )
        .unwrap();
        curves.push(Curve {
            label: format!("{name} (L2)"),
            points: t.iter().copied().zip(l2).collect(),
        });
    }
    figure(
        report,
        a,
        "manufactured_error_time.svg",
        "manufactured elasticity: L2 error against wall time",
        "time [s]",
        "L2 error",
        &curves,
        "L2 error against time",
    );
}

/// Draws `curves` into `out/file` and links it from the report.
#[allow(clippy::too_many_arguments)]
fn figure(
    report: &mut String,
    a: &Args,
    file: &str,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    curves: &[Curve],
    alt: &str,
) {
    if let Err(e) = plot(&a.out.join(file), title, xlabel, ylabel, curves) {
        eprintln!("plot: {e}");
    }
    writeln!(report, "![{alt}]({file})\n").unwrap();
}

fn reference(a: &Args) -> Option<Value> {
    serde_json::from_str(&std::fs::read_to_string(&a.reference).ok()?).ok()
}

/// Seed-scene outputs from a displacement vector (2 per node).
fn outputs(s: &tfem::scenes::TwoBlocksScene, u: &[f64]) -> [f64; 3] {
    let f = s.model.load_vector().expect("loads");
    [
        u[2 * s.corner_upper + 1] - u[2 * s.corner_lower + 1],
        u[2 * s.top_center + 1],
        f.iter().zip(u).map(|(a, b)| a * b).sum(),
    ]
}

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

fn seed(report: &mut String, a: &Args) {
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

/// The contact patch test: uniform pressure over the whole width, so the
/// exact stress is σ_yy = −p everywhere; conforming and non-matching
/// (upper mesh 7/3 coarser) interfaces.
fn patch_test(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512]
    };
    writeln!(
        report,
        "## Error against run time: the contact patch test\n\n\
         Two blocks pressed together over the whole width (2C = L): the exact stress is uniform, \
         σ_yy = −p, σ_xx = τ_xy = 0. Relative L2 (area-weighted) and max stress error over all \
         elements, and the whole contact solve's time. Non-matching: upper block meshed 7/3 as \
         coarse (almost no interface node matches; B triangulates the strip).\n\n\
         | h | conforming: unknowns | L2 | max | time [s] | non-matching: unknowns | L2 | max | time [s] |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut curves = vec![
        Curve {
            label: "conforming".into(),
            points: vec![],
        },
        Curve {
            label: "non-matching (7:3)".into(),
            points: vec![],
        },
    ];
    let (mut hs, mut l2s) = (Vec::new(), Vec::new());
    for &n in &levels {
        let h = 1.0 / n as f64;
        let mut cells = Vec::new();
        for (k, upper) in [None, Some(h * 7.0 / 3.0)].into_iter().enumerate() {
            let scene = TwoBlocks {
                c: 0.5,
                mesh_size: h,
                upper_mesh_size: upper,
                ..Default::default()
            };
            let mut s = scene.build().expect("scene");
            let t0 = Instant::now();
            let Ok(r) = s.solve(&ContactOptions::default()) else {
                cells.push("failed | – | – | –".to_string());
                continue;
            };
            let total = t0.elapsed().as_secs_f64();
            let mesh = s.model.mesh().expect("mesh");
            let p = scene.p;
            let (mut sum, mut area, mut worst) = (0.0, 0.0, 0.0f64);
            for (t, sig) in mesh
                .triangles()
                .iter()
                .zip(s.model.element_stresses().expect("stresses"))
            {
                let ar = 0.5 * tfem::TriGeometry::new(&mesh.corners(t)).j;
                let e2 = ((sig[1] + p).powi(2) + sig[0].powi(2) + sig[2].powi(2)) / (p * p);
                sum += ar * e2;
                area += ar;
                worst = worst.max(e2.sqrt());
            }
            let l2 = (sum / area).sqrt();
            cells.push(format!(
                "{} | {l2:.2e} | {worst:.2e} | {total:.3}",
                r.report.info.unknowns
            ));
            curves[k].points.push((total, l2.max(1e-16)));
            if k == 1 {
                hs.push(h);
                l2s.push(l2);
            }
        }
        writeln!(report, "| 1/{n} | {} |", cells.join(" | ")).unwrap();
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nLargest non-matching L2 error over the levels: {:.2e}. Both interfaces pass the patch \
             test to round-off (docs/method.md §6.11; `cargo run --release --example patch_test` \
             sweeps ratios, jitter and moduli).\n",
            l2s.iter().fold(0.0f64, |m, &v| m.max(v))
        )
        .unwrap();
    }
    figure(
        report,
        a,
        "patch_error_time.svg",
        "contact patch test: L2 stress error against wall time",
        "time [s]",
        "relative L2 stress error",
        &curves,
        "patch test error against time",
    );
}

/// Hertz contact: the curved, gapped, possibly non-matching interface.
fn hertz(report: &mut String, a: &Args) {
    use tfem::scenes::hertz::Hertz;
    let levels: Vec<f64> = if a.quick {
        vec![4.0, 8.0, 16.0]
    } else {
        vec![4.0, 8.0, 16.0, 32.0, 64.0]
    };
    let base = Hertz::default();
    writeln!(
        report,
        "## Error against run time: Hertz contact\n\n\
         A cylinder (R = {}) pressed on a block, plane strain, frictionless, half model; the load \
         is chosen for a = {} R (`tfem::scenes::hertz`: graded built-in mesh, the cylinder's part \
         near the contact spans 40a, the block 100a). B is the strip triangulation of the curved gap. \
         *a*: where the block's nodal contact pressure ends; *p₀*: the block's nodal pressure on the \
         axis; *both sides*: the nodal pressure read from both sides of the interface \
         (`contact::traction::interface_pressures`, docs/method.md §6.11); *max inside 0.8a*: the \
         largest |p_node − p(x)|/p₀ over the block's nodes within 0.8a, for the block's own \
         reading and for both sides'; *fit*: least squares \
         of p² = p₀²(1 − x²/a²) over the inner 80 % of the contact. \
         Relative errors against a = √(4PR/(πE*)), p₀ = 2P/(πa); rates fitted in h.\n",
        base.radius, base.half_width
    )
    .unwrap();
    let cases = [
        ("equal moduli", Hertz::default()),
        (
            "cylinder 100× stiffer",
            Hertz {
                e_cylinder: 100.0 * base.e_block,
                ..base
            },
        ),
        (
            "cylinder 100× softer",
            Hertz {
                e_cylinder: 0.01 * base.e_block,
                ..base
            },
        ),
        (
            "non-matching (cylinder mesh 2.5× coarser)",
            Hertz {
                cylinder_mesh_ratio: 2.5,
                ..base
            },
        ),
        (
            "non-matching (cylinder mesh 2.5× finer)",
            Hertz {
                cylinder_mesh_ratio: 0.4,
                ..base
            },
        ),
    ];
    let mut curves = Vec::new();
    for (label, case) in cases {
        writeln!(
            report,
            "### {label}\n\n| h | unknowns | iterations | time [s] | err a | err p₀ | err p₀ (both sides) | max inside 0.8a | max inside 0.8a (both sides) | err a (fit) | err p₀ (fit) |\n|---|---|---|---|---|---|---|---|---|---|---|"
        )
        .unwrap();
        let (mut hs, mut ea, mut ep, mut eb, mut ef, mut pts) = (
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Vec::new(),
        );
        for &k in &levels {
            let hz = Hertz {
                mesh_size: case.half_width / k,
                ..case
            };
            let mut s = hz.build().expect("scene");
            let t0 = Instant::now();
            match s.solve(&hz, &ContactOptions::default()) {
                Ok(r) => {
                    let t = t0.elapsed().as_secs_f64();
                    let rel = |v: f64, e: f64| (v - e) / e;
                    writeln!(
                        report,
                        "| a/{k} | {} | {} | {t:.3} | {:+.2e} | {:+.2e} | {:+.2e} | {:.2e} | {:.2e} | {:+.2e} | {:+.2e} |",
                        r.report.info.unknowns,
                        r.report.iterations,
                        rel(r.a, r.a_exact),
                        rel(r.p0, r.p0_exact),
                        rel(r.p0_interface, r.p0_exact),
                        r.inner_error(&r.pressure),
                        r.inner_error(&r.interface_pressure),
                        rel(r.a_fit, r.a_exact),
                        rel(r.p0_fit, r.p0_exact)
                    )
                    .unwrap();
                    hs.push(1.0 / k);
                    ea.push(rel(r.a, r.a_exact).abs());
                    ep.push(rel(r.p0, r.p0_exact).abs());
                    eb.push(rel(r.p0_interface, r.p0_exact).abs());
                    ef.push(rel(r.p0_fit, r.p0_exact).abs());
                    pts.push((t, rel(r.p0_fit, r.p0_exact).abs()));
                }
                Err(e) => {
                    writeln!(report, "| a/{k} | {}: {} |", e.status().name(), e.message()).unwrap()
                }
            }
        }
        if hs.len() >= 2 {
            writeln!(
                report,
                "\nFitted rates in h: a {:.2}, p₀ {:.2}, p₀ (both sides) {:.2}, p₀ (fit) {:.2}.\n",
                fitted_rate(&hs, &ea),
                fitted_rate(&hs, &ep),
                fitted_rate(&hs, &eb),
                fitted_rate(&hs, &ef)
            )
            .unwrap();
        }
        curves.push(Curve {
            label: format!("{label}: p₀ (fit)"),
            points: pts,
        });
    }
    figure(
        report,
        a,
        "hertz_error_time.svg",
        "Hertz contact: relative error of the peak pressure (fit) against wall time",
        "time [s]",
        "relative error",
        &curves,
        "Hertz error against time",
    );
}

fn stability(report: &mut String, a: &Args) {
    let base = TwoBlocks {
        mesh_size: if a.quick { 1.0 / 32.0 } else { 1.0 / 64.0 },
        ..Default::default()
    };
    writeln!(report, "## Stability on stiff and extreme cases\n").unwrap();
    writeln!(
        report,
        "The seed scene at h = {:.5} unless stated. Residual: ‖Ku − f‖/‖f‖ of the final system; \
         condition: estimate for the Jacobi-scaled matrix; balance: support reaction / (p·2C) − 1; \
         finite: every displacement and pressure is finite. The same cases are asserted in \
         `tests/stability.rs`.\n",
        base.mesh_size
    )
    .unwrap();
    writeln!(report, "| case | status | iterations | residual | condition | ℓc/L | v_top/L | max penetration/L | balance | finite |\n|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut cases: Vec<(String, TwoBlocks, ContactOptions)> = Vec::new();
    for r in [1.0, 1e3, 1e6, 1e9, 1e12] {
        cases.push((
            format!("E2/E1 = {r:.0e}"),
            TwoBlocks {
                e2: base.e1 * r,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for nu in [0.0, 0.3, 0.49, 0.4999] {
        cases.push((
            format!("ν = {nu}"),
            TwoBlocks {
                nu1: nu,
                nu2: nu,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for lh in [0.1, 1.0, 10.0, 1e2, 1e4, 1e6] {
        cases.push((
            format!("λ/h = {lh:.0e} (contact)"),
            base,
            ContactOptions {
                lambda: Some(lh * base.mesh_size),
                ..Default::default()
            },
        ));
    }
    for k in [1e-6, 1e-3, 1e3, 1e6] {
        cases.push((
            format!("lengths ×{k:.0e}"),
            TwoBlocks {
                h1: base.h1 * k,
                h2: base.h2 * k,
                length: base.length * k,
                c: base.c * k,
                mesh_size: base.mesh_size * k,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    for g in [0.0, 1e-12, 1e-9, 1e-6] {
        cases.push((
            format!("initial gap {g:.0e} m"),
            TwoBlocks { gap: g, ..base },
            ContactOptions::default(),
        ));
    }
    if !a.quick {
        cases.push((
            "h = 1/1448 (2.1M unknowns)".into(),
            TwoBlocks {
                mesh_size: 1.0 / 1448.0,
                ..base
            },
            ContactOptions::default(),
        ));
    }
    cases.push((
        "no symmetry condition (free sliding)".into(),
        TwoBlocks {
            symmetry: false,
            ..base
        },
        ContactOptions::default(),
    ));
    cases.push((
        "no support (floating)".into(),
        TwoBlocks {
            support: false,
            ..base
        },
        ContactOptions::default(),
    ));
    for (name, scene, opts) in cases {
        let mut s = scene.build().expect("scene");
        match s.solve(&opts) {
            Ok(r) => {
                let finite = s
                    .model
                    .displacements()
                    .map(|u| u.iter().flatten().all(|v| v.is_finite()))
                    .unwrap_or(false);
                let l = scene.length;
                writeln!(
                    report,
                    "| {name} | ok | {} | {:.1e} | {:.1e} | {:.4} | {:.5e} | {:.2e} | {:+.1e} | {} |",
                    r.report.iterations,
                    r.report.info.relative_residual,
                    r.report.info.condition_estimate,
                    r.lc / l,
                    r.v_top / l,
                    r.report.max_penetration / l,
                    r.support_reaction / (scene.p * 2.0 * scene.c) - 1.0,
                    if finite { "yes" } else { "NO" }
                )
                .unwrap();
            }
            Err(e) => {
                let msg: String = e.message().chars().take(110).collect();
                writeln!(
                    report,
                    "| {name} | {} | – | – | – | – | – | – | – | no output: {msg}… |",
                    e.status().name()
                )
                .unwrap();
            }
        }
    }
    writeln!(report).unwrap();
    degenerate(report);
}

/// One body (E = 1, ν = 0.3, plane strain) clamped on its boundary under a
/// unit downward body force.
fn clamped(b: tfem::meshgen::MeshBuilder) -> tfem::Model {
    let boundary: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
    let mut model = tfem::Model::new();
    model.set_mesh(b.build().expect("mesh"));
    model
        .set_material(
            1,
            Material::new(1.0, 0.3, PlaneMode::Strain, "body 1").expect("material"),
        )
        .expect("material");
    for v in boundary {
        model.fix(v, tfem::Component::X, 0.0).expect("fix");
        model.fix(v, tfem::Component::Y, 0.0).expect("fix");
    }
    model.set_body_force(1, [0.0, -1.0]).expect("load");
    model
}

/// Degenerate and inverted elements, and a tempering λ too small for the
/// mesh: a unit square (16 × 16 cells, edges fixed, body force) with a band
/// of caps of height ε along y = 1/2, TFEM against plain FEM.
fn degenerate(report: &mut String) {
    writeln!(
        report,
        "### Degenerate and inverted elements, λ too small\n\n\
         Square [0, 1] × [−1/2, 1/2], 16 × 16 cells, edges fixed, unit body force, E = 1, ν = 0.3, \
         with a band of caps of height ε along y = 0 (J = ε/16; ε < 0: inverted caps). *max |u|*: relative to \
         the regular mesh without the band. Every case ends with a finite answer or a status naming \
         the element.\n\n\
         | case | status | max |u| vs regular | finite | warnings / message |\n|---|---|---|---|---|"
    )
    .unwrap();
    let solve = |eps: Option<f64>, tempering: Tempering| -> (tfem::Result<f64>, Vec<String>) {
        // Built with the band at y = 1/2 and moved to y = 0, where ε down to
        // 1e-300 is representable (0.5 + 1e-300 rounds to 0.5).
        let mut b = unit_square(16, eps.map(|_| 0.0));
        for p in &mut b.nodes {
            p[1] -= 0.5;
        }
        if let Some(eps) = eps {
            // The band's apex row follows the lower grid's 17 × 9 nodes.
            for p in &mut b.nodes[17 * 9..17 * 9 + 18] {
                p[1] = eps;
            }
        }
        let mut model = clamped(b);
        model.set_tempering(tempering).expect("tempering");
        let r = model.solve().and_then(|_| model.displacements()).map(|u| {
            u.iter().flatten().fold(0.0f64, |m, v| {
                if v.is_finite() {
                    m.max(v.abs())
                } else {
                    f64::NAN
                }
            })
        });
        (r, model.warnings())
    };
    let reference = solve(None, Tempering::Auto).0.unwrap_or(f64::NAN);
    let mut rows: Vec<(String, Option<f64>, Tempering)> = Vec::new();
    for eps in [0.0, 1e-300, -1e-9] {
        rows.push((format!("ε = {eps:.0e}, TFEM"), Some(eps), Tempering::Auto));
        rows.push((
            format!("ε = {eps:.0e}, plain FEM"),
            Some(eps),
            Tempering::Off,
        ));
    }
    rows.push((
        "regular mesh, TFEM with λ = h/10 (too small)".into(),
        None,
        Tempering::Lambda(0.1 / 16.0),
    ));
    for (name, eps, tempering) in rows {
        let (r, warnings) = solve(eps, tempering);
        match r {
            Ok(m) => {
                let w: String = warnings.join("; ").chars().take(140).collect();
                writeln!(
                    report,
                    "| {name} | ok | {:+.2e} | {} | {} |",
                    m / reference - 1.0,
                    if m.is_finite() { "yes" } else { "NO" },
                    if w.is_empty() {
                        "–".into()
                    } else {
                        format!("{w}…")
                    }
                )
                .unwrap();
            }
            Err(e) => {
                let msg: String = e.message().chars().take(140).collect();
                writeln!(report, "| {name} | {} | – | – | {msg} |", e.status().name()).unwrap();
            }
        }
    }
    writeln!(report).unwrap();
}

/// Peak resident memory of this process so far (VmHWM), in bytes; Linux
/// only (`None` elsewhere).
fn peak_rss() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024.0)
}

/// One contact solve of the seed scene in a fresh process (so that its
/// peak memory is its own): `report --speed-run N ORDERING MODE` prints one
/// JSON line. ORDERING: `nd`, `amd` or `nd-one-tree`; MODE: `condensed`
/// (the default loop), `refactorize`, or `single` (its first iteration
/// only).
/// A proportional history of `steps` load steps of the seed scene (factors
/// k/steps), its last step's displacements recovered, timed as a whole.
fn history_run(model: &mut tfem::Model, steps: usize, rss_mesh: Option<f64>) -> ! {
    let options = ContactOptions::default();
    let t0 = Instant::now();
    let (mut factorizations, mut iterations) = (0, 0);
    for k in 1..=steps {
        let r = model
            .step(k as f64 / steps as f64, &options)
            .expect("a load step");
        factorizations += r.info.factorizations;
        iterations += r.iterations;
    }
    let stepping = t0.elapsed().as_secs_f64();
    let u = model.displacements().expect("the last step's field");
    let total = t0.elapsed().as_secs_f64();
    println!(
        "{}",
        serde_json::json!({
            "steps": steps, "total": total, "stepping": stepping, "recovery": total - stepping,
            "factorizations": factorizations, "iterations": iterations,
            "u_checksum": u.iter().flatten().sum::<f64>(),
            "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

fn speed_run(n: usize, ordering: &str, mode: &str) -> ! {
    let rss0 = peak_rss();
    let mut s = TwoBlocks {
        mesh_size: 1.0 / n as f64,
        ..Default::default()
    }
    .build()
    .expect("scene");
    let rss_mesh = peak_rss();
    s.model.set_ordering(match ordering {
        "amd" => Ordering::Amd,
        _ => Ordering::NestedDissection,
    });
    // "nd-one-tree": nested dissection factorised as one tree.
    s.model.set_parallel_subtrees(ordering != "nd-one-tree");
    // "single": the first iteration only (one assembly, factorisation and
    // solve of the seed scene's matrix with the initial contact set), whose
    // peak memory is what a factorisation + solve of that matrix takes in
    // this library; the solve then stops short of convergence.
    if let Some(steps) = mode.strip_prefix("history") {
        history_run(&mut s.model, steps.parse().expect("a step count"), rss_mesh);
    }
    let single = mode == "single";
    let mut options = ContactOptions {
        refactorize: mode != "condensed",
        ..Default::default()
    };
    if single {
        options.max_iterations = 1;
    }
    let t0 = Instant::now();
    let r = s.model.solve_contact(&options);
    let total = t0.elapsed().as_secs_f64();
    if single {
        let status = r.as_ref().map_or_else(|e| e.status().name(), |_| "ok");
        println!(
            "{}",
            serde_json::json!({
                "status": status, "total": total, "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
            })
        );
        std::process::exit(0)
    }
    let r = r.expect("contact solve");
    let i = r.info;
    let t = i.timings;
    println!(
        "{}",
        serde_json::json!({
            "unknowns": i.unknowns, "interface": i.interface_unknowns, "factor_nnz": i.factor_nnz,
            "matrix_nnz": i.matrix_nnz, "factorization_bytes": i.factorization_bytes,
            "allocated": i.memory_bytes, "analysis": t.analysis, "assembly": t.assembly,
            "factorization": t.factorization, "solve": t.solve, "dense": t.interface, "total": total,
            "iterations": r.iterations, "factorizations": i.factorizations,
            "rss_start": rss0, "rss_mesh": rss_mesh, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

/// `report --export-matrix N FILE`: solves the seed scene (default options)
/// and writes the matrix of its converged system with a nested-dissection
/// permutation of it, for [`faer_alone`]. Little-endian: n, nnz (u64), the
/// column pointers and row indices (u64), the values (f64), the permutation
/// (u64, `perm[new] = old`).
fn export_matrix(n: usize, file: &Path) -> ! {
    let mut s = TwoBlocks {
        mesh_size: 1.0 / n as f64,
        ..Default::default()
    }
    .build()
    .expect("scene");
    s.model
        .solve_contact(&ContactOptions::default())
        .expect("contact solve");
    let k = s.model.system_matrix().expect("the converged matrix");
    // tfem's pattern also holds the inactive contact elements, as stored
    // zeros; the matrix handed over has only its nonzeros (and diagonal), so
    // that faer's factor is not inflated by them.
    let (mut col_ptr, mut row_idx, mut values) = (vec![0], Vec::new(), Vec::new());
    for (j, w) in k.col_ptr.windows(2).enumerate() {
        for p in w[0]..w[1] {
            if k.values[p] != 0.0 || k.row_idx[p] == j {
                row_idx.push(k.row_idx[p]);
                values.push(k.values[p]);
            }
        }
        col_ptr.push(row_idx.len());
    }
    let nodes = s.model.mesh().expect("mesh").nodes();
    let coords: Vec<[f64; 2]> = k.unknowns.iter().map(|&g| nodes[g / 2]).collect();
    let perm = tfem::ordering::nested_dissection(&col_ptr, &row_idx, &coords);
    let mut w = std::io::BufWriter::new(std::fs::File::create(file).expect("matrix file"));
    let words = [k.n(), values.len()].into_iter().chain(col_ptr);
    for x in words.chain(row_idx).map(|x| x as u64) {
        std::io::Write::write_all(&mut w, &x.to_le_bytes()).expect("write");
    }
    for x in values {
        std::io::Write::write_all(&mut w, &x.to_le_bytes()).expect("write");
    }
    for &x in &perm {
        std::io::Write::write_all(&mut w, &(x as u64).to_le_bytes()).expect("write");
    }
    std::io::Write::flush(&mut w).expect("write");
    std::process::exit(0)
}

/// Reads `len` little-endian 8-byte words, 1 MiB at a time so that reading
/// costs no more memory than the result.
fn read_words<T>(r: &mut impl std::io::Read, len: usize, from: fn([u8; 8]) -> T) -> Vec<T> {
    let mut out = Vec::with_capacity(len);
    let mut buf = vec![0u8; 1 << 20];
    while out.len() < len {
        let m = (len - out.len()).min(buf.len() / 8);
        r.read_exact(&mut buf[..8 * m]).expect("matrix file");
        out.extend(
            buf[..8 * m]
                .chunks_exact(8)
                .map(|c| from(c.try_into().unwrap())),
        );
    }
    out
}

/// `report --faer-alone FILE`: the baseline of "the factorisation alone" —
/// a process that holds the matrix of [`export_matrix`] and nothing else,
/// and runs faer's supernodal Cholesky on it with the given
/// nested-dissection permutation (symbolic analysis with the factor's
/// storage, one numeric factorisation, one solve). Prints its times and
/// peak memory as JSON.
fn faer_alone(file: &Path) -> ! {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::cholesky::llt::factor::LltRegularization;
    use faer::perm::PermRef;
    use faer::sparse::linalg::cholesky::{
        CholeskySymbolicParams, LltRef, SymmetricOrdering, factorize_symbolic_cholesky,
    };
    use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
    use faer::{Conj, MatMut, Par, Side};

    let mut r = std::io::BufReader::new(std::fs::File::open(file).expect("matrix file"));
    let u64le = |b: [u8; 8]| u64::from_le_bytes(b) as usize;
    let head = read_words(&mut r, 2, u64le);
    let (n, nnz) = (head[0], head[1]);
    let col_ptr = read_words(&mut r, n + 1, u64le);
    let row_idx = read_words(&mut r, nnz, u64le);
    let values = read_words(&mut r, nnz, f64::from_le_bytes);
    let perm = read_words(&mut r, n, u64le);
    drop(r);
    let mut inv = vec![0usize; n];
    for (new, &old) in perm.iter().enumerate() {
        inv[old] = new;
    }
    let rss_matrix = peak_rss();

    let t0 = Instant::now();
    let sym = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
    let ord = SymmetricOrdering::Custom(PermRef::new_checked(&perm, &inv, n));
    let symbolic =
        factorize_symbolic_cholesky(sym, Side::Upper, ord, CholeskySymbolicParams::default())
            .expect("symbolic");
    // The factor's storage is allocated and its pages written in the
    // analysis, as tfem does: otherwise the first-touch page faults (~900 MB
    // at 1M unknowns) would be timed as factorisation here and as analysis
    // there.
    let mut l_values = Vec::with_capacity(symbolic.len_val());
    l_values.resize(symbolic.len_val(), 0.0);
    let analysis = t0.elapsed().as_secs_f64();
    let par = Par::rayon(0);
    let t0 = Instant::now();
    let mut mem =
        MemBuffer::new(symbolic.factorize_numeric_llt_scratch::<f64>(par, Default::default()));
    let a = SparseColMatRef::new(sym, &values);
    symbolic
        .factorize_numeric_llt(
            &mut l_values,
            a,
            Side::Upper,
            LltRegularization::default(),
            par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .expect("positive definite");
    drop(mem);
    let factorization = t0.elapsed().as_secs_f64();
    let t0 = Instant::now();
    let mut x = vec![1.0; n];
    let mut mem = MemBuffer::new(symbolic.solve_in_place_scratch::<f64>(1, par));
    LltRef::new(&symbolic, &l_values).solve_in_place_with_conj(
        Conj::No,
        MatMut::from_column_major_slice_mut(&mut x, n, 1),
        par,
        MemStack::new(&mut mem),
    );
    let solve = t0.elapsed().as_secs_f64();
    assert!(
        x.iter().all(|v| v.is_finite()),
        "faer's solve is not finite"
    );
    println!(
        "{}",
        serde_json::json!({
            "unknowns": n, "matrix_nnz": nnz, "factor_nnz": symbolic.len_val(),
            "analysis": analysis, "factorization": factorization, "solve": solve,
            "rss_matrix": rss_matrix, "rss_peak": peak_rss(),
        })
    );
    std::process::exit(0)
}

/// The seed scene's converged matrix at h = 1/n through [`export_matrix`]
/// and [`faer_alone`], each in its own process; the file is removed.
fn faer_child(n: usize) -> Option<Value> {
    let exe = std::env::current_exe().ok()?;
    let file =
        std::env::temp_dir().join(format!("tfem-report-matrix-{}-{n}.bin", std::process::id()));
    let file_arg = file.to_str()?;
    let exported = std::process::Command::new(&exe)
        .args(["--export-matrix", &n.to_string(), file_arg])
        .status()
        .ok()?
        .success();
    let out = exported
        .then(|| {
            std::process::Command::new(&exe)
                .args(["--faer-alone", file_arg])
                .output()
                .ok()
        })
        .flatten();
    let _ = std::fs::remove_file(&file);
    let text = String::from_utf8_lossy(&out?.stdout).into_owned();
    serde_json::from_str(text.lines().last()?).ok()
}

fn child(n: usize, ordering: &str, mode: &str) -> Option<Value> {
    let out = std::process::Command::new(std::env::current_exe().ok()?)
        .args(["--speed-run", &n.to_string(), ordering, mode])
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.lines().last()?).ok()
}

fn speed(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![64, 128]
    } else {
        vec![128, 256, 512, 1024, 1448]
    };
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    writeln!(report, "## Speed and scaling\n").unwrap();
    writeln!(
        report,
        "Seed scene, 2C/L = 0.2, nested-dissection ordering; each run in its own process (peak \
         memory = that process's VmHWM). *fact.+solve*: one numeric factorisation with its \
         singularity check (three inverse-iteration solves) plus one solve, from the refactorising \
         loop (its mean per iteration). *condensed*: the default loop (one factorisation with the \
         interface numbered last, dense interface updates, final recovery and refinement). \
         *ratio*: condensed loop without the symbolic analysis (paid once per mesh, kept across \
         solves) over fact.+solve; *ratio incl.*: with it. *factorisation [MB]*: what one numeric \
         factorisation needs at its peak — factor values, symbolic structure and faer's workspace \
         (`SolveInfo::factorization_bytes`); *matrix*: the CSC matrix it reads (pattern and values). \
         *peak / fact.*: the condensed solve's peak RSS (mesh, model, matrix, factor, interface, \
         results, allocator) over the factorisation; *peak / (fact. + matrix)*: over the \
         factorisation with its input; *fact.+solve peak*: the peak RSS of a process that builds \
         the same scene and runs only the first iteration (one assembly, one factorisation + solve \
         of the matrix with the initial contact set, no interface), i.e. what one factorisation + \
         solve of that matrix takes in this library; *peak / fact.+solve peak*: the whole contact \
         solve's peak over it.\n"
    )
    .unwrap();
    writeln!(report, "| h | unknowns | interface unknowns | iterations | analysis [s] | fact.+solve [s] | refactorising loop [s] | condensed loop [s] | ratio | ratio incl. | dense interface [s] | assembly / fact. | factorisation [MB] | matrix [MB] | peak RSS [MB] | peak / fact. | peak / (fact. + matrix) | fact.+solve peak [MB] | peak / fact.+solve peak |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut scaling: Vec<(f64, f64, f64)> = Vec::new();
    let mut orderings = Vec::new();
    let mut against_faer = Vec::new();
    for &n in &levels {
        let (Some(full), Some(cond)) = (child(n, "nd", "refactorize"), child(n, "nd", "condensed"))
        else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        let per = (f(&full, "factorization") + f(&full, "solve")) / f(&full, "factorizations");
        let factorization = f(&cond, "factorization_bytes");
        let matrix = 8.0 * (f(&cond, "unknowns") + 1.0 + 2.0 * f(&cond, "matrix_nnz"));
        let peak = f(&cond, "rss_peak");
        // Only a run that got through its one iteration is a baseline (it
        // stops with "not converged", or "ok" if one iteration settled).
        let single_peak = child(n, "nd", "single")
            .filter(|v| matches!(v["status"].as_str(), Some("not converged" | "ok")))
            .map_or(f64::NAN, |v| f(&v, "rss_peak"));
        writeln!(
            report,
            "| 1/{n} | {} | {} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.3} | {:.0} | {:.0} | {:.0} | {:.2} | {:.2} | {:.0} | {:.2} |",
            cond["unknowns"],
            cond["interface"],
            cond["iterations"],
            f(&cond, "analysis"),
            per,
            f(&full, "total"),
            f(&cond, "total"),
            (f(&cond, "total") - f(&cond, "analysis")) / per,
            f(&cond, "total") / per,
            f(&cond, "dense"),
            f(&cond, "assembly") / f(&cond, "factorization"),
            factorization / 1e6,
            matrix / 1e6,
            peak / 1e6,
            peak / factorization,
            peak / (factorization + matrix),
            single_peak / 1e6,
            peak / single_peak,
        )
        .unwrap();
        scaling.push((f(&cond, "unknowns"), f(&cond, "total"), peak));
        against_faer.push((n, faer_child(n), cond.clone()));
        if let (Some(amd), Some(one)) = (
            child(n, "amd", "condensed"),
            child(n, "nd-one-tree", "condensed"),
        ) {
            orderings.push((n, amd, one, cond));
        }
    }
    if scaling.len() >= 2 {
        let d: Vec<f64> = scaling.iter().map(|s| s.0).collect();
        let t: Vec<f64> = scaling.iter().map(|s| s.1).collect();
        let m: Vec<f64> = scaling.iter().map(|s| s.2).collect();
        writeln!(
            report,
            "\nFitted exponents against unknowns (condensed contact solve): time ∝ N^{:.2}, peak memory ∝ N^{:.2}.\n",
            fitted_rate(&d, &t),
            fitted_rate(&d, &m)
        )
        .unwrap();
    }
    writeln!(
        report,
        "### Against faer alone\n\nThe factorisation alone, measured: a process that reads the \
         converged matrix of the same scene (written by another process; its nonzeros, without \
         the inactive contact elements' stored zeros) with a nested-dissection permutation of \
         it, holds nothing else, and runs faer's supernodal Cholesky once (symbolic analysis, which \
         also allocates and writes the factor's storage as tfem's does; numeric factorisation; \
         one solve; `report --faer-alone`). Its peak \
         RSS includes the matrix it reads. Against it, the whole condensed contact solve of the \
         table above (its own process: mesh, model, every iteration, results). *time ratio*: the \
         contact solve without its symbolic analysis over faer's factorisation + solve; *incl.*: \
         both with their analyses.\n\n\
         | h | unknowns | faer factor nnz | faer analysis [s] | faer factorisation [s] | faer solve [s] | faer peak RSS [MB] | contact solve [s] | contact peak RSS [MB] | time ratio | time ratio incl. | memory ratio |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (n, alone, cond) in &against_faer {
        let Some(alone) = alone else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        let fact_solve = f(alone, "factorization") + f(alone, "solve");
        writeln!(
            report,
            "| 1/{n} | {} | {:.3e} | {:.2} | {:.2} | {:.2} | {:.0} | {:.2} | {:.0} | {:.2} | {:.2} | {:.2} |",
            alone["unknowns"],
            f(alone, "factor_nnz"),
            f(alone, "analysis"),
            f(alone, "factorization"),
            f(alone, "solve"),
            f(alone, "rss_peak") / 1e6,
            f(cond, "total"),
            f(cond, "rss_peak") / 1e6,
            (f(cond, "total") - f(cond, "analysis")) / fact_solve,
            f(cond, "total") / (f(alone, "analysis") + fact_solve),
            f(cond, "rss_peak") / f(alone, "rss_peak"),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
    writeln!(
        report,
        "### Orderings\n\nThe one factorisation (with its singularity check) of the condensed loop, \
         each in its own process, with the interface numbered last: faer's AMD on the whole \
         matrix; geometric nested dissection factorised by faer as one tree (*ND, one tree*: \
         parallel only inside dense blocks); and nested dissection as tfem runs it by default, \
         the two bodies (the subtrees below the interface) factorised concurrently and the \
         interface as a dense block (*ND*; `Model::set_parallel_subtrees`).\n\n\
         | h | unknowns | factor nnz AMD | factor nnz ND, one tree | factor nnz ND | factorisation AMD [s] | ND, one tree [s] | ND [s] | AMD / ND, one tree | AMD / ND |\n|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    for (n, amd, one, nd) in &orderings {
        writeln!(
            report,
            "| 1/{n} | {} | {:.3e} | {:.3e} | {:.3e} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
            nd["unknowns"],
            f(amd, "factor_nnz"),
            f(one, "factor_nnz"),
            f(nd, "factor_nnz"),
            f(amd, "factorization"),
            f(one, "factorization"),
            f(nd, "factorization"),
            f(amd, "factorization") / f(one, "factorization"),
            f(amd, "factorization") / f(nd, "factorization"),
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

/// The seed scene's contact sides as a host code would describe them: its
/// nodes, their equations (free DOFs numbered in global order), edges with
/// the body on the left.
fn host_contact_of(model: &tfem::Model) -> (tfem::contact::HostContact, Vec<Option<usize>>) {
    use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER};
    let mesh = model.mesh().expect("a mesh");
    let fixed: std::collections::BTreeSet<usize> = model.constraints().map(|c| c.0).collect();
    let mut next = 0;
    let equation: Vec<Option<usize>> = (0..2 * mesh.nodes().len())
        .map(|g| {
            (!fixed.contains(&g)).then(|| {
                next += 1;
                next - 1
            })
        })
        .collect();
    let mut hc = tfem::contact::HostContact::new(0, ContactOptions::default()).expect("context");
    let mut sides = Vec::new();
    for tag in [TAG_CONTACT_LOWER, TAG_CONTACT_UPPER] {
        let (mut nodes, mut edges, mut body) = (Vec::new(), Vec::new(), 0);
        for e in mesh.boundary_edges().iter().filter(|e| e.tag == tag) {
            let (t, third) = e.owner.expect("a boundary edge");
            body = mesh.body_of()[t];
            let [p, q] = e.nodes;
            let (a, b, c) = (mesh.nodes()[p], mesh.nodes()[q], mesh.nodes()[third]);
            let left = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0.0;
            edges.push(if left {
                [p as i64, q as i64]
            } else {
                [q as i64, p as i64]
            });
            nodes.extend([p, q]);
        }
        nodes.sort_unstable();
        nodes.dedup();
        let ids: Vec<i64> = nodes.iter().map(|&v| v as i64).collect();
        let xy: Vec<[f64; 2]> = nodes.iter().map(|&v| mesh.nodes()[v]).collect();
        let eq: Vec<[i64; 2]> = nodes
            .iter()
            .map(|&v| [0, 1].map(|c| equation[2 * v + c].map_or(-1, |e| e as i64)))
            .collect();
        let material = *model.material(body).expect("a material");
        sides.push(
            hc.add_side(tag, body, material, &ids, &xy, &eq, &edges)
                .expect("a side"),
        );
    }
    hc.add_pair(sides[0], sides[1]).expect("a pair");
    (hc, equation)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn histories(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick { vec![64] } else { vec![512, 1024] };
    let f = |v: &Value, k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    writeln!(report, "## Load histories\n").unwrap();
    writeln!(
        report,
        "The seed scene (2C/L = 0.2) loaded in 100 proportional steps (factors k/100, \
         `Model::step`), the last step's displacements recovered, against one contact solve of \
         the full load; each run in its own process. One factorisation serves the whole history \
         (the first step's); every later step is dense work on the contact interface, \
         warm-started from the step before. The last step equals the one-step answer to \
         round-off (`tests/history.rs`).\n"
    )
    .unwrap();
    writeln!(report, "| h | unknowns | one solve [s] | 100 steps [s] | of which recovery [s] | ratio | factorisations | active-set iterations | peak RSS one solve / history [MB] |\n|---|---|---|---|---|---|---|---|---|").unwrap();
    for &n in &levels {
        let (Some(one), Some(h)) = (child(n, "nd", "condensed"), child(n, "nd", "history100"))
        else {
            writeln!(report, "| 1/{n} | run failed |").unwrap();
            continue;
        };
        writeln!(
            report,
            "| 1/{n} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {} | {} | {:.0} / {:.0} |",
            one["unknowns"],
            f(&one, "total"),
            f(&h, "total"),
            f(&h, "recovery"),
            f(&h, "total") / f(&one, "total"),
            h["factorizations"],
            h["iterations"],
            f(&one, "rss_peak") / 1e6,
            f(&h, "rss_peak") / 1e6,
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

fn host_codes(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![32, 64]
    } else {
        vec![64, 128, 256, 512, 1024]
    };
    writeln!(
        report,
        "## Contact for host codes
"
    )
    .unwrap();
    writeln!(
        report,
        "`tfem_contact` (`tfem::contact::HostContact`) on the seed scene (2C/L = 0.2): the two \
         interface sides described as a host code would (its nodes, equations, edges), B built \
         once (*setup*: sides, pairs, B, laws, pattern), then the per-call cost of \
         `evaluate` (values of the tangent in the fixed pattern and the contact residual, at the \
         converged displacements; median of 21 calls, no allocation) and of `update` (the \
         inversion test; median of 21 calls on a fresh loop each), against the body assembly \
         of tfem's own solve at the same size (*assembly*: element matrices and scatter into the \
         pattern, the work a host's own assembly does).\n"
    )
    .unwrap();
    writeln!(report, "| h | unknowns | elements of B | pattern entries | setup [ms] | evaluate [µs] | update [µs] | body assembly [ms] | evaluate / assembly |\n|---|---|---|---|---|---|---|---|---|").unwrap();
    for &n in &levels {
        let mut scene = TwoBlocks {
            c: 0.1,
            mesh_size: 1.0 / n as f64,
            ..Default::default()
        }
        .build()
        .expect("scene");
        let info = scene
            .model
            .solve_contact(&ContactOptions::default())
            .expect("contact")
            .info;
        let u = scene.model.displacements().expect("displacements");
        let t0 = Instant::now();
        let (mut hc, _) = host_contact_of(&scene.model);
        let entries = hc.pattern().expect("pattern").0.len();
        let setup = t0.elapsed().as_secs_f64();
        let u_if: Vec<f64> = hc.nodes().iter().flat_map(|&v| u[v as usize]).collect();
        let mut values = vec![0.0; entries];
        let mut residual = vec![0.0; u_if.len()];
        let evaluate = median(
            (0..21)
                .map(|_| {
                    let t = Instant::now();
                    hc.evaluate(&u_if, Some(&mut values), Some(&mut residual))
                        .expect("evaluate");
                    t.elapsed().as_secs_f64()
                })
                .collect(),
        );
        let update = median(
            (0..21)
                .map(|_| {
                    hc.restart().expect("restart");
                    let t = Instant::now();
                    hc.update(&u_if).expect("update");
                    t.elapsed().as_secs_f64()
                })
                .collect(),
        );
        writeln!(
            report,
            "| 1/{n} | {} | {} | {} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1e} |",
            info.unknowns,
            hc.elements().expect("B").len(),
            entries,
            1e3 * setup,
            1e6 * evaluate,
            1e6 * update,
            1e3 * info.timings.assembly,
            evaluate / info.timings.assembly
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

/// The Q4 host of examples/host_q4.cpp (its own bilinear quadrilaterals,
/// Eigen's sparse Cholesky, tfem_contact's contributions) beside tfem's P1
/// on the seed scene at 2C/L = 0.4: error against run time. Needs g++ and
/// Eigen (Debian's libeigen3-dev, which the README's test command installs);
/// without them the section says so.
fn q4_host(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![16, 32]
    } else {
        vec![16, 32, 64, 128, 256, 512]
    };
    writeln!(
        report,
        "## Error against run time: a Q4 host code beside P1\n\n\
         `examples/host_q4.cpp`, a host code with its own bilinear quadrilaterals (2×2 Gauss), its \
         own assembly, Eigen's SimplicialLLT and its own active-set loop on tfem's contact \
         contributions (`tfem_contact_*`), against tfem's own P1 solve, on the seed scene at \
         2C/L = 0.4 (same h: the Q4 mesh has half as many cells as P1 has triangles, hence about \
         the same unknowns). Relative errors against the shipped reference. Times: the whole \
         solve without the mesh; the host refactorises at every active-set iteration.\n"
    )
    .unwrap();
    let lib = std::env::current_exe()
        .ok()
        .and_then(|e| e.parent()?.parent().map(Path::to_path_buf))
        .unwrap_or_default();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let exe = lib.join("report_host_q4");
    let eigen = Path::new("/usr/include/eigen3");
    let built = lib.join("libtfem.so").exists()
        && eigen.exists()
        && std::process::Command::new("g++")
            .args(["-O2", "-std=c++17", "-I/usr/include/eigen3"])
            .arg(format!("-I{}", root.join("include").display()))
            .arg(root.join("examples/host_q4.cpp"))
            .arg("-o")
            .arg(&exe)
            .arg(format!("-L{}", lib.display()))
            .arg("-ltfem")
            .arg(format!("-Wl,-rpath,{}", lib.display()))
            .status()
            .is_ok_and(|s| s.success());
    if !built {
        writeln!(
            report,
            "Not measured: g++, Eigen (/usr/include/eigen3) or {}/libtfem.so missing \
             (`cargo build --release --lib`).\n",
            lib.display()
        )
        .unwrap();
        return;
    }
    let mut args: Vec<String> = vec!["--c".into(), "0.2".into(), "--json".into()];
    for &n in &levels {
        args.extend(["--n".into(), n.to_string()]);
    }
    args.extend(["--reference".into(), a.reference.display().to_string()]);
    let out = match std::process::Command::new(&exe).args(&args).output() {
        Ok(o) if o.status.success() => String::from_utf8_lossy(&o.stdout).to_string(),
        Ok(o) => {
            writeln!(
                report,
                "host_q4 failed: {}\n",
                String::from_utf8_lossy(&o.stderr)
            )
            .unwrap();
            return;
        }
        Err(e) => {
            writeln!(report, "host_q4 did not run: {e}\n").unwrap();
            return;
        }
    };
    let q4: Vec<Value> = out
        .lines()
        .filter(|l| l.starts_with("{\"element\""))
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect();
    let case = reference(a).map(|r| r["cases"]["canonical_0.4"].clone());
    writeln!(
        report,
        "| h | P1 unknowns | P1 time [s] | P1 err gap_edge | P1 err v_top | P1 err compliance | Q4 unknowns | Q4 time [s] | Q4 iterations | Q4 err gap_edge | Q4 err v_top | Q4 err compliance |\n|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut errs: [Vec<f64>; 6] = Default::default();
    let mut hs = Vec::new();
    for (&n, q) in levels.iter().zip(&q4) {
        let mut s = TwoBlocks {
            c: 0.2,
            mesh_size: 1.0 / n as f64,
            ..Default::default()
        }
        .build()
        .expect("scene");
        let t0 = Instant::now();
        let r = s.solve(&ContactOptions::default()).expect("P1 solve");
        let t = t0.elapsed().as_secs_f64();
        let rel = |name: &str, v: f64| -> f64 {
            case.as_ref()
                .and_then(|cs| cs[name]["value"].as_f64())
                .map_or(f64::NAN, |rv| (v - rv) / rv)
        };
        let p1 = [
            rel("gap_edge", r.gap_edge),
            rel("v_top", r.v_top),
            rel("compliance", r.compliance),
        ];
        let qe = ["gap_edge", "v_top", "compliance"].map(|k| {
            q[format!("{k}_relative_error")]
                .as_f64()
                .unwrap_or(f64::NAN)
        });
        hs.push(1.0 / n as f64);
        for k in 0..3 {
            errs[k].push(p1[k]);
            errs[3 + k].push(qe[k]);
        }
        writeln!(
            report,
            "| 1/{n} | {} | {t:.3} | {:+.2e} | {:+.2e} | {:+.2e} | {} | {:.3} | {} | {:+.2e} | {:+.2e} | {:+.2e} |",
            r.report.info.unknowns,
            p1[0],
            p1[1],
            p1[2],
            q["unknowns"],
            q["time_total_s"].as_f64().unwrap_or(f64::NAN),
            q["iterations"],
            qe[0],
            qe[1],
            qe[2]
        )
        .unwrap();
    }
    if hs.len() >= 3 {
        let k0 = hs.len() - 3;
        let rate = |e: &[f64]| {
            let e: Vec<f64> = e[k0..].iter().map(|v| v.abs()).collect();
            fitted_rate(&hs[k0..], &e)
        };
        writeln!(
            report,
            "\nFitted log-log rates over the three finest sizes: P1 gap_edge {:.2}, v_top {:.2}, \
             compliance {:.2}; Q4 gap_edge {:.2}, v_top {:.2}, compliance {:.2}.",
            rate(&errs[0]),
            rate(&errs[1]),
            rate(&errs[2]),
            rate(&errs[3]),
            rate(&errs[4]),
            rate(&errs[5])
        )
        .unwrap();
    }
    writeln!(report).unwrap();
}

fn built(report: &mut String) {
    writeln!(report, "## What each scene built\n").unwrap();
    writeln!(report, "| scene | contact elements in B | matrix nnz | factor nnz | memory [MB] |\n|---|---|---|---|---|").unwrap();
    // Without contact: the same two blocks glued by nothing but each held on
    // its own (solve, not solve_contact): no contact structure exists.
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 64.0,
        ..Default::default()
    }
    .build()
    .expect("scene");
    let rc = s
        .model
        .solve_contact(&ContactOptions::default())
        .expect("contact");
    writeln!(
        report,
        "| seed scene, contact | {} | {} | {} | {:.1} |",
        rc.elements,
        rc.info.matrix_nnz,
        rc.info.factor_nnz,
        rc.info.memory_bytes as f64 / 1e6
    )
    .unwrap();
    let mut model = clamped(unit_square(128, None));
    let i = model.solve().expect("solve");
    writeln!(
        report,
        "| unit square 128², no contact | {} | {} | {} | {:.1} |\n",
        model.contact_elements().map_or(0, |c| c.len()),
        i.matrix_nnz,
        i.factor_nnz,
        i.memory_bytes as f64 / 1e6
    )
    .unwrap();
    writeln!(
        report,
        "A scene without contact pairs builds no contact mesh, no contact pattern entries and no \
         active-set state (`contact_elements()` is an error: there are none). Strains, stresses, \
         reactions and contact pressures are computed only when asked for (accessors), never during \
         the solve. The core library builds without the optional I/O (`--no-default-features`: no \
         `vtkio` in the dependency tree, no Gmsh reader; checked in CI).\n"
    )
    .unwrap();
}

/// Where and when the report is measured: CPU model (from Linux's
/// /proc/cpuinfo when there is one), architecture, cores, memory, and the
/// UTC date.
fn machine_and_date() -> String {
    let proc_line = |file: &str, key: &str| {
        let text = std::fs::read_to_string(file).ok()?;
        let line = text.lines().find(|l| l.starts_with(key))?;
        Some(line.split(':').nth(1)?.trim().to_string())
    };
    let cpu = proc_line("/proc/cpuinfo", "model name").unwrap_or_else(|| "unknown CPU".into());
    let memory = proc_line("/proc/meminfo", "MemTotal")
        .and_then(|m| m.trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(String::new(), |kb| format!(", {:.0} GiB", kb / 1_048_576.0));
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (y, m, d) = civil_from_days((secs / 86400) as i64);
    format!(
        "{cpu}, {}, {} cores{memory}, {y:04}-{m:02}-{d:02} {:02}:{:02} UTC",
        std::env::consts::ARCH,
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        secs % 86400 / 3600,
        secs % 3600 / 60
    )
}

/// The proleptic Gregorian date (year, month, day) of a day count from
/// 1970-01-01: H. Hinnant's `civil_from_days` (eras of 400 years, years
/// starting in March so that the leap day comes last).
fn civil_from_days(days: i64) -> (i64, i64, i64) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

fn main() {
    let a = args();
    std::fs::create_dir_all(&a.out).expect("output directory");
    let t0 = Instant::now();
    let mut report = String::new();
    writeln!(report, "# tfem report\n").unwrap();
    let stamp = machine_and_date();
    writeln!(
        report,
        "Generated by `cargo run --release --example report{}` on {stamp}. Times are wall-clock \
         seconds of single runs on a shared machine: compare rows, not machines.\n",
        match (a.quick, a.calculix) {
            (true, _) => " -- --quick",
            (false, true) => " -- --calculix",
            (false, false) => "",
        },
    )
    .unwrap();
    type Section = fn(&mut String, &Args);
    let sections: [(&str, Section); 18] = [
        ("manufactured", manufactured),
        ("seed", seed),
        ("patch_test", patch_test),
        ("patch_ratios", patch_ratios),
        ("hertz", hertz),
        ("interference", interference),
        ("indenters", indenters),
        ("many_bodies", many_bodies),
        ("stability", stability),
        ("speed", speed),
        ("histories", histories),
        ("interface_cost", interface_cost),
        ("friction", friction),
        ("cattaneo", cattaneo),
        ("calculix", calculix),
        ("host_codes", host_codes),
        ("q4_host", q4_host),
        ("built", |r, _| built(r)),
    ];
    assert!(sections.iter().map(|s| s.0).eq(SECTIONS.iter().copied()));
    for (name, section) in sections {
        // CalculiX is opt-in: CI does not install it, and it takes minutes.
        let wanted = a.wants(name)
            && (name != "calculix"
                || (!a.quick && (a.calculix || a.only.iter().any(|o| o == name))));
        if wanted {
            let t = Instant::now();
            section(&mut report, &a);
            eprintln!("section {name}: {:.1} s", t.elapsed().as_secs_f64());
        }
    }
    // Every section, hence every table, names where and when it was measured.
    let mut report: String = report
        .lines()
        .flat_map(|line| {
            let stamp = line
                .starts_with("## ")
                .then(|| format!("\n*Measured on {stamp}.*\n"));
            [Some(format!("{line}\n")), stamp].into_iter().flatten()
        })
        .collect();
    writeln!(
        report,
        "Report generated in {:.0} s.",
        t0.elapsed().as_secs_f64()
    )
    .unwrap();
    let path = a.out.join("report.md");
    std::fs::write(&path, report).expect("write the report");
    println!("wrote {}", path.display());
}

/// A failed solve's cell: its status and the first clause of its message.
fn failure(e: &tfem::Error) -> String {
    format!(
        "{}: {}",
        e.status().name(),
        e.message().split(';').next().unwrap_or("")
    )
}

/// Errors as "a, b, c" with three digits.
fn sci_list(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:.1e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Issue: the contact patch test on every interface ratio, both ways, on
/// uniform and jittered grids and two material pairs.
fn patch_ratios(report: &mut String, a: &Args) {
    use tfem::scenes::patch::PatchTest;
    let levels: Vec<usize> = if a.quick {
        vec![8, 16, 32]
    } else {
        vec![8, 16, 32, 64, 128]
    };
    let finest = *levels.last().expect("levels");
    writeln!(
        report,
        "## The contact patch test on every interface ratio\n\n\
         Two blocks under a uniform pressure p over the whole top (`tfem::scenes::patch`): the exact \
         solution is σ_yy = −p, σ_xx = τ_xy = 0 and a contact pressure p everywhere. Ratio: upper \
         cell width over lower (2:3 means 1.5, its reverse 3:2); jitter 0.3: every interior grid \
         column moved by up to 0.3 of a cell, so no interface nodes line up. Max stress error: over \
         every element, √Σ(σ − σ_exact)² / p, at each h = {}; nodal pressure error: the largest \
         |p_node/p − 1| over both interface sides and every h; released: elements of B not active \
         at convergence over every h (all should be active); times: building the scene and its contact solve, at each h.\n",
        levels
            .iter()
            .map(|n| format!("1/{n}"))
            .collect::<Vec<_>>()
            .join(", ")
    )
    .unwrap();
    writeln!(
        report,
        "| E2/E1 | ratio | jitter | max stress error / p (h = 1/{} … 1/{finest}) | nodal pressure error | released | iterations (max) | times [s] (h = 1/{} … 1/{finest}) |\n|---|---|---|---|---|---|---|---|",
        levels[0], levels[0]
    )
    .unwrap();
    let ratios: [(&str, f64); 7] = [
        ("1:1", 1.0),
        ("2:3", 1.5),
        ("3:2", 2.0 / 3.0),
        ("3:7", 7.0 / 3.0),
        ("7:3", 3.0 / 7.0),
        ("5:8", 1.6),
        ("8:5", 5.0 / 8.0),
    ];
    let (mut worst, mut worst_nodal, mut releases, mut failures) = (0.0f64, 0.0f64, 0, 0);
    // Round-off grows like the condition number, ~1/h²: 1e-8 p is far
    // above it at h = 1/128 and far below any discretisation error.
    let mut above = Vec::new();
    for (e_ratio, e1, e2) in [(1.0, 1e10, 1e10), (10.0, 1e10, 1e11)] {
        for &(name, ratio) in &ratios {
            for jitter in [0.0, 0.3] {
                let (mut errs, mut nodal, mut released, mut iters, mut times) =
                    (Vec::new(), 0.0f64, 0, 0, Vec::new());
                let mut failed = Vec::new();
                for &n in &levels {
                    let test = PatchTest {
                        e_lower: e1,
                        e_upper: e2,
                        mesh_size: 1.0 / n as f64,
                        ratio,
                        jitter,
                        ..Default::default()
                    };
                    let t0 = Instant::now();
                    let r = test
                        .build()
                        .and_then(|mut s| s.solve(&test, &ContactOptions::default()));
                    let t = t0.elapsed().as_secs_f64();
                    match r {
                        Ok(r) => {
                            errs.push(r.max_error);
                            nodal = nodal
                                .max((r.nodal_pressure.0 - 1.0).abs())
                                .max((r.nodal_pressure.1 - 1.0).abs());
                            released += r.released;
                            iters = iters.max(r.report.iterations);
                            times.push(format!("{t:.3}"));
                        }
                        Err(e) => failed.push(format!("1/{n} {}", failure(&e))),
                    }
                }
                for (&n, &e) in levels.iter().zip(&errs) {
                    if e > 1e-8 {
                        above.push(format!(
                            "E2/E1 = {e_ratio}, {name}, jitter {jitter}, h = 1/{n}: {e:.1e}"
                        ));
                    }
                }
                worst = errs.iter().fold(worst, |m, &v| m.max(v));
                worst_nodal = worst_nodal.max(nodal);
                releases += released;
                failures += failed.len();
                writeln!(
                    report,
                    "| {e_ratio} | {name} ({ratio:.3}) | {jitter} | {}{} | {nodal:.1e} | {released} | {iters} | {} |",
                    sci_list(&errs),
                    if failed.is_empty() {
                        String::new()
                    } else {
                        format!("; failed: {}", failed.join(", "))
                    },
                    times.join(", ")
                )
                .unwrap();
            }
        }
    }
    writeln!(
        report,
        "\nOver all {} solves: largest max stress error {worst:.1e} p, largest nodal pressure \
         error {worst_nodal:.1e} p, {releases} false release(s), {failures} failed solve(s). \
         Max stress errors above 1e-8 p (not round-off): {}.\n",
        2 * ratios.len() * 2 * levels.len(),
        if above.is_empty() {
            "none".to_string()
        } else {
            above.join("; ")
        }
    )
    .unwrap();
}

/// Issue: Lamé shrink fits, every element of B inverted at the start.
fn interference(report: &mut String, a: &Args) {
    use tfem::scenes::lame::Lame;
    let levels: Vec<f64> = if a.quick {
        vec![8.0, 16.0, 32.0]
    } else {
        vec![8.0, 16.0, 32.0, 64.0, 128.0]
    };
    let base = Lame::default();
    writeln!(
        report,
        "## Interference fits: the Lamé shrink fit\n\n\
         Two concentric rings overlapping by a radial interference δ (`tfem::scenes::lame`: a = {}, \
         b = {}, c = {}, inner E = {:.0e} ν = {}, outer E = {:.0e} ν = {}; quarter model, polar \
         criss-cross mesh of size h), every element of B inverted at the start (J0 < 0), against \
         the closed-form shrink fit of two rings of different materials. Errors relative to the \
         closed-form contact pressure p: *pressure*, the largest nodal contact pressure error on \
         both surfaces; *hoop* and *radial*, the largest error of a grid cell's mean σ_θθ, σ_rr \
         against the closed form at the cell's centre; *bore hoop*, the outer ring's hoop stress \
         along its bore relative to itself. Rates fitted in h.\n",
        base.inner_radius,
        base.radius,
        base.outer_radius,
        base.e_inner,
        base.nu_inner,
        base.e_outer,
        base.nu_outer
    )
    .unwrap();
    writeln!(
        report,
        "| plane | δ/b | h | unknowns | iterations | time [s] | p (closed form) [Pa] | pressure error | hoop error | radial error | bore hoop error |\n|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let mut rates = Vec::new();
    for plane in [PlaneMode::Strain, PlaneMode::Stress] {
        for delta in [1e-2, 1e-4, 1e-6] {
            let (mut hs, mut ep, mut eh, mut er) = (vec![], vec![], vec![], vec![]);
            for &k in &levels {
                let lame = Lame {
                    interference: delta * base.radius,
                    plane,
                    mesh_size: base.radius / k,
                    ..base
                };
                let t0 = Instant::now();
                let r = lame
                    .build()
                    .and_then(|mut s| s.solve(&lame, &ContactOptions::default()));
                let t = t0.elapsed().as_secs_f64();
                match r {
                    Ok(r) => {
                        writeln!(
                            report,
                            "| {plane:?} | {delta:.0e} | b/{k} | {} | {} | {t:.3} | {:.4e} | {:.2e} | {:.2e} | {:.2e} | {:.2e} |",
                            r.report.info.unknowns,
                            r.report.iterations,
                            r.exact.pressure,
                            r.pressure_error,
                            r.hoop_error,
                            r.radial_error,
                            r.bore_hoop_error
                        )
                        .unwrap();
                        hs.push(1.0 / k);
                        ep.push(r.pressure_error);
                        eh.push(r.hoop_error);
                        er.push(r.radial_error);
                    }
                    Err(e) => writeln!(
                        report,
                        "| {plane:?} | {delta:.0e} | b/{k} | {} | | | | | | | |",
                        failure(&e)
                    )
                    .unwrap(),
                }
            }
            if hs.len() >= 2 {
                rates.push(format!(
                    "| {plane:?} | {delta:.0e} | {:.2} | {:.2} | {:.2} |",
                    fitted_rate(&hs, &ep),
                    fitted_rate(&hs, &eh),
                    fitted_rate(&hs, &er)
                ));
            }
        }
    }
    writeln!(
        report,
        "\nFitted rates in h:\n\n| plane | δ/b | pressure | hoop | radial |\n|---|---|---|---|---|\n{}\n",
        rates.join("\n")
    )
    .unwrap();
}

/// Issue: rigid indenters, a flat punch (Sneddon) and a rigid cylinder
/// (Hertz with E* of the block alone).
fn indenters(report: &mut String, a: &Args) {
    use tfem::scenes::hertz::Hertz;
    use tfem::scenes::punch::{FlatPunch, RigidCylinder};
    let options = ContactOptions::default();
    let punch_levels: Vec<f64> = if a.quick {
        vec![8.0, 16.0, 32.0]
    } else {
        vec![8.0, 16.0, 32.0, 64.0, 128.0]
    };
    let base = FlatPunch::default();
    writeln!(
        report,
        "## Rigid indenters\n\n\
         ### Flat punch\n\n\
         A rigid flat punch of half-width a = {} pressed by a prescribed indentation into a block \
         of {}a × {}a (`tfem::scenes::punch`, plane strain, half model, frictionless; the block's \
         contact side extends to 2a so the contact's extent is the method's answer). *ℓc/a*: \
         contact length over the punch's half-width (1 exactly: the whole face, nothing beyond); \
         *pressure error*: the largest error of the block's nodal pressure against Sneddon's \
         P/(π√(a² − x²)) over 0 ≤ x ≤ 0.8a (away from the singular edge), relative to the \
         pressure there, P from the punch's reactions; *balance*: |P − support reaction| / P.\n",
        base.half_width, base.block_size, base.block_size
    )
    .unwrap();
    writeln!(
        report,
        "| h | unknowns | iterations | time [s] | P [N/m] | ℓc/a | active / elements of B | pressure error | balance |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let (mut hs, mut es) = (vec![], vec![]);
    for &k in &punch_levels {
        let punch = FlatPunch {
            mesh_size: base.half_width / k,
            ..base
        };
        let t0 = Instant::now();
        let r = punch.build().and_then(|mut s| s.solve(&punch, &options));
        let t = t0.elapsed().as_secs_f64();
        match r {
            Ok(r) => {
                writeln!(
                    report,
                    "| a/{k} | {} | {} | {t:.3} | {:.4e} | {:.6} | {} / {} | {:.2e} | {:.1e} |",
                    r.report.info.unknowns,
                    r.report.iterations,
                    r.force,
                    r.contact_length / punch.half_width,
                    r.active.0,
                    r.active.1,
                    r.pressure_error,
                    r.balance
                )
                .unwrap();
                hs.push(1.0 / k);
                es.push(r.pressure_error);
            }
            Err(e) => writeln!(report, "| a/{k} | {} | | | | | | | |", failure(&e)).unwrap(),
        }
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nFitted rate of the pressure error in h: {:.2}.\n",
            fitted_rate(&hs, &es)
        )
        .unwrap();
    }
    let cyl_levels: Vec<f64> = if a.quick {
        vec![4.0, 8.0, 16.0]
    } else {
        vec![4.0, 8.0, 16.0, 32.0, 64.0]
    };
    let rc0 = RigidCylinder::default();
    writeln!(
        report,
        "### Rigid cylinder\n\n\
         The Hertz scene's cylinder (R = {}) made rigid: every node translated by {:.3e} downwards \
         (`RigidCylinder`), the block elastic. Hertz for a rigid indenter, E* = E/(1 − ν²) of the \
         block alone: a = √(4PR/(πE*)), p₀ = 2P/(πa), P the cylinder's reaction; *a* and *p₀* \
         measured as in the Hertz section above (nodal, and fitted over the inner 80 %). Relative \
         errors; rates fitted in h.\n",
        rc0.hertz.radius, rc0.indentation
    )
    .unwrap();
    writeln!(
        report,
        "| h | unknowns | iterations | time [s] | P [N/m] | a/R (from P) | err a | err p₀ (fit) | err p₀ (nodal) |\n|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let (mut hs, mut ea, mut ep) = (vec![], vec![], vec![]);
    for &k in &cyl_levels {
        let rc = RigidCylinder {
            hertz: Hertz {
                mesh_size: rc0.hertz.half_width / k,
                ..rc0.hertz
            },
            ..rc0
        };
        let t0 = Instant::now();
        let r = rc.build().and_then(|mut s| s.solve(&rc, &options));
        let t = t0.elapsed().as_secs_f64();
        match r {
            Ok(r) => {
                let h = &r.hertz;
                let rel = |v: f64, e: f64| (v - e) / e;
                writeln!(
                    report,
                    "| a/{k} | {} | {} | {t:.3} | {:.4e} | {:.5} | {:+.2e} | {:+.2e} | {:+.2e} |",
                    h.report.info.unknowns,
                    h.report.iterations,
                    r.force,
                    h.a_exact / rc.hertz.radius,
                    rel(h.a, h.a_exact),
                    rel(h.p0_fit, h.p0_exact),
                    rel(h.p0, h.p0_exact)
                )
                .unwrap();
                hs.push(1.0 / k);
                ea.push(rel(h.a, h.a_exact).abs());
                ep.push(rel(h.p0_fit, h.p0_exact).abs());
            }
            Err(e) => writeln!(report, "| a/{k} | {} | | | | | | | |", failure(&e)).unwrap(),
        }
    }
    if hs.len() >= 2 {
        writeln!(
            report,
            "\nFitted rates in h: a {:.2}, p₀ (fit) {:.2}.\n",
            fitted_rate(&hs, &ea),
            fitted_rate(&hs, &ep)
        )
        .unwrap();
    }
}

/// Issue: many bodies — a stack, SSNP167's ring in a ring, a running-bond
/// wall, and automatic pairing against declared pairs.
fn many_bodies(report: &mut String, a: &Args) {
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
    // default cap of 50 iterations (as examples/interface_cost.rs).
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
/// refactorisation (examples/interface_cost.rs, one run per row).
fn interface_cost(report: &mut String, a: &Args) {
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

/// A seed-scene run for the friction and CalculiX sections.
struct SeedRun {
    result: tfem::scenes::TwoBlocksResult,
    /// Build and solve (every step), seconds.
    seconds: f64,
    factorizations: usize,
    /// Active-set iterations summed over the steps.
    iterations: usize,
}

/// The seed scene built and loaded in `steps` proportional steps (1: one
/// contact solve). A failed step is reported with its index.
fn seed_steps(scene: TwoBlocks, steps: usize) -> Result<SeedRun, String> {
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
/// Cattaneo–Mindlin partial slip (docs/method.md §6.15): TFEM's frictional
/// elements and the exact node-to-node frictional oracle on the same
/// meshes, against Johnson's stick half-width and shear traction.
fn cattaneo(report: &mut String, a: &Args) {
    use tfem::scenes::cattaneo::CattaneoMindlin;
    let levels: Vec<f64> = if a.quick {
        vec![8.0, 16.0, 32.0]
    } else {
        vec![8.0, 16.0, 32.0, 64.0]
    };
    let ratios = [0.15, 0.3, 0.45, 0.6];
    let base = CattaneoMindlin::default();
    writeln!(
        report,
        "## Cattaneo–Mindlin partial slip\n\n\
         A cylinder (R = 1) pressed on a block in plane strain to the Hertz half-width a = 0.005R \
         in one step, then sheared at that load by Q/(μP) = 0.15, 0.3, 0.45, 0.6 (μ = 0.3, equal \
         steel-like bodies, Dundurs β = 0; `tfem::scenes::cattaneo`). Each tangential step is \
         repeated (reverted) until it hits its Q, by a secant on the platen's displacement. \
         Against Johnson §7.1: stick half-width c = a√(1 − Q/(μP)), measured as *c_fit* (a \
         least-squares fit of the stick nodes' deficit (μp − q)² over |x| ≤ 0.8c), error \
         |c_fit − c|/a; shear traction q(x) = μp₀[√(1 − x²/a²) − (c/a)√(1 − x²/c²)], error \
         ‖q_h − q‖/‖q‖ over the node pairs. *TFEM*: the frictional elements of B, one \
         factorisation for the whole history. *Oracle*: exact node-to-node Coulomb contact on \
         the same meshes (`tfem::oracle::frictional`, a primal-dual active set on node-pair multipliers). Time: every step \
         and secant trial (TFEM includes building and factorising; the oracle's set-up is \
         separate).\n\n\
         | h | method | time [s] | contact iterations | c error at Q/(μP) = 0.15, 0.3, 0.45, 0.6 | q error (L2) at the same |\n\
         |---|---|---|---|---|---|"
    )
    .unwrap();
    let list = |v: &[f64]| {
        v.iter()
            .map(|e| format!("{e:.2e}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (mut tfem_c, mut oracle_c, mut tfem_q, mut oracle_q) = (vec![], vec![], vec![], vec![]);
    for &k in &levels {
        let cm = CattaneoMindlin {
            mesh_size: base.half_width / k,
            ..base
        };
        let t0 = Instant::now();
        let tfem = cm.build().and_then(|mut s| s.solve_tfem(&cm, &ratios));
        let tfem_seconds = t0.elapsed().as_secs_f64();
        match tfem {
            Ok(out) => {
                let c: Vec<f64> = out.steps[1..]
                    .iter()
                    .map(|s| (s.c_fit - s.analytic.c).abs() / s.analytic.a)
                    .collect();
                let q: Vec<f64> = out.steps[1..].iter().map(|s| s.q_error_l2).collect();
                writeln!(
                    report,
                    "| a/{k} | TFEM | {tfem_seconds:.2} | {} | {} | {} |",
                    out.iterations,
                    list(&c),
                    list(&q)
                )
                .unwrap();
                tfem_c.push(c);
                tfem_q.push(q);
            }
            Err(e) => writeln!(report, "| a/{k} | TFEM | {tfem_seconds:.2} | {e} | | |").unwrap(),
        }
        let oracle = cm.build().and_then(|s| s.solve(&cm, &ratios));
        match oracle {
            Ok(sol) => {
                let c: Vec<f64> = sol
                    .tangential
                    .iter()
                    .map(|s| (s.c_fit - s.analytic.c).abs() / s.analytic.a)
                    .collect();
                let q: Vec<f64> = sol.tangential.iter().map(|s| s.q_error_l2).collect();
                let seconds: f64 = std::iter::once(&sol.normal)
                    .chain(&sol.tangential)
                    .map(|s| s.seconds)
                    .sum();
                let iterations: usize = std::iter::once(&sol.normal)
                    .chain(&sol.tangential)
                    .map(|s| s.step.iterations)
                    .sum();
                writeln!(
                    report,
                    "| a/{k} | oracle (set-up {:.2} s) | {seconds:.2} | {iterations} | {} | {} |",
                    sol.setup_seconds,
                    list(&c),
                    list(&q)
                )
                .unwrap();
                oracle_c.push(c);
                oracle_q.push(q);
            }
            Err(e) => writeln!(report, "| a/{k} | oracle | | {e} | | |").unwrap(),
        }
    }
    let h: Vec<f64> = levels.iter().map(|k| 1.0 / k).collect();
    let rates = |table: &[Vec<f64>]| {
        if table.len() != levels.len() {
            return "–".to_string();
        }
        (0..ratios.len())
            .map(|i| {
                let e: Vec<f64> = table.iter().map(|r| r[i]).collect();
                format!("{:.2}", fitted_rate(&h, &e))
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    writeln!(
        report,
        "| fitted rate | TFEM | | | {} | {} |\n| fitted rate | oracle | | | {} | {} |\n",
        rates(&tfem_c),
        rates(&tfem_q),
        rates(&oracle_c),
        rates(&oracle_q)
    )
    .unwrap();
    writeln!(
        report,
        "q has square-root kinks at c and at a, so its error falls at about h¹ in L2 and hardly in \
         max (docs/method.md §6.15). Q/(μP) = 0.15 leaves a slip zone of 0.08a, under one element \
         at a/8.\n"
    )
    .unwrap();
}

fn friction(report: &mut String, a: &Args) {
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

/// `ccx` on the PATH, if any.
fn find_ccx() -> Option<PathBuf> {
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join("ccx"))
            .find(|p| p.is_file())
    })
}

/// Memory the kernel says is available, bytes.
fn mem_available() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = s.lines().find(|l| l.starts_with("MemAvailable:"))?;
    Some(line.split_whitespace().nth(1)?.parse::<f64>().ok()? * 1024.0)
}

/// One CalculiX run through scripts/calculix/run.sh: its JSON, or why not.
fn ccx_run(h: f64, mu: f64, steps: usize) -> Result<Value, String> {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/scripts/calculix/run.sh");
    let out = std::process::Command::new("bash")
        .args([
            script,
            "--h",
            &format!("{h:.17}"),
            "--mu",
            &mu.to_string(),
            "--steps",
            &steps.to_string(),
            "--workdir",
            "/tmp/tfem-ccx-report",
        ])
        .output()
        .map_err(|e| format!("cannot run {script}: {e}"))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(format!(
            "run.sh failed: {}",
            err.lines().last().unwrap_or("").replace('|', "/")
        ));
    }
    let text = String::from_utf8_lossy(&out.stdout);
    serde_json::from_str(text.lines().last().unwrap_or("")).map_err(|e| format!("bad JSON: {e}"))
}

/// Issue 20: CalculiX 2.20 beside tfem on the same meshes, in the same run
/// (`--calculix`).
fn calculix(report: &mut String, _a: &Args) {
    writeln!(report, "## CalculiX beside tfem, measured in this run\n").unwrap();
    let Some(ccx) = find_ccx() else {
        writeln!(
            report,
            "Skipped: `ccx` is not on the PATH (Debian: `apt-get install -y calculix-ccx`).\n"
        )
        .unwrap();
        return;
    };
    let version = std::process::Command::new(&ccx)
        .arg("-v")
        .output()
        .ok()
        .map(|o| {
            String::from_utf8_lossy(&o.stdout)
                .lines()
                .find(|l| l.contains("Version"))
                .unwrap_or("version unknown")
                .trim()
                .trim_start_matches("This is ")
                .to_string()
        })
        .unwrap_or_else(|| "version unknown".into());
    writeln!(
        report,
        "CalculiX ({}, `{}`) on the seed scene (2C/L = 0.2) through `scripts/calculix/run.sh` \
         (docs/calculix.md: tfem's mesh node for node, CPE3, node-to-surface penalty contact with \
         tfem's penalty, `*STATIC, DIRECT` with exactly N increments, SPOOLES, one thread), and \
         tfem on the same mesh with the same μ and N (`Model::step` with factors k/N). Times: \
         CalculiX's process alone (deck generation and parsing excluded) against tfem's build and \
         solve of every step, one run each. Differences (tfem − CalculiX)/CalculiX of the outputs \
         (CalculiX prints 7 digits); both are discretisations of the same problem with different \
         contact formulations (a penalty node-to-surface law, tfem's strip B), so the differences \
         are not errors of either: they measure how far the two codes' answers lie apart on one \
         mesh. The 67k case is run in 1 step only (100 CalculiX increments there take 6–8 minutes \
         each); 265k in 1 step only, when ≥ 10 GB are free (CalculiX took 8.5 GB) and the CalculiX part has \
         taken less than 6 minutes so far.\n",
        version,
        ccx.display()
    )
    .unwrap();
    writeln!(
        report,
        "| h | μ | N | unknowns tfem / equations CalculiX | t tfem [s] | t CalculiX [s] | CalculiX / tfem | Newton iterations CalculiX | active-set iterations tfem | gap_edge diff | slip_edge diff | v_top diff | compliance diff | ℓc diff |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    )
    .unwrap();
    let runs: &[(usize, f64, usize)] = &[
        (96, 0.0, 1),
        (96, 0.3, 1),
        (96, 0.0, 100),
        (96, 0.3, 100),
        (256, 0.0, 1),
        (256, 0.3, 1),
        (512, 0.0, 1),
        (512, 0.3, 1),
    ];
    let t_all = Instant::now();
    for &(n, mu, steps) in runs {
        let h = 1.0 / n as f64;
        let lead = format!("| 1/{n} | {mu} | {steps} |");
        if n >= 512 {
            let free = mem_available().unwrap_or(0.0);
            if free < 10e9 {
                writeln!(
                    report,
                    "{lead} skipped: {:.1} GB available, CalculiX needs about 8.5 GB | | | | | | | | | | |",
                    free / 1e9
                )
                .unwrap();
                continue;
            }
            if t_all.elapsed().as_secs_f64() > 360.0 {
                writeln!(
                    report,
                    "{lead} skipped: the CalculiX part already took {:.0} s of its ~10 min | | | | | | | | | | |",
                    t_all.elapsed().as_secs_f64()
                )
                .unwrap();
                continue;
            }
        }
        let ours = seed_steps(
            TwoBlocks {
                mesh_size: h,
                mu,
                ..TwoBlocks::default()
            },
            steps,
        );
        let theirs = ccx_run(h, mu, steps);
        match (ours, theirs) {
            (Ok(t), Ok(c)) => {
                let f = |k: &str| c[k].as_f64().unwrap_or(f64::NAN);
                let r = &t.result;
                let d = |ours: f64, k: &str| format!("{:+.2e}", (ours - f(k)) / f(k));
                let finished = c["finished"].as_bool().unwrap_or(false);
                writeln!(
                    report,
                    "{lead} {} / {} | {:.3} | {:.2} | {:.0}× | {}{} | {} | {} | {} | {} | {} | {} |",
                    r.report.info.unknowns,
                    c["equations"],
                    t.seconds,
                    f("time_s"),
                    f("time_s") / t.seconds,
                    c["newton_iterations"],
                    if finished { "" } else { " (NOT finished)" },
                    t.iterations,
                    d(r.gap_edge, "gap_edge"),
                    d(r.slip_edge, "slip_edge"),
                    d(r.v_top, "v_top"),
                    d(r.compliance, "compliance"),
                    d(r.lc, "lc")
                )
                .unwrap();
            }
            (t, c) => writeln!(
                report,
                "{lead} tfem: {} | CalculiX: {} | | | | | | | | | | |",
                t.err().unwrap_or_else(|| "ok".into()),
                c.err().unwrap_or_else(|| "ok".into())
            )
            .unwrap(),
        }
    }
    writeln!(
        report,
        "\nThe CalculiX part took {:.0} s in all.\n",
        t_all.elapsed().as_secs_f64()
    )
    .unwrap();
}
