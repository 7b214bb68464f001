#!/usr/bin/env bash
# Runs CalculiX (ccx 2.20, Debian's calculix-ccx) on tfem's seed scene and
# prints one JSON object: the seed scene's outputs (gap_edge, slip_edge,
# v_top, compliance, lc, ...), DOFs, Newton iterations from the .sta file,
# and the wall time (median over --repeat runs, each timed around ccx alone:
# deck generation and parsing excluded).
#
#   bash scripts/calculix/run.sh --h 0.0078125 --mu 0.3 --steps 10
#   bash scripts/calculix/run.sh --h 0.00390625 --steps 1 --threads 2 --repeat 3
#
# Options (defaults in brackets):
#   --h H            element size [required]
#   --mu MU          Coulomb friction coefficient [0]
#   --steps N        number of fixed increments (*STATIC, DIRECT, 1/N) [1]
#   --threads T      OMP_NUM_THREADS for ccx [1]
#   --repeat R       timed runs; the JSON gives their median and all times [1]
#   --workdir DIR    where decks and results go [/tmp/tfem-ccx]
#   --profile        add the contact pressure/shear profile to the JSON
#   --keep           keep the run directory (default: deleted after parsing)
#   any other option is passed to gen_deck.py (--element CPE4, --contact s2s,
#   --penalty K, --stick-slope S, --tension T, --controls Rn,Cn, --slave upper).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
h="" mu=0 steps=1 threads=1 repeat=1 workdir=/tmp/tfem-ccx profile="" keep=0
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --h) h="$2"; shift 2 ;;
    --mu) mu="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --workdir) workdir="$2"; shift 2 ;;
    --profile) profile="--profile"; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) extra+=("$1"); shift ;;
  esac
done
[[ -n "$h" ]] || { echo "run.sh: --h is required" >&2; exit 2; }
command -v ccx >/dev/null || { echo "run.sh: ccx not found (apt-get install -y calculix-ccx)" >&2; exit 2; }

mkdir -p "$workdir"
dir="$(mktemp -d "$workdir/run.XXXXXX")"
job="$dir/job"
python3 "$here/gen_deck.py" --h "$h" --mu "$mu" --steps "$steps" --out "$job" "${extra[@]}"

times=()
loads=()
rss=""
for ((r = 0; r < repeat; r++)); do
  rm -f "$job".{dat,sta,cvg,frd,12d} "$dir/spooles.out"
  loads+=("$(cut -d' ' -f1 /proc/loadavg)")
  t0=$(date +%s.%N)
  # ccx writes next to the job; /usr/bin/time reports the peak RSS (KB)
  if ! (cd "$dir" && OMP_NUM_THREADS="$threads" /usr/bin/time -f "%M" -o "$dir/rss.txt" \
        ccx -i job >"$dir/job.log" 2>&1); then
    echo "run.sh: ccx failed, see $dir/job.log" >&2
    tail -20 "$dir/job.log" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  times+=("$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }')")
  rss="$(tail -1 "$dir/rss.txt")"
done

times_json="[$(IFS=,; echo "${times[*]}")]"
loads_json="[$(IFS=,; echo "${loads[*]}")]"
python3 "$here/parse_results.py" "$job" --log "$dir/job.log" $profile |
  python3 -c '
import json, statistics, sys
r = json.load(sys.stdin)
t = json.loads(sys.argv[1])
r["wall_times_s"] = [round(x, 3) for x in t]
r["time_s"] = round(statistics.median(t), 3)
r["threads"] = int(sys.argv[2])
r["peak_rss_mb"] = round(int(sys.argv[3]) / 1024, 1)
r["load_avg_before"] = json.loads(sys.argv[4])  # 1-minute load average
print(json.dumps(r))
' "$times_json" "$threads" "$rss" "$loads_json"
if [[ "$keep" == 0 ]]; then rm -rf "$dir"; else echo "run.sh: kept $dir" >&2; fi
