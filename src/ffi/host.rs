//! The entry points of the contact context for host codes
//! ([`crate::contact::HostContact`]): a second handle, `tfem_contact`,
//! beside `tfem_model`.

use std::ffi::{c_char, c_int};

use super::convert::{TfemContactOptions, options_in, plane};
use super::plumbing::{
    Handle, check_live, copy_in, copy_message, copy_out, count, guarded, null, register,
    set_global_error, slice_in, unregister, with_handle, write, write_optional,
};
use crate::contact::{ContactOptions, HostContact};
use crate::error::{Error, Result, Status};
use crate::fem::material::Material;

/// Opaque handle to a contact context for a host code. Create with
/// `tfem_contact_create`, free with `tfem_contact_destroy`.
pub struct TfemContact {
    contact: HostContact,
    last_error: String,
}

impl Handle for TfemContact {
    const ARGUMENT: &'static str = "context";
    const KIND: &'static str = "a contact context (from tfem_contact_create)";
    fn last_error(&mut self) -> &mut String {
        &mut self.last_error
    }
}

fn with_context(
    context: *mut TfemContact,
    f: impl FnOnce(&mut HostContact) -> Result<()>,
) -> Status {
    with_handle(context, |c| f(&mut c.contact))
}

/// A caller's buffer of exactly `n` values (more is allowed).
fn out_slice<'a, T>(ptr: *mut T, len: usize, n: usize, what: &str) -> Result<&'a mut [T]> {
    if ptr.is_null() {
        return Err(null(what));
    }
    if len < n {
        return Err(Error::new(
            Status::BufferTooSmall,
            format!("`{what}` holds {len} values but {n} are needed"),
        ));
    }
    // SAFETY: the caller guarantees `len >= n` writable elements at `ptr`.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
}

/// Creates a contact context for a host code that keeps its own elements,
/// assembly, solver and Newton loop: node numbers and equation numbers in
/// `index_base` (0 for C, 1 for Fortran). Returns NULL if `index_base` is
/// not 0 or 1 (message in `tfem_last_error(NULL, …)`) or memory is
/// exhausted. The host then adds the sides of its contact interfaces
/// (`tfem_contact_add_side`) and the pairs (`tfem_contact_add_pair`); the
/// first call that needs the contact mesh B builds it, after which sides
/// and pairs are fixed.
#[unsafe(no_mangle)]
pub extern "C" fn tfem_contact_create(index_base: c_int) -> *mut TfemContact {
    let made = guarded(|| {
        let base = usize::try_from(index_base)
            .map_err(|_| Error::argument(format!("index_base = {index_base} must be 0 or 1")))?;
        HostContact::new(base, ContactOptions::default())
    });
    match made {
        Ok(Ok(contact)) => {
            set_global_error("");
            register(TfemContact {
                contact,
                last_error: String::new(),
            })
        }
        Ok(Err(e)) => {
            set_global_error(e.message());
            std::ptr::null_mut()
        }
        Err(_) => std::ptr::null_mut(),
    }
}

/// Destroys a contact context. NULL is a no-op, and so is a pointer that
/// is not a live context (destroyed already, or a model).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_destroy(context: *mut TfemContact) {
    if !context.is_null() && unregister(context) {
        // SAFETY: a live handle from tfem_contact_create, now unregistered,
        // so freed once.
        let _ = guarded(|| drop(unsafe { Box::from_raw(context) }));
    }
}

/// Copies the message of the last failed call on `context` (empty after a
/// successful call) into `buffer` (`length` bytes including the final NUL),
/// truncating like `tfem_last_error`. A `context` that is not a live
/// contact context gives TFEM_STATUS_INVALID_ARGUMENT with the message
/// saying so in `buffer`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_last_error(
    context: *const TfemContact,
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
    // SAFETY: a live handle from tfem_contact_create (just checked).
    match unsafe { context.as_ref() } {
        Some(c) => copy_message(&c.last_error, buffer, length),
        None => Status::NullPointer,
    }
}

