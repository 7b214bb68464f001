//! The seed scene (docs/method.md §4): two elastic blocks in frictionless contact,
//! pressed over 2C on top and supported over 2C below. Prints the contact
//! length ℓc, the opening at the corner, the top displacement and the
//! compliance, and compares them with the independent reference when the
//! parameters are canonical. Files only when asked: `--vtu` writes the
//! solved state for ParaView (`<out>/two_blocks.vtu`), `--picture` a PNG of
//! the exaggerated deformed shape coloured by v (`<out>/two_blocks.png`,
//! 1200×800 pixels whatever the mesh).
//!
//!   cargo run --release --example two_blocks                 # h = 1/64, 2C/L = 0.2
//!   cargo run --release --example two_blocks -- --c 0.3 --mesh-size 0.005 --json
//!   cargo run --release --example two_blocks -- --vtu --picture --out results
//!   cargo run --release --example two_blocks -- --sweep      # ℓc against h (seed Fig. 6)

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Parser, ValueEnum};
use plotters::prelude::*;
use serde_json::{Value, json};
use tfem::model::adapt::{AdaptOptions, AdaptReport, Cycle, Goal};
use tfem::scenes::{TwoBlocks, TwoBlocksResult, TwoBlocksScene};
use tfem::{ContactLaw, ContactOptions, InversionTest};

/// The reference values shipped in the repository (see
/// `docs/reference/README.md`), found from any working directory.
const REFERENCE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/docs/reference/two_blocks_canonical.json"
);

#[derive(Debug, Clone, Copy, ValueEnum)]
enum Law {
    Frictionless,
    Stick,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum Test {
    Linearised,
    Literal,
}

/// The seed scene of tfem: two blocks in frictionless contact.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// Young's modulus of the lower block Ω1 [Pa].
    #[arg(long, default_value_t = 1e10)]
    e1: f64,
    /// Poisson ratio of Ω1.
    #[arg(long, default_value_t = 0.3)]
    nu1: f64,
    /// Young's modulus of the upper block Ω2 [Pa].
    #[arg(long, default_value_t = 1e11)]
    e2: f64,
    /// Poisson ratio of Ω2.
    #[arg(long, default_value_t = 0.3)]
    nu2: f64,
    /// Height of Ω1 [m].
    #[arg(long, default_value_t = 0.25)]
    h1: f64,
    /// Height of Ω2 [m].
    #[arg(long, default_value_t = 0.25)]
    h2: f64,
    /// Length L of both blocks [m].
    #[arg(long, default_value_t = 1.0)]
    length: f64,
    /// Half-width C of the loaded and supported segments [m].
    #[arg(long, default_value_t = 0.1)]
    c: f64,
    /// Pressure on the loaded segment [Pa].
    #[arg(long, default_value_t = 1e7)]
    p: f64,
    /// Element size h [m].
    #[arg(long, default_value_t = 1.0 / 64.0)]
    mesh_size: f64,
    /// Element size of the upper block [m], if it differs (non-matching
    /// interface meshes).
    #[arg(long)]
    upper_mesh_size: Option<f64>,
    /// Initial gap between the blocks [m].
    #[arg(long, default_value_t = 0.0)]
    gap: f64,
    /// Constitutive law of the contact elements.
    #[arg(long, value_enum, default_value_t = Law::Frictionless)]
    law: Law,
    /// Inversion test of the active-set loop.
    #[arg(long, value_enum, default_value_t = Test::Linearised)]
    test: Test,
    /// λ of the contact elements [m] (default: the model size).
    #[arg(long)]
    lambda: Option<f64>,
    /// E_c of the contact elements [Pa] (default: the softer block's E).
    #[arg(long)]
    ec: Option<f64>,
    /// Coulomb's friction coefficient μ of the interface (0: frictionless,
    /// bit for bit).
    #[arg(long, default_value_t = 0.0)]
    mu: f64,
    /// Load in this many proportional steps (factors k/steps, one
    /// factorisation for all of them); 1 solves the full load at once.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    steps: u32,
    /// Solve to this tolerance on the compliance's relative error instead
    /// of on the mesh `--mesh-size` gives: refine where the estimated
    /// error is (docs/method.md §8), a progress line per cycle on stderr;
    /// `--picture` then also draws the adapted mesh.
    #[arg(long)]
    adapt: Option<f64>,
    /// The adaptive solve's limit on unknowns.
    #[arg(long, default_value_t = 2_000_000)]
    max_unknowns: usize,
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
    /// Sweep h for 2C/L = 0.2, 0.4, 0.6 and plot ℓc against h
    /// (`<out>/sweep_lc.svg`).
    #[arg(long)]
    sweep: bool,
    /// Write the solved state as a VTK XML grid for ParaView or meshio
    /// (`<out>/two_blocks.vtu`: displacement, nodal contact pressure, force
    /// and gap, element strain and stress).
    #[arg(long)]
    vtu: bool,
    /// Draw the exaggerated deformed shape coloured by v
    /// (`<out>/two_blocks.png`, 1200×800 pixels whatever the mesh).
    #[arg(long)]
    picture: bool,
    /// Where `--vtu`, `--picture` and `--sweep` write their files.
    #[arg(long, default_value = "out")]
    out: PathBuf,
    /// Reference values of the canonical scene (compared when found;
    /// default: the copy shipped in the repository, `docs/reference/`).
    #[arg(long, default_value = REFERENCE)]
    reference: PathBuf,
}

