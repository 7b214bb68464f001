"""Shared scenes of the Python tests."""

import ctypes
import os
import pathlib

import numpy as np
import pytest

import tfem
from tfem.meshing import Assembly

REPO = pathlib.Path(__file__).resolve().parents[2]
L, H, E1, E2, NU, P, C = 1.0, 0.25, 1e10, 1e11, 0.3, 1e7, 0.1


def seed_arrays(h: float = 1 / 16):
    """The seed scene's mesh as arrays: (nodes, triangles, bodies, edges,
    tags, symmetry-line nodes); tags 1 and 2 the interface, 3 the loaded
    top, 4 the support."""
    xs = np.union1d(np.linspace(0, L, round(L / h) + 1), [L / 2 - C, L / 2, L / 2 + C])
    ys = np.linspace(0, H, round(H / h) + 1)
    mesh = Assembly()
    mesh.add_grid(xs, ys - H, body=1)
    mesh.add_grid(xs, ys, body=2)
    eps = 1e-9
    mesh.tag(1, body=1, where=lambda x, y: abs(y) < eps)
    mesh.tag(2, body=2, where=lambda x, y: abs(y) < eps)
    mesh.tag(3, body=2, where=lambda x, y: abs(y - H) < eps and abs(x - L / 2) < C)
    mesh.tag(4, body=1, where=lambda x, y: abs(y + H) < eps and abs(x - L / 2) < C)
    axis = mesh.nodes_where(lambda x, y: abs(x - L / 2) < eps)
    return (*mesh.arrays(), axis)


def seed_model(h: float = 1 / 16, threads: int = 1) -> tfem.Model:
    """The seed scene, declared (not solved), on `threads` threads."""
    nodes, tris, bodies, edges, tags, axis = seed_arrays(h)
    m = tfem.Model()
    m.set_threads(threads)
    m.set_mesh(nodes, tris, bodies)
    m.set_boundary_edges(edges, tags)
    m.set_material(1, E1, NU)
    m.set_material(2, E2, NU)
    m.add_pressure(3, P)
    m.fix_edges(4, "y")
    for v in axis:
        m.fix(int(v), "x")
    m.add_contact_pair(1, 2)
    return m


def c_library():
    """The C library built from this repository (TFEM_C_LIBRARY, or
    target/release/libtfem.so); None if neither is there."""
    path = os.environ.get("TFEM_C_LIBRARY")
    if path:
        if not pathlib.Path(path).is_file():
            raise FileNotFoundError(f"TFEM_C_LIBRARY={path} is not a file")
        return ctypes.CDLL(path)
    default = REPO / "target" / "release" / "libtfem.so"
    return ctypes.CDLL(str(default)) if default.is_file() else None


@pytest.fixture(scope="session")
def libtfem():
    lib = c_library()
    if lib is None:
        pytest.skip("no C library: build it (cargo build --release) or set TFEM_C_LIBRARY")
    lib.tfem_create.restype = ctypes.c_void_p
    lib.tfem_destroy.argtypes = [ctypes.c_void_p]
    return lib
