"""Errors reach Python as exceptions carrying the command line's messages: InputError (a
ValueError) for bad input and options, FitError for a fit that fails."""

import numpy as np
import pandas as pd
import pytest

import frictionid

CLI_PREFIX = "frictionid: error: "


def cli_message(run_cli, *args, exit_code=2) -> str:
    p = run_cli(*args, check=False)
    assert p.returncode == exit_code, p.stderr
    line = p.stderr.strip().splitlines()[-1]
    assert line.startswith(CLI_PREFIX), line
    return line[len(CLI_PREFIX):]


def small_rows():
    return frictionid.generate("seed", "hertz", {"f": 0.9}, rows=40, noise=0.01, seed=3)


@pytest.mark.parametrize("cli_option, kwargs", [
    (["--fix", "zeta=1"], {"fix": {"zeta": 1}}),
    (["--fix", "b_tilde=1"], {"fix": {"b_tilde": 1}}),
    (["--bounds", "f=2:1"], {"bounds": {"f": (2, 1)}}),
    (["--loss", "huber:-1"], {"loss": "huber:-1"}),
    (["--channels", "T_z"], {"channels": ["T_z"]}),
    (["--pressure", "power:-1"], {"pressure": "power:-1"}),
    (["--model", "linear"], {"model": "linear"}),
    (["--threads", "-1"], {"threads": -1}),
])
def test_bad_options_raise_value_error_with_the_cli_message(example_csv, run_cli, tmp_path,
                                                            cli_option, kwargs):
    model = [] if "--model" in cli_option else ["--model", "seed"]
    expected = cli_message(run_cli, "fit", example_csv, *model, *cli_option, "--report", tmp_path)
    args = {"model": "seed", **kwargs}
    with pytest.raises(ValueError) as e:
        frictionid.fit(example_csv, **args)
    assert str(e.value) == expected
    assert isinstance(e.value, frictionid.InputError)


def test_a_bad_csv_file_raises_the_readers_message(source_dir, run_cli, tmp_path):
    bad = source_dir / "tests" / "data" / "bad" / "negative_N.csv"
    expected = cli_message(run_cli, "fit", bad, "--report", tmp_path)
    with pytest.raises(ValueError) as e:
        frictionid.fit(bad)
    assert str(e.value) == expected


def test_a_missing_file_is_a_value_error(tmp_path):
    with pytest.raises(ValueError, match="cannot open file"):
        frictionid.fit(tmp_path / "nothing.csv")


@pytest.mark.parametrize("change, message", [
    (lambda d: d.drop(columns=["omega"]), "no column 'omega'"),
    (lambda d: d.assign(N=-d.N), r"row 1 \(index 0\): column N has -2000; expected a finite "
                                 r"number > 0"),
    (lambda d: d.assign(R=np.where(d.index == 7, np.inf, d.R)),
     r"row 8 \(index 7\): column R has inf"),
    (lambda d: d.drop(columns=["T_x", "T_y", "M_z", "M_roll"]), "no channel column"),
    (lambda d: d.assign(T_x=np.nan, T_y=np.nan, M_z=np.nan, M_roll=np.nan),
     r"row 1 \(index 0\): no measured channel"),
    (lambda d: d.assign(T_x=d.T_x.where(d.index != 3, -np.inf)), r"row 4 \(index 3\): column T_x"),
    (lambda d: d.assign(sigma_M_z=0.0), r"column sigma_M_z has 0 while M_z is given"),
    (lambda d: d.iloc[:0], "no rows"),
    (lambda d: d.assign(v_x="fast"), "column v_x is not numeric"),
])
def test_bad_dataframes_raise_value_errors_that_name_row_and_column(change, message):
    with pytest.raises(ValueError, match=message):
        frictionid.fit(change(small_rows()))


def test_columns_of_different_lengths_are_rejected():
    d = {k: np.asarray(v) for k, v in small_rows().items()}
    d["N"] = d["N"][:-1]
    with pytest.raises(ValueError, match="column 'N' has 39 rows, column 'v_x' has 40"):
        frictionid.fit(d)


def test_a_channel_of_nan_only_is_not_measured_and_rows_still_fit():
    d = small_rows().assign(M_roll=np.nan)
    channels = frictionid.fit(d, global_search=False).channels
    assert "M_roll" not in channels and {"T_x", "M_z"} <= set(channels)


def test_a_failed_fit_raises_fit_error_with_the_cli_message(run_cli, tmp_path):
    # Loads near the largest double: with f held at 5 the model's T_x overflows at every start.
    csv = tmp_path / "overflow.csv"
    pd.DataFrame({"v_x": [0.1, 0.2, 0.3, 0.5], "omega": 2.0, "N": 1.7e308, "R": 1e-300,
                  "T_x": [1e308, 0.9e308, 0.8e308, 0.7e308]}).to_csv(csv, index=False, float_format="%.17g")
    p = run_cli("fit", csv, "--model", "seed", "--fix", "f=5", "--report", tmp_path / "r",
                check=False)
    assert p.returncode == 3
    with pytest.raises(frictionid.FitError) as e:
        frictionid.fit(csv, model="seed", fix={"f": 5})
    assert f"fit failed: {e.value}; no report written" in p.stderr
    assert isinstance(e.value, RuntimeError)


def test_an_unknown_noise_model_is_a_value_error_naming_the_choices():
    with pytest.raises(ValueError, match="--noise-model 'proportional': expected auto, constant"):
        frictionid.fit(small_rows(), noise_model="proportional")


def test_evaluate_rejects_a_load_that_is_not_positive():
    with pytest.raises(ValueError, match="N at index 1 is 0; expected a finite number > 0"):
        frictionid.evaluate("seed", "hertz", {}, [0.1, 0.2], 0, 1, [1, 0], 1)


def test_model_functions_share_the_cli_parameter_messages(run_cli):
    expected = cli_message(run_cli, "eval", "--model", "seed", "--param", "f=-1", "--vx", "1",
                           "--omega", "1")
    with pytest.raises(ValueError) as e:
        frictionid.evaluate("seed", "hertz", {"f": -1}, 1, 0, 1, 1, 1)
    assert str(e.value) == expected
    with pytest.raises(ValueError) as e:
        frictionid.generate("seed", "hertz", {"f": -1})
    assert str(e.value) == expected
