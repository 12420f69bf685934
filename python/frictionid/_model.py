"""The model without a fit: evaluate, coefficients, generate and simulate, as the command
line's eval, coefficients, generate and simulate."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Dict, Mapping, Optional, Sequence

import numpy as np

from . import _data, _frictionid, _options

if TYPE_CHECKING:
    import pandas

ArrayLike = Any


def evaluate(
    model: str,
    pressure: Optional[str],
    params: Optional[Mapping[str, float]],
    v_x: ArrayLike,
    v_y: ArrayLike,
    omega: ArrayLike,
    N: ArrayLike,
    R: ArrayLike,
    *,
    contact: str = "circle",
    threads: int = 0,
    cancel: Any = None,
    progress: Optional[Callable[[Dict[str, Any]], None]] = None,
) -> Dict[str, np.ndarray]:
    """The resultants ``model`` predicts, vectorised (numpy broadcasting over the inputs).

    Args:
        model: ``"seed"``, ``"corrected"`` or ``"exact"``.
        pressure: ``uniform``, ``hertz``, ``parabolic``, ``power:N`` or ``table:FILE``;
            None: ``hertz``, and the only choice with a pressure map.
        params: parameter name -> value, e.g. ``{"f": 0.9, "kappa": 1.2, "h": 0.1}``; the
            coefficients a, b, m, b_tilde, p0 not given follow from the pressure law (as
            ``frictionid eval --param``); ``result.params`` of a fit works too.
        v_x, v_y, omega: slip velocity [m/s] and spin [rad/s], finite.
        N, R: normal load [N] and contact radius [m], finite and > 0.
        contact: the contact spot, as for :func:`fit` (``--contact``).
        threads: threads for the rows (0: every core; 1 in a Dask task on a one-thread worker);
            the values do not depend on it.
        cancel: as for :func:`fit`: once set, the rows stop and :class:`FitCancelled` is raised
            (Ctrl-C in the main thread raises ``KeyboardInterrupt``).
        progress: as for :func:`fit`, with the stages ``"contact table"`` (a spot's table: its
            points and budget) and ``"model rows"`` (rows done of all).

    Returns:
        ``{"T_x", "T_y", "M_z", "M_roll", "N"}`` -> float64 arrays of the broadcast shape, and
        ``"M_tilt"`` on a spot other than the circle or with ``h_y``.

    Raises:
        InputError: (a ``ValueError``) unknown model, law or parameter, or bad values.

    The GIL is released during the evaluation.
    """
    arrays = np.broadcast_arrays(*(np.asarray(x, dtype=np.float64) for x in
                                   (v_x, v_y, omega, N, R)))
    shape = arrays[0].shape
    flat = [np.ascontiguousarray(a.reshape(-1)) for a in arrays]
    out = _frictionid.evaluate(model, "hertz" if pressure is None else pressure,
                               _options.values("--param", params), *flat, contact=contact,
                               pressure_given=pressure is not None, threads=threads,
                               cancel=cancel, progress=progress)
    return {k: v.reshape(shape) for k, v in out.items()}


def coefficients(pressure: Optional[str] = None, kappa: float = 1.0,
                 alpha: float = 0.0, *, contact: str = "circle") -> Dict[str, Any]:
    """The moments m0..m3 of a pressure law and the approximant coefficients they imply
    (docs/physics.md §3), as ``frictionid coefficients`` prints them.

    Args:
        pressure: ``uniform``, ``hertz`` (None: the default), ``parabolic``, ``power:N`` or
            ``table:FILE``.
        kappa: anisotropy, > 0.
        alpha: slip direction [rad] for m(alpha).
        contact: the contact spot, as for :func:`fit`: on a spot other than the circle, its
            own slope-matched a, b, m, b_tilde, p0 for slip along x.

    Returns:
        A dict with pressure, kappa, alpha, m0..m3, a, b, m, b_tilde, p0, mu_M,
        M_roll_per_hNR and consistency (which of the bounds hold); on another spot pressure,
        contact, kappa, alpha, a, b, m, b_tilde, p0, mu_M and M_roll_per_hNR.
    """
    return _frictionid.coefficients("hertz" if pressure is None else pressure, float(kappa),
                                    float(alpha), contact=contact,
                                    pressure_given=pressure is not None)


def generate(
    model: str = "exact",
    pressure: Optional[str] = None,
    params: Optional[Mapping[str, float]] = None,
    *,
    contact: str = "circle",
    rows: int = 600,
    noise: float = 0.0,
    noise_abs: float = 0.0,
    sigma_columns: bool = False,
    seed: int = 1,
    eps_min: float = 1e-2,
    eps_max: float = 1e2,
    loads: Sequence[float] = (2000.0, 4000.0, 6000.0),
    R: float = 0.05,
    spin: float = 2.0,
    slip_angles_deg: Sequence[float] = (0.0,),
    forward_only: bool = False,
    threads: int = 0,
    cancel: Any = None,
    progress: Optional[Callable[[Dict[str, Any]], None]] = None,
) -> "pandas.DataFrame":
    """A synthetic dataset from ``model``, as ``frictionid generate`` writes it (same design,
    same seeded noise, same numbers).

    Args:
        model, pressure, params, contact: the model, as for :func:`evaluate`.
        rows: rows of the design (slip/spin sweeps, eps log-spaced over eps_min..eps_max).
        noise: relative Gaussian noise (standard deviation as a fraction of each value).
        noise_abs: absolute Gaussian noise in the channel's units.
        sigma_columns: add ``sigma_*`` columns with the noise's standard deviations.
        seed: seed of the noise.
        loads: normal loads [N], cycled; R: contact radius [m]; spin: |omega| [rad/s].
        slip_angles_deg: slip directions [degrees], cycled.
        forward_only: no backward-slipping rows (else every 4th row has v_x < 0).
        threads: threads for the model's rows (0: every core, as for :func:`evaluate`); the data
            do not depend on it.
        cancel, progress: as for :func:`evaluate`.

    Returns:
        A pandas DataFrame with the canonical columns (``M_tilt`` too on a spot other than the
        circle or with ``h_y``); ``df.attrs["truth"]`` holds the parameters it was made with.
    """
    out = _frictionid.generate(model, "hertz" if pressure is None else pressure,
                               _options.values("--param", params),
                               _options.whole_number("--rows", rows, 1, 10**7), noise,
                               noise_abs, sigma_columns,
                               _options.whole_number("--seed", seed, 0, 2**64 - 1), eps_min,
                               eps_max,
                               [float(x) for x in loads], R, spin,
                               [float(x) for x in slip_angles_deg], forward_only,
                               contact=contact, pressure_given=pressure is not None,
                               threads=threads, cancel=cancel, progress=progress)
    df = _data.frame(out["columns"])
    df.attrs["truth"] = dict(out["truth"]["parameters"])
    df.attrs["pressure"] = out["truth"]["pressure"]
    df.attrs["contact"] = out["truth"].get("contact", "circle")
    return df


def simulate(
    model: str = "exact",
    pressure: Optional[str] = None,
    params: Optional[Mapping[str, float]] = None,
    *,
    contact: str = "circle",
    inertia_ratio: float,
    v0: float = 1.0,
    omega0: float = 1.0,
    slip_angle_deg: float = 0.0,
    mass: float = 1.0,
    R: float = 1.0,
    N: Optional[float] = None,
    tol: float = 1e-10,
    stop_fraction: float = 1e-12,
    max_steps: int = 200000,
    trajectory: bool = True,
) -> Dict[str, Any]:
    """A flat body sliding and spinning to rest on a plane under the model's friction
    (docs/physics.md §4), as ``frictionid simulate``.

    Args:
        model, pressure, params, contact: the friction model, as for :func:`evaluate`;
            pressure None is ``uniform`` here, as for ``frictionid simulate``.
        inertia_ratio: I/(M_b R^2): 0.5 a uniform disk, 1 a thin ring.
        v0, omega0, slip_angle_deg: initial speed [m/s], spin [rad/s], slip direction [deg].
        mass: M_b [kg]; R: radius [m]; N: normal load [N] (default M_b * 9.81).
        tol: tolerance of the Dormand-Prince integration; stop_fraction: stop when the speeds
            fell to this fraction; max_steps: step limit.
        trajectory: also return every accepted step.

    Returns:
        A dict with eps_final, t_stop_slide, t_stop_spin, slip_angle_final_deg, distance,
        rotation, energy_initial, stopped, steps, rejected_steps, evaluations, N and (with
        trajectory) "trajectory", a pandas DataFrame of t, v_x, v_y, omega, eps, T_x, T_y,
        M_z, energy.
    """
    out = dict(_frictionid.simulate(model, "uniform" if pressure is None else pressure,
                                    _options.values("--param", params), inertia_ratio, v0,
                                    omega0, slip_angle_deg, mass, R, N, tol, stop_fraction,
                                    max_steps, trajectory, contact=contact,
                                    pressure_given=pressure is not None))
    if trajectory:
        out["trajectory"] = _data.frame(out["trajectory"])
    return out
