"""contact= (``--contact``) and free= (``--free``) from Python: the same requests, checks and
numbers as the command line, on an ellipse, a rectangle and a pressure map."""

import json
import pickle

import numpy as np
import pandas as pd
import pytest

import frictionid
from frictionid import _frictionid

TRUTH = {"f": 0.9, "kappa": 1.15, "h": 0.08, "h_y": 0.05}


@pytest.fixture
def footprint(source_dir):
    return source_dir / "data" / "footprint_map.csv"


@pytest.fixture
def ellipse_csv(run_cli, tmp_path):
    out = tmp_path / "ellipse.csv"
    run_cli("generate", "--model", "exact", "--contact", "ellipse:0.7", "--param",
            ",".join(f"{k}={v}" for k, v in TRUTH.items()), "--rows", "120", "--noise", "0.005",
            "--output", out)
    return out


def test_a_fit_on_an_ellipse_gives_the_report_of_the_command_line(ellipse_csv, cli_report):
    cli = cli_report(ellipse_csv, "--model", "exact", "--contact", "ellipse:0.7")
    py = frictionid.fit(ellipse_csv, model="exact", contact="ellipse:0.7")
    assert cli["contact"] == "ellipse:0.7"
    assert py.contact == "ellipse:0.7"
    assert py.report == cli
    assert set(py.params) == {"f", "kappa", "h", "h_y", "q"}
    assert "M_tilt" in py.channels


def test_the_extension_names_the_spot_of_its_fit_in_a_read_only_contact(ellipse_csv,
                                                                        example_csv):
    for data, model, contact in ((ellipse_csv, "exact", "ellipse:0.7"),
                                 (example_csv, "seed", "circle")):
        request = _frictionid.FitRequest()
        request.model = model
        request.contact = contact
        request.no_global = True
        output = _frictionid.fit(_frictionid.load_dataset_csv(str(data)), request)
        assert output.contact == contact
        # The report names a spot other than the circle, with the same label.
        assert output.report().get("contact", "circle") == contact
        with pytest.raises(AttributeError):
            output.contact = "rect:0.5"


def test_free_q_fits_the_aspect_as_the_command_line_does(run_cli, tmp_path, cli_report):
    data = tmp_path / "rect.csv"
    run_cli("generate", "--model", "exact", "--contact", "rect:0.7", "--param",
            "f=0.9,kappa=1.15,h=0.08,h_y=0.05", "--rows", "100", "--output", data)
    cli = cli_report(data, "--model", "exact", "--contact", "rect:0.6", "--free", "q",
                     "--no-global")
    py = frictionid.fit(data, model="exact", contact="rect:0.6", free=["q"],
                        global_search=False)
    assert py.report == cli
    assert py.params["q"] == pytest.approx(0.7, rel=1e-8)
    # predict() evaluates on the fitted aspect: the fitted rows again.
    predicted = py.predict()
    for channel in py.channels:
        np.testing.assert_allclose(predicted[channel], py.fitted[channel], rtol=1e-9,
                                   atol=1e-9 * np.abs(py.fitted[channel]).max())


def test_evaluate_on_an_ellipse_of_aspect_one_equals_the_circle():
    v_x = np.array([0.3, -0.02, 0.4, 0.0])
    v_y = np.array([0.0, 0.05, 0.0, 0.0])
    omega = np.array([2.0, -3.0, 0.0, 1.5])
    params = {"f": 0.9, "kappa": 1.3, "h": 0.2}
    circle = frictionid.evaluate("exact", "hertz", params, v_x, v_y, omega, 2000.0, 0.05)
    ellipse = frictionid.evaluate("exact", "hertz", params, v_x, v_y, omega, 2000.0, 0.05,
                                  contact="ellipse:1")
    assert "M_tilt" not in circle
    np.testing.assert_allclose(ellipse["M_tilt"], 0.0, atol=1e-12 * 2000 * 0.05)
    for k in ("T_x", "T_y", "M_z", "M_roll", "N"):
        np.testing.assert_allclose(ellipse[k], circle[k], rtol=0, atol=1e-12 * 2000)


