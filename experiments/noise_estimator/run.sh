#!/usr/bin/env bash
# Does the two-term noise estimator reach the likelihood maximum on every dataset? (README.md)
#
#   experiments/noise_estimator/run.sh        # ~6 min on one core; R=200 for a quick run
#
# Builds noise_stress (stress.cpp) in $BUILD_DIR (default build-study, Release, benchmarks on),
# runs R replicates of each two-term form, and writes results.md next to this script; the
# per-replicate CSVs go to out/ (scratch).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
R="${R:-1000}"
BUILD_DIR="${BUILD_DIR:-$root/build-study}"

out="$here/out"
rm -rf "$out"
mkdir -p "$out"
cmake -S "$root" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DFRICTIONID_BUILD_TESTS=OFF \
  -DFRICTIONID_BUILD_BENCHMARKS=ON > "$out/cmake.log"
cmake --build "$BUILD_DIR" -j 2 --target noise_stress >> "$out/cmake.log"
cp "$BUILD_DIR/experiments/noise_stress" "$out/noise_stress"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
{
  echo "# Two-term noise estimator against brute force"
  echo
  echo "Commit $commit, $R replicates per form (tests/support/noise_stress_sample.hpp)."
  echo
  for form in affine additive; do
    echo "- $("$out/noise_stress" --replicates "$R" --form "$form" --output "$out/$form.csv")"
  done
} > "$here/results.md"
cat "$here/results.md"
