"""Turning the data a user passes (a path, a pandas DataFrame, a dict of arrays) into the C++
library's Dataset."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any, Dict, List, Mapping, NamedTuple, Optional, Union

import numpy as np

from . import _frictionid

if TYPE_CHECKING:
    import pandas

# The canonical dataset columns (docs/design.md "Dataset CSV").
COLUMNS = (
    "v_x", "v_y", "omega", "N", "R", "T_x", "T_y", "M_z", "M_roll", "M_tilt",
    "sigma_T_x", "sigma_T_y", "sigma_M_z", "sigma_M_roll", "sigma_M_tilt",
)
CHANNELS = ("T_x", "T_y", "M_z", "M_roll", "M_tilt")

DataLike = Union[str, "os.PathLike[str]", Mapping[str, Any], Any]


class Loaded(NamedTuple):
    """A Dataset and the index of the frame it came from (None: rows by position)."""

    dataset: "_frictionid.Dataset"
    row_index: Optional["pandas.Index"]


def column_map(columns: Optional[Mapping[str, str]]) -> Dict[str, str]:
    """canonical -> header, checked as the command line's --columns (names, hints, messages)."""
    return _frictionid.column_map({str(k): str(v) for k, v in (columns or {}).items()})


def load(data: DataLike, columns: Optional[Mapping[str, str]] = None,
         threads: int = 0) -> "_frictionid.Dataset":
    """The Dataset of ``data``: a CSV path read by the C++ reader, or named columns in memory.

    ``columns`` renames as the command line's ``--columns`` does: canonical name -> the name in
    the file or frame. ``threads`` bounds the threads that read a large file in parts (0: every
    core).
    """
    return load_indexed(data, columns, threads).dataset


def load_indexed(data: DataLike, columns: Optional[Mapping[str, str]] = None,
                 threads: int = 0) -> Loaded:
    """:func:`load`, keeping a DataFrame's index so that results line up with its rows."""
    if isinstance(data, _frictionid.Dataset):
        return Loaded(data, None)
    if isinstance(data, (str, os.PathLike)):
        return Loaded(_frictionid.load_dataset_csv(os.fspath(data), column_map(columns), threads), None)
    if not hasattr(data, "keys"):
        raise TypeError(
            "data must be a CSV path, a pandas DataFrame or a dict of arrays, "
            f"not {type(data).__name__}")
    is_frame = hasattr(data, "iloc")
    source = "DataFrame" if is_frame else "dict"
    header_of = column_map(columns)
    arrays = canonical_arrays(data, header_of, source)
    index = getattr(data, "index") if is_frame else None
    try:
        return Loaded(_frictionid.dataset_from_columns(arrays, source), index)
    except _frictionid.InputError:
        if index is None or _is_positional(index):
            raise
    # Checking again, only to name the rejected row by its index label as df.loc takes it.
    return Loaded(_frictionid.dataset_from_columns(arrays, source, row_labels(index)), index)


def canonical_arrays(data: Any, header_of: Mapping[str, str], source: str
                     ) -> Dict[str, np.ndarray]:
    """The canonical columns of a frame or dict as contiguous float64 arrays, after refusing
    what is not a measurement and column names that look like misspelt canonical ones."""
    keys = list(data.keys())
    arrays = {}
    for name in COLUMNS:
        key = header_of.get(name, name)
        if key in keys:
            arrays[name] = numbers(data[key], str(key), source)
    check_unknown_columns(keys, header_of, set(arrays), source)
    return arrays


def numbers(values: Any, key: str, source: str) -> np.ndarray:
    """One column as float64, where pd.NA (and None) mean "not measured" (NaN). Complex values,
    dates and durations are refused rather than converted (their real part, their
    nanoseconds)."""
    dtype = getattr(values, "dtype", None)
    if dtype is None:
        values = np.asarray(values)
        dtype = values.dtype
    kind = getattr(dtype, "kind", "O")
    if kind == "c":
        raise _frictionid.InputError(
            f"{source}: column {key} holds complex numbers; expected real numbers (pass "
            f".real explicitly if the imaginary part is meant to be dropped)")
    if kind in "mM":
        raise _frictionid.InputError(
            f"{source}: column {key} holds {'dates' if kind == 'M' else 'durations'} "
            f"({dtype}); expected numbers in SI units")
    try:
        if hasattr(values, "to_numpy"):  # pandas: nullable dtypes hold pd.NA
            out = values.to_numpy(dtype=np.float64, na_value=np.nan)
        else:
            if kind == "O":
                values = _without_na(values)
            out = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise _frictionid.InputError(
            f"{source}: column {key} is not numeric ({e}); expected numbers") from None
    if out.ndim != 1:
        raise _frictionid.InputError(
            f"{source}: column {key} has shape {out.shape}; expected one dimension")
    return np.ascontiguousarray(out)


def _without_na(values: np.ndarray) -> np.ndarray:
    try:
        import pandas as pd
    except ImportError:
        return values
    flat = np.asarray(values, dtype=object)
    return np.array([np.nan if v is pd.NA else v for v in flat.ravel()],
                    dtype=object).reshape(flat.shape)


def check_unknown_columns(keys: List[Any], header_of: Mapping[str, str], found: set,
                          source: str) -> None:
    """A column that is not canonical but one edit away from a canonical column the data lacks
    (``vy``, ``Tx``, ``m_z``) is an error: silently ignoring it would fit without that data. The
    test is the CSV reader's "did you mean" (text::misspelling_distance)."""
    used = {header_of.get(name, name) for name in found}
    for key in keys:
        text = str(key)
        if text in used or text in COLUMNS:
            continue
        best = None
        for name in COLUMNS:
            if name in found:
                continue
            header = header_of.get(name, name)
            d = _frictionid.misspelling_distance(text, header)
            if d is not None and (best is None or d < best[0]):
                best = (d, name, header)
        if best is None:
            continue
        _, name, header = best
        hint = f"did you mean '{header}'?" if header == name else (
            f"it is close to '{header}', given by columns= for {name}: check the spelling")
        raise _frictionid.InputError(
            f"{source}: column {text!r} is not a column frictionid reads; {hint} (rename the "
            f"column, or map it with columns={{{name!r}: {text!r}}})")


def _is_positional(index: Any) -> bool:
    """A RangeIndex 0, 1, ..., n-1: labels are positions, messages name them already."""
    import pandas as pd

    return (isinstance(index, pd.RangeIndex) and index.start == 0 and index.step == 1)


def row_labels(index: Any) -> List[str]:
    """Index labels as messages quote them: strings quoted, others as printed."""
    return [repr(label) if isinstance(label, str) else str(label) for label in index]


def frame(columns: Mapping[str, np.ndarray], index: Any = None) -> "pandas.DataFrame":
    """A pandas DataFrame of columns (pandas is imported only when needed), on ``index``."""
    import pandas as pd

    return pd.DataFrame(dict(columns), index=index)
