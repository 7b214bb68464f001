//! Contact for host codes: tfem's contributions in a host's own assembly (P1 and Q4).

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use serde_json::Value;

use tfem::ContactOptions;
use tfem::scenes::TwoBlocks;
use tfem::verification::fitted_rate;

use crate::Args;
use crate::common::{median, reference};

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

pub(crate) fn host_codes(report: &mut String, a: &Args) {
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
pub(crate) fn q4_host(report: &mut String, a: &Args) {
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
