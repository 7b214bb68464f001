//! The entry points of the C ABI for the 3D model
//! ([`crate::model::solid::SolidModel`]): a third handle,
//! `tfem_solid_model`, beside `tfem_model` and `tfem_contact`, with the
//! same conventions (statuses, messages naming the item, index base, outputs
//! written only on success, a failed call leaving the model as it was).
//! The 3D model is a separate type in Rust, so it is a separate handle here
//! rather than a mode of `tfem_model`: a 2D function given a 3D handle (or
//! the other way round) is refused by the live-handle check instead of
//! reading the wrong type.

use std::collections::BTreeSet;
use std::ffi::{c_char, c_int};

use super::convert::{TfemContactOptions, TfemSolveInfo, info_out, options_in};
use super::entry::path_of;
use super::plumbing::{
    Handle, check_live, copy_in, copy_message, copy_out, count, guarded, map_out, null, register,
    reserve, slice_in, too_small, unregister, with_handle, write, write_optional,
};
use crate::contact::ContactOptions;
use crate::error::{Error, Result, Status, ensure_finite};
use crate::fem::element::Tempering;
use crate::fem::solid_mesh::SolidMesh;
use crate::linalg::Ordering;
use crate::model::solid::{Axis, SolidMaterial, SolidModel};

/// A displacement component in space (argument `comp` of `tfem_solid_fix`
/// and `tfem_solid_fix_faces`): the 2D `tfem_component` has no z, and its
/// values must keep their meaning, so 3D has its own.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolidAxis {
    /// u_x.
    X = 0,
    /// u_y.
    Y = 1,
    /// u_z.
    Z = 2,
}

/// Opaque handle to a 3D model. Create with `tfem_solid_create`, free with
/// `tfem_solid_destroy`.
pub struct TfemSolidModel {
    model: SolidModel,
    index_base: usize,
    last_error: String,
    /// The bodies given a material: the Rust model keeps its materials to
    /// itself, and a solve missing one must be refused as
    /// TFEM_STATUS_INVALID_MATERIAL naming the body, as in 2D.
    materials: BTreeSet<i32>,
    /// Whether constraints or loads name the current faces: replacing the
    /// faces rebuilds the mesh, which would silently drop them.
    constrained: bool,
    loaded: bool,
}

impl Handle for TfemSolidModel {
    const ARGUMENT: &'static str = "model";
    const KIND: &'static str = "a 3D model (from tfem_solid_create)";
    fn last_error(&mut self) -> &mut String {
        &mut self.last_error
    }
}

fn with_solid(
    model: *mut TfemSolidModel,
    f: impl FnOnce(&mut TfemSolidModel) -> Result<()>,
) -> Status {
    with_handle(model, f)
}

impl TfemSolidModel {
    /// The mesh, or INVALID_STATE when none is set (the Rust model's own
    /// refusal is an argument error; the C API's convention is a state).
    fn mesh(&self) -> Result<&SolidMesh> {
        self.model.mesh().ok_or_else(|| {
            Error::state("no mesh: call tfem_solid_set_mesh or tfem_solid_load_gmsh first")
        })
    }

    fn n_nodes(&self) -> Result<usize> {
        self.mesh().map(|m| m.nodes().len())
    }

    /// A node index of the caller's base as 0-based, or the error naming it.
    fn node(&self, i: c_int) -> Result<usize> {
        let n = self.n_nodes()?;
        let b = self.index_base as i64;
        let v = i64::from(i) - b;
        if v < 0 || v as usize >= n {
            return Err(Error::argument(format!(
                "node {i} is out of range ({n} available, index base {b})"
            )));
        }
        Ok(v as usize)
    }

    /// Refuses result queries before a solve with INVALID_STATE, as the 2D
    /// API does (the Rust model's refusal is an argument error).
    fn solved(&self) -> Result<()> {
        self.mesh()?;
        self.model.solve_info().map(|_| ()).map_err(|_| {
            Error::state(
                "no solution: call tfem_solid_solve or tfem_solid_solve_contact first (any \
                 change of the problem discards it)",
            )
        })
    }

    /// The checks the C API makes before a solve: a mesh, and a material
    /// for every body (TFEM_STATUS_INVALID_MATERIAL naming the first
    /// without).
    fn ready(&self) -> Result<()> {
        let mesh = self.mesh()?;
        if let Some(b) = mesh.bodies().iter().find(|b| !self.materials.contains(b)) {
            return Err(Error::new(
                Status::InvalidMaterial,
                format!("body {b} has no material: call tfem_solid_set_material first"),
            ));
        }
        Ok(())
    }

    /// Takes `mesh` with its index base; everything that named the old
    /// mesh's nodes and faces goes with it (the Rust model clears them).
    fn replace_mesh(&mut self, mesh: SolidMesh, base: usize) {
        self.model.set_mesh(mesh);
        self.index_base = base;
        self.constrained = false;
        self.loaded = false;
    }
}

fn base_arg(index_base: c_int) -> Result<usize> {
    match index_base {
        0 | 1 => Ok(index_base as usize),
        _ => Err(Error::argument(format!(
            "index_base = {index_base} must be 0 or 1"
        ))),
    }
}

