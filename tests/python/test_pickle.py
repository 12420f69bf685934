"""A FitResult pickles (multiprocessing, joblib, Dask move results between processes by
pickle): the copy has the same report, tables and index, and writes the same report files."""

import multiprocessing
import pickle

import pandas as pd
import pytest

import frictionid


@pytest.fixture(scope="module")
def frame(example_csv):
    return pd.read_csv(example_csv, float_precision="round_trip").iloc[50:350]


@pytest.fixture(scope="module")
def result(frame):
    return frictionid.fit(frame, model="seed", global_evaluations=500, bounds={"f": (None, 3)})


def test_a_fit_result_survives_a_pickle_round_trip(result):
    copy = pickle.loads(pickle.dumps(result))
    assert copy.report == result.report
    assert copy.params == result.params and copy.stderr == result.stderr
    for name in ("fitted", "data", "residuals", "whitened_residuals", "sigma", "covariance"):
        pd.testing.assert_frame_equal(getattr(copy, name), getattr(result, name))
    pd.testing.assert_series_equal(copy.eps, result.eps)
    assert copy.fitted.index.equals(result.fitted.index)
    pd.testing.assert_frame_equal(copy.predict(), result.predict())
    assert copy.summary() == result.summary()


def test_an_unpickled_result_writes_the_same_report_files(result, tmp_path):
    copy = pickle.loads(pickle.dumps(result))
    written = result.write_report(tmp_path / "original")
    again = copy.write_report(tmp_path / "copy")  # fits the same rows again, once
    assert [p.split("/")[-1] for p in written] == [p.split("/")[-1] for p in again]
    for name in ("report.json", "report.md", "report.html"):
        assert ((tmp_path / "original" / name).read_bytes()
                == (tmp_path / "copy" / name).read_bytes()), name


def test_an_unpickled_fit_of_a_file_writes_the_same_report_naming_its_lines(example_csv,
                                                                             tmp_path):
    # The example's outlier warnings name file lines: the copy keeps the rows' lines.
    result = frictionid.fit(str(example_csv), model="seed", global_search=False)
    assert any("at line " in w for w in result.warnings)
    copy = pickle.loads(pickle.dumps(result))
    result.write_report(tmp_path / "original")
    copy.write_report(tmp_path / "copy")
    for name in ("report.json", "report.md", "report.html"):
        assert ((tmp_path / "original" / name).read_bytes()
                == (tmp_path / "copy" / name).read_bytes()), name


def _fit_in_child(rows):
    return frictionid.fit(rows, model="seed", global_search=False)


def test_a_fit_returned_by_a_multiprocessing_worker(frame):
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        remote = pool.apply(_fit_in_child, (frame,))
    local = _fit_in_child(frame)
    assert remote.report == local.report
    assert remote.fitted.index.equals(frame.index)
