"""tfem: contact between elastic bodies by the Tempered Finite Element Method.

The Rust library's API from Python: a :class:`Model` takes a mesh of
triangles as numpy arrays, materials, constraints, loads and contact
pairs, solves (with contact, load steps, or adaptively to a tolerance)
and gives its results back as numpy arrays. Every failure raises an
exception of the :class:`Error` family carrying ``status`` (the C ABI's
code) and a message naming the offending node, triangle, edge, body or
argument; the model is then unchanged. (An argument of the wrong Python
type, or a negative count or index, raises Python's own ``TypeError`` or
``OverflowError`` before the library is reached.) Warnings go to Python's
``warnings`` as :class:`Warning`; turned into errors, a warning raises
after the call that gave it has done its work. Solves release the GIL.

Meshes: :func:`read_msh` (a Gmsh MSH 4.1 file), :func:`from_gmsh` (the
current model of Gmsh's Python API), or arrays of your own
(:mod:`tfem.meshing` builds structured ones). Results out:
:meth:`Model.write_vtu`, or :func:`to_meshio` where meshio is installed.
"""

from __future__ import annotations

import numpy as np

from . import _tfem
from ._tfem import (
    DegenerateElement,
    Error,
    InternalError,
    InvalidArgument,
    InvalidContact,
    InvalidMaterial,
    InvalidMesh,
    InvalidState,
    IoError,
    NotConverged,
    NumericalFailure,
    OutOfMemory,
    Singular,
    Warning,
    __version__,
)

__all__ = [
    "Model",
    "read_msh",
    "from_gmsh",
    "to_meshio",
    "Error",
    "InvalidArgument",
    "InvalidMesh",
    "InvalidMaterial",
    "InvalidState",
    "Singular",
    "NotConverged",
    "DegenerateElement",
    "InvalidContact",
    "NumericalFailure",
    "OutOfMemory",
    "IoError",
    "InternalError",
    "Warning",
    "__version__",
]


def _error(cls, message, status):
    """An exception of the tfem family raised from Python, carrying the
    status code and name its native siblings carry."""
    e = cls(message)
    e.status, e.status_name = status, {2: "invalid argument", 3: "invalid mesh"}[status]
    return e


def _array(a, dtype, what):
    """`a` as a C-contiguous array of `dtype`: `a` itself (no copy) when it
    is one already, else a converted copy; a wrong dtype kind (floats for
    indices) or a value the dtype cannot hold is refused rather than
    truncated or wrapped."""
    arr = np.asarray(a)
    if np.issubdtype(dtype, np.integer) and arr.size:
        if not np.issubdtype(arr.dtype, np.integer):
            raise _error(InvalidArgument, f"{what} must hold integers (got dtype {arr.dtype})", 2)
        info = np.iinfo(dtype)
        lo, hi = arr.min(), arr.max()
        if lo < info.min or hi > info.max:
            bad = lo if lo < info.min else hi
            raise _error(InvalidArgument, f"{what} holds {bad}, outside the range of {np.dtype(dtype).name}", 2)
    return np.ascontiguousarray(arr, dtype=dtype)


class Model(_tfem.Model):
    """A contact model (see the module's documentation); arrays in any
    layout and integer width are accepted, and read in place when they are
    C-contiguous of the native dtype (float64 nodes, int64 indices, int32
    bodies and tags)."""

    def set_mesh(self, nodes, triangles, bodies):
        """Sets the mesh: `nodes` (n, 2), `triangles` (m, 3) 0-based node
        numbers, `bodies` (m,) each triangle's body."""
        super().set_mesh(
            _array(nodes, np.float64, "nodes"),
            _array(triangles, np.int64, "triangles"),
            _array(bodies, np.int32, "bodies"),
        )

    def set_boundary_edges(self, edges, tags):
        """Sets the tagged boundary edges: `edges` (k, 2) node pairs,
        `tags` (k,)."""
        super().set_boundary_edges(_array(edges, np.int64, "edges"), _array(tags, np.int32, "tags"))

    def add_boundary_edges(self, edges, tags):
        """Adds tagged boundary edges to those already set."""
        super().add_boundary_edges(_array(edges, np.int64, "edges"), _array(tags, np.int32, "tags"))