fn axis_arg(comp: c_int) -> Result<Axis> {
    Axis::from_i32(comp)
        .ok_or_else(|| Error::argument(format!("component = {comp} must be 0 (x), 1 (y) or 2 (z)")))
}

/// `values` (`per` per item) checked finite, naming the item as `item` in
/// the model's index base: no NaN or Inf leaves with TFEM_STATUS_OK.
fn finite(values: &[f64], per: usize, quantity: &str, item: &str, base: usize) -> Result<()> {
    ensure_finite(values.iter().copied(), per, quantity, |i| {
        format!("{item} {}", i + base)
    })
}

/// A scalar result checked finite, `of` saying whose it is.
fn finite_value(value: f64, quantity: &str, of: &str) -> Result<()> {
    ensure_finite([value], 1, quantity, |_| of.to_string())
}

fn flat3(v: Vec<[f64; 3]>) -> Vec<f64> {
    v.into_iter().flatten().collect()
}

fn flat6(v: Vec<[f64; 6]>) -> Vec<f64> {
    v.into_iter().flatten().collect()
}

// -------- Lifecycle, errors and warnings ------------------------------

/// Creates an empty 3D model. Returns NULL only if memory is exhausted.
/// Free it with `tfem_solid_destroy`. A 3D model is its own handle: the
/// 2D functions (`tfem_*` without `solid`) refuse it, and the 3D ones
/// refuse a 2D model.
#[unsafe(no_mangle)]
pub extern "C" fn tfem_solid_create() -> *mut TfemSolidModel {
    guarded(|| {
        register(TfemSolidModel {
            model: SolidModel::new(),
            index_base: 0,
            last_error: String::new(),
            materials: BTreeSet::new(),
            constrained: false,
            loaded: false,
        })
    })
    .unwrap_or(std::ptr::null_mut())
}

/// Destroys a 3D model and everything it owns. NULL is a no-op, and so is
/// a pointer that is not a live 3D model (destroyed already, or another
/// kind of handle): do not use a handle after destroying it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_destroy(model: *mut TfemSolidModel) {
    if !model.is_null() && unregister(model) {
        // SAFETY: a live handle from tfem_solid_create, now unregistered,
        // so freed once.
        let _ = guarded(|| drop(unsafe { Box::from_raw(model) }));
    }
}

/// Copies the message of the last failed call on `model` (empty after a
/// successful call) into `buffer` (`length` bytes including the final
/// NUL), truncating like `tfem_last_error` (TFEM_STATUS_BUFFER_TOO_SMALL;
/// `tfem_solid_last_error_length` gives the size needed). A 3D model keeps
/// its own messages; calls given no handle at all leave theirs in the
/// thread's slot, read with `tfem_last_error(NULL, …)`. A `model` that is
/// not a live 3D model gives TFEM_STATUS_INVALID_ARGUMENT with the message
/// saying so in `buffer`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_last_error(
    model: *const TfemSolidModel,
    buffer: *mut c_char,
    length: usize,
) -> Status {
    if model.is_null() {
        return Status::NullPointer;
    }
    if let Err(e) = check_live(model) {
        let _ = copy_message(e.message(), buffer, length);
        return e.status();
    }
    // SAFETY: a live handle from tfem_solid_create (just checked).
    match unsafe { model.as_ref() } {
        Some(m) => copy_message(&m.last_error, buffer, length),
        None => Status::NullPointer,
    }
}

/// Size in bytes (including the final NUL) of the message
/// `tfem_solid_last_error` would give for `model`, so that a buffer of
/// this size holds all of it: 1 after a successful call; for a handle
/// that is not a live 3D model, the size of the message saying so.
/// `model` may be NULL: 1 (it has no message).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_last_error_length(model: *const TfemSolidModel) -> usize {
    if model.is_null() {
        return 1;
    }
    if let Err(e) = check_live(model) {
        return e.message().len() + 1;
    }
    // SAFETY: a live handle from tfem_solid_create (just checked).
    unsafe { model.as_ref() }.map_or(1, |m| m.last_error.len() + 1)
}

