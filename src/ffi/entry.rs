//! The entry points of the C ABI for the model, by group in the order of
//! the header (lifecycle, mesh, materials, loads and constraints, contact
//! pairs, solve, results, contact results, load history, utilities; the
//! host codes' contact context is `host`): each checks its arguments,
//! calls the Rust API, and writes its outputs.

use std::ffi::{c_char, c_int};

use super::convert::{
    AdaptGoal, TfemAdaptReport, TfemContactOptions, TfemContactReport, TfemSolveInfo, component,
    corners_arg, info_out, jmin_arg, options_in, plane, report_out,
};
use super::plumbing::{
    LAST_ERROR, TfemModel, check_live, copy_in, copy_message, copy_out, count, guarded, map_out,
    null, register, reserve, slice_in, too_small, unregister, with_model, without_model, write,
    write_optional,
};
use crate::contact::mortar::SlaveNode;
use crate::contact::{ContactOptions, ContactWeighting};
use crate::error::{Error, Result, Status};
use crate::fem::curve::Curve;
use crate::fem::element::{Tempering, TriGeometry, laplacian_stiffness, section_stiffness};
use crate::fem::material::Material;
use crate::fem::mesh::Mesh;
use crate::linalg::Ordering;
use crate::model::Model;
use crate::model::adapt::{AdaptOptions, Goal};

// -------- Lifecycle, errors and warnings ------------------------------

/// The library version as a static NUL-terminated string ("major.minor.patch").
/// Thread-safe; never NULL; do not free.
#[unsafe(no_mangle)]
pub extern "C" fn tfem_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// Creates an empty model. Returns NULL only if memory is exhausted.
/// Free it with `tfem_destroy`.
#[unsafe(no_mangle)]
pub extern "C" fn tfem_create() -> *mut TfemModel {
    guarded(|| {
        register(TfemModel {
            model: Model::new(),
            index_base: 0,
            last_error: String::new(),
            adapt: Vec::new(),
        })
    })
    .unwrap_or(std::ptr::null_mut())
}

/// Destroys a model and everything it owns. NULL is a no-op, and so is a
/// pointer that is not a live model (destroyed already, or a contact
/// context). A destroyed handle given to any function is refused
/// (TFEM_STATUS_INVALID_ARGUMENT), as is a handle of the other kind —
/// unless its address has since been reused by a new handle, which it
/// then reaches: do not use a handle after destroying it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_destroy(model: *mut TfemModel) {
    if !model.is_null() && unregister(model) {
        // SAFETY: a live handle from tfem_create, now unregistered, so
        // freed once.
        let _ = guarded(|| drop(unsafe { Box::from_raw(model) }));
    }
}

/// Copies the message of the last failed call on `model` (empty after a
/// successful call) into `buffer` (`length` bytes including the final NUL).
/// With `model` NULL, gives the calling thread's last error from calls that
/// have no model (or were given a NULL one). A message longer than the buffer
/// is truncated (still NUL-terminated) and TFEM_STATUS_BUFFER_TOO_SMALL is
/// returned; `tfem_last_error_length` gives the size needed. A `model`
/// that is not a live model gives TFEM_STATUS_INVALID_ARGUMENT with the
/// message saying so in `buffer`. (These, with `tfem_contact_last_error`
/// and `tfem_get_warning`, are the only failed calls that write an
/// output: see the conventions at the top.)
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_last_error(
    model: *const TfemModel,
    buffer: *mut c_char,
    length: usize,
) -> Status {
    let text = match model_error(model) {
        Ok(text) => text,
        Err(e) => {
            let _ = copy_message(e.message(), buffer, length);
            return e.status();
        }
    };
    copy_message(&text, buffer, length)
}

/// Size in bytes (including the final NUL) of the message `tfem_last_error`
/// would give. `model` may be NULL (thread's last error).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_last_error_length(model: *const TfemModel) -> usize {
    match model_error(model) {
        Ok(text) => text.len() + 1,
        Err(e) => e.message().len() + 1,
    }
}

/// The last error of `model` (NULL: the thread's), or why `model` is not
/// a live model.
fn model_error(model: *const TfemModel) -> Result<String> {
    if model.is_null() {
        return Ok(LAST_ERROR.with(|e| e.borrow().clone()));
    }
    check_live(model)?;
    // SAFETY: a live handle from tfem_create (just checked).
    Ok(unsafe { model.as_ref() }.map_or_else(String::new, |m| m.last_error.clone()))
}

/// Number of warnings: mesh validation (unused or coincident nodes,
/// inverted or clockwise triangles), what `tfem_add_contact_pairs_auto`
/// left out (a tag whose edges bound several bodies, an interface found
/// again under other tags: kept until the pairs are cleared, the boundary
/// edges set anew or the mesh replaced) and the last solve or load step (tempering of well-shaped
/// elements, an ill-conditioned system, contact pressures with fewer than
/// six correct digits: a penalty E_c so stiff that its overlaps approach
/// the rounding of the displacements; after `tfem_solve` or
/// `tfem_solve_contact`, a body's reactions with fewer than six correct
/// digits: a "rigid" body modelled with a huge Young's modulus; a
/// one-sided contact zone). The pairing warnings outlive solves.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_warning_count(model: *mut TfemModel, count: *mut c_int) -> Status {
    with_model(model, |m| {
        write(count, m.model.warnings().len() as c_int, "count")
    })
}

/// Writes to `size` the size in bytes (including the final NUL) of
/// warning number `index` (0-based, whatever the index base): a buffer
/// of this size holds all of it in `tfem_get_warning`. An index out of
/// range is refused (TFEM_STATUS_INVALID_ARGUMENT), `size` unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_warning_size(
    model: *mut TfemModel,
    index: c_int,
    size: *mut usize,
) -> Status {
    with_model(model, |m| {
        let w = m.model.warnings();
        let i = warning_index(index, w.len())?;
        write(size, w[i].len() + 1, "size")
    })
}

/// The 0-based index of warning `index` of `n`, or the error naming it.
fn warning_index(index: c_int, n: usize) -> Result<usize> {
    usize::try_from(index)
        .ok()
        .filter(|&i| i < n)
        .ok_or_else(|| {
            Error::argument(format!(
                "warning index {index} is out of range ({n} warnings)"
            ))
        })
}

/// Copies warning number `index` (0-based, whatever the index base) into
/// `buffer` of `length` bytes, truncating like `tfem_last_error`
/// (`tfem_get_warning_size` gives the size needed): the truncated warning
/// is written with TFEM_STATUS_BUFFER_TOO_SMALL; on any other error
/// (an index out of range) `buffer` is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_warning(
    model: *mut TfemModel,
    index: c_int,
    buffer: *mut c_char,
    length: usize,
) -> Status {
    let mut status = Status::Ok;
    let s = with_model(model, |m| {
        let w = m.model.warnings();
        let i = warning_index(index, w.len())?;
        status = copy_message(&w[i], buffer, length);
        match status {
            Status::Ok => Ok(()),
            s => Err(Error::new(
                s,
                "`buffer` is NULL or too short for the warning",
            )),
        }
    });
    if s == Status::Ok { status } else { s }
}

/// Sets the number of threads the model's solves run on: 1 <= `threads`
/// <= 1024 gives the model a pool of its own (1: no parallelism at all, for a
/// host that runs its own OpenMP or MPI threads); 0 (the default) uses
/// the process-wide pool, with as many threads as cores or the
/// environment variable RAYON_NUM_THREADS. Results do not depend on it
/// beyond round-off, and are kept.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_threads(model: *mut TfemModel, threads: c_int) -> Status {
    with_model(model, |m| {
        let n = usize::try_from(threads)
            .map_err(|_| Error::argument(format!("threads = {threads} must be >= 0")))?;
        m.model.set_threads(n)
    })
}

/// Writes the number of threads the model's solves run on (see
/// `tfem_set_threads`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_threads(model: *mut TfemModel, threads: *mut c_int) -> Status {
    with_model(model, |m| {
        let n = c_int::try_from(m.model.threads()).unwrap_or(c_int::MAX);
        write(threads, n, "threads")
    })
}

// -------- Mesh --------------------------------------------------------

