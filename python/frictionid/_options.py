"""Python option values as the typed fields of the C++ requests (src/app/requests.hpp): dicts of
numbers, (lower, upper) pairs, lists of names. The C++ side checks them with the command line's
own code, so the messages are the same."""

from __future__ import annotations

import math
import numbers
import operator
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

from . import _frictionid

Number = Union[float, int]


def _float(option: str, name: str, value: object) -> float:
    if isinstance(value, (bool, complex)) or not isinstance(value, numbers.Real):
        raise _frictionid.InputError(
            f"{option}: value for '{name}' is {value!r}; expected a real number")
    return float(value)


def values(option: str, given: Optional[Mapping[str, Number]]) -> Dict[str, float]:
    """{"kappa": 1} -> {"kappa": 1.0} (--fix, --param): real numbers only."""
    return {str(name): _float(option, name, v) for name, v in (given or {}).items()}


def bounds(given: Optional[Mapping[str, Tuple[Optional[Number], Optional[Number]]]],
           defaults: Optional[Callable[[], Mapping[str, Tuple[float, float]]]] = None
           ) -> Dict[str, Tuple[float, float]]:
    """{"f": (0.1, 2)} -> {"f": (0.1, 2.0)} (--bounds).

    One-sided bounds: None, -inf (lower) or +inf (upper) keeps the default bound of that side
    (the model's, as without bounds=; ``defaults()`` gives them). The fit itself needs finite
    bounds, so an open side means "as by default", never "unbounded"."""
    out = {}
    default: Optional[Mapping[str, Tuple[float, float]]] = None
    for name, pair in (given or {}).items():
        try:
            lower, upper = pair
        except (TypeError, ValueError):
            raise _frictionid.InputError(
                f"--bounds: {name} needs a (lower, upper) pair, not {pair!r}") from None
        sides = []
        for side, value, open_value in (("lower", lower, -math.inf), ("upper", upper, math.inf)):
            if value is not None:
                value = _float("--bounds", name, value)
            if value is None or (value == open_value and defaults is not None):
                if default is None:
                    default = defaults() if defaults is not None else {}
                if str(name) not in default:
                    raise _frictionid.InputError(
                        f"--bounds: {name} has no default {side} bound to keep (None or an "
                        f"infinite {side} bound keeps the default); expected a parameter of "
                        f"the model: {', '.join(default)}")
                value = default[str(name)][0 if side == "lower" else 1]
            sides.append(value)
        out[str(name)] = (sides[0], sides[1])
    return out


def names(given: Optional[Union[str, Iterable[str]]]) -> List[str]:
    """["T_x", "M_z"] or "T_x,M_z" -> ["T_x", "M_z"] (--channels, --group-by)."""
    if given is None:
        return []
    if isinstance(given, str):
        return [part.strip() for part in given.split(",")] if given.strip() else []
    return [str(n) for n in given]


def loss(value: Union[str, Sequence]) -> str:
    """"huber:3" or ("huber", 3) -> "huber:3.0" (--loss: a kind and its scale)."""
    if isinstance(value, str):
        return value
    name, scale = value[0], value[1]
    return f"{name}:{_float('--loss', str(name), scale)!r}"


def whole_number(option: str, value: Any, low: int, high: int) -> int:
    """An int in [low, high], with the command line's message otherwise (no wrap, no clamp)."""
    if isinstance(value, bool):
        value = str(value)
    try:
        number = operator.index(value)  # ints and numpy integers; not floats or strings
    except TypeError:
        raise _frictionid.InputError(
            f"{option}: got '{value}' (not a whole number); expected a whole number from "
            f"{low} to {high}") from None
    if number < low or number > high:
        why = "negative" if number < 0 else ("too small" if number < low else "too large")
        raise _frictionid.InputError(
            f"{option}: got '{number}' ({why}); expected a whole number from {low} to {high}")
    return number
