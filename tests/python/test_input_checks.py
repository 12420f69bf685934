"""Python input that is not a measurement is refused with a message naming the column or the
row (by the frame's index label), never converted silently; pd.NA means "not measured"."""

import math

import numpy as np
import pandas as pd
import pytest

import frictionid


@pytest.fixture(scope="module")
def frame(example_csv):
    return pd.read_csv(example_csv, float_precision="round_trip")


QUICK = dict(model="seed", global_search=False)


def test_pd_na_in_a_channel_column_means_not_measured(frame):
    rows = frame.copy()
    rows["T_x"] = rows["T_x"].astype("Float64")
    rows.loc[[3, 7], "T_x"] = pd.NA
    r = frictionid.fit(rows, **QUICK)
    assert r.statistics["channel_rows"]["T_x"] == len(frame) - 2
    as_nan = frame.copy()
    as_nan.loc[[3, 7], "T_x"] = np.nan
    assert r.params == frictionid.fit(as_nan, **QUICK).params


def test_pd_na_in_an_object_column_and_in_a_dict_means_not_measured(frame):
    columns = {c: frame[c].to_numpy() for c in frame.columns}
    t_x = columns["T_x"].astype(object)
    t_x[5] = pd.NA
    columns["T_x"] = t_x
    r = frictionid.fit(columns, **QUICK)
    assert r.statistics["channel_rows"]["T_x"] == len(frame) - 1


def test_pd_na_in_a_kinematic_column_names_the_row(frame):
    rows = frame.copy()
    rows["omega"] = rows["omega"].astype("Float64")
    rows.loc[4, "omega"] = pd.NA
    with pytest.raises(frictionid.InputError, match=r"row 5 \(index 4\): column omega"):
        frictionid.fit(rows, **QUICK)


@pytest.mark.parametrize("column", ["omega", "T_x"])
def test_complex_columns_are_refused_not_cut_to_their_real_part(frame, column):
    rows = frame.copy()
    rows[column] = rows[column].to_numpy() + 1e-3j
    with pytest.raises(frictionid.InputError, match=f"column {column} holds complex numbers"):
        frictionid.fit(rows, **QUICK)
    columns = {c: frame[c].to_numpy() for c in frame.columns}
    columns[column] = columns[column].astype(complex)
    with pytest.raises(frictionid.InputError, match="complex"):
        frictionid.fit(columns, **QUICK)


def test_datetime_and_timedelta_columns_are_refused_as_numbers(frame):
    rows = frame.copy()
    rows["omega"] = pd.to_datetime(rows["omega"] * 1e9)
    with pytest.raises(frictionid.InputError, match=r"column omega holds dates"):
        frictionid.fit(rows, **QUICK)
    rows["omega"] = pd.to_timedelta(frame["omega"], unit="s")
    with pytest.raises(frictionid.InputError, match=r"column omega holds durations"):
        frictionid.fit(rows, **QUICK)
    columns = {c: frame[c].to_numpy() for c in frame.columns}
    columns["N"] = columns["N"].astype("datetime64[s]")
    with pytest.raises(frictionid.InputError, match="column N holds dates"):
        frictionid.fit(columns, **QUICK)


def test_minus_inf_in_n_names_the_row_by_its_index_label(frame):
    rows = frame.iloc[100:200].copy()
    rows.loc[150, "N"] = -math.inf
    with pytest.raises(frictionid.InputError,
                       match=r"row with index 150 \(row 51 of the frame\): column N has -inf"):
        frictionid.fit(rows, **QUICK)
    labelled = rows.set_index(pd.Index([f"run-{i}" for i in rows.index]))
    with pytest.raises(frictionid.InputError, match=r"row with index 'run-150'"):
        frictionid.fit(labelled, **QUICK)


