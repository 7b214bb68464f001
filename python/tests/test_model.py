"""The Python package: results equal the C ABI's, errors, warnings, the
GIL, arrays in and out, Gmsh and meshio."""

import ctypes
import json
import shutil
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import tfem
from conftest import REPO, seed_arrays, seed_model


def c_seed(lib, h):
    """The seed scene through the C ABI: (displacements, nodal pressures)."""
    nodes, tris, bodies, edges, tags, axis = seed_arrays(h)
    m = ctypes.c_void_p(lib.tfem_create())
    dptr = lambda a: a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
    iptr = lambda a: a.ctypes.data_as(ctypes.POINTER(ctypes.c_int))
    c_int = lambda a: np.ascontiguousarray(a, dtype=np.intc)
    try:
        ok = lambda status, call: status == 0 or pytest.fail(f"{call}: status {status}")
        ok(lib.tfem_set_threads(m, 1), "set_threads")
        xy = np.ascontiguousarray(nodes, dtype=np.float64)
        t, b = c_int(tris), c_int(bodies)
        ok(lib.tfem_set_mesh(m, len(nodes), dptr(xy), len(tris), iptr(t), iptr(b), 0), "set_mesh")
        e, g = c_int(edges), c_int(tags)
        ok(lib.tfem_set_boundary_edges(m, len(edges), iptr(e), iptr(g)), "set_boundary_edges")
        for body, young in ((1, 1e10), (2, 1e11)):
            ok(lib.tfem_set_material(m, body, ctypes.c_double(young), ctypes.c_double(0.3), 0), "material")
        ok(lib.tfem_add_pressure(m, 3, ctypes.c_double(1e7)), "pressure")
        ok(lib.tfem_fix_edges(m, 4, 1, ctypes.c_double(0.0)), "fix_edges")
        for v in axis:
            ok(lib.tfem_fix(m, int(v), 0, ctypes.c_double(0.0)), "fix")
        ok(lib.tfem_add_contact_pair(m, 1, 2, None), "pair")
        ok(lib.tfem_solve_contact(m, None, None), "solve_contact")
        u = np.empty(2 * len(nodes))
        ok(lib.tfem_get_displacements(m, dptr(u), ctypes.c_size_t(len(u))), "displacements")
        p = np.empty(len(nodes))
        ok(lib.tfem_get_contact_nodal_pressures(m, dptr(p), ctypes.c_size_t(len(p))), "pressures")
        return u.reshape(-1, 2), p
    finally:
        lib.tfem_destroy(m)


def test_the_seed_scene_equals_the_c_abis_to_the_bit(libtfem):
    m = seed_model(1 / 32)
    m.solve_contact()
    u, p = c_seed(libtfem, 1 / 32)
    assert np.array_equal(m.displacements(), u)
    assert np.array_equal(m.contact_nodal_pressures(), p)


def test_the_seed_scene_converges_towards_the_reference():
    case = json.loads((REPO / "docs/reference/two_blocks_canonical.json").read_text())
    ref = case["cases"]["canonical_0.2"]["lc"]["value"]
    # First order in h (docs/report.md): 4.9e-3 at 1/256, the error at
    # 1/32 a few percent, halving with h.
    errors = []
    for h in (1 / 16, 1 / 32):
        m = seed_model(h)
        r = m.solve_contact()
        errors.append(abs(r["contact_length"] - ref) / ref)
    assert errors[1] < 0.6 * errors[0] and errors[1] < 0.1, errors


def test_a_triangle_with_a_node_out_of_range_raises_invalid_mesh_naming_it():
    nodes, tris, bodies, *_ = seed_arrays()
    bad = tris.copy()
    bad[7, 1] = len(nodes) + 3
    m = tfem.Model()
    with pytest.raises(tfem.InvalidMesh, match="triangle 7") as e:
        m.set_mesh(nodes, bad, bodies)
    assert e.value.status == 3 and e.value.status_name == "invalid mesh"
    with pytest.raises(tfem.InvalidState):
        m.mesh_nodes()


def test_a_bad_material_raises_invalid_material_naming_the_body_and_keeps_the_model():
    m = seed_model()
    before = m.solve_contact()
    u = m.displacements()
    with pytest.raises(tfem.InvalidMaterial, match="body 2") as e:
        m.set_material(2, 1e11, 0.7)
    assert isinstance(e.value, tfem.Error) and e.value.status == 4
    assert np.array_equal(m.displacements(), u)
    assert m.solve_contact()["iterations"] == before["iterations"]
    assert np.array_equal(m.displacements(), u)


def test_an_edge_that_is_no_side_raises_naming_it_and_keeps_the_edges():
    m = seed_model()
    edges, tags = m.boundary_edges()
    with pytest.raises(tfem.Error, match="edge"):
        m.set_boundary_edges(np.array([[0, 40]]), np.array([9]))
    after, after_tags = m.boundary_edges()
    assert np.array_equal(edges, after) and np.array_equal(tags, after_tags)


