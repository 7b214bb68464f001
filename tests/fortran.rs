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
//! The file is Fortran 2008 and holds three modules: tfem_c (the bind(C)
//! interfaces as the C prototypes have them), tfem_specifics (module
//! procedures) and tfem (the module to use), in which the functions with a
//! `size_t` length, a nullable pointer or a nullable model handle are
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
    /// The head of the group this prototype opens (the header's
    /// `/****…` comments), if it does.
    section: Option<String>,
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
    let mut section = None;
    while let Some(start) = rest.find("/**") {
        let end = rest[start..].find("*/").expect("closed comment") + start;
        let banner = rest[start..].starts_with("/****");
        let doc = clean_doc(rest[start + 3..end].trim_matches('*'));
        rest = &rest[end + 2..];
        if banner {
            section = Some(doc);
            continue;
        }
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
                section: section.take(),
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
const HANDLES: [&str; 4] = [
    "struct tfem_model",
    "struct tfem_contact",
    "struct tfem_solid_model",
    "struct tfem_solid_contact",
];

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

/// The Fortran declaration of one C parameter in tfem_c's bind(C)
/// interface: every argument required, as the C prototype has it.
fn fortran_param(pass: &Pass, name: &str) -> String {
    match pass {
        Pass::Handle => format!("type(c_ptr), value :: {name}"),
        Pass::Struct { name: s, konst } => {
            let intent = if *konst { "in" } else { "inout" };
            format!("type({s}), intent({intent}) :: {name}")
        }
        Pass::Value(base) => format!("{}, value :: {name}", kind_of(base)),
        Pass::Array { base, konst } => format!(
            "{}, intent({}) :: {name}(*)",
            kind_of(base),
            if *konst { "in" } else { "inout" }
        ),
        Pass::Out { base } => format!("{}, intent(inout) :: {name}", kind_of(base)),
    }
}

// ---------------------------------------------------------------------------
// The modules: tfem_c, tfem_specifics, tfem.

/// What the module says, at its top, about its Fortran-specific design;
/// the functions of [`Offer::Procedures`] are listed after it.
const FORTRAN_NOTES: &str = "\
In Fortran (`use tfem`), where it differs from the C conventions above
- The model handle is a type(c_ptr) from tfem_create, passed by value.
- Functions returning a tfem_status return an integer(c_int): compare it with the
  TFEM_STATUS_* parameters below. tfem_error_message([model]) returns the last error as a
  Fortran string (model omitted: the calling thread's model-free calls);
  tfem_contact_error_message(context) that of a contact context;
  tfem_solid_error_message(model) that of a 3D model (from tfem_solid_create);
  tfem_solid_contact_error_message(context) that of a 3D contact context;
  tfem_warning_message(model, index), tfem_solid_warning_message(model, index) and
  tfem_version_string() return strings too.
- Indices: pass index_base = 1 to tfem_set_mesh (or tfem_load_gmsh; for a 3D model
  tfem_solid_set_mesh or tfem_solid_load_gmsh; for a contact context tfem_contact_create or
  tfem_solid_contact_create) and every node, triangle, tetrahedron, edge and face number of
  later calls and messages is 1-based, like Fortran arrays. Numbers that a function documents
  as 0-based stay 0-based.
- NULL: a pointer argument that the C documentation says may be NULL is OPTIONAL: omit it (by
  keyword, or at the end of the list) and the library receives NULL. A nullable model handle
  is passed by value: its generic has a specific without it instead (tfem_last_error(buffer,
  length), tfem_last_error_length()).
- Kinds: C int is integer(c_int), the default integer of gfortran, ifx, flang and nvfortran
  (unless built with -fdefault-integer-8 or -i8), so default integer counts, indices and
  index arrays are passed as they are; double is real(c_double), int64_t integer(c_int64_t).
  Buffer lengths (size_t) accept default integers too: see the generic interfaces below.
- Arrays: a numeric array that the C function takes as a flat buffer may have rank 1 or 2,
  each array of a call its own: xy(2, n_nodes), triangles(3, n_triangles), u(2, n_nodes),
  stresses(3, n_triangles). The library reads and writes the array's elements in array
  element order, in place (a contiguous array is not copied).
- Character buffers are character(kind=c_char) arrays or strings; a path is NUL-terminated:
  append c_null_char.

Fortran 2008
This file compiles under -std=f2008 (and -std=f2018). It holds three modules, in this order:
- tfem_c, the C API as it is: every function as a bind(C) interface under its C name with its
  whole C documentation, every argument required (a nullable pointer too: pass a variable),
  arrays assumed-size (any rank, or an element as the start of a buffer), size_t lengths
  integer(c_size_t); the enums as named constants, the structs as bind(C) types. It is the
  module as it was before the generic interfaces.
- tfem_specifics, the module procedures behind the generic interfaces of tfem: not for direct
  use (their names and number may change). They are apart from tfem because a procedure has at
  most one explicit interface in a scoping unit: here a C name is tfem_c's bind(C) interface,
  called directly, or one that takes the nullable pointers as type(c_ptr).
- tfem, the module to use: tfem_c's constants, types and the interfaces of the functions that
  need nothing converted, and a generic interface for every other function.

Generic interfaces
A function with a size_t length, a nullable pointer or a nullable model handle is a generic
interface named like the C function. Its specifics take every combination of
- lengths as integer(c_size_t) (the kind of integer(c_int64_t) on 64-bit platforms) or as
  integer(tfem_length_kind) (c_int where size_t is wider, so default integers and literals;
  c_int64_t where size_t is c_int), all the lengths of one call of one kind; a negative
  length is passed as 0, so that the call fails with TFEM_STATUS_BUFFER_TOO_SMALL;
- each numeric array with rank 1 or 2: generic resolution matches ranks, so a rank-1 dummy
  alone would refuse the rank-2 arrays that sequence association passes to the assumed-size
  dummy of a bind(C) interface. The specific takes a rank-2 array as an assumed-size x(1, *)
  and passes it on to the C function's x(*) by sequence association, without a copy;
- character buffers as character(kind=c_char) arrays or as character(len=*) strings;
- a nullable model handle given or omitted (c_null_ptr is passed).
The specifics are named after the C function with suffixes: _opt (nullable pointers), _no_<arg>
(handle omitted), _str (strings), _i (tfem_length_kind lengths), _r<ranks> (a digit per numeric
array, when one has rank 2). Ranks above 2, and an array element as the start of a buffer
(u(1)), match no specific (a scalar dummy cannot be passed on as the start of an array): use
tfem_c's interface for them.
A function without a nullable pointer also keeps tfem_c's bind(C) interface among its specifics
(every argument, integer(c_size_t) lengths, rank-1 arrays), so that such calls, procedure actual
arguments and c_funloc reach it under the C name as before.
A function with a nullable pointer cannot. Fortran 2008 forbids OPTIONAL dummies in bind(C)
interfaces (Fortran 2018 allows them, from TS 29113), so the omitted arguments need a module
procedure; one whose OPTIONAL dummies have the types of the bind(C) interface's arguments is
indistinguishable from it (an OPTIONAL dummy tells no specifics apart), and specifics that leave
arguments out cannot tell two of one type apart when either is omitted by keyword
(tfem_get_sizes(m, n_triangles=n) and tfem_get_sizes(m, n_nodes=n)). Keeping the bind(C)
interface under the C name would thus lose omitted arguments that compiled before; tfem keeps
them, and its generic for such a function holds module procedures only. They pass an absent
argument as a null type(c_ptr) and a given one as its address (a zero-length array as that of a
private one-element array, so that the C function sees a buffer of length 0, not NULL). A
nullable array of rank 2 is a required argument of its specifics, the rank of an OPTIONAL dummy
telling none apart: given, it may have rank 1 or 2; omitted, it is absent. What these names lose
in tfem is the bind(C) procedure itself: for c_funloc or a procedure actual argument, take it
from tfem_c under another local name (use tfem_c, only: c_tfem_solve => tfem_solve). These
functions are:";

/// How module tfem offers a function.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Offer {
    /// tfem_c's bind(C) interface: nothing to convert or to omit.
    Interface,
    /// A generic interface whose specifics are tfem_c's bind(C) interface
    /// and module procedures (size_t lengths, a nullable model handle).
    Generic,
    /// A generic interface of module procedures only (a nullable pointer:
    /// see [`FORTRAN_NOTES`]).
    Procedures,
}

/// A specific of a generic interface: which conversions it makes.
#[derive(Debug, Clone, PartialEq, Default)]
struct Variant {
    /// Without the nullable model handle (passes c_null_ptr).
    omit_handle: bool,
    /// Character buffers as character(len=*) strings.
    string: bool,
    /// Lengths as integer(tfem_length_kind).
    alt_length: bool,
    /// The rank (1 or 2) of each numeric array, in the order of
    /// [`Shape::arrays`].
    ranks: Vec<u8>,
}

impl Variant {
    /// The call tfem_c's bind(C) interface takes as it is.
    fn is_interface(&self) -> bool {
        !self.omit_handle && !self.string && !self.alt_length && self.ranks.iter().all(|&r| r == 1)
    }
}

/// Everything the generator derives about one function.
struct Shape {
    passes: Vec<Pass>,
    /// Per parameter: a nullable pointer other than the model handle
    /// (OPTIONAL in the specifics).
    optional: Vec<bool>,
    /// The nullable model handle, if any.
    nullable_handle: Option<usize>,
    /// The size_t parameters.
    lengths: Vec<usize>,
    /// The character arrays.
    chars: Vec<usize>,
    /// The numeric arrays.
    arrays: Vec<usize>,
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
    let s = Shape {
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
        arrays: (0..passes.len())
            .filter(|&k| matches!(&passes[k], Pass::Array { base, .. } if base != "char"))
            .collect(),
        passes,
    };
    assert!(
        s.offer() != Offer::Procedures || s.nullable_handle.is_none(),
        "{}: a nullable handle beside nullable pointers; the generator supports either",
        p.name
    );
    assert!(
        s.chars.iter().all(|&k| !s.optional[k]),
        "{}: a nullable character buffer; the generator has no string form for it",
        p.name
    );
    s
}

/// Every vector of `n` ranks, each 1 or 2, the all-1 first.
fn rank_choices(n: usize) -> Vec<Vec<u8>> {
    (0..1usize << n)
        .map(|bits| (0..n).map(|k| 1 + ((bits >> k) & 1) as u8).collect())
        .collect()
}

impl Shape {
    fn offer(&self) -> Offer {
        if self.optional.contains(&true) {
            Offer::Procedures
        } else if !self.lengths.is_empty() || self.nullable_handle.is_some() {
            Offer::Generic
        } else {
            Offer::Interface
        }
    }

    /// The module-procedure specifics of the generic (with tfem_c's
    /// bind(C) interface, for [`Offer::Generic`]); empty for
    /// [`Offer::Interface`].
    fn variants(&self) -> Vec<Variant> {
        let offer = self.offer();
        if offer == Offer::Interface {
            return Vec::new();
        }
        let choices = |on: bool| if on { vec![false, true] } else { vec![false] };
        let mut out = Vec::new();
        for omit_handle in choices(self.nullable_handle.is_some()) {
            for string in choices(!self.chars.is_empty()) {
                for alt_length in choices(!self.lengths.is_empty()) {
                    for ranks in rank_choices(self.arrays.len()) {
                        let v = Variant {
                            omit_handle,
                            string,
                            alt_length,
                            ranks,
                        };
                        if offer == Offer::Procedures || !v.is_interface() {
                            out.push(v);
                        }
                    }
                }
            }
        }
        out
    }

    /// The rank variant `v` gives parameter `k` (a numeric array).
    fn rank(&self, v: &Variant, k: usize) -> Option<u8> {
        let at = self.arrays.iter().position(|&a| a == k)?;
        Some(v.ranks[at])
    }
}

fn specific_name(p: &Proto, s: &Shape, v: &Variant) -> String {
    let mut name = p.name.clone();
    if s.offer() == Offer::Procedures {
        name.push_str("_opt");
    }
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
    if v.ranks.contains(&2) {
        name.push_str("_r");
        for r in &v.ranks {
            name.push(char::from(b'0' + r));
        }
    }
    assert!(name.len() <= 63, "Fortran name {name} is longer than 63");
    name
}

/// The bind(C) interface of an [`Offer::Procedures`] function in
/// tfem_specifics: its nullable pointers as type(c_ptr), value.
fn by_address_name(p: &Proto) -> String {
    format!("{}_by_address", p.name)
}

/// The length of the buffer of nullable array `k`: the size_t parameter
/// after it (the header's buffer convention), or the count its doc gives
/// as "`name` (`count` values".
fn buffer_length(p: &Proto, k: usize) -> usize {
    if let Some(at) = (k + 1..p.params.len()).find(|&j| p.params[j].0 == "size_t") {
        return at;
    }
    let name = &p.params[k].1;
    p.params
        .iter()
        .position(|(_, n)| p.doc.contains(&format!("`{name}` (`{n}` values")))
        .unwrap_or_else(|| panic!("{}: no length for the nullable array `{name}`", p.name))
}

/// The kind tag of a numeric array's base type, as in the names of the
/// address helpers (tfem_address_c_double, …).
fn kind_tag(base: &str) -> &'static str {
    let kind = kind_of(base);
    let inner = &kind[kind.find('(').unwrap() + 1..kind.len() - 1];
    match inner {
        "c_double" => "c_double",
        "c_int" => "c_int",
        "c_int64_t" => "c_int64_t",
        "c_int8_t" => "c_int8_t",
        t => panic!("no address helper for kind {t}"),
    }
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

/// The Fortran-specific sentences of a generic interface of module tfem.
fn fortran_note(p: &Proto, s: &Shape) -> String {
    let names =
        |ks: &[usize]| -> Vec<String> { ks.iter().map(|&k| p.params[k].1.clone()).collect() };
    let mut parts = vec![format!("{} (documented in module tfem_c).", p.name)];
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
    match s.arrays.len() {
        0 => {}
        1 => parts.push(format!("{} may have rank 1 or 2.", list(&names(&s.arrays)))),
        _ => parts.push(format!(
            "{} may each have rank 1 or 2.",
            list(&names(&s.arrays))
        )),
    }
    if !s.chars.is_empty() {
        parts.push(format!(
            "{} may also be a character string.",
            list(&names(&s.chars))
        ));
    }
    if s.offer() == Offer::Procedures {
        parts.push(
            "The name is no bind(C) procedure here (for c_funloc: module tfem_c).".to_string(),
        );
    }
    format!("Fortran: {}", parts.join(" "))
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
        "const char *"
        | "struct tfem_model *"
        | "struct tfem_contact *"
        | "struct tfem_solid_model *"
        | "struct tfem_solid_contact *" => ("function", " result(res)", "type(c_ptr) :: res"),
        t => panic!("no Fortran mapping for return type {t}"),
    }
}