def test_a_nan_sigma_names_the_row_by_its_index_label(frame):
    rows = frame.iloc[10:].copy()
    rows.loc[42, "sigma_T_x"] = -1.0
    with pytest.raises(frictionid.InputError, match=r"row with index 42 .*column sigma_T_x"):
        frictionid.fit(rows, **QUICK)


@pytest.mark.parametrize("misspelt, canonical, drop", [
    ("vy", "v_y", "v_y"), ("Tx", "T_x", "T_x"), ("m_z", "M_z", "M_z"),
    ("sigma_Tx", "sigma_T_x", "sigma_T_x"),
])
def test_a_channel_like_column_is_an_error_with_did_you_mean(frame, misspelt, canonical, drop):
    rows = frame.drop(columns=[drop]).assign(**{misspelt: frame[drop]})
    with pytest.raises(frictionid.InputError,
                       match=f"column '{misspelt}' is not a column frictionid reads; did you "
                             f"mean '{canonical}'"):
        frictionid.fit(rows, **QUICK)


def test_unrelated_extra_columns_and_mapped_names_are_accepted(frame):
    rows = frame.assign(run="a", load_set=2000.0, R2=1.0)
    frictionid.fit(rows, **QUICK)
    renamed = frame.rename(columns={"T_x": "Tx"})
    r = frictionid.fit(renamed, columns={"T_x": "Tx"}, **QUICK)
    assert "T_x" in r.channels


def test_one_sided_bounds_keep_the_default_on_the_open_side(frame):
    default = frictionid.fit(frame, **QUICK).report["parameters"]
    r = frictionid.fit(frame, bounds={"f": (None, 2.0), "kappa": (0.5, math.inf),
                                      "h": (-math.inf, None)}, **QUICK)
    p = r.report["parameters"]
    assert (p["f"]["lower"], p["f"]["upper"]) == (default["f"]["lower"], 2.0)
    assert (p["kappa"]["lower"], p["kappa"]["upper"]) == (0.5, default["kappa"]["upper"])
    assert (p["h"]["lower"], p["h"]["upper"]) == (default["h"]["lower"],
                                                  default["h"]["upper"])


def test_one_sided_bounds_that_cross_the_default_are_refused_with_the_clis_message(frame):
    with pytest.raises(frictionid.InputError, match="--bounds.*expected lo < hi"):
        frictionid.fit(frame, bounds={"f": (None, 1e-6)}, **QUICK)
    with pytest.raises(frictionid.InputError, match="--bounds: nope has no default"):
        frictionid.fit(frame, bounds={"nope": (None, 1.0)}, **QUICK)


def test_intervals_and_bootstrap_are_fit_options(frame, cli_report, example_csv):
    r = frictionid.fit(example_csv, intervals="profile", bootstrap=30, **QUICK)
    cli = cli_report(example_csv, "--model", "seed", "--no-global", "--intervals", "profile",
                     "--bootstrap", "30")
    assert r.report == cli
    f = r.report["parameters"]["f"]
    assert f["ci95_bootstrap"] is not None and f["ci95_profile"] is not None
    with pytest.raises(frictionid.InputError, match="--bootstrap"):
        frictionid.fit(frame, bootstrap=-1, **QUICK)
    with pytest.raises(frictionid.InputError, match="--intervals 'nope'"):
        frictionid.fit(frame, intervals="nope", **QUICK)


@pytest.mark.parametrize("seed, why", [(2**32, "too large"), (-1, "negative")])
def test_seeds_outside_32_bits_are_refused_as_by_the_cli(frame, seed, why):
    with pytest.raises(frictionid.InputError,
                       match=f"--seed: got '{seed}' \\({why}\\); expected a whole number from 0 "
                             f"to 4294967295"):
        frictionid.fit(frame, model="seed", seed=seed)


def test_generate_refuses_more_rows_than_the_cli_at_once():
    import time

    start = time.monotonic()
    with pytest.raises(frictionid.InputError, match="--rows"):
        frictionid.generate("seed", "hertz", rows=10**12)
    assert time.monotonic() - start < 1.0
