"""frictionid: identification of the coupled dry-friction model of a wheel that rolls, slides
and spins (Kireenkov & Zhavoronok's anisotropic Coulomb law over a circular contact spot).

The same C++ code as the ``frictionid`` command line, so the same numbers and messages:

>>> import frictionid
>>> result = frictionid.fit("data/example_hertz.csv", model="exact", pressure="hertz")
>>> print(result.summary())

Functions: :func:`fit` (-> :class:`FitResult`), :func:`evaluate`, :func:`coefficients`,
:func:`generate`, :func:`simulate`, :func:`shimmy`. Bad input raises :class:`InputError` (a
``ValueError``), a fit that fails raises :class:`FitError`, Ctrl-C during a fit raises
``KeyboardInterrupt``, a fit stopped by its :class:`CancelToken` raises :class:`FitCancelled`.
"""

import atexit
import threading

from ._frictionid import CancelToken, FitCancelled, FitError, InputError, cancel_all_fits
from ._fit import fit
from ._model import coefficients, evaluate, generate, simulate
from ._result import FitResult
from ._shimmy import shimmy
from ._version import __version__

InputError.__module__ = FitError.__module__ = FitCancelled.__module__ = __name__
CancelToken.__module__ = __name__
FitCancelled.__doc__ = (
    "A fit stopped by its cancel token, or by the interpreter's exit (a FitError).")

# The interpreter's exit cancels running fits: threading's exit hooks run before it waits for
# non-daemon threads, so a fit in a worker thread does not hold the exit up (atexit would run
# only after that wait).
_register_exit = getattr(threading, "_register_atexit", None)
if _register_exit is not None:
    _register_exit(cancel_all_fits)
atexit.register(cancel_all_fits)
InputError.__doc__ = (
    "Rejected input (data, file, option or value): a ValueError whose message is the command "
    "line's, naming what and where.")
FitError.__doc__ = (
    "A fit that could not produce a result: the model not finite at every start, or the "
    "solver failing (the command line's exit code 3).")

__all__ = [
    "CancelToken",
    "FitCancelled",
    "FitError",
    "FitResult",
    "InputError",
    "coefficients",
    "evaluate",
    "fit",
    "generate",
    "shimmy",
    "simulate",
    "__version__",
]
