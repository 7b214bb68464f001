#!/usr/bin/env python3
"""Writes a CalculiX (ccx 2.20) input deck for tfem's seed scene.

The seed scene (docs/method.md §4, canonical parameters): two blocks
[0, L] x [-H1, 0] (E1, nu1) and [0, L] x [0, H2] (E2, nu2), touching along
y = 0, plane strain; a pressure p on the top of the upper block over
x in [L/2 - C, L/2 + C]; u_y = 0 on the bottom of the lower block over the
same range; u_x = 0 on x = L/2 in both blocks; contact (frictionless or
Coulomb friction mu) between the two.

The mesh is tfem's (src/studies/meshgen.rs, src/studies/scenes.rs): the
same grid lines (subdivide_symmetric with stops at L/2 +- C, subdivide in y)
and, for CPE3, the same triangles (each cell split along "/" left of L/2
and "\\" right of it), numbered in the same order (lower block first, row
by row). For CPE4 each grid cell is one quadrilateral.

Besides JOB.inp, writes JOB.meta.json: the node numbers the parser reads
the outputs at, the interface nodes and the loaded edges.

    python3 gen_deck.py --h 0.0078125 --mu 0.3 --steps 10 --out run/job
"""

import argparse
import json
import math
import os
import sys


def subdivide(a, b, stops, h):
    """tfem's meshgen::subdivide: spacing at most h, through every stop."""
    knots = [a] + [s for s in stops if a < s < b] + [b]
    out = [a]
    for w0, w1 in zip(knots, knots[1:]):
        n = max(1, math.ceil((w1 - w0) / h - 1e-9))
        for k in range(1, n + 1):
            out.append(w1 if k == n else w0 + (w1 - w0) * k / n)
    return out


def subdivide_symmetric(a, b, stops, h):
    """tfem's meshgen::subdivide_symmetric: mirror-symmetric about (a+b)/2."""
    mid = 0.5 * (a + b)
    half = subdivide(a, mid, [s for s in stops if a < s < mid], h)
    out = list(half)
    for x in reversed(half[:-1]):
        out.append(mid + (mid - x))
    out[-1] = b
    return out


def build(args):
    L, H1, H2, C = args.length, args.h1, args.h2, args.c
    mid = 0.5 * L
    xs = subdivide_symmetric(0.0, L, [mid - C, mid + C], args.h)
    ys1 = subdivide(-H1, 0.0, [], args.h)
    ys2 = subdivide(0.0, H2, [], args.h)
    nodes = []  # (x, y), node k has CalculiX number k + 1
    elems = []  # (body, [node numbers, counter-clockwise])

    def grid(ys, body):
        rows = []
        for y in ys:
            row = []
            for x in xs:
                nodes.append((x, y))
                row.append(len(nodes))
            rows.append(row)
        for j in range(len(ys) - 1):
            for i in range(len(xs) - 1):
                a, b = rows[j][i], rows[j][i + 1]
                c, d = rows[j + 1][i + 1], rows[j + 1][i]
                if args.element == "CPE4":
                    elems.append((body, [a, b, c, d]))
                elif 0.5 * (xs[i] + xs[i + 1]) < mid:  # Diagonal::MirroredAt
                    elems.append((body, [a, b, c]))
                    elems.append((body, [a, c, d]))
                else:
                    elems.append((body, [a, b, d]))
                    elems.append((body, [b, c, d]))
        return rows

    lower = grid(ys1, 1)
    upper = grid(ys2, 2)
    return xs, ys1, ys2, nodes, elems, lower, upper


def faces_on(elems, nodes, body, pred):
    """(element, face label) of every element edge of `body` whose two ends
    satisfy pred; CalculiX numbers the edges of a 2D element 1-2, 2-3, ...
    as faces S1, S2, ... (P1, P2, ... for *DLOAD)."""
    out = []
    for e, (b, conn) in enumerate(elems, start=1):
        if b != body:
            continue
        n = len(conn)
        for k in range(n):
            p, q = conn[k], conn[(k + 1) % n]
            if pred(nodes[p - 1]) and pred(nodes[q - 1]):
                out.append((e, k + 1, p, q))
    return out