def read_msh(path) -> Model:
    """A model with the mesh of a Gmsh MSH 4.1 file (ASCII or binary):
    physical surfaces become bodies (tag = body), physical curves
    boundary-edge tags."""
    m = Model()
    m.read_msh(str(path))
    return m


def from_gmsh(gmsh=None) -> Model:
    """A model with the mesh of the current model of Gmsh's Python API
    (``import gmsh``; a 2D mesh of 3-node triangles in the plane z = 0),
    read as :func:`read_msh` reads a file: each physical surface's
    triangles become a body (tag = body; a surface in several groups goes
    to the first, with a warning), each physical curve's 2-node lines
    boundary edges with its tag; physical points are not used (a
    warning); only the nodes of the elements read are kept."""
    import warnings  # noqa: PLC0415

    if gmsh is None:
        import gmsh  # noqa: PLC0415  (optional dependency)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = np.asarray(coords, dtype=np.float64).reshape(-1, 3)
    index = {int(t): i for i, t in enumerate(tags)}
    tris, bodies, edges, edge_tags = [], [], [], []
    surfaces = {}
    for dim, phys in gmsh.model.getPhysicalGroups():
        if dim == 0:
            warnings.warn(f"physical group {phys} holds points: not used", Warning, stacklevel=2)
            continue
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, phys):
            if dim == 2:
                if int(entity) in surfaces:
                    warnings.warn(
                        f"surface {entity} is in physical groups {surfaces[int(entity)]} and {phys}: "
                        f"its triangles go to body {surfaces[int(entity)]}",
                        Warning,
                        stacklevel=2,
                    )
                    continue
                surfaces[int(entity)] = phys
            types, _, nodes = gmsh.model.mesh.getElements(dim, entity)
            for etype, enodes in zip(types, nodes):
                conn = [index[int(v)] for v in enodes]
                if dim == 2 and etype == 2:
                    tris.extend(np.reshape(conn, (-1, 3)).tolist())
                    bodies.extend([phys] * (len(conn) // 3))
                elif dim == 1 and etype == 1:
                    edges.extend(np.reshape(conn, (-1, 2)).tolist())
                    edge_tags.extend([phys] * (len(conn) // 2))
                else:
                    raise _error(
                        InvalidMesh,
                        f"physical group {phys} (dimension {dim}) has elements of Gmsh type "
                        f"{etype}: only 3-node triangles (2) and 2-node lines (1) are read",
                        3,
                    )
    if not tris:
        raise _error(InvalidMesh, "the Gmsh model has no physical surface of triangles: define one", 3)
    tris, edges = np.reshape(tris, (-1, 3)), np.reshape(edges, (-1, 2))
    used = np.unique(np.concatenate([tris.ravel(), edges.ravel()]))
    renumber = np.full(len(xyz), -1, dtype=np.int64)
    renumber[used] = np.arange(len(used))
    if np.max(np.abs(xyz[used, 2])) > 0.0:
        raise _error(InvalidMesh, "the Gmsh model has nodes off the plane z = 0", 3)
    m = Model()
    m.set_mesh(xyz[used, :2], renumber[tris], bodies)
    if len(edges):
        m.set_boundary_edges(renumber[edges], edge_tags)
    return m


def to_meshio(model: Model):
    """The model's mesh with its displacements, element stresses and (after
    a contact solve) nodal contact pressures, as a ``meshio.Mesh``."""
    import meshio  # noqa: PLC0415  (optional dependency)

    points = np.column_stack([model.mesh_nodes(), np.zeros(len(model.mesh_nodes()))])
    point_data = {"displacement": model.displacements()}
    try:
        point_data["contact_pressure"] = model.contact_nodal_pressures()
    except InvalidState:
        pass
    return meshio.Mesh(
        points,
        [("triangle", model.mesh_triangles())],
        point_data=point_data,
        cell_data={"stress": [model.element_stresses()], "body": [model.mesh_bodies()]},
    )