/// Size in bytes (including the final NUL) of the message
/// `tfem_contact_last_error` would give for `context` (a buffer of this
/// size holds all of it): 1 after a successful call; for a handle that is
/// not a live contact context (destroyed, or a model), the size of the
/// message saying so. `context` may be NULL: 1 (it has no message).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_last_error_length(context: *const TfemContact) -> usize {
    if context.is_null() {
        return 1;
    }
    if let Err(e) = check_live(context) {
        return e.message().len() + 1;
    }
    // SAFETY: a live handle from tfem_contact_create (just checked).
    unsafe { context.as_ref() }.map_or(1, |c| c.last_error.len() + 1)
}

/// Sets the contact options (law, E_c, λ, inversion test, and
/// `max_iterations`: the number of `tfem_contact_update` calls of one loop
/// before it counts as not converged; `refactorize` is ignored). Only
/// before the contact mesh is built. Defaults: `tfem_contact_options_default`,
/// with λ the larger side of the interface nodes' bounding box.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_set_options(
    context: *mut TfemContact,
    options: *const TfemContactOptions,
) -> Status {
    with_context(context, |c| {
        // SAFETY: NULL or a caller-owned options struct.
        let o = unsafe { options.as_ref() }.ok_or_else(|| null("options"))?;
        c.set_options(options_in(o)?)
    })
}

/// Adds one side of a contact interface, of body `body` (Young's modulus
/// `young`, Poisson ratio `poisson`, `plane_mode` a `PlaneMode`: the
/// softer side's E is the default E_c, the stick law takes its ν):
/// `n_nodes` interface nodes `nodes` (the host's node numbers) with their
/// coordinates `xy` (2 per node) and the equations of their x and y
/// unknowns `equations` (2 per node, in the index base; a value below the
/// base marks a fixed DOF without an equation), and `n_edges` edges
/// `edges` (2 host node numbers each), each given with its body on its
/// left (the counter-clockwise boundary orientation); an edge that runs
/// against its neighbour is refused (TFEM_STATUS_INVALID_CONTACT, naming
/// it). A node of two sides must come with the same coordinates and
/// equations. A node number below the index base is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming the side, the node's entry and the
/// number), and so is an equation that no host vector can hold (from
/// index_base + PTRDIFF_MAX / 8 on: no array of doubles spans more bytes),
/// naming the node and the equation. The host's system size is not known
/// here: `tfem_contact_gather` and `tfem_contact_scatter_add` check every
/// equation against the vector they are given. Writes the side's
/// index (0-based) to `side` (may be NULL). On error nothing changes.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn tfem_contact_add_side(
    context: *mut TfemContact,
    tag: c_int,
    body: c_int,
    young: f64,
    poisson: f64,
    plane_mode: c_int,
    n_nodes: c_int,
    nodes: *const c_int,
    xy: *const f64,
    equations: *const i64,
    n_edges: c_int,
    edges: *const c_int,
    side: *mut c_int,
) -> Status {
    with_context(context, |c| {
        let material = Material::new(young, poisson, plane(plane_mode)?, &format!("body {body}"))?;
        let nn = count(n_nodes, "n_nodes")?;
        let ne = count(n_edges, "n_edges")?;
        let ids = copy_in(slice_in(nodes, nn, "nodes")?, 1, "nodes", |v| v[0] as i64)?;
        let xy = copy_in(slice_in(xy, 2 * nn, "xy")?, 2, "xy", |p| [p[0], p[1]])?;
        let eq = copy_in(
            slice_in(equations, 2 * nn, "equations")?,
            2,
            "equations",
            |e| [e[0], e[1]],
        )?;
        let edges = copy_in(slice_in(edges, 2 * ne, "edges")?, 2, "edges", |e| {
            [e[0] as i64, e[1] as i64]
        })?;
        let s = c.add_side(tag, body, material, &ids, &xy, &eq, &edges)?;
        write_optional(side, s as c_int);
        Ok(())
    })
}

