#!/usr/bin/env python3
"""CalculiX (ccx 2.20) on tfem's axisymmetric press fit, node for node.

The scene is `ShaftHub` of src/studies/scenes/revolution.rs: a solid shaft
0 <= r <= b + delta and a hub b <= r <= c, both 0 <= z <= l, ends held
axially (u_z = 0), u_r = 0 on the axis, contact between the shaft's surface
and the hub's bore; Lame's plane-strain shrink fit gives the pressure
p = E' delta (c^2 - b^2) / (2 b c^2), E' = E / (1 - nu^2), at every z, and
with Coulomb friction mu the push-out force F = 2 pi b l mu p.

The mesh is tfem's (src/studies/meshgen.rs `subdivide`, `add_grid` with
Diagonal::Forward): the shaft's grid then the hub's, row by row along z,
each cell (a, b, c, d) split into (a, b, c), (a, c, d) for CAX3 or kept
whole for CAX4; node k of tfem is CalculiX node k + 1, triangle t element
t + 1.

Subcommands:

  deck    write JOB.inp (+ JOB.meta.json: what the parser reads)
  run     write the deck, run ccx (--repeat, median wall time of ccx alone),
          parse, print one JSON line
  parse   parse a finished run
  batch   the runs of docs/calculix.md ("The axisymmetric press fit"),
          CalculiX and tfem's `press_fit --json`, one JSON line each
          appended to press_fit_results.jsonl (overwritten)
  table   the markdown tables from press_fit_results.jsonl

    python3 scripts/calculix/press_fit.py run --cells 16 --mu 0.1 --repeat 3
    python3 scripts/calculix/press_fit.py batch
    python3 scripts/calculix/press_fit.py table

CalculiX's axisymmetric conventions (ccx 2.20): each CAX element is
expanded into a 2 degree wedge (C3D6 for CAX3, C3D8 for CAX4; JOB.12d);
*NODE PRINT RF in JOB.dat is for the 2 degree segment (x 180 for the ring),
RF in JOB.frd for 360 degrees (both are read: they agree to 1e-6);
*EL PRINT stresses in JOB.dat are at the wedge's integration points, in the
Cartesian axes of the expansion (x radial in the x-y plane, y the axis, z
out of the plane); face-to-face contact output (*CONTACT FILE, JOB.frd) is
at the slave's 2D nodes, node-to-face output with a face-based slave
surface at the expanded nodes.
"""

import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
RESULTS = os.path.join(HERE, "press_fit_results.jsonl")


# --------------------------------------------------------------------------
# the scene and its mesh (tfem's)

def subdivide(a, b, stops, h):
    """tfem's meshgen::subdivide: spacing at most h, through every stop."""
    knots = [a] + [s for s in stops if a < s < b] + [b]
    out = [a]
    for w0, w1 in zip(knots, knots[1:]):
        n = max(1, math.ceil((w1 - w0) / h - 1e-9))
        for k in range(1, n + 1):
            out.append(w1 if k == n else w0 + (w1 - w0) * k / n)
    return out


