#!/usr/bin/env bash
# The measurement batch of docs/calculix.md: every run of the table, one
# after the other (timings in one batch on a quiet-as-possible host), one
# JSON line per run appended to $OUT (default scripts/calculix/results.jsonl,
# overwritten). Then `python3 scripts/calculix/make_table.py $OUT` prints the
# tables. Takes about 50 minutes on 2 cores (about 8 GB of memory at h = 1/512).
#
#   bash scripts/calculix/table.sh            # the whole batch
#   QUICK=1 bash scripts/calculix/table.sh    # h = 1/32 only (seconds)
#   ONLY_EXTRA=1 bash scripts/calculix/table.sh  # the last runs only, appended
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${OUT:-$here/results.jsonl}"
[[ -n "${ONLY_EXTRA:-}" ]] || : >"$out"   # ONLY_EXTRA appends

run() { # label, then run.sh options
  local label="$1"; shift
  echo "== $label: $*" >&2
  if r="$(bash "$here/run.sh" "$@")"; then
    python3 -c 'import json,sys; r=json.loads(sys.argv[1]); r["label"]=sys.argv[2]; print(json.dumps(r))' \
      "$r" "$label" | tee -a "$out" | cut -c1-200 >&2
  else
    echo "{\"label\": \"$label\", \"failed\": true, \"args\": \"$*\"}" | tee -a "$out" >&2
  fi
}

# tfem's own run of the same scene (frictionless; its friction is not in yet)
tfem_bin="${TFEM_TWO_BLOCKS:-$here/../../target/release/examples/two_blocks}"
tfem() { # h, N, repeat
  [[ -x "$tfem_bin" ]] || { echo "no $tfem_bin (cargo build --release --example two_blocks)" >&2; return 0; }
  local h="$1" n="$2" rep="$3" k outs=()
  echo "== tfem: h $h, N $n" >&2
  for ((k = 0; k < rep; k++)); do
    outs+=("$("$tfem_bin" --mesh-size "$h" --steps "$n" --json --out "${TMPDIR:-/tmp}/tfem-ccx-tfem")")
  done
  python3 -c '
import json, statistics, sys
rs = [json.loads(s) for s in sys.argv[2:]]
r = rs[-1]
r["wall_times_s"] = [x["time_s"] for x in rs]   # tfem'"'"'s own time: mesh, model, solve
r["time_s"] = statistics.median(r["wall_times_s"])
r["h"] = float(sys.argv[1]); r["label"] = "tfem"
print(json.dumps(r))' "$h" "${outs[@]}" | tee -a "$out" | cut -c1-200 >&2
}

if [[ -n "${QUICK:-}" ]]; then
  tfem 0.03125 1 3
  for mu in 0 0.3; do for n in 1 4; do run main --h 0.03125 --mu $mu --steps $n --repeat 3; done; done
  exit 0
fi

h10k=0.010416666666666666   # 1/96:  9 829 equations
h65k=0.00390625             # 1/256: 67 157
h265k=0.001953125           # 1/512: 265 377

extra() {
  # ccx's default tension diverges with DIRECT at 1/96: the same with
  # automatic incrementation, to see what the default does to the outputs
  run ccx-default-tension-auto --h $h10k --steps 1 --tension 0 --auto
  # ~65k, N = 100, both mu (~200 iterations each)
  for mu in 0 0.3; do run main --h $h65k --mu $mu --steps 100 --profile; done
  # ~265k, N = 4, frictionless (N = 10 and 100 skipped: ~19 s per iteration)
  run main --h $h265k --steps 4 --profile
}
if [[ -n "${ONLY_EXTRA:-}" ]]; then extra; exit 0; fi

for h in $h10k $h65k $h265k; do
  for n in 1 4 10 100; do tfem $h $n 3; done
done
# ~10k unknowns: every N, both mu; median of 3 runs except N = 100
for mu in 0 0.3; do
  for n in 1 4 10; do run main --h $h10k --mu $mu --steps $n --repeat 3 --profile; done
  run main --h $h10k --mu $mu --steps 100 --profile
done
# two threads (OMP_NUM_THREADS=2: ccx's assembly and SPOOLES)
run threads2 --h $h10k --steps 1 --threads 2 --repeat 3
# deck choices at ~10k, N = 1, frictionless
run ccx-default-tension --h $h10k --steps 1 --tension 0
run ccx-hard --h $h10k --steps 1 --hard
run tight-controls --h $h10k --steps 1 --controls 1e-7,1e-7
run cpe4 --h $h10k --steps 1 --element CPE4
run cpe4 --h $h10k --steps 1 --element CPE4 --mu 0.3
run stick-slope-K/10 --h $h10k --steps 1 --mu 0.3 --stick-slope 9.216e12
run face-to-face --h $h10k --steps 1 --contact s2s
# ~65k unknowns: N = 1, 4, 10, both mu (N = 100 skipped: ~200 iterations
# at ~10 s each)
for mu in 0 0.3; do
  for n in 1 4 10; do run main --h $h65k --mu $mu --steps $n --profile; done
done
run threads2 --h $h65k --steps 1 --threads 2
run cpe4 --h $h65k --steps 1 --element CPE4
# ~265k unknowns: N = 1 only
run main --h $h265k --steps 1 --profile
run main --h $h265k --mu 0.3 --steps 1 --profile
extra