impl Args {
    fn scene(&self, c: f64, h: f64) -> TwoBlocks {
        TwoBlocks {
            e1: self.e1,
            nu1: self.nu1,
            e2: self.e2,
            nu2: self.nu2,
            h1: self.h1,
            h2: self.h2,
            length: self.length,
            c,
            p: self.p,
            mesh_size: h,
            upper_mesh_size: self.upper_mesh_size,
            gap: self.gap,
            mu: self.mu,
            ..Default::default()
        }
    }

    fn options(&self) -> ContactOptions {
        ContactOptions {
            law: match self.law {
                Law::Frictionless => ContactLaw::Frictionless,
                Law::Stick => ContactLaw::Stick,
            },
            test: match self.test {
                Test::Linearised => InversionTest::Linearised,
                Test::Literal => InversionTest::Literal,
            },
            lambda: self.lambda,
            contact_modulus: self.ec,
            ..Default::default()
        }
    }
}

struct Run {
    scene: TwoBlocksScene,
    result: TwoBlocksResult,
    /// The adaptive solve's cycles (`--adapt`).
    adapt: Option<AdaptReport>,
    /// Numeric factorisations over the whole run (one for a history).
    factorizations: usize,
    seconds: f64,
}

fn run(args: &Args, c: f64, h: f64) -> Result<Run, tfem::Error> {
    let t0 = Instant::now();
    let mut scene = args.scene(c, h).build()?;
    let options = args.options();
    if let Some(tolerance) = args.adapt {
        let adapt = AdaptOptions {
            tolerance,
            goal: Goal::Compliance,
            max_unknowns: args.max_unknowns,
            contact: options,
            progress: Some(|c: &Cycle| {
                eprintln!(
                    "cycle: {:>8} unknowns, estimated compliance error {:.3e}, contact edges \
                     to {:.1e} of lc, {:.3} s",
                    c.unknowns, c.estimate, c.contact_edge, c.seconds
                )
            }),
            ..Default::default()
        };
        let report = scene.model.solve_adaptive(&adapt)?;
        let result = scene.measure(scene.model.contact_report()?.clone())?;
        return Ok(Run {
            scene,
            result,
            factorizations: report.cycles.len(),
            adapt: Some(report),
            seconds: t0.elapsed().as_secs_f64(),
        });
    }
    let (result, factorizations) = if args.steps == 1 {
        let result = scene.solve(&options)?;
        let f = result.report.info.factorizations;
        (result, f)
    } else {
        let mut factorizations = 0;
        let mut last = None;
        for k in 1..=args.steps {
            let report = scene.model.step(k as f64 / args.steps as f64, &options)?;
            factorizations += report.info.factorizations;
            last = Some(report);
        }
        (
            scene.measure(last.expect("one step at least"))?,
            factorizations,
        )
    };
    Ok(Run {
        scene,
        result,
        factorizations,
        adapt: None,
        seconds: t0.elapsed().as_secs_f64(),
    })
}