/// Sets the mesh: `n_nodes` nodes with coordinates `xy` (2·n_nodes values,
/// x0 y0 x1 y1 …), `n_triangles` P1 triangles with `connectivity`
/// (3·n_triangles node indices) and a body tag per triangle in
/// `body_of_triangle`. `index_base` is 0 (C) or 1 (Fortran) and applies to
/// every index of every later call. Orientation: triangles may be numbered
/// clockwise, counter-clockwise, or both; each connected region of a body
/// is numbered consistently across its shared edges and turned
/// counter-clockwise by area (a warning counts the triangles turned; every
/// later output refers to the turned triangles). A triangle still
/// clockwise then is a fold of the mesh, an inverted element, which TFEM
/// tempers (a warning counts them). Degenerate triangles are legal.
/// Coordinates whose products overflow double precision are refused.
/// Replacing a mesh discards constraints, loads, contact pairs and
/// results; materials and tempering are kept.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_mesh(
    model: *mut TfemModel,
    n_nodes: c_int,
    xy: *const f64,
    n_triangles: c_int,
    connectivity: *const c_int,
    body_of_triangle: *const c_int,
    index_base: c_int,
) -> Status {
    with_model(model, |m| {
        let base = match index_base {
            0 | 1 => index_base as usize,
            _ => {
                return Err(Error::argument(format!(
                    "index_base = {index_base} must be 0 or 1"
                )));
            }
        };
        let nn = count(n_nodes, "n_nodes")?;
        let nt = count(n_triangles, "n_triangles")?;
        let xy = slice_in(xy, 2 * nn, "xy")?;
        let conn = slice_in(connectivity, 3 * nt, "connectivity")?;
        let bodies = slice_in(body_of_triangle, nt, "body_of_triangle")?;
        let nodes = copy_in(xy, 2, "xy", |c| [c[0], c[1]])?;
        let mut tris = reserve(nt, "connectivity")?;
        for (t, c) in conn.chunks_exact(3).enumerate() {
            let mut tri = [0usize; 3];
            for k in 0..3 {
                let v = c[k] as i64 - base as i64;
                if v < 0 || v as usize >= nn {
                    return Err(Error::mesh(format!(
                        "triangle {}: node index {} is out of range ({nn} nodes, index base {base})",
                        t + base,
                        c[k]
                    )));
                }
                tri[k] = v as usize;
            }
            tris.push(tri);
        }
        let bodies = copy_in(bodies, 1, "body_of_triangle", |b| b[0])?;
        let mesh = Mesh::new(nodes, tris, bodies, base)?;
        m.model.set_mesh(mesh);
        m.index_base = base;
        Ok(())
    })
}

/// Loads a Gmsh MSH 4.1 mesh (ASCII or binary) from the file `path`
/// (NUL-terminated; on Unix any bytes, as the file system takes them,
/// elsewhere UTF-8): physical surfaces become bodies (tag = body),
/// physical curves become boundary-edge tags (a curve in several groups
/// under each of their tags; a surface in several is the body of the first,
/// and physical points are not used: a warning names both); only
/// 3-node triangles and 2-node lines, in the plane z = 0. Replaces the
/// mesh like `tfem_set_mesh` with the given `index_base` for later calls:
/// node i is the i-th node of the file's `$Nodes` section, whatever its
/// Gmsh tag (`tfem_get_mesh_nodes`, `tfem_get_mesh_triangles` and
/// `tfem_get_boundary_edges` read the mesh back).
/// Returns TFEM_STATUS_IO for an unreadable or malformed file,
/// TFEM_STATUS_INVALID_MESH for unsupported content: another version of
/// the format (MSH 2.2, 4.0, …; the message says how to convert the file:
/// `gmsh old.msh -save -format msh41 -o new.msh`; TFEM_STATUS_IO in
/// earlier versions), an element type other
/// than those above, a node off the plane, a triangle with a repeated
/// node (an error about an element or a node names its entity and
/// physical group: tag, and name from `$PhysicalNames`);
/// TFEM_STATUS_INVALID_ARGUMENT if the library was built without the
/// `gmsh` feature. On error the model is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_load_gmsh(
    model: *mut TfemModel,
    path: *const c_char,
    index_base: c_int,
) -> Status {
    with_model(model, |m| {
        if path.is_null() {
            return Err(null("path"));
        }
        let base = match index_base {
            0 | 1 => index_base as usize,
            _ => {
                return Err(Error::argument(format!(
                    "index_base = {index_base} must be 0 or 1"
                )));
            }
        };
        // SAFETY: a NUL-terminated string from the caller.
        let path = unsafe { std::ffi::CStr::from_ptr(path) };
        load_gmsh(m, &path_of(path)?, base)
    })
}

/// A C path as a file-system path. On Unix a path is bytes, not text: a
/// file named in Latin-1 (`lat\xe9.msh`) must open as the shell opens it,
/// so the bytes are taken as they are.
#[cfg(unix)]
pub(super) fn path_of(path: &std::ffi::CStr) -> Result<std::path::PathBuf> {
    use std::os::unix::ffi::OsStrExt;
    Ok(std::ffi::OsStr::from_bytes(path.to_bytes()).into())
}

/// A C path as a file-system path: elsewhere than on Unix, UTF-8 text.
#[cfg(not(unix))]
pub(super) fn path_of(path: &std::ffi::CStr) -> Result<std::path::PathBuf> {
    path.to_str()
        .map(Into::into)
        .map_err(|_| Error::argument("path is not valid UTF-8"))
}

#[cfg(feature = "gmsh")]
fn load_gmsh(m: &mut TfemModel, path: &std::path::Path, base: usize) -> Result<()> {
    let mesh = crate::io::gmsh::read_msh(path, base)?;
    m.model.set_mesh(mesh);
    m.index_base = base;
    Ok(())
}

#[cfg(not(feature = "gmsh"))]
fn load_gmsh(_: &mut TfemModel, _: &std::path::Path, _: usize) -> Result<()> {
    Err(Error::argument(
        "this libtfem was built without the `gmsh` feature",
    ))
}

/// Sets the tagged boundary edges: `n_edges` edges given by `edge_nodes`
/// (2·n_edges node indices) with a tag each in `tags`. Tags name the edges
/// for loads, constraints and contact pairs. Replaces previous edges (use
/// `tfem_add_boundary_edges` to add one group at a time). Refused, naming
/// the tag, when a load or contact pair already declared would lose its
/// edges or find them interior (an edge shared by two triangles can carry
/// a constraint, not a load or a contact interface); on any error nothing
/// changes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_boundary_edges(
    model: *mut TfemModel,
    n_edges: c_int,
    edge_nodes: *const c_int,
    tags: *const c_int,
) -> Status {
    with_model(model, |m| {
        let (edges, tags) = edges_in(m, n_edges, edge_nodes, tags)?;
        m.model.set_boundary_edges(&edges, tags)
    })
}

/// The edges (0-based) and tags of a C edge list.
fn edges_in<'t>(
    m: &TfemModel,
    n_edges: c_int,
    edge_nodes: *const c_int,
    tags: *const c_int,
) -> Result<(Vec<[usize; 2]>, &'t [c_int])> {
    let n = m.n_nodes()?;
    let ne = count(n_edges, "n_edges")?;
    let en = slice_in(edge_nodes, 2 * ne, "edge_nodes")?;
    let tags = slice_in(tags, ne, "tags")?;
    let mut edges = reserve(ne, "edge_nodes")?;
    for c in en.chunks_exact(2) {
        edges.push([
            m.index(c[0], n, "edge node")?,
            m.index(c[1], n, "edge node")?,
        ]);
    }
    Ok((edges, tags))
}

/// Adds tagged boundary edges to those already set (see
/// `tfem_set_boundary_edges`): `n_edges` edges given by `edge_nodes`
/// (2·n_edges node indices) with a tag each in `tags`, for instance one
/// call per boundary group. An edge given again with a tag it already has
/// is refused (its loads would count twice); on any error nothing changes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_boundary_edges(
    model: *mut TfemModel,
    n_edges: c_int,
    edge_nodes: *const c_int,
    tags: *const c_int,
) -> Status {
    with_model(model, |m| {
        let (edges, tags) = edges_in(m, n_edges, edge_nodes, tags)?;
        m.model.add_boundary_edges(&edges, tags)
    })
}

/// Sizes: nodes, triangles, and elements of the contact mesh of the last
/// contact solve (0 otherwise). Any pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_sizes(
    model: *mut TfemModel,
    n_nodes: *mut c_int,
    n_triangles: *mut c_int,
    n_contact_elements: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let mesh = m
            .model
            .mesh()
            .ok_or_else(|| Error::state("no mesh: call tfem_set_mesh first"))?;
        let nc = m.model.contact_elements().map(|c| c.len()).unwrap_or(0);
        write_optional(n_nodes, mesh.nodes().len() as c_int);
        write_optional(n_triangles, mesh.triangles().len() as c_int);
        write_optional(n_contact_elements, nc as c_int);
        Ok(())
    })
}

/// Number of boundary edges the model holds (each with its tag), from
/// `tfem_set_boundary_edges` / `tfem_add_boundary_edges` or a Gmsh file's
/// physical lines; see `tfem_get_boundary_edges`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_boundary_edge_count(
    model: *mut TfemModel,
    count: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let mesh = m.mesh()?;
        write(count, mesh.boundary_edges().len() as c_int, "count")
    })
}