/// A bind(C) interface body of `p` named `name`, its parameters declared
/// by `decl` (parameter index -> declaration).
fn bind_c_body(f: &mut String, p: &Proto, name: &str, decl: impl Fn(usize) -> String) {
    let (kind, result, result_decl) = result_of(p);
    let args: Vec<String> = p.params.iter().map(|(_, n)| n.clone()).collect();
    writeln!(
        f,
        "    {kind} {name}({}) &\n        bind(C, name=\"{}\"){result}",
        arglist(&args, name.len() + 10),
        p.name
    )
    .unwrap();
    f.push_str("      import\n");
    for k in 0..p.params.len() {
        writeln!(f, "      {}", decl(k)).unwrap();
    }
    if !result_decl.is_empty() {
        writeln!(f, "      {result_decl}").unwrap();
    }
    writeln!(f, "    end {kind} {name}").unwrap();
}

/// tfem_c's bind(C) interface of `p`, with its whole C documentation:
/// every argument required, as the C prototype has it.
fn interface_body(f: &mut String, p: &Proto, s: &Shape) {
    comment(f, "    ", &p.doc);
    bind_c_body(f, p, &p.name, |k| {
        fortran_param(&s.passes[k], &p.params[k].1)
    });
}

/// The bind(C) interface of an [`Offer::Procedures`] function that
/// tfem_specifics calls: nullable pointers as type(c_ptr), value.
fn by_address_body(f: &mut String, p: &Proto, s: &Shape) {
    bind_c_body(f, p, &by_address_name(p), |k| {
        let n = &p.params[k].1;
        if s.optional[k] {
            format!("type(c_ptr), value :: {n}")
        } else {
            fortran_param(&s.passes[k], n)
        }
    });
}