/// Number of warnings: what the mesh noticed (tetrahedra numbered with
/// negative volume and renumbered, nodes used by no tetrahedron) and what
/// the last solve noticed but did not refuse (an ill-conditioned system).
/// They are kept until the next solve or mesh.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_warning_count(
    model: *mut TfemSolidModel,
    count: *mut c_int,
) -> Status {
    with_solid(model, |m| {
        write(count, m.model.warnings().len() as c_int, "count")
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

/// Writes to `size` the size in bytes (including the final NUL) of
/// warning number `index` (0-based, whatever the index base), so that a
/// buffer of this size holds all of it in `tfem_solid_get_warning`. An
/// index out of range is refused (TFEM_STATUS_INVALID_ARGUMENT), `size`
/// unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_warning_size(
    model: *mut TfemSolidModel,
    index: c_int,
    size: *mut usize,
) -> Status {
    with_solid(model, |m| {
        let w = m.model.warnings();
        let i = warning_index(index, w.len())?;
        write(size, w[i].len() + 1, "size")
    })
}

/// Copies warning number `index` (0-based, whatever the index base) into
/// `buffer` of `length` bytes, truncating like `tfem_get_warning`: the
/// truncated warning is written with TFEM_STATUS_BUFFER_TOO_SMALL; on any
/// other error `buffer` is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_warning(
    model: *mut TfemSolidModel,
    index: c_int,
    buffer: *mut c_char,
    length: usize,
) -> Status {
    let mut status = Status::Ok;
    let s = with_solid(model, |m| {
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

// -------- Mesh --------------------------------------------------------

/// Sets the mesh: `n_nodes` nodes with coordinates `xyz` (3·n_nodes
/// values, x0 y0 z0 x1 …), `n_tetrahedra` linear tetrahedra with
/// `connectivity` (4·n_tetrahedra node indices) and a body tag per
/// tetrahedron in `body_of_tetrahedron`. `index_base` is 0 (C) or 1
/// (Fortran) and applies to every index of every later call and message,
/// as `tfem_set_mesh`'s. A tetrahedron numbered with negative volume is
/// renumbered (its last two nodes swapped; a warning counts them, and
/// every output refers to the renumbered ones); flat ones are legal
/// (tempered). The mesh has no tagged faces yet: give them with
/// `tfem_solid_set_boundary_faces`. Replacing a mesh discards
/// constraints, loads, contact pairs and results; materials and
/// tempering are kept. Refused, naming the tetrahedron or node, for a
/// node index out of range, a node repeated in a tetrahedron or a
/// coordinate that is not finite (TFEM_STATUS_INVALID_MESH).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_set_mesh(
    model: *mut TfemSolidModel,
    n_nodes: c_int,
    xyz: *const f64,
    n_tetrahedra: c_int,
    connectivity: *const c_int,
    body_of_tetrahedron: *const c_int,
    index_base: c_int,
) -> Status {
    with_solid(model, |m| {
        let base = base_arg(index_base)?;
        let nn = count(n_nodes, "n_nodes")?;
        let nt = count(n_tetrahedra, "n_tetrahedra")?;
        let xyz = slice_in(xyz, 3 * nn, "xyz")?;
        let conn = slice_in(connectivity, 4 * nt, "connectivity")?;
        let bodies = slice_in(body_of_tetrahedron, nt, "body_of_tetrahedron")?;
        let nodes = copy_in(xyz, 3, "xyz", |c| [c[0], c[1], c[2]])?;
        let mut tets = reserve(nt, "connectivity")?;
        for (t, c) in conn.chunks_exact(4).enumerate() {
            let mut tet = [0usize; 4];
            for k in 0..4 {
                let v = i64::from(c[k]) - base as i64;
                if v < 0 || v as usize >= nn {
                    return Err(Error::mesh(format!(
                        "tetrahedron {}: node index {} is out of range ({nn} nodes, index base \
                         {base})",
                        t + base,
                        c[k]
                    )));
                }
                tet[k] = v as usize;
            }
            tets.push(tet);
        }
        let bodies = copy_in(bodies, 1, "body_of_tetrahedron", |b| b[0])?;
        let mesh = SolidMesh::new(nodes, tets, bodies, base)?;
        m.replace_mesh(mesh, base);
        Ok(())
    })
}

/// Loads a Gmsh MSH 4.1 mesh (ASCII or binary) of tetrahedra from the file
/// `path` (NUL-terminated; on Unix any bytes, as for `tfem_load_gmsh`):
/// physical volumes become bodies (tag = body), the triangles of physical
/// surfaces become tagged boundary faces (tag = the physical surface's),
/// node i being the i-th node of the file's `$Nodes` section. Replaces the
/// mesh like `tfem_solid_set_mesh` with the given `index_base`. Returns
/// TFEM_STATUS_IO for an unreadable or malformed file,
/// TFEM_STATUS_INVALID_MESH for content a tetrahedral mesh cannot take
/// (another version of the format, no tetrahedra in a physical volume as
/// in a 2D file, elements of higher order, a tagged triangle that is not
/// the face of exactly one tetrahedron; named by the file's tags and
/// physical groups), TFEM_STATUS_INVALID_ARGUMENT if the library was built
/// without the `gmsh` feature. On error the model is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_load_gmsh(
    model: *mut TfemSolidModel,
    path: *const c_char,
    index_base: c_int,
) -> Status {
    with_solid(model, |m| {
        if path.is_null() {
            return Err(null("path"));
        }
        let base = base_arg(index_base)?;
        // SAFETY: a NUL-terminated string from the caller.
        let path = unsafe { std::ffi::CStr::from_ptr(path) };
        let mesh = read_solid_gmsh(&path_of(path)?, base)?;
        m.replace_mesh(mesh, base);
        Ok(())
    })
}

#[cfg(feature = "gmsh")]
fn read_solid_gmsh(path: &std::path::Path, base: usize) -> Result<SolidMesh> {
    crate::io::gmsh::read_solid_msh(path, base)
}

#[cfg(not(feature = "gmsh"))]
fn read_solid_gmsh(_: &std::path::Path, _: usize) -> Result<SolidMesh> {
    Err(Error::argument(
        "this libtfem was built without the `gmsh` feature",
    ))
}

/// The faces (0-based) and tags of a C face list.
fn faces_in<'t>(
    m: &TfemSolidModel,
    n_faces: c_int,
    face_nodes: *const c_int,
    tags: *const c_int,
) -> Result<(Vec<[usize; 3]>, &'t [c_int])> {
    let n = m.n_nodes()?;
    let nf = count(n_faces, "n_faces")?;
    let fnodes = slice_in(face_nodes, 3 * nf, "face_nodes")?;
    let tags = slice_in(tags, nf, "tags")?;
    let b = m.index_base;
    let mut faces = reserve(nf, "face_nodes")?;
    for (f, c) in fnodes.chunks_exact(3).enumerate() {
        let mut face = [0usize; 3];
        for k in 0..3 {
            let v = i64::from(c[k]) - b as i64;
            if v < 0 || v as usize >= n {
                return Err(Error::mesh(format!(
                    "boundary face {}: node index {} is out of range ({n} nodes, index base {b})",
                    f + b,
                    c[k]
                )));
            }
            face[k] = v as usize;
        }
        faces.push(face);
    }
    Ok((faces, tags))
}

/// Changes the faces of the model's mesh by `change`, refused while
/// constraints, loads or contact pairs name the faces: the Rust model
/// takes new faces only with a new mesh, which would drop them silently.
fn change_faces(
    m: &mut TfemSolidModel,
    change: impl FnOnce(&mut SolidMesh) -> Result<()>,
) -> Result<()> {
    let mut mesh = m.mesh()?.clone();
    if m.constrained || m.loaded || !m.model.contact_pairs().is_empty() {
        return Err(Error::state(
            "the boundary faces are given before constraints, loads and contact pairs, which \
             name them: clear those first (tfem_solid_clear_constraints, \
             tfem_solid_clear_loads, tfem_solid_clear_contact_pairs)",
        ));
    }
    change(&mut mesh)?;
    let base = m.index_base;
    m.replace_mesh(mesh, base);
    Ok(())
}

/// Sets the tagged boundary faces: `n_faces` triangles given by
/// `face_nodes` (3·n_faces node indices, in any order: the outward side is
/// away from the tetrahedron the face belongs to) with a tag each in
/// `tags`. Tags name the faces for constraints, loads and contact pairs.
/// Replaces previous faces (`tfem_solid_add_boundary_faces` adds one group
/// at a time). Each must be a face of exactly one tetrahedron, and a face
/// given twice with one tag is refused (its loads would count twice):
/// TFEM_STATUS_INVALID_MESH naming the face. Faces are given before the
/// constraints, loads and contact pairs that name them: while any is
/// declared the call is refused (TFEM_STATUS_INVALID_STATE). Discards the
/// results. On any error nothing changes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_set_boundary_faces(
    model: *mut TfemSolidModel,
    n_faces: c_int,
    face_nodes: *const c_int,
    tags: *const c_int,
) -> Status {
    with_solid(model, |m| {
        let (faces, tags) = faces_in(m, n_faces, face_nodes, tags)?;
        change_faces(m, |mesh| mesh.set_boundary_faces(&faces, tags))
    })
}