/// Copies the node coordinates the model holds (x0 y0 x1 y1 …, 2·n_nodes
/// values, n_nodes from `tfem_get_sizes`) into `xy` of `length` values.
/// After `tfem_load_gmsh` node i (in the model's index base) is the i-th
/// node of the file's `$Nodes` section, whatever its Gmsh tag.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_mesh_nodes(
    model: *mut TfemModel,
    xy: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let mesh = m.mesh()?;
        let v: Vec<f64> = mesh.nodes().iter().flatten().copied().collect();
        copy_out(&v, xy, length, "xy")
    })
}

/// Copies the triangles the model holds (3·n_triangles node indices in the
/// model's index base, n_triangles from `tfem_get_sizes`) into `triangles`
/// of `length` values and each triangle's body tag into `bodies` of
/// `bodies_length` values; `bodies` may be NULL. Triangles given clockwise
/// are held (and copied) counter-clockwise. Nothing is written unless both
/// buffers are large enough.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_mesh_triangles(
    model: *mut TfemModel,
    triangles: *mut c_int,
    length: usize,
    bodies: *mut c_int,
    bodies_length: usize,
) -> Status {
    with_model(model, |m| {
        let mesh = m.mesh()?;
        let b = m.index_base as c_int;
        let n = mesh.triangles().len();
        if !bodies.is_null() && bodies_length < n {
            return Err(too_small("bodies", bodies_length, n));
        }
        let v: Vec<c_int> = mesh
            .triangles()
            .iter()
            .flat_map(|t| t.map(|v| v as c_int + b))
            .collect();
        copy_out(&v, triangles, length, "triangles")?;
        if !bodies.is_null() {
            copy_out(mesh.body_of(), bodies, bodies_length, "bodies")?;
        }
        Ok(())
    })
}

/// Copies the boundary edges the model holds (2·count node indices in the
/// model's index base, count from `tfem_get_boundary_edge_count`) into
/// `edges` of `length` values and each edge's tag into `tags` of
/// `tags_length` values, in the order they were given (a Gmsh file's: its
/// line elements, by physical group); `tags` may be NULL. Nothing is
/// written unless both buffers are large enough.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_boundary_edges(
    model: *mut TfemModel,
    edges: *mut c_int,
    length: usize,
    tags: *mut c_int,
    tags_length: usize,
) -> Status {
    with_model(model, |m| {
        let mesh = m.mesh()?;
        let b = m.index_base as c_int;
        let list = mesh.boundary_edges();
        if !tags.is_null() && tags_length < list.len() {
            return Err(too_small("tags", tags_length, list.len()));
        }
        let v: Vec<c_int> = list
            .iter()
            .flat_map(|e| e.nodes.map(|v| v as c_int + b))
            .collect();
        copy_out(&v, edges, length, "edges")?;
        if !tags.is_null() {
            let t: Vec<c_int> = list.iter().map(|e| e.tag).collect();
            copy_out(&t, tags, tags_length, "tags")?;
        }
        Ok(())
    })
}

// -------- Materials, tempering and ordering ---------------------------

/// Sets the material of body `body`: Young's modulus `young` (> 0), Poisson
/// ratio `poisson` (in (-1, 0.5) for plane strain and axisymmetric bodies,
/// (-1, 0.5] for plane stress) and `plane` (a `PlaneMode`: 0 strain, 1
/// stress, 2 axisymmetric). Axisymmetric bodies (x the radius, y the axis)
/// do not mix with plane ones, lie at x >= 0, need u_r = 0 fixed on nodes
/// on the axis (checked by the solve) and take the whole ring's forces:
/// nodal forces and reactions are totals around the circumference,
/// pressures and tractions per unit area (docs/method.md §7).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_material(
    model: *mut TfemModel,
    body: c_int,
    young: f64,
    poisson: f64,
    plane_mode: c_int,
) -> Status {
    with_model(model, |m| {
        let mat = Material::new(young, poisson, plane(plane_mode)?, &format!("body {body}"))?;
        m.model.set_material(body, mat)
    })
}

/// Chooses Jmin: `mode` is a `TemperingMode` (0 auto, 1 lambda = `value`,
/// 2 fixed Jmin = `value`, 3 off); `value` is ignored for 0 and 3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_tempering(
    model: *mut TfemModel,
    mode: c_int,
    value: f64,
) -> Status {
    with_model(model, |m| {
        let t = match mode {
            0 => Tempering::Auto,
            1 => Tempering::Lambda(value),
            2 => Tempering::Fixed(value),
            3 => Tempering::Off,
            _ => {
                return Err(Error::argument(format!(
                    "tempering mode = {mode} must be 0, 1, 2 or 3"
                )));
            }
        };
        m.model.set_tempering(t)
    })
}

/// Chooses the fill-reducing ordering: `ordering` is an `OrderingMode`
/// (0 auto, 1 AMD, 2 nested dissection); `parallel_subtrees` = 1 (default)
/// factorises the two subtrees of a nested dissection concurrently, 0 as
/// one tree. Results do not depend on either beyond round-off: the results
/// of the last solve (all of them, the matrix included) are kept, and the
/// next solve analyses the matrix anew.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_ordering(
    model: *mut TfemModel,
    ordering: c_int,
    parallel_subtrees: c_int,
) -> Status {
    with_model(model, |m| {
        let ordering = match ordering {
            0 => Ordering::Auto,
            1 => Ordering::Amd,
            2 => Ordering::NestedDissection,
            _ => {
                return Err(Error::argument(format!(
                    "ordering = {ordering} must be 0 (auto), 1 (AMD) or 2 (nested dissection)"
                )));
            }
        };
        let parallel = match parallel_subtrees {
            0 => false,
            1 => true,
            _ => {
                return Err(Error::argument(format!(
                    "parallel_subtrees = {parallel_subtrees} must be 0 or 1"
                )));
            }
        };
        m.model.set_ordering(ordering);
        m.model.set_parallel_subtrees(parallel);
        Ok(())
    })
}

// -------- Loads and constraints ---------------------------------------

/// Prescribes displacement component `component` (0 x, 1 y) of `node` to
/// `value` (model length units). A component already prescribed a
/// different value is refused (TFEM_STATUS_INVALID_ARGUMENT naming the
/// node): one of the two would silently win. Call `tfem_clear_constraints`
/// to change prescribed values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_fix(
    model: *mut TfemModel,
    node: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_model(model, |m| {
        let n = m.n_nodes()?;
        let v = m.index(node, n, "node")?;
        m.model.fix(v, component(comp)?, value)
    })
}

/// Prescribes component `component` to `value` on every node of the
/// boundary edges tagged `tag` (interior edges too). All or nothing: a node
/// already prescribed a different value (see `tfem_fix`) refuses the
/// whole call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_fix_edges(
    model: *mut TfemModel,
    tag: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_model(model, |m| {
        let c = component(comp)?;
        m.model.fix_edges(tag, c, value)
    })
}

/// Changes the value of displacement component `comp` (0 x, 1 y) of
/// `node`, prescribed before by `tfem_fix` or `tfem_fix_edges`: the loads of
/// a non-proportional load history, which goes on with the same
/// factorisation (the set of prescribed DOFs is unchanged). A node not
/// prescribed in that component is refused, naming it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_prescribed(
    model: *mut TfemModel,
    node: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_model(model, |m| {
        let n = m.n_nodes()?;
        let v = m.index(node, n, "node")?;
        m.model.set_prescribed(v, component(comp)?, value)
    })
}

/// Changes the value of displacement component `comp` (0 x, 1 y) on every
/// node of the boundary edges tagged `tag`, each prescribed before by
/// `tfem_fix_edges` or `tfem_fix`: `tfem_set_prescribed` for a whole tag,
/// the loads of a load history given as `tfem_fix_edges` gives them (the
/// factorisation is kept). All or nothing: an unknown tag, a value that is
/// not finite or a node not prescribed in that component is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming it) and the model is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_prescribed_edges(
    model: *mut TfemModel,
    tag: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_model(model, |m| {
        let c = component(comp)?;
        m.model.set_prescribed_edges(tag, c, value)
    })
}

/// Removes every prescribed displacement.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_clear_constraints(model: *mut TfemModel) -> Status {
    with_model(model, |m| {
        m.model.clear_constraints();
        Ok(())
    })
}

/// Declares that the boundary edges tagged `tag` lie on the circle of
/// centre (`center_x`, `center_y`) and radius `radius` (> 0), so that
/// `tfem_solve_adaptive` puts the nodes it adds on those edges on the
/// circle rather than at the chords' midpoints: the refined boundary then
/// converges to the circle (a cylinder's contact, a ring's bore). It
/// replaces a curve declared on the tag before and changes nothing of a
/// solve. Refused, nothing changed, if the circle is ill defined, no edge
/// has the tag, or a node of its edges lies farther than 1e-6·radius from
/// the circle (the message names the node).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_boundary_circle(
    model: *mut TfemModel,
    tag: c_int,
    center_x: f64,
    center_y: f64,
    radius: f64,
) -> Status {
    with_model(model, |m| {
        m.model.set_curve(
            tag,
            Curve::Circle {
                center: [center_x, center_y],
                radius,
            },
        )
    })
}

