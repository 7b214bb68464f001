//! The Fortran module `include/tfem.f90` (ISO_C_BINDING interfaces to
//! every function of the C header, named constants, message helpers) is
//! generated from `include/tfem.h`; these tests keep it honest and run the
//! Fortran programs. Regenerate with `TFEM_BLESS=1 cargo test --test fortran`.
//!
//! What the generator reads from the header, beyond the C types:
//! - every doc comment, copied whole (functions, enums, structs, and the
//!   conventions block at the top of the header);
//! - which pointer arguments may be NULL ([`nullable`]): those become
//!   OPTIONAL dummy arguments;
//! - which pointer arguments are arrays ([`classify`]).
//!
//! Functions with a `size_t` length or a nullable model handle become
//! generic interfaces (see [`FORTRAN_NOTES`], copied to the top of the
//! module).

mod common;

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::process::Command;

use common::{ensure_shared_library, lib_dir, root, run};

/// A C prototype: return type, name, parameters (type, name), and its doc
/// comment (whole, lines joined by spaces).
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

/// The text of a `/** … */` comment body: lines trimmed of their `*`,
/// joined by spaces.
fn clean_doc(body: &str) -> String {
    body.lines()
        .map(|l| l.trim().trim_start_matches('*').trim())
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The doc comment that ends right before `at` (only white space between),
/// or "".
fn doc_before(text: &str, at: usize) -> String {
    let before = text[..at].trim_end();
    match (before.strip_suffix("*/"), before.rfind("/**")) {
        (Some(body), Some(start)) if start + 3 <= body.len() => clean_doc(&body[start + 3..]),
        _ => String::new(),
    }
}

/// The prototypes of the header, with their docs.
fn prototypes(header: &str) -> Vec<Proto> {
    let mut out = Vec::new();
    let mut rest = header;
    while let Some(start) = rest.find("/**") {
        let end = rest[start..].find("*/").expect("closed comment") + start;
        let doc = clean_doc(&rest[start + 3..end]);
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
                doc,
            });
        }
    }
    out
}

/// The lines of the header's leading `/* … */` comment (conventions and
/// thread contract), without the comment markers.
fn conventions(header: &str) -> Vec<String> {
    let start = header.find("/*").expect("leading comment");
    let end = header[start..].find("*/").expect("closed comment") + start;
    let mut lines: Vec<String> = header[start + 2..end]
        .lines()
        .map(|l| {
            let l = l.trim_end();
            let l = l.trim_start();
            let l = l.strip_prefix('*').unwrap_or(l);
            l.strip_prefix(' ').unwrap_or(l).to_string()
        })
        .collect();
    while lines.first().is_some_and(|l| l.is_empty()) {
        lines.remove(0);
    }
    while lines.last().is_some_and(|l| l.is_empty()) {
        lines.pop();
    }
    lines
}

/// A C enum: name, doc, and (constant, value, doc).
struct Enum {
    name: String,
    doc: String,
    consts: Vec<(String, i64, String)>,
}

/// A C struct: name, doc, and (C type, field, doc), in order.
struct Struct {
    name: String,
    doc: String,
    fields: Vec<(String, String, String)>,
}

/// Splits a `{ … }` body into its declarations (up to `,`, `;` or the end
/// of line) with the doc comment before each.
fn members(body: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut doc = String::new();
    let mut comment: Option<String> = None;
    for l in body.lines().map(str::trim) {
        if let Some(c) = comment.as_mut() {
            c.push('\n');
            c.push_str(l);
            if l.ends_with("*/") {
                doc = clean_doc(c.trim_end_matches("*/"));
                comment = None;
            }
            continue;
        }
        if let Some(c) = l.strip_prefix("/**") {
            if let Some(one) = c.strip_suffix("*/") {
                doc = clean_doc(one);
            } else {
                comment = Some(c.to_string());
            }
            continue;
        }
        if !l.is_empty() {
            out.push((l.to_string(), std::mem::take(&mut doc)));
        }
    }
    out
}

fn enums(header: &str) -> Vec<Enum> {
    let mut out = Vec::new();
    for (at, _) in header.match_indices("typedef enum ") {
        let block = &header[at + "typedef enum ".len()..];
        let name = block.split_whitespace().next().unwrap().to_string();
        let body = &block[block.find('{').unwrap() + 1..block.find('}').unwrap()];
        let consts = members(body)
            .into_iter()
            .filter(|(l, _)| l.starts_with("TFEM_"))
            .map(|(l, doc)| {
                let (k, v) = l.trim_end_matches(',').split_once('=').unwrap();
                (k.trim().to_string(), v.trim().parse().unwrap(), doc)
            })
            .collect();
        out.push(Enum {
            name,
            doc: doc_before(header, at),
            consts,
        });
    }
    out
}

fn structs(header: &str) -> Vec<Struct> {
    let mut out = Vec::new();
    for (at, _) in header.match_indices("typedef struct ") {
        let block = &header[at + "typedef struct ".len()..];
        let name = block.split_whitespace().next().unwrap().to_string();
        let Some(open) = block.find('{') else {
            continue;
        };
        if open > block.find(';').unwrap_or(usize::MAX) {
            continue; // opaque
        }
        let body = &block[open + 1..block.find("} ").unwrap()];
        let fields = members(body)
            .into_iter()
            .filter_map(|(l, doc)| {
                let decl = l.strip_suffix(';')?;
                let cut = decl.rfind(' ').unwrap();
                Some((
                    decl[..cut].trim().to_string(),
                    decl[cut + 1..].to_string(),
                    doc,
                ))
            })
            .collect();
        out.push(Struct {
            name,
            doc: doc_before(header, at),
            fields,
        });
    }
    out
}

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

// ---------------------------------------------------------------------------
// What the header's documentation says about the parameters.

/// Sentences about NULL that make no parameter optional: the small table of
/// what the nullability rule cannot tell from the wording itself. Every
/// sentence of a function's doc that mentions NULL must either be read by
/// [`nullable`] or contain one of these phrases
/// ([`every_null_in_the_function_docs_is_understood`]).
const NULL_WITHOUT_OPTIONAL: [(&str, &str); 4] = [
    ("Returns NULL", "about the return value"),
    ("never NULL", "about the return value"),
    (
        "NULL is a no-op",
        "tfem_destroy: NULL is harmless, but a call without the handle to \
         destroy means nothing, so `model` stays required",
    ),
    ("tfem_last_error(NULL", "names a call of another function"),
];

/// Phrases that make every pointer argument but the model handle nullable.
const ANY_POINTER_MAY_BE_NULL: [&str; 3] = [
    "Any pointer may be NULL",
    "Either pointer may be NULL",
    "Every pointer may be NULL",
];

/// The opaque handles of the C ABI, passed as `type(c_ptr), value`.
const HANDLES: [&str; 2] = ["struct tfem_model", "struct tfem_contact"];

fn is_handle(ty: &str) -> bool {
    let base = ty.trim_start_matches("const ").trim_end_matches('*').trim();
    HANDLES.contains(&base)
}

/// The nullability rule. A pointer parameter `p` of a function may be NULL
/// (and so is OPTIONAL in Fortran) when the function's doc says
/// "`p` may be NULL", "`p` (may be NULL" or "With `p` NULL"; or, for every
/// pointer parameter except the model handle, "Any pointer may be NULL" or
/// "Either pointer may be NULL". Nothing else makes a parameter optional.
fn nullable(p: &Proto) -> Vec<String> {
    let doc = &p.doc;
    let any = ANY_POINTER_MAY_BE_NULL.iter().any(|s| doc.contains(s));
    p.params
        .iter()
        .filter(|(ty, _)| ty.ends_with('*'))
        .filter(|(ty, n)| {
            (any && !is_handle(ty))
                || [
                    format!("`{n}` may be NULL"),
                    format!("`{n}` (may be NULL"),
                    format!("With `{n}` NULL"),
                    format!("with `{n}` NULL"),
                ]
                .iter()
                .any(|s| doc.contains(s.as_str()))
        })
        .map(|(_, n)| n.clone())
        .collect()
}

