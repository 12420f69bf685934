"""One version, from CMakeLists.txt's project(VERSION): the package, its metadata (setup.py)
and `frictionid --version` all say it; the package is marked typed (PEP 561) and mypy accepts it."""

import pathlib
import re
import subprocess
import sys

import frictionid


def project_version(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text()
    return re.search(r"project\(\s*frictionid\s+VERSION\s+([0-9.]+)", text).group(1)


def test_the_package_version_is_the_cmake_project_version(source_dir, exe):
    version = project_version(source_dir)
    assert frictionid.__version__ == version
    out = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.strip() == f"frictionid {version}"


def test_no_source_file_writes_the_version_itself(source_dir):
    version = project_version(source_dir)
    for path in ["python/frictionid/__init__.py", "src/cli/main.cpp", "setup.py",
                 "pyproject.toml"]:
        assert version not in (source_dir / path).read_text(), path


def test_setup_reads_the_version_from_cmakelists(source_dir):
    out = subprocess.run([sys.executable, "setup.py", "--version"], cwd=source_dir,
                         capture_output=True, text=True, check=True).stdout
    assert out.strip().splitlines()[-1] == project_version(source_dir)


def test_the_package_is_marked_typed():
    assert (pathlib.Path(frictionid.__file__).parent / "py.typed").is_file()


def test_the_type_hints_check_with_mypy(source_dir):
    """py.typed promises hints that a type checker accepts: mypy (Debian's python3-mypy) finds
    no error in the package, unannotated function bodies included."""
    try:
        import mypy  # noqa: F401
    except ImportError:
        import pytest
        pytest.skip("mypy is not installed (Debian: python3-mypy)")
    out = subprocess.run([sys.executable, "-m", "mypy", "--ignore-missing-imports",
                          "--check-untyped-defs", "--no-incremental",
                          str(source_dir / "python" / "frictionid")],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