/// Applies pressure `pressure` on the boundary edges tagged `tag`: a
/// stress (force per unit area, Pa in SI), positive pushing into the body;
/// with the 2D convention of unit thickness, an edge of length ℓ carries
/// the force ℓ·pressure per unit thickness (axisymmetric bodies: the
/// whole ring's, ∫ pressure·2πr ds). Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_pressure(
    model: *mut TfemModel,
    tag: c_int,
    pressure: f64,
) -> Status {
    with_model(model, |m| m.model.add_pressure(tag, pressure))
}

/// Applies the traction (tx, ty) on the boundary edges tagged `tag`: a
/// stress vector (force per unit area, Pa in SI); an edge of length ℓ
/// carries ℓ·(tx, ty) per unit thickness (axisymmetric bodies: the whole
/// ring's, ∫ (tx, ty)·2πr ds). Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_traction(
    model: *mut TfemModel,
    tag: c_int,
    tx: f64,
    ty: f64,
) -> Status {
    with_model(model, |m| m.model.add_traction(tag, [tx, ty]))
}

/// Adds the point force (fx, fy) at `node`: force per unit thickness (N/m
/// in SI; axisymmetric bodies: the total force on the node's ring, N).
/// Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_nodal_force(
    model: *mut TfemModel,
    node: c_int,
    fx: f64,
    fy: f64,
) -> Status {
    with_model(model, |m| {
        let n = m.n_nodes()?;
        let v = m.index(node, n, "node")?;
        m.model.add_nodal_force(v, [fx, fy])
    })
}

/// Sets the body force (bx, by) of body `body`: force per unit volume (ρg,
/// N/m³ in SI), acting on each unit area of the mesh per unit thickness
/// (axisymmetric bodies: on the whole ring's volume).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_body_force(
    model: *mut TfemModel,
    body: c_int,
    bx: f64,
    by: f64,
) -> Status {
    with_model(model, |m| m.model.set_body_force(body, [bx, by]))
}

/// Removes every load.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_clear_loads(model: *mut TfemModel) -> Status {
    with_model(model, |m| {
        m.model.clear_loads();
        Ok(())
    })
}

// -------- Contact pairs -----------------------------------------------

/// Declares a potential contact interface between the boundary edges tagged
/// `tag_a` (one body) and `tag_b` (another body). The contact mesh B is
/// built from matching nodes when they match (a small normal gap is
/// allowed), else by triangulating the strip between the two interfaces
/// (each must be one open chain of edges). Writes the pair's index
/// (0-based) to `pair` (may be NULL). A pair declared already, or one
/// whose tags share boundary edges with both tags of a declared pair (the
/// same interface under other tags, which would count twice), is refused
/// with TFEM_STATUS_INVALID_CONTACT.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_contact_pair(
    model: *mut TfemModel,
    tag_a: c_int,
    tag_b: c_int,
    pair: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let p = m.model.add_contact_pair(tag_a, tag_b)?;
        write_optional(pair, p as c_int);
        Ok(())
    })
}

/// Declares a contact pair with a user-made contact mesh B: `n_triangles`
/// triangles in `connectivity` (3 per triangle) over nodes of the two
/// interfaces. Wrongly oriented triangles are flipped; their number goes to
/// `flipped` (may be NULL), the pair's index to `pair` (may be NULL). A
/// triangle given twice (the same three nodes, in any order) is refused
/// with TFEM_STATUS_INVALID_CONTACT naming both triangles. The triangles
/// are the contact: a pair of tags declared already, or sharing edges with
/// a declared pair, is not refused here (several meshes may cover parts of
/// one interface), so do not give a part twice.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_contact_pair_with_mesh(
    model: *mut TfemModel,
    tag_a: c_int,
    tag_b: c_int,
    n_triangles: c_int,
    connectivity: *const c_int,
    pair: *mut c_int,
    flipped: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let n = m.n_nodes()?;
        let nt = count(n_triangles, "n_triangles")?;
        let conn = slice_in(connectivity, 3 * nt, "connectivity")?;
        let mut tris = reserve(nt, "connectivity")?;
        for c in conn.chunks_exact(3) {
            tris.push([
                m.index(c[0], n, "contact node")?,
                m.index(c[1], n, "contact node")?,
                m.index(c[2], n, "contact node")?,
            ]);
        }
        let (p, f) = m.model.add_contact_pair_with_mesh(tag_a, tag_b, &tris)?;
        write_optional(pair, p as c_int);
        write_optional(flipped, f as c_int);
        Ok(())
    })
}

/// Declares a contact pair for every two boundary tags of different bodies
/// whose edges face each other within `tolerance` (model length units: some
/// edge of the one within `tolerance` of some edge of the other, outward
/// normals opposed within 30°, each in front of the other, overlapping
/// along the interface, no third body between them; a gap of exactly
/// `tolerance` pairs; docs/method.md §6.16). `tags` (`n_tags` values) restricts the search to
/// those tags; with `n_tags` = 0 every tag that can be a contact side is
/// considered, and `tags` may be NULL. Pairs already declared are skipped,
/// tags of one body never pair, and an interface found again under tags
/// that share its edges with a pair kept (a "whole boundary" group beside
/// the faces) is skipped: the pair of tags with the fewest edges is kept
/// (to pair an interface under other tags, declare that pair by hand
/// instead). What is left out without an error — with `n_tags` = 0, a tag
/// whose edges bound several bodies; an interface found again under other
/// tags — is named in a warning (`tfem_warning_count`, `tfem_get_warning`).
/// The pairs added get consecutive indices:
/// writes the first to `first` (may be NULL) and their number, 0 when
/// nothing faces within the tolerance, to `count` (may be NULL). A negative
/// or non-finite tolerance, an unknown tag or an interface whose contact
/// mesh cannot be built is refused, naming it, and nothing is added.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_add_contact_pairs_auto(
    model: *mut TfemModel,
    n_tags: c_int,
    tags: *const c_int,
    tolerance: f64,
    first: *mut c_int,
    count: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let n = usize::try_from(n_tags)
            .map_err(|_| Error::argument(format!("n_tags = {n_tags} must be >= 0")))?;
        let tags = match n {
            0 => None,
            _ => Some(slice_in(tags, n, "tags")?),
        };
        let before = m.model.contact_pairs().len();
        let added = m.model.add_contact_pairs_auto(tags, tolerance)?;
        write_optional(first, before as c_int);
        write_optional(count, added.len() as c_int);
        Ok(())
    })
}

/// Sets Coulomb's friction coefficient μ ≥ 0 of contact pair `pair`
/// (0-based, from `tfem_add_contact_pair`): stick while the shear stays
/// within μ times the pressure, slip against the slip of the step beyond
/// (docs/method.md §6.15). 0, the default, is frictionless, bit for bit.
/// A negative or non-finite μ, or an unknown pair, is refused
/// (TFEM_STATUS_INVALID_ARGUMENT naming it). Changing μ starts a new load
/// history. Frictional or not, the elements of a pair's contact mesh
/// measure every point of the interface along the first side's normal
/// there, so that a frictionless interface transmits no tangential
/// traction.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_friction(model: *mut TfemModel, pair: c_int, mu: f64) -> Status {
    with_model(model, |m| {
        let n = m.model.contact_pairs().len();
        let p = usize::try_from(pair).map_err(|_| crate::error::no_pair(pair, n))?;
        m.model.set_friction(p, mu)
    })
}

/// Chooses how the contact pairs' energy is weighted along their
/// interfaces: `weighting` is a `ContactWeightingMode`. 2 automatic, the
/// default: each pair what is right for it — the elements of the contact
/// mesh B (the seed's method) where the two sides' nodes match, one
/// weighted gap per node of the interface's coarser side where they do not
/// (exact on the contact patch test whatever the meshes, converging on
/// curved interfaces where B reads one side only), B for a pair with
/// friction or a contact mesh of its own. 0 strip and 1 mortar force one
/// weighting on every pair (an expert's override). A change discards the
/// results, like any change of the contact pairs. The mortar weighting is
/// frictionless and makes no mesh B: forcing it with a pair that has
/// friction or a contact mesh of its own, or giving such a pair under it,
/// is refused by that call (TFEM_ERR_ARGUMENT, naming the pair); a solve
/// under it with the stick law or the literal inversion test is refused
/// too. The per-element outputs (`tfem_get_contact_active`,
/// `tfem_get_contact_pressure`, `tfem_get_contact_elements`, shear,
/// friction state, dissipation; `tfem_get_sizes`' contact elements) cover
/// the pairs weighted by B, and are refused when no pair is
/// (`tfem_get_contact_mesh` still gives the B the pairs would make); the
/// state of the others is per slave node (`tfem_get_contact_slave_nodes`).
/// Nodal pressures, gaps and forces, reactions and the report cover every
/// pair, the report's `elements` counting elements of B and slave nodes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_contact_weighting(
    model: *mut TfemModel,
    weighting: c_int,
) -> Status {
    with_model(model, |m| {
        let w = ContactWeighting::from_i32(weighting).ok_or_else(|| {
            Error::argument(format!(
                "weighting = {weighting} must be 0 (strip), 1 (mortar) or 2 (automatic)"
            ))
        })?;
        m.model.set_contact_weighting(w)
    })
}

