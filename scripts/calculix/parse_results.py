#!/usr/bin/env python3
"""Reads a finished CalculiX run of the seed scene (JOB.dat, JOB.sta,
JOB.12d, JOB.meta.json written by gen_deck.py, and ccx's screen output)
and prints one JSON object with tfem's outputs (docs/method.md §4):

  gap_edge    u_y(upper) - u_y(lower) at the corner (0, 0)
  slip_edge   u_x(upper) - u_x(lower) at the corner (0, 0)
  v_top       u_y of the upper block at (L/2, H2)
  compliance  integral over the loaded segment of p * (-u_y) (exact for
              linear edges: p * edge length * mean of the two end values)
  lc          contact length: the summed tributary length (half of each
              adjacent interface edge) of the slave nodes with a contact
              pressure > 0
  max_penetration, p_max, and (with --profile) the pressure and shear
  at each slave node.

CalculiX expands each 2D node into nodes on both faces of a slab (JOB.12d
lists the expansion); contact output is per expanded slave node, and the
two expanded copies of a 2D node are averaged.

    python3 parse_results.py run/job [--log run/job.log] [--profile]
"""

import argparse
import json
import math
import re
import sys


def blocks(path, title_regex):
    """Every block of the .dat file whose title matches, as a list of rows
    (lists of floats, the first one the node number)."""
    out, cur = [], None
    rx = re.compile(title_regex)
    with open(path) as f:
        for line in f:
            s = line.strip()
            if rx.search(s):
                cur = []
                out.append(cur)
                continue
            if cur is None:
                continue
            if not s:
                if cur:  # a blank line after the rows ends the block
                    cur = None
                continue
            parts = s.split()
            try:
                cur.append([float(p) for p in parts])
            except ValueError:
                cur = None
    return out


def expansion(path):
    """Expanded node -> 2D node, from JOB.12d."""
    m = {}
    with open(path) as f:
        lines = f.read().split("ELEMENT")
    for chunk in lines[1:]:
        head, _, rest = chunk.partition("with nodes:")
        nodes2d, _, rest = rest.partition("is expanded into")
        topo = rest.partition("with topology:")[2]
        n2 = [int(x) for x in nodes2d.split()]
        n3 = [int(x) for x in topo.split()]
        k = len(n2)
        if len(n3) < 2 * k:
            continue
        for i in range(k):
            m[n3[i]] = n2[i]
            m[n3[i + k]] = n2[i]
    return m


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("job")
    ap.add_argument("--log", default=None, help="ccx's screen output")
    ap.add_argument("--profile", action="store_true",
                    help="include the pressure profile along the interface")
    args = ap.parse_args()
    job = args.job
    meta = json.load(open(job + ".meta.json"))
    coords = {int(k): v for k, v in meta["coords"].items()}
    p = meta["params"]["p"]

    disp = blocks(job + ".dat", r"^displacements \(vx,vy,vz\) for set NOUT")
    if not disp:
        sys.exit(f"{job}.dat: no displacements (did ccx finish?)")
    u = {int(r[0]): (r[1], r[2]) for r in disp[-1]}
    cl, cu, top = meta["corner_lower"], meta["corner_upper"], meta["top_center"]
    res = {
        "gap_edge": u[cu][1] - u[cl][1],
        "slip_edge": u[cu][0] - u[cl][0],
        "v_top": u[top][1],
    }
    comp = 0.0
    for a, b in meta["load_edges"]:
        length = math.dist(coords[a], coords[b])
        comp += p * length * -0.5 * (u[a][1] + u[b][1])
    res["compliance"] = comp

    # contact: per expanded slave node, averaged over the copies of a 2D node
    cstr = blocks(job + ".dat", r"^contact stress \(slave node")
    cdis = blocks(job + ".dat", r"^relative contact displacement \(slave node")
    emap = expansion(job + ".12d")
    acc = {}
    for r in (cstr[-1] if cstr else []):
        n2 = emap.get(int(r[0]), int(r[0]))
        a = acc.setdefault(n2, [0.0, 0.0, 0.0, 0])
        a[0] += r[1]
        a[1] += r[2]
        a[3] += 1
    for r in (cdis[-1] if cdis else []):
        n2 = emap.get(int(r[0]), int(r[0]))
        if n2 in acc:
            a = acc[n2]
            a[2] = max(a[2], -r[1])  # ccx 2.20: normal < 0 is an overclosure
    slave = meta["interface_lower"] if meta["slave"] == "lower" else meta["interface_upper"]
    xs = [coords[n][0] for n in slave]
    trib = []
    for i in range(len(xs)):
        left = xs[i] - xs[i - 1] if i > 0 else 0.0
        right = xs[i + 1] - xs[i] if i + 1 < len(xs) else 0.0
        trib.append(0.5 * (left + right))
    lc, pmax, pen, profile = 0.0, 0.0, 0.0, []
    for n, x, t in zip(slave, xs, trib):
        if n in acc:
            a = acc[n]
            pn, pt, k = a[0] / a[3], a[1] / a[3], a[3]
        else:
            pn, pt = 0.0, 0.0
        if pn > 0:
            lc += t
            pen = max(pen, acc[n][2])
        pmax = max(pmax, pn)
        profile.append([x, pn, pt])
    res.update({"lc": lc, "p_max": pmax, "max_penetration": pen,
                "active_slave_nodes": sum(1 for q in profile if q[1] > 0)})

    # iterations and increments from the .sta file
    # (an attempt marked "U" did not converge and was cut back: its
    # iterations count, the increment does not)
    incs, iters, atts, cutbacks = 0, 0, 0, 0
    with open(job + ".sta") as f:
        for line in f:
            parts = line.split()
            if len(parts) >= 7 and parts[0].isdigit():
                att = parts[2]
                if att.endswith("U"):
                    cutbacks += 1
                else:
                    incs += 1
                atts = max(atts, int(att.rstrip("U")))
                iters += int(parts[3])
    res.update({"increments": incs, "newton_iterations": iters, "max_attempt": atts,
                "cutbacks": cutbacks})
    if args.log:
        text = open(args.log).read()
        res["factorizations"] = text.count("Factoring the system of equations")
        m = re.findall(r"number of equations\s+(\d+)", text)
        if m:
            res["equations"] = int(m[0])
        res["finished"] = "Job finished" in text
        m = re.findall(r"Total CalculiX Time:\s*([0-9.eE+-]+)", text)
        if m:
            res["ccx_time_s"] = float(m[-1])
    for k in ("h", "mu", "steps", "element", "contact", "slave", "penalty",
              "stick_slope", "tension", "controls", "dofs_2d", "dofs_free_2d", "nodes_2d", "elements"):
        res[k] = meta[k]
    if args.profile:
        res["profile"] = profile
    print(json.dumps(res))


if __name__ == "__main__":
    main()