def test_generate_on_a_spot_writes_m_tilt_as_the_command_line(run_cli, tmp_path):
    out = tmp_path / "gen.csv"
    run_cli("generate", "--model", "exact", "--contact", "rect:0.5", "--param",
            "f=0.8,h=0.1,h_y=0.05", "--rows", "30", "--noise", "0.01", "--seed", "4",
            "--output", out)
    cli = pd.read_csv(out, float_precision="round_trip")
    py = frictionid.generate("exact", None, {"f": 0.8, "h": 0.1, "h_y": 0.05},
                             contact="rect:0.5", rows=30, noise=0.01, seed=4)
    assert list(cli.columns)[-1] == "M_tilt"
    assert py.attrs["contact"] == "rect:0.5"
    assert py.attrs["truth"]["q"] == 0.5
    # The CSV writes 0.0 as "0", which pandas reads as an integer column: compare values.
    pd.testing.assert_frame_equal(py[list(cli.columns)], cli, check_exact=True,
                                  check_dtype=False)
    circle = frictionid.generate("exact", "hertz", {"f": 0.8}, rows=5)
    assert "M_tilt" not in circle.columns
    assert circle.attrs["contact"] == "circle"


def test_evaluate_and_generate_give_the_same_numbers_on_any_threads(footprint):
    rng = np.random.default_rng(3)
    v_x, v_y = rng.normal(0.0, 0.2, 200), rng.normal(0.0, 0.05, 200)
    omega = np.where(np.arange(200) % 2 == 0, 2.0, -2.0)
    params = {"f": 0.8, "kappa": 1.1, "h": 0.05, "h_y": 0.03}
    spot = f"map:{footprint}"
    one = frictionid.evaluate("exact", None, params, v_x, v_y, omega, 3000.0, 0.05,
                              contact=spot, threads=1)
    two = frictionid.evaluate("exact", None, params, v_x, v_y, omega, 3000.0, 0.05,
                              contact=spot, threads=2)
    assert one.keys() == two.keys()
    for k in one:
        np.testing.assert_array_equal(one[k], two[k])
    kw = dict(contact="rect:0.6", rows=150, noise=0.01, slip_angles_deg=[0.0, 6.0])
    pd.testing.assert_frame_equal(frictionid.generate("exact", "hertz", params, threads=1, **kw),
                                  frictionid.generate("exact", "hertz", params, threads=2, **kw),
                                  check_exact=True)
    with pytest.raises(frictionid.InputError, match="--threads must be 0"):
        frictionid.evaluate("exact", None, params, 0.1, 0.0, 1.0, 1.0, 1.0, contact=spot,
                            threads=-1)


def test_evaluate_and_generate_report_their_rows_and_stop_on_a_token(footprint):
    rng = np.random.default_rng(5)
    n = 3000
    v_x, v_y = rng.normal(0.0, 0.2, n), rng.normal(0.0, 0.05, n)
    omega = np.where(np.arange(n) % 2 == 0, 2.0, -2.0)
    params = {"f": 0.8, "h_y": 0.03}
    spot = f"map:{footprint}"
    seen = []
    heard = frictionid.evaluate("exact", None, params, v_x, v_y, omega, 3000.0, 0.05,
                                contact=spot, threads=1, progress=seen.append)
    rows = [p for p in seen if p["stage"] == "model rows"]
    assert rows and all(p["total"] == n and 0 < p["done"] < n for p in rows), seen
    quiet = frictionid.evaluate("exact", None, params, v_x, v_y, omega, 3000.0, 0.05,
                                contact=spot, threads=1)
    for k in quiet:
        np.testing.assert_array_equal(heard[k], quiet[k])
    seen.clear()
    frictionid.generate("exact", None, params, contact=spot, rows=n, threads=1,
                        progress=seen.append)
    assert any(p["stage"] == "model rows" and p["total"] == n for p in seen), seen
    token = frictionid.CancelToken()
    token.cancel()
    with pytest.raises(frictionid.FitCancelled):
        frictionid.evaluate("exact", None, params, v_x, v_y, omega, 3000.0, 0.05,
                            contact=spot, cancel=token)
    with pytest.raises(frictionid.FitCancelled):
        frictionid.generate("exact", None, params, contact=spot, rows=n, cancel=token)


