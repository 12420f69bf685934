"""What a FitResult offers besides the report: consistent statistics, predictions, text."""

import numpy as np
import pytest

import frictionid


@pytest.fixture(scope="module")
def result(example_csv):
    return frictionid.fit(example_csv, model="seed", fix={"kappa": 1.15})


def test_params_stderr_and_ci95_are_keyed_by_the_models_parameters(result):
    assert list(result.params) == ["f", "kappa", "h", "a", "b", "m"]
    assert result.params["kappa"] == 1.15 and result.stderr["kappa"] is None
    assert result.ci95["kappa"] is None
    for name in ("f", "h", "a"):
        lo, hi = result.ci95[name]
        assert lo < result.params[name] < hi
        assert hi - lo == pytest.approx(2 * 1.96 * result.stderr[name], rel=1e-3)


def test_covariance_is_symmetric_with_the_squared_standard_errors_on_its_diagonal(result):
    cov = result.covariance
    assert list(cov.index) == list(cov.columns) == result.report["correlation"]["names"]
    assert "kappa" not in cov.index
    m = cov.to_numpy()
    np.testing.assert_allclose(m, m.T, rtol=1e-12)
    np.testing.assert_allclose(np.diag(m), [result.stderr[n] ** 2 for n in cov.index],
                               rtol=1e-12)
    assert np.all(np.linalg.eigvalsh(m) > 0)


def test_predict_on_the_fitted_rows_reproduces_the_fitted_values(result):
    predicted = result.predict()
    fitted = result.fitted
    assert len(predicted) == len(fitted) == result.rows
    for channel in result.channels:
        np.testing.assert_allclose(predicted[channel], fitted[channel], rtol=1e-12, atol=1e-9)


def test_predict_accepts_new_rows_without_v_y(result):
    rows = {"v_x": [0.01, 0.1], "omega": [2.0, 2.0], "N": [1000.0, 1000.0], "R": [0.05, 0.05]}
    out = result.predict(rows)
    assert list(out.columns) == ["T_x", "T_y", "M_z", "M_roll", "N"]
    # Faster slip, larger traction along it, below the Coulomb limit f N.
    assert 0 < out.T_x[0] < out.T_x[1] < result.params["f"] * 1000.0


def test_the_summary_lists_every_parameter_and_statistic(result):
    text = result.summary()
    for name in result.params:
        assert f"    {name}:" in text
    assert "kappa:" in text and "(fixed)" in text
    assert f"{result.statistics['reduced_chi2']:.8g}" in text
    assert str(result) == text


def test_the_html_view_is_a_table_of_the_parameters(result):
    page = result._repr_html_()
    assert page.count("<tr><td>") == len(result.params)
    assert "fixed" in page


def test_evaluate_broadcasts_its_inputs():
    out = frictionid.evaluate("seed", "hertz", {"f": 0.5}, np.linspace(0.1, 1, 6).reshape(2, 3),
                              0.0, 2.0, 100.0, 0.1)
    assert out["T_x"].shape == (2, 3)
    assert np.all(np.diff(out["T_x"].ravel()) > 0)  # traction grows with the slip speed
    assert np.all(out["N"] == 100.0)


def test_every_public_function_is_documented_and_typed():
    for name in frictionid.__all__:
        obj = getattr(frictionid, name)
        assert obj.__doc__, name
        if callable(obj) and not isinstance(obj, type):
            assert "return" in obj.__annotations__, name


def test_columns_rename_as_the_command_lines_option(example_csv):
    import pandas as pd

    df = pd.read_csv(example_csv, float_precision="round_trip")
    renamed = df.rename(columns={"v_x": "speed", "omega": "spin"})
    same = frictionid.fit(renamed, model="seed", columns={"v_x": "speed", "omega": "spin"})
    assert same.params == frictionid.fit(df, model="seed").params
    with pytest.raises(ValueError, match="--columns"):
        frictionid.fit(renamed, columns={"v_z": "speed"})