class Scene:
    """ShaftHub's parameters, Lame's answers and tfem's mesh."""

    def __init__(self, a):
        self.b, self.c, self.l = a.bore, a.outer, a.length
        self.delta, self.e, self.nu = a.interference, a.e, a.nu
        self.cells, self.ratio, self.mu = a.cells, tuple(a.ratio), a.mu
        if not (self.b > 0 and self.c > self.b and self.l > 0 and 0 <= self.delta < 0.1 * self.b
                and self.cells >= 2):
            sys.exit("press_fit: need 0 < b < c, l > 0, 0 <= delta < b/10, cells >= 2")

    def pressure(self):
        e_plane = self.e / (1.0 - self.nu ** 2)
        b, c = self.b, self.c
        return e_plane * self.delta * (c * c - b * b) / (2.0 * b * c * c)

    def hub_hoop(self, r):
        b, c = self.b, self.c
        return self.pressure() * b * b / (c * c - b * b) * (1.0 + c * c / (r * r))

    def push_out_force(self):
        return 2.0 * math.pi * self.b * self.l * self.mu * self.pressure()

    def mesh(self, element):
        """Nodes [(r, z)], elements [(body, [node numbers])] (1-based, counter-
        clockwise in (r, z)), rows of each grid (rows[j][i] at (rs[i], zs[j]))."""
        h = self.b / self.cells
        num, den = self.ratio
        shaft_r = subdivide(0.0, self.b + self.delta, [], h)
        hub_r = subdivide(self.b, self.c, [], h)
        shaft_z = subdivide(0.0, self.l, [], h)
        hub_z = subdivide(0.0, self.l, [], h * den / num)
        nodes, elems = [], []

        def grid(rs, zs, body):
            rows = []
            for z in zs:
                row = []
                for r in rs:
                    nodes.append((r, z))
                    row.append(len(nodes))
                rows.append(row)
            for j in range(len(zs) - 1):
                for i in range(len(rs) - 1):
                    a, b = rows[j][i], rows[j][i + 1]
                    c, d = rows[j + 1][i + 1], rows[j + 1][i]
                    if element == "CAX4":
                        elems.append((body, [a, b, c, d]))
                    else:  # Diagonal::Forward
                        elems.append((body, [a, b, c]))
                        elems.append((body, [a, c, d]))
            return rows

        shaft = grid(shaft_r, shaft_z, 1)
        hub = grid(hub_r, hub_z, 2)
        return nodes, elems, shaft, hub


def faces_on(elems, nodes, body, pred):
    """(element, face number, n1, n2) of every edge of a `body` element whose
    two ends satisfy pred (CalculiX: face k is the edge from node k to k+1)."""
    out = []
    for e, (b, conn) in enumerate(elems, start=1):
        if b != body:
            continue
        for k in range(len(conn)):
            p, q = conn[k], conn[(k + 1) % len(conn)]
            if pred(nodes[p - 1]) and pred(nodes[q - 1]):
                out.append((e, k + 1, p, q))
    return out


def write_set(f, keyword, items, per_line=10):
    f.write(keyword + "\n")
    for k in range(0, len(items), per_line):
        f.write(", ".join(str(i) for i in items[k:k + per_line]) + ",\n")