/// The reference case whose parameters equal the scene's, if any.
fn reference_case(args: &Args, c: f64) -> Option<Value> {
    let text = std::fs::read_to_string(&args.reference).ok()?;
    let all: Value = serde_json::from_str(&text).ok()?;
    let s = args.scene(c, 1.0);
    let ours = [
        ("E1", s.e1),
        ("nu1", s.nu1),
        ("E2", s.e2),
        ("nu2", s.nu2),
        ("H1", s.h1),
        ("H2", s.h2),
        ("C", s.c),
        ("p", s.p),
        ("L", s.length),
    ];
    // The reference values are those of frictionless contact.
    let plain = matches!(args.law, Law::Frictionless)
        && s.gap == 0.0
        && s.upper_mesh_size.is_none()
        && s.mu == 0.0;
    all["cases"]
        .as_object()?
        .values()
        .find(|case| {
            plain
                && ours.iter().all(|(k, v)| {
                    case["params"][*k]
                        .as_f64()
                        .is_some_and(|r| (r - v).abs() <= 1e-12 * v.abs())
                })
        })
        .cloned()
}

fn outputs(r: &TwoBlocksResult) -> [(&'static str, f64); 4] {
    [
        ("lc", r.lc),
        ("gap_edge", r.gap_edge),
        ("v_top", r.v_top),
        ("compliance", r.compliance),
    ]
}

fn main() {
    let args = Args::parse();
    let writes = args.sweep || args.vtu || args.picture;
    if writes {
        if let Err(e) = std::fs::create_dir_all(&args.out) {
            eprintln!("cannot create {}: {e}", args.out.display());
            std::process::exit(2);
        }
    }
    let code = if args.sweep {
        sweep(&args)
    } else {
        single(&args)
    };
    std::process::exit(code);
}

fn single(args: &Args) -> i32 {
    let r = match run(args, args.c, args.mesh_size) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("two_blocks: {e}");
            return 1;
        }
    };
    let info = r.result.report.info;
    let reference = reference_case(args, args.c);
    let files = write_files(args, &r.scene);
    if args.json {
        let mut obj = json!({
            "lc": r.result.lc,
            "gap_edge": r.result.gap_edge,
            "v_top": r.result.v_top,
            "compliance": r.result.compliance,
            "max_penetration": r.result.report.max_penetration,
            "iterations": r.result.report.iterations,
            "ndof": info.unknowns,
            "time_s": r.seconds,
            "support_reaction": r.result.support_reaction,
            "active_contact_elements": r.result.report.active,
            "contact_elements": r.result.report.elements,
            "time_assembly_s": info.timings.assembly,
            "time_factorization_s": info.timings.factorization,
            "time_solve_s": info.timings.solve,
            "steps": args.steps,
            "factorizations": r.factorizations,
            "factorisations": r.factorizations,
            "mu": args.mu,
            "stick_length": r.result.stick_length,
            "slip_edge": r.result.slip_edge,
            "max_shear": r.result.max_shear,
        });
        if let Some(a) = &r.adapt {
            let last = a.cycles.last();
            obj["unknowns"] = json!(last.map(|c| c.unknowns));
            obj["cycles"] = json!(a.cycles.len());
            obj["estimate"] = json!(last.map(|c| c.estimate));
            obj["contact_edge"] = json!(last.map(|c| c.contact_edge));
            obj["tolerance_reached"] = json!(a.reached);
        }
        if let Some(case) = &reference {
            for (k, v) in outputs(&r.result) {
                obj[format!("{k}_reference")] = case[k]["value"].clone();
                if let Some(rv) = case[k]["value"].as_f64() {
                    obj[format!("{k}_relative_error")] = json!((v - rv) / rv);
                }
            }
        }
        println!("{obj}");
        // stdout holds the JSON object alone.
        match &files {
            Ok(written) if !written.is_empty() => eprintln!("wrote {}", written.join(", ")),
            Ok(_) => {}
            Err(e) => eprintln!("two_blocks: {e}"),
        }
    } else {
        println!(
            "tfem {} — seed scene, 2C/L = {:.3}, h = {:.5} m, {} unknowns, {} contact elements",
            env!("CARGO_PKG_VERSION"),
            2.0 * args.c / args.length,
            args.mesh_size,
            info.unknowns,
            r.result.report.elements
        );
        if let Some(a) = &r.adapt {
            println!(
                "adapted from h = {} in {} cycles to {} unknowns: estimated compliance error {:.3e} ({} the tolerance {:.1e})",
                args.mesh_size,
                a.cycles.len(),
                info.unknowns,
                a.cycles.last().map_or(f64::NAN, |c| c.estimate),
                if a.reached { "within" } else { "above" },
                args.adapt.unwrap_or(f64::NAN)
            );
        }
        println!(
            "active-set loop: {} iterations, active per iteration {:?}",
            r.result.report.iterations,
            r.result
                .report
                .history
                .iter()
                .map(|h| h.active)
                .collect::<Vec<_>>()
        );
        println!(
            "\n{:<12} {:>15} {:>15} {:>12} {:>10}",
            "quantity", "tfem", "reference", "± ref err", "rel. err"
        );
        for (k, v) in outputs(&r.result) {
            match &reference {
                Some(case) => {
                    let rv = case[k]["value"].as_f64().unwrap_or(f64::NAN);
                    let re = case[k]["err"].as_f64().unwrap_or(f64::NAN);
                    println!(
                        "{k:<12} {v:>15.6e} {rv:>15.6e} {re:>12.2e} {:>+10.2e}",
                        (v - rv) / rv
                    );
                }
                None => println!("{k:<12} {v:>15.6e} {:>15} {:>12} {:>10}", "-", "-", "-"),
            }
        }
        if args.mu > 0.0 {
            println!(
                "friction μ = {}: stick length {:.6e} m, slip at the edge {:+.6e} m, max shear {:.6e} Pa",
                args.mu, r.result.stick_length, r.result.slip_edge, r.result.max_shear
            );
        }
        println!(
            "\nmax interpenetration {:.3e} m, support reaction {:.6e} N/m (p·2C = {:.6e})",
            r.result.report.max_penetration,
            r.result.support_reaction,
            args.p * 2.0 * args.c
        );
        println!(
            "time {:.3} s: analysis {:.3}, assembly {:.3}, factorisation(s) {:.3} ({}), solves {:.3}, \
             interface ({} unknowns) {:.3}",
            r.seconds,
            info.timings.analysis,
            info.timings.assembly,
            info.timings.factorization,
            info.factorizations,
            info.timings.solve,
            info.interface_unknowns,
            info.timings.interface
        );
        match &files {
            Ok(written) if !written.is_empty() => println!("wrote {}", written.join(", ")),
            Ok(_) => println!(
                "(no files written: --vtu and --picture write {} and {})",
                args.out.join("two_blocks.vtu").display(),
                args.out.join("two_blocks.png").display()
            ),
            Err(e) => eprintln!("two_blocks: {e}"),
        }
        if reference.is_none() {
            println!(
                "(no reference for these parameters: {})",
                args.reference.display()
            );
        }
    }
    i32::from(files.is_err())
}

