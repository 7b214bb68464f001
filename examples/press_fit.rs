//! A hub shrunk on a shaft, axisymmetric (docs/method.md §7): a steel hub
//! of bore b = 1 and outer radius c = 2 on a solid shaft of radius b + δ,
//! both of length ℓ = 2 with their ends held axially (a slice of a long
//! fit). Prints the contact pressure and the hoop stresses at mid-length
//! against Lamé's shrink fit, and with friction (`--mu`) the force that
//! pushes the shaft through the hub against 2π b ℓ μ p. Files only when
//! asked: `--vtu` (`<out>/press_fit.vtu`, hoop stress included) and
//! `--picture` (`<out>/press_fit.png`, the section coloured by the hoop
//! stress on the deformed shape).
//!
//!   cargo run --release --example press_fit                     # h = b/16, μ = 0.1
//!   cargo run --release --example press_fit -- --cells 32 --json
//!   cargo run --release --example press_fit -- --vtu --picture --out results

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Parser;
use serde_json::json;
use tfem::scenes::revolution::{ShaftHub, ShaftHubResult, ShaftHubScene};

#[derive(Parser, Debug)]
#[command(about = "A hub shrunk on a shaft (axisymmetric) against Lamé")]
struct Args {
    /// Cells over the bore radius b (h = b/cells).
    #[arg(long, default_value_t = 16)]
    cells: usize,
    /// Radial interference δ over b.
    #[arg(long, default_value_t = 1e-3)]
    interference: f64,
    /// Coulomb coefficient of the fit (0: no push-out).
    #[arg(long, default_value_t = 0.1)]
    mu: f64,
    /// Matching nodes along the interface (default: the hub 3 cells for
    /// the shaft's 2).
    #[arg(long)]
    matching: bool,
    /// One JSON object on stdout instead of the text.
    #[arg(long)]
    json: bool,
    /// Write `<out>/press_fit.vtu`.
    #[arg(long)]
    vtu: bool,
    /// Write `<out>/press_fit.png`.
    #[arg(long)]
    picture: bool,
    /// Where `--vtu` and `--picture` write.
    #[arg(long, default_value = "results")]
    out: PathBuf,
}

fn main() {
    let args = Args::parse();
    std::process::exit(match run(&args) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("press_fit: {e}");
            1
        }
    })
}

fn run(args: &Args) -> Result<(), Box<dyn std::error::Error>> {
    let fit = ShaftHub {
        cells: args.cells,
        interference: args.interference,
        ratio: if args.matching { (1, 1) } else { (3, 2) },
        mu: args.mu,
        ..Default::default()
    };
    let t0 = Instant::now();
    let (scene, r) = fit.solve()?;
    let seconds = t0.elapsed().as_secs_f64();
    let push = if fit.mu > 0.0 {
        // Moved by δ the whole interface slips.
        let t0 = Instant::now();
        let (force, slipping) = fit.push_out(fit.interference, 1)?;
        Some((force, slipping, t0.elapsed().as_secs_f64()))
    } else {
        None
    };
    if args.json {
        let mut out = json!({
            "cells": args.cells,
            "unknowns": r.unknowns,
            "pressure": fit.pressure() * (1.0 + r.pressure_error),
            "pressure_lame": fit.pressure(),
            "pressure_error": r.pressure_error,
            "pressure_spread": r.pressure_spread,
            "hub_hoop_error": r.hub_hoop_error,
            "shaft_hoop_error": r.shaft_hoop_error,
            "seconds": seconds,
        });
        if let Some((force, slipping, s)) = push {
            out["push_out_force"] = json!(force);
            out["push_out_force_exact"] = json!(fit.push_out_force());
            out["push_out_error"] = json!(force / fit.push_out_force() - 1.0);
            out["slipping_share"] = json!(slipping);
            out["push_out_seconds"] = json!(s);
        }
        println!("{out}");
    } else {
        print_text(&fit, &r, seconds, push);
    }
    write_files(args, &scene)
}

fn print_text(fit: &ShaftHub, r: &ShaftHubResult, seconds: f64, push: Option<(f64, f64, f64)>) {
    let p = fit.pressure();
    println!(
        "hub b = {}, c = {} on a shaft of radius b + {:.1e}, length {}; E = {:.0}, nu = {}",
        fit.bore, fit.outer, fit.interference, fit.length, fit.e, fit.nu
    );
    println!(
        "h = b/{}: {} unknowns, solved in {:.3} s",
        fit.cells, r.unknowns, seconds
    );
    println!("at mid-length (the middle half), against Lamé:");
    println!(
        "  contact pressure  {:.4} (Lamé {p:.4}): {:+.2e}, nodes within {:.1e}",
        p * (1.0 + r.pressure_error),
        r.pressure_error,
        r.pressure_spread
    );
    println!(
        "  hub hoop stress at the bore   {:+.2e} of Lamé's {:.4}",
        r.hub_hoop_error,
        fit.hub_hoop(fit.bore)
    );
    println!(
        "  shaft hoop stress             {:+.2e} of Lamé's {:.4}",
        r.shaft_hoop_error, -p
    );
    if let Some((force, slipping, s)) = push {
        println!(
            "push-out with mu = {}: F = {:.2} against 2 pi b l mu p = {:.2} ({:+.2e}; {:.0} % of the interface slipping; {:.3} s)",
            fit.mu,
            force,
            fit.push_out_force(),
            force / fit.push_out_force() - 1.0,
            100.0 * slipping,
            s
        );
    }
}

fn write_files(args: &Args, scene: &ShaftHubScene) -> Result<(), Box<dyn std::error::Error>> {
    if !(args.vtu || args.picture) {
        return Ok(());
    }
    std::fs::create_dir_all(&args.out)?;
    if args.vtu {
        let path = args.out.join("press_fit.vtu");
        tfem::io::vtu::write_vtu(&scene.model, &path)?;
        println!("wrote {}", path.display());
    }
    if args.picture {
        let path = args.out.join("press_fit.png");
        draw(scene, &path)?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// The section on its deformed shape (the largest displacement drawn as
/// 4 % of the model's size) coloured by the hoop stress, averaged at the
/// nodes from their triangles.
fn draw(scene: &ShaftHubScene, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let model = &scene.model;
    let mesh = model.mesh().ok_or("no mesh")?;
    let u = model.displacements()?;
    let umax = u.iter().map(|d| d[0].hypot(d[1])).fold(0.0, f64::max);
    let scale = if umax > 0.0 {
        0.04 * mesh.size() / umax
    } else {
        1.0
    };
    let x: Vec<[f64; 2]> = (mesh.nodes().iter().zip(&u))
        .map(|(p, d)| [p[0] + scale * d[0], p[1] + scale * d[1]])
        .collect();
    let hoop = model.element_out_of_plane_stresses()?;
    let (mut sum, mut count) = (vec![0.0f64; x.len()], vec![0.0f64; x.len()]);
    for (t, tri) in mesh.triangles().iter().enumerate() {
        for &v in tri {
            sum[v] += hoop[t];
            count[v] += 1.0;
        }
    }
    let nodal: Vec<f64> = sum
        .iter()
        .zip(&count)
        .map(|(s, c)| s / c.max(1.0))
        .collect();
    let title = format!("press fit (r, z): deformed x{scale:.0}, coloured by the hoop stress");
    picture::field_png(&x, mesh.triangles(), &nodal, &title, path)
}

#[path = "common/picture.rs"]
mod picture;
