#!/usr/bin/env python3
"""Richardson-type extrapolation q = q_inf + K h^s through the three finest
runs of results.jsonl (per element, contact type and penalty; runs flagged
"converged": false left out), for each output; prints a table
and one JSON line per element. Only meaningful when the three values are
monotone in h (else "not monotone" and no fit).

    python3 scripts/calculix/seed3d/extrapolate.py [results.jsonl]
"""

import json
import os
import sys

KEYS = ["contact_area", "gap_corner", "v_top", "compliance"]


def fit(h, q):
    """q_inf, K, s through three points (h descending), by bisection on s."""
    (h1, h2, h3), (q1, q2, q3) = h, q
    if not ((q1 - q2) * (q2 - q3) > 0):
        return None
    r = (q1 - q2) / (q2 - q3)
    f = lambda s: (h1 ** s - h2 ** s) / (h2 ** s - h3 ** s) - r
    lo, hi = 1e-3, 20.0
    if f(lo) * f(hi) > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(lo) * f(mid) > 0 else (lo, mid)
    s = 0.5 * (lo + hi)
    k = (q2 - q3) / (h2 ** s - h3 ** s)
    return q3 - k * h3 ** s, k, s


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "results.jsonl")
    runs = [json.loads(l) for l in open(path) if l.strip()]
    runs = [r for r in runs if r.get("converged") is not False]  # ccx's false convergences
    for series in sorted({(r["element"], r["contact"], r["penalty"]) for r in runs}):
        el = f"{series[0]} {series[1]} K={series[2]:g}"
        rs = {}
        for r in runs:  # the last run per h wins
            if (r["element"], r["contact"], r["penalty"]) == series:
                rs[round(1 / r["h"])] = r
        fine = sorted(rs.values(), key=lambda r: -r["h"])[-3:]
        if len(fine) < 3:
            continue
        h = [r["h"] for r in fine]
        out = {"element": el, "h": h}
        print(f"{el}: h = 1/{round(1 / h[0])}, 1/{round(1 / h[1])}, 1/{round(1 / h[2])}")
        for k in KEYS:
            q = [r[k] for r in fine]
            res = fit(h, q)
            if res is None:
                print(f"  {k:13s} {q}  not monotone / no fit")
                out[k] = None
            else:
                qi, kk, s = res
                print(f"  {k:13s} {' '.join(f'{v:.6g}' for v in q)}  ->  {qi:.6g}  (s = {s:.2f}, "
                      f"finest off by {(q[2] - qi) / qi:+.2%})")
                out[k] = {"q_inf": qi, "order": s, "K": kk}
        print(json.dumps(out))


if __name__ == "__main__":
    main()