/// Writes the contact weighting (a `ContactWeightingMode`: 0 strip, 1
/// mortar, 2 automatic, the default) into `*weighting`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_weighting(
    model: *mut TfemModel,
    weighting: *mut c_int,
) -> Status {
    with_model(model, |m| {
        write(weighting, m.model.contact_weighting().to_i32(), "weighting")
    })
}

/// Writes the number of elements of the contact mesh B of the declared
/// contact pairs, available before any solve (0 without pairs).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_mesh_size(
    model: *mut TfemModel,
    n_elements: *mut c_int,
) -> Status {
    with_model(model, |m| {
        write(
            n_elements,
            m.model.contact_mesh()?.len() as c_int,
            "n_elements",
        )
    })
}

/// Copies the nodes of every element of the contact mesh B of the declared
/// contact pairs (3 per element, in the model's index base, oriented so
/// that J > 0 when the gap opens), available before any solve: the same
/// elements, in the same order, as `tfem_get_contact_elements` gives after
/// a contact solve.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_mesh(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let b = m.index_base as c_int;
        let v: Vec<c_int> = m
            .model
            .contact_mesh()?
            .iter()
            .flat_map(|e| e.nodes.map(|n| n as c_int + b))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies, for every element of the contact mesh B (see
/// `tfem_get_contact_mesh`), the index of its contact pair (0-based, as
/// returned by `tfem_add_contact_pair`, whatever the index base).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_element_pairs(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v: Vec<c_int> = m
            .model
            .contact_mesh()?
            .iter()
            .map(|e| e.pair as c_int)
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies, for every element of the contact mesh B (see
/// `tfem_get_contact_mesh`), its apex: the node (in the model's index
/// base) alone on its side of the interface, whose distance from the
/// element's interface edge is the element's gap.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_element_apexes(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let b = m.index_base as c_int;
        let v: Vec<c_int> = m
            .model
            .contact_mesh()?
            .iter()
            .map(|e| e.apex as c_int + b)
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Writes the bodies of contact pair `pair` (0-based, as returned by
/// `tfem_add_contact_pair`): `body_a` carries the pair's first tag,
/// `body_b` its second. Either pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_pair_bodies(
    model: *mut TfemModel,
    pair: c_int,
    body_a: *mut c_int,
    body_b: *mut c_int,
) -> Status {
    with_model(model, |m| {
        let pairs = m.model.contact_pairs();
        let p = usize::try_from(pair)
            .ok()
            .and_then(|i| pairs.get(i))
            .ok_or_else(|| {
                Error::argument(format!(
                    "pair = {pair} is out of range ({} contact pairs, 0-based)",
                    pairs.len()
                ))
            })?;
        let (a, b) = (p.body_a, p.body_b);
        write_optional(body_a, a);
        write_optional(body_b, b);
        Ok(())
    })
}

// -------- Solve -------------------------------------------------------

/// Fills `options` with the defaults: frictionless law, E_c and λ derived
/// from the model, linearised inversion test, 50 iterations.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_contact_options_default(options: *mut TfemContactOptions) -> Status {
    without_model(|| {
        let d = ContactOptions::default();
        write(
            options,
            TfemContactOptions {
                law: d.law as c_int,
                contact_modulus: 0.0,
                lambda: 0.0,
                inversion_test: d.test as c_int,
                max_iterations: d.max_iterations as c_int,
                refactorize: c_int::from(d.refactorize),
            },
            "options",
        )
    })
}

/// Solves a scene without contact. `info` may be NULL. A body that is not
/// restrained gives TFEM_STATUS_SINGULAR naming it. A model with every
/// DOF prescribed has nothing to solve: TFEM_STATUS_INVALID_STATE; so also
/// `tfem_solve_contact` and `tfem_step`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solve(model: *mut TfemModel, info: *mut TfemSolveInfo) -> Status {
    with_model(model, |m| {
        let i = m.model.solve()?;
        write_optional(info, info_out(&i));
        Ok(())
    })
}

/// Solves the contact problem by the active-set loop over inverted contact
/// elements (under the mortar weighting, `tfem_set_contact_weighting`, over
/// the slave nodes whose weighted gap is negative). `options` may be NULL (defaults); `report` may be NULL.
/// TFEM_STATUS_NOT_CONVERGED (cycle or iteration cap) gives the history in
/// the message; the model is then unchanged. Every DOF prescribed:
/// TFEM_STATUS_INVALID_STATE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solve_contact(
    model: *mut TfemModel,
    options: *const TfemContactOptions,
    report: *mut TfemContactReport,
) -> Status {
    with_model(model, |m| {
        // SAFETY: NULL or a caller-owned options struct.
        let opts = match unsafe { options.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        let r = m.model.solve_contact(&opts)?;
        write_optional(report, report_out(&r));
        Ok(())
    })
}

/// Solves to a tolerance (docs/method.md §8): solve (a contact solve with
/// the `contact` options when the model has pairs),
/// estimate the error by stress recovery, refine the triangles holding
/// half of it by newest-vertex bisection, and again, until the estimated
/// relative error of `goal` (an `AdaptGoal`: 0 energy norm, 1 compliance)
/// is at most `tolerance` (> 0) — and, with contact, the edges of the
/// contact zones are located to `tolerance` of the contact length (the
/// interface edges pressed at one end only refined until shorter) — or
/// the next mesh would exceed
/// `max_unknowns`, or `max_cycles` solves are done (either is a warning
/// with the estimate reached, `tfem_get_warning`, and TFEM_STATUS_OK).
/// The model keeps the refined mesh — the given nodes keep their indices,
/// new ones follow; read it back with `tfem_get_sizes`,
/// `tfem_get_mesh_nodes`, `tfem_get_mesh_triangles` and
/// `tfem_get_boundary_edges` — its loads, constraints and pairs carried
/// over, and the last solve's results. New nodes on edges whose tag has
/// a circle (`tfem_set_boundary_circle`) go on the circle, and a curved
/// interface's facing edges are bisected together. `contact` may be NULL (the default
/// options); `report` may be NULL. Bad arguments change nothing; a failed
/// solve restores the model as it was given.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solve_adaptive(
    model: *mut TfemModel,
    tolerance: f64,
    goal: c_int,
    max_unknowns: i64,
    max_cycles: c_int,
    contact: *const TfemContactOptions,
    report: *mut TfemAdaptReport,
) -> Status {
    with_model(model, |m| {
        let goal = match goal {
            g if g == AdaptGoal::Energy as c_int => Goal::Energy,
            g if g == AdaptGoal::Compliance as c_int => Goal::Compliance,
            g => {
                return Err(Error::argument(format!(
                    "goal = {g} must be 0 (energy) or 1 (compliance)"
                )));
            }
        };
        let positive = |v: i64, what: &str| {
            usize::try_from(v)
                .ok()
                .filter(|&v| v > 0)
                .ok_or_else(|| Error::argument(format!("{what} = {v} must be at least 1")))
        };
        // SAFETY: NULL or a caller-owned options struct.
        let contact = match unsafe { contact.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        let options = AdaptOptions {
            tolerance,
            goal,
            max_unknowns: positive(max_unknowns, "max_unknowns")?,
            max_cycles: positive(i64::from(max_cycles), "max_cycles")?,
            contact,
            ..AdaptOptions::default()
        };
        let r = m.model.solve_adaptive(&options)?;
        let last = r.cycles.last().copied();
        write_optional(
            report,
            TfemAdaptReport {
                cycles: r.cycles.len() as c_int,
                reached: c_int::from(r.reached),
                unknowns: last.map_or(0, |c| c.unknowns as i64),
                triangles: last.map_or(0, |c| c.triangles as i64),
                estimate: last.map_or(f64::NAN, |c| c.estimate),
                seconds: r.seconds,
            },
        );
        m.adapt = r.cycles;
        Ok(())
    })
}

/// Copies each cycle of the last successful `tfem_solve_adaptive`
/// (`cycles` of its report): its unknowns, its estimated relative error and its seconds
/// (solve and estimate), into arrays of `length` values each: `unknowns`
/// may be NULL, `estimates` may be NULL, `seconds` may be NULL. Nothing is
/// written unless `length` holds every cycle.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_adapt_cycles(
    model: *mut TfemModel,
    unknowns: *mut i64,
    estimates: *mut f64,
    seconds: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        if m.adapt.is_empty() {
            return Err(Error::state(
                "no adaptive solve: call tfem_solve_adaptive first",
            ));
        }
        let n: Vec<i64> = m.adapt.iter().map(|c| c.unknowns as i64).collect();
        let e: Vec<f64> = m.adapt.iter().map(|c| c.estimate).collect();
        let t: Vec<f64> = m.adapt.iter().map(|c| c.seconds).collect();
        if length < n.len() {
            return Err(Error::new(
                Status::BufferTooSmall,
                format!("length = {length}: {} values are needed", n.len()),
            ));
        }
        if !unknowns.is_null() {
            copy_out(&n, unknowns, length, "unknowns")?;
        }
        if !estimates.is_null() {
            copy_out(&e, estimates, length, "estimates")?;
        }
        if !seconds.is_null() {
            copy_out(&t, seconds, length, "seconds")?;
        }
        Ok(())
    })
}

