#!/usr/bin/env python3
"""Writes a CalculiX (ccx 2.20) deck for tfem's seed scene in 3D, quarter model.

Lower block [0, 1/2]^2 x [-H1, 0] (E1), upper block [0, 1/2]^2 x [0, H2]
(E2), nu both; uniform hexahedra of size h (h must divide 0.1 and 0.25),
the two blocks meshed separately with coincident, unmerged interface nodes.
Symmetry u_x = 0 on x = 1/2 and u_y = 0 on y = 1/2 (both blocks); pressure
p on the upper block's top over x, y in [1/2 - C, 1/2]; u_z = 0 on the
lower block's bottom nodes there. Frictionless penalty contact, LINEAR
pressure-overclosure with slope K [Pa/m], slave = the lower (softer)
block's top faces, master = the upper block's bottom faces:
  --contact n2s (default): NODE TO SURFACE, K = 1e15, sigma_inf = 1 Pa;
  --contact s2s: SURFACE TO SURFACE (ccx 2.20 refuses SMALL SLIDING with
    it), use --penalty 1e16; it chatters and may stop unconverged (parse.py
    flags it).

Writes JOB.inp and JOB.meta.json (what parse.py reads).

    python3 gen_deck.py --h 0.025 --out /tmp/seed3d/job
"""