def test_coefficients_and_simulate_take_a_contact(run_cli, footprint):
    py = frictionid.coefficients(kappa=1.2, contact="ellipse:0.6")
    cli = json.loads(run_cli("coefficients", "--kappa", "1.2", "--contact",
                             "ellipse:0.6").stdout)
    assert py == cli
    assert frictionid.coefficients(contact=f"map:{footprint}")["contact"] == f"map:{footprint}"
    out = frictionid.simulate("exact", "uniform", {"f": 0.3}, contact="ellipse:0.8",
                              inertia_ratio=0.5, v0=1, omega0=10, R=0.1, trajectory=False)
    assert out["contact"] == "ellipse:0.8"
    assert out["stopped"]
    on_map = frictionid.simulate(params={"f": 0.3}, contact=f"map:{footprint}",
                                 inertia_ratio=0.5, v0=1, omega0=10, R=0.1, trajectory=False)
    assert on_map["pressure"] == "map"
    assert frictionid.simulate(params={"f": 0.3}, inertia_ratio=0.5, trajectory=False)[
        "pressure"] == "uniform"


def test_a_map_is_the_pressure(run_cli, tmp_path, footprint):
    data = tmp_path / "map.csv"
    run_cli("generate", "--model", "exact", "--contact", f"map:{footprint}", "--param",
            "f=0.8,h=0.05,h_y=0.03", "--rows", "60", "--output", data)
    with pytest.raises(frictionid.InputError, match="leave --pressure out with map:FILE"):
        frictionid.fit(data, model="exact", pressure="hertz", contact=f"map:{footprint}")
    with pytest.raises(frictionid.InputError, match="--pressure: a pressure map"):
        frictionid.evaluate("exact", "uniform", {}, 0.1, 0.0, 1.0, 1.0, 1.0,
                            contact=f"map:{footprint}")
    r = frictionid.fit(data, model="exact", contact=f"map:{footprint}")
    assert r.pressure == "map"
    assert r.params["h_y"] == pytest.approx(0.03, rel=1e-8)


def test_bad_spots_raise_the_command_lines_messages(ellipse_csv, run_cli):
    cases = [
        (dict(contact="ellipse:5"), ["--contact", "ellipse:5"]),
        (dict(contact="square:1"), ["--contact", "square:1"]),
        (dict(free=["q"]), ["--free", "q"]),
        (dict(contact="ellipse:0.7", fix={"h": 0.9, "h_y": 0.9}),
         ["--contact", "ellipse:0.7", "--fix", "h=0.9,h_y=0.9"]),
    ]
    for kwargs, args in cases:
        p = run_cli("fit", ellipse_csv, "--model", "exact", *args, "--report", "unused",
                    check=False)
        assert p.returncode == 2
        message = p.stderr.strip().removeprefix("frictionid: error: ")
        with pytest.raises(frictionid.InputError) as e:
            frictionid.fit(ellipse_csv, model="exact", **kwargs)
        assert str(e.value) == message
    with pytest.raises(frictionid.InputError, match="needs --model exact"):
        frictionid.fit(ellipse_csv, model="seed", contact="ellipse:0.7")


def test_a_pickled_fit_on_a_spot_writes_its_report(ellipse_csv, tmp_path):
    r = frictionid.fit(ellipse_csv, model="exact", contact="ellipse:0.7", seed=2)
    copy = pickle.loads(pickle.dumps(r))
    assert copy.contact == "ellipse:0.7"
    copy.write_report(tmp_path / "again")
    again = json.loads((tmp_path / "again" / "report.json").read_text())
    assert again["contact"] == "ellipse:0.7"
    assert again["parameters"]["h_y"]["value"] == r.params["h_y"]


def test_progress_names_the_contact_stages_before_the_search(run_cli, tmp_path, footprint):
    # Before the search the rows' integrals on the map are computed once; the callback hears
    # that stage first ("contact integrals", rows done of all).
    data = tmp_path / "map.csv"
    run_cli("generate", "--model", "exact", "--contact", f"map:{footprint}", "--param",
            "f=0.8,h=0.05,h_y=0.03", "--rows", "3000", "--output", data)
    seen = []
    fit = frictionid.fit(data, model="exact", contact=f"map:{footprint}", threads=1,
                         global_evaluations=300, progress=lambda p: seen.append(dict(p)))
    assert fit.rows == 3000
    stages = [p["stage"] for p in seen]
    assert stages[0] == "contact integrals", stages
    assert seen[0]["total"] == 3000 and 0 < seen[0]["done"] < 3000
    # (The callback hears at most every 50 ms: the search may come and go in between.)
    assert set(stages) <= {"contact table", "contact integrals", "global search", "local fit"}
