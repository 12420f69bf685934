"""A fit from Python and `frictionid fit` on the same rows with the same options give the same
numbers, bit for bit, and the same report."""

import json

import pandas as pd
import pytest

import frictionid


def test_a_csv_path_gives_the_report_of_the_command_line(example_csv, cli_report):
    cli = cli_report(example_csv, "--model", "exact", "--pressure", "hertz")
    py = frictionid.fit(example_csv, model="exact", pressure="hertz")
    assert py.report == cli
    for name, entry in cli["parameters"].items():
        assert py.params[name] == entry["value"]
        assert py.stderr[name] == entry["stderr"]
        assert py.ci95[name] == tuple(entry["ci95"])


def test_a_dataframe_read_round_trip_gives_the_same_numbers_with_every_option(
        example_csv, cli_report):
    cli = cli_report(example_csv, "--model", "seed", "--pressure", "power:0.5",
                     "--fix", "kappa=1.15", "--bounds", "f=0.1:2,h=-0.5:0.5",
                     "--noise-model", "affine", "--loss", "huber:3", "--channels", "T_x,M_z",
                     "--starts", "3", "--seed", "5", "--global-evaluations", "800",
                     "--global-subsample", "300", "--threads", "2")
    df = pd.read_csv(example_csv, float_precision="round_trip")
    # threads=1 here: the result must not depend on the thread count either.
    py = frictionid.fit(df, model="seed", pressure="power:0.5", fix={"kappa": 1.15},
                        bounds={"f": (0.1, 2), "h": (-0.5, 0.5)}, noise_model="affine",
                        loss=("huber", 3), channels=["T_x", "M_z"], starts=3, seed=5,
                        global_evaluations=800, global_subsample=300, threads=1)
    assert list(py.report) == list(cli)
    assert py.params == {n: e["value"] for n, e in cli["parameters"].items()}
    assert py.stderr == {n: e["stderr"] for n, e in cli["parameters"].items()}
    assert py.stderr["kappa"] is None  # fixed
    assert py.report == cli


def test_a_report_written_from_python_is_the_command_lines_file(example_csv, run_cli, tmp_path):
    run_cli("fit", example_csv, "--model", "seed", "--report", tmp_path / "cli")
    result = frictionid.fit(example_csv, model="seed")
    written = result.write_report(tmp_path / "py")
    assert str(tmp_path / "py" / "report.json") in written
    py = json.loads((tmp_path / "py" / "report.json").read_text())
    cli = json.loads((tmp_path / "cli" / "report.json").read_text())
    # The same fit; only the provenance names the front end that wrote it.
    assert cli["provenance"]["command_line"].startswith("frictionid fit ")
    assert py["provenance"]["command_line"] is None
    assert py["provenance"]["inputs"] == []
    assert py["provenance"]["version"] == cli["provenance"]["version"]
    del py["provenance"], cli["provenance"]
    assert py == cli


def test_generate_makes_the_rows_of_the_command_line(run_cli, tmp_path):
    out = tmp_path / "gen.csv"
    run_cli("generate", "--model", "corrected", "--pressure", "parabolic", "--param",
            "f=0.7,kappa=1.3,h=0.05", "--rows", "97", "--noise", "0.02", "--sigma-columns",
            "--seed", "11", "--loads", "1000,3000", "--slip-angles", "0,30", "--output", out)
    cli = pd.read_csv(out, float_precision="round_trip")
    py = frictionid.generate("corrected", "parabolic", {"f": 0.7, "kappa": 1.3, "h": 0.05},
                             rows=97, noise=0.02, sigma_columns=True, seed=11,
                             loads=[1000, 3000], slip_angles_deg=[0, 30])
    assert py.attrs["truth"]["f"] == 0.7
    # The CSV writes 2.0 as "2", which pandas reads as an integer column: compare values.
    pd.testing.assert_frame_equal(py[list(cli.columns)], cli, check_exact=True,
                                  check_dtype=False)


def test_evaluate_predicts_what_eval_writes(example_csv, run_cli, tmp_path):
    out = tmp_path / "eval.csv"
    params = "f=0.8,kappa=1.2,h=0.1"
    run_cli("eval", "--model", "exact", "--pressure", "hertz", "--param", params,
            "--input", example_csv, "--output", out)
    cli = pd.read_csv(out, float_precision="round_trip")
    rows = pd.read_csv(example_csv, float_precision="round_trip")
    py = frictionid.evaluate("exact", "hertz", {"f": 0.8, "kappa": 1.2, "h": 0.1}, rows.v_x,
                             rows.v_y, rows.omega, rows.N, rows.R)
    for name in ("T_x", "T_y", "M_z", "M_roll"):
        assert (py[name] == cli[name + "_model"].to_numpy()).all(), name


def test_coefficients_are_the_command_lines(run_cli):
    cli = json.loads(run_cli("coefficients", "--pressure", "power:1.7", "--kappa", "1.4",
                             "--alpha", "0.3").stdout)
    assert frictionid.coefficients("power:1.7", kappa=1.4, alpha=0.3) == cli


def test_simulate_ends_where_the_command_line_ends(run_cli):
    cli = json.loads(run_cli("simulate", "--model", "exact", "--pressure", "uniform",
                             "--inertia-ratio", "0.5", "--v0", "1", "--omega0", "10", "--R",
                             "0.1", "--param", "f=0.3").stdout)
    py = frictionid.simulate("exact", "uniform", {"f": 0.3}, inertia_ratio=0.5, v0=1,
                             omega0=10, R=0.1)
    for key in ("eps_final", "t_stop_slide", "t_stop_spin", "distance", "steps"):
        assert py[key] == cli[key], key
    t = py["trajectory"]
    assert t.v_x.iloc[0] == pytest.approx(1.0) and t.omega.iloc[0] == pytest.approx(10.0)
    assert (t.t.diff().dropna() > 0).all()
    assert (t.energy.diff().dropna() <= 0).all()  # friction only takes energy away
