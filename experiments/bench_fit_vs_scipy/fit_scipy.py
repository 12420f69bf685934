#!/usr/bin/python3
"""The seed approximant fitted with scipy.optimize.least_squares: the reference for run.sh.

Re-implements, in vectorised numpy, exactly what frictionid does for `fit --model seed`:

  * the seed model for any slip direction, as include/frictionid/model/approximants.hpp writes it (same
    small/large-eps branches, same tilt stand-ins, shape constants from the pressure law's
    moments as in approximant_shape() and law_moments());
  * a fixed whitening: residual = (model - measured)/scale per channel, scale = RMS of that
    channel's measured values (the data must have no sigma_* columns). frictionid estimates its
    noise model by default; run.sh gives it the same scales as sigma columns (`with-sigma`) and
    `--noise-model columns`, so that both solve the same least-squares problem;
  * the parameters f, kappa, h, a, b, m and frictionid's default bounds;
  * cost = 1/2 sum r^2 (what Ceres and least_squares both report).

Usage:
  fit_scipy.py fit DATA.csv --param f=..,kappa=..,h=..,a=..,b=..,m=.. [--tol X] [--json OUT]
      least_squares(method='trf', x_scale='jac', jac='2-point') from the given start; prints the
      wall time of the least_squares call only, the final cost, nfev and the parameters.
  fit_scipy.py with-sigma DATA.csv OUT.csv
      writes DATA with a sigma_<channel> column per channel: the scale `fit` whitens by.
  fit_scipy.py check DATA.csv PRED.csv --param ...
      compares this model's predictions for DATA's kinematics with the *_model columns that
      `frictionid eval --model seed --input DATA.csv --output PRED.csv --param ...` wrote;
      exits non-zero unless every prediction agrees to --rtol (default 1e-12) relative.

Run it with /usr/bin/python3 (numpy >= 1.24, scipy >= 1.10).
"""
import argparse
import json
import math
import sys
import time

import numpy as np
from scipy.optimize import least_squares

PARAMS = ("f", "kappa", "h", "a", "b", "m")
# frictionid's defaults (src/identify/fit_settings.cpp, default_parameter_settings).
LOWER = np.array([0.01, 0.05, -1.0, 1e-3, 4.0, 1.0])
UPPER = np.array([5.0, 20.0, 1.0, 4.0, 1e4, 1e4])
CHANNELS = ("T_x", "T_y", "M_z", "M_roll")
KINEMATICS = ("v_x", "v_y", "omega", "N", "R")


# --- pressure law: moments m_0..m_5 (include/frictionid/model/pressure_law.hpp, closed forms only) -----------
def law_moments(law):
    if law == "hertz":
        return [math.pi / 4, 1.0 / 3, math.pi / 16, 2.0 / 15, math.pi / 32, 8.0 / 105]
    if law == "uniform":
        return [1.0 / (k + 1) for k in range(6)]
    if law == "parabolic":
        return [2.0 / ((k + 1) * (k + 3)) for k in range(6)]
    raise SystemExit(f"fit_scipy.py: pressure law {law!r} not supported (hertz, uniform, parabolic)")


def approximant_shape(mo):
    """approximant_shape() of approximants.hpp."""
    rS = 4 * mo[2] / mo[5]
    rX = 4 * mo[3] / (3 * mo[2])
    rV = 4 * mo[3] / mo[2]
    rU = mo[2] / mo[5]
    return dict(mu_M=mo[2] / mo[1], rho_roll=mo[3] / (2 * mo[1]), p0_law=mo[2] / (2 * mo[1]),
                b_S=np.cbrt(rS * rS), c_X=rX * rX, c_V=rV * rV, c_U=np.cbrt(rU * rU),
                u_scale=mo[2] / (4 * mo[3]))


