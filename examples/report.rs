//! Regenerates `docs/report.md` and its pictures: error against run time for
//! the verification scenes and the seed scene, stability on stiff and
//! extreme cases, speed with both orderings, and what each scene built.
//!
//!   cargo run --release --example report               # full, up to ~1M unknowns (~10 min)
//!   cargo run --release --example report -- --quick    # small sizes, for CI

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use plotters::prelude::*;
use serde_json::Value;
use tfem::meshgen::unit_square;
use tfem::scenes::TwoBlocks;
use tfem::verification::{StudyPoint, fitted_rate, run_manufactured_elasticity};
use tfem::{ContactOptions, Material, Ordering, PlaneMode, Tempering};

struct Args {
    quick: bool,
    out: PathBuf,
    reference: PathBuf,
}

fn args() -> Args {
    let mut a = Args {
        quick: false,
        out: PathBuf::from("docs"),
        reference: PathBuf::from("../shared/reference/two_blocks_canonical.json"),
    };
    let mut it = std::env::args().skip(1);
    while let Some(x) = it.next() {
        match x.as_str() {
            "--quick" => a.quick = true,
            "--out" => a.out = PathBuf::from(it.next().expect("--out DIR")),
            "--reference" => a.reference = PathBuf::from(it.next().expect("--reference FILE")),
            other => {
                eprintln!("unknown argument {other}; use --quick, --out DIR, --reference FILE");
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
         (METHOD.md §1). Energy error over the elements with J > 0 (the caps' true gradients are what \
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
    let file = a.out.join("manufactured_error_time.svg");
    if let Err(e) = plot(
        &file,
        "manufactured elasticity: L2 error against wall time",
        "time [s]",
        "L2 error",
        &curves,
    ) {
        eprintln!("plot: {e}");
    }
    writeln!(
        report,
        "![L2 error against time](manufactured_error_time.svg)\n"
    )
    .unwrap();
}

fn reference(a: &Args) -> Option<Value> {
    serde_json::from_str(&std::fs::read_to_string(&a.reference).ok()?).ok()
}

fn seed(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![16, 32, 64]
    } else {
        vec![16, 32, 64, 128, 256, 512, 1024]
    };
    let refs = reference(a);
    writeln!(report, "## Error against run time: the seed scene\n").unwrap();
    writeln!(
        report,
        "Canonical parameters (METHOD.md §4), frictionless law, defaults. Relative errors against the \
         independent reference (GetFEM, exact frictionless contact, extrapolated; `{}`), when found. \
         Times: analysis (pattern, ordering, symbolic), assembly, numeric factorisations, solves, whole \
         contact solve.\n",
        a.reference.display()
    )
    .unwrap();
    let mut curves = Vec::new();
    for c in [0.1, 0.2, 0.3] {
        let key = format!("canonical_{:.1}", 2.0 * c);
        let case = refs.as_ref().map(|r| r["cases"][&key].clone());
        writeln!(report, "### 2C/L = {:.1}\n", 2.0 * c).unwrap();
        writeln!(
            report,
            "| h | unknowns | iterations | analysis | assembly | factorisations | solves | total [s] | memory [MB] | ℓc | err ℓc | err gap_edge | err v_top | err compliance | max penetration |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
        )
        .unwrap();
        let mut pts = Vec::new();
        for &n in &levels {
            let mut s = TwoBlocks {
                c,
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .expect("scene");
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
            let i = r.report.info;
            writeln!(
                report,
                "| 1/{n} | {} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {:.0} | {:.4} | {} | {} | {} | {} | {:.2e} |",
                i.unknowns,
                r.report.iterations,
                i.timings.analysis,
                i.timings.assembly,
                i.timings.factorization,
                i.timings.solve,
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
            if let Some(rv) = case
                .as_ref()
                .and_then(|cs| cs["compliance"]["value"].as_f64())
            {
                pts.push((total, ((r.compliance - rv) / rv).abs()));
            }
        }
        writeln!(report).unwrap();
        if !pts.is_empty() {
            curves.push(Curve {
                label: format!("2C/L = {:.1}: compliance", 2.0 * c),
                points: pts,
            });
        }
    }
    let file = a.out.join("seed_error_time.svg");
    if let Err(e) = plot(
        &file,
        "seed scene: relative error of the compliance against wall time",
        "time [s]",
        "relative error",
        &curves,
    ) {
        eprintln!("plot: {e}");
    }
    writeln!(
        report,
        "![seed scene error against time](seed_error_time.svg)\n"
    )
    .unwrap();
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
}

fn speed(report: &mut String, a: &Args) {
    let levels: Vec<usize> = if a.quick {
        vec![64, 128]
    } else {
        vec![128, 256, 512, 1024, 1448]
    };
    writeln!(report, "## Speed and scaling\n").unwrap();
    writeln!(
        report,
        "Seed scene, 2C/L = 0.2, one run per row. *fact.+solve*: one numeric factorisation with its \
         singularity check (three inverse-iteration solves) plus one solve with refinement. The \
         contact loop refactorises at every iteration.\n"
    )
    .unwrap();
    writeln!(report, "| h | unknowns | ordering | factor nnz | memory [MB] | analysis [s] | fact.+solve [s] | contact solve [s] | iterations | contact/(fact.+solve) | assembly/fact. |\n|---|---|---|---|---|---|---|---|---|---|---|").unwrap();
    let mut scaling: Vec<(f64, f64, f64)> = Vec::new();
    for &n in &levels {
        for ordering in [Ordering::Amd, Ordering::NestedDissection] {
            let mut s = TwoBlocks {
                mesh_size: 1.0 / n as f64,
                ..Default::default()
            }
            .build()
            .expect("scene");
            s.model.set_ordering(ordering);
            let t0 = Instant::now();
            let Ok(r) = s.model.solve_contact(&ContactOptions::default()) else {
                continue;
            };
            let total = t0.elapsed().as_secs_f64();
            let i = r.info;
            let per = (i.timings.factorization + i.timings.solve) / i.factorizations as f64;
            writeln!(
                report,
                "| 1/{n} | {} | {ordering:?} | {:.3e} | {:.0} | {:.2} | {:.2} | {:.2} | {} | {:.1} | {:.3} |",
                i.unknowns,
                i.factor_nnz as f64,
                i.memory_bytes as f64 / 1e6,
                i.timings.analysis,
                per,
                total,
                r.iterations,
                total / per,
                (i.timings.assembly / i.factorizations as f64) / (i.timings.factorization / i.factorizations as f64)
            )
            .unwrap();
            if ordering == Ordering::NestedDissection {
                scaling.push((i.unknowns as f64, per, i.memory_bytes as f64));
            }
        }
    }
    if scaling.len() >= 2 {
        let d: Vec<f64> = scaling.iter().map(|s| s.0).collect();
        let t: Vec<f64> = scaling.iter().map(|s| s.1).collect();
        let m: Vec<f64> = scaling.iter().map(|s| s.2).collect();
        writeln!(
            report,
            "\nFitted exponents against unknowns (nested dissection): time of one factorisation + solve ∝ N^{:.2}, memory ∝ N^{:.2}.\n",
            fitted_rate(&d, &t),
            fitted_rate(&d, &m)
        )
        .unwrap();
    }
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
    let b = unit_square(128, None);
    let mut model = tfem::Model::new();
    let boundary: Vec<usize> = b.boundary_edges().into_iter().flatten().collect();
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
         `vtkio`, no `mshio` in the dependency tree; checked in CI).\n"
    )
    .unwrap();
}

fn main() {
    let a = args();
    std::fs::create_dir_all(&a.out).expect("output directory");
    let t0 = Instant::now();
    let mut report = String::new();
    writeln!(report, "# tfem report\n").unwrap();
    writeln!(
        report,
        "Generated by `cargo run --release --example report{}` on {} ({} cores), unix time {}. \
         Times are wall-clock seconds of single runs on a shared machine: compare rows, not machines.\n",
        if a.quick { " -- --quick" } else { "" },
        std::env::consts::ARCH,
        std::thread::available_parallelism().map_or(1, |n| n.get()),
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs())
    )
    .unwrap();
    manufactured(&mut report, &a);
    seed(&mut report, &a);
    stability(&mut report, &a);
    speed(&mut report, &a);
    built(&mut report);
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