/// Adds tagged boundary faces to those already set, checked as
/// `tfem_solid_set_boundary_faces` checks them (a face already holding
/// the tag is refused): for instance one call per physical surface.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_add_boundary_faces(
    model: *mut TfemSolidModel,
    n_faces: c_int,
    face_nodes: *const c_int,
    tags: *const c_int,
) -> Status {
    with_solid(model, |m| {
        let (faces, tags) = faces_in(m, n_faces, face_nodes, tags)?;
        change_faces(m, |mesh| mesh.add_boundary_faces(&faces, tags))
    })
}

/// Sizes: nodes, tetrahedra, and tetrahedra of the contact layer B of the
/// last solve (0 before a solve, or without contact pairs), which size the
/// buffers of the getters. Any pointer may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_sizes(
    model: *mut TfemSolidModel,
    n_nodes: *mut c_int,
    n_tetrahedra: *mut c_int,
    n_contact_tetrahedra: *mut c_int,
) -> Status {
    with_solid(model, |m| {
        let mesh = m.mesh()?;
        let nc = m.model.contact_active().map_or(0, <[bool]>::len);
        write_optional(n_nodes, mesh.nodes().len() as c_int);
        write_optional(n_tetrahedra, mesh.tets().len() as c_int);
        write_optional(n_contact_tetrahedra, nc as c_int);
        Ok(())
    })
}

/// Number of tagged boundary faces the model holds, from
/// `tfem_solid_set_boundary_faces` / `tfem_solid_add_boundary_faces` or a
/// Gmsh file's physical surfaces; see `tfem_solid_get_boundary_faces`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_boundary_face_count(
    model: *mut TfemSolidModel,
    count: *mut c_int,
) -> Status {
    with_solid(model, |m| {
        let n = m.mesh()?.boundary_faces().len();
        write(count, n as c_int, "count")
    })
}

/// Copies the node coordinates the model holds (x0 y0 z0 x1 …, 3·n_nodes
/// values) into `xyz` of `length` values: after `tfem_solid_load_gmsh`,
/// the mesh the file gave.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_mesh_nodes(
    model: *mut TfemSolidModel,
    xyz: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        let v: Vec<f64> = m.mesh()?.nodes().iter().flatten().copied().collect();
        copy_out(&v, xyz, length, "xyz")
    })
}

