//! Compiles the C and C++ programs of `c_tests/` against the shared
//! library built by cargo (with the `cc` crate, as a build script would)
//! and runs them: they must exit 0.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{ensure_shared_library, lib_dir, root, run};

fn compiler(cpp: bool) -> Command {
    let mut build = cc::Build::new();
    build
        .cargo_metadata(false)
        .target(env!("TFEM_BUILD_TARGET"))
        .host(env!("TFEM_BUILD_HOST"))
        .opt_level(2)
        .debug(false)
        .cpp(cpp)
        .warnings(true)
        .extra_warnings(true);
    build.get_compiler().to_command()
}

/// Builds `c_tests/<source>` into an executable linked with libtfem.
pub fn build(source: &str, extra: &[&str]) -> PathBuf {
    ensure_shared_library();
    let cpp = source.ends_with(".cpp");
    let lib = lib_dir();
    let out_dir = lib.join("c_tests");
    std::fs::create_dir_all(&out_dir).expect("output directory");
    let exe = out_dir.join(Path::new(source).file_stem().expect("file name"));
    let mut cmd = compiler(cpp);
    cmd.arg(root().join("c_tests").join(source))
        .arg("-I")
        .arg(root().join("include"))
        .args(extra)
        .arg("-o")
        .arg(&exe)
        .arg("-L")
        .arg(&lib)
        .arg("-ltfem")
        .arg(format!("-Wl,-rpath,{}", lib.display()))
        .arg("-lm")
        .arg("-Werror");
    let out = cmd.output().expect("run the C compiler");
    assert!(
        out.status.success(),
        "compiling {source} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

#[test]
fn c_api_test_passes_every_check() {
    let exe = build("api_test.c", &["-std=c11"]);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

#[test]
fn the_mortar_weighting_passes_the_patch_test_through_the_c_abi() {
    let exe = build("mortar_test.c", &["-std=c11"]);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// The 3D model's C ABI (`tfem_solid_*`): two stacked cubes of Kuhn
/// tetrahedra pressed into frictionless contact, held to the exact
/// uniaxial stress, contact area and reactions, and every refusal (NULL,
/// a node out of range, a wrong component, a body without material, a
/// buffer too short, a handle of the other kind) leaving the model usable.
#[test]
fn the_3d_model_passes_the_contact_patch_test_through_the_c_abi() {
    let exe = build("solid_test.c", &["-std=c11"]);
    let folder = lib_dir().join("c_tests");
    let out = run(&exe, &[folder.to_str().expect("a UTF-8 path")]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// The 3D contact context for host codes (`tfem_solid_contact_*`): a C
/// host with its own tetrahedra, stiffness, dense Cholesky solver and
/// active-set loop presses two stacked cubes into frictionless contact
/// through tfem's B in its 1-based (and 0-based) equations, exact (uniform
/// σ_zz = −p from the host's own solution, every tetrahedron of B active,
/// contact area 1), and every refusal (NULL, a wrong length, a node not in
/// its side, a side out of range, a NaN, a handle of another kind or
/// destroyed) with its status and message, writing nothing.
#[test]
fn a_3d_host_passes_the_contact_patch_test_through_the_c_abi() {
    let exe = build("solid_host_test.c", &["-std=c11"]);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

#[test]
fn c_boundary_regressions_hold() {
    let exe = build("boundary_test.c", &["-std=c11"]);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

#[test]
fn element_matrices_match_the_independent_eigen_implementation() {
    let eigen = Path::new("/usr/include/eigen3");
    assert!(
        eigen.exists(),
        "Eigen is missing: install Debian's libeigen3-dev (the README's test command does)"
    );
    let exe = build(
        "element_reference.cpp",
        &[
            "-std=c++17",
            "-I/usr/include/eigen3",
            "-Wno-deprecated-copy",
        ],
    );
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// Tetrahedra of every shape a mesh of a gap or a band makes: jittered
/// regular ones, caps (a vertex near the opposite face), needles, slivers
/// (two opposite edges nearly coplanar), exactly flat and inverted ones,
/// each with Jmin below and above its J.
fn tet_cases() -> Vec<([[f64; 3]; 4], f64)> {
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut rand = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let regular = [
        [1.0, 0.0, -0.5f64.sqrt()],
        [-1.0, 0.0, -0.5f64.sqrt()],
        [0.0, 1.0, 0.5f64.sqrt()],
        [0.0, -1.0, 0.5f64.sqrt()],
    ];
    let mut cases = Vec::new();
    for k in 0..400 {
        let mut x = regular;
        for p in x.iter_mut() {
            for c in p.iter_mut() {
                *c += 0.3 * rand();
            }
        }
        let t = 10f64.powi(-(k % 9));
        match k % 6 {
            0 => {}
            // A cap: the fourth vertex nearly on the plane of the others.
            1 => x[3] = [0.1 * rand(), 0.1 * rand(), t * rand()],
            // A needle: one vertex far along an axis.
            2 => x[3] = [0.0, 0.0, 1.0 / t.max(1e-3)],
            // A sliver: two opposite edges nearly coplanar, no short edge.
            3 => {
                x = [
                    [1.0, 0.0, 0.0],
                    [-1.0, 0.0, 0.0],
                    [0.0, 1.0, t],
                    [0.0, -1.0, -t],
                ];
            }
            // Exactly flat: four points of one plane.
            4 => {
                x[3] = [
                    0.5 * x[0][0] + 0.5 * x[1][0],
                    0.5 * x[0][1] + 0.5 * x[2][1],
                    0.0,
                ]
            }
            // Inverted: two vertices swapped.
            _ => x.swap(0, 1),
        }
        if k % 6 == 4 {
            for p in x.iter_mut().take(3) {
                p[2] = 0.0;
            }
        }
        let j = tfem::fem::tet::TetGeometry::new(&x).j;
        let jmin = if k % 2 == 0 {
            1e-3
        } else {
            10.0 * j.abs().max(1e-6)
        };
        cases.push((x, jmin));
    }
    cases
}

#[test]
fn tempered_tetrahedra_match_the_independent_eigen_implementation() {
    use std::io::Write;
    use tfem::fem::tet::{TetGeometry, isotropic_d, stiffness};
    let exe = build(
        "tet_reference.cpp",
        &[
            "-std=c++17",
            "-I/usr/include/eigen3",
            "-Wno-deprecated-copy",
        ],
    );
    let out = run(&exe, &["--self-test"]);
    assert!(out.contains(" 0 failed"), "{out}");
    let cases = tet_cases();
    let (young, poisson) = (2.5, 0.3);
    let mut input = String::new();
    for (x, jmin) in &cases {
        let coords: Vec<String> = x.iter().flatten().map(|v| format!("{v:e}")).collect();
        input += &format!("{} {young:e} {poisson:e} {jmin:e}\n", coords.join(" "));
    }
    // Through a file: a pipe both ways would block once the answers fill
    // it while the questions are still being written.
    let path = lib_dir().join("c_tests").join("tet_cases.txt");
    std::fs::File::create(&path)
        .and_then(|mut f| f.write_all(input.as_bytes()))
        .expect("write the cases");
    let output = Command::new(&exe)
        .stdin(std::fs::File::open(&path).expect("the cases"))
        .output()
        .expect("run tet_reference");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = String::from_utf8(output.stdout).expect("utf-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), cases.len());
    let d = isotropic_d(young, poisson).unwrap();
    let mut worst = 0.0f64;
    for ((x, jmin), line) in cases.iter().zip(&lines) {
        // The cases are read back from their printed digits, as the
        // reference reads them.
        let x: [[f64; 3]; 4] = {
            let v: Vec<f64> = x
                .iter()
                .flatten()
                .map(|c| format!("{c:e}").parse().unwrap())
                .collect();
            [
                [v[0], v[1], v[2]],
                [v[3], v[4], v[5]],
                [v[6], v[7], v[8]],
                [v[9], v[10], v[11]],
            ]
        };
        let g = TetGeometry::new(&x);
        let k = stiffness(&g, &d, *jmin).unwrap();
        let want: Vec<f64> = line
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(want.len(), 144, "{line}");
        let size = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        // K ∝ 1/max(J, Jmin): where J > Jmin it carries J's rounding,
        // |a||e|/J times the unit round-off (the reference is exact there).
        let h3 = g.h.powi(3);
        let allowance = 1e-14 * size * (1.0 + h3 / g.j.max(*jmin));
        for (a, b) in k.iter().flatten().zip(&want) {
            assert!((a - b).abs() <= allowance, "{x:?}, Jmin {jmin}: {a} vs {b}");
            worst = worst.max((a - b).abs() / size.max(f64::MIN_POSITIVE));
        }
    }
    // Measured: 7.6e-16 of the largest entry over 400 tetrahedra.
    assert!(worst < 1e-12, "{worst}");
}

#[test]
fn two_blocks_through_the_c_abi_matches_rust() {
    use std::fmt::Write;
    use tfem::scenes::{TAG_CONTACT_LOWER, TAG_CONTACT_UPPER, TAG_LOAD, TwoBlocks};

    let scene = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    };
    let mut s = scene.build().unwrap();
    let r = s.solve(&tfem::ContactOptions::default()).unwrap();

    let mesh = s.model.mesh().unwrap();
    let mut text = String::new();
    writeln!(text, "nodes {}", mesh.nodes().len()).unwrap();
    for p in mesh.nodes() {
        writeln!(text, "{:e} {:e}", p[0], p[1]).unwrap();
    }
    writeln!(text, "triangles {}", mesh.triangles().len()).unwrap();
    for (t, b) in mesh.triangles().iter().zip(mesh.body_of()) {
        writeln!(text, "{} {} {} {b}", t[0], t[1], t[2]).unwrap();
    }
    writeln!(text, "edges {}", mesh.boundary_edges().len()).unwrap();
    for e in mesh.boundary_edges() {
        writeln!(text, "{} {} {}", e.nodes[0], e.nodes[1], e.tag).unwrap();
    }
    writeln!(text, "materials 2").unwrap();
    for b in [1, 2] {
        let m = s.model.material(b).unwrap();
        writeln!(
            text,
            "{b} {:e} {:e} {}",
            m.young(),
            m.poisson(),
            m.plane() as i32
        )
        .unwrap();
    }
    let fixed: Vec<(usize, f64)> = s.model.constraints().collect();
    writeln!(text, "fixed {}", fixed.len()).unwrap();
    for (g, v) in fixed {
        writeln!(text, "{} {} {v:e}", g / 2, g % 2).unwrap();
    }
    writeln!(text, "pressures 1\n{TAG_LOAD} {:e}", scene.p).unwrap();
    writeln!(text, "contact 2\n{TAG_CONTACT_LOWER} {TAG_CONTACT_UPPER}").unwrap();
    writeln!(
        text,
        "probes 3\n{} {} {}",
        s.corner_lower, s.corner_upper, s.top_center
    )
    .unwrap();
    let file = lib_dir().join("c_tests").join("two_blocks_scene.txt");
    std::fs::create_dir_all(file.parent().unwrap()).unwrap();
    std::fs::write(&file, text).unwrap();

    let exe = build("two_blocks_c.c", &["-std=c11"]);
    let out = run(&exe, &[file.to_str().unwrap()]);
    let value = |name: &str| -> f64 {
        out.lines()
            .find_map(|l| l.strip_prefix(&format!("{name} ")))
            .unwrap_or_else(|| panic!("{name} missing in {out}"))
            .trim()
            .parse()
            .unwrap()
    };
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
    assert!(same(value("lc"), r.lc), "{} vs {}", value("lc"), r.lc);
    assert!(
        same(value("gap_edge"), r.gap_edge),
        "{} vs {}",
        value("gap_edge"),
        r.gap_edge
    );
    assert!(
        same(value("v_top"), r.v_top),
        "{} vs {}",
        value("v_top"),
        r.v_top
    );
    assert!(same(value("max_penetration"), r.report.max_penetration));
    assert_eq!(value("iterations") as usize, r.report.iterations);
    assert_eq!(value("active") as usize, r.report.active);
    assert_eq!(value("unknowns") as usize, r.report.info.unknowns);
}

/// Builds one of the C++ host codes of `examples/` (their own Q4 elements,
/// assembly and Eigen Cholesky; tfem only for contact), once per test
/// binary: two tests use host_q4, and one must not rewrite the executable
/// while the other runs it.
fn build_host(source: &str) -> PathBuf {
    use std::collections::BTreeMap;
    use std::sync::Mutex;
    static BUILT: Mutex<BTreeMap<String, PathBuf>> = Mutex::new(BTreeMap::new());
    let mut built = BUILT.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(exe) = built.get(source) {
        return exe.clone();
    }
    let eigen = Path::new("/usr/include/eigen3");
    assert!(
        eigen.exists(),
        "Eigen is missing: install Debian's libeigen3-dev (the README's test command does)"
    );
    let exe = build(
        &format!("../examples/{source}"),
        &["-std=c++17", "-I/usr/include/eigen3"],
    );
    built.insert(source.to_string(), exe.clone());
    exe
}

/// The JSON objects a host prints, one per line.
fn json_lines(out: &str) -> Vec<serde_json::Value> {
    out.lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect()
}

/// Least-squares slope of log|e| against log h.
fn fitted_rate(h: &[f64], e: &[f64]) -> f64 {
    let n = h.len() as f64;
    let (x, y): (Vec<f64>, Vec<f64>) = h.iter().zip(e).map(|(h, e)| (h.ln(), e.abs().ln())).unzip();
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(&y).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = x.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// examples/host_q4.cpp, a host with its own Q4 assembly, Eigen's sparse
/// Cholesky and its own active-set loop, converges on the seed scene
/// (2C/L = 0.4) to the shipped reference at first order, like tfem's P1,
/// with about half P1's error.
///
/// Measured with the contact tempering T_e = ℓ_e h_c²/λ (docs/method.md
/// §6.11), relative errors at h = 1/16 … 1/256: gap_edge 7.4, 5.6, 3.3, 1.66,
/// 0.85 %; v_top 3.6, 2.0, 1.10, 0.58, 0.30 %; compliance 4.1, 2.3, 1.21,
/// 0.63, 0.32 %. gap_edge is pre-asymptotic on the two coarsest meshes (its
/// error falls by only 1.33 from 1/16 to 1/32, a fitted rate of 0.58 over
/// 1/16 … 1/64), so the sizes checked are 1/32, 1/64, 1/128 (0.4 s), where
/// the fitted rates are gap_edge 0.88, v_top 0.90, compliance 0.92, all held
/// to 0.8. ℓc is a sum of whole interface edges: it moves in steps of the
/// grid and its error is not monotone in h (fitted rate 0.73 over 1/16 …
/// 1/256), so it is held to |ℓc − reference| ≤ 2h at every size (measured at
/// most 1.76h over 2C/L = 0.2, 0.4, 0.6 and h = 1/16 … 1/256).
#[test]
fn the_q4_host_converges_to_the_reference_at_first_order() {
    use tfem::scenes::TwoBlocks;

    let exe = build_host("host_q4.cpp");
    let reference = root().join("docs/reference/two_blocks_canonical.json");
    let reference = reference.to_str().unwrap();
    let args: Vec<&str> = "--c 0.2 --n 32 --n 64 --n 128 --json --min-rate 0.8 --lc-bound 2"
        .split(' ')
        .chain(["--reference", reference])
        .collect();
    let runs = json_lines(&run(&exe, &args));
    let runs = &runs[..3];
    let h: Vec<f64> = runs.iter().map(|r| r["h"].as_f64().unwrap()).collect();
    let error = |r: &serde_json::Value, q: &str| r[format!("{q}_relative_error")].as_f64().unwrap();
    for (q, bound) in [("gap_edge", 0.8), ("v_top", 0.8), ("compliance", 0.8)] {
        let e: Vec<f64> = runs.iter().map(|r| error(r, q)).collect();
        let rate = fitted_rate(&h, &e);
        assert!(
            rate >= bound,
            "{q}: fitted rate {rate:.3} < {bound} ({e:?})"
        );
        assert!(
            e.windows(2).all(|w| w[1].abs() < w[0].abs()),
            "{q}: the error does not fall with h ({e:?})"
        );
    }
    for (r, &h) in runs.iter().zip(&h) {
        let lc = r["lc"].as_f64().unwrap();
        let lc_ref = r["lc_reference"].as_f64().unwrap();
        assert!(
            (lc - lc_ref).abs() <= 2.0 * h,
            "h = {h}: lc {lc} vs {lc_ref}"
        );
        assert_eq!(
            r["unknowns"].as_i64().unwrap() % 2,
            1,
            "symmetry line x fixed"
        );
        // tfem's own P1 on the same grid lines: the Q4 host's errors are
        // smaller for the three displacement quantities.
        let scene = TwoBlocks {
            c: 0.2,
            mesh_size: h,
            ..Default::default()
        };
        let p1 = scene
            .build()
            .unwrap()
            .solve(&tfem::ContactOptions::default())
            .unwrap();
        assert_eq!(
            r["unknowns"].as_u64().unwrap() as usize,
            p1.report.info.unknowns,
            "the same nodes and constraints as the P1 scene"
        );
        for (q, p1_value) in [
            ("gap_edge", p1.gap_edge),
            ("v_top", p1.v_top),
            ("compliance", p1.compliance),
        ] {
            let q4 = r[q].as_f64().unwrap();
            let reference = r[format!("{q}_reference")].as_f64().unwrap();
            assert!(
                (q4 - reference).abs() < (p1_value - reference).abs(),
                "h = {h}, {q}: Q4 {q4:e}, P1 {p1_value:e}, reference {reference:e}"
            );
        }
    }
}

/// examples/host_newton.cpp: the host's own Newton–Raphson loop with a
/// hyperelastic stiffening bulk law and tfem's contact contributions in its
/// residual and tangent converges quadratically for every active set (at
/// h = 1/32, 2C/L = 0.4: 4 active sets, 6 Newton iterations for the first,
/// from u = 0, and 3 for each later one, warm-started: at most 6, measured,
/// is the bound); with the law made linear it takes one Newton step per
/// active set and reproduces the linear host's displacements (host_q4) to
/// 1e-10 of the largest (measured 1.3e-13).
#[test]
fn the_newton_host_converges_and_reproduces_the_linear_host() {
    let q4 = build_host("host_q4.cpp");
    let newton = build_host("host_newton.cpp");
    let dir = lib_dir().join("c_tests");
    let dump = dir.join("host_q4_n32_c0.2.txt");
    let dump = dump.to_str().unwrap();
    run(
        &q4,
        &[
            "--n",
            "32",
            "--c",
            "0.2",
            "--dump",
            dump,
            "--reference",
            "none",
        ],
    );

    let nonlinear = &json_lines(&run(
        &newton,
        &["--n", "32", "--c", "0.2", "--json", "--max-newton", "6"],
    ))[0];
    let sets = nonlinear["residuals"].as_array().unwrap();
    assert!(sets.len() > 1, "the active set changes");
    for (k, set) in sets.iter().enumerate() {
        let r: Vec<f64> = set
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let last = *r.last().unwrap();
        assert!(last <= 1e-10, "active set {k}: |R|/|f| = {last:e} ({r:?})");
        assert!(
            r.len() - 1 <= 6,
            "active set {k}: {} Newton iterations",
            r.len() - 1
        );
        // Quadratic convergence: once |R| is small, each step squares it
        // (up to a constant), down to round-off.
        for w in r.windows(2) {
            if w[0] < 1e-2 && w[1] > 1e-12 {
                assert!(
                    w[1] <= 10.0 * w[0] * w[0],
                    "active set {k}: {:e} after {:e} is not quadratic ({r:?})",
                    w[1],
                    w[0]
                );
            }
        }
    }

    let linear = &json_lines(&run(
        &newton,
        &[
            "--n",
            "32",
            "--c",
            "0.2",
            "--linear",
            "--json",
            "--compare",
            dump,
        ],
    ))[0];
    assert_eq!(
        linear["newton_max_per_set"].as_i64(),
        Some(1),
        "linear: one Newton step per active set"
    );
    let difference = linear["compare_relative_difference"].as_f64().unwrap();
    assert!(
        difference <= 1e-10,
        "linear Newton host vs host_q4: {difference:e}"
    );
    let stiffer = nonlinear["v_top"].as_f64().unwrap() / linear["v_top"].as_f64().unwrap();
    assert!(
        stiffer < 0.95,
        "the stiffening law shows in the result (v_top ratio {stiffer})"
    );
}
