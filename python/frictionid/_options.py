"""Python option values as the command line's option text, so that the C++ side parses and
checks them with the command line's own code (and messages). Floats are written with repr(),
which reads back as the same double."""

from __future__ import annotations

from typing import Iterable, Mapping, Optional, Sequence, Tuple, Union

Number = Union[float, int, str]


def number(value: Number) -> str:
    if isinstance(value, str):
        return value
    text = repr(float(value))
    # "2.0" -> "2": messages then quote what a user would have typed on the command line.
    return text[:-2] if text.endswith(".0") else text


def assignments(values: Optional[Mapping[str, Number]]) -> str:
    """{"kappa": 1.0} -> "kappa=1.0" (--fix, --param)."""
    return ",".join(f"{name}={number(v)}" for name, v in (values or {}).items())


def bounds(values: Optional[Mapping[str, Tuple[Number, Number]]]) -> str:
    """{"f": (0.1, 2)} -> "f=0.1:2.0" (--bounds)."""
    out = []
    for name, pair in (values or {}).items():
        try:
            lower, upper = pair
        except (TypeError, ValueError):
            raise ValueError(
                f"bounds: {name} needs a (lower, upper) pair, not {pair!r}") from None
        out.append(f"{name}={number(lower)}:{number(upper)}")
    return ",".join(out)


def names(values: Optional[Union[str, Iterable[str]]]) -> str:
    """["T_x", "M_z"] -> "T_x,M_z" (--channels)."""
    if values is None:
        return ""
    if isinstance(values, str):
        return values
    return ",".join(values)


def loss(value: Union[str, Sequence]) -> str:
    """"huber:3" or ("huber", 3) -> "huber:3.0" (--loss)."""
    if isinstance(value, str):
        return value
    name, scale = value
    return f"{name}:{number(scale)}"
