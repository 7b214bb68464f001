//! The entry points of the 3D contact context for host codes
//! ([`crate::contact::host_solid::SolidHostContact`]): a fourth handle,
//! `tfem_solid_contact`, beside `tfem_model`, `tfem_contact` and
//! `tfem_solid_model`. It is the 2D context (`host`) in space, with its
//! conventions: statuses, messages naming the node, equation or side in
//! the host's numbering, outputs written only on success, no NaN or Inf
//! with TFEM_STATUS_OK. It is its own handle, not a mode of
//! `tfem_contact`, because the Rust types differ (three unknowns per node,
//! tetrahedra of B instead of triangles): a 2D function given a 3D context
//! (or the other way round) is refused by the live-handle check instead of
//! reading the wrong type.
//!
//! Side, pair and contact-tetrahedron numbers are in the context's index
//! base, as the Rust context names them in its messages: a Fortran host
//! reads "side 2" for the side it numbered 2. (The 2D context numbers its
//! sides and pairs from 0 whatever the base; its messages do too.)

use std::ffi::{c_char, c_int};

use super::convert::{TfemContactOptions, options_in};
use super::plumbing::{
    Handle, check_live, copy_in, copy_message, copy_out, count, guarded, null, panic_message,
    register, reserve, set_global_error, slice_in, too_small, unregister, with_handle, write,
    write_optional,
};
use crate::contact::ContactOptions;
use crate::contact::host_solid::{HostSurface, SolidHostContact};
use crate::error::{Error, Result, Status, ensure_finite};

/// Opaque handle to a 3D contact context for a host code. Create with
/// `tfem_solid_contact_create`, free with `tfem_solid_contact_destroy`.
pub struct TfemSolidContact {
    contact: SolidHostContact,
    last_error: String,
    /// Per-tetrahedron values (the gaps) computed and checked here before
    /// they reach the caller's buffer, which a failed call must leave as
    /// it was; kept so that repeated calls do not allocate.
    scratch: Vec<f64>,
}

impl Handle for TfemSolidContact {
    const ARGUMENT: &'static str = "context";
    const KIND: &'static str = "a 3D contact context (from tfem_solid_contact_create)";
    fn last_error(&mut self) -> &mut String {
        &mut self.last_error
    }
}

fn with_context(
    context: *mut TfemSolidContact,
    f: impl FnOnce(&mut TfemSolidContact) -> Result<()>,
) -> Status {
    with_handle(context, f)
}

/// A caller's buffer of at least `n` values, of which the first `n` are
/// given back (more is allowed, as in the 2D context).
fn out_slice<'a, T>(ptr: *mut T, len: usize, n: usize, what: &str) -> Result<&'a mut [T]> {
    if ptr.is_null() {
        return Err(null(what));
    }
    if len < n {
        return Err(too_small(what, len, n));
    }
    // SAFETY: the caller guarantees `len >= n` writable elements at `ptr`.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
}

/// A count for a C int, refused rather than truncated: a count that wraps
/// would size the host's buffers wrong without a word.
fn c_int_of(n: usize, what: &str) -> Result<c_int> {
    c_int::try_from(n)
        .map_err(|_| Error::argument(format!("{what} = {n} is more than a C int holds")))
}

/// Side number `i` (in the index base) as the Rust context's 0-based index.
/// One past the last is the context's to refuse, with the count of sides.
fn side_arg(c: &SolidHostContact, i: c_int, what: &str) -> Result<usize> {
    let base = c.index_base() as i64;
    usize::try_from(i64::from(i) - base).map_err(|_| {
        Error::argument(format!(
            "{what} = {i} is below the index base {base}: sides are numbered from it"
        ))
    })
}

/// The 2D context's refusal of `scatter_add` input that is not finite,
/// checked before the Rust context would call the sum an overflow: a NaN
/// from the host is its input (TFEM_STATUS_INVALID_ARGUMENT naming the
/// node, and the equation for the host's vector), not tfem's overflow.
/// A length the context refuses is left to it.
fn check_scatter_input(c: &SolidHostContact, residual: &[f64], host: &[f64]) -> Result<()> {
    let nodes = c.nodes();
    if residual.len() != 3 * nodes.len() {
        return Ok(());
    }
    let base = c.index_base() as i64;
    for (v, id) in nodes.iter().enumerate() {
        let equations = c.equations(v);
        for k in 0..3 {
            let axis = ["x", "y", "z"][k];
            let r = residual[3 * v + k];
            if !r.is_finite() {
                return Err(Error::argument(format!(
                    "`residual`: the {axis} value of interface node {id} is {r}, not finite"
                )));
            }
            let Some(e) = equations[k] else { continue };
            if let Some(h) = host.get((e - base) as usize)
                && !h.is_finite()
            {
                return Err(Error::argument(format!(
                    "`host_vector` holds {h} at equation {e} ({axis} of interface node {id}), \
                     not finite"
                )));
            }
        }
    }
    Ok(())
}