/// Declares sides `side_a` and `side_b` (on different bodies) a contact
/// pair: the contact mesh B is built from their matching nodes, or by
/// triangulating the strip between them. Two sides whose outward normals
/// point the same way (one of them given clockwise) are refused with
/// TFEM_STATUS_INVALID_CONTACT naming both. A pair of two sides already
/// paired (either way round) is refused with TFEM_STATUS_INVALID_CONTACT
/// naming it: it would double their contact. Messages name a side by its
/// index and tag ("side 0 (tag 101)") and nodes by the host's numbers.
/// Writes the pair's index (0-based) to `pair` (may be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_add_pair(
    context: *mut TfemContact,
    side_a: c_int,
    side_b: c_int,
    pair: *mut c_int,
) -> Status {
    with_context(context, |c| {
        let a = count(side_a, "side_a")?;
        let b = count(side_b, "side_b")?;
        let p = c.add_pair(a, b)?;
        write_optional(pair, p as c_int);
        Ok(())
    })
}

/// Declares a pair with the host's own contact mesh B: `n_triangles`
/// triangles `connectivity` (3 host node numbers each) over the interface
/// nodes of the two sides; wrongly oriented ones are turned. A triangle
/// given twice (the same three nodes) is refused
/// (TFEM_STATUS_INVALID_CONTACT naming both triangles), and so is a pair
/// already declared, as by `tfem_contact_add_pair`. A node number below
/// the index base is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
/// pair, the triangle, the node's place in it and the number). Writes the pair's
/// index (0-based) to `pair` (may be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_add_pair_with_mesh(
    context: *mut TfemContact,
    side_a: c_int,
    side_b: c_int,
    n_triangles: c_int,
    connectivity: *const c_int,
    pair: *mut c_int,
) -> Status {
    with_context(context, |c| {
        let a = count(side_a, "side_a")?;
        let b = count(side_b, "side_b")?;
        let nt = count(n_triangles, "n_triangles")?;
        let tris = copy_in(
            slice_in(connectivity, 3 * nt, "connectivity")?,
            3,
            "connectivity",
            |t| [t[0] as i64, t[1] as i64, t[2] as i64],
        )?;
        let p = c.add_pair_with_mesh(a, b, &tris)?;
        write_optional(pair, p as c_int);
        Ok(())
    })
}

/// Builds the contact mesh B (if not yet) and writes the sizes: interface
/// nodes (the length of every per-node array: 2 values per node for
/// displacements and residuals), elements of B, and entries of the
/// pattern. Any pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_sizes(
    context: *mut TfemContact,
    n_nodes: *mut c_int,
    n_elements: *mut c_int,
    n_entries: *mut i64,
) -> Status {
    with_context(context, |c| {
        let entries = c.pattern()?.0.len();
        let elements = c.elements()?.len();
        write_optional(n_nodes, c.n_nodes() as c_int);
        write_optional(n_elements, elements as c_int);
        write_optional(n_entries, entries as i64);
        Ok(())
    })
}

/// Copies the interface nodes (host numbers, n_nodes values), in the
/// order of every per-node array.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_nodes(
    context: *mut TfemContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let v: Vec<c_int> = c.nodes().iter().map(|&n| n as c_int).collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the fixed pattern of the contact contributions into `rows`
/// (n_entries values) and `cols` (n_entries values), in the host's
/// equation numbering and index base: element
/// after element of B, each element's 6×6 block row by row over its DOFs
/// (x then y of its first, second and third node), the DOFs without an
/// equation left out; both triangles of each block. Entries repeat where
/// elements share a DOF pair: the host sums them.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_pattern(
    context: *mut TfemContact,
    rows: *mut i64,
    cols: *mut i64,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let (r, k) = c.pattern()?;
        let n = r.len();
        out_slice(rows, length, n, "rows")?;
        out_slice(cols, length, n, "cols")?;
        copy_out(r, rows, length, "rows")?;
        copy_out(k, cols, length, "cols")
    })
}

