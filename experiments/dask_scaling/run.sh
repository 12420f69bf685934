#!/usr/bin/env bash
# How does frictionid.dask.fit_many scale with worker processes on this machine (1 and 2), and
# what does the Dask scheduler cost per run? Writes results.md (numbers, then the plan for 100
# nodes in plan.md appended); scratch in out/ (git-ignored).
#
#   experiments/dask_scaling/run.sh   # binary: $FRICTIONID, else build/frictionid;
#                                     # package: build/python
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bin="${FRICTIONID:-$root/build/frictionid}"
[[ "$bin" = /* ]] || bin="$PWD/$bin"
[[ -x "$bin" ]] || { echo "run.sh: no executable frictionid at $bin (set FRICTIONID)" >&2; exit 1; }
export PYTHONPATH="$root/build/python${PYTHONPATH:+:$PYTHONPATH}"
RUNS=${RUNS:-24}
REPS=${REPS:-3}
out="$here/out"
rm -rf "$out"
mkdir -p "$out/normal" "$out/trivial"

# RUNS files of 200 rows (an exact-model fit with the global stage) and RUNS*4 of 20 rows (a
# seed-model fit without the global stage, milliseconds: the rest of a run is the scheduler's).
for (( k = 1; k <= RUNS; k++ )); do
  "$bin" generate --model exact --param f=0.8,kappa=1.2,h=0.1 --rows 200 --noise 0.01 \
    --seed "$k" --output "$out/normal/run_$k.csv" > /dev/null 2>&1
done
for (( k = 1; k <= RUNS * 4; k++ )); do
  "$bin" generate --model exact --param f=0.8,kappa=1.2,h=0.1 --rows 20 --noise 0.01 \
    --seed "$k" --output "$out/trivial/run_$k.csv" > /dev/null 2>&1
done

batch_rate() {  # runs/s of `frictionid batch --jobs J` on the normal runs (median of REPS)
  local j=$1 times=()
  for (( r = 1; r <= REPS; r++ )); do
    local t0 t1
    t0=$(date +%s.%N)
    "$bin" batch "$out/normal" --model exact --report "$out/batch_$j" --jobs "$j" --force \
      --per-run-reports none > /dev/null
    t1=$(date +%s.%N)
    times+=("$(echo "$t1 - $t0" | bc -l)")
  done
  printf '%s\n' "${times[@]}" | sort -g | awk -v n="$RUNS" '{ v[NR] = $1 } END { printf "%.2f", n / v[int((NR + 1) / 2)] }'
}

{
  echo "# Dask scale-out: throughput and scheduler overhead"
  echo
  echo "\`experiments/dask_scaling/run.sh\` (RUNS=$RUNS, REPS=$REPS, medians);"
  echo "$(getconf _NPROCESSORS_ONLN) cores, load before: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo "Dask $(/usr/bin/python3 -c 'import distributed; print(distributed.__version__)'),"
  echo "LocalCluster of worker processes with one thread each, on loopback."
  echo
  /usr/bin/python3 "$here/measure.py" "$out/normal" "$out/trivial" "$REPS"
  echo
  echo "For reference, the command line on the same $RUNS runs: \`frictionid batch --jobs 1\`"
  echo "$(batch_rate 1) runs/s, \`--jobs 2\` $(batch_rate 2) runs/s."
  echo
  echo "Load after: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  cat "$here/plan.md"
} > "$out/results.md"
cp "$out/results.md" "$here/results.md"
cat "$here/results.md"
