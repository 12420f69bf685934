"""Results line up with the DataFrame they came from (issue: a filtered frame's `sub["fit"] =
r.fitted["T_x"]` silently misaligned rows): every per-row table keeps the frame's index, and
the residuals are there raw and whitened by the fit's own sigmas."""

import numpy as np
import pandas as pd
import pytest

import frictionid


@pytest.fixture(scope="module")
def frame(example_csv):
    return pd.read_csv(example_csv, float_precision="round_trip")


@pytest.fixture(scope="module")
def filtered(frame):
    return frame[frame["N"] > 2500]  # index 1, 2, 4, ...: not 0..n-1


@pytest.fixture(scope="module")
def result(filtered):
    return frictionid.fit(filtered, model="seed", global_evaluations=500)


def test_fitted_eps_and_data_keep_a_filtered_frames_index(filtered, result):
    for table in (result.fitted, result.data, result.eps, result.residuals, result.sigma):
        assert table.index.equals(filtered.index)
    sub = filtered.copy()
    sub["fit"] = result.fitted["T_x"]  # aligned by label: no NaN, the right rows
    assert not sub["fit"].isna().any()
    np.testing.assert_array_equal(sub["fit"].to_numpy(), result.fitted["T_x"].to_numpy())
    pd.testing.assert_series_equal(result.data["N"], filtered["N"], check_dtype=False)


def test_predict_keeps_the_index_of_the_frame_it_is_given(filtered, result):
    shuffled = filtered.sample(frac=1.0, random_state=3)
    predicted = result.predict(shuffled)
    assert predicted.index.equals(shuffled.index)
    # The same row gives the same prediction whatever its position.
    pd.testing.assert_series_equal(predicted["T_x"].sort_index(), result.predict()["T_x"])
    assert result.predict().index.equals(filtered.index)


def test_residuals_are_measured_minus_fitted_and_nan_where_not_measured(filtered):
    rows = filtered.copy()
    rows.loc[rows.index[3], "M_z"] = np.nan
    r = frictionid.fit(rows, model="seed", global_evaluations=500)
    expected = rows["T_x"] - r.fitted["T_x"]
    pd.testing.assert_series_equal(r.residuals["T_x"], expected, check_names=False)
    assert np.isnan(r.residuals.loc[rows.index[3], "M_z"])
    assert np.isnan(r.whitened_residuals.loc[rows.index[3], "M_z"])


def test_whitened_residuals_are_the_ones_the_fit_summed_into_chi2(result):
    w = result.whitened_residuals.to_numpy()
    chi2 = np.nansum(w * w)
    assert chi2 == pytest.approx(result.statistics["chi2"], rel=1e-12)


def test_whitened_residuals_use_the_estimated_noise_model_per_row(run_cli, tmp_path):
    path = tmp_path / "plain.csv"
    run_cli("generate", "--model", "seed", "--rows", 400, "--noise", 0.02, "--noise-abs", 0.5,
            "--output", path)
    r = frictionid.fit(str(path), model="seed", noise_model="affine", global_evaluations=500)
    assert r.statistics["noise_model"]["iterations"] > 0
    sigma = r.sigma["T_x"].to_numpy()
    assert sigma.std() > 0  # affine: sigma varies with the fitted value, row by row
    w = r.whitened_residuals.to_numpy()
    assert np.nansum(w * w) == pytest.approx(r.statistics["chi2"], rel=1e-12)


def test_a_dict_of_arrays_gives_a_range_index(frame):
    columns = {c: frame[c].to_numpy() for c in frame.columns}
    r = frictionid.fit(columns, model="seed", global_search=False)
    assert r.fitted.index.equals(pd.RangeIndex(len(frame)))