/// The sentences of a doc that mention NULL and that neither the rule nor
/// the table [`NULL_WITHOUT_OPTIONAL`] accounts for.
fn unexplained_nulls(p: &Proto) -> Vec<String> {
    let one = |s: &str| Proto {
        doc: s.to_string(),
        ..p.clone()
    };
    p.doc
        .split(". ")
        .flat_map(|s| s.split("; "))
        .filter(|s| s.contains("NULL"))
        .filter(|s| {
            nullable(&one(s)).is_empty()
                && !NULL_WITHOUT_OPTIONAL
                    .iter()
                    .any(|(phrase, _)| s.contains(phrase))
        })
        .map(str::to_string)
        .collect()
}

/// How a C parameter is passed.
#[derive(Debug, Clone, PartialEq)]
enum Pass {
    /// The opaque model handle: type(c_ptr), value.
    Handle,
    /// A struct by reference (const: intent(in)).
    Struct { name: String, konst: bool },
    /// A scalar by value.
    Value(String),
    /// An array (assumed size).
    Array { base: String, konst: bool },
    /// A scalar output by reference: intent(inout), as a failed call
    /// writes none of its outputs (the header's conventions, [`KEPT_RULE`]).
    /// With intent(out) the argument is undefined on entry, and the
    /// caller's value may not survive the call even when the C side leaves
    /// it alone: gfortran -O2 drops a store made just before the call
    /// (tfem_get_warning_size gave 0, not the 7 set before it).
    Out { base: String },
}

/// Reads how parameter `k` of `p` is passed. A pointer is an array when it
/// points to char, is const (an input), is followed by a `size_t` length
/// (the header's buffer convention) or its doc says "`name` (N values"
/// (N digits or the name of a size, such as n_entries);
/// any other non-const pointer is a scalar output.
fn classify(p: &Proto, k: usize) -> Pass {
    let (ty, name) = &p.params[k];
    let konst = ty.starts_with("const ");
    let base = ty.trim_start_matches("const ").trim_end_matches('*').trim();
    if !ty.ends_with('*') {
        return Pass::Value(base.to_string());
    }
    if HANDLES.contains(&base) {
        return Pass::Handle;
    }
    if let Some(s) = base.strip_prefix("struct ") {
        return Pass::Struct {
            name: s.to_string(),
            konst,
        };
    }
    let next_is_length = p.params.get(k + 1).is_some_and(|(t, _)| t == "size_t");
    let sized = p.doc.match_indices(&format!("`{name}` (")).any(|(at, m)| {
        // A count: digits, or a size's name such as n_entries.
        let rest = &p.doc[at + m.len()..];
        let count = rest
            .char_indices()
            .take_while(|&(_, c)| c.is_ascii_alphanumeric() || c == '_')
            .last()
            .map_or(0, |(i, c)| i + c.len_utf8());
        count > 0 && rest[count..].starts_with(" values")
    });
    if base == "char" || konst || next_is_length || sized {
        Pass::Array {
            base: base.to_string(),
            konst,
        }
    } else {
        Pass::Out {
            base: base.to_string(),
        }
    }
}

fn kind_of(base: &str) -> &'static str {
    match base {
        "double" => "real(c_double)",
        "int" => "integer(c_int)",
        "int64_t" => "integer(c_int64_t)",
        "uint8_t" => "integer(c_int8_t)",
        "size_t" => "integer(c_size_t)",
        "char" => "character(kind=c_char)",
        t => panic!("no Fortran mapping for parameter type {t}"),
    }
}

/// The Fortran declaration of one C parameter in the bind(C) interface.
fn fortran_param(pass: &Pass, name: &str, optional: bool) -> String {
    let opt = if optional { ", optional" } else { "" };
    match pass {
        Pass::Handle => format!("type(c_ptr), value :: {name}"),
        Pass::Struct { name: s, konst } => {
            let intent = if *konst { "in" } else { "inout" };
            format!("type({s}), intent({intent}){opt} :: {name}")
        }
        Pass::Value(base) => format!("{}, value :: {name}", kind_of(base)),
        Pass::Array { base, konst } => format!(
            "{}, intent({}){opt} :: {name}(*)",
            kind_of(base),
            if *konst { "in" } else { "inout" }
        ),
        Pass::Out { base } => format!("{}, intent(inout){opt} :: {name}", kind_of(base)),
    }
}

// ---------------------------------------------------------------------------
// Generic interfaces.

/// What the module says, at its top, about its Fortran-specific design.
const FORTRAN_NOTES: &str = "\
In Fortran (`use tfem`), where it differs from the C conventions above
- The model handle is a type(c_ptr) from tfem_create, passed by value.
- Functions returning a tfem_status return an integer(c_int): compare it with the
  TFEM_STATUS_* parameters below. tfem_error_message([model]) returns the last error as a
  Fortran string (model omitted: the calling thread's model-free calls);
  tfem_contact_error_message(context) that of a contact context;
  tfem_warning_message(model, index) and tfem_version_string() return strings too.
- Indices: pass index_base = 1 to tfem_set_mesh (or tfem_load_gmsh) and every node, triangle
  and edge number of later calls and messages is 1-based, like Fortran arrays. Numbers that a
  function documents as 0-based stay 0-based.
- NULL: a pointer argument that the C documentation says may be NULL is OPTIONAL here: omit it
  (by keywords, or at the end of the list) and the library receives NULL (Fortran 2018 and
  TS 29113: an absent optional argument of a bind(C) procedure is passed as a null pointer).
  This needs a Fortran 2018 compiler mode: gfortran's default or -std=f2018, not -std=f2008.
  A nullable model handle is passed by value, which a bind(C) interface cannot make OPTIONAL:
  its generic has a specific without it instead (tfem_last_error(buffer, length),
  tfem_last_error_length()).
- Kinds: C int is integer(c_int), the default integer of gfortran, ifx, flang and nvfortran
  (unless built with -fdefault-integer-8 or -i8), so default integer counts, indices and
  index arrays are passed as they are; double is real(c_double), int64_t integer(c_int64_t).
  Buffer lengths (size_t) accept default integers too: see the generic interfaces below.
- Character buffers are character(kind=c_char) arrays (or strings, for generic functions); a
  path is NUL-terminated: append c_null_char.

Generic interfaces
A function with a size_t length or a nullable model handle is a generic interface named like
the C function. Its specifics:
- the bind(C) interface itself, under the C name too, so that calls with integer(c_size_t)
  lengths (the kind of integer(c_int64_t) on 64-bit platforms), procedure actual arguments and
  c_funloc keep working as before;
- private module procedures that convert and forward to it, named after the C function with
  suffixes: _i takes every length as integer(tfem_length_kind) (c_int where size_t is wider, so
  default integers and literals; c_int64_t where size_t is c_int) and passes a negative length
  as 0, so that the call fails with TFEM_STATUS_BUFFER_TOO_SMALL; _no_<arg> omits a nullable
  model handle and passes c_null_ptr; _str takes a character(len=*) string for each character
  buffer (generic resolution needs matching ranks, so without it a string would no longer
  reach the array dummy by sequence association).
All the lengths of one call share one kind. For the reason of _str, pass the buffers of a
generic function as arrays or array sections, not as their first element (u(1)). Counts and
indices (C int) are not generic: integer(c_int) is already the default integer.";

/// A specific of a generic interface: which conversions it makes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct Variant {
    /// Without the nullable model handle (passes c_null_ptr).
    omit_handle: bool,
    /// Character buffers as character(len=*) strings.
    string: bool,
    /// Lengths as integer(tfem_length_kind).
    alt_length: bool,
}

