#!/usr/bin/python3
"""Fits the bundled example with the Python package, prints the summary and plots the data
against the fitted model (one panel per channel, over eps = v/(|omega| R)) into a PNG.

    /usr/bin/python3 examples/python/fit_example.py [--data CSV] [--output DIR]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: runs without a display (CI)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

import frictionid  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=REPOSITORY / "data" / "example_hertz.csv",
                        type=pathlib.Path, help="dataset CSV (default: the bundled example)")
    parser.add_argument("--output", default=pathlib.Path("python_example"), type=pathlib.Path,
                        help="directory for fit_example.png (default: python_example/)")
    args = parser.parse_args()

    # round_trip: the exact doubles of the file, so the fit equals `frictionid fit` on it.
    data = pd.read_csv(args.data, float_precision="round_trip")
    result = frictionid.fit(data, model="exact", pressure="hertz")
    print(result.summary())

    eps = result.eps
    order = np.argsort(eps)
    fitted = result.fitted
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for ax, channel in zip(axes.flat, result.channels):
        ax.plot(eps, data[channel], ".", ms=3, alpha=0.5, label="measured")
        # Rows differ in load and spin sign: plot the model at every row, not as one curve.
        ax.plot(eps[order], fitted[channel].to_numpy()[order], "x", ms=2, color="C3",
                label="fitted model")
        ax.set_xscale("log")
        ax.set_title(channel)
        ax.set_xlabel("eps = v / (|omega| R)")
    axes.flat[0].legend()
    fig.suptitle(f"{result.model} model, {result.pressure} pressure: "
                 + ", ".join(f"{k} = {v:.5g}" for k, v in result.params.items()))
    fig.tight_layout()
    args.output.mkdir(parents=True, exist_ok=True)
    png = args.output / "fit_example.png"
    fig.savefig(png, dpi=100)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
