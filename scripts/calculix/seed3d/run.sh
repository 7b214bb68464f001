#!/usr/bin/env bash
# CalculiX (ccx 2.20) on tfem's seed scene in 3D (quarter model, hexahedra,
# frictionless penalty contact): writes the deck, runs ccx on one
# thread (timed alone), parses, prints one JSON line; --append adds it to
# scripts/calculix/seed3d/results.jsonl.
#
#   bash scripts/calculix/seed3d/run.sh --h 0.025
#   bash scripts/calculix/seed3d/run.sh --h 0.0125 --append
#   bash scripts/calculix/seed3d/run.sh --h 0.05 --contact s2s --penalty 1e16
#
# Options: --h H (required), --workdir DIR [/tmp/seed3d], --keep, --append;
# anything else goes to gen_deck.py (--element C3D8|C3D8I,
# --contact n2s|s2s, --penalty K, --delcon D). extrapolate.py fits the finest three.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
h="" workdir=/tmp/seed3d keep=0 append=0 extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --h) h="$2"; shift 2 ;;
    --workdir) workdir="$2"; shift 2 ;;
    --keep) keep=1; shift ;;
    --append) append=1; shift ;;
    *) extra+=("$1"); shift ;;
  esac
done
[[ -n "$h" ]] || { echo "run.sh: --h is required" >&2; exit 2; }

mkdir -p "$workdir"
dir="$(mktemp -d "$workdir/run.XXXXXX")"
python3 "$here/gen_deck.py" --h "$h" --out "$dir/job" "${extra[@]}"

export OMP_NUM_THREADS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_EQUATION_SOLVER=1 CCX_NPROC_RESULTS=1
load="$(cut -d' ' -f1 /proc/loadavg)"
t0=$(date +%s.%N)
if ! (cd "$dir" && /usr/bin/time -f "%M" -o rss.txt ccx -i job >job.log 2>&1); then
  echo "run.sh: ccx failed, see $dir/job.log" >&2; exit 1
fi
t1=$(date +%s.%N)

line="$(python3 "$here/parse.py" "$dir/job" --log "$dir/job.log" |
  python3 -c 'import json, sys
r = json.load(sys.stdin)
r["ccx_seconds"] = round(float(sys.argv[2]) - float(sys.argv[1]), 3)
r["peak_rss_mb"] = round(int(open(sys.argv[3]).read().split()[-1]) / 1024, 1)
r["threads"] = 1
r["load_avg_before"] = float(sys.argv[4])
print(json.dumps(r))' "$t0" "$t1" "$dir/rss.txt" "$load")"
echo "$line"
if [[ "$append" == 1 ]]; then echo "$line" >>"$here/results.jsonl"; fi
if [[ "$keep" == 0 ]]; then rm -rf "$dir"; else echo "run.sh: kept $dir" >&2; fi