def write_deck(a):
    s = Scene(a)
    nodes, elems, shaft, hub = s.mesh(a.element)
    b, l, d = s.b, s.l, s.delta
    tol = 1e-12 * max(s.c, l)
    h = b / s.cells
    middle = lambda z: 0.25 * l <= z <= 0.75 * l  # tfem: (0.25 l..=0.75 l).contains(z)

    shaft_faces = faces_on(elems, nodes, 1, lambda p: abs(p[0] - (b + d)) <= tol)
    bore_faces = faces_on(elems, nodes, 2, lambda p: abs(p[0] - b) <= tol)
    axis = [row[0] for row in shaft]
    shaft_ends = list(shaft[0]) + list(shaft[-1])
    hub_ends = list(hub[0]) + list(hub[-1])
    shaft_surface = [row[-1] for row in shaft]
    hub_bore = [row[0] for row in hub]
    # tfem's hub hoop measure: hub elements whose centroid is in the middle
    # half and within h of the bore
    bore_elems, bore_centroids = [], []
    for e, (body, conn) in enumerate(elems, start=1):
        if body != 2:
            continue
        rc = sum(nodes[n - 1][0] for n in conn) / len(conn)
        zc = sum(nodes[n - 1][1] for n in conn) / len(conn)
        if middle(zc) and rc < b + h:
            bore_elems.append(e)
            bore_centroids.append(rc)

    slave_faces, master_faces = (bore_faces, shaft_faces) if a.slave == "hub" else \
        (shaft_faces, bore_faces)
    slave_nodes = hub_bore if a.slave == "hub" else shaft_surface
    job = a.out
    os.makedirs(os.path.dirname(os.path.abspath(job)), exist_ok=True)
    with open(job + ".inp", "w") as f:
        f.write("** tfem's ShaftHub press fit for CalculiX 2.20, written by "
                "scripts/calculix/press_fit.py\n")
        f.write(f"** b = {b!r}, c = {s.c!r}, l = {l!r}, delta = {d!r}, cells = {s.cells}, "
                f"ratio = {s.ratio}, {a.element}, mu = {s.mu!r}\n")
        f.write("*HEADING\ntfem ShaftHub (src/studies/scenes/revolution.rs)\n")
        f.write("*NODE, NSET=NALL\n")
        for k, (r, z) in enumerate(nodes, start=1):
            f.write(f"{k}, {r!r}, {z!r}, 0.0\n")
        for body, name in ((1, "ESHAFT"), (2, "EHUB")):
            f.write(f"*ELEMENT, TYPE={a.element}, ELSET={name}\n")
            for e, (bb, conn) in enumerate(elems, start=1):
                if bb == body:
                    f.write(f"{e}, " + ", ".join(map(str, conn)) + "\n")
        f.write(f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{s.e!r}, {s.nu!r}\n")
        # axisymmetric: no thickness line (the 2 degree expansion is fixed)
        f.write("*SOLID SECTION, ELSET=ESHAFT, MATERIAL=STEEL\n")
        f.write("*SOLID SECTION, ELSET=EHUB, MATERIAL=STEEL\n")
        write_set(f, "*NSET, NSET=NAXIS", axis)
        write_set(f, "*NSET, NSET=NSHAFTENDS", shaft_ends)
        write_set(f, "*NSET, NSET=NHUBENDS", hub_ends)
        write_set(f, "*ELSET, ELSET=EBORE", bore_elems)
        f.write("*SURFACE, NAME=SSHAFT, TYPE=ELEMENT\n")
        for e, k, _, _ in shaft_faces:
            f.write(f"{e}, S{k}\n")
        f.write("*SURFACE, NAME=SBORE, TYPE=ELEMENT\n")
        for e, k, _, _ in bore_faces:
            f.write(f"{e}, S{k}\n")
        f.write("*SURFACE INTERACTION, NAME=SI\n")
        if a.penalty:
            f.write(f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{a.penalty!r}\n")
        else:
            # ccx: HARD is its LINEAR law with K = 50 x E (the defaults)
            f.write("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n")
        if s.mu > 0:
            # no stick slope: ccx's default (E/2 of the first material)
            f.write("*FRICTION\n" + (f"{s.mu!r}, {a.stick_slope!r}\n" if a.stick_slope
                                     else f"{s.mu!r}\n"))
        slave, master = ("SBORE", "SSHAFT") if a.slave == "hub" else ("SSHAFT", "SBORE")
        if a.contact == "n2s-nodes":
            write_set(f, "*NSET, NSET=NSLAVE", slave_nodes)
            f.write("*SURFACE, NAME=SNODES, TYPE=NODE\nNSLAVE\n")
            slave = "SNODES"
        ctype = "SURFACE TO SURFACE" if a.contact == "s2s" else "NODE TO SURFACE"
        f.write(f"*CONTACT PAIR, INTERACTION=SI, TYPE={ctype}\n{slave}, {master}\n")
        f.write("*BOUNDARY\nNAXIS, 1, 1, 0.0\nNSHAFTENDS, 2, 2, 0.0\nNHUBENDS, 2, 2, 0.0\n")
        # step 1: the fit (the overclosure is ramped over the step, ccx's rule
        # for *STATIC); automatic incrementation from a full increment (ccx's
        # default 1, 1)
        direct = "DIRECT, " if a.direct else ""
        f.write(f"*STEP, INC=1000\n*STATIC, {direct}SOLVER=SPOOLES\n1.0, 1.0\n")
        f.write("*NODE PRINT, NSET=NSHAFTENDS, TOTALS=ONLY, FREQUENCY=100000\nRF\n")
        f.write("*EL PRINT, ELSET=EBORE, FREQUENCY=100000\nS\n")
        f.write("*NODE FILE, FREQUENCY=100000\nU, RF\n*EL FILE, FREQUENCY=100000\nS\n")
        f.write("*CONTACT FILE, FREQUENCY=100000\nCSTR, CDIS\n")
        f.write("*END STEP\n")
        if s.mu > 0 and a.push != 0:
            # step 2: the shaft's ends moved along the axis by `push`
            f.write(f"*STEP, INC=1000\n*STATIC, {direct}SOLVER=SPOOLES\n1.0, 1.0\n")
            f.write(f"*BOUNDARY\nNSHAFTENDS, 2, 2, {a.push!r}\n")
            f.write("*NODE PRINT, NSET=NSHAFTENDS, TOTALS=ONLY, FREQUENCY=100000\nRF\n")
            f.write("*END STEP\n")

    fixed = len(axis) + len(shaft_ends) + len(hub_ends)  # the corner (0, 0): u_r and u_z
    meta = {
        "cells": s.cells, "ratio": list(s.ratio), "element": a.element, "mu": s.mu,
        "contact": a.contact, "slave": a.slave, "penalty": a.penalty,
        "stick_slope": a.stick_slope, "push": a.push if s.mu > 0 else None,
        "direct": a.direct,
        "params": {"b": b, "c": s.c, "l": l, "delta": d, "E": s.e, "nu": s.nu},
        "p_lame": s.pressure(), "push_out_exact": s.push_out_force() if s.mu > 0 else None,
        "nodes_2d": len(nodes), "elements": len(elems),
        "dofs_free_2d": 2 * len(nodes) - fixed,
        "slave_nodes": slave_nodes, "shaft_ends": shaft_ends,
        "coords": {str(n): nodes[n - 1] for n in slave_nodes},
        "bore_elems": bore_elems, "bore_centroids": bore_centroids,
        "bore_hoop_lame": [s.hub_hoop(r) for r in bore_centroids],
    }
    with open(job + ".meta.json", "w") as f:
        json.dump(meta, f)
    return meta


# --------------------------------------------------------------------------
# parsing

def dat_blocks(path, title_regex):
    """Every block of JOB.dat whose title matches: (title, rows of floats)."""
    out, cur = [], None
    rx = re.compile(title_regex)
    with open(path) as f:
        for line in f:
            s = line.strip()
            if rx.search(s):
                cur = []
                out.append((s, cur))
                continue
            if cur is None:
                continue
            if not s:
                if cur:
                    cur = None
                continue
            try:
                cur.append([float(x) for x in s.split()])
            except ValueError:
                cur = None
    return out


def frd_blocks(path, name):
    """The nodal result blocks called `name` (e.g. CONTACT, STRESS) of
    JOB.frd, each a dict node -> values (fixed columns: ' -1', 10 for the
    node, 12 per value)."""
    out, cur = [], None
    with open(path) as f:
        for line in f:
            if line.startswith(" -4"):
                cur = {} if line.split()[1] == name else None
                if cur is not None:
                    out.append(cur)
            elif line.startswith(" -1") and cur is not None:
                node = int(line[3:13])
                vals = [float(line[13 + 12 * k:25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
                cur[node] = vals
            elif line.startswith(" -3"):
                cur = None
    return out


def expansion(path):
    """2D node -> its expanded 3D nodes, from JOB.12d."""
    m = {}
    with open(path) as f:
        chunks = f.read().split("ELEMENT")
    for chunk in chunks[1:]:
        _, _, rest = chunk.partition("with nodes:")
        nodes2d, _, rest = rest.partition("is expanded into")
        n2 = [int(x) for x in nodes2d.split()]
        n3 = [int(x) for x in rest.partition("with topology:")[2].split()]
        k = len(n2)
        for i in range(min(k, len(n3) // 2)):
            m.setdefault(n2[i], set()).update((n3[i], n3[i + k]))
    return m


def sta_counts(path):
    incs, iters, cutbacks = 0, 0, 0
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) >= 7 and parts[0].isdigit():
                if parts[2].endswith("U"):
                    cutbacks += 1
                else:
                    incs += 1
                iters += int(parts[3])
    return incs, iters, cutbacks


def parse(job, log=None):
    meta = json.load(open(job + ".meta.json"))
    p = meta["p_lame"]
    l = meta["params"]["l"]
    coords = {int(k): v for k, v in meta["coords"].items()}
    res = {k: meta[k] for k in ("cells", "ratio", "element", "mu", "contact", "slave",
                                "penalty", "stick_slope", "push", "direct", "nodes_2d",
                                "elements", "dofs_free_2d", "p_lame", "push_out_exact")}
    # contact pressure at the slave nodes (JOB.frd, CONTACT block of step 1:
    # COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2)
    contact = frd_blocks(job + ".frd", "CONTACT")
    if contact:
        c1 = contact[0]
        # face-to-face (and a nodal slave surface): values at the 2D nodes;
        # node-to-face with a face-based slave surface: at the expanded
        # nodes, averaged back onto their 2D node
        if not any(n in c1 for n in meta["slave_nodes"]):
            emap = expansion(job + ".12d")
            for n in meta["slave_nodes"]:
                vals = [c1[m] for m in emap.get(n, ()) if m in c1]
                if vals:
                    c1[n] = [sum(v[k] for v in vals) / len(vals) for k in range(6)]
        mid = [n for n in meta["slave_nodes"] if 0.25 * l <= coords[n][1] <= 0.75 * l]
        ratios = [c1.get(n, [0.0] * 6)[3] / p for n in mid]
        res["pressure_error"] = sum(ratios) / len(ratios) - 1.0
        res["pressure_spread"] = max(abs(x - 1.0) for x in ratios)
        res["pressure_nodes"] = len(ratios)
        res["max_penetration"] = max(-v[0] for v in c1.values()) if c1 else None
        res["profile"] = [[coords[n][1], c1.get(n, [0.0] * 6)[3]] for n in meta["slave_nodes"]]
    # hub hoop stress of the bore elements (JOB.dat, step 1): the wedge's
    # integration points (two per element, one each side of the x-y plane),
    # Cartesian. In axisymmetry theta is a principal direction, so the x-z
    # block of the Cartesian stress is diag(s_rr, s_tt) turned by the
    # point's angle (about 0.3 degrees here): the hoop stress is that
    # block's eigenvalue nearer szz (szz itself differs by ~1e-4 of it).
    st = dat_blocks(job + ".dat", r"^stresses \(elem, integ\.pnt\.")
    if st:
        by_elem = {}
        for row in st[0][1]:
            by_elem.setdefault(int(row[0]), []).append(row[2:8])
        hoop, plain = [], []
        for e in meta["bore_elems"]:
            vals = []
            for sxx, syy, szz, sxy, sxz, syz in by_elem[e]:
                m, r = 0.5 * (sxx + szz), math.hypot(0.5 * (szz - sxx), sxz)
                vals.append(m + r if szz >= sxx else m - r)
            hoop.append(sum(vals) / len(vals))
            plain.append(sum(q[2] for q in by_elem[e]) / len(by_elem[e]))
        exact = sum(meta["bore_hoop_lame"])
        res["hub_hoop_error"] = sum(hoop) / exact - 1.0
        res["hub_hoop_error_szz"] = sum(plain) / exact - 1.0  # Cartesian szz as is
    # reactions of the shaft's ends, per step (TOTALS=ONLY: one row per step)
    rf = dat_blocks(job + ".dat", r"^total force \(fx,fy,fz\) for set NSHAFTENDS")
    if rf:
        steps = [rows[0] for _, rows in rf]
        if len(steps) > 1 and meta["push"]:
            res["push_out_force"] = abs(180.0 * steps[-1][1])
            res["push_out_error"] = res["push_out_force"] / meta["push_out_exact"] - 1.0
        # the same from JOB.frd (RF for 360 degrees), the push's last block
        forc = frd_blocks(job + ".frd", "FORC")
        if len(forc) > 1 and meta["push"]:
            res["push_out_force_frd"] = abs(sum(forc[-1][n][1] for n in meta["shaft_ends"]))
    incs, iters, cut = sta_counts(job + ".sta")
    res.update({"increments": incs, "newton_iterations": iters, "cutbacks": cut})
    if log:
        text = open(log).read()
        m = re.findall(r"number of equations\s+(\d+)", text)
        if m:
            res["equations"] = int(m[0])
        res["factorizations"] = text.count("Factoring the system of equations")
        res["finished"] = "Job finished" in text
        res["warnings"] = sorted(set(re.findall(r"\*(?:WARNING|INFO)[^\n]*", text)))[:10]
    return res


# --------------------------------------------------------------------------
# running

def run_ccx(a):
    if not shutil.which("ccx"):
        sys.exit("press_fit: ccx not found (apt-get install -y calculix-ccx)")
    os.makedirs(a.workdir, exist_ok=True)
    d = tempfile.mkdtemp(dir=a.workdir, prefix="press.")
    a.out = os.path.join(d, "job")
    write_deck(a)
    times, loads, rss = [], [], None
    for _ in range(a.repeat):
        for ext in ("dat", "sta", "cvg", "frd", "12d"):
            try:
                os.remove(f"{a.out}.{ext}")
            except FileNotFoundError:
                pass
        loads.append(float(open("/proc/loadavg").read().split()[0]))
        env = dict(os.environ, OMP_NUM_THREADS=str(a.threads))
        t0 = time.perf_counter()
        with open(os.path.join(d, "job.log"), "w") as log:
            r = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", os.path.join(d, "rss.txt"),
                                "ccx", "-i", "job"], cwd=d, env=env, stdout=log,
                               stderr=subprocess.STDOUT)
        times.append(time.perf_counter() - t0)
        if r.returncode != 0:
            tail = open(os.path.join(d, "job.log")).read()[-2000:]
            sys.exit(f"press_fit: ccx failed in {d}:\n{tail}")
        rss = int(open(os.path.join(d, "rss.txt")).read().split()[-1])
    res = parse(a.out, os.path.join(d, "job.log"))
    res.update({"code": "ccx", "wall_times_s": [round(t, 4) for t in times],
                "time_s": round(statistics.median(times), 4), "threads": a.threads,
                "peak_rss_mb": round(rss / 1024, 1), "load_avg_before": loads})
    if a.keep:
        res["dir"] = d
    else:
        shutil.rmtree(d)
    return res


def run_tfem(cells, mu, repeat, threads):
    """tfem's `press_fit --json` (examples/press_fit.rs), `repeat` times, on
    `threads` threads (RAYON_NUM_THREADS). Its `seconds`: building the mesh
    and model and the contact solve of the fit, in-process; with mu > 0
    `push_out_seconds`: the fit again and the push (ShaftHub::push_out)."""
    exe = os.path.join(ROOT, "target", "release", "examples", "press_fit")
    subprocess.run(["cargo", "build", "--release", "--example", "press_fit"], cwd=ROOT,
                   check=True, capture_output=True)
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    outs = []
    for _ in range(repeat):
        cmd = [exe, "--json", "--cells", str(cells), "--mu", str(mu)]
        outs.append(json.loads(subprocess.run(cmd, cwd=ROOT, env=env, check=True,
                                              capture_output=True, text=True).stdout))
    r = outs[-1]
    r.update({"code": "tfem", "mu": mu, "threads": threads,
              "wall_times_s": [o["seconds"] for o in outs]})
    r["time_s"] = statistics.median(r["wall_times_s"])
    if "push_out_seconds" in r:
        r["push_out_times_s"] = [o["push_out_seconds"] for o in outs]
        r["push_out_time_s"] = statistics.median(r["push_out_times_s"])
    return r


# label -> deck options of the batch's CalculiX runs (beside the defaults)
VARIANTS = {
    "main": {},                                    # CAX3, face-to-face, HARD
    "CAX4": {"element": "CAX4"},
    "K x100": {"penalty": 100 * 50 * 210e3},       # 100 x ccx's default K
    "n2s": {"contact": "n2s"},                     # node-to-face, face-based slave
    "n2s nodal slave=hub": {"contact": "n2s-nodes"},
    "n2s nodal slave=shaft": {"contact": "n2s-nodes", "slave": "shaft"},
}


def batch(a):
    out = open(a.results, "a" if a.append else "w")

    def emit(label, r):
        r["label"] = label
        r["date_utc"] = time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime())
        r["host"] = {"cpus": os.cpu_count(), "load_avg": open("/proc/loadavg").read().split()[:3]}
        line = json.dumps(r)
        out.write(line + "\n")
        out.flush()
        print(line[:240], file=sys.stderr)

    base = vars(a).copy()
    rep = max(3, a.repeat)  # medians of 3 at least

    def ccx(label, mu, repeat):
        ns = argparse.Namespace(**{**base, **VARIANTS[label], "mu": mu, "repeat": repeat})
        try:
            emit(label, run_ccx(ns))
        except SystemExit as e:
            emit(label, {"code": "ccx", "failed": True, "error": str(e)[-500:],
                         "cells": ns.cells, "mu": mu})

    for cells in a.cells_list:
        base["cells"] = cells
        for mu in (0.0, 0.1):
            emit("tfem", run_tfem(cells, mu, rep, a.tfem_threads))
            for label in ("main", "CAX4", "K x100"):
                ccx(label, mu, rep)
        for label in ("n2s", "n2s nodal slave=hub", "n2s nodal slave=shaft"):
            ccx(label, 0.1, 1)
    out.close()


# --------------------------------------------------------------------------
# tables

def table(a):
    rows = [json.loads(s) for s in open(a.results) if s.strip()]
    ok = [r for r in rows if not r.get("failed")]

    def e(x, d=2):
        return "–" if x is None else f"{x:+.{d}e}"

    def find(cells, label, mu):
        got = [r for r in ok if r["cells"] == cells and r["label"] == label and r["mu"] == mu]
        return got[-1] if got else None

    cells = sorted({r["cells"] for r in ok})
    print("| cells over b | DOFs tfem / ccx | p error tfem | p error ccx | hoop error tfem | "
          "hoop error ccx | push-out error tfem | push-out error ccx | time fit tfem [s] | "
          "time fit ccx [s] | ccx / tfem | time fit + push tfem [s] | "
          "time fit + push ccx [s] | ccx / tfem |")
    print("|" + "---|" * 14)
    for n in cells:
        t0, t1 = find(n, "tfem", 0.0), find(n, "tfem", 0.1)
        c0, c1 = find(n, "main", 0.0), find(n, "main", 0.1)
        if not (t0 and t1 and c0 and c1):
            continue
        print(f"| {n} | {t0['unknowns']} / {c0.get('equations')} | {e(t0['pressure_error'])} | "
              f"{e(c0['pressure_error'])} | {e(t0['hub_hoop_error'])} | "
              f"{e(c0['hub_hoop_error'])} | {e(t1['push_out_error'])} | "
              f"{e(c1['push_out_error'])} | {t0['time_s']:.4f} | {c0['time_s']:.3f} | "
              f"{c0['time_s'] / t0['time_s']:.0f} | {t1['push_out_time_s']:.4f} | "
              f"{c1['time_s']:.3f} | {c1['time_s'] / t1['push_out_time_s']:.0f} |")
    print()
    print("| cells over b | run | μ | DOFs | p error | p spread | hoop error | push-out force "
          "(exact) | push-out error | max penetration | Newton iterations (increments) | "
          "wall time [s] (runs) |")
    print("|" + "---|" * 12)
    for n in cells:
        for r in [r for r in ok if r["cells"] == n]:
            dofs = r.get("unknowns") or r.get("equations")
            force = (f"{r['push_out_force']:.2f} ({r.get('push_out_force_exact') or r.get('push_out_exact'):.2f})"
                     if r.get("push_out_force") else "–")
            its = (f"{r['newton_iterations']} ({r['increments']})" if r["code"] == "ccx" else "–")
            t = r["push_out_time_s"] if r["code"] == "tfem" and r["mu"] > 0 else r["time_s"]
            pen = f"{r['max_penetration']:.2e}" if r.get("max_penetration") is not None else "–"
            print(f"| {n} | {r['label']} | {r['mu']:g} | {dofs} | {e(r.get('pressure_error'))} | "
                  f"{r.get('pressure_spread', 0):.1e} | {e(r.get('hub_hoop_error'))} | {force} | "
                  f"{e(r.get('push_out_error'))} | {pen} | {its} | "
                  f"{t:.4f} ({len(r['wall_times_s'])}) |")
    failed = [r for r in rows if r.get("failed")]
    if failed:
        print("\nfailed:", json.dumps(failed)[:1000])


# --------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("command", choices=["deck", "run", "parse", "batch", "table"])
    ap.add_argument("--cells", type=int, default=8, help="cells over the bore radius b")
    ap.add_argument("--cells-list", type=int, nargs="+", default=[8, 16, 32],
                    help="batch: the meshes")
    ap.add_argument("--ratio", type=int, nargs=2, default=[3, 2],
                    help="the hub's cells along z per the shaft's (3 2: non-matching)")
    ap.add_argument("--bore", type=float, default=1.0)
    ap.add_argument("--outer", type=float, default=2.0)
    ap.add_argument("--length", type=float, default=2.0)
    ap.add_argument("--interference", type=float, default=1e-3)
    ap.add_argument("--e", type=float, default=210e3)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--mu", type=float, default=0.0,
                    help="Coulomb coefficient; > 0 adds the push-out step")
    ap.add_argument("--push", type=float, default=None,
                    help="the shaft ends' axial motion of the push-out step (default delta)")
    ap.add_argument("--element", choices=["CAX3", "CAX4"], default="CAX3")
    ap.add_argument("--contact", default="s2s", choices=["s2s", "n2s", "n2s-nodes"],
                    help="s2s: TYPE=SURFACE TO SURFACE (face-to-face penalty, the table); "
                         "n2s: NODE TO SURFACE with a face-based slave surface; n2s-nodes: "
                         "NODE TO SURFACE with a nodal slave surface (*SURFACE, TYPE=NODE: "
                         "the set-up of CalculiX issue #98)")
    ap.add_argument("--slave", choices=["hub", "shaft"], default="hub",
                    help="the slave side (default the hub's bore, the finer along z)")
    ap.add_argument("--penalty", type=float, default=None,
                    help="LINEAR with this K; default HARD (ccx: LINEAR, K = 50 E)")
    ap.add_argument("--stick-slope", type=float, default=None,
                    help="stick slope of *FRICTION (default: ccx's, E/2)")
    ap.add_argument("--direct", action="store_true", help="*STATIC, DIRECT (no cut-backs)")
    ap.add_argument("--threads", type=int, default=1, help="OMP_NUM_THREADS for ccx")
    ap.add_argument("--repeat", type=int, default=1,
                    help="timed runs (median; batch: 3 for the main runs)")
    ap.add_argument("--tfem-threads", type=int, default=1,
                    help="batch: RAYON_NUM_THREADS for tfem's example")
    ap.add_argument("--workdir", default="/tmp/tfem-ccx")
    ap.add_argument("--keep", action="store_true", help="keep the run directory")
    ap.add_argument("--out", default=None, help="deck: job path without .inp; parse: job path")
    ap.add_argument("--results", default=RESULTS)
    ap.add_argument("--append", action="store_true", help="batch: append to --results")
    a = ap.parse_args()
    if a.push is None:
        a.push = a.interference
    if a.command == "deck":
        if not a.out:
            sys.exit("deck: --out JOB")
        write_deck(a)
    elif a.command == "run":
        print(json.dumps(run_ccx(a)))
    elif a.command == "parse":
        log = a.out + ".log"
        print(json.dumps(parse(a.out, log if os.path.exists(log) else None)))
    elif a.command == "batch":
        batch(a)
    else:
        table(a)


if __name__ == "__main__":
    main()