/// Copies the tetrahedra the model holds (4·n_tetrahedra node indices in
/// the model's index base, those given with negative volume renumbered)
/// into `tetrahedra` of `length` values and each one's body tag into
/// `bodies` of `bodies_length` values; `bodies` may be NULL. Nothing is
/// written unless both buffers are large enough.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_mesh_tetrahedra(
    model: *mut TfemSolidModel,
    tetrahedra: *mut c_int,
    length: usize,
    bodies: *mut c_int,
    bodies_length: usize,
) -> Status {
    with_solid(model, |m| {
        let mesh = m.mesh()?;
        let b = m.index_base as c_int;
        let n = mesh.tets().len();
        if !bodies.is_null() && bodies_length < n {
            return Err(too_small("bodies", bodies_length, n));
        }
        let v: Vec<c_int> = (mesh.tets().iter())
            .flat_map(|t| t.map(|v| v as c_int + b))
            .collect();
        copy_out(&v, tetrahedra, length, "tetrahedra")?;
        if !bodies.is_null() {
            copy_out(mesh.body_of(), bodies, bodies_length, "bodies")?;
        }
        Ok(())
    })
}

/// Copies the tagged boundary faces the model holds (3·count node indices
/// in the model's index base, count from
/// `tfem_solid_get_boundary_face_count`) into `faces` of `length` values
/// and each face's tag into `tags` of `tags_length` values, in the order
/// they were given; `tags` may be NULL. Nothing is written unless both
/// buffers are large enough.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_boundary_faces(
    model: *mut TfemSolidModel,
    faces: *mut c_int,
    length: usize,
    tags: *mut c_int,
    tags_length: usize,
) -> Status {
    with_solid(model, |m| {
        let list = m.mesh()?.boundary_faces();
        let b = m.index_base as c_int;
        if !tags.is_null() && tags_length < list.len() {
            return Err(too_small("tags", tags_length, list.len()));
        }
        let v: Vec<c_int> = (list.iter())
            .flat_map(|f| f.nodes.map(|v| v as c_int + b))
            .collect();
        copy_out(&v, faces, length, "faces")?;
        if !tags.is_null() {
            let t: Vec<c_int> = list.iter().map(|f| f.tag).collect();
            copy_out(&t, tags, tags_length, "tags")?;
        }
        Ok(())
    })
}

// -------- Materials, tempering and ordering ---------------------------

/// Sets the isotropic material of body `body`: Young's modulus `young`
/// (finite, > 0) and Poisson's ratio `poisson` (in (-1, 0.5)); a body may
/// be given its material before or after the mesh. Refused with
/// TFEM_STATUS_INVALID_MATERIAL naming the body. Every body of the mesh
/// needs one before a solve.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_set_material(
    model: *mut TfemSolidModel,
    body: c_int,
    young: f64,
    poisson: f64,
) -> Status {
    with_solid(model, |m| {
        let mat = SolidMaterial::new(young, poisson).map_err(|e| {
            Error::new(
                Status::InvalidMaterial,
                format!("body {body}: {}", e.message()),
            )
        })?;
        m.model.set_material(body, mat);
        m.materials.insert(body);
        Ok(())
    })
}

/// Chooses Jmin, the floor of the tempered tetrahedra's Jacobian, with
/// `tfem_set_tempering`'s encoding (a `tfem_tempering_mode`): 0 auto,
/// Jmin = min(h⁴/λ, h³/10) with λ the larger side of the mesh's bounding
/// box (h the element's longest edge); 1 the same h⁴/λ with λ = `value`
/// (a length); 2 Jmin = `value` for every tetrahedron (length³; J is six
/// times the volume); 3 off, plain FEM (a flat tetrahedron is then an
/// error). `value` is ignored for 0 and 3, and must be finite and > 0 for
/// 1 and 2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_set_tempering(
    model: *mut TfemSolidModel,
    mode: c_int,
    value: f64,
) -> Status {
    with_solid(model, |m| {
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

/// Chooses the fill-reducing ordering of the factorisation (a
/// `tfem_ordering_mode`: 0 auto, 1 AMD, 2 nested dissection). Results do
/// not depend on it beyond round-off, and are kept.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_set_ordering(
    model: *mut TfemSolidModel,
    ordering: c_int,
) -> Status {
    with_solid(model, |m| {
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
        m.model.set_ordering(ordering);
        Ok(())
    })
}

// -------- Loads and constraints ---------------------------------------

/// Prescribes displacement component `comp` (a `tfem_axis`: 0 x, 1 y,
/// 2 z) of `node` to `value` (model length units). A component prescribed
/// again takes the new value (unlike `tfem_fix`, which refuses a different
/// one). Refused, naming it, for a node out of range, a component other
/// than 0, 1, 2 or a value that is not finite.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_fix(
    model: *mut TfemSolidModel,
    node: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_solid(model, |m| {
        let v = m.node(node)?;
        m.model.fix(v, axis_arg(comp)?, value)?;
        m.constrained = true;
        Ok(())
    })
}

/// Prescribes component `comp` (0 x, 1 y, 2 z) to `value` on every node of
/// the boundary faces tagged `tag`, as they are when called (faces are
/// fixed before constraints: see `tfem_solid_set_boundary_faces`). An
/// unknown tag is refused, naming it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_fix_faces(
    model: *mut TfemSolidModel,
    tag: c_int,
    comp: c_int,
    value: f64,
) -> Status {
    with_solid(model, |m| {
        m.mesh()?;
        m.model.fix_faces(tag, axis_arg(comp)?, value)?;
        m.constrained = true;
        Ok(())
    })
}