/// The declaration of parameter `k` of `p` as a dummy argument of the
/// specific `v`.
fn specific_dummy(p: &Proto, s: &Shape, v: &Variant, k: usize) -> String {
    let n = &p.params[k].1;
    if s.lengths.contains(&k) {
        let kind = if v.alt_length {
            "tfem_length_kind"
        } else {
            "c_size_t"
        };
        return format!("integer({kind}), intent(in) :: {n}");
    }
    match &s.passes[k] {
        Pass::Array { base, konst } => {
            let intent = if *konst { "in" } else { "inout" };
            if base == "char" {
                return if v.string {
                    format!("character(kind=c_char, len=*), intent({intent}) :: {n}")
                } else {
                    format!("character(kind=c_char), intent({intent}) :: {n}(*)")
                };
            }
            let rank = s.rank(v, k).unwrap();
            let dims = if rank == 2 { "(1, *)" } else { "(*)" };
            // A nullable array is OPTIONAL at rank 1 and required at rank
            // 2; either way its address is taken.
            let attrs = match (s.optional[k], rank) {
                (true, 1) => ", optional, target",
                (true, _) => ", target",
                (false, _) => "",
            };
            format!("{}, intent({intent}){attrs} :: {n}{dims}", kind_of(base))
        }
        Pass::Struct { name, konst } if s.optional[k] => format!(
            "type({name}), intent({}), optional, target :: {n}",
            if *konst { "in" } else { "inout" }
        ),
        Pass::Out { base } if s.optional[k] => {
            format!("{}, intent(inout), optional, target :: {n}", kind_of(base))
        }
        pass => fortran_param(pass, n),
    }
}

/// The module procedure of tfem_specifics for variant `v` of `p`.
fn specific(f: &mut String, p: &Proto, s: &Shape, v: &Variant) {
    let name = specific_name(p, s, v);
    let procedures = s.offer() == Offer::Procedures;
    let (kind, result, result_decl) = result_of(p);
    let (mut args, mut decls, mut locals, mut actuals, mut body) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (k, (_, n)) in p.params.iter().enumerate() {
        if v.omit_handle && Some(k) == s.nullable_handle {
            actuals.push("c_null_ptr".to_string());
            continue;
        }
        args.push(n.clone());
        decls.push(specific_dummy(p, s, v, k));
        if v.alt_length && s.lengths.contains(&k) {
            actuals.push(format!("tfem_to_size_t({n})"));
        } else if procedures && s.optional[k] {
            let address = format!("{n}_address");
            assert!(
                !p.params.iter().any(|(_, m)| *m == address),
                "{}: a parameter is named {address}",
                p.name
            );
            match &s.passes[k] {
                Pass::Array { base, .. } => {
                    let at = buffer_length(p, k);
                    let len = &p.params[at].1;
                    let nonempty = if s.lengths.contains(&at) && !v.alt_length {
                        format!("{len} /= 0")
                    } else {
                        format!("{len} > 0")
                    };
                    body.push(format!(
                        "{address} = tfem_address_{}({n}, {nonempty})",
                        kind_tag(base)
                    ));
                }
                _ => {
                    body.push(format!("{address} = c_null_ptr"));
                    body.push(format!("if (present({n})) {address} = c_loc({n})"));
                }
            }
            locals.push(format!("type(c_ptr) :: {address}"));
            actuals.push(address);
        } else {
            actuals.push(n.clone());
        }
    }
    let target = if procedures {
        by_address_name(p)
    } else {
        p.name.clone()
    };
    writeln!(
        f,
        "  {kind} {name}({}){result}",
        arglist(&args, name.len() + kind.len() + 4 + result.len())
    )
    .unwrap();
    for d in &decls {
        writeln!(f, "    {d}").unwrap();
    }
    if !result_decl.is_empty() {
        writeln!(f, "    {result_decl}").unwrap();
    }
    for l in &locals {
        writeln!(f, "    {l}").unwrap();
    }
    for b in &body {
        writeln!(f, "    {b}").unwrap();
    }
    let lhs = match kind {
        "subroutine" => "call ".to_string(),
        _ => format!("{} = ", &result[" result(".len()..result.len() - 1]),
    };
    writeln!(
        f,
        "    {lhs}{target}({})",
        arglist(&actuals, 4 + lhs.len() + target.len() + 1)
    )
    .unwrap();
    writeln!(f, "  end {kind} {name}\n").unwrap();
}

