//! CalculiX 2.20 beside tfem on the seed scene, in the same run (`--calculix`).

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use serde_json::Value;

use tfem::scenes::TwoBlocks;

use crate::Args;
use crate::common::mem_available;
use crate::friction::seed_steps;

/// `ccx` on the PATH, if any.
fn find_ccx() -> Option<PathBuf> {
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join("ccx"))
            .find(|p| p.is_file())
    })
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
pub(crate) fn calculix(report: &mut String, _a: &Args) {
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