// -------- Lifecycle and errors ----------------------------------------

/// Creates a 3D contact context for a host code that keeps its own
/// elements, assembly, solver and Newton loop: node numbers, equation
/// numbers, and side, pair and contact-tetrahedron numbers in
/// `index_base` (0 for C, 1 for Fortran). `options` may be NULL (the
/// defaults of `tfem_contact_options_default`); they are fixed here, as B
/// is built from them once: `contact_modulus` (0: the smaller Young's
/// modulus of a pair's two sides), `lambda` (0: the larger side of the
/// interface nodes' bounding box) and `max_iterations` (the number of
/// `tfem_solid_contact_update` calls of one loop before it counts as not
/// converged) are read, `refactorize` is ignored; 3D contact is
/// frictionless with its own inversion test, so `law` and
/// `inversion_test` must be 0. Returns NULL if `index_base` is not 0 or 1
/// or an option is refused (message in `tfem_last_error(NULL, …)`), or
/// memory is exhausted. The host then adds the sides
/// (`tfem_solid_contact_add_side`) and pairs
/// (`tfem_solid_contact_add_pair`); the first call that needs B builds it,
/// after which sides and pairs are fixed. A 3D context is its own handle:
/// the 2D `tfem_contact_*` functions refuse it, and these refuse a 2D
/// context or a model.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_create(
    index_base: c_int,
    options: *const TfemContactOptions,
) -> *mut TfemSolidContact {
    let made = guarded(|| {
        let base = usize::try_from(index_base)
            .ok()
            .filter(|&b| b <= 1)
            .ok_or_else(|| Error::argument(format!("index_base = {index_base} must be 0 or 1")))?;
        // SAFETY: NULL or a caller-owned options struct.
        let opts = match unsafe { options.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        SolidHostContact::new(base, opts)
    });
    match made {
        Ok(Ok(contact)) => {
            let handle = register(TfemSolidContact {
                contact,
                last_error: String::new(),
                scratch: Vec::new(),
            });
            set_global_error(match handle.is_null() {
                true => "out of memory: the handle registry cannot grow",
                false => "",
            });
            handle
        }
        Ok(Err(e)) => {
            set_global_error(e.message());
            std::ptr::null_mut()
        }
        Err(p) => {
            set_global_error(&panic_message(p.as_ref()));
            std::ptr::null_mut()
        }
    }
}

/// Destroys a 3D contact context. NULL is a no-op, and so is a pointer
/// that is not a live 3D context (destroyed already, or another kind of
/// handle): do not use a handle after destroying it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_destroy(context: *mut TfemSolidContact) {
    if !context.is_null() && unregister(context) {
        // SAFETY: a live handle from tfem_solid_contact_create, now
        // unregistered, so freed once.
        let _ = guarded(|| drop(unsafe { Box::from_raw(context) }));
    }
}

/// Copies the message of the last failed call on `context` (empty after a
/// successful call) into `buffer` (`length` bytes including the final NUL),
/// truncating like `tfem_last_error` (TFEM_STATUS_BUFFER_TOO_SMALL;
/// `tfem_solid_contact_last_error_length` gives the size needed). A 3D
/// context keeps its own messages. A `context` that is not a live 3D
/// contact context gives TFEM_STATUS_INVALID_ARGUMENT with the message
/// saying so in `buffer`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_last_error(
    context: *const TfemSolidContact,
    buffer: *mut c_char,
    length: usize,
) -> Status {
    if context.is_null() {
        return Status::NullPointer;
    }
    if let Err(e) = check_live(context) {
        let _ = copy_message(e.message(), buffer, length);
        return e.status();
    }
    // SAFETY: a live handle from tfem_solid_contact_create (just checked).
    match unsafe { context.as_ref() } {
        Some(c) => copy_message(&c.last_error, buffer, length),
        None => Status::NullPointer,
    }
}