/// Removes every prescribed displacement (and so lets the boundary faces
/// change again, once loads and pairs are cleared too).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_clear_constraints(model: *mut TfemSolidModel) -> Status {
    with_solid(model, |m| {
        m.model.clear_constraints();
        m.constrained = false;
        Ok(())
    })
}

/// Applies pressure `pressure` on the boundary faces tagged `tag`: a
/// stress (force per unit area, Pa in SI), positive pushing into the body,
/// along each face's outward normal. Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_add_pressure(
    model: *mut TfemSolidModel,
    tag: c_int,
    pressure: f64,
) -> Status {
    with_solid(model, |m| {
        m.mesh()?;
        m.model.add_pressure(tag, pressure)?;
        m.loaded = true;
        Ok(())
    })
}

/// Applies the traction (tx, ty, tz) on the boundary faces tagged `tag`: a
/// stress vector (force per unit area, Pa in SI) whatever the faces'
/// orientation. Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_add_traction(
    model: *mut TfemSolidModel,
    tag: c_int,
    tx: f64,
    ty: f64,
    tz: f64,
) -> Status {
    with_solid(model, |m| {
        m.mesh()?;
        m.model.add_traction(tag, [tx, ty, tz])?;
        m.loaded = true;
        Ok(())
    })
}

/// Adds the point force (fx, fy, fz) at `node` (N in SI). Loads add up.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_add_nodal_force(
    model: *mut TfemSolidModel,
    node: c_int,
    fx: f64,
    fy: f64,
    fz: f64,
) -> Status {
    with_solid(model, |m| {
        let v = m.node(node)?;
        m.model.add_nodal_force(v, [fx, fy, fz])?;
        m.loaded = true;
        Ok(())
    })
}

/// Removes every load.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_clear_loads(model: *mut TfemSolidModel) -> Status {
    with_solid(model, |m| {
        m.model.clear_loads();
        m.loaded = false;
        Ok(())
    })
}

// -------- Contact pairs -----------------------------------------------

/// Declares a frictionless contact interface between the boundary faces
/// tagged `tag_a` and those tagged `tag_b`, on two bodies. Side a must be
/// planar: its outward normal is the direction that opens the gap, and the
/// contact layer B is a layer of flat tetrahedra built across that plane
/// (docs/method.md §9). Side b must face side a node to node (matching
/// meshes); that, the planarity and the two bodies are checked by the
/// solve, which names the pair and its tags. Writes the pair's index
/// (0-based, whatever the index base) to `pair` (may be NULL). Two equal
/// tags or a tag without faces are refused here, naming the tag.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_add_contact_pair(
    model: *mut TfemSolidModel,
    tag_a: c_int,
    tag_b: c_int,
    pair: *mut c_int,
) -> Status {
    with_solid(model, |m| {
        m.mesh()?;
        let p = m.model.add_contact_pair(tag_a, tag_b)?;
        write_optional(pair, p as c_int);
        Ok(())
    })
}

/// Removes every contact pair.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_clear_contact_pairs(model: *mut TfemSolidModel) -> Status {
    with_solid(model, |m| {
        m.model.clear_contact_pairs();
        Ok(())
    })
}

// -------- Solve -------------------------------------------------------

/// Solves the model with the default contact options (as
/// `tfem_solid_solve_contact` without options), the call for a model
/// without contact pairs: one linear solve then. `info` may be NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_solve(
    model: *mut TfemSolidModel,
    info: *mut TfemSolveInfo,
) -> Status {
    with_solid(model, |m| {
        m.ready()?;
        let i = m.model.solve()?;
        write_optional(info, info_out(&i));
        Ok(())
    })
}