/// Everything the generator derives about one function.
struct Shape {
    passes: Vec<Pass>,
    /// Per parameter: OPTIONAL in the bind(C) interface (nullable, by
    /// reference).
    optional: Vec<bool>,
    /// The nullable model handle, if any.
    nullable_handle: Option<usize>,
    /// The size_t parameters.
    lengths: Vec<usize>,
    /// The character arrays.
    chars: Vec<usize>,
}

fn shape(p: &Proto) -> Shape {
    let passes: Vec<Pass> = (0..p.params.len()).map(|k| classify(p, k)).collect();
    let null = nullable(p);
    let is_null = |k: usize| null.contains(&p.params[k].1);
    let handles: Vec<usize> = (0..passes.len())
        .filter(|&k| passes[k] == Pass::Handle && is_null(k))
        .collect();
    assert!(
        handles.len() <= 1,
        "{}: more than one nullable handle; the generator supports one",
        p.name
    );
    Shape {
        optional: (0..passes.len())
            .map(|k| passes[k] != Pass::Handle && is_null(k))
            .collect(),
        nullable_handle: handles.first().copied(),
        lengths: (0..passes.len())
            .filter(|&k| passes[k] == Pass::Value("size_t".into()))
            .collect(),
        chars: (0..passes.len())
            .filter(|&k| matches!(&passes[k], Pass::Array { base, .. } if base == "char"))
            .collect(),
        passes,
    }
}

impl Shape {
    fn generic(&self) -> bool {
        !self.lengths.is_empty() || self.nullable_handle.is_some()
    }

    /// The module-procedure specifics of the generic (the bind(C) interface
    /// is the remaining one); empty when the function is not generic.
    fn variants(&self) -> Vec<Variant> {
        if !self.generic() {
            return Vec::new();
        }
        let choices = |on: bool| if on { vec![false, true] } else { vec![false] };
        let mut out = Vec::new();
        for omit_handle in choices(self.nullable_handle.is_some()) {
            for string in choices(!self.chars.is_empty()) {
                for alt_length in choices(!self.lengths.is_empty()) {
                    let v = Variant {
                        omit_handle,
                        string,
                        alt_length,
                    };
                    if v != Variant::default() {
                        out.push(v);
                    }
                }
            }
        }
        out
    }
}

fn specific_name(p: &Proto, s: &Shape, v: Variant) -> String {
    let mut name = p.name.clone();
    if v.omit_handle {
        name.push_str("_no_");
        name.push_str(&p.params[s.nullable_handle.unwrap()].1);
    }
    if v.string {
        name.push_str("_str");
    }
    if v.alt_length {
        name.push_str("_i");
    }
    assert!(name.len() <= 63, "Fortran name {name} is longer than 63");
    name
}

/// The bind(C) interface, reachable by a specific name from the `_str`
/// specifics (a string is sequence-associated with an array dummy only in
/// a reference to a specific procedure).
fn raw_name(p: &Proto) -> String {
    format!("{}_raw", p.name)
}

/// `a`, `a` and `b`, `a`, `b` and `c`.
fn list(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    match quoted.len() {
        0 => String::new(),
        1 => quoted[0].clone(),
        n => format!("{} and {}", quoted[..n - 1].join(", "), quoted[n - 1]),
    }
}

/// The Fortran-specific sentence added to a function's C doc.
fn fortran_note(p: &Proto, s: &Shape) -> Option<String> {
    let names =
        |ks: &[usize]| -> Vec<String> { ks.iter().map(|&k| p.params[k].1.clone()).collect() };
    let mut parts = Vec::new();
    let optional: Vec<usize> = (0..p.params.len()).filter(|&k| s.optional[k]).collect();
    if !optional.is_empty() {
        let (verb, it) = if optional.len() == 1 {
            ("is", "it")
        } else {
            ("are", "them")
        };
        parts.push(format!(
            "{} {verb} OPTIONAL: omit {it} to pass NULL.",
            list(&names(&optional))
        ));
    }
    if let Some(h) = s.nullable_handle {
        parts.push(format!(
            "`{}` may be omitted (NULL is passed).",
            p.params[h].1
        ));
    }
    match s.lengths.len() {
        0 => {}
        1 => parts.push(format!(
            "{} takes an integer(c_size_t) or a default integer (kind tfem_length_kind); \
             a negative length is passed as 0.",
            list(&names(&s.lengths))
        )),
        _ => parts.push(format!(
            "{} take integer(c_size_t) or default integers (kind tfem_length_kind), all of \
             one kind; a negative length is passed as 0.",
            list(&names(&s.lengths))
        )),
    }
    if s.generic() && !s.chars.is_empty() {
        parts.push(format!(
            "{} may also be a character string.",
            list(&names(&s.chars))
        ));
    }
    (!parts.is_empty()).then(|| format!("Fortran: {}", parts.join(" ")))
}

/// Appends `text` as `!>`/`!!` comment lines at `indent`, wrapped at 100
/// columns.
fn comment(f: &mut String, indent: &str, text: &str) {
    wrap(f, indent, text, "!>", "!!");
}

/// Appends `text` as comment lines starting `first` then `rest`, wrapped
/// at 100 columns.
fn wrap(f: &mut String, indent: &str, text: &str, first: &str, rest: &str) {
    let mut line = format!("{indent}{first}");
    let bare = line.len();
    for w in text.split_whitespace() {
        if line.len() > bare && line.chars().count() + 1 + w.chars().count() > 100 {
            f.push_str(&line);
            f.push('\n');
            line = format!("{indent}{rest}");
        }
        line.push(' ');
        line.push_str(w);
    }
    f.push_str(&line);
    f.push('\n');
}

/// `a, b, c` with free-form continuations before column 100; `lead` is
/// the width of the line before the list.
fn arglist(args: &[String], lead: usize) -> String {
    let mut out = String::new();
    let mut line = lead;
    for (k, a) in args.iter().enumerate() {
        if k > 0 {
            out.push(',');
            line += 1;
            if line + a.len() > 100 {
                out.push_str(" &\n        ");
                line = 8;
            } else {
                out.push(' ');
                line += 1;
            }
        }
        out.push_str(a);
        line += a.len();
    }
    out
}

/// (subroutine or function, ` result(x)`, declaration of the result).
fn result_of(p: &Proto) -> (&'static str, &'static str, &'static str) {
    match p.ret.as_str() {
        "void" => ("subroutine", "", ""),
        "enum tfem_status" => ("function", " result(status)", "integer(c_int) :: status"),
        "size_t" => ("function", " result(res)", "integer(c_size_t) :: res"),
        "const char *" | "struct tfem_model *" | "struct tfem_contact *" => {
            ("function", " result(res)", "type(c_ptr) :: res")
        }
        t => panic!("no Fortran mapping for return type {t}"),
    }
}

