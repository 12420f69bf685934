#!/usr/bin/env bash
# What do the tabulated spot integrals cost to build and to evaluate? (README.md, "Contact
# spots")
#
#   experiments/spot_speed/run.sh        # ~5 min; REPEAT=5 builds and passes per median
#
# Builds spot_speed.cpp (header-only, no CMake target) with g++ -O3 -fno-math-errno, as a Release
# build compiles the library (CMakeLists.txt), into out/ and writes results.md next to this
# script.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
REPEAT="${REPEAT:-5}"

out="$here/out"
rm -rf "$out"
mkdir -p "$out"
g++ -O3 -fno-math-errno -std=c++17 -pthread -I"$root/include" "$here/spot_speed.cpp" -o "$out/spot_speed"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
{
  echo "# Tabulated spot integrals: build and evaluation time"
  echo
  echo "Commit $commit, g++ -O3 -fno-math-errno, $(nproc) CPUs, load average $(cut -d' ' -f1 /proc/loadavg) at the" \
       "start; medians of $REPEAT builds and of $REPEAT (table: $((5 * REPEAT))) passes over 256" \
       "centres of rotation (CPU time), one thread; builds over 1 s: medians of 3."
  echo
  "$out/spot_speed" --repeat "$REPEAT" --root "$root"
} > "$here/results.md"
cat "$here/results.md"