/// Solves the model: where it has contact pairs, the tetrahedra of B are
/// switched on where they would invert, by the active-set loop of the 2D
/// contact solve. `options` may be NULL (defaults: see
/// `tfem_contact_options_default`); 3D contact is frictionless with its
/// own inversion test, so `law` must be 0 and `inversion_test` 0
/// (TFEM_STATUS_INVALID_ARGUMENT saying so otherwise); `contact_modulus`
/// and `lambda` (0: the smaller E of the pair's bodies, the other body's
/// for a rigid tool; the mesh's size), `max_iterations` and `refactorize`
/// are read. `info` may be NULL. A body without material gives
/// TFEM_STATUS_INVALID_MATERIAL naming it, a body not restrained
/// TFEM_STATUS_SINGULAR naming it, a pair whose sides do not fit (side a
/// not planar, sides not matching node to node, both on one body) an
/// error naming the pair and its tags. On error the model is unchanged,
/// its previous results included.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_solve_contact(
    model: *mut TfemSolidModel,
    options: *const TfemContactOptions,
    info: *mut TfemSolveInfo,
) -> Status {
    with_solid(model, |m| {
        // SAFETY: NULL or a caller-owned options struct.
        let opts = match unsafe { options.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        m.ready()?;
        let i = m.model.solve_contact(&opts)?;
        write_optional(info, info_out(&i));
        Ok(())
    })
}

/// One quasi-static load step: the model's loads and prescribed
/// displacements times `load_factor` (finite; initial gaps as they are),
/// started from the active set of the last solve or step, on the
/// structure, pattern and symbolic analysis the first solve derived, so
/// that a load history repeats neither the analysis nor the active-set
/// iterations a cold start would. Frictionless contact has no memory: a
/// step's answer is that of a solve at its factor, and the loads may
/// change between steps (a non-proportional history). `options` may be
/// NULL (defaults; refused as by `tfem_solid_solve_contact`); `info` may be
/// NULL. `tfem_solid_revert_step` takes the step back. On error the model
/// is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_step(
    model: *mut TfemSolidModel,
    load_factor: f64,
    options: *const TfemContactOptions,
    info: *mut TfemSolveInfo,
) -> Status {
    with_solid(model, |m| {
        // SAFETY: NULL or a caller-owned options struct.
        let opts = match unsafe { options.as_ref() } {
            None => ContactOptions::default(),
            Some(o) => options_in(o)?,
        };
        m.ready()?;
        let i = m.model.step(load_factor, &opts)?;
        write_optional(info, info_out(&i));
        Ok(())
    })
}

/// Takes back the last load step: its results, and the active set the
/// next step starts from, are those before it. Once per step, and not
/// after a change of the model (which discards the results): refused then
/// with TFEM_STATUS_INVALID_STATE, the model unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_revert_step(model: *mut TfemSolidModel) -> Status {
    with_solid(model, |m| {
        m.mesh()?;
        // The Rust model refuses only where there is no step to take back:
        // a state, in the C API's terms.
        m.model.revert_step().map_err(|e| Error::state(e.message()))
    })
}

/// Writes the statistics of the last solve (unknowns, factorisations,
/// interface unknowns, residual, times) to `info`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_solve_info(
    model: *mut TfemSolidModel,
    info: *mut TfemSolveInfo,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        write(info, info_out(m.model.solve_info()?), "info")
    })
}

/// Writes the active-set iterations of the last solve (1 without contact)
/// to `iterations`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_iterations(
    model: *mut TfemSolidModel,
    iterations: *mut c_int,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let n = c_int::try_from(m.model.iterations()?).unwrap_or(c_int::MAX);
        write(iterations, n, "iterations")
    })
}

// -------- Results -----------------------------------------------------

/// Copies the nodal displacements (ux0 uy0 uz0 ux1 …, 3·n_nodes values)
/// of the last solve into `out` of `length` values.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_displacements(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let u = flat3(m.model.displacements()?);
        finite(&u, 3, "displacement", "node", m.index_base)?;
        copy_out(&u, out, length, "out")
    })
}

/// Copies element strains (ε_xx ε_yy ε_zz γ_yz γ_xz γ_xy per tetrahedron,
/// engineering shears, 6·n_tetrahedra values), computed on request and
/// tempered below Jmin as the stiffness is.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_element_strains(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let v = flat6(m.model.element_strains()?);
        finite(&v, 6, "strain", "tetrahedron", m.index_base)?;
        copy_out(&v, out, length, "out")
    })
}

/// Copies element stresses (σ_xx σ_yy σ_zz σ_yz σ_xz σ_xy per tetrahedron,
/// 6·n_tetrahedra values, the order of the strains; force per unit area,
/// Pa in SI), computed on request. An overflow gives
/// TFEM_STATUS_NUMERICAL_FAILURE naming the tetrahedron.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_element_stresses(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let v = flat6(m.model.element_stresses()?);
        finite(&v, 6, "stress", "tetrahedron", m.index_base)?;
        copy_out(&v, out, length, "out")
    })
}

/// Copies reaction forces (Rx Ry Rz per node, 3·n_nodes values, N in SI;
/// zero at components that are not prescribed), computed on request: with
/// the loads and the contact forces they balance every body.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_reactions(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let v = flat3(m.model.reactions()?);
        finite(&v, 3, "reaction", "node", m.index_base)?;
        copy_out(&v, out, length, "out")
    })
}

/// Writes the work of the external loads of the last solve, Σ f·u over
/// every node (J in SI): for a pressure load, the compliance.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_external_work(
    model: *mut TfemSolidModel,
    work: *mut f64,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let w = m.model.external_work()?;
        finite_value(w, "external work", "the loads")?;
        write(work, w, "work")
    })
}

// -------- Contact results ---------------------------------------------

/// Copies the nodes of every tetrahedron of the contact layer B of the
/// last solve (4·n_contact_tetrahedra indices in the model's index base,
/// pair by pair, numbered so that opening the gap makes J positive).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_tetrahedra(
    model: *mut TfemSolidModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let b = m.index_base as c_int;
        let v: Vec<c_int> = (m.model.contact_tetrahedra()?.iter())
            .flat_map(|t| t.map(|v| v as c_int + b))
            .collect();
        copy_out(&v, out, length, "out")
    })
}