/// The bind(C) interface body of `p`.
fn interface_body(f: &mut String, p: &Proto, s: &Shape) {
    let mut doc = p.doc.clone();
    if let Some(note) = fortran_note(p, s) {
        doc = format!("{doc} {note}");
    }
    comment(f, "    ", &doc);
    let (kind, result, decl) = result_of(p);
    let args: Vec<String> = p.params.iter().map(|(_, n)| n.clone()).collect();
    writeln!(
        f,
        "    {kind} {}({}) &\n        bind(C, name=\"{}\"){result}",
        p.name,
        arglist(&args, p.name.len() + 10),
        p.name
    )
    .unwrap();
    f.push_str("      import\n");
    for (k, (_, n)) in p.params.iter().enumerate() {
        writeln!(f, "      {}", fortran_param(&s.passes[k], n, s.optional[k])).unwrap();
    }
    if !decl.is_empty() {
        writeln!(f, "      {decl}").unwrap();
    }
    writeln!(f, "    end {kind} {}", p.name).unwrap();
}

/// A module procedure: `name(args)` forwarding to `target` with `actuals`.
fn forwarder(
    f: &mut String,
    p: &Proto,
    name: &str,
    args: &[String],
    decls: &[String],
    target: &str,
    actuals: &[String],
) {
    let (kind, result, decl) = result_of(p);
    writeln!(
        f,
        "  {kind} {name}({}){result}",
        arglist(args, name.len() + kind.len() + 4)
    )
    .unwrap();
    for d in decls {
        writeln!(f, "    {d}").unwrap();
    }
    if !decl.is_empty() {
        writeln!(f, "    {decl}").unwrap();
    }
    let lhs = match kind {
        "subroutine" => "call ".to_string(),
        _ => format!("{} = ", &result[" result(".len()..result.len() - 1]),
    };
    writeln!(
        f,
        "    {lhs}{target}({})",
        arglist(actuals, 4 + lhs.len() + target.len() + 1)
    )
    .unwrap();
    writeln!(f, "  end {kind} {name}\n").unwrap();
}

/// The module procedures behind the generic of `p`.
fn specifics(f: &mut String, p: &Proto, s: &Shape) {
    for v in s.variants() {
        let name = specific_name(p, s, v);
        let mut what = Vec::new();
        if v.omit_handle {
            what.push(format!(
                "without `{}` (NULL)",
                p.params[s.nullable_handle.unwrap()].1
            ));
        }
        if v.string {
            what.push("character buffers as strings".to_string());
        }
        if v.alt_length {
            what.push("lengths of kind tfem_length_kind".to_string());
        }
        wrap(
            f,
            "  ",
            &format!("{}, {}.", p.name, what.join(", ")),
            "!",
            "!",
        );
        let (mut args, mut decls, mut actuals) = (Vec::new(), Vec::new(), Vec::new());
        for (k, (_, n)) in p.params.iter().enumerate() {
            if v.omit_handle && Some(k) == s.nullable_handle {
                actuals.push("c_null_ptr".to_string());
                continue;
            }
            args.push(n.clone());
            if v.alt_length && s.lengths.contains(&k) {
                decls.push(format!("integer(tfem_length_kind), intent(in) :: {n}"));
                actuals.push(format!("tfem_to_size_t({n})"));
                continue;
            }
            actuals.push(n.clone());
            match &s.passes[k] {
                Pass::Array { base, konst } if v.string && base == "char" => decls.push(format!(
                    "character(kind=c_char, len=*), intent({}){} :: {n}",
                    if *konst { "in" } else { "inout" },
                    if s.optional[k] { ", optional" } else { "" }
                )),
                pass => decls.push(fortran_param(pass, n, s.optional[k])),
            }
        }
        let target = if v.string {
            raw_name(p)
        } else {
            p.name.clone()
        };
        forwarder(f, p, &name, &args, &decls, &target, &actuals);
    }
    if s.generic() && !s.chars.is_empty() {
        writeln!(
            f,
            "  ! {}, by a specific name (for the strings of the _str specifics).",
            p.name
        )
        .unwrap();
        let args: Vec<String> = p.params.iter().map(|(_, n)| n.clone()).collect();
        let decls: Vec<String> = p
            .params
            .iter()
            .enumerate()
            .map(|(k, (_, n))| fortran_param(&s.passes[k], n, s.optional[k]))
            .collect();
        forwarder(f, p, &raw_name(p), &args, &decls, &p.name, &args);
    }
}