def test_floats_given_as_indices_are_refused_not_truncated():
    nodes, tris, bodies, *_ = seed_arrays()
    with pytest.raises(tfem.InvalidArgument, match="triangles must hold integers"):
        tfem.Model().set_mesh(nodes, tris + 0.5, bodies)


def test_a_bad_component_and_a_bad_plane_raise_invalid_argument():
    m = seed_model()
    with pytest.raises(tfem.InvalidArgument, match="component"):
        m.fix(0, "z")
    with pytest.raises(tfem.InvalidArgument, match="plane"):
        m.set_material(1, 1e10, 0.3, "membrane")


def test_results_before_a_solve_raise_invalid_state():
    with pytest.raises(tfem.InvalidState, match="solve"):
        seed_model().displacements()


def test_an_unrestrained_body_raises_singular_naming_it():
    nodes, tris, bodies, edges, tags, _ = seed_arrays()
    m = tfem.Model()
    m.set_mesh(nodes, tris, bodies)
    m.set_material(1, 1e10, 0.3)
    m.set_material(2, 1e11, 0.3)
    with pytest.raises(tfem.Singular, match="body"):
        m.solve()


def test_arrays_in_any_layout_and_integer_width_give_the_same_results():
    nodes, tris, bodies, edges, tags, axis = seed_arrays()
    a = seed_model()
    a.solve_contact()
    b = tfem.Model()
    b.set_threads(1)
    b.set_mesh(np.asfortranarray(nodes), np.asfortranarray(tris.astype(np.int32)), bodies.astype(np.int64)[::1])
    b.set_boundary_edges(np.asfortranarray(edges.astype(np.uint16)), list(tags))
    b.set_material(1, 1e10, 0.3)
    b.set_material(2, 1e11, 0.3)
    b.add_pressure(3, 1e7)
    b.fix_edges(4, 1)
    for v in axis:
        b.fix(int(v), 0)
    b.add_contact_pair(1, 2)
    b.solve_contact()
    assert np.array_equal(a.displacements(), b.displacements())


def test_a_c_contiguous_array_of_the_native_dtype_is_passed_without_a_copy():
    nodes = np.zeros((10, 2))
    assert tfem._array(nodes, np.float64, "nodes") is nodes
    tris = np.zeros((4, 3), dtype=np.int64)
    assert tfem._array(tris, np.int64, "triangles") is tris


def test_an_index_out_of_the_native_range_is_refused_not_wrapped():
    nodes, tris, bodies, *_ = seed_arrays()
    with pytest.raises(tfem.InvalidArgument, match="bodies holds 4294967297") as e:
        tfem.Model().set_mesh(nodes, tris, np.full(len(tris), 2**32 + 1))
    assert e.value.status == 2


def test_results_are_numpy_arrays_of_the_mesh_shapes():
    m = seed_model()
    m.solve_contact()
    n, t = len(m.mesh_nodes()), len(m.mesh_triangles())
    assert m.displacements().shape == (n, 2) and m.displacements().dtype == np.float64
    assert m.element_stresses().shape == (t, 3)
    assert m.contact_nodal_pressures().shape == (n,)
    assert m.reactions().shape == (n, 2)
    squared, eta, energy = m.error_estimate()
    assert squared.shape == (t,) and eta > 0 and energy > 0


def test_the_reactions_balance_the_load():
    m = seed_model()
    m.solve_contact()
    assert abs(m.reactions()[:, 1].sum() - 1e7 * 0.2) < 1e-9 * 1e7


def test_solves_on_threads_release_the_gil_and_give_the_same_results():
    serial = seed_model(1 / 128)
    serial.solve_contact()
    expected = serial.displacements()
    # Built first: only the solves run while the Python thread counts.
    models = [seed_model(1 / 128) for _ in range(4)]
    ticks = 0
    stop = threading.Event()

    def count():
        nonlocal ticks
        while not stop.is_set():
            ticks += 1

    counter = threading.Thread(target=count)
    counter.start()
    t0 = time.perf_counter()
    with ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(lambda m: m.solve_contact(), models))
    elapsed = time.perf_counter() - t0
    stop.set()
    counter.join()
    for m in models:
        assert np.array_equal(m.displacements(), expected)
    # A pure-Python loop counts millions per second with the GIL; held by
    # the solves, it would count only in the switch intervals left to it
    # (5 ms each) between them.
    assert ticks > 1e5 * elapsed, (ticks, elapsed)


def test_a_frictionless_load_history_ends_where_one_solve_does():
    m = seed_model()
    m.solve_contact()
    u_full = m.displacements()
    steps = seed_model()
    for k in (0.25, 0.5, 1.0):
        steps.step(k)
    assert np.allclose(steps.displacements(), u_full, rtol=0, atol=1e-10 * np.abs(u_full).max())


def test_an_adaptive_solve_returns_its_cycles_and_the_refined_mesh():
    m = seed_model(1 / 8)
    n0 = len(m.mesh_nodes())
    r = m.solve_adaptive(1e-2, goal="compliance")
    assert r["reached"] and len(r["cycles"]) > 1
    assert r["cycles"][-1]["estimate"] <= 1e-2
    assert len(m.mesh_nodes()) > n0 and m.displacements().shape == (len(m.mesh_nodes()), 2)


