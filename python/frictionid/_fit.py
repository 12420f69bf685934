"""frictionid.fit: the command line's `fit`, from Python."""

from __future__ import annotations

from typing import Any, Callable, Dict, Iterable, Mapping, Optional, Sequence, Tuple, Union

from . import _data, _frictionid, _options
from ._result import FitResult

Bounds = Mapping[str, Tuple[Optional[float], Optional[float]]]
Progress = Callable[[Dict[str, Any]], Any]

MAX_SEED = 2**32 - 1  # as `frictionid fit --seed`: NLopt keeps 32 bits of a seed


def fit(
    data: _data.DataLike,
    model: str = "seed",
    pressure: Optional[str] = None,
    *,
    contact: str = "circle",
    fix: Optional[Mapping[str, float]] = None,
    free: Optional[Union[str, Iterable[str]]] = None,
    bounds: Optional[Bounds] = None,
    start: Optional[Mapping[str, float]] = None,
    loss: Union[str, Sequence] = "none",
    channels: Optional[Union[str, Iterable[str]]] = None,
    noise_model: str = "auto",
    intervals: str = "model",
    bootstrap: int = 0,
    seed: int = 1,
    threads: int = 0,
    starts: int = 4,
    global_search: bool = True,
    global_algorithm: str = "crs2",
    global_evaluations: int = 3000,
    global_subsample: int = 400,
    columns: Optional[Mapping[str, str]] = None,
    cancel: Optional[Any] = None,
    progress: Optional[Progress] = None,
) -> FitResult:
    """Identify the parameters of ``model`` from steady-state measurements.

    The same fit as ``frictionid fit``: the same options give the same settings (they are
    checked by the command line's code), and the same rows, options and seed give the same
    parameters, standard errors and report, bit for bit.

    Args:
        data: a CSV path (read by the command line's reader), a pandas DataFrame or a dict of
            1-D arrays with the canonical columns ``v_x``, ``v_y`` (optional), ``omega``, ``N``,
            ``R``, any of ``T_x``, ``T_y``, ``M_z``, ``M_roll`` (NaN: not measured in that row)
            and optional ``sigma_<channel>``. Other columns are ignored. For bit-identical
            results with a CSV read by pandas, read it with ``float_precision="round_trip"``.
        model: ``"seed"`` (f, kappa, h, a, b, m), ``"corrected"`` (f, kappa, h, a, b_tilde, m,
            p0) or ``"exact"`` (f, kappa, h, and n with ``power:N``; h_y on a spot other than
            the circle or with an ``M_tilt`` column; q with ``free=["q"]``).
        pressure: ``uniform``, ``hertz`` (the default), ``parabolic``, ``power:N`` or
            ``table:FILE``; not with a pressure map (``contact="map:FILE"``).
        contact: the contact spot (``--contact``): ``"circle"``, ``"ellipse:Q"`` or
            ``"rect:Q"`` (extent Q R across the rolling direction, 0 < Q <= 4) or
            ``"map:FILE"`` (a measured pressure map ``x,y,sigma0``); anything but the circle
            needs ``model="exact"``.
        fix: parameters held at a value, ``{"kappa": 1.0}`` (``--fix kappa=1``).
        free: parameters held by default that the fit should fit (``--free``): ``"h_y"``,
            ``"q"`` (the aspect of an ellipse or a rectangle).
        bounds: parameter bounds, ``{"f": (0.1, 2)}`` (``--bounds f=0.1:2``). One side None
            (or -inf as lower, +inf as upper) keeps the model's default bound on that side:
            ``{"f": (None, 2)}`` lowers only the upper bound. The fit's bounds are always
            finite.
        start: initial values, ``{"f": 0.9}`` (``--param f=0.9``).
        loss: ``"none"``, ``"huber:S"``, ``"cauchy:S"``, ``"soft_l1:S"`` or ``("huber", S)``.
        channels: the channels to fit, e.g. ``["T_x", "M_z"]``; default every measured one.
        noise_model: each channel's noise (``--noise-model``): ``"auto"`` (the ``sigma_*``
            columns where given, else the variance function with the smallest BIC, estimated
            from the residuals), ``"constant"``, ``"relative"``, ``"affine"``, ``"additive"``
            (that function for every channel) or ``"columns"`` (the sigma columns as given).
        intervals: the interval reports show first (``--intervals``): ``"model"``,
            ``"sandwich"`` or ``"profile"`` (``report["parameters"][p]["ci95_profile"]``).
        bootstrap: wild bootstrap refits (``--bootstrap``), 0 to 100000, seeded by ``seed``.
        seed: seed of the global stage, 0 to 2**32 - 1.
        threads: threads for the passes over the rows (0: every core); results do not depend
            on it.
        starts: local fits started from the global stage's best distinct points.
        global_search: False skips the global stage (``--no-global``).
        global_algorithm: ``--global-algorithm``.
        global_evaluations: objective budget of the global stage.
        global_subsample: rows the global stage sees.
        columns: renames, canonical name -> name in the data (``--columns``).
        cancel: a :class:`CancelToken` (or any object with ``is_set()``, such as a
            ``threading.Event``): once set, from any thread, the fit stops within about 50 ms
            of solver work and raises :class:`FitCancelled`.
        progress: called in the fitting thread, at most every 50 ms, with a dict ``stage``
            (``"global search"`` or ``"local fit"``; before them, on a non-circular spot,
            ``"contact table"`` with its points and budget and ``"contact integrals"`` with the
            rows done), ``done``, ``total``, ``start``, ``starts``, ``cost``; an exception it
            raises stops the fit and is raised by fit().

    Returns:
        A :class:`FitResult`.

    Raises:
        InputError: (a ``ValueError``) bad data or options, with the command line's message.
        FitError: the fit failed (no start gave a finite model, the solver failed).
        FitCancelled: (a FitError) the cancel token was set, or the interpreter is exiting.
        KeyboardInterrupt: Ctrl-C in the main thread; the fit stops within about 50 ms of
            solver work, and the next fit runs normally.

    The GIL is released while the fit runs: fits in several Python threads run in parallel.
    Results keep a DataFrame's index: ``r.fitted``, ``r.residuals``, ``r.data`` and ``r.eps``
    have the frame's row labels.
    """
    loaded = _data.load_indexed(data, columns, threads)
    o = options(model, pressure, contact=contact, fix=fix, free=free, bounds=bounds,
                start=start, loss=loss,
                channels=channels, noise_model=noise_model, intervals=intervals,
                bootstrap=bootstrap, seed=seed, threads=threads, starts=starts,
                global_search=global_search, global_algorithm=global_algorithm,
                global_evaluations=global_evaluations, global_subsample=global_subsample)
    output = _frictionid.fit(loaded.dataset, o, cancel, progress)
    return FitResult(output, model=model, pressure=pressure, index=loaded.row_index, request=o)


