"""Hertz contact from a Gmsh-made mesh: an elastic cylinder (radius R) on
an elastic block, half model, meshed with Gmsh's Python API and graded
towards the contact; the contact half-width a and peak pressure p0
against Hertz's a = (4PR/(πE*))^½, p0 = 2P/(πa).

    pip install gmsh
    python python/examples/hertz_gmsh.py [--h 0.00125]
"""

import argparse
import math

import numpy as np

import tfem

R, E, NU = 1.0, 2e11, 0.3
A = 0.02 * R  # the half-width the load is chosen for
E_STAR = E / (2 * (1 - NU**2))
LOAD = math.pi * A * A * E_STAR / (4 * R)  # P per unit thickness, whole cylinder
BLOCK, CYLINDER = 1, 2
BLOCK_TOP, ARC, CHORD, SUPPORT, AXIS = 11, 12, 13, 14, 15


def mesh_with_gmsh(size_at_contact: float) -> tfem.Model:
    import gmsh  # noqa: PLC0415  (the example's one optional dependency)

    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        occ = gmsh.model.occ
        block = occ.addRectangle(0, -2 * R, 0, 2 * R, 2 * R)
        disk = occ.addDisk(0, R, 0, R, R)
        box = occ.addRectangle(0, 0, 0, 0.8 * R, R)
        (cylinder, *_), _ = occ.intersect([(2, disk)], [(2, box)])
        occ.synchronize()
        gmsh.model.addPhysicalGroup(2, [block], BLOCK)
        gmsh.model.addPhysicalGroup(2, [cylinder[1]], CYLINDER)
        curves = {BLOCK_TOP: [], ARC: [], CHORD: [], SUPPORT: [], AXIS: []}
        for dim, surface in ((2, block), cylinder):
            for _, c in gmsh.model.getBoundary([(2, surface)], oriented=False):
                x, y, _ = occ.getCenterOfMass(1, c)
                if abs(x) < 1e-9:
                    curves[AXIS].append(c)
                elif surface == block and abs(y) < 1e-9:
                    curves[BLOCK_TOP].append(c)
                elif surface == block and abs(y + 2 * R) < 1e-9:
                    curves[SUPPORT].append(c)
                elif surface != block and abs(y - R) < 1e-9:
                    curves[CHORD].append(c)
                elif surface != block and y < R and x < 0.8 * R - 1e-9:
                    curves[ARC].append(c)
        for tag, cs in curves.items():
            gmsh.model.addPhysicalGroup(1, cs, tag)
        # The contact's size within 1.5a of the contact point, growing
        # linearly beyond.
        field = gmsh.model.mesh.field
        size = field.add("MathEval")
        grow = f"0.2 * (Sqrt(x^2 + y^2) - {1.5 * A})"
        field.setString(size, "F", f"Min({0.2 * R}, Max({size_at_contact}, {grow}))")
        field.setAsBackgroundMesh(size)
        for option in ("MeshSizeFromPoints", "MeshSizeFromCurvature", "MeshSizeExtendFromBoundary"):
            gmsh.option.setNumber(f"Mesh.{option}", 0)
        gmsh.model.mesh.generate(2)
        return tfem.from_gmsh(gmsh)
    finally:
        gmsh.finalize()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--h", type=float, default=A / 16, help="element size at the contact")
    args = parser.parse_args()
    m = mesh_with_gmsh(args.h)
    for body in (BLOCK, CYLINDER):
        m.set_material(body, E, NU, "strain")
    m.fix_edges(AXIS, "x")
    m.fix_edges(SUPPORT, "y")
    m.add_pressure(CHORD, 0.5 * LOAD / (0.8 * R))  # half the load on the half model
    m.add_contact_pair(BLOCK_TOP, ARC)
    r = m.solve_contact()
    print(f"{r['unknowns']} unknowns, {r['iterations']} contact iterations")
    x, p = m.mesh_nodes(), m.contact_nodal_pressures()
    edges, tags = m.boundary_edges()
    top = np.unique(edges[tags == BLOCK_TOP])
    top = top[np.argsort(x[top, 0])]
    pressed = np.flatnonzero(p[top] > 1e-9 * p[top].max())
    # p² falls linearly to zero at the edge (p ∝ √(a² − x²)): extrapolated
    # from the last two pressed nodes, at most to the first free one.
    k = pressed[-1]
    (x1, p1), (x2, p2) = (x[top[k - 1], 0], p[top[k - 1]]), (x[top[k], 0], p[top[k]])
    a = min(x2 + p2**2 * (x2 - x1) / (p1**2 - p2**2), x[top[k + 1], 0]) if p1 > p2 else x2
    p0 = p[top[0]]
    a_exact, p0_exact = A, 2 * LOAD / (math.pi * A)
    print(f"a  = {a:.5e}   Hertz {a_exact:.5e}   relative {(a - a_exact) / a_exact:+.2e}")
    print(f"p0 = {p0:.5e}   Hertz {p0_exact:.5e}   relative {(p0 - p0_exact) / p0_exact:+.2e}")


if __name__ == "__main__":
    main()
