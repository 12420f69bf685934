#!/bin/sh
# `pip install .` of the source tree into a fresh venv that sees Debian's numpy and pandas
# (--system-site-packages), offline (--no-index: pip may download nothing), then import the
# installed package from outside the tree: its version metadata is CMakeLists.txt's, and it fits.
#
# usage: venv_install.sh SOURCE_DIR BUILD_DIR PYTHON
# The extension is built in BUILD_DIR (reused: only frictionid_python is brought up to date);
# with FRICTIONID_VENV_TEST_FRESH=1 setup.py configures and builds everything afresh instead.
set -eu
source_dir=$1
build_dir=$2
python=$3
# Skipped (77) where Debian's venv, setuptools or wheel are not installed, saying so.
if ! "$python" -c "import ensurepip, setuptools, wheel" 2>/dev/null; then
  echo "skipped: needs python3-venv, python3-setuptools and python3-wheel" >&2
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$python" -m venv --system-site-packages "$work/venv"
if [ "${FRICTIONID_VENV_TEST_FRESH:-0}" = 1 ]; then
  unset FRICTIONID_BUILD_DIR
else
  export FRICTIONID_BUILD_DIR="$build_dir"
fi
export FRICTIONID_SETUP_BUILD_BASE="$work/setup"
unset PYTHONPATH
(cd "$source_dir" &&
  "$work/venv/bin/pip" install --quiet --no-index --no-cache-dir --no-build-isolation \
    --no-deps .)

cd "$work"
"$work/venv/bin/python" - "$source_dir" <<'PY'
import importlib.metadata as metadata
import pathlib
import re
import sys

import frictionid

source = pathlib.Path(sys.argv[1])
expected = re.search(r"project\(\s*frictionid\s+VERSION\s+([0-9.]+)",
                     (source / "CMakeLists.txt").read_text()).group(1)
assert metadata.version("frictionid") == frictionid.__version__ == expected, expected
package = pathlib.Path(frictionid.__file__).parent
assert package.is_relative_to(pathlib.Path(sys.prefix)), package  # the venv's copy
assert (package / "py.typed").is_file()
result = frictionid.fit(str(source / "data" / "example_hertz.csv"), global_search=False)
assert result.rows == 600
print(f"frictionid {metadata.version('frictionid')} installed in {package}")
PY