/// Size in bytes (including the final NUL) of the message
/// `tfem_solid_contact_last_error` would give for `context`, so that a
/// buffer of this size holds all of it: 1 after a successful call; for a
/// handle that is not a live 3D contact context (destroyed, or another
/// kind), the size of the message saying so. `context` may be NULL: 1 (it
/// has no message).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_last_error_length(
    context: *const TfemSolidContact,
) -> usize {
    if context.is_null() {
        return 1;
    }
    if let Err(e) = check_live(context) {
        return e.message().len() + 1;
    }
    // SAFETY: a live handle from tfem_solid_contact_create (just checked).
    unsafe { context.as_ref() }.map_or(1, |c| c.last_error.len() + 1)
}

// -------- Sides and pairs ---------------------------------------------

/// Adds one side of a contact interface, of body `body` (Young's modulus
/// `young`, finite and > 0: the softer side's is the default E_c):
/// `n_nodes` interface nodes `nodes` (the host's node numbers) with their
/// coordinates `xyz` (3 per node) and the equations of their x, y and z
/// unknowns `equations` (3 per node, in the index base; a value below the
/// base marks a fixed DOF without an equation), and `n_triangles`
/// triangles `triangles` (3 host node numbers each) numbered
/// counter-clockwise seen from outside the body, so that the two sides of
/// a pair face each other. A node of two sides, or given twice in one,
/// must come with the same coordinates and equations. Refused with TFEM_STATUS_INVALID_ARGUMENT,
/// naming the side (by its number in the index base and its tag), the node
/// or the triangle: a node number below the index base, a coordinate that
/// is not finite, an equation no host vector can hold (from index_base +
/// PTRDIFF_MAX / 8 on), a triangle over a node the side does not give, a
/// side without triangles; TFEM_STATUS_INVALID_STATE once B is built. The
/// host's system size is not known here: `tfem_solid_contact_gather` and
/// `tfem_solid_contact_scatter_add` check every equation against the
/// vector they are given. Writes the side's number (in the index base) to
/// `side` (may be NULL). On error nothing changes.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn tfem_solid_contact_add_side(
    context: *mut TfemSolidContact,
    tag: c_int,
    body: c_int,
    young: f64,
    n_nodes: c_int,
    nodes: *const c_int,
    xyz: *const f64,
    equations: *const i64,
    n_triangles: c_int,
    triangles: *const c_int,
    side: *mut c_int,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let nn = count(n_nodes, "n_nodes")?;
        let nt = count(n_triangles, "n_triangles")?;
        let ids = copy_in(slice_in(nodes, nn, "nodes")?, 1, "nodes", |v| {
            i64::from(v[0])
        })?;
        let xyz = copy_in(slice_in(xyz, 3 * nn, "xyz")?, 3, "xyz", |p| {
            [p[0], p[1], p[2]]
        })?;
        let eq = copy_in(
            slice_in(equations, 3 * nn, "equations")?,
            3,
            "equations",
            |e| [e[0], e[1], e[2]],
        )?;
        let tris = copy_in(
            slice_in(triangles, 3 * nt, "triangles")?,
            3,
            "triangles",
            |t| [t[0], t[1], t[2]].map(i64::from),
        )?;
        let s = c.add_side(&HostSurface {
            tag,
            body,
            young,
            nodes: &ids,
            xyz: &xyz,
            equations: &eq,
            triangles: &tris,
        })?;
        let s = c_int_of(s + c.index_base(), "the side's number")?;
        write_optional(side, s);
        Ok(())
    })
}

/// Declares sides `side_a` and `side_b` (their numbers in the index base,
/// of two different bodies) a contact pair: side a must be planar (its
/// outward normal opens the gap) and side b face it node to node; B, a
/// layer of flat tetrahedra over the prisms between the facing triangles,
/// is built from them (docs/method.md §9). A side that does not exist, or
/// two sides of one body, are refused with TFEM_STATUS_INVALID_ARGUMENT
/// naming them; sides that do not fit (side a not planar, sides not facing
/// each other or not matching) are refused by the call that builds B,
/// naming the pair and its sides. Writes the pair's number (in the index
/// base) to `pair` (may be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_add_pair(
    context: *mut TfemSolidContact,
    side_a: c_int,
    side_b: c_int,
    pair: *mut c_int,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let a = side_arg(c, side_a, "side_a")?;
        let b = side_arg(c, side_b, "side_b")?;
        let p = c.add_pair(a, b)?;
        let p = c_int_of(p + c.index_base(), "the pair's number")?;
        write_optional(pair, p);
        Ok(())
    })
}