// -------- Results -----------------------------------------------------

/// Copies the nodal displacements (u0 v0 u1 v1 …, 2·n_nodes values) of the
/// last solve into `out` of `length` values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_displacements(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let u: Vec<f64> = m.model.displacements()?.into_iter().flatten().collect();
        copy_out(&u, out, length, "out")
    })
}

/// Copies element strains (ε_xx ε_yy γ_xy per triangle, engineering shear,
/// 3·n_triangles values), computed on request.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_element_strains(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v: Vec<f64> = m.model.element_strains()?.into_iter().flatten().collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies element stresses (σ_xx σ_yy σ_xy per triangle, 3·n_triangles
/// values; force per unit area, Pa in SI), computed on request. An
/// overflow gives TFEM_STATUS_NUMERICAL_FAILURE naming the triangle.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_element_stresses(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v: Vec<f64> = m.model.element_stresses()?.into_iter().flatten().collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies each triangle's stress normal to the mesh's plane (n_triangles
/// values), computed on request: the hoop stress σ_θθ of axisymmetric
/// bodies, σ_zz = λ(ε_xx + ε_yy) in plane strain, 0 in plane stress.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_element_out_of_plane_stresses(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(
            &m.model.element_out_of_plane_stresses()?,
            out,
            length,
            "out",
        )
    })
}

/// Copies J (twice the signed area, initial configuration) of every
/// triangle as stored, that is after the turning of triangles numbered
/// clockwise (see `tfem_set_mesh`): negative only for the mesh's folds
/// (n_triangles values). Needs only a mesh.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_element_jacobians(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v = m.model.element_jacobians()?;
        copy_out(&v, out, length, "out")
    })
}

/// Copies reaction forces (Rx Ry per node, 2·n_nodes values; force per
/// unit thickness, N/m in SI; zero at DOFs that are not prescribed),
/// computed on request. `tfem_solve` and `tfem_solve_contact` bound their
/// rounding per body and warn (`tfem_get_warning`), naming the body, where
/// its reactions may carry fewer than six correct digits (a "rigid" body
/// given a huge Young's modulus: prescribe its motion with a modulus like
/// its neighbours' instead).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_reactions(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v: Vec<f64> = m.model.reactions()?.into_iter().flatten().collect();
        copy_out(&v, out, length, "out")
    })
}

/// Writes the work of the external loads of the last solve, Σ f·u over
/// every node (force × length per unit thickness, J/m in SI; axisymmetric
/// bodies: the whole ring's, J): for a pressure load, the compliance
/// ∫ p (−u·n) ds.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_external_work(model: *mut TfemModel, work: *mut f64) -> Status {
    with_model(model, |m| write(work, m.model.external_work()?, "work"))
}

/// Writes the solved model to the file `path` (NUL-terminated; on Unix any
/// bytes, as for `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`,
/// read by ParaView, VTK and meshio; binary: raw appended data,
/// little-endian, UInt64 block headers, no compression):
/// the mesh in its initial configuration (z = 0) with
/// - point data `displacement` ([u, v, 0]) and, after a contact solve or
///   load step under either weighting, `contact_pressure` (the nodal
///   pressure of `tfem_get_contact_nodal_pressures`), `contact_shear`
///   (the nodal shear of `tfem_get_contact_nodal_tractions`),
///   `contact_force` ([f_x, f_y, 0], `tfem_get_contact_forces`) and
///   `contact_gap` (`tfem_get_contact_gaps`); none of them after a solve
///   without contact;
/// - cell data `body` (the body tag), `J` (twice the signed area), `strain`
///   [ε_xx, ε_yy, γ_xy] and `stress` [σ_xx, σ_yy, σ_xy];
/// - for the pairs weighted by B, its elements
///   appended after the body triangles as cells of body −1 (zero strain
///   and stress), with cell data `contact_element_active` (UInt8, 1 where
///   active) and `contact_element_pressure` (`tfem_get_contact_active`,
///   `tfem_get_contact_pressure`; 0 on the body triangles). Pairs under
///   the mortar weighting have no B: their contact is in the nodal arrays.
///
/// (Earlier versions named the last two `contact_active` and
/// `contact_pressure`, wrote them as zeros under the mortar weighting,
/// and wrote no nodal contact array.)
/// Returns TFEM_STATUS_INVALID_STATE before a solve (nothing is written),
/// TFEM_STATUS_IO when the file cannot be written (the message names it
/// and the reason), TFEM_STATUS_INVALID_ARGUMENT if the library was built
/// without the `vtu` feature, and TFEM_STATUS_NUMERICAL_FAILURE (nothing
/// is written) when a result it holds cannot be computed as the accessors
/// would refuse it: an overflowing stress, or a load step's field that
/// cannot be recovered to working accuracy, named in the message. The
/// model is never changed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_write_vtu(model: *mut TfemModel, path: *const c_char) -> Status {
    with_model(model, |m| {
        if path.is_null() {
            return Err(null("path"));
        }
        // SAFETY: a NUL-terminated string from the caller.
        let path = unsafe { std::ffi::CStr::from_ptr(path) };
        write_vtu(m, &path_of(path)?)
    })
}

#[cfg(feature = "vtu")]
fn write_vtu(m: &TfemModel, path: &std::path::Path) -> Result<()> {
    crate::io::vtu::write_vtu(&m.model, path)
}

#[cfg(not(feature = "vtu"))]
fn write_vtu(_: &TfemModel, _: &std::path::Path) -> Result<()> {
    Err(Error::argument(
        "this libtfem was built without the `vtu` feature",
    ))
}

// -------- Contact results ---------------------------------------------

/// Writes the report of the last contact solve to `report`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_report(
    model: *mut TfemModel,
    report: *mut TfemContactReport,
) -> Status {
    with_model(model, |m| {
        write(report, report_out(m.model.contact_report()?), "report")
    })
}

/// Copies the force the contact exerts on every node in the last contact
/// solve (fx fy per node, 2·n_nodes values; force per unit thickness, N/m
/// in SI, or the whole ring's for axisymmetric bodies; zero off the
/// contact interfaces), computed on request. The
/// forces of one pair sum to zero; on a body they balance its loads and
/// reactions.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_forces(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let v: Vec<f64> = m.model.contact_forces()?.into_iter().flatten().collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the contact pressure at every node in the last contact solve
/// (n_nodes values; force per unit area, Pa in SI, positive in compression;
/// zero off the contact interfaces), computed on request: the traction
/// read from both sides of the interface (the mean of a node's normal
/// contact force over its tributary — the integral of its hat over its
/// interface edges as far as they face the other side, half its edges
/// where they face it whole — and the other side's forces over their
/// tributaries near it); where the other side is more than 1.8 times
/// coarser, a node takes the other side's reading there, interpolated
/// (the coarser side's reading is the closer to the traction), blended
/// with its own from 1.2 times. Exact for a
/// uniform pressure on matching and non-matching interfaces alike. Each
/// pair is read with its own forces; a node on several pairs (where three
/// bodies meet) gets their normal
/// forces over their tributaries together: the pressure where two pairs
/// continue one face, the tributary-weighted mean of its faces' pressures
/// at a corner.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_nodal_pressures(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(&m.model.contact_nodal_pressures()?, out, length, "out")
    })
}

/// Copies the contact traction at every node in the last contact solve or
/// step, as (p, τ) per node (2·n_nodes values; force per unit area, Pa in
/// SI; zero off the contact interfaces), computed on request. p is the
/// pressure of `tfem_get_contact_nodal_pressures`, positive in
/// compression. τ is the tangential traction the other body exerts on the
/// node's body, along t = (−n_y, n_x) with n the body's outward normal
/// (the direction of travel along a counter-clockwise boundary), so that
/// both sides of an interface read one traction with one sign; the vector
/// traction on the node's body is τ t − p n. Each part is the contact
/// law's own, read along the normal the contact mesh measures the point
/// along (one per point of the interface: its first side's): a
/// frictionless interface reads τ = 0 to round-off, curved or not, and a
/// frictional one its Coulomb shear. Pairs under the mortar weighting
/// (frictionless) read τ = 0. Before a contact solve, or after a change,
/// there are no results (TFEM_STATUS_INVALID_STATE).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_nodal_tractions(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let t: Vec<f64> = m
            .model
            .contact_nodal_tractions()?
            .into_iter()
            .flatten()
            .collect();
        copy_out(&t, out, length, "out")
    })
}