/// Writes the files asked for, saying for each where it went, its size
/// and how long it took.
fn write_files(args: &Args, scene: &TwoBlocksScene) -> Result<Vec<String>, String> {
    let mut written = Vec::new();
    let said = |path: &Path, t0: Instant| {
        let bytes = std::fs::metadata(path).map_or(0, |m| m.len()) as f64;
        let size = if bytes < 1e6 {
            format!("{:.0} kB", bytes / 1e3)
        } else {
            format!("{:.1} MB", bytes / 1e6)
        };
        format!(
            "{} ({size}, {:.2} s)",
            path.display(),
            t0.elapsed().as_secs_f64()
        )
    };
    if args.vtu {
        let path = args.out.join("two_blocks.vtu");
        let t0 = Instant::now();
        tfem::io::vtu::write_vtu(&scene.model, &path).map_err(|e| e.to_string())?;
        written.push(said(&path, t0));
    }
    if args.picture {
        let path = args.out.join("two_blocks.png");
        let t0 = Instant::now();
        draw_deformed(scene, &path).map_err(|e| format!("cannot draw {}: {e}", path.display()))?;
        written.push(said(&path, t0));
        if args.adapt.is_some() {
            let path = args.out.join("two_blocks_mesh.png");
            let t0 = Instant::now();
            let mesh = scene.model.mesh().ok_or("no mesh")?;
            let title = format!(
                "two blocks: the adapted mesh, {} triangles",
                mesh.triangles().len()
            );
            picture::mesh_png(mesh.nodes(), mesh.triangles(), &title, &path)
                .map_err(|e| format!("cannot draw {}: {e}", path.display()))?;
            written.push(said(&path, t0));
        }
    }
    Ok(written)
}

