#!/usr/bin/env bash
# What do threads save eval and generate on a spot whose rows are integrated one by one? 10,000
# rows on the bundled footprint sampled on a 64 x 64 grid (scripts/make-footprint-map), where a
# table would cost more than the rows and each row takes ~0.6 ms (README.md, "frictionid eval").
#
#   experiments/rows_on_threads/run.sh     # binary: $FRICTIONID, else build/frictionid
#
# Times `generate` and `eval --input` with --threads 1 and with every core, REPS times each
# (wall clock, median), and checks that both thread counts write the same bytes. Writes
# results.md; scratch in out/ (git-ignored).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"  # root, bin ($FRICTIONID or build/frictionid), py
REPS=${REPS:-5}
ROWS=${ROWS:-10000}
out="$here/out"
rm -rf "$out"
mkdir -p "$out"

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
seconds() {  # wall seconds of the command
  local t0 t1
  t0=$(date +%s.%N)
  "$@" 2>/dev/null
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }'
}

"$py" "$root/scripts/make-footprint-map" "$out/map64.csv" 64 64
model=(--model exact --contact "map:$out/map64.csv" --param f=0.8,kappa=1.1,h=0.05,h_y=0.03)
design=(--rows "$ROWS" --noise 0.01 --slip-angles 0,4,-4)
cores=$(nproc)
declare -A median_of
for threads in 1 "$cores"; do
  g=() e=()
  for ((r = 0; r < REPS; r++)); do
    g+=("$(seconds "$bin" generate "${model[@]}" "${design[@]}" --threads "$threads" \
            --output "$out/g$threads.csv")")
    e+=("$(seconds "$bin" eval "${model[@]}" --threads "$threads" --input "$out/g1.csv" \
            --output "$out/e$threads.csv")")
  done
  median_of[g$threads]=$(printf '%s\n' "${g[@]}" | median)
  median_of[e$threads]=$(printf '%s\n' "${e[@]}" | median)
done
cmp -s "$out/g1.csv" "$out/g$cores.csv" || { echo "generate: the files differ" >&2; exit 1; }
cmp -s "$out/e1.csv" "$out/e$cores.csv" || { echo "eval: the files differ" >&2; exit 1; }
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
{
  echo "# eval and generate on threads: $ROWS rows on a 64 x 64 pressure map"
  echo
  echo "Commit $commit, $cores CPUs, load average $(cut -d' ' -f1 /proc/loadavg) at the end;" \
       "medians of $REPS runs, wall clock. Both thread counts wrote the same bytes."
  echo
  echo "| command | --threads 1 | --threads $cores | ratio |"
  echo "|---|---:|---:|---:|"
  for c in g e; do
    name=$([[ $c == g ]] && echo generate || echo "eval --input")
    printf '| %s | %.2f s | %.2f s | %.2f |\n' "$name" "${median_of[${c}1]}" \
      "${median_of[$c$cores]}" "$(awk -v a="${median_of[${c}1]}" -v b="${median_of[$c$cores]}" 'BEGIN { print a / b }')"
  done
} > "$here/results.md"
cat "$here/results.md"
