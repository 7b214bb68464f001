#!/usr/bin/env python3
"""Prints the markdown tables of docs/calculix.md from the JSON lines of
table.sh (default scripts/calculix/results.jsonl): CalculiX's runs, errors
against the shipped reference (frictionless), and tfem's runs of the batch.

    python3 scripts/calculix/make_table.py [results.jsonl]
"""

import json
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results.jsonl")
ref_path = os.path.join(here, "..", "..", "docs", "reference", "two_blocks_canonical.json")
ref = json.load(open(ref_path))["cases"]["canonical_0.2"]
rows = [json.loads(line) for line in open(path) if line.strip()]


def frac(h):
    n = round(1 / h)
    return f"1/{n}" if abs(1 / n - h) < 1e-12 else f"{h:g}"


def rel(r, k):
    return (r[k] - ref[k]["value"]) / ref[k]["value"]


def e(x, d=3):
    return f"{x:.{d}e}"


ccx = [r for r in rows if not r.get("failed") and r.get("label") != "tfem"]
# by size (coarsest first), then main runs before variants, mu, N
ccx.sort(key=lambda r: (-r["h"], r["label"] != "main", r["mu"], r["steps"]))
tfem = [r for r in rows if r.get("label") == "tfem"]
failed = [r for r in rows if r.get("failed")]

print("### CalculiX 2.20, CPE3, node-to-surface penalty contact (the table)\n")
print("| h | equations | μ | N | wall time [s] | runs | Newton iterations | "
      "gap_edge [m] | slip_edge [m] | v_top [m] | compliance [J/m] | ℓc [m] | "
      "max penetration [m] | peak RSS [MB] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in ccx:
    if r["label"] != "main":
        continue
    print(f"| {frac(r['h'])} | {r['equations']} | {r['mu']:g} | {r['steps']} | "
          f"{r['time_s']:.2f} | {len(r['wall_times_s'])} | {r['newton_iterations']} | "
          f"{e(r['gap_edge'], 4)} | {e(r['slip_edge'], 4)} | {e(r['v_top'], 5)} | "
          f"{r['compliance']:.2f} | {r['lc']:.4f} | {e(r['max_penetration'], 2)} | "
          f"{r['peak_rss_mb']:.0f} |")

print("\n### Frictionless runs against the reference (relative errors)\n")
print("| h | equations | N | deck | gap_edge | v_top | compliance | ℓc |")
print("|---|---|---|---|---|---|---|---|")
for r in ccx:
    if r["mu"] != 0:
        continue
    deck = r["label"] if r["label"] != "main" else "as in the table"
    lc = "n/a" if r["contact"] == "s2s" else f"{rel(r, 'lc'):+.2e}"
    print(f"| {frac(r['h'])} | {r['equations']} | {r['steps']} | {deck} | "
          f"{rel(r, 'gap_edge'):+.2e} | {rel(r, 'v_top'):+.2e} | "
          f"{rel(r, 'compliance'):+.2e} | {lc} |")

print("\n### Deck variants and threads (N = 1)\n")
print("| h | μ | deck | wall time [s] | runs | threads | Newton iterations | gap_edge [m] | "
      "slip_edge [m] | v_top [m] | compliance [J/m] | max penetration [m] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in ccx:
    if r["label"] == "main":
        continue
    print(f"| {frac(r['h'])} | {r['mu']:g} | {r['label']} | {r['time_s']:.2f} | "
          f"{len(r['wall_times_s'])} | {r['threads']} | {r['newton_iterations']} | "
          f"{e(r['gap_edge'], 4)} | {e(r['slip_edge'], 4)} | {e(r['v_top'], 5)} | "
          f"{r['compliance']:.2f} | "
          + ("n/a" if r["contact"] == "s2s" else e(r["max_penetration"], 2)) + " |")

if tfem:
    print("\n### tfem in the same batch (frictionless, `two_blocks --json --steps N`)\n")
    print("| h | unknowns | N | time [s] | runs | active-set iterations (last step) | factorisations | "
          "gap_edge | v_top | compliance | ℓc |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in tfem:
        print(f"| {frac(r['h'])} | {r['ndof']} | {r['steps']} | {r['time_s']:.3f} | "
              f"{len(r['wall_times_s'])} | {r['iterations']} | {r['factorizations']} | "
              f"{rel(r, 'gap_edge'):+.2e} | {rel(r, 'v_top'):+.2e} | "
              f"{rel(r, 'compliance'):+.2e} | {rel(r, 'lc'):+.2e} |")

if tfem:
    print("\n### CalculiX (CPE3, frictionless) against tfem on the same mesh, N = 1\n")
    print("| h | equations / unknowns | gap_edge | v_top | compliance | ℓc | "
          "CalculiX time / tfem time |")
    print("|---|---|---|---|---|---|---|")
    for r in ccx:
        if r["label"] != "main" or r["mu"] != 0 or r["steps"] != 1:
            continue
        t = [x for x in tfem if abs(x["h"] - r["h"]) < 1e-15 and x["steps"] == 1]
        if not t:
            continue
        t = t[0]
        d = {k: (r[k] - t[k]) / abs(t[k]) for k in ("gap_edge", "v_top", "compliance", "lc")}
        print(f"| {frac(r['h'])} | {r['equations']} / {t['ndof']} | {d['gap_edge']:+.1e} | "
              f"{d['v_top']:+.1e} | {d['compliance']:+.1e} | {d['lc']:+.1e} | "
              f"{r['time_s'] / t['time_s']:.0f} |")

if failed:
    print("\nFailed runs:")
    for r in failed:
        print(f"* {r['label']}: {r['args']}")