/// The exaggerated deformed shape coloured by v, as a PNG of
/// [`picture::WIDTH`] × [`picture::HEIGHT`] pixels ([`picture::field_png`]).
fn draw_deformed(scene: &TwoBlocksScene, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let mesh = scene.model.mesh().ok_or("no mesh")?;
    let u = scene.model.displacements()?;
    let umax = u.iter().map(|d| d[0].hypot(d[1])).fold(0.0, f64::max);
    let size = mesh.size();
    let scale = if umax > 0.0 { 0.04 * size / umax } else { 1.0 };
    let x: Vec<[f64; 2]> = mesh
        .nodes()
        .iter()
        .zip(&u)
        .map(|(p, d)| [p[0] + scale * d[0], p[1] + scale * d[1]])
        .collect();
    let v: Vec<f64> = u.iter().map(|d| d[1]).collect();
    let title = format!("two blocks: deformed shape x{scale:.0}, coloured by v [m]");
    picture::field_png(&x, mesh.triangles(), &v, &title, path)
}

#[path = "common/picture.rs"]
mod picture;

fn sweep(args: &Args) -> i32 {
    let levels = [16usize, 32, 64, 128, 256];
    let widths = [0.1, 0.2, 0.3];
    println!(
        "| 2C/L | h | unknowns | iterations | ℓc | gap_edge | v_top | compliance | max penetration | time [s] |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut curves = Vec::new();
    for &c in &widths {
        let mut pts = Vec::new();
        for &n in &levels {
            let h = args.length / n as f64;
            match run(args, c * args.length, h) {
                Ok(r) => {
                    println!(
                        "| {:.1} | 1/{n} | {} | {} | {:.4} | {:.4e} | {:.5e} | {:.2} | {:.2e} | {:.2} |",
                        2.0 * c,
                        r.result.report.info.unknowns,
                        r.result.report.iterations,
                        r.result.lc,
                        r.result.gap_edge,
                        r.result.v_top,
                        r.result.compliance,
                        r.result.report.max_penetration,
                        r.seconds
                    );
                    pts.push((h, r.result.lc / args.length));
                }
                Err(e) => {
                    eprintln!("2C/L = {:.1}, h = 1/{n}: {e}", 2.0 * c);
                    return 1;
                }
            }
        }
        let reference =
            reference_case(args, c * args.length).and_then(|case| case["lc"]["value"].as_f64());
        curves.push((c, pts, reference));
    }
    let path = args.out.join("sweep_lc.svg");
    match plot_sweep(&curves, &path) {
        Ok(()) => {
            println!("\nwrote {}", path.display());
            0
        }
        Err(e) => {
            eprintln!("could not draw {}: {e}", path.display());
            1
        }
    }
}

type Curve = (f64, Vec<(f64, f64)>, Option<f64>);

fn plot_sweep(curves: &[Curve], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (800, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let hmin = curves
        .iter()
        .flat_map(|c| c.1.iter().map(|p| p.0))
        .fold(f64::INFINITY, f64::min);
    let hmax = curves
        .iter()
        .flat_map(|c| c.1.iter().map(|p| p.0))
        .fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "contact length ℓc/L against mesh size (seed Fig. 6)",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d((hmin / 1.5..hmax * 1.5).log_scale(), 0.3f64..1.05)?;
    chart
        .configure_mesh()
        .x_desc("h / L")
        .y_desc("ℓc / L")
        .draw()?;
    let colours = [RED, BLUE, GREEN];
    for ((c, pts, reference), col) in curves.iter().zip(colours) {
        chart
            .draw_series(LineSeries::new(pts.clone(), col.stroke_width(2)))?
            .label(format!("2C/L = {:.1} (tfem)", 2.0 * c))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2)));
        chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, col.filled())))?;
        if let Some(r) = reference {
            chart
                .draw_series(LineSeries::new(
                    vec![(hmin / 1.5, *r), (hmax * 1.5, *r)],
                    col.mix(0.5),
                ))?
                .label(format!(
                    "2C/L = {:.1} reference (exact frictionless)",
                    2.0 * c
                ))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.mix(0.5)));
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerRight)
        .draw()?;
    root.present()?;
    Ok(())
}
