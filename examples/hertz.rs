//! Hertz contact (plane strain): an elastic cylinder pressed on an elastic
//! block, meshed by the built-in graded triangulator, solved with TFEM's
//! frictionless contact over five mesh levels; contact half-width a and
//! peak pressure p₀ against the analytic values, with fitted rates.
//!
//!   cargo run --release --example hertz                  # equal moduli
//!   cargo run --release --example hertz -- --contrast 100 # cylinder 100× stiffer
//!   cargo run --release --example hertz -- --cylinder-mesh-ratio 2.5  # non-matching
//!   cargo run --release --example hertz -- --history  # the active-set loop per level
//!   cargo run --release --example hertz -- --contrast 100 --cylinder-mesh-ratio 0.4 --mortar
//!       # the mortar weighting (one weighted gap per node of the coarser side)
//!
//! With `--mortar` the "both sides" columns are the library's nodal
//! pressures (the slave's −κG_i/m_i, interpolated at the master's nodes).

use tfem::scenes::hertz::Hertz;
use tfem::verification::fitted_rate;
use tfem::{ContactOptions, ContactWeighting};

fn main() {
    let mut contrast = 1.0;
    let mut ratio = 1.0;
    let mut half_width = Hertz::default().half_width;
    let mut history = false;
    let mut weighting = ContactWeighting::Strip;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--contrast" => {
                contrast = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--contrast E2/E1")
            }
            "--half-width" => {
                half_width = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--half-width a")
            }
            "--cylinder-mesh-ratio" => {
                ratio = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--cylinder-mesh-ratio r")
            }
            "--history" => history = true,
            "--mortar" => weighting = ContactWeighting::Mortar,
            other => {
                eprintln!(
                    "unknown argument {other}; use --contrast E2/E1, --half-width a, --cylinder-mesh-ratio r, --history, --mortar"
                );
                std::process::exit(2);
            }
        }
    }
    let base = Hertz {
        e_cylinder: Hertz::default().e_block * contrast,
        cylinder_mesh_ratio: ratio,
        half_width,
        ..Default::default()
    };
    println!("contact weighting: {weighting:?}");
    println!(
        "Hertz, plane strain: R = {}, E_block = {:.2e}, E_cylinder = {:.2e}, ν = {}, P = {:.4e} N/m; analytic a = {}, p0 = {:.4e} Pa",
        base.radius,
        base.e_block,
        base.e_cylinder,
        base.nu_block,
        base.load(),
        base.half_width,
        2.0 * base.load() / (std::f64::consts::PI * base.half_width)
    );
    println!(
        "| h/a | unknowns | iterations | a | err a | p0 | err p0 | p0 (both sides) | err | max err in 0.8a | (both sides) | a (fit) | err | p0 (fit) | err | time [s] |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let (mut hs, mut ea, mut ep) = (Vec::new(), Vec::new(), Vec::new());
    let mut loops = Vec::new();
    for k in [2.0, 4.0, 8.0, 16.0, 32.0, 64.0] {
        let hz = Hertz {
            mesh_size: base.half_width / k,
            ..base
        };
        let mut s = hz.build().expect("scene");
        s.model
            .set_contact_weighting(weighting)
            .expect("a frictionless scene");
        let t0 = std::time::Instant::now();
        match s.solve(&hz, &ContactOptions::default()) {
            Ok(r) => {
                let t = t0.elapsed().as_secs_f64();
                let rel = |v: f64, e: f64| (v - e) / e;
                println!(
                    "| 1/{k} | {} | {} | {:.5} | {:+.2e} | {:.4e} | {:+.2e} | {:.4e} | {:+.2e} | {:.2e} | {:.2e} | {:.5} | {:+.2e} | {:.4e} | {:+.2e} | {t:.2} |",
                    r.report.info.unknowns,
                    r.report.iterations,
                    r.a,
                    rel(r.a, r.a_exact),
                    r.p0,
                    rel(r.p0, r.p0_exact),
                    r.p0_interface,
                    rel(r.p0_interface, r.p0_exact),
                    r.inner_error(&r.pressure),
                    r.inner_error(&r.interface_pressure),
                    r.a_fit,
                    rel(r.a_fit, r.a_exact),
                    r.p0_fit,
                    rel(r.p0_fit, r.p0_exact),
                );
                // Per iteration: the elements the solve used, then how many
                // its inversion test switched on and off.
                let steps: Vec<String> = r
                    .report
                    .history
                    .iter()
                    .map(|s| format!("{} +{} -{}", s.active, s.switched_on, s.switched_off))
                    .collect();
                loops.push(format!("h = a/{k}: {}", steps.join(", ")));
                hs.push(1.0 / k);
                ea.push(rel(r.a, r.a_exact).abs());
                ep.push(rel(r.p0, r.p0_exact).abs());
            }
            Err(e) => println!("| 1/{k} | {}: {} |", e.status().name(), e.message()),
        }
    }
    if history {
        println!("active-set loop (active, switched on, switched off per iteration):");
        for l in &loops {
            println!("{l}");
        }
    }
    if hs.len() >= 2 {
        println!(
            "fitted rates in h: a {:.2}, p0 {:.2}",
            fitted_rate(&hs, &ea),
            fitted_rate(&hs, &ep)
        );
    }
}