/// The contact contributions at the displacements `u` of the interface
/// nodes (2 per node, `u_length` = 2·n_nodes): the tangent's values in the
/// pattern's order into `values` (n_entries values, zeros for inactive
/// elements), and the contact residual Σ (K_e u_e − f0_e) of the active
/// elements, 2 per interface node, into `residual`. `values` may be NULL;
/// `residual` may be NULL. A linear host adds the values to its matrix and minus the
/// residual at u = 0 (the load of initial gaps) to its right-hand side; a
/// Newton host adds the values to its tangent and the residual at its
/// current u to its residual. The contact law is linear in u for a given
/// active set: the values depend on the active set only, not on `u`, and
/// change only when `tfem_contact_update` or `tfem_contact_set_active`
/// changes the set. A non-finite value in `u` is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value); a result
/// that overflows is TFEM_STATUS_NUMERICAL_FAILURE; either way the buffers
/// are unchanged. Allocates nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_evaluate(
    context: *mut TfemContact,
    u: *const f64,
    u_length: usize,
    values: *mut f64,
    values_length: usize,
    residual: *mut f64,
    residual_length: usize,
) -> Status {
    with_context(context, |c| {
        let u = slice_in(u, u_length, "u")?;
        let entries = c.pattern()?.0.len();
        let n = 2 * c.n_nodes();
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

/// Copies into `u` (2 per interface node) the displacements of the
/// interface nodes from the host's solution vector `u_equations`
/// (`n_equations` values; entry i is equation i + index_base); a DOF
/// without an equation counts as fixed at zero. A non-finite entry at an
/// interface node's equation is refused (TFEM_STATUS_INVALID_ARGUMENT
/// naming the node and the equation); `u` is then unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_gather(
    context: *mut TfemContact,
    u_equations: *const f64,
    n_equations: usize,
    u: *mut f64,
    u_length: usize,
) -> Status {
    with_context(context, |c| {
        let host = slice_in(u_equations, n_equations, "u_equations")?;
        let n = 2 * c.n_nodes();
        c.gather(host, out_slice(u, u_length, n, "u")?)
    })
}

/// Adds per-node values `residual` (2 per interface node, as
/// `tfem_contact_evaluate` writes them) into the host's vector
/// `host_vector` (`n_equations` values, entry i is equation i +
/// index_base); DOFs without an equation are left out. A non-finite value
/// in `residual` is refused (TFEM_STATUS_INVALID_ARGUMENT naming the node),
/// and so is a sum that would not be finite: an entry of `host_vector`
/// that is not finite already (TFEM_STATUS_INVALID_ARGUMENT), or an
/// overflow (TFEM_STATUS_NUMERICAL_FAILURE), naming the node and the
/// equation. `host_vector` is then unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_scatter_add(
    context: *mut TfemContact,
    residual: *const f64,
    residual_length: usize,
    host_vector: *mut f64,
    n_equations: usize,
) -> Status {
    with_context(context, |c| {
        let r = slice_in(residual, residual_length, "residual")?;
        c.scatter_add(
            r,
            out_slice(host_vector, n_equations, n_equations, "host_vector")?,
        )
    })
}

/// The inversion test at the displacements `u` (2 per interface node) of
/// a solve with the current active set: the elements found inverted are
/// switched on, the others off; `changed` (may be NULL) is set to 1 if the
/// set changed, 0 if it settled. The same test and cycle detection as
/// tfem's own loop: a set visited before, or more calls than the options'
/// `max_iterations` since the last `tfem_contact_restart`, gives
/// TFEM_STATUS_NOT_CONVERGED with the history, the set unchanged. Call
/// it with converged displacements of the host's problem for the current
/// set (after its Newton loop, not at every Newton iteration): the test
/// judges the solution, and a mid-Newton iterate may switch elements that
/// the converged state would not. A non-finite value in `u` is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_update(
    context: *mut TfemContact,
    u: *const f64,
    u_length: usize,
    changed: *mut c_int,
) -> Status {
    with_context(context, |c| {
        let u = slice_in(u, u_length, "u")?;
        let update = c.update(u)?;
        write_optional(changed, c_int::from(update.changed));
        Ok(())
    })
}

/// Starts a new active-set loop from the current flags (a new load step):
/// the history and the sets visited are forgotten.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_restart(context: *mut TfemContact) -> Status {
    with_context(context, |c| c.restart())
}

/// Copies the active flag (1 active, 0 not) of every element of B.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_get_active(
    context: *mut TfemContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let v: Vec<c_int> = c.active()?.iter().map(|&a| c_int::from(a)).collect();
        copy_out(&v, out, length, "out")
    })
}