/// Copies the contact pressure of contact pair `pair` (0-based, from
/// `tfem_add_contact_pair` or `tfem_add_contact_pairs_auto`) alone at every
/// node in the last contact solve (n_nodes values, as
/// `tfem_get_contact_nodal_pressures`; zero off that pair's contact
/// mesh), computed on request from that pair's forces over that pair's
/// tributaries: a node where three bodies meet reads each face on its own
/// (at a block's corner, the bed's pressure on the bed pair and the head
/// joint's on the head pair), where `tfem_get_contact_nodal_pressures`
/// gives their tributary-weighted mean. As there, where one side ends
/// inside an edge of the other, the first node of the other side past
/// that end reads the other side's pressure near that end.
/// An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT naming it);
/// before a contact solve, or after a change (declaring a pair is one),
/// there are no results (TFEM_STATUS_INVALID_STATE).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_pair_nodal_pressures(
    model: *mut TfemModel,
    pair: c_int,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let n = m.model.contact_pairs().len();
        let p = usize::try_from(pair).map_err(|_| crate::error::no_pair(pair, n))?;
        copy_out(
            &m.model.contact_pair_nodal_pressures(p)?,
            out,
            length,
            "out",
        )
    })
}

/// `tfem_get_contact_nodal_tractions` of contact pair `pair` (0-based)
/// alone, read over that pair's forces and tributaries as
/// `tfem_get_contact_pair_nodal_pressures` reads its pressures (2·n_nodes
/// values). An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT
/// naming it).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_pair_nodal_tractions(
    model: *mut TfemModel,
    pair: c_int,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let n = m.model.contact_pairs().len();
        let p = usize::try_from(pair).map_err(|_| crate::error::no_pair(pair, n))?;
        let t: Vec<f64> = (m.model.contact_pair_nodal_tractions(p)?.into_iter())
            .flatten()
            .collect();
        copy_out(&t, out, length, "out")
    })
}

/// Copies the normal gap at every node in the last contact solve
/// (n_nodes values, model length units; zero off the contact interfaces),
/// computed on request: the smallest, over the contact elements at the
/// node, of the distance of an element's apex from its interface edge in
/// the deformed configuration (linearised). Positive: open; negative: the
/// bodies interpenetrate (by O(h²), the penalty of the contact elements).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_gaps(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(&m.model.contact_gaps()?, out, length, "out")
    })
}

/// Copies the active flag (1 active, 0 not) of every contact element of
/// the last contact solve (n_contact_elements values, see `tfem_get_sizes`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_active(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        map_out(m.model.contact_active()?, out, length, "out", c_int::from)
    })
}

/// Copies the contact pressure of every contact element (n_contact_elements
/// values): the normal stress −n·σ·n in the element (force per unit area,
/// Pa in SI), positive in compression, 0 when inactive. It is the
/// traction at the element's apex (the interface point it measures:
/// on matching meshes the apex node), times the share of its edge that
/// faces the other side; each point is measured by two elements, one
/// with its edge on either side. For the traction at the interface
/// nodes, read `tfem_get_contact_nodal_tractions` (on a non-matching
/// interface one family's element values read up to twice the traction).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_pressure(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(m.model.contact_pressure()?, out, length, "out")
    })
}

/// Copies the nodes of every contact element (3·n_contact_elements
/// indices, in the model's index base), oriented so that J > 0 when the gap
/// opens. Refused (TFEM_STATUS_INVALID_STATE) after a solve under
/// the mortar weighting, which uses no B.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_elements(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let b = m.index_base as c_int;
        let v: Vec<c_int> = m
            .model
            .contact_elements()?
            .iter()
            .flat_map(|e| e.nodes.map(|n| n as c_int + b))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the shear traction τ = n·σ·t (Pa in SI; t = (−n_y, n_x), n the
/// element's normal, see `tfem_get_contact_mesh`) of every contact element
/// of the last contact solve or step (n_contact_elements values): 0 when
/// open, |τ| ≤ μp when sticking, μp when slipping; all 0 when frictionless.
/// An element value at its apex, as `tfem_get_contact_pressure`; the
/// shear at the interface nodes is `tfem_get_contact_nodal_tractions`'.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_shear(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(&m.model.contact_shear()?, out, length, "out")
    })
}

/// Copies the frictional state of every contact element of the last
/// contact solve or step (n_contact_elements values): 0 open, 1 stick,
/// 2 slip (a frictionless solve: 2 where active).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_friction_state(
    model: *mut TfemModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let state = m.model.contact_friction_state()?;
        map_out(&state, out, length, "out", c_int::from)
    })
}

/// Copies the energy dissipated by slip in the last step (or solve) at
/// every contact element (n_contact_elements values, J per unit thickness
/// in SI; for axisymmetric bodies per unit length of the element's ring,
/// 2πr̄ times less than the whole ring's): ½ τ Δγ_p ≥ 0; all 0 when frictionless.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_dissipation(
    model: *mut TfemModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        copy_out(&m.model.contact_dissipation()?, out, length, "out")
    })
}

/// Copies the state of every slave node after a contact solve under the
/// mortar weighting, n = the report's `elements`, in the order of the
/// pairs: `node` (n values: the slave node, in the model's index base),
/// `tributary` (n values: m_i, the length its hat covers where it faces
/// the other side), `gap` (n values: the mean gap G_i/m_i, negative where
/// the bodies overlap) and `pressure` (n values: −κG_i/m_i, positive in
/// compression, 0 when inactive; an active node whose weighted gap is at
/// the round-off of the displacements, as where the bodies touch without
/// load, can read a pressure of that round-off of either sign). Any pointer may be NULL (that column is
/// not written); `length` (>= n) is the size of each buffer given. Refused
/// after a solve under the strip weighting.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_slave_nodes(
    model: *mut TfemModel,
    node: *mut c_int,
    tributary: *mut f64,
    gap: *mut f64,
    pressure: *mut f64,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let slaves = m.model.contact_slave_nodes()?;
        if length < slaves.len() {
            return Err(Error::new(
                Status::BufferTooSmall,
                format!(
                    "length = {length} is smaller than the {} slave nodes",
                    slaves.len()
                ),
            ));
        }
        let base = m.index_base;
        let names = slaves
            .iter()
            .map(|s| c_int::try_from(s.node + base))
            .collect::<std::result::Result<Vec<c_int>, _>>()
            .map_err(|_| Error::argument("a slave node's number does not fit in an int"))?;
        if !node.is_null() {
            copy_out(&names, node, length, "node")?;
        }
        let column = |out: *mut f64, f: fn(&SlaveNode) -> f64| -> Result<()> {
            if out.is_null() {
                return Ok(());
            }
            let v: Vec<f64> = slaves.iter().map(f).collect();
            copy_out(&v, out, length, "slave node values")
        };
        column(tributary, |s| s.tributary)?;
        column(gap, |s| s.gap)?;
        column(pressure, |s| s.pressure)?;
        Ok(())
    })
}

// -------- Load history ------------------------------------------------

/// One quasi-static load step: the contact problem with the loads and
/// prescribed displacements as set, scaled by `load_factor`, warm-started
/// from the contact state of the last step (the initial set of a contact
/// solve for the first, or a state given by `tfem_set_contact_state`).
/// One factorisation serves every step while the stiffness (mesh,
/// constraints, materials, tempering, contact pairs) and the contact
/// options (`options` may be NULL: defaults; `max_iterations` may change)
/// are unchanged: a step is dense work on the contact interface, plus one
/// sparse solve when the loads changed since the last step (a
/// non-proportional history). Its displacements, and everything computed
/// from them, are recovered on first request (one sparse solve, or, where
/// that cannot reach working accuracy on a very non-matching interface, a
/// factorisation of the step's own matrix, made and dropped at that
/// request); the system matrix of a step is not available. The step is
/// accepted as it is: `tfem_revert_step` undoes it. `report` may be NULL.
/// Where the contact interface is not condensed (options with
/// `refactorize` set, an interface too large to condense — see
/// `TfemContactOptions` —, or a contact that couples no free unknown)
/// each step is a contact solve of its scaled loads started from the state
/// of the step before. A warm start that leads nowhere (a body left free:
/// unloading to zero from a loaded set passes through no contact at all;
/// a cycle) is tried again from the initial set of the step's own loads.
/// `load_factor` must be finite, at most 1e300 in magnitude, and a step
/// whose field would overflow is refused (TFEM_STATUS_NUMERICAL_FAILURE).
/// On error the model is unchanged. A frictional history goes on from the
/// slip state it reached across a change of materials, options or
/// prescribed DOFs between steps (with friction the answer depends on the
/// path). Every DOF prescribed: TFEM_STATUS_INVALID_STATE. Under the
/// mortar weighting (`tfem_set_contact_weighting`, frictionless) a step is
/// the same history over the slave nodes' weighted gaps.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_step(
    model: *mut TfemModel,
    load_factor: f64,
    options: *const TfemContactOptions,
    report: *mut TfemContactReport,
) -> Status {
    with_model(model, |m| {
        // SAFETY: NULL or a caller-owned options struct.
        let opts = match unsafe { options.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        let r = m.model.step(load_factor, &opts)?;
        write_optional(report, report_out(&r));
        Ok(())
    })
}

/// Undoes the last load step: its results, and the contact state the next
/// step starts from, go back to what they were before it. Once per step.
/// Refused with TFEM_STATUS_INVALID_STATE, the model unchanged, once the
/// mesh, its boundary edges, the contact pairs, friction on/off or the
/// contact weighting have changed since that step: they remake the
/// contact mesh, and its contact state belongs to the one before; the
/// message names the change. Fixing
/// or clearing prescribed DOFs does not block it: like new materials, it
/// changes the stiffness, not the contact mesh. The state brought back is
/// the next step's start even if that step starts a new history (new
/// materials, options or prescribed DOFs), with that problem's own
/// interface factor.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_revert_step(model: *mut TfemModel) -> Status {
    with_model(model, |m| m.model.revert_step())
}

