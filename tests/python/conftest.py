"""Shared fixtures: the command-line executable and the repository's data, from the variables
CTest sets (tests/CMakeLists.txt)."""

import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def exe() -> str:
    path = os.environ.get("FRICTIONID_EXE")
    if not path:
        pytest.fail("FRICTIONID_EXE is not set: run these tests through ctest")
    return path


@pytest.fixture(scope="session")
def source_dir() -> pathlib.Path:
    path = os.environ.get("FRICTIONID_SOURCE_DIR")
    if not path:
        pytest.fail("FRICTIONID_SOURCE_DIR is not set: run these tests through ctest")
    return pathlib.Path(path)


@pytest.fixture(scope="session")
def example_csv(source_dir) -> pathlib.Path:
    return source_dir / "data" / "example_hertz.csv"


@pytest.fixture
def run_cli(exe):
    """Runs `frictionid ARGS...`; returns the CompletedProcess (text mode)."""

    def run(*args, check=True):
        p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"frictionid {' '.join(map(str, args))} exited "
                                 f"{p.returncode}: {p.stderr}")
        return p

    return run


@pytest.fixture
def cli_report(run_cli, tmp_path):
    """Runs `frictionid fit CSV OPTIONS... --report DIR` and returns report.json as a dict."""

    def fit(csv, *options):
        out = tmp_path / "cli_report"
        run_cli("fit", csv, *options, "--report", out)
        return json.loads((out / "report.json").read_text())

    return fit
