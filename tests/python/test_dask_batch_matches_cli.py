"""`python3 -m frictionid batch` on a Dask cluster writes `frictionid batch`'s files, byte for
byte, and exits as it does (docs/design.md §3.1, §3.6a)."""

import os
import subprocess
import sys

from conftest import without_traceability

OPTIONS = ["--model", "exact", "--pressure", "hertz", "--global-evaluations", "1000"]


def python_batch(*args):
    return subprocess.run([sys.executable, "-m", "frictionid", "batch", *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def files_under(directory):
    out = {}
    for root, _, names in os.walk(directory):
        for name in names:
            path = os.path.join(root, name)
            out[os.path.relpath(path, directory)] = open(path, "rb").read()
    return out


def test_the_summary_and_reports_are_the_cli_bytes_with_the_same_exit_code(
        run_cli, campaign, dask_client, tmp_path):
    cli = run_cli("batch", campaign, *OPTIONS, "--report", tmp_path / "cli", check=False)
    assert cli.returncode == 4, cli.stderr  # bad.csv fails, the others are fitted
    dask = python_batch(campaign, *OPTIONS, "--output", tmp_path / "dask",
                        "--scheduler", dask_client.scheduler.address)
    assert dask.returncode == 4, dask.stderr
    assert "run 'bad' failed" in dask.stderr

    expected = files_under(tmp_path / "cli")
    del expected["journal.jsonl"]  # the command line's resume log; the cluster keeps none
    got = files_under(tmp_path / "dask")
    assert sorted(got) == sorted(expected)
    assert set(got) >= {"summary.csv", "summary.json", os.path.join("runs", "load_1000",
                                                                   "report.json")}
    for name in expected:
        assert without_traceability(got[name]) == without_traceability(expected[name]), name


def test_groups_of_one_file_and_a_manifest_give_the_cli_bytes(run_cli, campaign, dask_client,
                                                              tmp_path):
    manifest = tmp_path / "manifest.csv"
    manifest.write_text("path,label,surface\n"
                        f"{campaign / 'load_1000.csv'},dry,asphalt\n"
                        f"{campaign / 'load_3000.csv'},wet,\"asphalt, wet\"\n")
    loads = tmp_path / "loads.csv"
    run_cli("generate", "--model", "exact", "--param", "f=0.8,kappa=1.2,h=0.1", "--rows", 300,
            "--noise", 0.01, "--loads", "1000,2000,3000", "--output", loads)
    cases = {"manifest": [manifest], "groups": [loads, "--group-by", "N"]}
    for name, inputs in cases.items():
        args = [*inputs, *OPTIONS, "--no-global", "--per-run-reports", "none", "--trend-x", "N"
                if name == "groups" else "mean_N"]
        cli = run_cli("batch", *args, "--report", tmp_path / f"cli_{name}")
        dask = python_batch(*args, "--output", tmp_path / f"dask_{name}",
                            "--scheduler", dask_client.scheduler.address)
        assert dask.returncode == 0, dask.stderr
        for table in ("summary.csv", "summary.json", "summary.html"):
            assert (without_traceability((tmp_path / f"dask_{name}" / table).read_bytes())
                    == without_traceability((tmp_path / f"cli_{name}" / table).read_bytes())), (
                name, cli.stdout)
    # One run per load: the grouping really happened.
    labels = [line.split(",")[0] for line in
              (tmp_path / "dask_groups" / "summary.csv").read_text().splitlines()[1:]]
    assert labels == ["1000", "2000", "3000"]


def test_bad_input_exits_2_naming_it_before_any_cluster_is_used(tmp_path):
    missing = tmp_path / "no_such.csv"
    p = python_batch(missing, "--output", tmp_path / "out", "--scheduler", "tcp://127.0.0.1:9")
    assert p.returncode == 2
    assert str(missing) in p.stderr and "no such file" in p.stderr
    assert not (tmp_path / "out").exists()

    p = python_batch(tmp_path, "--output", tmp_path / "out", "--model", "nope")
    assert p.returncode == 2 and "--model 'nope'" in p.stderr

    csv = tmp_path / "run.csv"
    csv.write_text("v_x,omega,N,R,T_x\n0.1,2,1000,0.05,500\n")
    p = python_batch(csv, "--output", tmp_path / "out", "--trend-x", "Load",
                     "--scheduler", "tcp://127.0.0.1:9")
    assert p.returncode == 2 and "--trend-x: no covariate 'Load'" in p.stderr, p.stderr
    assert not (tmp_path / "out").exists()


def test_an_unreachable_scheduler_exits_1(campaign, tmp_path):
    p = python_batch(campaign, "--output", tmp_path / "out", "--scheduler", "tcp://127.0.0.1:9",
                     "--timeout", 1)
    assert p.returncode == 1, p.stderr
    assert "frictionid: error:" in p.stderr
    assert not (tmp_path / "out" / "summary.csv").exists()
