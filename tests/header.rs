//! The committed C header must be exactly what cbindgen generates from the
//! current sources. Regenerate with `TFEM_BLESS=1 cargo test --test header`.

use std::path::PathBuf;

fn generate() -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(&root)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("utf-8 header")
}

#[test]
fn committed_header_is_fresh() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("include/tfem.h");
    let fresh = generate();
    if std::env::var_os("TFEM_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("write include/tfem.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/tfem.h is stale: run `TFEM_BLESS=1 cargo test --test header` and commit it"
    );
}

#[test]
fn header_documents_every_function() {
    let fresh = generate();
    let lines: Vec<&str> = fresh.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        if line.contains(" tfem_") && line.contains('(') && !line.trim_start().starts_with('*') {
            let previous = lines[..i]
                .iter()
                .rev()
                .find(|l| !l.trim().is_empty())
                .copied()
                .unwrap_or("");
            assert!(
                previous.trim_end().ends_with("*/"),
                "function without documentation in the header: {line}"
            );
        }
    }
}
