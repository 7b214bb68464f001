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
