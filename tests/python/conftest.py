"""Shared fixtures: the command-line executable and the repository's data, from the variables
CTest sets (tests/CMakeLists.txt)."""

import json
import os
import pathlib
import subprocess

import pytest

import frictionid


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
    """Runs `frictionid fit CSV OPTIONS... --report DIR` and returns report.json as a dict,
    without its "provenance" (the command line that wrote the file, which a FitResult from
    Python has no part of)."""

    def fit(csv, *options):
        out = tmp_path / "cli_report"
        run_cli("fit", csv, *options, "--report", out)
        report = json.loads((out / "report.json").read_text())
        del report["provenance"]
        return report

    return fit


@pytest.fixture(scope="session")
def dask_client():
    """A real Dask cluster for the scale-out tests: two worker processes of one thread each on
    loopback, shared by the tests of a session (starting one takes seconds)."""
    import logging

    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, processes=True, threads_per_worker=1, host="127.0.0.1",
                      dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        yield client


@pytest.fixture(scope="session")
def campaign(exe, tmp_path_factory):
    """A small campaign written by `frictionid generate`: three loads, each its own file with its
    own f (as a real tire's friction falls with load), one common kappa and h, and one file that
    is not a dataset (its run fails)."""
    directory = tmp_path_factory.mktemp("campaign")
    for load, f in ((1000, 0.85), (2000, 0.8), (3000, 0.75)):
        subprocess.run([exe, "generate", "--model", "exact", "--pressure", "hertz", "--param",
                        f"f={f},kappa=1.2,h=0.1", "--rows", "200", "--noise", "0.01", "--seed",
                        str(load), "--loads", str(load), "--output",
                        str(directory / f"load_{load}.csv")], check=True, capture_output=True)
    (directory / "bad.csv").write_text("not,a,dataset\n1,2,3\n")
    return directory


@pytest.fixture(scope="session")
def second_long_fit():
    """A fit of about a second on one core, as a function of no arguments (the GIL tests): the
    exact model with the pressure exponent free."""
    rows = frictionid.generate("exact", "power:1.5", {"f": 0.8, "kappa": 1.2, "h": 0.05},
                               rows=600, noise=0.01, seed=2)
    return lambda: frictionid.fit(rows, model="exact", pressure="power:1", threads=1, starts=2,
                                  global_evaluations=1000)


def without_traceability(data: bytes) -> bytes:
    """A report file's bytes without what names the run that wrote it (the "Traceability"
    section of a page, the "provenance" key of a JSON report), as tests/support/
    without_traceability.hpp: the command line and the Python driver are asked differently,
    and must agree on everything else byte for byte."""
    text = data.decode("utf-8", errors="surrogateescape")
    html = text.find('<h2 id="traceability">')
    if html >= 0:
        end = text.find("</dl>\n", html)
        if end >= 0:
            text = text[:html] + text[end + 6:]
        return text.encode("utf-8", errors="surrogateescape")
    md = text.find("## Traceability\n")
    if md >= 0:
        end = text.find("\n\n", md + 16)
        if end >= 0:
            text = text[:md] + text[end + 2:]
        return text.encode("utf-8", errors="surrogateescape")
    if text.startswith("{"):
        try:
            j = json.loads(text, object_pairs_hook=dict)
        except ValueError:
            return data
        if isinstance(j, dict):
            j.pop("provenance", None)
        return j
    return data