fn generate(header: &str) -> String {
    let mut f = String::new();
    f.push_str(
        "! Generated from include/tfem.h by tests/fortran.rs. Do not edit:\n\
         ! regenerate with `TFEM_BLESS=1 cargo test --test fortran`.\n\
         !\n\
         ! Fortran interface to tfem (ISO_C_BINDING): every function of tfem.h with its whole\n\
         ! documentation, the enums as named constants, the structs as bind(C) types, and\n\
         ! string helpers. From tfem.h:\n\
         !\n",
    );
    for l in conventions(header)
        .iter()
        .map(String::as_str)
        .chain([""])
        .chain(FORTRAN_NOTES.lines())
    {
        writeln!(f, "{}", format!("! {l}").trim_end()).unwrap();
    }
    let protos = prototypes(header);
    let shapes: Vec<Shape> = protos.iter().map(shape).collect();
    f.push_str(
        "module tfem\n  use, intrinsic :: iso_c_binding\n  implicit none\n  private :: c_strlen, tfem_to_size_t\n",
    );
    for (p, s) in protos.iter().zip(&shapes) {
        for v in s.variants() {
            writeln!(f, "  private :: {}", specific_name(p, s, v)).unwrap();
        }
        if s.generic() && !s.chars.is_empty() {
            writeln!(f, "  private :: {}", raw_name(p)).unwrap();
        }
    }
    f.push('\n');
    comment(
        &mut f,
        "  ",
        "The kind of the lengths the generic interfaces accept besides integer(c_size_t): \
         c_int (the default integer) where size_t is wider, else c_int64_t.",
    );
    f.push_str(
        "  integer, parameter :: tfem_length_kind = merge(c_int, c_int64_t, c_size_t /= c_int)\n\n",
    );
    for e in enums(header) {
        wrap(
            &mut f,
            "  ",
            &format!("enum {}: {}", e.name, e.doc),
            "!",
            "!",
        );
        for (k, v, doc) in e.consts {
            comment(&mut f, "  ", &doc);
            writeln!(f, "  integer(c_int), parameter :: {k} = {v}").unwrap();
        }
        f.push('\n');
    }
    for st in structs(header) {
        comment(&mut f, "  ", &st.doc);
        writeln!(f, "  type, bind(C) :: {}", st.name).unwrap();
        for (ty, field, doc) in st.fields {
            comment(&mut f, "    ", &doc);
            writeln!(f, "    {} :: {field}", fortran_field(&ty)).unwrap();
        }
        writeln!(f, "  end type {}\n", st.name).unwrap();
    }
    for (p, s) in protos.iter().zip(&shapes) {
        if s.generic() {
            writeln!(f, "  interface {}", p.name).unwrap();
            interface_body(&mut f, p, s);
            for v in s.variants() {
                writeln!(f, "    module procedure {}", specific_name(p, s, v)).unwrap();
            }
            writeln!(f, "  end interface {}\n", p.name).unwrap();
        } else {
            f.push_str("  interface\n");
            interface_body(&mut f, p, s);
            f.push_str("  end interface\n\n");
        }
    }
    f.push_str(
        "contains\n\n\
         \x20 pure function c_strlen(buf) result(n)\n\
         \x20   character(kind=c_char), intent(in) :: buf(:)\n\
         \x20   integer :: n\n\
         \x20   n = 0\n\
         \x20   do while (n < size(buf))\n\
         \x20     if (buf(n + 1) == c_null_char) exit\n\
         \x20     n = n + 1\n\
         \x20   end do\n\
         \x20 end function c_strlen\n\n\
         \x20 !> A length of kind tfem_length_kind as integer(c_size_t). A negative length becomes 0, so\n\
         \x20 !! that the library reports TFEM_STATUS_BUFFER_TOO_SMALL instead of reading a huge size_t.\n\
         \x20 elemental function tfem_to_size_t(n) result(s)\n\
         \x20   integer(tfem_length_kind), intent(in) :: n\n\
         \x20   integer(c_size_t) :: s\n\
         \x20   if (n <= 0) then\n\
         \x20     s = 0\n\
         \x20   else if (n >= huge(s)) then\n\
         \x20     s = huge(s)\n\
         \x20   else\n\
         \x20     s = int(n, c_size_t)\n\
         \x20   end if\n\
         \x20 end function tfem_to_size_t\n\n",
    );
    for (p, s) in protos.iter().zip(&shapes) {
        specifics(&mut f, p, s);
    }
    f.push_str(
        "\x20 !> The message of the last failed call on model (omitted or c_null_ptr: this thread's\n\
         \x20 !! model-free calls), as a Fortran string.\n\
         \x20 function tfem_error_message(model) result(msg)\n\
         \x20   type(c_ptr), intent(in), optional :: model\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   type(c_ptr) :: handle\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   handle = c_null_ptr\n\
         \x20   if (present(model)) handle = model\n\
         \x20   allocate(buf(tfem_last_error_length(handle)))\n\
         \x20   status = tfem_last_error(handle, buf, size(buf, kind=c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_error_message\n\n\
         \x20 !> The message of the last failed call on the contact context (from\n\
         \x20 !! tfem_contact_create), as a Fortran string: a context keeps its own messages,\n\
         \x20 !! which tfem_error_message, reading a model's, does not see.\n\
         \x20 !! The buffer is sized by tfem_contact_last_error_length, so that a message of any length\n\
         \x20 !! comes whole.\n\
         \x20 function tfem_contact_error_message(context) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: context\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   allocate(buf(tfem_contact_last_error_length(context)))\n\
         \x20   buf(1) = c_null_char\n\
         \x20   status = tfem_contact_last_error(context, buf, size(buf, kind=c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   if (status == TFEM_STATUS_NULL_POINTER) n = 0\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_contact_error_message\n\n\
         \x20 !> Warning number index (0-based) of model, as a Fortran string. The buffer is sized by\n\
         \x20 !! tfem_get_warning_size, so that a warning of any length comes whole.\n\
         \x20 function tfem_warning_message(model, index) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: model\n\
         \x20   integer, intent(in) :: index\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_size_t) :: bytes\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   bytes = 1\n\
         \x20   if (tfem_get_warning_size(model, int(index, c_int), bytes) /= TFEM_STATUS_OK) bytes = 1\n\
         \x20   allocate(buf(bytes))\n\
         \x20   buf(1) = c_null_char\n\
         \x20   status = tfem_get_warning(model, int(index, c_int), buf, size(buf, kind=c_size_t))\n\
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

fn module() -> String {
    std::fs::read_to_string(root().join("include/tfem.f90")).expect("include/tfem.f90")
}

// ---------------------------------------------------------------------------
// Reading the committed module back (independent of the generator).

/// A procedure of the module: its dummy arguments and declaration lines.
struct FProc {
    args: Vec<String>,
    decls: Vec<String>,
}

/// Every function and subroutine of the module (interface bodies and
/// module procedures), by name.
fn procedures(module: &str) -> BTreeMap<String, FProc> {
    const HEADS: [&str; 4] = [
        "function ",
        "subroutine ",
        "pure function ",
        "elemental function ",
    ];
    let mut out = BTreeMap::new();
    let mut lines = module.lines().map(str::trim);
    while let Some(l) = lines.next() {
        let Some(mut rest) = HEADS
            .iter()
            .find_map(|k| l.strip_prefix(k))
            .map(str::to_string)
        else {
            continue;
        };
        while rest.trim_end().ends_with('&') {
            let next = lines.next().expect("continued line");
            rest = format!("{} {next}", rest.trim_end().trim_end_matches('&'));
        }
        let name = rest[..rest.find('(').expect("argument list")]
            .trim()
            .to_string();
        let inner = &rest[rest.find('(').unwrap() + 1..rest.find(')').unwrap()];
        let args = inner
            .split(',')
            .map(str::trim)
            .filter(|a| !a.is_empty())
            .map(str::to_string)
            .collect();
        let mut decls = Vec::new();
        for l in lines.by_ref() {
            if l.starts_with("end function") || l.starts_with("end subroutine") {
                break;
            }
            if l.contains("::") {
                decls.push(l.to_string());
            }
        }
        out.insert(name, FProc { args, decls });
    }
    out
}

/// Generic name -> its specific procedures (the interface body of the same
/// name included), read from the module's `interface <name>` blocks.
fn generics(module: &str) -> BTreeMap<String, Vec<String>> {
    let mut out: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut current: Option<String> = None;
    for l in module.lines().map(str::trim) {
        if let Some(name) = l.strip_prefix("interface ") {
            current = Some(name.trim().to_string());
            out.entry(name.trim().to_string()).or_default();
        } else if l.starts_with("end interface") {
            current = None;
        } else if let (Some(g), Some(p)) = (&current, l.strip_prefix("module procedure ")) {
            out.get_mut(g).unwrap().push(p.trim().to_string());
        } else if let (Some(g), true) = (&current, l.contains("bind(C, name=")) {
            out.get_mut(g).unwrap().push(g.clone());
        }
    }
    out
}

/// The declaration of dummy `n` among `decls`.
fn decl_of<'a>(decls: &'a [String], n: &str) -> Option<&'a String> {
    decls.iter().find(|l| {
        let l = l.trim_end();
        l.ends_with(&format!(":: {n}")) || l.ends_with(&format!(":: {n}(*)"))
    })
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
    let module = module();
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
            let handle = is_handle(ty);
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
                "uint8_t" => decl.contains("c_int8_t"),
                "size_t" => decl.contains("c_size_t"),
                "char" => decl.contains("c_char"),
                "struct tfem_model" | "struct tfem_contact" => decl.contains("c_ptr"),
                s => decl.contains(s.trim_start_matches("struct ")),
            };
            assert!(kind_ok, "{}: {n} declared `{decl}` for C type {ty}", p.name);
        }
    }
}

#[test]
fn module_keeps_the_whole_c_documentation_within_132_columns() {
    let module = module();
    let header = header();
    for (k, l) in module.lines().enumerate() {
        assert!(
            l.len() <= 132,
            "line {} of tfem.f90 is {} bytes (free form ends at column 132): {l}",
            k + 1,
            l.len()
        );
    }
    // The comment block right above each bind(C) interface holds the whole
    // doc of its C function.
    let lines: Vec<&str> = module.lines().collect();
    for p in prototypes(&header) {
        let head = lines
            .iter()
            .position(|l| {
                let l = l.trim_start();
                (l.starts_with("function ") || l.starts_with("subroutine "))
                    && l.contains(&format!(" {}(", p.name))
            })
            .unwrap_or_else(|| panic!("no interface head for {}", p.name));
        let mut text = Vec::new();
        for l in lines[..head].iter().rev() {
            let Some(c) = l.trim_start().strip_prefix('!') else {
                break;
            };
            text.push(c.trim_start_matches(['>', '!']).trim());
        }
        text.reverse();
        let text = squash(&text.join(" "));
        assert!(
            text.contains(&squash(&p.doc)),
            "{}: the module's comment\n  {text}\ndoes not hold the C doc\n  {}",
            p.name,
            p.doc
        );
    }
    // The conventions and the thread contract, line by line.
    let top: Vec<&str> = module.lines().take_while(|l| l.starts_with('!')).collect();
    for l in conventions(&header) {
        assert!(
            top.contains(&format!("! {l}").trim_end()),
            "the module's header comment lacks the line `{l}` of tfem.h"
        );
    }
    // Enum constants and struct fields keep their docs too.
    for e in enums(&header) {
        for (k, _, doc) in &e.consts {
            let at = module.find(&format!(":: {k} =")).expect("constant");
            let before = squash(&module[..at].replace("!>", "").replace("!!", ""));
            assert!(before.contains(&squash(doc)), "{k}: doc missing");
        }
    }
}