import argparse
import json
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--h", type=float, required=True)
    ap.add_argument("--element", choices=["C3D8", "C3D8I"], default="C3D8")
    ap.add_argument("--penalty", type=float, default=1e15, help="K [Pa/m]")
    ap.add_argument("--contact", choices=["s2s", "n2s"], default="n2s",
                    help="SURFACE TO SURFACE or NODE TO SURFACE (then sigma_inf = 1 Pa)")
    ap.add_argument("--delcon", type=float, default=None,
                    help="*CONTROLS, PARAMETERS=CONTACT first value: the relative change in "
                         "the number of contact elements ccx accepts as converged (its default 1e-3)")
    ap.add_argument("--out", required=True, help="job path without .inp")
    a = ap.parse_args()
    L, H1, H2, C, p = 1.0, 0.25, 0.25, 0.1, 1e7
    E1, E2, nu = 1e10, 1e11, 0.3
    half = L / 2

    def cells(length):
        n = round(length / a.h)
        assert n >= 1 and abs(n * a.h - length) < 1e-9, f"h must divide {length}"
        return n

    nx, nz1, nz2, nc = cells(half), cells(H1), cells(H2), cells(C)
    coords, ids = [], {}  # ids[(body, i, j, k)] = node number

    def node(b, i, j, k):
        key = (b, i, j, k)
        if key not in ids:
            z = -H1 + H1 * k / nz1 if b == 1 else H2 * k / nz2
            coords.append((half * i / nx, half * j / nx, z))
            ids[key] = len(coords)
        return ids[key]

    elems = []  # (body, i, j, k, 8 nodes)
    for b, nz in ((1, nz1), (2, nz2)):
        for k in range(nz):
            for j in range(nx):
                for i in range(nx):
                    c = [node(b, i + di, j + dj, k + dk) for dk in (0, 1)
                         for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                    elems.append((b, i, j, k, c))
    i0 = nx - nc  # first grid index of the loaded / supported square
    sym_x = [n for (b, i, j, k), n in ids.items() if i == nx]
    sym_y = [n for (b, i, j, k), n in ids.items() if j == nx]
    support = [n for (b, i, j, k), n in ids.items() if b == 1 and k == 0 and i >= i0 and j >= i0]
    slave = [(e, 2) for e, (b, i, j, k, _) in enumerate(elems, 1) if b == 1 and k == nz1 - 1]
    master = [(e, 1) for e, (b, i, j, k, _) in enumerate(elems, 1) if b == 2 and k == 0]
    loaded = [(e, 2) for e, (b, i, j, k, _) in enumerate(elems, 1)
              if b == 2 and k == nz2 - 1 and i >= i0 and j >= i0]
    loaded_faces = [elems[e - 1][4][4:] for e, _ in loaded]  # the top face's 4 nodes
    top_nodes = sorted({n for f in loaded_faces for n in f})
    if_lower = {(i, j): ids[(1, i, j, nz1)] for i in range(nx + 1) for j in range(nx + 1)}
    if_upper = {(i, j): ids[(2, i, j, 0)] for i in range(nx + 1) for j in range(nx + 1)}

    def write_list(f, head, items):
        f.write(head + "\n")
        for s in range(0, len(items), 12):
            f.write(", ".join(map(str, items[s:s + 12])) + ",\n")

    job = a.out
    os.makedirs(os.path.dirname(os.path.abspath(job)), exist_ok=True)
    with open(job + ".inp", "w") as f:
        f.write(f"** tfem seed scene 3D, quarter; h = {a.h!r}, {a.element}, K = {a.penalty!r}\n")
        f.write("*NODE, NSET=NALL\n")
        for n, (x, y, z) in enumerate(coords, 1):
            f.write(f"{n}, {x!r}, {y!r}, {z!r}\n")
        for body in (1, 2):
            f.write(f"*ELEMENT, TYPE={a.element}, ELSET=EB{body}\n")
            for e, (b, *_, c) in enumerate(elems, 1):
                if b == body:
                    f.write(f"{e}, " + ", ".join(map(str, c)) + "\n")
        f.write(f"*MATERIAL, NAME=M1\n*ELASTIC\n{E1!r}, {nu!r}\n")
        f.write(f"*MATERIAL, NAME=M2\n*ELASTIC\n{E2!r}, {nu!r}\n")
        f.write("*SOLID SECTION, ELSET=EB1, MATERIAL=M1\n*SOLID SECTION, ELSET=EB2, MATERIAL=M2\n")
        write_list(f, "*NSET, NSET=NSYMX", sorted(sym_x))
        write_list(f, "*NSET, NSET=NSYMY", sorted(sym_y))
        write_list(f, "*NSET, NSET=NSUP", sorted(support))
        write_list(f, "*NSET, NSET=NOUT", sorted(set(top_nodes) | set(if_lower.values())
                                                  | set(if_upper.values())))
        f.write("*SURFACE, NAME=SLOWER, TYPE=ELEMENT\n")
        f.writelines(f"{e}, S{s}\n" for e, s in slave)
        f.write("*SURFACE, NAME=SUPPER, TYPE=ELEMENT\n")
        f.writelines(f"{e}, S{s}\n" for e, s in master)
        f.write("*SURFACE INTERACTION, NAME=SI\n")
        tension = ", 1.0" if a.contact == "n2s" else ""  # sigma_inf: see docs/calculix.md
        f.write(f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{a.penalty!r}{tension}\n")
        ctype = "SURFACE TO SURFACE" if a.contact == "s2s" else "NODE TO SURFACE"
        f.write(f"*CONTACT PAIR, INTERACTION=SI, TYPE={ctype}\nSLOWER, SUPPER\n")
        f.write("*BOUNDARY\nNSYMX, 1, 1, 0.0\nNSYMY, 2, 2, 0.0\nNSUP, 3, 3, 0.0\n")
        f.write("*STEP, INC=1000\n*STATIC, SOLVER=SPOOLES\n1.0, 1.0\n")
        if a.delcon is not None:
            f.write(f"*CONTROLS, PARAMETERS=CONTACT\n{a.delcon!r}\n")
        f.write("*DLOAD\n")
        f.writelines(f"{e}, P{s}, {p!r}\n" for e, s in loaded)
        f.write("*NODE PRINT, NSET=NOUT\nU\n")
        f.write("*NODE PRINT, NSET=NSUP, TOTALS=ONLY\nRF\n")
        f.write("*CONTACT FILE\nCDIS, CSTR\n")
        f.write("*END STEP\n")

    meta = {
        "h": a.h, "element": a.element, "penalty": a.penalty, "contact": a.contact,
        "delcon": a.delcon, "p": p, "nx": nx,
        "nodes": len(coords), "elements": len(elems),
        "dofs": 3 * len(coords), "dofs_free": 3 * len(coords) - len(sym_x) - len(sym_y) - len(support),
        "loaded_faces": loaded_faces, "face_area": (half / nx) ** 2,
        "top_center": ids[(2, nx, nx, nz2)],
        "corner_lower": ids[(1, 0, 0, nz1)], "corner_upper": ids[(2, 0, 0, 0)],
        # interface grid, row j, column i: node numbers of the slave / master side
        "if_lower": [[if_lower[(i, j)] for i in range(nx + 1)] for j in range(nx + 1)],
        "if_upper": [[if_upper[(i, j)] for i in range(nx + 1)] for j in range(nx + 1)],
    }
    with open(job + ".meta.json", "w") as f:
        json.dump(meta, f)


if __name__ == "__main__":
    main()
