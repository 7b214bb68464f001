//! The contact patch test (`tfem::scenes::patch`): two blocks under a
//! uniform pressure, matching and non-matching interfaces (upper cell width
//! over lower: 2:3, 3:7, 5:8 both ways), uniform or jittered grids, equal
//! moduli or the upper block 10× stiffer, h = 1/8 … 1/128. Prints, per
//! case, the max and L2 stress errors / p, the range of element and nodal
//! contact pressures / p, released elements, the reported and the actual
//! largest interpenetration, and iterations.
//!
//!   cargo run --release --example patch_test
//!   cargo run --release --example patch_test -- --levels 8,16 --json

use tfem::ContactOptions;
use tfem::scenes::patch::PatchTest;

fn main() {
    let mut levels = vec![8usize, 16, 32, 64, 128];
    let mut json = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--levels" => {
                levels = args
                    .next()
                    .expect("--levels n1,n2,…")
                    .split(',')
                    .map(|v| v.parse().expect("a number of cells"))
                    .collect()
            }
            "--json" => json = true,
            other => {
                eprintln!("unknown argument {other}; use --levels 8,16,… and --json");
                std::process::exit(2);
            }
        }
    }
    let ratios: [(&str, f64); 7] = [
        ("1:1", 1.0),
        ("2:3", 1.5),
        ("3:2", 2.0 / 3.0),
        ("3:7", 7.0 / 3.0),
        ("7:3", 3.0 / 7.0),
        ("5:8", 1.6),
        ("8:5", 5.0 / 8.0),
    ];
    let materials: [(&str, f64, f64); 2] = [("E2=E1", 1e10, 1e10), ("E2=10E1", 1e10, 1e11)];
    if !json {
        println!(
            "| E | ratio | jitter | h | cells | max err | L2 err | worst at | p_e/p | p_node/p | traction/p | released | pen. reported | pen. actual | it |"
        );
        println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    }
    let mut rows = Vec::new();
    for &(mname, e1, e2) in &materials {
        for &(rname, ratio) in &ratios {
            for jitter in [0.0, 0.3] {
                for &n in &levels {
                    let test = PatchTest {
                        e_lower: e1,
                        e_upper: e2,
                        mesh_size: 1.0 / n as f64,
                        ratio,
                        jitter,
                        ..Default::default()
                    };
                    let mut s = test.build().expect("scene");
                    let t0 = std::time::Instant::now();
                    match s.solve(&test, &ContactOptions::default()) {
                        Ok(r) => {
                            let t = t0.elapsed().as_secs_f64();
                            if json {
                                rows.push(format!(
                                    "{{\"E\":\"{mname}\",\"ratio\":\"{rname}\",\"jitter\":{jitter},\"n\":{n},\"max\":{:e},\"l2\":{:e},\"pe\":[{:e},{:e}],\"pn\":[{:e},{:e}],\"released\":{},\"pen_reported\":{:e},\"pen\":{:e},\"overlap\":{:e},\"iterations\":{},\"time\":{t:e}}}",
                                    r.max_error,
                                    r.l2_error,
                                    r.element_pressure.0,
                                    r.element_pressure.1,
                                    r.nodal_pressure.0,
                                    r.nodal_pressure.1,
                                    r.released,
                                    r.reported_penetration,
                                    r.penetration,
                                    r.overlap,
                                    r.report.iterations
                                ));
                            } else {
                                println!(
                                    "| {mname} | {rname} | {jitter} | 1/{n} | {}:{} | {:.2e} | {:.2e} | ({:.3}, {:.3}) | {:.3}…{:.3} | {:.4}…{:.4} | {:.4}…{:.4} | {} | {:.3e} | {:.3e} | {} |",
                                    s.cells.0,
                                    s.cells.1,
                                    r.max_error,
                                    r.l2_error,
                                    r.worst_at[0],
                                    r.worst_at[1],
                                    r.element_pressure.0,
                                    r.element_pressure.1,
                                    r.nodal_pressure.0,
                                    r.nodal_pressure.1,
                                    r.traction.0,
                                    r.traction.1,
                                    r.released,
                                    r.reported_penetration,
                                    r.penetration,
                                    r.report.iterations
                                );
                            }
                        }
                        Err(e) => println!(
                            "| {mname} | {rname} | {jitter} | 1/{n} | {}: {} |",
                            e.status().name(),
                            e.message()
                        ),
                    }
                }
            }
        }
    }
    if json {
        println!("[\n{}\n]", rows.join(",\n"));
    }
}
