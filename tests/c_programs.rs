//! Compiles the C and C++ programs of `c_tests/` against the shared
//! library built by cargo (with the `cc` crate, as a build script would)
//! and runs them: they must exit 0.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// target/<profile>, where cargo puts libtfem.so next to the deps folder.
fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test executable path");
    exe.parent().and_then(Path::parent).expect("target/<profile>").to_path_buf()
}

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

/// `cargo test` builds the library only as an rlib for the tests, so the
/// shared library the C programs link against is (re)built here, once.
fn ensure_shared_library() {
    static BUILT: std::sync::OnceLock<()> = std::sync::OnceLock::new();
    BUILT.get_or_init(|| {
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
        let mut cmd = Command::new(cargo);
        cmd.current_dir(root()).args(["build", "--lib", "--quiet"]);
        if env!("TFEM_BUILD_PROFILE") == "release" {
            cmd.arg("--release");
        }
        let status = cmd.status().expect("run cargo build --lib");
        assert!(status.success(), "cargo build --lib failed");
    });
}

/// Builds `c_tests/<source>` into an executable linked with libtfem.
pub fn build(source: &str, extra: &[&str]) -> PathBuf {
    ensure_shared_library();
    let cpp = source.ends_with(".cpp");
    let lib = lib_dir();
    assert!(
        lib.join("libtfem.so").exists(),
        "{} is missing after cargo build --lib",
        lib.join("libtfem.so").display()
    );
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

pub fn run(exe: &Path, args: &[&str]) -> String {
    let out = Command::new(exe).args(args).output().expect("run the test program");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    println!("{stdout}");
    assert!(
        out.status.success(),
        "{} failed ({}):\n{stdout}\n{}",
        exe.display(),
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

#[test]
fn c_api_test_passes_every_check() {
    let exe = build("api_test.c", &["-std=c11"]);
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
    let exe = build("element_reference.cpp", &["-std=c++17", "-I/usr/include/eigen3", "-Wno-deprecated-copy"]);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}
