#!/usr/bin/env bash
# Installs frictionid from the build tree into a temporary prefix, builds examples/ against it as
# a separate CMake project (find_package(frictionid CONFIG REQUIRED)), and fits the bundled
# example through the public headers.
# Usage: consume_installed_package.sh SOURCE_DIR BUILD_DIR [CMAKE_ARG...]
#   CMAKE_ARGs go to the consumer's configure step (a sanitizer build passes its link flags).
set -euo pipefail
source_dir=$1
build_dir=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/fit_from_csv" "$source_dir/data/example_hertz.csv" hertz "$work/report")
echo "$out"
# The bundled example was made with f = 0.9, kappa = 1.15, h = 0.08 and 1 % noise.
echo "$out" | awk '
  $1 == "f"     { f = $2 }
  $1 == "kappa" { k = $2 }
  $1 == "h"     { h = $2 }
  END {
    ok = (f > 0.899 && f < 0.901 && k > 1.148 && k < 1.152 && h > 0.0795 && h < 0.0805)
    if (!ok) { print "installed-package fit does not recover the truth" > "/dev/stderr"; exit 1 }
  }'
test -s "$work/report/report.json"
echo "installed package: found, built against, fitted the example"