class Kinematics:
    """slip_geometry() of include/frictionid/model/kinematics.hpp for every row; parameter-independent, so it is
    computed once per dataset (frictionid recomputes it per row and evaluation)."""

    def __init__(self, v_x, v_y, omega, N, R):
        self.N, self.R = N, R
        v = np.hypot(v_x, v_y)
        pos = v > 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            self.ca = np.where(pos, v_x / np.where(pos, v, 1.0), 1.0)
            self.sa = np.where(pos, v_y / np.where(pos, v, 1.0), 0.0)
            u = np.abs(omega) * R
            self.eps = np.where(u > 0.0, v / np.where(u > 0.0, u, 1.0), np.inf)
        self.s = np.sign(omega)  # +1, -1 or 0 like spin_sign (omega is never NaN here)
        self.at_rest = (v == 0.0) & (omega == 0.0)
        self.small = self.eps <= 1.0
        self.e2 = self.eps * self.eps
        with np.errstate(divide="ignore"):
            self.inv2 = np.where(self.small, 0.0, 1.0 / self.e2)
        self.aligned = not np.any(self.sa != 0.0)  # every row on the principal axis
        self.nonzero_sa = self.sa != 0.0


def saturating(k, c):
    """eps/sqrt(eps^2 + c), finite for eps = 0 and eps = inf (approximants.hpp)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(k.small, k.eps / np.sqrt(k.e2 + c), 1.0 / np.sqrt(1.0 + c * k.inv2))


def seed_resultants(p, k, shape):
    """approximant_resultants(ApproximantForm::Seed, ...): returns T_x, T_y, M_z, M_roll."""
    f, kappa, h, a, b, m = p
    eps, e2, inv2, small, ca, sa, s = k.eps, k.e2, k.inv2, k.small, k.ca, k.sa, k.s
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        t = saturating(k, a)
        p_hat = np.where(small, eps / np.sqrt((1.0 + b * e2) * (e2 + a)),
                         1.0 / np.sqrt((inv2 + b) * (e2 + a)))
        if k.aligned:
            # sa == 0 everywhere: d11 = 1, d12 = 0, d22 = kappa; every tilt stand-in but p_hat
            # drops out (same arithmetic as the general branch below for these rows).
            d11 = ca * ca + kappa * (sa * sa)
            d22 = sa * sa + kappa * (ca * ca)
            d12 = (kappa - 1.0) * (sa * ca)
            s_hat = u_hat = x_hat = v_hat = 0.0
        else:
            d11 = ca * ca + kappa * (sa * sa)
            d22 = sa * sa + kappa * (ca * ca)
            d12 = (kappa - 1.0) * (sa * ca)
            nz = k.nonzero_sa
            sw = np.where(small, 1.0 / (1.0 + shape["b_S"] * e2), inv2 / (inv2 + shape["b_S"]))
            s_hat = np.where(nz, shape["p0_law"] * sw * np.sqrt(sw), 0.0)
            uw = np.where(small, 1.0 / (1.0 + shape["c_U"] * e2), 1.0 / (inv2 + shape["c_U"]))
            u_hat = np.where(nz, shape["u_scale"] * np.where(small, eps, inv2) * uw * np.sqrt(uw),
                             0.0)
            x_hat = np.where(nz, saturating(k, shape["c_X"]), 0.0)
            v_hat = np.where(nz, saturating(k, shape["c_V"]), 0.0)
        m_alpha = m * (kappa * kappa) / (d22 * d22)
        g_hat = np.where(small, 1.0 / np.sqrt(1.0 + m_alpha * e2),
                         np.sqrt(inv2) / np.sqrt(inv2 + m_alpha))

        F0 = f * k.N
        base = t + h * (s * sa) * s_hat
        tilt = h * (s * ca) * p_hat
        t_par = F0 * (d11 * base + d12 * tilt)
        t_perp = F0 * (d12 * base + d22 * tilt)
        T_x = t_par * ca - t_perp * sa
        T_y = t_par * sa + t_perp * ca
        M0 = (1.0 + kappa) * 0.5 * shape["mu_M"] * F0 * k.R
        M_z = M0 * s * g_hat
        if not k.aligned:
            M_z = M_z + np.where(
                k.nonzero_sa,
                F0 * k.R * h * shape["rho_roll"] *
                (ca * d12 * (x_hat - u_hat) - sa * (d22 * u_hat - d11 * v_hat)), 0.0)
    M_roll = h * k.N * k.R * shape["rho_roll"]
    rest = k.at_rest
    if np.any(rest):
        T_x, T_y, M_z = (np.where(rest, 0.0, x) for x in (T_x, T_y, M_z))
    return T_x, T_y, M_z, M_roll


# --- data ---------------------------------------------------------------------------------
def read_csv(path):
    with open(path) as fh:
        header = fh.readline().strip().split(",")
    cols = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    if cols.shape[1] != len(header):
        raise SystemExit(f"fit_scipy.py: {path}: {cols.shape[1]} values per row, {len(header)} headers")
    return {name: cols[:, j].copy() for j, name in enumerate(header)}


def kinematics_of(d):
    missing = [c for c in KINEMATICS if c not in d]
    if missing:
        raise SystemExit(f"fit_scipy.py: missing columns {missing}")
    return Kinematics(*(d[c] for c in KINEMATICS))


def parse_params(text):
    kv = dict(item.split("=", 1) for item in text.split(","))
    unknown = set(kv) - set(PARAMS)
    if unknown or len(kv) != len(PARAMS):
        raise SystemExit(f"fit_scipy.py: --param needs exactly {','.join(PARAMS)}")
    return np.array([float(kv[n]) for n in PARAMS])


# --- commands -----------------------------------------------------------------------------
def cmd_check(args):
    d = read_csv(args.data)
    pred = read_csv(args.pred)
    k = kinematics_of(d)
    p = parse_params(args.param)
    ours = seed_resultants(p, k, approximant_shape(law_moments(args.pressure)))
    worst = 0.0
    for name, x in zip(CHANNELS, ours):
        # eval names its predictions NAME_model when the input measures NAME, else NAME.
        ref = pred[name + "_model"] if name + "_model" in pred else pred[name]
        x = np.broadcast_to(x, ref.shape)
        diff = np.abs(x - ref)
        rel = np.where(ref != 0.0, diff / np.where(ref != 0.0, np.abs(ref), 1.0),
                       np.where(diff == 0.0, 0.0, np.inf))
        i = int(np.argmax(rel))
        print(f"{name:7s} max relative difference {rel[i]:.3e} (row {i + 1}: scipy {x[i]!r}, "
              f"frictionid {ref[i]!r}); exact matches {np.mean(diff == 0.0) * 100:.1f}%")
        worst = max(worst, rel[i])
    kind = "aligned only (v_y = 0)" if k.aligned else "general slip directions"
    ok = worst <= args.rtol
    print(f"{len(k.eps)} rows, {kind}: worst relative difference {worst:.3e} "
          f"{'<=' if ok else '>'} {args.rtol:g}: {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


def channel_scales(d):
    """(index, name, measured mask, scale) of every measured channel; scale = RMS of its values."""
    out = []
    for ci, c in enumerate(CHANNELS):
        if c not in d:
            continue
        y = d[c]
        ok = np.isfinite(y)
        if not ok.any():
            continue
        rms = math.sqrt(float(np.sum(y[ok] ** 2)) / int(ok.sum()))
        out.append((ci, c, ok, rms if rms > 0.0 else 1.0))
    return out


def cmd_with_sigma(args):
    scales = channel_scales(read_csv(args.data))
    extra = "".join(f",sigma_{c}" for _, c, _, _ in scales)
    values = "".join(f",{s!r}" for _, _, _, s in scales)
    with open(args.data) as src, open(args.out, "w") as dst:
        dst.write(src.readline().rstrip("\n") + extra + "\n")
        for line in src:
            if line.strip():
                dst.write(line.rstrip("\n") + values + "\n")
    return 0


def cmd_fit(args):
    d = read_csv(args.data)
    if any(c.startswith("sigma_") for c in d):
        raise SystemExit("fit_scipy.py: sigma_* columns are not supported (whitening by RMS only)")
    if args.aligned_only and np.any(d["v_y"] != 0.0):
        raise SystemExit("fit_scipy.py: --aligned-only needs v_y == 0 in every row")
    k = kinematics_of(d)
    shape = approximant_shape(law_moments(args.pressure))
    # Channels present in the file, canonical order; a missing cell (NaN) holds residual 0 as in
    # residuals.hpp. Scale = RMS of the measured values (fitter.cpp).
    chans, meas, inv_scale, present = [], [], [], []
    for ci, c, ok, scale in channel_scales(d):
        chans.append(ci)
        meas.append(np.where(ok, d[c], 0.0))
        inv_scale.append(1.0 / scale)
        present.append(ok)
    all_present = all(p.all() for p in present)
    n = len(k.eps)
    out = np.empty((n, len(chans)))  # row-major: the residual vector is row by row, like Ceres

    def residuals(p):
        pred = seed_resultants(p, k, shape)
        for j, ci in enumerate(chans):
            r = (pred[ci] - meas[j]) * inv_scale[j]
            out[:, j] = r if all_present else np.where(present[j], r, 0.0)
        return out.ravel().copy()  # least_squares keeps f0 while it probes x + h

    x0 = parse_params(args.param)
    if np.any(x0 <= LOWER) or np.any(x0 >= UPPER):
        raise SystemExit("fit_scipy.py: the start must lie strictly inside the bounds")
    tol = {} if args.tol is None else dict(ftol=args.tol, xtol=args.tol, gtol=args.tol)
    c0, t0 = time.process_time(), time.perf_counter()
    res = least_squares(residuals, x0, jac="2-point", bounds=(LOWER, UPPER), method="trf",
                        x_scale="jac", **tol)
    wall = time.perf_counter() - t0
    cpu = time.process_time() - c0
    cost = float(res.cost)
    print(f"model seed, pressure {args.pressure}, {n} rows, channels "
          f"{' '.join(CHANNELS[c] for c in chans)}, "
          f"{'aligned' if k.aligned else 'general'} slip")
    for name, v in zip(PARAMS, res.x):
        print(f"  {name:8s} {v:.10g}")
    print(f"cost {cost!r}")
    print(f"nfev {res.nfev}, njev {res.njev}, status {res.status}: {res.message}")
    print(f"time: least_squares {wall:.6f} s (CPU {cpu:.6f} s)")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(dict(rows=n, wall_s=wall, cpu_s=cpu, cost=cost, nfev=int(res.nfev),
                           njev=int(res.njev) if res.njev is not None else None,
                           status=int(res.status), message=res.message,
                           tol=args.tol, params=dict(zip(PARAMS, map(float, res.x)))), fh,
                      indent=1)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    f = sub.add_parser("fit", help="fit the seed model with least_squares")
    f.add_argument("data")
    f.add_argument("--param", required=True, help="start: f=..,kappa=..,h=..,a=..,b=..,m=..")
    f.add_argument("--pressure", default="hertz")
    f.add_argument("--tol", type=float, default=None,
                   help="ftol = xtol = gtol (default: least_squares' defaults, 1e-8)")
    f.add_argument("--aligned-only", action="store_true", help="assert v_y == 0 in every row")
    f.add_argument("--json", help="write the result here")
    c = sub.add_parser("check", help="compare predictions with frictionid eval's")
    c.add_argument("data")
    c.add_argument("pred")
    c.add_argument("--param", required=True)
    c.add_argument("--pressure", default="hertz")
    c.add_argument("--rtol", type=float, default=1e-12)
    w = sub.add_parser("with-sigma", help="the data with the fit's scales as sigma columns")
    w.add_argument("data")
    w.add_argument("out")
    args = ap.parse_args()
    return {"check": cmd_check, "fit": cmd_fit, "with-sigma": cmd_with_sigma}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