def write_set(f, keyword, items, per_line=10):
    f.write(keyword + "\n")
    for k in range(0, len(items), per_line):
        f.write(", ".join(str(i) for i in items[k:k + per_line]) + ",\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--h", type=float, required=True, help="element size h [m]")
    ap.add_argument("--mu", type=float, default=0.0, help="Coulomb friction coefficient")
    ap.add_argument("--steps", type=int, default=1,
                    help="number of increments N (fixed: *STATIC, DIRECT, 1/N)")
    ap.add_argument("--element", choices=["CPE3", "CPE4"], default="CPE3")
    ap.add_argument("--contact", choices=["n2s", "s2s"], default="n2s",
                    help="NODE TO SURFACE or SURFACE TO SURFACE penalty contact")
    ap.add_argument("--slave", choices=["lower", "upper"], default="lower",
                    help="the slave (dependent) side; lower = the softer block")
    ap.add_argument("--penalty", type=float, default=None,
                    help="normal spring constant K [Pa/m] (default: E_c*lambda/h_c^2 with "
                         "tfem's defaults E_c = the softer E, lambda = the model size L, h_c = "
                         "the shortest interface edge: tfem's contact penalty per unit length)")
    ap.add_argument("--hard", action="store_true",
                    help="PRESSURE-OVERCLOSURE=HARD with no data: ccx 2.20 turns it into "
                         "its LINEAR law with K = 50 x E of the first material (5e11 Pa/m "
                         "here) and sigma_inf = E/70000 (--penalty, --tension ignored)")
    ap.add_argument("--tension", type=float, default=1.0,
                    help="sigma_inf of the LINEAR law: the tension a node-to-surface "
                         "spring keeps at large clearance [Pa] (default 1 Pa; 0: ccx's "
                         "own default, E1/70000 = 1.4e5 Pa here, which halves gap_edge "
                         "at h = 1/16)")
    ap.add_argument("--stick-slope", type=float, default=None,
                    help="stick slope of *FRICTION [Pa/m] (default: K)")
    ap.add_argument("--controls", default=None,
                    help="R_n,C_n for *CONTROLS, PARAMETERS=FIELD (default: ccx's)")
    ap.add_argument("--auto", action="store_true",
                    help="automatic incrementation (no DIRECT): ccx may cut back and "
                         "change the increment; N only sets the first increment")
    ap.add_argument("--solver", default="SPOOLES")
    ap.add_argument("--e1", type=float, default=1e10)
    ap.add_argument("--nu1", type=float, default=0.3)
    ap.add_argument("--e2", type=float, default=1e11)
    ap.add_argument("--nu2", type=float, default=0.3)
    ap.add_argument("--h1", type=float, default=0.25)
    ap.add_argument("--h2", type=float, default=0.25)
    ap.add_argument("--length", type=float, default=1.0)
    ap.add_argument("--c", type=float, default=0.1)
    ap.add_argument("--p", type=float, default=1e7)
    ap.add_argument("--out", required=True, help="job path without .inp")
    args = ap.parse_args()
    if args.steps < 1:
        sys.exit("--steps must be >= 1")

    xs, ys1, ys2, nodes, elems, lower, upper = build(args)
    L, C, mid = args.length, args.c, 0.5 * args.length
    tol = 1e-12 * L
    hmin = min(b - a for a, b in zip(xs, xs[1:]))
    lam = max(L, args.h1 + args.h2)  # tfem's default lambda: the bounding box's larger side
    K = args.penalty if args.penalty else min(args.e1, args.e2) * lam / hmin ** 2
    if args.hard:
        K = 50.0 * args.e1  # what ccx makes of HARD (surfacebehaviors.f)
    stick = args.stick_slope if args.stick_slope else K

    def loaded(x):
        return mid - C - tol <= x <= mid + C + tol

    # interface faces (y = 0) of each body, support and loaded faces
    if_lower = faces_on(elems, nodes, 1, lambda p: abs(p[1]) <= tol)
    if_upper = faces_on(elems, nodes, 2, lambda p: abs(p[1]) <= tol)
    load = faces_on(elems, nodes, 2,
                    lambda p: abs(p[1] - args.h2) <= tol and loaded(p[0]))
    support_nodes = [k for k in lower[0] if loaded(nodes[k - 1][0])]
    i_mid = xs.index(mid)
    sym_nodes = [row[i_mid] for row in lower] + [row[i_mid] for row in upper]
    corner_lower = lower[-1][0]
    corner_upper = upper[0][0]
    top_center = upper[-1][i_mid]
    load_nodes = sorted({n for f in load for n in f[2:]})
    if_lower_nodes = list(lower[-1])
    if_upper_nodes = list(upper[0])

    slave, master = ("SLOWER", "SUPPER") if args.slave == "lower" else ("SUPPER", "SLOWER")
    etype = args.element
    job = args.out
    os.makedirs(os.path.dirname(os.path.abspath(job)), exist_ok=True)
    with open(job + ".inp", "w") as f:
        f.write("** tfem seed scene for CalculiX 2.20, written by scripts/calculix/gen_deck.py\n")
        f.write(f"** h = {args.h!r}, mu = {args.mu!r}, increments N = {args.steps}, "
                f"{etype}, contact {args.contact}, K = {K!r} Pa/m\n")
        f.write("*HEADING\ntfem seed scene (docs/method.md section 4)\n")
        f.write("*NODE, NSET=NALL\n")
        for k, (x, y) in enumerate(nodes, start=1):
            f.write(f"{k}, {x!r}, {y!r}, 0.0\n")
        for body in (1, 2):
            f.write(f"*ELEMENT, TYPE={etype}, ELSET=EBODY{body}\n")
            for e, (b, conn) in enumerate(elems, start=1):
                if b == body:
                    f.write(f"{e}, " + ", ".join(map(str, conn)) + "\n")
        f.write("*MATERIAL, NAME=M1\n*ELASTIC\n"
                f"{args.e1!r}, {args.nu1!r}\n")
        f.write("*MATERIAL, NAME=M2\n*ELASTIC\n"
                f"{args.e2!r}, {args.nu2!r}\n")
        # plane strain: the thickness (1 m, forces per metre) is the same for all
        f.write("*SOLID SECTION, ELSET=EBODY1, MATERIAL=M1\n1.0\n")
        f.write("*SOLID SECTION, ELSET=EBODY2, MATERIAL=M2\n1.0\n")
        write_set(f, "*NSET, NSET=NSYM", sym_nodes)
        write_set(f, "*NSET, NSET=NSUPPORT", support_nodes)
        write_set(f, "*NSET, NSET=NOUT",
                  sorted({corner_lower, corner_upper, top_center}
                         | set(load_nodes) | set(if_lower_nodes) | set(if_upper_nodes)))
        f.write("*SURFACE, NAME=SLOWER, TYPE=ELEMENT\n")
        for e, k, _, _ in if_lower:
            f.write(f"{e}, S{k}\n")
        f.write("*SURFACE, NAME=SUPPER, TYPE=ELEMENT\n")
        for e, k, _, _ in if_upper:
            f.write(f"{e}, S{k}\n")
        f.write("*SURFACE INTERACTION, NAME=SI\n")
        if args.hard:
            f.write("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n")
        else:
            f.write("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n")
            f.write(f"{K!r}" + (f", {args.tension!r}" if args.tension else "") + "\n")
        if args.mu > 0:
            f.write(f"*FRICTION\n{args.mu!r}, {stick!r}\n")
        ctype = "NODE TO SURFACE" if args.contact == "n2s" else "SURFACE TO SURFACE"
        f.write(f"*CONTACT PAIR, INTERACTION=SI, TYPE={ctype}\n{slave}, {master}\n")
        f.write("*BOUNDARY\nNSYM, 1, 1, 0.0\nNSUPPORT, 2, 2, 0.0\n")
        f.write(f"*STEP, INC={max(1000, 10 * args.steps)}\n")
        direct = "" if args.auto else "DIRECT, "
        f.write(f"*STATIC, {direct}SOLVER={args.solver}\n")
        f.write(f"{1.0 / args.steps!r}, 1.0\n")
        if args.controls:
            rn, cn = args.controls.split(",")
            f.write(f"*CONTROLS, PARAMETERS=FIELD\n{rn}, {cn}\n")
        f.write("*DLOAD\n")
        for e, k, _, _ in load:
            f.write(f"{e}, P{k}, {args.p!r}\n")
        # only the last increment's results
        f.write("*NODE PRINT, NSET=NOUT, FREQUENCY=100000\nU\n")
        f.write("*CONTACT PRINT, FREQUENCY=100000\nCSTR, CDIS\n")
        # no *NODE FILE: the .frd file is not read (ccx still writes its header)
        f.write("*END STEP\n")

    n2d = len(nodes)
    meta = {
        "h": args.h, "mu": args.mu, "steps": args.steps, "element": etype,
        "contact": args.contact, "slave": args.slave, "penalty": K,
        "stick_slope": stick if args.mu > 0 else None,
        "tension": None if args.hard else args.tension, "hard": args.hard,
        "controls": args.controls, "auto": args.auto,
        "params": {"E1": args.e1, "nu1": args.nu1, "E2": args.e2, "nu2": args.nu2,
                   "H1": args.h1, "H2": args.h2, "L": L, "C": C, "p": args.p},
        "nodes_2d": n2d, "elements": len(elems),
        "dofs_2d": 2 * n2d,
        "dofs_free_2d": 2 * n2d - len(sym_nodes) - len(support_nodes),
        "corner_lower": corner_lower, "corner_upper": corner_upper,
        "top_center": top_center,
        "load_edges": [[p, q] for _, _, p, q in load],
        "interface_lower": if_lower_nodes, "interface_upper": if_upper_nodes,
        "coords": {str(n): nodes[n - 1] for n in
                   sorted(set(if_lower_nodes) | set(if_upper_nodes) | set(load_nodes)
                          | {corner_lower, corner_upper, top_center})},
    }
    with open(job + ".meta.json", "w") as f:
        json.dump(meta, f)


if __name__ == "__main__":
    main()