/// Builds B of every pair and the pattern now, so that a host learns of
/// sides that do not fit where it declares them rather than at its first
/// evaluation (every call that needs B builds it otherwise). Sides and
/// pairs are fixed from then on; the active set starts from the
/// tetrahedra touching or overlapping at rest. Without a pair,
/// TFEM_STATUS_INVALID_STATE. Calling it again does nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_setup(context: *mut TfemSolidContact) -> Status {
    with_context(context, |h| h.contact.setup())
}

// -------- The pattern and the element blocks ---------------------------

/// Builds B (if not yet) and writes the sizes: interface nodes (3 values
/// per node in every per-node array: displacements and residuals),
/// tetrahedra of B (the length of the per-tetrahedron arrays), and entries
/// of the pattern. Any pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_sizes(
    context: *mut TfemSolidContact,
    n_nodes: *mut c_int,
    n_tetrahedra: *mut c_int,
    n_entries: *mut i64,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let entries = c.pattern()?.0.len() as i64;
        let tets = c_int_of(c.active()?.len(), "n_tetrahedra")?;
        let nodes = c_int_of(c.nodes().len(), "n_nodes")?;
        write_optional(n_nodes, nodes);
        write_optional(n_tetrahedra, tets);
        write_optional(n_entries, entries);
        Ok(())
    })
}

/// Copies the interface nodes (host numbers, n_nodes values), in the
/// order of every per-node array: the order in which the sides first gave
/// them.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_nodes(
    context: *mut TfemSolidContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let v: Vec<c_int> = h.contact.nodes().iter().map(|&n| n as c_int).collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the nodes of every tetrahedron of B (4 host node numbers each,
/// numbered so that J grows as the gap opens), pair by pair: with the
/// per-tetrahedron arrays (active flags, gaps), where the contact is.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_tetrahedra(
    context: *mut TfemSolidContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let tets = c.tetrahedra()?;
        let ids = c.nodes();
        let v: Vec<c_int> = (tets.iter())
            .flat_map(|t| t.map(|n| ids[n] as c_int))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the fixed pattern of the contact contributions into `rows`
/// (n_entries values) and `cols` (n_entries values), in the host's
/// equation numbering and index base: tetrahedron after tetrahedron of B,
/// each one's 12×12 block row by row over its DOFs (x, y, z of its first
/// node, then of its second …), the DOFs without an equation left out;
/// both triangles of each block. Entries repeat where tetrahedra share a
/// DOF pair: the host sums them. B's topology never changes, so a host
/// sets up its sparse matrix once.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_pattern(
    context: *mut TfemSolidContact,
    rows: *mut i64,
    cols: *mut i64,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let (r, k) = h.contact.pattern()?;
        let n = r.len();
        out_slice(rows, length, n, "rows")?;
        out_slice(cols, length, n, "cols")?;
        copy_out(r, rows, length, "rows")?;
        copy_out(k, cols, length, "cols")
    })
}

/// Copies the equations of every tetrahedron's twelve DOFs (12 per
/// tetrahedron, x, y, z of each node, in the index base; index_base − 1
/// marks a DOF without an equation): with
/// `tfem_solid_contact_element_blocks`, the contributions as unassembled
/// element blocks, for a host that assembles elements rather than a
/// pattern.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_element_equations(
    context: *mut TfemSolidContact,
    out: *mut i64,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let none = c.index_base() as i64 - 1;
        let n = c.active()?.len();
        let mut v = reserve(12 * n, "the element equations")?;
        for k in 0..n {
            v.extend(c.element_equations(k)?.map(|e| e.unwrap_or(none)));
        }
        copy_out(&v, out, length, "out")
    })
}

/// Copies every tetrahedron's 12×12 tangent block (144 values per
/// tetrahedron, row-major over its DOFs as in
/// `tfem_solid_contact_element_equations`): its stiffness when active,
/// zeros when not.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_element_blocks(
    context: *mut TfemSolidContact,
    out: *mut f64,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let n = c.active()?.len();
        let out = out_slice(out, length, 144 * n, "out")?;
        let mut block = [0.0; 144];
        for k in 0..n {
            c.element_block(k, &mut block)?;
            out[144 * k..144 * k + 144].copy_from_slice(&block);
        }
        Ok(())
    })
}

