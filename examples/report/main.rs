//! Regenerates `docs/report.md` and its pictures: error against run time for
//! the verification scenes and the seed scene, stability on stiff and
//! extreme cases, speed with both orderings, and what each scene built.
//!
//!   cargo run --release --example report               # full: 2D to ~2M unknowns, 3D to 685k (~2 h)
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

mod adaptive;
mod adaptive_curved;
mod axisymmetric;
mod built;
mod calculix;
mod cattaneo;
mod combined;
mod common;
mod friction;
mod hertz;
mod histories;
mod host;
mod indenters;
mod interface_cost;
mod interference;
mod manufactured;
mod many_bodies;
mod patch;
mod seed;
mod speed;
mod speed_3d;
mod stability;
mod tetrahedra;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::adaptive::adaptive;
use crate::axisymmetric::axisymmetric;
use crate::built::built;
use crate::calculix::calculix;
use crate::cattaneo::cattaneo;
use crate::combined::combined;
use crate::common::machine_and_date;
use crate::friction::friction;
use crate::hertz::hertz;
use crate::histories::histories;
use crate::host::{host_codes, q4_host};
use crate::indenters::indenters;
use crate::interface_cost::interface_cost;
use crate::interference::interference;
use crate::manufactured::manufactured;
use crate::many_bodies::many_bodies;
use crate::patch::{patch_ratios, patch_test};
use crate::seed::seed;
use crate::speed::{export_matrix, faer_alone, speed, speed_run};
use crate::speed_3d::{seed3d_run, speed_3d};
use crate::stability::stability;
use crate::tetrahedra::tetrahedra;

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
    "combined",
    "axisymmetric",
    "adaptive",
    "tetrahedra",
    "speed_3d",
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
            "--seed3d-run" => {
                let n = it
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--seed3d-run N");
                seed3d_run(n);
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
    let sections: [(&str, Section); 23] = [
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
        ("combined", combined),
        ("axisymmetric", axisymmetric),
        ("adaptive", adaptive),
        ("tetrahedra", tetrahedra),
        ("speed_3d", speed_3d),
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
