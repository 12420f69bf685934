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
        eps: per row, v/(|omega| R) (inf where omega = 0).
        fitted: pandas DataFrame of the fitted channels' predictions, one row per data row.
        data: pandas DataFrame of the rows fitted (canonical columns).
    """

    def __init__(self, output: "_frictionid.FitOutput", model: str, pressure: str) -> None:
        self._output = output
        self._pressure_spec = pressure
        self.report: Dict[str, Any] = output.report()
        self.model: str = self.report["model"]
        self.pressure: str = self.report["pressure"]
        self.rows: int = self.report["rows"]
        self.channels: List[str] = list(self.report["channels"])
        p = self.report["parameters"]
        self.params: Dict[str, float] = {n: e["value"] for n, e in p.items()}
        self.stderr: Dict[str, Optional[float]] = {n: e["stderr"] for n, e in p.items()}
        self.ci95: Dict[str, Optional[Tuple[float, float]]] = {
            n: None if e["ci95"] is None else tuple(e["ci95"]) for n, e in p.items()}
        self.statistics: Dict[str, Any] = self.report["statistics"]
        self.warnings: List[str] = list(self.report["warnings"])
        self.time_s: float = output.time_s

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
    def eps(self) -> np.ndarray:
        return self._output.eps

    @property
    def fitted(self) -> "pandas.DataFrame":
        return _data.frame(self._output.fitted)

    @property
    def data(self) -> "pandas.DataFrame":
        return _data.frame(self._output.data.columns())

    def predict(self, data: Any = None) -> "pandas.DataFrame":
        """The fitted model's T_x, T_y, M_z, M_roll and N for every row of ``data`` (a
        DataFrame or dict with v_x, v_y (optional), omega, N, R; default the fitted rows), as a
        pandas DataFrame."""
        from ._model import evaluate

        if data is None:
            data = self._output.data.columns()
        v_y = data["v_y"] if "v_y" in data.keys() else 0.0
        out = evaluate(self.model, self._pressure_spec, self.params, data["v_x"], v_y,
                       data["omega"], data["N"], data["R"])
        return _data.frame(out)

    # -- files and text ---------------------------------------------------------------------
    def write_report(self, dir: "str | os.PathLike[str]") -> List[str]:
        """Writes report.json, report.md and the plots to ``dir``, as ``frictionid fit --report
        dir`` does; returns the paths written."""
        return self._output.write_report(os.fspath(dir))

    def summary(self) -> str:
        """A plain-text report in the style of lmfit's ``fit_report``."""
        st = self.statistics
        free = [e for e in self.report["parameters"].values() if not e["fixed"]]
        lines = [
            "[[Fit Statistics]]",
            f"    model              = {self.model}",
            f"    pressure           = {self.pressure}",
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
