"""FitResult: what frictionid.fit returns, a view of the C++ FitResult and its report.json."""

from __future__ import annotations

import html
import os
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Tuple

import numpy as np

from . import _data, _frictionid

if TYPE_CHECKING:
    import pandas


def _fmt(x: Optional[float], digits: int = 8) -> str:
    return "None" if x is None else f"{x:.{digits}g}"


_REQUEST_FIELDS = (
    "model", "pressure", "pressure_given", "contact", "fix", "free", "bounds", "start", "loss",
    "channels", "intervals",
    "bootstrap", "noise_model", "starts", "seed", "global_evaluations", "global_subsample",
    "no_global", "global_algorithm", "threads",
)


class FitResult:
    """The result of :func:`frictionid.fit`.

    Attributes:
        report: the dict that ``report.json`` holds (the same keys and numbers; docs/design.md).
        params: parameter name -> fitted value (fixed parameters included).
        stderr: name -> standard error, or None (fixed, or not determined by the data).
        ci95: name -> (lower, upper) 95 % confidence interval, or None.
        correlation: pandas DataFrame among the parameters that have a standard error.
        covariance: the same parameters' covariance, stderr_i * stderr_j * correlation_ij.
        statistics: report["statistics"]: cost, chi2, reduced_chi2, aic, bic, dof, rmse, r2...
        warnings: list of warning sentences (parameters not determined, at bounds, ...).
        model, pressure: as passed to fit; rows: rows fitted.
        contact: the contact spot as reports name it (``"circle"``, ``"ellipse:0.7"``, ...).
        index: the row labels of the fitted DataFrame (a RangeIndex for a file or a dict).
        eps: pandas Series, per row, v/(|omega| R) (inf where omega = 0).
        fitted: pandas DataFrame of the fitted channels' predictions, one row per data row.
        residuals: measured - fitted per fitted channel (NaN where a row does not measure it).
        sigma: the sigma the fit divided each residual by (sigma column, estimated noise model
            or the channel's scale).
        whitened_residuals: residuals / sigma, the residuals the fit minimised (before a
            robust loss).
        data: pandas DataFrame of the rows fitted (canonical columns).

    Every per-row table has the fitted frame's index, so ``df["fit"] = r.fitted["T_x"]`` lines
    up row by row. A FitResult pickles (multiprocessing, joblib, Dask): the copy holds the
    report and the per-row arrays; only :meth:`write_report` needs the C++ result, which an
    unpickled copy recomputes once by fitting the same rows with the same options again.
    """

    def __init__(self, output: "Optional[_frictionid.FitOutput]", model: str,
                 pressure: Optional[str],
                 index: Any = None, request: "Optional[_frictionid.FitRequest]" = None
                 ) -> None:
        self._output = output
        self._pressure_spec = pressure
        self._index = index
        self._request: Dict[str, Any] = (
            {} if request is None else {f: getattr(request, f) for f in _REQUEST_FIELDS})
        self._arrays: Optional[Dict[str, Any]] = None
        if output is not None:
            self._init_from_report(output.report(), output.time_s)

    def _init_from_report(self, report: Dict[str, Any], time_s: float) -> None:
        self.report: Dict[str, Any] = report
        self.model: str = self.report["model"]
        self.pressure: str = self.report["pressure"]
        self.contact: str = self.report.get("contact", "circle")
        self.rows: int = self.report["rows"]
        self.channels: List[str] = list(self.report["channels"])
        p = self.report["parameters"]
        self.params: Dict[str, float] = {n: e["value"] for n, e in p.items()}
        self.stderr: Dict[str, Optional[float]] = {n: e["stderr"] for n, e in p.items()}
        self.ci95: Dict[str, Optional[Tuple[float, float]]] = {
            n: None if e["ci95"] is None else (e["ci95"][0], e["ci95"][1]) for n, e in p.items()}
        self.statistics: Dict[str, Any] = self.report["statistics"]
        self.warnings: List[str] = list(self.report["warnings"])
        self.time_s: float = time_s

    # -- pickling ---------------------------------------------------------------------------
    def __getstate__(self) -> Dict[str, Any]:
        """The report and the per-row arrays; not the C++ result (it has no Python form)."""
        return {"report": self.report, "time_s": self.time_s,
                "pressure_spec": self._pressure_spec, "index": self._index,
                "request": self._request, "arrays": self._row_arrays()}

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self._output = None
        self._pressure_spec = state["pressure_spec"]
        self._index = state["index"]
        self._request = state["request"]
        self._arrays = state["arrays"]
        self._init_from_report(state["report"], state["time_s"])

    def _row_arrays(self) -> Dict[str, Any]:
        if self._arrays is None:
            out = self._output
            assert out is not None
            self._arrays = {"eps": out.eps, "fitted": dict(out.fitted), "sigma": dict(out.sigma),
                            "data": dict(out.data.columns()), "source": out.data.source,
                            "lines": out.data.lines}
        return self._arrays

    def _cpp_output(self) -> "_frictionid.FitOutput":
        """The C++ result; after unpickling, the same fit run again (same rows, options and
        seed: the same result, docs/design.md §5)."""
        if self._output is None:
            request = _frictionid.FitRequest()
            for name, value in self._request.items():
                setattr(request, name, value)
            arrays = self._row_arrays()
            # The file and its lines too: warnings name the line of a CSV row.
            data = _frictionid.restore_dataset(arrays["data"], arrays["source"],
                                               list(arrays["lines"]))
            self._output = _frictionid.fit(data, request)
        return self._output

    # -- matrices ---------------------------------------------------------------------------
    @property
    def correlation(self) -> "pandas.DataFrame":
        import pandas as pd

        c = self.report["correlation"]
        m = np.array(c["matrix"], dtype=float).reshape(len(c["names"]), len(c["names"]))
        return pd.DataFrame(m, index=c["names"], columns=c["names"])

    @property
    def covariance(self) -> "pandas.DataFrame":
        corr = self.correlation
        se = np.array([self.stderr[n] for n in corr.index], dtype=float)
        return corr * np.outer(se, se)

    # -- rows -------------------------------------------------------------------------------
    @property
    def index(self) -> "pandas.Index":
        import pandas as pd

        return pd.RangeIndex(self.rows) if self._index is None else self._index

    @property
    def eps(self) -> "pandas.Series":
        import pandas as pd

        return pd.Series(self._row_arrays()["eps"], index=self.index, name="eps")

    @property
    def fitted(self) -> "pandas.DataFrame":
        return _data.frame(self._row_arrays()["fitted"], self.index)

    @property
    def sigma(self) -> "pandas.DataFrame":
        return _data.frame(self._row_arrays()["sigma"], self.index)

    @property
    def residuals(self) -> "pandas.DataFrame":
        data = self._row_arrays()["data"]
        fitted = self._row_arrays()["fitted"]
        return _data.frame({c: data[c] - fitted[c] for c in fitted}, self.index)

    @property
    def whitened_residuals(self) -> "pandas.DataFrame":
        return self.residuals / self.sigma

    @property
    def data(self) -> "pandas.DataFrame":
        return _data.frame(self._row_arrays()["data"], self.index)

    def predict(self, data: Any = None) -> "pandas.DataFrame":
        """The fitted model's T_x, T_y, M_z, M_roll (M_tilt on a spot other than the circle
        or with h_y) and N for every row of ``data`` (a DataFrame or dict with v_x, v_y
        (optional), omega, N, R; default the fitted rows), as a pandas DataFrame on ``data``'s
        index (the fitted rows' index by default)."""
        from ._model import evaluate

        if data is None:
            data, index = self._row_arrays()["data"], self.index
        else:
            index = data.index if hasattr(data, "iloc") else None
        v_y = data["v_y"] if "v_y" in data.keys() else 0.0
        # The spot with the fitted aspect q, which the spot names instead of a parameter.
        params = dict(self.params)
        contact = self.contact
        if "q" in params:
            q = params.pop("q")
            contact = f"{contact.split(':', 1)[0]}:{q!r}"
        out = evaluate(self.model, self._pressure_spec, params, data["v_x"], v_y,
                       data["omega"], data["N"], data["R"], contact=contact)
        return _data.frame(out, index)

    # -- files and text ---------------------------------------------------------------------
    def write_report(self, dir: "str | os.PathLike[str]") -> List[str]:
        """Writes report.json, report.md and the plots to ``dir``, as ``frictionid fit --report
        dir`` does; returns the paths written."""
        return self._cpp_output().write_report(os.fspath(dir))

    def summary(self) -> str:
        """A plain-text report in the style of lmfit's ``fit_report``."""
        st = self.statistics
        free = [e for e in self.report["parameters"].values() if not e["fixed"]]
        lines = [
            "[[Fit Statistics]]",
            f"    model              = {self.model}",
            f"    pressure           = {self.pressure}",
            *([f"    contact            = {self.contact}"] if self.contact != "circle" else []),
            f"    # data rows        = {self.rows}",
            f"    channels           = {', '.join(self.channels)}",
            f"    # residuals        = {st['residuals']}",
            f"    # free parameters  = {len(free)}",
            f"    degrees of freedom = {st['dof']}",
            f"    chi-square         = {_fmt(st['chi2'])}",
            f"    reduced chi-square = {_fmt(st['reduced_chi2'])}",
            f"    Akaike info crit   = {_fmt(st['aic'])}",
            f"    Bayesian info crit = {_fmt(st['bic'])}",
            f"    loss               = {st['loss']}",
            "[[Variables]]",
        ]
        width = max(len(n) for n in self.params) + 1
        for n, e in self.report["parameters"].items():
            name = f"{n}:".ljust(width)
            if e["fixed"]:
                lines.append(f"    {name} {_fmt(e['value'])} (fixed)")
                continue
            se = e["stderr"]
            if se is None:
                text = f"{_fmt(e['value'])} +/- None (not determined)"
            else:
                rel = f" ({100 * se / abs(e['value']):.2f}%)" if e["value"] else ""
                text = f"{_fmt(e['value'])} +/- {_fmt(se, 3)}{rel}"
            bound = " (at bound)" if e["at_bound"] else ""
            lines.append(f"    {name} {text} (init = {_fmt(e['initial'])}){bound}")
        corr = self.correlation
        pairs = [(abs(corr.iat[i, j]), corr.index[i], corr.index[j], corr.iat[i, j])
                 for i in range(len(corr)) for j in range(i + 1, len(corr))]
        pairs = sorted((p for p in pairs if p[0] >= 0.1), reverse=True)
        if pairs:
            lines.append("[[Correlations]] (unreported correlations are < 0.100)")
            for _, a, b, c in pairs:
                lines.append(f"    C({a}, {b}) = {c:+.4f}")
        if self.warnings:
            lines.append("[[Warnings]]")
            lines.extend(f"    {w}" for w in self.warnings)
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()

    def __repr__(self) -> str:
        parts = []
        for name, value in self.params.items():
            se = self.stderr[name]
            parts.append(f"{name}={value:.6g}" + ("" if se is None else f"±{se:.2g}"))
        return (f"<FitResult model={self.model!r} pressure={self.pressure!r} rows={self.rows} "
                f"{' '.join(parts)} reduced_chi2={self.statistics['reduced_chi2']:.4g}>")

    def _repr_html_(self) -> str:
        """Jupyter: the statistics, the parameters and the warnings as tables."""
        e = html.escape
        st = self.statistics
        stats = [("model", self.model), ("pressure", self.pressure), ("rows", self.rows),
                 ("channels", ", ".join(self.channels)), ("χ²", _fmt(st["chi2"])),
                 ("reduced χ²", _fmt(st["reduced_chi2"])), ("AIC", _fmt(st["aic"])),
                 ("BIC", _fmt(st["bic"])), ("loss", st["loss"])]
        out = ["<div><h4>frictionid fit</h4><table><tbody>"]
        out += [f"<tr><th style='text-align:left'>{e(str(k))}</th><td>{e(str(v))}</td></tr>"
                for k, v in stats]
        out.append("</tbody></table><table><thead><tr><th>name</th><th>value</th>"
                   "<th>std. error</th><th>95 % interval</th><th>initial</th><th>bounds</th>"
                   "<th>note</th></tr></thead><tbody>")
        for n, p in self.report["parameters"].items():
            ci = p["ci95"]
            ci_text = "" if ci is None else f"[{ci[0]:.6g}, {ci[1]:.6g}]"
            lo = "-∞" if p["lower"] is None else f"{p['lower']:.4g}"
            hi = "∞" if p["upper"] is None else f"{p['upper']:.4g}"
            note = "fixed" if p["fixed"] else "at bound" if p["at_bound"] else (
                "not determined" if p["stderr"] is None else "")
            out.append(
                f"<tr><td>{e(n)}</td><td>{p['value']:.8g}</td>"
                f"<td>{'' if p['stderr'] is None else format(p['stderr'], '.3g')}</td>"
                f"<td>{ci_text}</td><td>{p['initial']:.6g}</td><td>[{lo}, {hi}]</td>"
                f"<td>{note}</td></tr>")
        out.append("</tbody></table>")
        if self.warnings:
            out.append("<ul>" + "".join(f"<li>{e(w)}</li>" for w in self.warnings) + "</ul>")
        out.append("</div>")
        return "".join(out)
