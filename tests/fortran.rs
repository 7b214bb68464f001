//! The Fortran module `include/tfem.f90` (ISO_C_BINDING interfaces to
//! every function of the C header, named constants, message helpers) is
//! generated from `include/tfem.h`; these tests keep it honest and run the
//! Fortran programs. Regenerate with `TFEM_BLESS=1 cargo test --test fortran`.

mod common;

use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::Command;

use common::{ensure_shared_library, lib_dir, root, run};

/// A C prototype: return type, name, parameters (type, name).
#[derive(Debug, Clone, PartialEq)]
struct Proto {
    ret: String,
    name: String,
    params: Vec<(String, String)>,
    doc: String,
}

fn squash(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The prototypes of the header, with the first sentence of their docs.
fn prototypes(header: &str) -> Vec<Proto> {
    let mut out = Vec::new();
    let mut rest = header;
    while let Some(start) = rest.find("/**") {
        let end = rest[start..].find("*/").expect("closed comment") + start;
        let doc = rest[start + 3..end]
            .lines()
            .map(|l| l.trim().trim_start_matches('*').trim())
            .filter(|l| !l.is_empty())
            .collect::<Vec<_>>()
            .join(" ");
        rest = &rest[end + 2..];
        let semi = rest.find(';').unwrap_or(rest.len());
        let decl = squash(&rest[..semi]);
        let plain = !decl.contains("/*") && !decl.contains('{') && !decl.contains('}');
        if plain && decl.contains("tfem_") && decl.contains('(') && !decl.starts_with("typedef") {
            let open = decl.find('(').unwrap();
            let head = &decl[..open];
            let name_start = head.rfind([' ', '*']).unwrap() + 1;
            let ret = head[..name_start].trim().to_string();
            let name = head[name_start..].to_string();
            let inner = &decl[open + 1..decl.rfind(')').unwrap()];
            let params = if inner.trim() == "void" {
                Vec::new()
            } else {
                inner
                    .split(',')
                    .map(|p| {
                        let p = p.trim();
                        let cut = p
                            .rfind([' ', '*'])
                            .unwrap_or_else(|| panic!("cannot split parameter `{p}` of `{decl}`"))
                            + 1;
                        (p[..cut].trim().to_string(), p[cut..].to_string())
                    })
                    .collect()
            };
            out.push(Proto {
                ret,
                name,
                params,
                doc: doc.clone(),
            });
        }
    }
    out
}

/// (enum name, [(constant, value)]) of the header.
fn enums(header: &str) -> Vec<(String, Vec<(String, i64)>)> {
    let mut out = Vec::new();
    for block in header.split("typedef enum ").skip(1) {
        let name = block.split_whitespace().next().unwrap().to_string();
        let body = &block[block.find('{').unwrap() + 1..block.find('}').unwrap()];
        let consts = body
            .lines()
            .map(str::trim)
            .filter(|l| l.starts_with("TFEM_"))
            .map(|l| {
                let (k, v) = l.trim_end_matches(',').split_once('=').unwrap();
                (k.trim().to_string(), v.trim().parse().unwrap())
            })
            .collect();
        out.push((name, consts));
    }
    out
}

/// (struct name, [(C type, field)]) of the header, in order.
fn structs(header: &str) -> Vec<(String, Vec<(String, String)>)> {
    let mut out = Vec::new();
    for block in header.split("typedef struct ").skip(1) {
        let name = block.split_whitespace().next().unwrap().to_string();
        let Some(open) = block.find('{') else {
            continue;
        };
        if open > block.find(';').unwrap_or(usize::MAX) {
            continue; // opaque
        }
        let body = &block[open + 1..block.find("} ").unwrap()];
        let mut fields = Vec::new();
        let mut in_comment = false;
        for l in body.lines().map(str::trim) {
            if l.starts_with("/**") {
                in_comment = !l.ends_with("*/");
                continue;
            }
            if in_comment {
                in_comment = !l.ends_with("*/");
                continue;
            }
            if let Some(decl) = l.strip_suffix(';') {
                let cut = decl.rfind(' ').unwrap();
                fields.push((decl[..cut].trim().to_string(), decl[cut + 1..].to_string()));
            }
        }
        out.push((name, fields));
    }
    out
}

const ARRAYS: [&str; 12] = [
    "path",
    "xy",
    "connectivity",
    "body_of_triangle",
    "edge_nodes",
    "tags",
    "out",
    "buffer",
    "col_ptr",
    "row_idx",
    "values",
    "dofs",
];

fn fortran_field(ty: &str) -> String {
    match ty {
        "int64_t" => "integer(c_int64_t)".into(),
        "double" => "real(c_double)".into(),
        "int" => "integer(c_int)".into(),
        t if t.starts_with("struct ") => format!("type({})", &t[7..]),
        t if t.starts_with("tfem_") => format!("type({t})"),
        t => panic!("no Fortran mapping for field type {t}"),
    }
}

/// The Fortran declaration of one C parameter.
fn fortran_param(ty: &str, name: &str) -> String {
    let array = ARRAYS.contains(&name);
    let konst = ty.starts_with("const ");
    let base = ty.trim_start_matches("const ").trim_end_matches('*').trim();
    let pointer = ty.ends_with('*');
    if base == "struct tfem_model" {
        return format!("type(c_ptr), value :: {name}");
    }
    if let Some(s) = base.strip_prefix("struct ") {
        let intent = if konst { "in" } else { "inout" };
        return format!("type({s}), intent({intent}) :: {name}");
    }
    let kind = match base {
        "double" => "real(c_double)",
        "int" => "integer(c_int)",
        "int64_t" => "integer(c_int64_t)",
        "size_t" => "integer(c_size_t)",
        "char" => "character(kind=c_char)",
        t => panic!("no Fortran mapping for parameter type {t}"),
    };
    match (pointer, array) {
        (false, _) => format!("{kind}, value :: {name}"),
        (true, true) => format!(
            "{kind}, intent({}) :: {name}(*)",
            if konst { "in" } else { "inout" }
        ),
        (true, false) => format!(
            "{kind}, intent({}) :: {name}",
            if konst { "in" } else { "out" }
        ),
    }
}

fn wrap_doc(doc: &str) -> String {
    let first = doc.split(". ").next().unwrap_or("").trim_end_matches('.');
    let mut out = String::new();
    let mut line = String::from("  !>");
    for w in first.split_whitespace() {
        if line.len() + w.len() > 100 {
            out.push_str(&line);
            out.push('\n');
            line = String::from("  !!");
        }
        line.push(' ');
        line.push_str(w);
    }
    out.push_str(&line);
    out.push('\n');
    out
}

fn generate(header: &str) -> String {
    let mut f = String::new();
    f.push_str(
        "! Generated from include/tfem.h by tests/fortran.rs. Do not edit:\n\
         ! regenerate with `TFEM_BLESS=1 cargo test --test fortran`.\n\
         !\n\
         ! Fortran interface to tfem (ISO_C_BINDING). Every function returns an\n\
         ! integer(c_int) status (TFEM_STATUS_OK = 0). Pass index_base = 1 to\n\
         ! tfem_set_mesh to use 1-based node, triangle and edge numbers in every\n\
         ! call and message. The model handle is a type(c_ptr). See tfem.h for\n\
         ! units, sizes and the thread contract; tfem_error_message(model) returns\n\
         ! the last error as a Fortran string.\n\
         module tfem\n  use, intrinsic :: iso_c_binding\n  implicit none\n  private :: c_strlen\n\n",
    );
    for (name, consts) in enums(header) {
        writeln!(f, "  ! {name}").unwrap();
        for (k, v) in consts {
            writeln!(f, "  integer(c_int), parameter :: {k} = {v}").unwrap();
        }
        f.push('\n');
    }
    for (name, fields) in structs(header) {
        writeln!(f, "  type, bind(C) :: {name}").unwrap();
        for (ty, field) in fields {
            writeln!(f, "    {} :: {field}", fortran_field(&ty)).unwrap();
        }
        writeln!(f, "  end type {name}\n").unwrap();
    }
    f.push_str("  interface\n");
    for p in prototypes(header) {
        f.push_str(&wrap_doc(&p.doc));
        let args: Vec<&str> = p.params.iter().map(|(_, n)| n.as_str()).collect();
        // Free-form lines end at column 132: long argument lists continue.
        let mut arglist = String::new();
        let mut line = p.name.len() + 10;
        for (k, a) in args.iter().enumerate() {
            if k > 0 {
                arglist.push(',');
                line += 1;
                if line + a.len() > 100 {
                    arglist.push_str(" &\n        ");
                    line = 8;
                } else {
                    arglist.push(' ');
                    line += 1;
                }
            }
            arglist.push_str(a);
            line += a.len();
        }
        let (kind, result) = match p.ret.as_str() {
            "void" => ("subroutine", String::new()),
            "enum tfem_status" => ("function", " result(status)".into()),
            _ => ("function", " result(res)".into()),
        };
        writeln!(
            f,
            "    {kind} {}({arglist}) &\n        bind(C, name=\"{}\"){result}",
            p.name, p.name
        )
        .unwrap();
        f.push_str("      import\n");
        for (ty, n) in &p.params {
            writeln!(f, "      {}", fortran_param(ty, n)).unwrap();
        }
        match p.ret.as_str() {
            "void" => {}
            "enum tfem_status" => f.push_str("      integer(c_int) :: status\n"),
            "size_t" => f.push_str("      integer(c_size_t) :: res\n"),
            "const char *" | "struct tfem_model *" => f.push_str("      type(c_ptr) :: res\n"),
            t => panic!("no Fortran mapping for return type {t}"),
        }
        writeln!(f, "    end {kind} {}\n", p.name).unwrap();
    }
    f.push_str(
        "  end interface\n\n\
         contains\n\n\
         \x20 pure function c_strlen(buf) result(n)\n\
         \x20   character(kind=c_char), intent(in) :: buf(:)\n\
         \x20   integer :: n\n\
         \x20   n = 0\n\
         \x20   do while (n < size(buf))\n\
         \x20     if (buf(n + 1) == c_null_char) exit\n\
         \x20     n = n + 1\n\
         \x20   end do\n\
         \x20 end function c_strlen\n\n\
         \x20 !> The message of the last failed call on model (c_null_ptr: this thread's\n\
         \x20 !! model-free calls), as a Fortran string.\n\
         \x20 function tfem_error_message(model) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: model\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   allocate(buf(tfem_last_error_length(model)))\n\
         \x20   status = tfem_last_error(model, buf, int(size(buf), c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_error_message\n\n\
         \x20 !> Warning number index (0-based) of model, as a Fortran string.\n\
         \x20 function tfem_warning_message(model, index) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: model\n\
         \x20   integer, intent(in) :: index\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char) :: buf(4096)\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   status = tfem_get_warning(model, int(index, c_int), buf, int(size(buf), c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   if (status /= TFEM_STATUS_OK .and. status /= TFEM_STATUS_BUFFER_TOO_SMALL) n = 0\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_warning_message\n\n\
         \x20 !> The library version as a Fortran string.\n\
         \x20 function tfem_version_string() result(v)\n\
         \x20   character(len=:), allocatable :: v\n\
         \x20   character(kind=c_char), pointer :: p(:)\n\
         \x20   integer :: i, n\n\
         \x20   call c_f_pointer(tfem_version(), p, [64])\n\
         \x20   n = c_strlen(p)\n\
         \x20   allocate(character(len=n) :: v)\n\
         \x20   do i = 1, n\n\
         \x20     v(i:i) = p(i)\n\
         \x20   end do\n\
         \x20 end function tfem_version_string\n\n\
         end module tfem\n",
    );
    f
}

fn header() -> String {
    std::fs::read_to_string(root().join("include/tfem.h")).expect("include/tfem.h")
}

#[test]
fn fortran_module_is_generated_from_the_current_header() {
    let path = root().join("include/tfem.f90");
    let fresh = generate(&header());
    if std::env::var_os("TFEM_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("write include/tfem.f90");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/tfem.f90 is stale: run `TFEM_BLESS=1 cargo test --test fortran`"
    );
}

#[test]
fn every_header_function_has_a_matching_fortran_interface() {
    // Independent of the generator: read the committed module back.
    let module =
        std::fs::read_to_string(root().join("include/tfem.f90")).expect("include/tfem.f90");
    let protos = prototypes(&header());
    assert!(
        protos.len() >= 30,
        "parsed only {} prototypes",
        protos.len()
    );
    for p in protos {
        let marker = format!("bind(C, name=\"{}\")", p.name);
        let at = module
            .find(&marker)
            .unwrap_or_else(|| panic!("no Fortran interface for {}", p.name));
        let head_start = module[..at]
            .rfind(&format!(" {}(", p.name))
            .expect("interface head");
        let head = &module[head_start..at];
        let args = &head[head.find('(').unwrap() + 1..head.find(')').unwrap()];
        let args = args.replace('&', "");
        let names: Vec<&str> = args
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect();
        let c_names: Vec<&str> = p.params.iter().map(|(_, n)| n.as_str()).collect();
        assert_eq!(names, c_names, "arguments of {}", p.name);
        let body_end = module[at..].find("end ").unwrap() + at;
        let body = &module[at..body_end];
        for (ty, n) in &p.params {
            let decl = body
                .lines()
                .find(|l| {
                    l.trim_end().ends_with(&format!(":: {n}"))
                        || l.trim_end().ends_with(&format!(":: {n}(*)"))
                })
                .unwrap_or_else(|| panic!("{}: no declaration of {n}", p.name));
            // Pointers are passed by reference, except the opaque handle,
            // which is a type(c_ptr) passed by value.
            let by_value = decl.contains(", value ::");
            let handle = ty.contains("struct tfem_model");
            assert_eq!(
                by_value,
                handle || !ty.ends_with('*'),
                "{}: {n} passing vs C type {ty}",
                p.name
            );
            let kind_ok = match ty.trim_start_matches("const ").trim_end_matches('*').trim() {
                "double" => decl.contains("c_double"),
                "int" => decl.contains("c_int"),
                "int64_t" => decl.contains("c_int64_t"),
                "size_t" => decl.contains("c_size_t"),
                "char" => decl.contains("c_char"),
                "struct tfem_model" => decl.contains("c_ptr"),
                s => decl.contains(s.trim_start_matches("struct ")),
            };
            assert!(kind_ok, "{}: {n} declared `{decl}` for C type {ty}", p.name);
        }
    }
}

/// Compiles Fortran sources (module first) into an executable linked with
/// libtfem and returns its path.
fn build_fortran(sources: &[&Path], name: &str) -> PathBuf {
    ensure_shared_library();
    let lib = lib_dir();
    let dir = lib.join("fortran").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let exe = dir.join(name);
    let out = Command::new("gfortran")
        .arg("-std=f2008")
        .arg("-Wall")
        .arg("-Werror")
        .arg("-Wno-unused-dummy-argument")
        .arg("-J")
        .arg(&dir)
        .arg(root().join("include/tfem.f90"))
        .args(sources)
        .arg("-o")
        .arg(&exe)
        .arg(format!("-L{}", lib.display()))
        .arg("-ltfem")
        .arg(format!("-Wl,-rpath,{}", lib.display()))
        .output()
        .expect("gfortran is installed (Debian package gfortran; scripts/test.sh installs it)");
    assert!(
        out.status.success(),
        "gfortran failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

#[test]
fn fortran_api_test_passes_every_check() {
    let exe = build_fortran(
        &[&root().join("c_tests/fortran_api_test.f90")],
        "fortran_api_test",
    );
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

#[test]
fn fortran_seed_scene_example_matches_the_rust_numbers() {
    use tfem::scenes::TwoBlocks;
    let exe = build_fortran(&[&root().join("examples/two_blocks.f90")], "two_blocks_f90");
    let out = run(&exe, &[]);
    let value = |name: &str| -> f64 {
        out.lines()
            .find_map(|l| l.trim().strip_prefix(&format!("{name} ")))
            .unwrap_or_else(|| panic!("{name} missing in {out}"))
            .trim()
            .parse()
            .unwrap()
    };
    // The Fortran example meshes the canonical scene (2C/L = 0.2, h = 1/32)
    // with the same structured triangulation: the numbers agree to round-off.
    let mut s = TwoBlocks {
        mesh_size: 1.0 / 32.0,
        ..Default::default()
    }
    .build()
    .unwrap();
    let r = s.solve(&tfem::ContactOptions::default()).unwrap();
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-10 * a.abs().max(b.abs());
    assert!(same(value("lc"), r.lc), "lc {} vs {}", value("lc"), r.lc);
    assert!(
        same(value("gap_edge"), r.gap_edge),
        "gap_edge {} vs {}",
        value("gap_edge"),
        r.gap_edge
    );
    assert!(
        same(value("v_top"), r.v_top),
        "v_top {} vs {}",
        value("v_top"),
        r.v_top
    );
    assert_eq!(value("iterations") as usize, r.report.iterations);
}
