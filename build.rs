//! Records the target triple so the tests can drive the `cc` crate (which
//! normally runs inside a build script) to compile the C/C++ test programs.
fn main() {
    for key in ["TARGET", "HOST", "PROFILE"] {
        let value = std::env::var(key).unwrap_or_default();
        println!("cargo:rustc-env=TFEM_BUILD_{key}={value}");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