/// Copies the active flag (1 pressed, 0 open) of every tetrahedron of B
/// in the last solve (n_contact_tetrahedra values, see
/// `tfem_solid_get_sizes`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_active(
    model: *mut TfemSolidModel,
    out: *mut c_int,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        map_out(m.model.contact_active()?, out, length, "out", c_int::from)
    })
}

/// Copies the force the contact exerts on every node in the last solve
/// (fx fy fz per node, 3·n_nodes values, N in SI; zero off the contact
/// interfaces), computed on request: the forces of one pair sum to zero.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_forces(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let v = flat3(m.model.contact_forces()?);
        finite(&v, 3, "contact force", "node", m.index_base)?;
        copy_out(&v, out, length, "out")
    })
}

/// Copies the contact pressure at every node in the last solve (n_nodes
/// values; force per unit area, Pa in SI, positive in compression; zero
/// off the pairs' faces), computed on request: the normal force B exerts
/// on the node over its tributary area, a third of each of its faces.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_nodal_pressures(
    model: *mut TfemSolidModel,
    out: *mut f64,
    length: usize,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let v = m.model.contact_nodal_pressures()?;
        finite(&v, 1, "contact pressure", "node", m.index_base)?;
        copy_out(&v, out, length, "out")
    })
}

/// Writes the area in contact in the last solve, every pair together
/// (model length units squared): each active tetrahedron of B stands for
/// a third of the facing triangle of its prism, so a closed interface
/// reads its whole area.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_area(
    model: *mut TfemSolidModel,
    area: *mut f64,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let a = m.model.contact_area()?;
        finite_value(a, "contact area", "the contact pairs")?;
        write(area, a, "area")
    })
}

/// Writes the area in contact of contact pair `pair` alone (0-based, as
/// `tfem_solid_add_contact_pair` returned it, whatever the index base) in
/// the last solve. An unknown pair is refused (TFEM_STATUS_INVALID_ARGUMENT
/// naming it).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_get_contact_pair_area(
    model: *mut TfemSolidModel,
    pair: c_int,
    area: *mut f64,
) -> Status {
    with_solid(model, |m| {
        m.solved()?;
        let n = m.model.contact_pairs().len();
        let p = usize::try_from(pair)
            .ok()
            .filter(|&p| p < n)
            .ok_or_else(|| crate::error::no_pair(pair, n))?;
        let a = m.model.contact_pair_area(p)?;
        finite_value(a, "contact area", &format!("contact pair {pair}"))?;
        write(area, a, "area")
    })
}

/// Writes the solved model to the file `path` (NUL-terminated; on Unix any
/// bytes, as for `tfem_load_gmsh`) as a VTK XML unstructured grid (`.vtu`,
/// binary appended data, read by ParaView, VTK and meshio): the
/// tetrahedra in their initial configuration with point data
/// `displacement` ([u_x, u_y, u_z]) and, when the model has contact pairs,
/// `contact_pressure` (`tfem_solid_get_contact_nodal_pressures`); cell
/// data `body`, `J` (six times the signed volume) and `stress` (VTK's
/// order of a symmetric tensor, [σ_xx, σ_yy, σ_zz, σ_xy, σ_yz, σ_xz], so
/// that its tensor filters read it; not the Voigt order of
/// `tfem_solid_get_element_stresses`). Returns TFEM_STATUS_INVALID_STATE
/// before a solve, TFEM_STATUS_NUMERICAL_FAILURE for a result that is not
/// finite (nothing is written then), TFEM_STATUS_IO when the file cannot
/// be written (the message names it and the reason), and
/// TFEM_STATUS_INVALID_ARGUMENT if the library was built without the `vtu`
/// feature. The model is never changed.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tfem_solid_write_vtu(
    model: *mut TfemSolidModel,
    path: *const c_char,
) -> Status {
    with_solid(model, |m| {
        if path.is_null() {
            return Err(null("path"));
        }
        // SAFETY: a NUL-terminated string from the caller.
        let path = unsafe { std::ffi::CStr::from_ptr(path) };
        let path = path_of(path)?;
        m.solved()?;
        write_solid_vtu(m, &path)
    })
}

#[cfg(feature = "vtu")]
fn write_solid_vtu(m: &TfemSolidModel, path: &std::path::Path) -> Result<()> {
    let base = m.index_base;
    let u = m.model.displacements()?;
    finite(u.as_flattened(), 3, "displacement", "node", base)?;
    let stress = m.model.element_stresses()?;
    finite(stress.as_flattened(), 6, "stress", "tetrahedron", base)?;
    let pressure = match m.model.contact_pairs().is_empty() {
        true => None,
        false => Some(m.model.contact_nodal_pressures()?),
    };
    if let Some(p) = &pressure {
        finite(p, 1, "contact pressure", "node", base)?;
    }
    let fields = crate::io::vtu::SolidFields {
        displacement: Some(&u),
        stress: Some(&stress),
        contact_pressure: pressure.as_deref(),
    };
    crate::io::vtu::write_solid_vtu(m.mesh()?, &fields, path)
}

#[cfg(not(feature = "vtu"))]
fn write_solid_vtu(_: &TfemSolidModel, _: &std::path::Path) -> Result<()> {
    Err(Error::argument(
        "this libtfem was built without the `vtu` feature",
    ))
}
