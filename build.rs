//! Records the target triple so the tests can drive the `cc` crate (which
//! normally runs inside a build script) to compile the C/C++ test programs,
//! and gives the shared library its versioned SONAME.
use std::path::Path;

fn main() {
    for key in ["TARGET", "HOST", "PROFILE"] {
        let value = std::env::var(key).unwrap_or_default();
        println!("cargo:rustc-env=TFEM_BUILD_{key}={value}");
    }
    soname();
    println!("cargo:rerun-if-changed=build.rs");
}

/// ELF targets: `libtfem.so` gets the SONAME `libtfem.so.<major>` (major of
/// the Cargo.toml version), so a program linked against it records that name
/// (`NEEDED libtfem.so.0`), not a path, and finds the library through its
/// RUNPATH or `LD_LIBRARY_PATH` wherever the install was moved to. The CMake
/// build installs `libtfem.so -> libtfem.so.0 -> libtfem.so.0.1.0`.
///
/// For programs linked straight against cargo's `target/<profile>/libtfem.so`
/// (the C and Fortran tests, the README's cargo recipe), the loader then
/// looks for `libtfem.so.0`: a symlink `libtfem.so.0 -> libtfem.so` is put
/// next to it. It dangles until cargo links the library, which is harmless.
fn soname() {
    let var = |k: &str| std::env::var(k).unwrap_or_default();
    let os = var("CARGO_CFG_TARGET_OS");
    if var("CARGO_CFG_TARGET_FAMILY") != "unix" || matches!(os.as_str(), "macos" | "ios") {
        return;
    }
    let soname = format!("libtfem.so.{}", var("CARGO_PKG_VERSION_MAJOR"));
    println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");

    // OUT_DIR is <target dir>/<profile>/build/tfem-<hash>/out.
    let out_dir = var("OUT_DIR");
    let Some(profile_dir) = Path::new(&out_dir).ancestors().nth(3) else {
        return;
    };
    let link = profile_dir.join(&soname);
    if link.symlink_metadata().is_err() {
        #[cfg(unix)]
        if let Err(e) = std::os::unix::fs::symlink("libtfem.so", &link) {
            println!("cargo:warning=could not create {}: {e}", link.display());
        }
    }
}
