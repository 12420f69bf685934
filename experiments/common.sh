# Sourced by every experiments/*/run.sh after it has set `here` (its own folder): the project
# root, the frictionid binary under test (absolute; $FRICTIONID or build/frictionid), Debian's
# Python with numpy and scipy, installed with gnuplot when missing.
root="$(cd "$here/../.." && pwd)"
bin="${FRICTIONID:-$root/build/frictionid}"
[[ "$bin" = /* ]] || bin="$PWD/$bin"  # a relative $FRICTIONID is relative to the caller
[[ -x "$bin" ]] || { echo "run.sh: no executable frictionid at $bin (set FRICTIONID)" >&2; exit 1; }
py=/usr/bin/python3
"$root/scripts/install-deps" --experiments >&2