/// `keyword :: a, b, c` statements of at most 100 columns, at `indent`.
fn name_list(f: &mut String, indent: &str, keyword: &str, names: &[String]) {
    let lead = indent.len() + keyword.len() + 4;
    let mut line: Vec<&str> = Vec::new();
    let mut width = lead;
    for n in names {
        if !line.is_empty() && width + 2 + n.len() > 100 {
            writeln!(f, "{indent}{keyword} :: {}", line.join(", ")).unwrap();
            line.clear();
            width = lead;
        }
        width += n.len() + if line.is_empty() { 0 } else { 2 };
        line.push(n);
    }
    if !line.is_empty() {
        writeln!(f, "{indent}{keyword} :: {}", line.join(", ")).unwrap();
    }
}

/// `use module, only: a, b, c` with continuation lines before column 100.
fn use_only(f: &mut String, module: &str, names: &[String]) {
    let head = format!("  use {module}, only: ");
    writeln!(f, "{head}{}", arglist(names, head.len())).unwrap();
}

fn generate(header: &str) -> String {
    let protos = prototypes(header);
    let shapes: Vec<Shape> = protos.iter().map(shape).collect();
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
    wrap(
        &mut f,
        "",
        &by_offer(&protos, &shapes, Offer::Procedures).join(", "),
        "!  ",
        "!  ",
    );
    f.push('\n');

    let (constants, types) = module_tfem_c(&mut f, header, &protos, &shapes);
    module_tfem_specifics(&mut f, &protos, &shapes, &types);
    module_tfem(&mut f, &protos, &shapes, constants, types);
    f
}

/// The names of the functions `protos` that module tfem offers `offer`.
fn by_offer(protos: &[Proto], shapes: &[Shape], offer: Offer) -> Vec<String> {
    protos
        .iter()
        .zip(shapes)
        .filter(|(_, s)| s.offer() == offer)
        .map(|(p, _)| p.name.clone())
        .collect()
}

/// Module tfem_c: the constants, the types and every bind(C) interface;
/// returns the names of the constants and of the types.
fn module_tfem_c(
    f: &mut String,
    header: &str,
    protos: &[Proto],
    shapes: &[Shape],
) -> (Vec<String>, Vec<String>) {
    f.push_str(
        "! The C API as it is (see \"Fortran 2008\" above).\n\
         module tfem_c\n  use, intrinsic :: iso_c_binding\n  implicit none\n\n",
    );
    let mut constants = Vec::new();
    for e in enums(header) {
        wrap(f, "  ", &format!("enum {}: {}", e.name, e.doc), "!", "!");
        for (k, v, doc) in e.consts {
            comment(f, "  ", &doc);
            writeln!(f, "  integer(c_int), parameter :: {k} = {v}").unwrap();
            constants.push(k);
        }
        f.push('\n');
    }
    let mut types = Vec::new();
    for st in structs(header) {
        comment(f, "  ", &st.doc);
        writeln!(f, "  type, bind(C) :: {}", st.name).unwrap();
        for (ty, field, doc) in st.fields {
            comment(f, "    ", &doc);
            writeln!(f, "    {} :: {field}", fortran_field(&ty)).unwrap();
        }
        writeln!(f, "  end type {}\n", st.name).unwrap();
        types.push(st.name);
    }
    f.push_str("  interface\n");
    for (k, (p, s)) in protos.iter().zip(shapes).enumerate() {
        if k > 0 {
            f.push('\n');
        }
        if let Some(head) = &p.section {
            writeln!(f, "    ! {}", "=".repeat(94)).unwrap();
            wrap(f, "    ", head, "!", "!");
            writeln!(f, "    ! {}\n", "=".repeat(94)).unwrap();
        }
        interface_body(f, p, s);
    }
    f.push_str("  end interface\nend module tfem_c\n\n");
    (constants, types)
}

