"""Turning the data a user passes (a path, a pandas DataFrame, a dict of arrays) into the C++
library's Dataset."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any, Dict, Mapping, Optional, Union

import numpy as np

from . import _frictionid

if TYPE_CHECKING:
    import pandas

# The canonical dataset columns (docs/design.md "Dataset CSV").
COLUMNS = (
    "v_x", "v_y", "omega", "N", "R", "T_x", "T_y", "M_z", "M_roll",
    "sigma_T_x", "sigma_T_y", "sigma_M_z", "sigma_M_roll",
)
CHANNELS = ("T_x", "T_y", "M_z", "M_roll")

DataLike = Union[str, "os.PathLike[str]", Mapping[str, Any], Any]


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
    if isinstance(data, _frictionid.Dataset):
        return data
    if isinstance(data, (str, os.PathLike)):
        return _frictionid.load_dataset_csv(os.fspath(data), column_map(columns), threads)
    if not hasattr(data, "keys"):
        raise TypeError(
            "data must be a CSV path, a pandas DataFrame or a dict of arrays, "
            f"not {type(data).__name__}")
    source = "DataFrame" if hasattr(data, "iloc") else "dict"
    header_of = column_map(columns)
    arrays = {}
    for name in COLUMNS:
        key = header_of.get(name, name)
        if key not in data.keys():
            continue
        try:
            values = np.asarray(data[key], dtype=np.float64)
        except (TypeError, ValueError) as e:
            raise _frictionid.InputError(
                f"{source}: column {key} is not numeric ({e}); expected numbers") from None
        if values.ndim != 1:
            raise _frictionid.InputError(
                f"{source}: column {key} has shape {values.shape}; expected one dimension")
        arrays[name] = np.ascontiguousarray(values)
    return _frictionid.dataset_from_columns(arrays, source)


def frame(columns: Mapping[str, np.ndarray]) -> "pandas.DataFrame":
    """A pandas DataFrame of columns (pandas is imported only when needed)."""
    import pandas as pd

    return pd.DataFrame(dict(columns))
