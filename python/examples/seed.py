"""The seed scene from Python: two blocks pressed together, the contact
length, the gap at the corner, the top's settlement and the compliance
against the converged reference; with ``--plot``, the seed's Fig. 5 (the
deformed blocks coloured by v) and Fig. 6 (the contact length against h
for 2C/L = 0.2, 0.4, 0.6) drawn with matplotlib.

    python python/examples/seed.py [--h 0.015625] [--plot]
"""

import argparse
import json
import pathlib

import numpy as np

import tfem
from tfem.meshing import Assembly

L, H, E1, E2, NU, P = 1.0, 0.25, 1e10, 1e11, 0.3, 1e7


def seed(c: float, h: float):
    """The two blocks, 2C/L = 2c, mesh size h; the solved model and its mesh."""
    xs = np.union1d(np.linspace(0, L, round(L / h) + 1), [L / 2 - c, L / 2, L / 2 + c])
    ys = np.linspace(0, H, round(H / h) + 1)
    mesh = Assembly()
    mesh.add_grid(xs, ys - H, body=1)  # Ω1, below y = 0
    mesh.add_grid(xs, ys, body=2)  # Ω2, above, with its own nodes on y = 0
    eps = 1e-9 * L
    mesh.tag(1, body=1, where=lambda x, y: abs(y) < eps)  # Ω1's top
    mesh.tag(2, body=2, where=lambda x, y: abs(y) < eps)  # Ω2's bottom
    mesh.tag(3, body=2, where=lambda x, y: abs(y - H) < eps and abs(x - L / 2) < c)  # loaded
    mesh.tag(4, body=1, where=lambda x, y: abs(y + H) < eps and abs(x - L / 2) < c)  # support
    m = tfem.Model()
    mesh.into(m)
    m.set_material(1, E1, NU, "strain")
    m.set_material(2, E2, NU, "strain")
    m.add_pressure(3, P)
    m.fix_edges(4, "y")
    for v in mesh.nodes_where(lambda x, y: abs(x - L / 2) < eps):
        m.fix(int(v), "x")
    m.add_contact_pair(1, 2)
    report = m.solve_contact()
    return m, report


def outputs(m: tfem.Model, report: dict, c: float) -> dict:
    """ℓc, gap_edge, v_top and the compliance, as the reference defines them."""
    x, u = m.mesh_nodes(), m.displacements()
    bodies = np.zeros(len(x), dtype=int)
    bodies[m.mesh_triangles().ravel()] = np.repeat(m.mesh_bodies(), 3)
    at = lambda px, py, b: np.flatnonzero((np.hypot(*(x - [px, py]).T) < 1e-9) & (bodies == b))[0]
    edges, tags = m.boundary_edges()
    loaded = edges[tags == 3]
    lengths = np.abs(x[loaded[:, 1], 0] - x[loaded[:, 0], 0])
    return {
        "lc": report["contact_length"],
        "gap_edge": u[at(0, 0, 2), 1] - u[at(0, 0, 1), 1],
        "v_top": u[at(L / 2, H, 2), 1],
        "compliance": float(np.sum(P * lengths * -0.5 * (u[loaded[:, 0], 1] + u[loaded[:, 1], 1]))),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--h", type=float, default=1 / 64)
    parser.add_argument("--plot", action="store_true")
    args = parser.parse_args()
    m, report = seed(0.1, args.h)
    out = outputs(m, report, 0.1)
    refs = pathlib.Path(__file__).resolve().parents[2] / "docs/reference/two_blocks_canonical.json"
    case = json.loads(refs.read_text())["cases"]["canonical_0.2"]
    print(f"seed scene, 2C/L = 0.2, h = {args.h:g}: {report['unknowns']} unknowns, "
          f"{report['iterations']} contact iterations")
    for k, v in out.items():
        ref, err = case[k]["value"], case[k]["err"]
        print(f"  {k:10s} {v: .6e}   reference {ref: .6e} ± {err:.1e}   relative error {(v - ref) / ref:+.2e}")
    if args.plot:
        plot(m)


def plot(m: tfem.Model) -> None:
    """Fig. 5 and Fig. 6 of the seed, as PNG files in the working directory."""
    import matplotlib  # noqa: PLC0415

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415

    x, u, tri = m.mesh_nodes(), m.displacements(), m.mesh_triangles()
    scale = 0.05 * L / np.abs(u).max()
    fig, ax = plt.subplots(figsize=(8, 4))
    shape = ax.tripcolor(*(x + scale * u).T, tri, u[:, 1], shading="gouraud", cmap="viridis")
    fig.colorbar(shape, label="v [m]")
    ax.set_aspect("equal")
    ax.set_title(f"Fig. 5: deformed blocks (displacements ×{scale:.0f}), 2C/L = 0.2")
    fig.savefig("seed_fig5.png", dpi=120)
    fig, ax = plt.subplots(figsize=(6, 4))
    hs = [1 / 16, 1 / 32, 1 / 64, 1 / 128]
    for c in (0.1, 0.2, 0.3):
        lc = [seed(c, h)[1]["contact_length"] for h in hs]
        ax.semilogx(hs, lc, "o-", label=f"2C/L = {2 * c:.1f}")
    ax.set_xlabel("h [m]")
    ax.set_ylabel("ℓc [m]")
    ax.set_title("Fig. 6: contact length against the mesh size")
    ax.legend()
    fig.savefig("seed_fig6.png", dpi=120)
    print("wrote seed_fig5.png, seed_fig6.png")


if __name__ == "__main__":
    main()