/// Writes to `size` the number of bytes of the contact state of the last
/// load step (see `tfem_get_contact_state`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_state_size(
    model: *mut TfemModel,
    size: *mut usize,
) -> Status {
    with_model(model, |m| {
        write(size, m.model.contact_state()?.len(), "size")
    })
}

/// Copies the contact state of the last load step into `buffer` (`length`
/// bytes, at least `tfem_get_contact_state_size`): the active set and the
/// factor of the condensed interface system, so that
/// `tfem_set_contact_state` continues the history bit for bit (a restart,
/// in this model or another one holding the same problem). Under the mortar
/// weighting the set is the slave nodes'.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_contact_state(
    model: *mut TfemModel,
    buffer: *mut u8,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let state = m.model.contact_state()?;
        // The state is counted in bytes, not values (an outside probe read
        // "holds 10 values but 19473 are needed").
        if !buffer.is_null() && length < state.len() {
            return Err(Error::new(
                Status::BufferTooSmall,
                format!(
                    "`buffer` holds {length} bytes but {} are needed (tfem_get_contact_state_size)",
                    state.len()
                ),
            ));
        }
        copy_out(&state, buffer, length, "buffer")
    })
}

/// Continues the load history from a contact state (`length` bytes from
/// `tfem_get_contact_state`): the next `tfem_step` starts from it. Refused,
/// naming why, if the bytes are not such a state, belong to another
/// contact mesh, or are frictional where no pair has friction; the model
/// is then unchanged. From a history of the same problem (the same
/// geometry, materials, constraints and options) the steps go on bit for
/// bit; from one whose interface system differs (the same contact mesh,
/// another shape or stiffness), from its active set and slip state, with
/// the interface factor of this problem; so also when the next step
/// starts a new history (new materials, options or prescribed DOFs). If
/// the mesh, its boundary edges, the pairs or friction on/off change
/// before the next step (they remake the contact mesh), that step starts
/// afresh and warns; a change of the prescribed DOFs keeps it. A
/// frictional state waiting for a step under the stick law is refused by
/// that step (TFEM_STATUS_INVALID_ARGUMENT) until another state is set.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_set_contact_state(
    model: *mut TfemModel,
    buffer: *const u8,
    length: usize,
) -> Status {
    with_model(model, |m| {
        let bytes = slice_in(buffer, length, "buffer")?;
        m.model.set_contact_state(bytes)
    })
}

// -------- Utilities ---------------------------------------------------

/// Sizes of the stiffness matrix of the last solve (see
/// `tfem_get_system_matrix`): `n` unknowns and `nnz` stored entries of its
/// upper triangle. Either pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_get_system_matrix_size(
    model: *mut TfemModel,
    n: *mut i64,
    nnz: *mut i64,
) -> Status {
    with_model(model, |m| {
        let k = m.model.system_matrix()?;
        write_optional(n, k.n() as i64);
        write_optional(nnz, k.values.len() as i64);
        Ok(())
    })
}

/// Copies the stiffness matrix K of the last solve on its unknowns (the
/// DOFs left after Dirichlet elimination), the system K u = f whose
/// solution `tfem_get_displacements` returns; for a contact solve it holds
/// the contact elements active at convergence. Upper triangle in
/// compressed sparse columns, rows ascending within each column:
/// `col_ptr` (n + 1 values), `row_idx` and `values` (nnz values each),
/// indices in the model's index base (`col_ptr[0]` = base). `dofs` (n
/// values) gives each unknown's position in the array of
/// `tfem_get_displacements`, in the index base (2·node + component for
/// base 0). Every buffer is checked before any is written. Like every
/// result it outlives a failed solve (which rebuilds it bit for bit) and
/// is discarded by a change of the problem (TFEM_STATUS_INVALID_STATE).
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn tfem_get_system_matrix(
    model: *mut TfemModel,
    col_ptr: *mut i64,
    col_ptr_length: usize,
    row_idx: *mut i64,
    row_idx_length: usize,
    values: *mut f64,
    values_length: usize,
    dofs: *mut i64,
    dofs_length: usize,
) -> Status {
    with_model(model, |m| {
        let k = m.model.system_matrix()?;
        let (n, nnz) = (k.n(), k.values.len());
        for (ptr, len, need, what) in [
            (col_ptr.is_null(), col_ptr_length, n + 1, "col_ptr"),
            (row_idx.is_null(), row_idx_length, nnz, "row_idx"),
            (values.is_null(), values_length, nnz, "values"),
            (dofs.is_null(), dofs_length, n, "dofs"),
        ] {
            if ptr {
                return Err(null(what));
            }
            if len < need {
                return Err(Error::new(
                    Status::BufferTooSmall,
                    format!("`{what}` holds {len} values but {need} are needed"),
                ));
            }
        }
        let b = m.index_base as i64;
        let based = |i: usize| i as i64 + b;
        map_out(k.col_ptr, col_ptr, col_ptr_length, "col_ptr", based)?;
        map_out(k.row_idx, row_idx, row_idx_length, "row_idx", based)?;
        copy_out(k.values, values, values_length, "values")?;
        map_out(k.unknowns, dofs, dofs_length, "dofs", based)
    })
}

/// Tempered elasticity stiffness of one P1 triangle with corners `xy`
/// (x1 y1 x2 y2 x3 y3): K = B̂ᵀ D B̂ / (2·max(J, jmin)), written row-major
/// into `out` (36 values, DOFs u1 v1 u2 v2 u3 v3). For
/// `TFEM_PLANE_MODE_AXISYMMETRIC` (x the radius, corners with x ≥ 0) the
/// whole ring's K = 2πx̄ (B̂ + J H)ᵀ D₄ (B̂ + J H) / (2·max(J, jmin)), H
/// the hoop row 1/(3x̄) on each u_r (docs/method.md §7). `jmin` > 0
/// tempers; `jmin` = 0 is plain FEM (divides by |J|, fails for J = 0).
/// Pure and thread-safe; errors go to the thread's `tfem_last_error(NULL,
/// …)`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_element_stiffness(
    xy: *const f64,
    young: f64,
    poisson: f64,
    plane_mode: c_int,
    jmin: f64,
    out: *mut f64,
) -> Status {
    without_model(|| {
        let x = corners_arg(xy)?;
        let mat = Material::new(young, poisson, plane(plane_mode)?, "element")?;
        let section = mat.section();
        if let Some(c) = (0..3).find(|&c| section.is_revolution() && x[c][0] < 0.0) {
            return Err(Error::argument(format!(
                "corner {} has x = {} < 0: an axisymmetric element lies at x >= 0 (x is \
                 the radius)",
                c + 1,
                x[c][0]
            )));
        }
        let k = section_stiffness(&x, &mat.d_matrix(), section, jmin_arg(jmin)?)?;
        let flat: Vec<f64> = k.iter().flatten().copied().collect();
        copy_out(&flat, out, 36, "out")
    })
}

/// Tempered Laplacian stiffness of one P1 triangle: K_ij = κ g_i·g_j /
/// (2·max(J, jmin)), row-major into `out` (9 values). `jmin` as in
/// `tfem_element_stiffness`. Pure and thread-safe.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_laplacian_stiffness(
    xy: *const f64,
    kappa: f64,
    jmin: f64,
    out: *mut f64,
) -> Status {
    without_model(|| {
        let x = corners_arg(xy)?;
        if !(kappa.is_finite() && kappa > 0.0) {
            return Err(Error::argument(format!(
                "kappa = {kappa:?} must be finite and > 0"
            )));
        }
        let k = laplacian_stiffness(&TriGeometry::new(&x), kappa, jmin_arg(jmin)?)?;
        let flat: Vec<f64> = k.iter().flatten().copied().collect();
        copy_out(&flat, out, 9, "out")
    })
}