/// Sets the active flags of the elements of B (n_elements values, 0 or
/// 1): a warm start or a restored state; starts a new loop.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_set_active(
    context: *mut TfemContact,
    active: *const c_int,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let a = slice_in(active, length, "active")?;
        if let Some(k) = a.iter().position(|&v| v != 0 && v != 1) {
            return Err(Error::argument(format!(
                "active[{k}] = {} must be 0 or 1",
                a[k]
            )));
        }
        let flags: Vec<bool> = a.iter().map(|&v| v == 1).collect();
        c.set_active(&flags)
    })
}

/// Copies the normal gap at every interface node (n_nodes values, model
/// length units) for the displacements `u` (2 per interface node): the
/// smallest, over the elements of B at the node, of the distance of an
/// element's apex from its interface edge (linearised; negative:
/// interpenetration). A node in no element of B (on a part of its side
/// that faces nothing of the other, beyond the other side's end) has no
/// gap and reads 0, as if touching: it is not in contact, and no contact
/// force acts there; tell such nodes by their absence from
/// `tfem_contact_elements`. A non-finite value in `u` is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_gaps(
    context: *mut TfemContact,
    u: *const f64,
    u_length: usize,
    out: *mut f64,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let u = slice_in(u, u_length, "u")?;
        let n = c.n_nodes();
        let out = out_slice(out, length, n, "out")?;
        c.gaps(u, out)
    })
}

/// Copies the contact pressure of every element of B (n_elements values;
/// a stress, positive in compression, zero when inactive) for the
/// displacements `u` (2 per interface node). A non-finite value in `u` is
/// refused (TFEM_STATUS_INVALID_ARGUMENT naming the node and the value).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_pressures(
    context: *mut TfemContact,
    u: *const f64,
    u_length: usize,
    out: *mut f64,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let u = slice_in(u, u_length, "u")?;
        let n = c.elements()?.len();
        let out = out_slice(out, length, n, "out")?;
        c.pressures(u, out)
    })
}

/// Copies the nodes of every element of B (3 host node numbers each,
/// oriented so that J > 0 when the gap opens).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_elements(
    context: *mut TfemContact,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let ids = c.nodes().to_vec();
        let v: Vec<c_int> = c
            .elements()?
            .iter()
            .flat_map(|e| e.nodes.map(|n| ids[n] as c_int))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the equations of every element's six DOFs (6 per element, x
/// then y of each node, in the index base; index_base − 1 marks a DOF
/// without an equation): with `tfem_contact_element_blocks`, the
/// contributions as unassembled element blocks.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_element_equations(
    context: *mut TfemContact,
    out: *mut i64,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let none = c.index_base() as i64 - 1;
        let n = c.elements()?.len();
        let mut v = Vec::with_capacity(6 * n);
        for k in 0..n {
            v.extend(c.element_equations(k)?.map(|e| e.unwrap_or(none)));
        }
        copy_out(&v, out, length, "out")
    })
}

/// Copies every element's 6×6 tangent block (36 values per element,
/// row-major over its DOFs as in `tfem_contact_element_equations`): its
/// stiffness when active, zeros when not.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_element_blocks(
    context: *mut TfemContact,
    out: *mut f64,
    length: usize,
) -> Status {
    with_context(context, |c| {
        let n = c.elements()?.len();
        let out = out_slice(out, length, 36 * n, "out")?;
        let mut block = [0.0; 36];
        for k in 0..n {
            c.element_block(k, &mut block)?;
            out[36 * k..36 * k + 36].copy_from_slice(&block);
        }
        Ok(())
    })
}

/// Writes the contact length of the current active set to `length`, model
/// length units: per contact zone (a pair's active elements of B connected
/// through shared nodes), the summed interface-edge length
/// of the active elements (each as far as it faces the other side) of the
/// family — edges on one side, or on the other: each covers the interface
/// once — active over the longer length; +0.0 when no element is active.
/// (Their mean would count half the width where one family alone carries
/// a contact.)
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_length(
    context: *mut TfemContact,
    length: *mut f64,
) -> Status {
    with_context(context, |c| write(length, c.contact_length()?, "length"))
}