def test_a_limit_reached_before_the_tolerance_is_a_tfem_warning():
    m = seed_model(1 / 8)
    with pytest.warns(tfem.Warning, match="limit of cycles"):
        r = m.solve_adaptive(1e-4, goal="compliance", max_cycles=2)
    assert not r["reached"]


def test_a_bad_tolerance_raises_and_changes_nothing():
    m = seed_model(1 / 8)
    n0 = len(m.mesh_nodes())
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(tfem.InvalidArgument, match="tolerance"):
            m.solve_adaptive(bad)
    assert len(m.mesh_nodes()) == n0


def test_a_gmsh_file_of_the_seed_scene_reads_and_solves_with_its_physical_groups(tmp_path):
    gmsh = shutil.which("gmsh")
    if gmsh is None:
        pytest.skip("no gmsh on the PATH (Debian's gmsh)")
    msh = tmp_path / "two_blocks.msh"
    geo = REPO / "examples" / "meshes" / "two_blocks.geo"
    subprocess.run(
        [gmsh, "-2", "-setnumber", "h", "0.03125", "-format", "msh41", str(geo), "-o", str(msh)],
        check=True,
        capture_output=True,
    )
    m = tfem.read_msh(msh)
    _, tags = m.boundary_edges()
    assert set(tags) == {1, 2, 3, 4, 5}
    assert set(m.mesh_bodies()) == {1, 2}
    m.set_material(1, 1e10, 0.3)
    m.set_material(2, 1e11, 0.3)
    m.add_pressure(4, 1e7)
    m.fix_edges(1, "y")
    m.fix_edges(5, "x")
    m.add_contact_pair(2, 3)
    r = m.solve_contact()
    case = json.loads((REPO / "docs/reference/two_blocks_canonical.json").read_text())
    ref = case["cases"]["canonical_0.2"]["lc"]["value"]
    # First order in h: a few percent at h = 1/32.
    assert abs(r["contact_length"] - ref) / ref < 0.1


def test_a_missing_file_raises_io_error_naming_it(tmp_path):
    missing = tmp_path / "nothing.msh"
    with pytest.raises(tfem.IoError, match="nothing.msh"):
        tfem.read_msh(missing)


def test_the_gmsh_python_api_model_becomes_a_tfem_model():
    try:
        import gmsh
    except (ImportError, OSError) as e:  # the wheel needs GL and X libraries
        pytest.skip(f"no gmsh module: {e}")
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("plate")
        s = gmsh.model.occ.addRectangle(0, 0, 0, 1, 0.5)
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(2, [s], 1)
        bottom = [c for _, c in gmsh.model.getBoundary([(2, s)], oriented=False) if abs(gmsh.model.occ.getCenterOfMass(1, c)[1]) < 1e-9]
        gmsh.model.addPhysicalGroup(1, bottom, 5)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.1)
        gmsh.model.mesh.generate(2)
        m = tfem.from_gmsh(gmsh)
    finally:
        gmsh.finalize()
    edges, tags = m.boundary_edges()
    assert set(tags) == {5} and len(m.mesh_triangles()) > 20
    m.set_material(1, 1.0, 0.3)
    m.fix_edges(5, "x")
    m.fix_edges(5, "y")
    m.set_body_force(1, 0.0, -1.0)
    m.solve()
    assert m.displacements()[:, 1].min() < 0


def test_meshio_receives_the_mesh_and_fields():
    meshio = pytest.importorskip("meshio")
    m = seed_model()
    m.solve_contact()
    mesh = tfem.to_meshio(m)
    assert isinstance(mesh, meshio.Mesh)
    assert np.array_equal(mesh.point_data["displacement"], m.displacements())


def test_the_type_stub_is_generated_from_the_module_and_fresh():
    script = REPO / "python" / "gen_stub.py"
    run = subprocess.run([sys.executable, str(script), "--check"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr


def test_every_method_has_a_docstring_from_the_rust_docs():
    for name in dir(tfem._tfem.Model):
        if not name.startswith("_"):
            doc = getattr(tfem._tfem.Model, name).__doc__
            assert doc and doc.strip().endswith("."), name


def test_tempering_off_refuses_a_flat_triangle_that_auto_tempers():
    nodes = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.0], [0.5, 1.0]])
    tris = np.array([[0, 1, 3], [0, 2, 1]])  # the second is flat (J = 0)
    m = tfem.Model()
    m.set_mesh(nodes, tris, [1, 1])
    m.set_material(1, 1.0, 0.3)
    for v in (0, 1):
        m.fix(v, "x")
        m.fix(v, "y")
    m.add_nodal_force(3, 0.0, -1.0)
    m.solve()
    m.set_tempering("off")
    with pytest.raises(tfem.DegenerateElement, match="triangle 1"):
        m.solve()
    with pytest.raises(tfem.InvalidArgument, match="needs a value"):
        m.set_tempering("lambda")