#[test]
fn nullability_rule_reads_the_doc_wording() {
    let proto = |doc: &str| Proto {
        ret: "enum tfem_status".into(),
        name: "tfem_f".into(),
        params: vec![
            ("struct tfem_model *".into(), "model".into()),
            ("int *".into(), "count".into()),
            ("struct tfem_solve_info *".into(), "info".into()),
        ],
        doc: doc.into(),
    };
    let cases: [(&str, &[&str]); 9] = [
        ("Writes it to `count` (may be NULL).", &["count"]),
        ("`info` may be NULL.", &["info"]),
        (
            "`info` may be NULL (defaults); `count` may be NULL.",
            &["count", "info"],
        ),
        ("With `model` NULL, reads the thread's error.", &["model"]),
        ("Any pointer may be NULL.", &["count", "info"]),
        ("Either pointer may be NULL.", &["count", "info"]),
        ("Writes it to `count`.", &[]),
        ("`count` must not be NULL.", &[]),
        ("Errors go to `tfem_last_error(NULL, …)`.", &[]),
    ];
    for (doc, expected) in cases {
        assert_eq!(nullable(&proto(doc)), expected.to_vec(), "{doc}");
    }
    // Wording the rule does not know is reported, not guessed.
    assert_eq!(
        unexplained_nulls(&proto("`count` can be NULL.")),
        vec!["`count` can be NULL.".to_string()]
    );
    assert!(unexplained_nulls(&proto("`count` (may be NULL). NULL is a no-op.")).is_empty());
}

#[test]
fn every_null_in_the_function_docs_is_understood() {
    // A doc sentence about NULL that neither the rule nor the table
    // NULL_WITHOUT_OPTIONAL reads would leave a nullable parameter
    // required: extend the rule (or the table) when this fails.
    let mut unexplained = Vec::new();
    for p in prototypes(&header()) {
        for s in unexplained_nulls(&p) {
            unexplained.push(format!("{}: {s}", p.name));
        }
    }
    assert!(
        unexplained.is_empty(),
        "doc sentences mention NULL in wording the nullability rule does not read:\n{}",
        unexplained.join("\n")
    );
}

#[test]
fn documented_nullable_parameters_are_optional_and_lengths_generic() {
    // Read back from the committed module: every pointer parameter the doc
    // says may be NULL is OPTIONAL (a nullable handle: the generic has a
    // specific without it), and no other is; every function with a size_t
    // length is generic with a specific taking tfem_length_kind lengths.
    let module = module();
    let procs = procedures(&module);
    let generics = generics(&module);
    let mut optional = 0;
    for p in prototypes(&header()) {
        let null = nullable(&p);
        let raw = &procs[&p.name];
        let c_names: Vec<String> = p.params.iter().map(|(_, n)| n.clone()).collect();
        let specifics: Vec<&FProc> = generics
            .get(&p.name)
            .map(|g| g.iter().map(|s| &procs[s]).collect())
            .unwrap_or_default();
        for (ty, n) in &p.params {
            let decl = decl_of(&raw.decls, n).expect("declaration");
            if is_handle(ty) {
                assert!(!decl.contains("optional"), "{}: {decl}", p.name);
                let without: Vec<&String> = c_names.iter().filter(|a| *a != n).collect();
                let omittable = specifics
                    .iter()
                    .any(|s| s.args.iter().collect::<Vec<_>>() == without);
                assert_eq!(
                    omittable,
                    null.contains(n),
                    "{}: `{n}` can be omitted iff the doc says it may be NULL",
                    p.name
                );
                optional += usize::from(omittable);
            } else if ty.ends_with('*') {
                assert_eq!(
                    decl.contains(", optional"),
                    null.contains(n),
                    "{}: `{decl}` is OPTIONAL iff the doc says `{n}` may be NULL",
                    p.name
                );
                optional += usize::from(null.contains(n));
            }
        }
        let lengths: Vec<&String> = p
            .params
            .iter()
            .filter(|(ty, _)| ty == "size_t")
            .map(|(_, n)| n)
            .collect();
        if !lengths.is_empty() {
            let converting = specifics.iter().any(|s| {
                s.args == c_names
                    && lengths.iter().all(|n| {
                        decl_of(&s.decls, n).is_some_and(|d| d.contains("tfem_length_kind"))
                    })
            });
            assert!(
                converting,
                "{}: no specific takes the lengths as integer(tfem_length_kind)",
                p.name
            );
        }
    }
    assert!(optional >= 10, "only {optional} nullable parameters found");
}

// ---------------------------------------------------------------------------
// Fortran programs.

/// Compiles Fortran sources (module first; objects allowed) into an
/// executable linked with libtfem and returns its path.
fn build_fortran(sources: &[&Path], name: &str) -> PathBuf {
    build_fortran_with(sources, name, &[])
}