// -------- Evaluation, host vectors and the active set ------------------

/// The contact contributions at the displacements `u` of the interface
/// nodes (3 per node, `u_length` = 3·n_nodes): the tangent's values in the
/// pattern's order into `values` (n_entries values, zeros for inactive
/// tetrahedra), and the contact residual Σ (K_e u_e − f0_e) of the active
/// tetrahedra, 3 per interface node, into `residual`. `values` may be
/// NULL; `residual` may be NULL. A linear host adds the values to its
/// matrix and minus the residual at u₀ to its right-hand side, u₀ zero at
/// DOFs with an equation and the prescribed value at those without (a
/// rigid tool pressed by δ: `tfem_solid_contact_gather` reads such DOFs
/// as 0, so set them in `u` itself, here and for
/// `tfem_solid_contact_update`); that is the load of the initial gaps and
/// of the prescribed values. A Newton host adds the values to its tangent and
/// the residual at its current u to its residual. The law is linear in u
/// for a given active set: the values depend on the active set only, and
/// change only when `tfem_solid_contact_update` or
/// `tfem_solid_contact_set_active` changes it. A non-finite value in `u`
/// is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node); a residual
/// that overflows is TFEM_STATUS_NUMERICAL_FAILURE naming the node;
/// either way the buffers are unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_evaluate(
    context: *mut TfemSolidContact,
    u: *const f64,
    u_length: usize,
    values: *mut f64,
    values_length: usize,
    residual: *mut f64,
    residual_length: usize,
) -> Status {
    with_context(context, |h| {
        let c = &mut h.contact;
        let u = slice_in(u, u_length, "u")?;
        let entries = c.pattern()?.0.len();
        let n = 3 * c.nodes().len();
        let values = match values.is_null() {
            true => None,
            false => Some(out_slice(values, values_length, entries, "values")?),
        };
        let residual = match residual.is_null() {
            true => None,
            false => Some(out_slice(residual, residual_length, n, "residual")?),
        };
        c.evaluate(u, values, residual)
    })
}

/// Copies into `u` (3 per interface node) the displacements of the
/// interface nodes from the host's solution vector `u_equations`
/// (`n_equations` values; entry i is equation i + index_base); a DOF
/// without an equation counts as fixed at zero. An interface node's
/// equation beyond `n_equations`, or a non-finite entry there, is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming the node and the equation); `u` is
/// then unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_gather(
    context: *mut TfemSolidContact,
    u_equations: *const f64,
    n_equations: usize,
    u: *mut f64,
    u_length: usize,
) -> Status {
    with_context(context, |h| {
        let c = &h.contact;
        let host = slice_in(u_equations, n_equations, "u_equations")?;
        let n = 3 * c.nodes().len();
        c.gather(host, out_slice(u, u_length, n, "u")?)
    })
}

/// Adds per-node values `residual` (3 per interface node, as
/// `tfem_solid_contact_evaluate` writes them) into the host's vector
/// `host_vector` (`n_equations` values, entry i is equation i +
/// index_base); DOFs without an equation are left out. A non-finite value
/// in `residual` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
/// node), and so is a sum that would not be finite: an entry of
/// `host_vector` that is not finite already (TFEM_STATUS_INVALID_ARGUMENT),
/// or an overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the
/// equation; an equation beyond `n_equations` is refused naming the node.
/// `host_vector` is then unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_scatter_add(
    context: *mut TfemSolidContact,
    residual: *const f64,
    residual_length: usize,
    host_vector: *mut f64,
    n_equations: usize,
) -> Status {
    with_context(context, |h| {
        let c = &h.contact;
        let r = slice_in(residual, residual_length, "residual")?;
        let host = out_slice(host_vector, n_equations, n_equations, "host_vector")?;
        check_scatter_input(c, r, host)?;
        c.scatter_add(r, host)
    })
}

