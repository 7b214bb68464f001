#!/usr/bin/env python3
"""Reads a finished ccx run of the 3D seed scene (JOB.dat, JOB.frd, JOB.sta,
JOB.cvg, JOB.meta.json from gen_deck.py) and prints one JSON object, for the
WHOLE scene (the quarter's integrals x 4):

  gap_corner   u_z(upper) - u_z(lower) at (0, 0, 0)             [JOB.dat U]
  v_top        u_z of the upper block at (1/2, 1/2, H2)         [JOB.dat U]
  compliance   4 x sum over the loaded faces of p h^2/4 x sum of (-u_z) of
               its 4 nodes (consistent nodal forces of uniform p on a
               bilinear face: exact integral of p (-u_z))
  contact_area 4 x the tributary area (h^2, h^2/2 on a grid edge, h^2/4 at
               a corner) of the slave interface nodes with CPRESS > 0
               [JOB.frd, *CONTACT FILE: CPRESS/COPEN at the slave nodes;
               node-to-face: the nodes' own springs, face-to-face:
               extrapolated from its integration points]
  contact_area_faces_all / _any  4 x the area of the slave faces with
               CPRESS > 0 at all 4 / at least 1 of their nodes (bounds)
  max_penetration  max of -COPEN over the slave nodes; penetration_nodes:
               max of u_z(lower) - u_z(upper) over coincident interface nodes
  transmitted  4 x the support's z reaction / (p (2C)^2): 1 in equilibrium

    python3 parse.py /tmp/seed3d/run/job [--log job.log]
"""

import argparse
import json
import re


def dat_blocks(path, title):
    """Rows (lists of floats) of every block of JOB.dat whose title starts so."""
    out, cur = [], None
    for line in open(path):
        s = line.strip()
        if s.startswith(title):
            cur = []
            out.append(cur)
        elif cur is not None and s:
            try:
                cur.append([float(x) for x in s.split()])
            except ValueError:
                cur = None
        elif cur:
            cur = None
    return out


def frd_contact(path):
    """Node -> (COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2), last CONTACT block."""
    lines = open(path).read().splitlines()
    start = [k for k, l in enumerate(lines) if l.startswith(" -4  CONTACT")][-1]
    out = {}
    for l in lines[start + 1:]:
        if l.startswith(" -5"):
            continue
        if not l.startswith(" -1"):
            break
        out[int(l[3:13])] = [float(l[13 + 12 * q:25 + 12 * q]) for q in range(6)]
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("job")
    ap.add_argument("--log", default=None)
    a = ap.parse_args()
    m = json.load(open(a.job + ".meta.json"))
    p, h2, nx = m["p"], m["face_area"], m["nx"]
    u = {int(r[0]): r[1:4] for r in dat_blocks(a.job + ".dat", "displacements (vx,vy,vz)")[-1]}
    rz = dat_blocks(a.job + ".dat", "total force (fx,fy,fz) for set NSUP")[-1][0][2]
    res = {
        "h": m["h"], "element": m["element"], "penalty": m["penalty"],
        "contact": m["contact"], "delcon": m["delcon"],
        "nodes": m["nodes"], "elements": m["elements"], "dofs_free": m["dofs_free"],
        "gap_corner": u[m["corner_upper"]][2] - u[m["corner_lower"]][2],
        "v_top": u[m["top_center"]][2],
        "compliance": 4 * sum(p * h2 / 4 * -sum(u[n][2] for n in f) for f in m["loaded_faces"]),
        "transmitted": 4 * rz / (p * 0.2 ** 2),
    }
    c = frd_contact(a.job + ".frd")
    c0 = [0.0] * 6  # node-to-face lists only the slave nodes near the master
    press = [[c.get(n, c0)[3] for n in row] for row in m["if_lower"]]  # press[j][i]
    w = [0.5 if k in (0, nx) else 1.0 for k in range(nx + 1)]
    res["contact_area"] = 4 * h2 * sum(w[i] * w[j] for j in range(nx + 1)
                                       for i in range(nx + 1) if press[j][i] > 0)
    faces = [[press[j][i], press[j][i + 1], press[j + 1][i], press[j + 1][i + 1]]
             for j in range(nx) for i in range(nx)]
    res["contact_area_faces_all"] = 4 * h2 * sum(1 for f in faces if min(f) > 0)
    res["contact_area_faces_any"] = 4 * h2 * sum(1 for f in faces if max(f) > 0)
    res["active_slave_nodes"] = sum(1 for row in press for q in row if q > 0)
    res["p_max"] = max(max(row) for row in press)
    res["max_penetration"] = max(0.0, max(-c.get(n, c0)[0] for row in m["if_lower"] for n in row))
    res["penetration_nodes"] = max(
        u[lo][2] - u[up][2] for rl, ru in zip(m["if_lower"], m["if_upper"]) for lo, up in zip(rl, ru))
    res["max_penetration_over_v_top"] = res["max_penetration"] / abs(res["v_top"])

    rows = [l.split() for l in open(a.job + ".sta") if l.split() and l.split()[0].isdigit()]
    res["increments"] = sum(1 for r in rows if not r[2].endswith("U"))
    res["newton_iterations"] = sum(int(r[3]) for r in rows)
    cvg = [l.split() for l in open(a.job + ".cvg") if l.split() and l.split()[0].isdigit()]
    res["contact_elements_final"] = int(cvg[-1][4])
    res["final_correction_pct"] = float(cvg[-1][6])  # last Newton correction, % of the increment
    # ccx accepts a face-to-face state once the number of contact elements changes by less
    # than DELCON (1e-3 relative) with a zero residual, whatever the correction: check it here
    # (node-to-face has a nonzero residual and converges on it: not checked)
    res["converged"] = res["final_correction_pct"] < 1e-3 if m["contact"] == "s2s" else None
    if a.log:
        text = open(a.log).read()
        res["finished"] = "Job finished" in text
        eq = re.findall(r"number of equations\s+(\d+)", text)
        res["equations"] = int(eq[0]) if eq else None
        tt = re.findall(r"Total CalculiX Time:\s*([0-9.eE+-]+)", text)
        res["ccx_reported_seconds"] = float(tt[-1]) if tt else None
    print(json.dumps(res))


if __name__ == "__main__":
    main()