def options(
    model: str = "seed",
    pressure: Optional[str] = None,
    *,
    contact: str = "circle",
    fix: Optional[Mapping[str, float]] = None,
    free: Optional[Union[str, Iterable[str]]] = None,
    bounds: Optional[Bounds] = None,
    start: Optional[Mapping[str, float]] = None,
    loss: Union[str, Sequence] = "none",
    channels: Optional[Union[str, Iterable[str]]] = None,
    noise_model: str = "auto",
    intervals: str = "model",
    bootstrap: int = 0,
    seed: int = 1,
    threads: int = 0,
    starts: int = 4,
    global_search: bool = True,
    global_algorithm: str = "crs2",
    global_evaluations: int = 3000,
    global_subsample: int = 400,
    columns: Optional[Mapping[str, str]] = None,
) -> "_frictionid.FitRequest":
    """The fit request (src/app/requests.hpp) for :func:`fit`'s keyword arguments, checked by
    the command line's code when the fit runs (``request.check()`` checks it at once)."""
    o = _frictionid.FitRequest()
    o.model = model
    # None: the default law, not given (a pressure map takes no law).
    o.pressure = "hertz" if pressure is None else pressure
    o.pressure_given = pressure is not None
    o.contact = contact
    o.fix = _options.values("--fix", fix)
    o.free = _options.names(free)
    o.bounds = _options.bounds(bounds, o.default_bounds)
    o.start = _options.values("--param", start)
    o.loss = _options.loss(loss)
    o.channels = _options.names(channels)
    o.noise_model = noise_model
    o.intervals = intervals
    o.bootstrap = _options.whole_number("--bootstrap", bootstrap, 0, 100000)
    o.seed = _options.whole_number("--seed", seed, 0, MAX_SEED)
    o.threads = threads
    o.starts = starts
    o.no_global = not global_search
    o.global_algorithm = global_algorithm
    o.global_evaluations = global_evaluations
    o.global_subsample = _options.whole_number("--global-subsample", global_subsample, 1,
                                               10**9)
    o.columns = dict(columns or {})
    return o