/// The inversion test at the displacements `u` (3 per interface node) of
/// a solve with the current active set: the tetrahedra of B whose gap is
/// not positive (pressed, or touching) are switched on, the others off.
/// `changed` (may be NULL) is set to 1 if the set changed, 0 if it
/// settled; `switched_on` (may be NULL) and `switched_off` (may be NULL)
/// to the number of tetrahedra switched each way. The same test and cycle
/// detection as tfem's own loop: a set visited before, or more calls than
/// the options' `max_iterations` since the last
/// `tfem_solid_contact_restart`, gives TFEM_STATUS_NOT_CONVERGED with the
/// history, the set unchanged. Call it with converged displacements of
/// the host's problem for the current set (after its Newton loop, not at
/// every Newton iteration): the test judges the solution. A non-finite
/// value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_update(
    context: *mut TfemSolidContact,
    u: *const f64,
    u_length: usize,
    changed: *mut c_int,
    switched_on: *mut c_int,
    switched_off: *mut c_int,
) -> Status {
    with_context(context, |h| {
        let u = slice_in(u, u_length, "u")?;
        let update = h.contact.update(u)?;
        let n = |k: usize| c_int::try_from(k).unwrap_or(c_int::MAX);
        write_optional(changed, c_int::from(update.changed));
        write_optional(switched_on, n(update.switched_on));
        write_optional(switched_off, n(update.switched_off));
        Ok(())
    })
}

/// Starts a new active-set loop from the current flags (a new load step):
/// the history and the sets visited are forgotten, so that a set met in
/// an earlier step is no cycle.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_restart(context: *mut TfemSolidContact) -> Status {
    with_context(context, |h| h.contact.restart())
}

/// Copies the active flag (1 active, 0 not) of every tetrahedron of B
/// (n_tetrahedra values): the state a host saves to restore with
/// `tfem_solid_contact_set_active`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_get_active(
    context: *mut TfemSolidContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let v: Vec<c_int> = (h.contact.active()?.iter())
            .map(|&a| c_int::from(a))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Sets the active flags of the tetrahedra of B (n_tetrahedra values, 0
/// or 1): a warm start or a restored state; starts a new loop. A value
/// other than 0 or 1, or another count, is refused
/// (TFEM_STATUS_INVALID_ARGUMENT), the flags unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_set_active(
    context: *mut TfemSolidContact,
    active: *const c_int,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let a = slice_in(active, length, "active")?;
        if let Some(k) = a.iter().position(|&v| v != 0 && v != 1) {
            return Err(Error::argument(format!(
                "active[{k}] = {} must be 0 or 1",
                a[k]
            )));
        }
        let flags: Vec<bool> = a.iter().map(|&v| v == 1).collect();
        h.contact.set_active(&flags)
    })
}

// -------- Results -----------------------------------------------------

/// Copies the opening of every tetrahedron of B (n_tetrahedra values,
/// model length units) at the displacements `u` (3 per interface node):
/// its linearised gap over its facing area, the distance across the
/// interface (negative: an overlap). Per tetrahedron rather than per node
/// as in 2D: in space a node's tetrahedra may face different triangles. A
/// non-finite value in `u` is refused (TFEM_STATUS_INVALID_ARGUMENT naming
/// the node), a gap that overflows is TFEM_STATUS_NUMERICAL_FAILURE naming
/// the tetrahedron; `out` is then unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_gaps(
    context: *mut TfemSolidContact,
    u: *const f64,
    u_length: usize,
    out: *mut f64,
    length: usize,
) -> Status {
    with_context(context, |h| {
        let u = slice_in(u, u_length, "u")?;
        let n = h.contact.active()?.len();
        let out = out_slice(out, length, n, "out")?;
        let base = h.contact.index_base();
        h.scratch.clear();
        h.scratch.resize(n, 0.0);
        h.contact.gaps(u, &mut h.scratch)?;
        ensure_finite(h.scratch.iter().copied(), 1, "gap", |k| {
            format!("contact tetrahedron {}", k + base)
        })?;
        out.copy_from_slice(&h.scratch);
        Ok(())
    })
}

/// Writes the area in contact of the current active set to `area` (model
/// length units squared): each active tetrahedron of B stands for a third
/// of its prism's facing triangle, so that a closed interface reads its
/// whole area. A sum that overflows is TFEM_STATUS_NUMERICAL_FAILURE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_contact_area(
    context: *mut TfemSolidContact,
    area: *mut f64,
) -> Status {
    with_context(context, |h| {
        let a = h.contact.contact_area()?;
        ensure_finite([a], 1, "contact area", |_| "the contact pairs".to_string())?;
        write(area, a, "area")
    })
}