/// Module tfem_specifics: the module procedures behind tfem's generic
/// interfaces, and the interfaces they call.
fn module_tfem_specifics(f: &mut String, protos: &[Proto], shapes: &[Shape], types: &[String]) {
    let specific_names = specific_names(protos, shapes);
    let mut address_kinds = BTreeSet::new();
    for s in shapes {
        for &k in &s.arrays {
            if let (true, Pass::Array { base, .. }) = (s.optional[k], &s.passes[k]) {
                address_kinds.insert((kind_tag(base), kind_of(base)));
            }
        }
    }
    f.push_str(
        "! The module procedures behind the generic interfaces of module tfem (see \"Generic\n\
         ! interfaces\" above); not for direct use.\n\
         module tfem_specifics\n  use, intrinsic :: iso_c_binding\n",
    );
    let mut imported = types.to_vec();
    imported.extend(by_offer(protos, shapes, Offer::Generic));
    use_only(f, "tfem_c", &imported);
    f.push_str("  implicit none\n  private\n  public :: tfem_length_kind\n");
    name_list(f, "  ", "public", &specific_names);
    f.push('\n');
    comment(
        f,
        "  ",
        "The kind of the lengths the generic interfaces accept besides integer(c_size_t): \
         c_int (the default integer) where size_t is wider, else c_int64_t.",
    );
    f.push_str(
        "  integer, parameter :: tfem_length_kind = merge(c_int, c_int64_t, c_size_t /= c_int)\n\n",
    );
    for (tag, kind) in &address_kinds {
        writeln!(
            f,
            "  ! The buffer passed for a given zero-length {tag} array: never read or written."
        )
        .unwrap();
        writeln!(f, "  {kind}, target, save :: tfem_empty_{tag}(1)").unwrap();
    }
    f.push_str("\n  interface\n");
    let mut first = true;
    for (p, s) in protos.iter().zip(shapes) {
        if s.offer() == Offer::Procedures {
            if !first {
                f.push('\n');
            }
            first = false;
            by_address_body(f, p, s);
        }
    }
    f.push_str("  end interface\n\ncontains\n\n");
    f.push_str(
        "\x20 !> A length of kind tfem_length_kind as integer(c_size_t). A negative length becomes 0, so\n\
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
    for (tag, kind) in &address_kinds {
        writeln!(
            f,
            "  !> The address to pass for the nullable {tag} array x: NULL when absent, that of\n\
             \x20 !! tfem_empty_{tag} when its buffer is empty (c_loc needs a nonzero size).\n\
             \x20 function tfem_address_{tag}(x, nonempty) result(address)\n\
             \x20   {kind}, intent(in), optional, target :: x(*)\n\
             \x20   logical, intent(in) :: nonempty\n\
             \x20   type(c_ptr) :: address\n\
             \x20   address = c_null_ptr\n\
             \x20   if (.not. present(x)) return\n\
             \x20   address = c_loc(tfem_empty_{tag})\n\
             \x20   if (nonempty) address = c_loc(x)\n\
             \x20 end function tfem_address_{tag}\n"
        )
        .unwrap();
    }
    for (p, s) in protos.iter().zip(shapes) {
        for v in s.variants() {
            specific(f, p, s, &v);
        }
    }
    f.push_str("end module tfem_specifics\n\n");
}

/// The names of every module procedure of tfem_specifics behind a generic.
fn specific_names(protos: &[Proto], shapes: &[Shape]) -> Vec<String> {
    protos
        .iter()
        .zip(shapes)
        .flat_map(|(p, s)| s.variants().into_iter().map(|v| specific_name(p, s, &v)))
        .collect()
}

/// Module tfem: tfem_c's constants, types and plain interfaces, the
/// generic interfaces and the string helpers.
fn module_tfem(
    f: &mut String,
    protos: &[Proto],
    shapes: &[Shape],
    constants: Vec<String>,
    types: Vec<String>,
) {
    let specific_names = specific_names(protos, shapes);
    f.push_str(
        "! The module to use: tfem_c's constants and types, its interfaces where nothing is\n\
         ! converted, and the generic interfaces.\n\
         module tfem\n  use, intrinsic :: iso_c_binding\n",
    );
    let mut imported = constants;
    imported.extend(types);
    imported.extend(by_offer(protos, shapes, Offer::Interface));
    imported.extend(by_offer(protos, shapes, Offer::Generic));
    use_only(f, "tfem_c", &imported);
    f.push_str("  use tfem_specifics\n  implicit none\n  private :: c_strlen\n");
    name_list(f, "  ", "private", &specific_names);
    f.push('\n');
    for (p, s) in protos.iter().zip(shapes) {
        if s.offer() == Offer::Interface {
            continue;
        }
        comment(f, "  ", &fortran_note(p, s));
        writeln!(f, "  interface {}", p.name).unwrap();
        if s.offer() == Offer::Generic {
            writeln!(f, "    procedure {}", p.name).unwrap();
        }
        for v in s.variants() {
            writeln!(f, "    procedure {}", specific_name(p, s, &v)).unwrap();
        }
        writeln!(f, "  end interface {}\n", p.name).unwrap();
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
         \x20 end function c_strlen\n\n",
    );
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
         \x20 !> The message of the last failed call on the 3D model (from tfem_solid_create), as a\n\
         \x20 !! Fortran string: a 3D model keeps its own messages, which tfem_error_message, reading a\n\
         \x20 !! 2D model's, does not see. The buffer is sized by tfem_solid_last_error_length, so that\n\
         \x20 !! a message of any length comes whole.\n\
         \x20 function tfem_solid_error_message(model) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: model\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   allocate(buf(tfem_solid_last_error_length(model)))\n\
         \x20   buf(1) = c_null_char\n\
         \x20   status = tfem_solid_last_error(model, buf, size(buf, kind=c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   if (status == TFEM_STATUS_NULL_POINTER) n = 0\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_solid_error_message\n\n\
         \x20 !> The message of the last failed call on the 3D contact context (from\n\
         \x20 !! tfem_solid_contact_create), as a Fortran string: a context keeps its own messages,\n\
         \x20 !! which tfem_error_message and tfem_contact_error_message do not see. The buffer is\n\
         \x20 !! sized by tfem_solid_contact_last_error_length, so that a message of any length comes\n\
         \x20 !! whole.\n\
         \x20 function tfem_solid_contact_error_message(context) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: context\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   allocate(buf(tfem_solid_contact_last_error_length(context)))\n\
         \x20   buf(1) = c_null_char\n\
         \x20   status = tfem_solid_contact_last_error(context, buf, size(buf, kind=c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   if (status == TFEM_STATUS_NULL_POINTER) n = 0\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_solid_contact_error_message\n\n\
         \x20 !> Warning number index (0-based) of the 3D model, as a Fortran string. The buffer is\n\
         \x20 !! sized by tfem_solid_get_warning_size, so that a warning of any length comes whole.\n\
         \x20 function tfem_solid_warning_message(model, index) result(msg)\n\
         \x20   type(c_ptr), intent(in) :: model\n\
         \x20   integer, intent(in) :: index\n\
         \x20   character(len=:), allocatable :: msg\n\
         \x20   character(kind=c_char), allocatable :: buf(:)\n\
         \x20   integer(c_size_t) :: bytes\n\
         \x20   integer(c_int) :: status\n\
         \x20   integer :: i, n\n\
         \x20   bytes = 1\n\
         \x20   if (tfem_solid_get_warning_size(model, int(index, c_int), bytes) /= TFEM_STATUS_OK) bytes = 1\n\
         \x20   allocate(buf(bytes))\n\
         \x20   buf(1) = c_null_char\n\
         \x20   status = tfem_solid_get_warning(model, int(index, c_int), buf, size(buf, kind=c_size_t))\n\
         \x20   n = c_strlen(buf)\n\
         \x20   if (status /= TFEM_STATUS_OK .and. status /= TFEM_STATUS_BUFFER_TOO_SMALL) n = 0\n\
         \x20   allocate(character(len=n) :: msg)\n\
         \x20   do i = 1, n\n\
         \x20     msg(i:i) = buf(i)\n\
         \x20   end do\n\
         \x20 end function tfem_solid_warning_message\n\n\
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

/// Generic name -> its specific procedures (tfem_c's bind(C) interface of
/// the same name included), read from the `interface <name>` blocks.
fn generics(module: &str) -> BTreeMap<String, Vec<String>> {
    let mut out: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut current: Option<String> = None;
    for l in module.lines().map(str::trim) {
        if let Some(name) = l.strip_prefix("interface ") {
            current = Some(name.trim().to_string());
            out.entry(name.trim().to_string()).or_default();
        } else if l.starts_with("end interface") {
            current = None;
        } else if let (Some(g), Some(p)) = (&current, l.strip_prefix("procedure ")) {
            out.get_mut(g).unwrap().push(p.trim().to_string());
        }
    }
    out
}

/// The declaration of dummy `n` among `decls`.
fn decl_of<'a>(decls: &'a [String], n: &str) -> Option<&'a String> {
    decls.iter().find(|l| {
        let l = l.trim_end();
        l.ends_with(&format!(":: {n}"))
            || l.ends_with(&format!(":: {n}(*)"))
            || l.ends_with(&format!(":: {n}(1, *)"))
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
    let file = module();
    let module = module_text(&file, "tfem_c");
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
                "struct tfem_model"
                | "struct tfem_contact"
                | "struct tfem_solid_model"
                | "struct tfem_solid_contact" => decl.contains("c_ptr"),
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
        section: None,
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

/// The text of module `name` of the committed file.
fn module_text<'a>(module: &'a str, name: &str) -> &'a str {
    let start = module
        .find(&format!("\nmodule {name}\n"))
        .unwrap_or_else(|| panic!("no module {name}"));
    let end = module[start..]
        .find(&format!("\nend module {name}\n"))
        .unwrap()
        + start;
    &module[start..end]
}

#[test]
fn documented_nullable_parameters_are_optional_and_lengths_generic() {
    // Read back from the committed module: in module tfem, every pointer
    // parameter the doc says may be NULL is OPTIONAL in the specifics of
    // its generic (or, an array, given at rank 2), and no other is; a
    // nullable handle has a specific without it; every size_t length takes
    // integer(c_size_t) and tfem_length_kind. tfem_c's bind(C) interfaces
    // have no OPTIONAL (Fortran 2008), so a generic with an OPTIONAL
    // dummy cannot hold one.
    let module = module();
    let procs = procedures(&module);
    let generics = generics(module_text(&module, "tfem"));
    assert!(!module_text(&module, "tfem_c").contains("optional"));
    let mut optional = 0;
    for p in prototypes(&header()) {
        let null = nullable(&p);
        let c_names: Vec<String> = p.params.iter().map(|(_, n)| n.clone()).collect();
        let specifics: Vec<&FProc> = generics
            .get(&p.name)
            .map(|g| g.iter().map(|s| &procs[s]).collect())
            .unwrap_or_default();
        let decls = |s: &FProc, n: &str| decl_of(&s.decls, n).cloned();
        let with_optional = null
            .iter()
            .any(|n| !is_handle(&p.params.iter().find(|(_, m)| m == n).unwrap().0));
        assert_eq!(
            generics.get(&p.name).is_some_and(|g| g.contains(&p.name)),
            !with_optional && !specifics.is_empty(),
            "{}: tfem_c's bind(C) interface is a specific iff no argument is OPTIONAL",
            p.name
        );
        for (ty, n) in &p.params {
            if is_handle(ty) {
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
                for s in &specifics {
                    let Some(decl) = decls(s, n) else {
                        continue;
                    };
                    let given_at_rank_2 = decl.ends_with("(1, *)");
                    assert_eq!(
                        decl.contains(", optional"),
                        null.contains(n) && !given_at_rank_2,
                        "{}: `{decl}` is OPTIONAL iff the doc says `{n}` may be NULL",
                        p.name
                    );
                }
                if null.contains(n) {
                    assert!(
                        specifics
                            .iter()
                            .any(|s| decls(s, n).is_some_and(|d| d.contains(", optional"))),
                        "{}: `{n}` is OPTIONAL in no specific",
                        p.name
                    );
                    optional += 1;
                }
            }
        }
        let lengths: Vec<&String> = p
            .params
            .iter()
            .filter(|(ty, _)| ty == "size_t")
            .map(|(_, n)| n)
            .collect();
        for kind in ["tfem_length_kind", "c_size_t"] {
            if !lengths.is_empty() {
                let converting = specifics.iter().any(|s| {
                    s.args == c_names
                        && lengths
                            .iter()
                            .all(|n| decls(s, n).is_some_and(|d| d.contains(kind)))
                });
                assert!(
                    converting,
                    "{}: no specific takes the lengths as integer({kind})",
                    p.name
                );
            }
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
    build_fortran_linked(sources, name, flags, true)
}

/// [`build_fortran_with`], linked with libtfem or not (a probe library
/// among the sources defines the functions instead).
fn build_fortran_linked(sources: &[&Path], name: &str, flags: &[&str], libtfem: bool) -> PathBuf {
    let lib = lib_dir();
    let dir = lib.join("fortran").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    let exe = dir.join(name);
    let mut command = Command::new("gfortran");
    // The module is Fortran 2008 (its head comment): so are the programs
    // built against it here.
    command
        .args([
            "-std=f2008",
            "-Wall",
            "-Werror",
            "-Wno-unused-dummy-argument",
        ])
        .args(flags)
        .arg("-J")
        .arg(&dir)
        .arg(root().join("include/tfem.f90"))
        .args(sources)
        .arg("-o")
        .arg(&exe);
    if libtfem {
        ensure_shared_library();
        command
            .arg(format!("-L{}", lib.display()))
            .arg("-ltfem")
            .arg(format!("-Wl,-rpath,{}", lib.display()));
    }
    let out = command
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

// ---------------------------------------------------------------------------
// Calls checked against a probe: a C library with every function of tfem.h
// as a stub that records the pointers it was given.

/// Compiles the probe library of `name`: every function of tfem.h (its
/// prototype checked against the header) records its arguments, and
/// `tfem_probe_arg(k)` returns the k-th pointer argument of the last call
/// (NULL for an argument that is no pointer).
fn probe_library(name: &str) -> PathBuf {
    let mut c = String::from(
        "#include <stddef.h>\n#include \"tfem.h\"\n\n\
         static const void *args[32];\n\n\
         const void *tfem_probe_arg(int k) { return args[k]; }\n\n\
         static void probe_clear(void) {\n  for (int k = 0; k < 32; k++) args[k] = NULL;\n}\n",
    );
    for p in prototypes(&header()) {
        assert!(
            p.params.len() <= 32,
            "{}: more arguments than the probe keeps",
            p.name
        );
        let params: Vec<String> = p.params.iter().map(|(t, n)| format!("{t} {n}")).collect();
        let params = if params.is_empty() {
            "void".to_string()
        } else {
            params.join(", ")
        };
        writeln!(c, "\n{} {}({params}) {{\n  probe_clear();", p.ret, p.name).unwrap();
        for (k, (t, n)) in p.params.iter().enumerate() {
            if t.ends_with('*') {
                writeln!(c, "  args[{k}] = (const void *){n};").unwrap();
            } else {
                writeln!(c, "  (void){n};").unwrap();
            }
        }
        match p.ret.as_str() {
            "void" => {}
            "enum tfem_status" => c.push_str("  return TFEM_STATUS_OK;\n"),
            "size_t" => c.push_str("  return 0;\n"),
            "const char *" => c.push_str("  return \"probe\";\n"),
            _ => c.push_str("  return NULL;\n"),
        }
        c.push_str("}\n");
    }
    let source = generated_source(name, "probe.c", &c);
    let object = source.with_extension("o");
    let out = cc::Build::new()
        .cargo_metadata(false)
        .target(env!("TFEM_BUILD_TARGET"))
        .host(env!("TFEM_BUILD_HOST"))
        .opt_level(0)
        .get_compiler()
        .to_command()
        .arg("-c")
        .arg(format!("-I{}", root().join("include").display()))
        .arg(&source)
        .arg("-o")
        .arg(&object)
        .output()
        .expect("run the C compiler");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    object
}

/// How a generated call passes its arguments.
#[derive(Clone, Copy)]
struct Way<'a> {
    /// The kind suffix of the length literals (`_c_size_t`, or "" for
    /// default integers).
    kind: &'a str,
    /// Arguments by keyword.
    keywords: bool,
    /// Every nullable argument (handle included) omitted.
    omit_nullables: bool,
    /// This nullable argument alone omitted.
    omit: Option<usize>,
    /// The rank of every numeric array.
    rank: u8,
    /// This nullable array given with zero length (its buffer length 0).
    empty: Option<usize>,
}

/// A generated call of `p` and what the probe must have recorded: per
/// pointer argument, `Some(variable)` for the address of that variable,
/// `None` for NULL, `Some("")` for a buffer of some address (not NULL).
struct ProbedCall {
    call: String,
    expect: Vec<(usize, Option<String>)>,
}

/// The call of `p` made `way`, declaring its variables in `vars` (all
/// TARGET: the probe compares addresses).
fn probed_call(p: &Proto, way: Way, vars: &mut BTreeMap<String, String>) -> ProbedCall {
    let s = shape(p);
    let null = nullable(p);
    let emptied = way.empty.map(|k| buffer_length(p, k));
    let mut args = Vec::new();
    let mut expect = Vec::new();
    for (k, (ty, n)) in p.params.iter().enumerate() {
        let omitted = (way.omit_nullables && null.contains(n)) || way.omit == Some(k);
        if omitted {
            if ty.ends_with('*') {
                expect.push((k, None));
            }
            continue;
        }
        let length = if emptied == Some(k) { "0" } else { "64" };
        let var: String = match &s.passes[k] {
            Pass::Handle => {
                vars.insert("model".into(), "type(c_ptr) :: model = c_null_ptr".into());
                "model".into()
            }
            Pass::Struct { name, .. } => {
                let v = format!("s{k}_{name}");
                vars.insert(v.clone(), format!("type({name}), target :: {v}"));
                v
            }
            Pass::Value(b) => match b.as_str() {
                "double" => "1.0_c_double".into(),
                "int" => length.into(),
                "int64_t" => "1_c_int64_t".into(),
                "size_t" => format!("{length}{}", way.kind),
                t => panic!("no actual argument for {t}"),
            },
            Pass::Array { base, .. } => {
                let (tag, ty) = match base.as_str() {
                    "double" => ("rd", "real(c_double)"),
                    "int" => ("ia", "integer(c_int)"),
                    "int64_t" => ("la", "integer(c_int64_t)"),
                    "uint8_t" => ("ba", "integer(c_int8_t)"),
                    "char" => ("ca", "character(kind=c_char)"),
                    t => panic!("no actual argument for {t}"),
                };
                let dims = if way.empty == Some(k) {
                    "(0)"
                } else if way.rank == 2 && base != "char" {
                    "(2, 32)"
                } else {
                    "(64)"
                };
                let shape_tag = match dims {
                    "(0)" => "e",
                    "(2, 32)" => "2",
                    _ => "1",
                };
                let v = format!("{tag}{k}_{shape_tag}");
                vars.insert(v.clone(), format!("{ty}, target :: {v}{dims}"));
                v
            }
            Pass::Out { base } => {
                let ty = match base.as_str() {
                    "double" => "real(c_double)",
                    "int" => "integer(c_int)",
                    "int64_t" => "integer(c_int64_t)",
                    "size_t" => "integer(c_size_t)",
                    t => panic!("no actual argument for {t}"),
                };
                let v = format!("o{k}_{}", base.replace('_', ""));
                vars.insert(v.clone(), format!("{ty}, target :: {v}"));
                v
            }
        };
        if ty.ends_with('*') && s.passes[k] != Pass::Handle {
            // A given array whose buffer is empty reaches C as a buffer
            // that is not the array (c_loc needs a nonzero size).
            let empty = s.optional[k]
                && s.arrays.contains(&k)
                && emptied.is_some_and(|e| e == buffer_length(p, k));
            expect.push((k, Some(if empty { String::new() } else { var.clone() })));
        }
        args.push(if way.keywords {
            format!("{n}={var}")
        } else {
            var
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
    ProbedCall {
        call: format!(
            "  {lhs}{}({})",
            p.name,
            arglist(&args, 2 + lhs.len() + p.name.len() + 1)
        ),
        expect,
    }
}

/// A program that makes `calls` (with `vars`) and checks after each what
/// the probe recorded; it prints `N checked, M failed`.
fn probe_program(
    name: &str,
    vars: &BTreeMap<String, String>,
    calls: &[(String, ProbedCall)],
) -> String {
    let mut program = format!(
        "! Generated by tests/fortran.rs ({name}).\n\
         program {name}\n  use, intrinsic :: iso_c_binding\n  use tfem\n  implicit none\n\
         \x20 interface\n\
         \x20   function tfem_probe_arg(k) bind(C, name=\"tfem_probe_arg\") result(p)\n\
         \x20     import\n      integer(c_int), value :: k\n      type(c_ptr) :: p\n\
         \x20   end function tfem_probe_arg\n  end interface\n\
         \x20 integer :: failed = 0, checked = 0\n"
    );
    for d in vars.values() {
        writeln!(program, "  {d}").unwrap();
    }
    for (what, c) in calls {
        writeln!(program, "{}", c.call).unwrap();
        for (k, e) in &c.expect {
            let (test, said) = match e {
                None => (format!(".not. c_associated(tfem_probe_arg({k}))"), "NULL"),
                Some(v) if v.is_empty() => {
                    (format!("c_associated(tfem_probe_arg({k}))"), "a buffer")
                }
                Some(v) => (
                    format!("c_associated(tfem_probe_arg({k}), c_loc({v}))"),
                    "in place",
                ),
            };
            writeln!(
                program,
                "  call expect({test}, &\n      '{what}: argument {k} {said}')"
            )
            .unwrap();
        }
    }
    write!(
        program,
        "  write (*, '(i0, a, i0, a)') checked, ' checked, ', failed, ' failed'\n\
         \x20 if (failed > 0) stop 1\ncontains\n\
         \x20 subroutine expect(ok, what)\n    logical, intent(in) :: ok\n\
         \x20   character(len=*), intent(in) :: what\n    checked = checked + 1\n\
         \x20   if (.not. ok) then\n      failed = failed + 1\n      write (*, '(2a)') 'FAIL ', what\n\
         \x20   end if\n  end subroutine expect\nend program {name}\n"
    )
    .unwrap();
    program
}

/// Builds and runs a probe program; returns the number of checks.
fn run_probe_program(name: &str, program: &str) -> usize {
    let object = probe_library(name);
    let source = generated_source(name, &format!("{name}.f90"), program);
    let exe = build_fortran_linked(&[&source, &object], name, &[], false);
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
    out.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn every_function_takes_rank_2_arrays_in_place() {
    // Every function called with every numeric array of rank 2 (2 × 32):
    // positionally with integer(c_size_t) lengths and every argument, as a
    // legacy client calls the bind(C) interfaces; and by keyword with
    // default-integer lengths and the nullable arguments omitted. The probe
    // sees each array at its own address (no copy) and omitted arguments
    // as NULL.
    let mut vars = BTreeMap::new();
    let mut calls = Vec::new();
    for p in prototypes(&header()) {
        for (what, kind, keywords, omit_nullables) in [
            (
                "c_size_t lengths, every argument",
                "_c_size_t",
                false,
                false,
            ),
            ("default lengths, nullables omitted", "", true, true),
        ] {
            let way = Way {
                kind,
                keywords,
                omit_nullables,
                omit: None,
                rank: 2,
                empty: None,
            };
            calls.push((
                format!("{}, {what}", p.name),
                probed_call(&p, way, &mut vars),
            ));
        }
    }
    let program = probe_program("rank_2_call", &vars, &calls);
    let checked = run_probe_program("rank_2_call", &program);
    assert!(checked > 200, "only {checked} checks");
}

#[test]
fn an_omitted_nullable_argument_reaches_c_as_null_and_an_empty_one_as_a_buffer() {
    // Each nullable pointer argument alone omitted (with either kind of
    // length), then, for an array, given with zero length: the probe sees
    // NULL for the omitted one, a buffer (not NULL) for the empty one, and
    // every other argument at its address.
    let mut vars = BTreeMap::new();
    let mut calls = Vec::new();
    for p in prototypes(&header()) {
        let s = shape(&p);
        for k in (0..p.params.len()).filter(|&k| s.optional[k]) {
            let n = &p.params[k].1;
            let mut way = Way {
                kind: "_c_size_t",
                keywords: true,
                omit_nullables: false,
                omit: Some(k),
                rank: 1,
                empty: None,
            };
            calls.push((
                format!("{}, {n} omitted", p.name),
                probed_call(&p, way, &mut vars),
            ));
            if !s.lengths.is_empty() {
                way.kind = "";
                calls.push((
                    format!("{}, {n} omitted, default lengths", p.name),
                    probed_call(&p, way, &mut vars),
                ));
            }
            if s.arrays.contains(&k) {
                way.omit = None;
                way.empty = Some(k);
                calls.push((
                    format!("{}, {n} empty", p.name),
                    probed_call(&p, way, &mut vars),
                ));
            }
        }
    }
    let program = probe_program("nullable_call", &vars, &calls);
    let checked = run_probe_program("nullable_call", &program);
    assert!(checked > 100, "only {checked} checks");
}

#[test]
fn every_c_name_is_a_bind_c_procedure_of_tfem_c_and_the_generics_keep_theirs() {
    // c_funloc and procedure pointers (as procedure actual arguments) need
    // the bind(C) interface under the name: every function has it in
    // tfem_c; in tfem every function but those with a nullable pointer
    // (FORTRAN_NOTES) keeps it under its C name.
    let protos = prototypes(&header());
    let mut from_c = String::new();
    let mut from_tfem = String::new();
    let mut kept = 0;
    for (k, p) in protos.iter().enumerate() {
        let both = shape(p).offer() != Offer::Procedures;
        for (text, module, on) in [
            (&mut from_c, "tfem_c", true),
            (&mut from_tfem, "tfem", both),
        ] {
            if on {
                writeln!(
                    text,
                    "  subroutine {module}_{k}()\n    use {module}, only: {0}\n\
                     \x20   procedure({0}), pointer :: f\n    type(c_funptr) :: address\n\
                     \x20   f => {0}\n    address = c_funloc({0})\n\
                     \x20   if (.not. (associated(f) .and. c_associated(address))) stop 1\n\
                     \x20 end subroutine {module}_{k}",
                    p.name
                )
                .unwrap();
            }
        }
        kept += usize::from(both);
    }
    assert!(
        kept > 60 && kept < protos.len(),
        "{kept} of {}",
        protos.len()
    );
    let program = format!(
        "! Generated by tests/fortran.rs: the bind(C) procedures under the C names.\n\
         module c_names\n  use, intrinsic :: iso_c_binding\n  implicit none\ncontains\n\
         {from_c}{from_tfem}end module c_names\n\
         program c_names_program\n  use c_names\nend program c_names_program\n"
    );
    let source = generated_source("c_names", "c_names.f90", &program);
    build_fortran(&[&source], "c_names");
}

#[test]
fn the_module_compiles_without_warnings_as_fortran_2008_and_2018() {
    // Alone, at -O0 and -O2: Fortran 2008 for legacy clients built with
    // -std=f2008, Fortran 2018 for clients in gfortran's default mode.
    let dir = lib_dir().join("fortran").join("module_alone");
    std::fs::create_dir_all(&dir).unwrap();
    for std in ["-std=f2008", "-std=f2018"] {
        for opt in ["-O0", "-O2"] {
            let out = Command::new("gfortran")
                .args([std, opt, "-Wall", "-Werror", "-c", "-J"])
                .arg(&dir)
                .arg(root().join("include/tfem.f90"))
                .arg("-o")
                .arg(dir.join("tfem.o"))
                .output()
                .expect("gfortran is installed");
            assert!(
                out.status.success(),
                "gfortran {std} {opt} failed:\n{}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
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
    let module = module_text(&module, "tfem_c");
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

/// A client written against the bind(C) interfaces as they were before
/// the generic interfaces (every argument, integer(c_size_t) lengths,
/// rank-2 arrays where the C API takes flat buffers), built with
/// -std=f2008: the contact patch test against its closed form.
#[test]
fn fortran_legacy_client_with_rank_2_arrays_passes_every_check() {
    let exe = build_fortran(
        &[&root().join("c_tests/fortran_legacy_f2008_test.f90")],
        "fortran_legacy_f2008_test",
    );
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// The 3D model (`tfem_solid_*`) from a client built with -std=f2008,
/// index_base = 1 and rank-2 arrays: two stacked cubes of Kuhn tetrahedra
/// pressed into frictionless contact, against the exact uniaxial stress,
/// contact area and reactions, and its refusals named in 1-based numbers.
#[test]
fn fortran_solid_client_passes_the_3d_contact_patch_test() {
    let exe = build_fortran(
        &[&root().join("c_tests/fortran_solid_f2008_test.f90")],
        "fortran_solid_f2008_test",
    );
    let out = run(&exe, &[]);
    assert!(out.contains(" 0 failed"), "{out}");
}

/// The 3D contact context for host codes (`tfem_solid_contact_*`) from a
/// client built with -std=f2008, index_base = 1 and rank-2 arrays: a host
/// with its own tetrahedra, stiffness and dense solver presses two stacked
/// cubes into frictionless contact through its own active-set loop, against
/// the exact uniaxial stress and contact area, and the refusals named in
/// 1-based numbers.
#[test]
fn fortran_solid_host_passes_the_3d_contact_patch_test() {
    let exe = build_fortran(
        &[&root().join("c_tests/fortran_solid_host_f2008_test.f90")],
        "fortran_solid_host_f2008_test",
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