/// [`build_fortran`] with extra gfortran flags (an optimisation level).
fn build_fortran_with(sources: &[&Path], name: &str, flags: &[&str]) -> PathBuf {
    ensure_shared_library();
    let lib = lib_dir();
    let dir = lib.join("fortran").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let exe = dir.join(name);
    // Fortran 2018: OPTIONAL dummies of bind(C) interfaces (TS 29113).
    let out = Command::new("gfortran")
        .arg("-std=f2018")
        .arg("-Wall")
        .arg("-Werror")
        .arg("-Wno-unused-dummy-argument")
        .args(flags)
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

/// Writes a generated source into the build folder of `name`.
fn generated_source(name: &str, file: &str, text: &str) -> PathBuf {
    let dir = lib_dir().join("fortran").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn every_function_takes_default_integer_lengths_and_omitted_nullables() {
    // A generated program (compiled and linked, never run) calls every
    // function four ways: as C would (c_size_t lengths, every argument);
    // with default-integer literal lengths and every nullable argument
    // omitted; with c_int64_t lengths and strings for character buffers;
    // with c_int lengths, strings and nullables omitted.
    let mut vars: BTreeMap<String, String> = BTreeMap::new();
    let mut calls = String::new();
    for p in prototypes(&header()) {
        let s = shape(&p);
        let null = nullable(&p);
        for (length, keywords, omit, string) in [
            ("1_c_size_t", false, false, false),
            ("1", true, true, false),
            ("1_c_int64_t", true, false, true),
            ("1_c_int", true, true, true),
        ] {
            let mut args = Vec::new();
            for (k, (_, n)) in p.params.iter().enumerate() {
                if omit && null.contains(n) {
                    continue;
                }
                let (var, decl): (String, String) = match &s.passes[k] {
                    Pass::Handle => ("model".into(), "type(c_ptr) :: model = c_null_ptr".into()),
                    Pass::Struct { name, .. } => {
                        (format!("s_{name}"), format!("type({name}) :: s_{name}"))
                    }
                    Pass::Value(b) => match b.as_str() {
                        "double" => ("1.0_c_double".into(), String::new()),
                        "int" => ("1".into(), String::new()),
                        "int64_t" => ("1_c_int64_t".into(), String::new()),
                        "size_t" => (length.into(), String::new()),
                        t => panic!("no actual argument for {t}"),
                    },
                    Pass::Array { base, .. } => {
                        let (v, d) = match base.as_str() {
                            "double" => ("rd", "real(c_double) :: rd(64) = 0"),
                            "int" => ("ia", "integer(c_int) :: ia(64) = 0"),
                            "int64_t" => ("la", "integer(c_int64_t) :: la(64) = 0"),
                            "uint8_t" => ("ba", "integer(c_int8_t) :: ba(64) = 0"),
                            "char" if string => ("cs", "character(len=64) :: cs = ''"),
                            "char" => ("ca", "character(kind=c_char) :: ca(64) = ''"),
                            t => panic!("no actual argument for {t}"),
                        };
                        (v.into(), d.into())
                    }
                    Pass::Out { base, .. } => {
                        // One variable per position: two outputs of a call
                        // must not share an actual argument.
                        let (v, t) = match base.as_str() {
                            "double" => ("sd", "real(c_double)"),
                            "int" => ("si", "integer(c_int)"),
                            "int64_t" => ("sl", "integer(c_int64_t)"),
                            "size_t" => ("sz", "integer(c_size_t)"),
                            t => panic!("no actual argument for {t}"),
                        };
                        (format!("{v}{k}"), format!("{t} :: {v}{k}"))
                    }
                };
                if !decl.is_empty() {
                    vars.insert(var.clone(), decl);
                }
                args.push(if keywords {
                    format!("{n}={var}")
                } else {
                    var.to_string()
                });
            }
            let lhs = match p.ret.as_str() {
                "void" => "call ",
                "enum tfem_status" => {
                    vars.insert("st".into(), "integer(c_int) :: st".into());
                    "st = "
                }
                "size_t" => {
                    vars.insert("sz".into(), "integer(c_size_t) :: sz".into());
                    "sz = "
                }
                _ => {
                    vars.insert("pp".into(), "type(c_ptr) :: pp".into());
                    "pp = "
                }
            };
            writeln!(
                calls,
                "  {lhs}{}({})",
                p.name,
                arglist(&args, 2 + lhs.len() + p.name.len() + 1)
            )
            .unwrap();
        }
    }
    let mut program = String::from(
        "! Generated by tests/fortran.rs: every function of tfem.h called four ways.\n\
         program every_call\n  use, intrinsic :: iso_c_binding\n  use tfem\n  implicit none\n",
    );
    for d in vars.values() {
        writeln!(program, "  {d}").unwrap();
    }
    program.push_str(&calls);
    program.push_str("end program every_call\n");
    let source = generated_source("every_call", "every_call.f90", &program);
    build_fortran(&[&source], "every_call");
}

#[test]
fn gfortran_passes_null_for_every_absent_optional_argument_kind() {
    // Every kind of OPTIONAL dummy the module's bind(C) interfaces use,
    // checked against a C function that reports whether it got NULL:
    // absent, present, and absent forwarded through an optional dummy of a
    // module procedure (as the generic specifics do).
    let module = module();
    let procs = procedures(&module);
    let mut kinds = BTreeSet::new();
    for p in prototypes(&header()) {
        for d in &procs[&p.name].decls {
            if let Some((ty, name)) = d.split_once(" ::") {
                if ty.contains(", optional") {
                    kinds.insert((ty.replace(", optional", ""), name.ends_with("(*)")));
                }
            }
        }
    }
    assert!(kinds.len() >= 4, "optional kinds: {kinds:?}");
    let mut c = String::from("#include <stddef.h>\n");
    let mut interfaces = String::new();
    let mut decls = String::new();
    let mut checks = String::new();
    let mut forwards = String::new();
    for (k, (ty, array)) in kinds.iter().enumerate() {
        let dims = if *array { "(*)" } else { "" };
        writeln!(
            c,
            "int tfem_optional_probe_{k}(const void *x) {{ return x == NULL; }}"
        )
        .unwrap();
        writeln!(
            interfaces,
            "    function probe_{k}(x) bind(C, name=\"tfem_optional_probe_{k}\") result(isnull)\n\
             \x20     import\n\
             \x20     {ty}, optional :: x{dims}\n\
             \x20     integer(c_int) :: isnull\n\
             \x20   end function probe_{k}"
        )
        .unwrap();
        let var_ty = ty.split(", intent").next().unwrap();
        let var_dims = if *array { "(4)" } else { "" };
        writeln!(decls, "  {var_ty} :: x_{k}{var_dims}").unwrap();
        writeln!(
            checks,
            "  call expect(probe_{k}() == 1, '{ty}: absent is NULL')\n\
             \x20 call expect(probe_{k}(x_{k}) == 0, '{ty}: present is not NULL')\n\
             \x20 call expect(forward_{k}() == 1, '{ty}: absent and forwarded is NULL')"
        )
        .unwrap();
        writeln!(
            forwards,
            "  function forward_{k}(x) result(isnull)\n\
             \x20   {ty}, optional :: x{dims}\n\
             \x20   integer(c_int) :: isnull\n\
             \x20   isnull = probe_{k}(x)\n\
             \x20 end function forward_{k}"
        )
        .unwrap();
    }
    let program = format!(
        "program optional_probe\n  use, intrinsic :: iso_c_binding\n  use tfem\n  implicit none\n\
         \x20 interface\n{interfaces}  end interface\n{decls}  integer :: failed = 0, checked = 0\n\
         {checks}  write (*, '(i0, a, i0, a)') checked, ' checked, ', failed, ' failed'\n\
         \x20 if (failed > 0) stop 1\ncontains\n\
         \x20 subroutine expect(ok, what)\n    logical, intent(in) :: ok\n\
         \x20   character(len=*), intent(in) :: what\n    checked = checked + 1\n\
         \x20   if (.not. ok) then\n      failed = failed + 1\n      write (*, '(2a)') 'FAIL ', what\n\
         \x20   end if\n  end subroutine expect\n{forwards}end program optional_probe\n"
    );
    let c_source = generated_source("optional_probe", "probe.c", &c);
    let object = c_source.with_extension("o");
    let out = cc::Build::new()
        .cargo_metadata(false)
        .target(env!("TFEM_BUILD_TARGET"))
        .host(env!("TFEM_BUILD_HOST"))
        .opt_level(0)
        .get_compiler()
        .to_command()
        .arg("-c")
        .arg(&c_source)
        .arg("-o")
        .arg(&object)
        .output()
        .expect("run the C compiler");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let source = generated_source("optional_probe", "optional_probe.f90", &program);
    let exe = build_fortran(&[&source, &object], "optional_probe");
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// The header's rule that every scalar output declared intent(inout)
/// stands on: a failed call writes none of its outputs.
const KEPT_RULE: &str = "A call that returns an error writes none of its outputs";

/// The header states that a failed call writes none of its outputs, and
/// every scalar output is intent(inout) in the committed module
/// (intent(out) would make it undefined on entry, and the caller's value
/// could be lost on error); none is intent(out).
#[test]
fn outputs_kept_on_error_are_intent_inout() {
    let module = module();
    assert!(
        squash(&header()).contains(&squash(KEPT_RULE)),
        "the header no longer states the rule: {KEPT_RULE}"
    );
    assert!(!module.contains("intent(out)"), "an intent(out) output");
    let mut kept = Vec::new();
    for p in prototypes(&header()) {
        let at = module
            .find(&format!("bind(C, name=\"{}\")", p.name))
            .unwrap_or_else(|| panic!("no Fortran interface for {}", p.name));
        let body = &module[at..module[at..].find("end ").unwrap() + at];
        for (k, (_, n)) in p.params.iter().enumerate() {
            let Pass::Out { .. } = classify(&p, k) else {
                continue;
            };
            let decl = body
                .lines()
                .find(|l| l.trim_end().ends_with(&format!(":: {n}")))
                .unwrap_or_else(|| panic!("{}: no declaration of {n}", p.name));
            assert!(
                decl.contains("intent(inout)"),
                "{}: {n} declared `{decl}`, not intent(inout)",
                p.name
            );
            kept.push(format!("{}({n})", p.name));
        }
    }
    assert!(kept.contains(&"tfem_get_warning_size(size)".to_string()));
    assert!(kept.len() > 20, "{kept:?}");
}

/// tfem_get_warning_size refused (an index out of range) leaves `size` as
/// it was, also in Fortran built with -O2: with `size` intent(out) there,
/// gfortran dropped the 7 stored before the call, and `size` came back 0.
#[test]
fn a_refused_warning_size_keeps_the_fortran_variable_at_o2() {
    let source = generated_source(
        "warning_size_kept",
        "warning_size_kept.f90",
        "program warning_size_kept\n\
         \x20 use, intrinsic :: iso_c_binding\n\
         \x20 use tfem\n\
         \x20 implicit none\n\
         \x20 type(c_ptr) :: m\n\
         \x20 integer(c_size_t) :: size\n\
         \x20 integer(c_int) :: status\n\
         \x20 m = tfem_create()\n\
         \x20 size = 7\n\
         \x20 status = tfem_get_warning_size(m, 0_c_int, size)\n\
         \x20 print '(a, i0, a, i0)', 'status ', status, ' size ', size\n\
         \x20 call tfem_destroy(m)\n\
         end program warning_size_kept\n",
    );
    let exe = build_fortran_with(&[&source], "warning_size_kept", &["-O2"]);
    let out = run(&exe, &[]);
    assert_eq!(
        out.trim(),
        format!("status {} size 7", tfem::Status::InvalidArgument as i32),
        "{out}"
    );
}

/// A failed call writes none of its outputs (the header's rule), and the
/// Fortran variables passed for them keep their values at -O2 too: the
/// count of tfem_get_boundary_edge_count, an optional size of
/// tfem_get_sizes and the work of tfem_get_external_work, all refused
/// without a mesh. Declared intent(out) before, gfortran -O2 could drop
/// the values stored just before the calls.
#[test]
fn failed_calls_keep_the_fortran_output_variables_at_o2() {
    let source = generated_source(
        "outputs_kept",
        "outputs_kept.f90",
        "program outputs_kept\n\
         \x20 use, intrinsic :: iso_c_binding\n\
         \x20 use tfem\n\
         \x20 implicit none\n\
         \x20 type(c_ptr) :: m\n\
         \x20 integer(c_int) :: count, nodes, s1, s2, s3\n\
         \x20 real(c_double) :: work\n\
         \x20 m = tfem_create()\n\
         \x20 count = 7\n\
         \x20 nodes = 8\n\
         \x20 work = 9.5_c_double\n\
         \x20 s1 = tfem_get_boundary_edge_count(m, count)\n\
         \x20 s2 = tfem_get_sizes(m, n_nodes=nodes)\n\
         \x20 s3 = tfem_get_external_work(m, work)\n\
         \x20 print '(5(i0, 1x), f3.1)', s1, s2, s3, count, nodes, work\n\
         \x20 call tfem_destroy(m)\n\
         end program outputs_kept\n",
    );
    let exe = build_fortran_with(&[&source], "outputs_kept", &["-O2"]);
    let out = run(&exe, &[]);
    let state = tfem::Status::InvalidState as i32;
    assert_eq!(
        out.trim(),
        format!("{state} {state} {state} 7 8 9.5"),
        "{out}"
    );
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
fn fortran_generic_test_passes_every_check() {
    let exe = build_fortran(
        &[&root().join("c_tests/fortran_generic_test.f90")],
        "fortran_generic_test",
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

#[test]
fn fortran_host_with_its_own_skyline_solver_reproduces_the_built_in_contact_solve() {
    use tfem::scenes::TwoBlocks;
    // examples/host_skyline.f90 keeps its own P1 elements, equation
    // numbering, skyline LDLᵀ and active-set loop, and takes only the
    // contact from tfem_contact_* (index_base = 1); it solves the same mesh
    // with tfem_solve_contact and prints both. Two mesh sizes, two widths.
    let exe = build_fortran(&[&root().join("examples/host_skyline.f90")], "host_skyline");
    for (ratio, cells) in [(0.2, 32), (0.6, 32), (0.2, 64), (0.6, 64)] {
        let out = run(&exe, &[&ratio.to_string(), &cells.to_string()]);
        let fields = |name: &str| -> Vec<String> {
            let line = out
                .lines()
                .find(|l| l.split_whitespace().next() == Some(name))
                .unwrap_or_else(|| panic!("{name} missing in {out}"));
            line.split_whitespace().skip(1).map(String::from).collect()
        };
        let number = |name: &str, k: usize| -> f64 { fields(name)[k].parse().unwrap() };
        let case = format!("2C/L = {ratio}, h = 1/{cells}");
        let rel = number("relative_difference", 0);
        assert!(rel <= 1e-10, "{case}: host vs built-in {rel:e}\n{out}");
        // At these sizes the skyline agrees without its refinement step too.
        let plain = number("relative_difference_unrefined", 0);
        assert!(plain <= 1e-10, "{case}: unrefined {plain:e}\n{out}");
        assert_eq!(fields("same_active_set"), ["T"], "{case}\n{out}");
        assert_eq!(fields("same_element_order"), ["T"], "{case}\n{out}");
        let (host, tfem) = (number("iterations", 0), number("iterations", 1));
        assert_eq!(host, tfem, "{case}: active-set iterations");
        assert_eq!(number("unknowns", 0), number("unknowns", 1), "{case}");
        // The contact couples the two interface rows, outside the bodies'
        // profile: the host had to raise those columns.
        let outside = number("outside_body_profile", 0);
        assert!(
            outside > 0.0,
            "{case}: the contact stays in the body profile?\n{out}"
        );
        assert!(out.contains("agreement ok"), "{out}");
        // The host's numbers are the seed scene's (the Rust scene, same mesh).
        let mut s = TwoBlocks {
            c: 0.5 * ratio,
            mesh_size: 1.0 / cells as f64,
            ..Default::default()
        }
        .build()
        .unwrap();
        let r = s.solve(&tfem::ContactOptions::default()).unwrap();
        let lc = number("lc", 0);
        assert!(
            (lc - r.lc).abs() <= 1e-12 * r.lc,
            "{case}: lc {lc} vs {}",
            r.lc
        );
        // Displacements: to 1e-10 of the largest, as the example checks.
        let scale = number("max_displacement", 0);
        for (name, rust) in [("gap_edge", r.gap_edge), ("v_top", r.v_top)] {
            let host = number(name, 0);
            assert!(
                (host - rust).abs() <= 1e-10 * scale,
                "{case}: {name} host {host} vs Rust {rust}"
            );
        }
        assert_eq!(
            host as usize, r.report.iterations,
            "{case}: Rust iterations"
        );
    }
}
