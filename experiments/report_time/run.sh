#!/usr/bin/env bash
# How long does writing the report take (report.json, report.md, report.html and every SVG
# plot), at 2,000 and 100,000 rows? Target (issue "Reports people look at"): <= 50 ms at 1e5 rows.
#
#   experiments/report_time/run.sh     # binary: $FRICTIONID, else build/frictionid
#
# Generates the rows (seed model, default design, 1 % noise), fits each REPS times with
# --model seed and takes the "report" time that `fit` prints (write_report alone, wall clock).
# Each report goes once to a directory on disk (every file is fsync'ed) and once to /dev/shm
# (tmpfs: fsync costs nothing, so the rest is the time spent making the report). Writes
# results.md; scratch in out/ (git-ignored).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bin="${FRICTIONID:-$root/build/frictionid}"
[[ "$bin" = /* ]] || bin="$PWD/$bin"
[[ -x "$bin" ]] || { echo "run.sh: no executable frictionid at $bin (set FRICTIONID)" >&2; exit 1; }
REPS=${REPS:-7}
out="$here/out"
rm -rf "$out"
mkdir -p "$out"
shm=""
[[ -d /dev/shm && -w /dev/shm ]] && shm="$(mktemp -d /dev/shm/frictionid-report-time.XXXXXX)"
trap '[[ -n "$shm" ]] && rm -rf "$shm"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# The fastest run: on a shared machine the least disturbed one, closest to the report's own cost.
fastest() { sort -g | head -1; }

{
  echo "# Report writing time"
  echo
  echo "\`experiments/report_time/run.sh\`, $REPS fits per row count, median of the \"report\" time"
  echo "that \`fit\` prints; $(getconf _NPROCESSORS_ONLN) cores, load before: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  echo "| rows | files | report.html | on disk: median (fastest) [ms] | on tmpfs: median (fastest) [ms] |"
  echo "|---|---|---|---|---|"
} > "$out/results.md"

for rows in 2000 100000; do
  data="$out/data_$rows.csv"
  "$bin" generate --model seed --param f=0.85,kappa=1.3,h=0.12 --rows "$rows" --noise 0.01 \
    --seed 4 --output "$data" > /dev/null 2>&1
  disk=() tmpfs=()
  for (( rep = 1; rep <= REPS; rep++ )); do
    t=$("$bin" fit "$data" --model seed --report "$out/report_$rows" | sed -n 's/.*report \([0-9.]*\) s$/\1/p')
    disk+=("$t")
    if [[ -n "$shm" ]]; then
      t=$("$bin" fit "$data" --model seed --report "$shm/report_$rows" | sed -n 's/.*report \([0-9.]*\) s$/\1/p')
      tmpfs+=("$t")
    fi
  done
  files=$(ls "$out/report_$rows" | wc -l)
  html_kb=$(( $(stat -c %s "$out/report_$rows/report.html") / 1024 ))
  ms() { awk '{ printf "%.0f", $1 * 1000 }'; }
  disk_ms="$(printf '%s\n' "${disk[@]}" | median | ms) ($(printf '%s\n' "${disk[@]}" | fastest | ms))"
  tmpfs_ms="—"
  [[ -n "$shm" ]] && tmpfs_ms="$(printf '%s\n' "${tmpfs[@]}" | median | ms) ($(printf '%s\n' "${tmpfs[@]}" | fastest | ms))"
  echo "| $rows | $files | $html_kb KiB | $disk_ms | $tmpfs_ms |" >> "$out/results.md"
  echo "run.sh: $rows rows done" >&2
done
{
  echo
  echo "Load after: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
  echo "On tmpfs the time is the report's own work: building report.json, report.md, report.html"
  echo "and the SVG plots (at most ~4000 plotted rows per plot, so it hardly grows with the rows)."
  echo "On disk the files are staged in the report's temporary directory and made durable by one"
  echo "syncfs before the directory is swapped in (io/report_transaction), so the disk adds little;"
  echo "with an fsync per file (an earlier version) 1e5 rows took 155 ms on disk."
} >> "$out/results.md"
cp "$out/results.md" "$here/results.md"
cat "$here/results.md"
