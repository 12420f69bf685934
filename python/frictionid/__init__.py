"""frictionid: identification of the coupled dry-friction model of a wheel that rolls, slides
and spins (Kireenkov & Zhavoronok's anisotropic Coulomb law over a circular contact spot).

The same C++ code as the ``frictionid`` command line, so the same numbers and messages:

>>> import frictionid
>>> result = frictionid.fit("data/example_hertz.csv", model="exact", pressure="hertz")
>>> print(result.summary())

Functions: :func:`fit` (-> :class:`FitResult`), :func:`evaluate`, :func:`coefficients`,
:func:`generate`, :func:`simulate`. Bad input raises :class:`InputError` (a ``ValueError``), a
fit that fails raises :class:`FitError`, Ctrl-C during a fit raises ``KeyboardInterrupt``.
"""

from ._frictionid import FitError, InputError
from ._fit import fit
from ._model import coefficients, evaluate, generate, simulate
from ._result import FitResult

InputError.__module__ = FitError.__module__ = __name__
InputError.__doc__ = (
    "Rejected input (data, file, option or value): a ValueError whose message is the command "
    "line's, naming what and where.")
FitError.__doc__ = (
    "A fit that could not produce a result: the model not finite at every start, or the "
    "solver failing (the command line's exit code 3).")

__version__ = "0.1.0"

__all__ = [
    "FitError",
    "FitResult",
    "InputError",
    "coefficients",
    "evaluate",
    "fit",
    "generate",
    "simulate",
]
