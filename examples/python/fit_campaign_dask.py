#!/usr/bin/python3
"""Fits a small generated campaign on a local Dask cluster and plots the friction coefficient f
against the normal load.

The campaign is one CSV per load, made with the same kappa and h but an f that falls with load
(as a tire's does). frictionid.dask.fit_many fits every file on a LocalCluster of worker
processes and returns the same summary table as `frictionid batch`.

    /usr/bin/python3 examples/python/fit_campaign_dask.py [--output DIR] [--workers N]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: runs without a display (CI)
import matplotlib.pyplot as plt  # noqa: E402

import frictionid  # noqa: E402
from frictionid.dask import fit_many  # noqa: E402

LOADS = (1000.0, 2000.0, 3000.0, 4000.0, 5000.0)
KAPPA, H = 1.2, 0.1


def true_f(load: float) -> float:
    return 0.9 - 4e-5 * load  # 0.86 at 1 kN down to 0.70 at 5 kN


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default=pathlib.Path("campaign_example"), type=pathlib.Path,
                        help="directory for the campaign's CSVs and f_vs_load.png")
    parser.add_argument("--workers", default=2, type=int, help="worker processes")
    args = parser.parse_args()

    data_dir = args.output / "campaign"
    data_dir.mkdir(parents=True, exist_ok=True)
    for k, load in enumerate(LOADS):
        frame = frictionid.generate("exact", "hertz", {"f": true_f(load), "kappa": KAPPA, "h": H},
                                    rows=300, noise=0.01, seed=k + 1, loads=[load])
        # %.17g: the doubles read back exactly, as `frictionid generate` writes them.
        frame.to_csv(data_dir / f"load_{load:.0f}.csv", index=False, float_format="%.17g")

    # No client: fit_many starts a LocalCluster of worker processes and closes it afterwards.
    table = fit_many(str(data_dir), model="exact", pressure="hertz", n_workers=args.workers,
                     global_evaluations=1000)
    print(table[["label", "status", "mean_N", "f", "f_stderr", "kappa", "h"]].to_string(
        index=False))

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.errorbar(table["mean_N"], table["f"],
                yerr=[table["f"] - table["f_ci95_lo"], table["f_ci95_hi"] - table["f"]],
                fmt="o", capsize=3, label="fitted f (95 % interval)")
    ax.plot(LOADS, [true_f(load) for load in LOADS], "--", color="C3", label="true f")
    ax.set_xlabel("normal load N [N]")
    ax.set_ylabel("friction coefficient f")
    ax.set_title(f"exact model, hertz pressure; fitted kappa {table['kappa'].mean():.4g}, "
                 f"h {table['h'].mean():.3g}")
    ax.legend()
    fig.tight_layout()
    png = args.output / "f_vs_load.png"
    fig.savefig(png, dpi=100)
    print(f"wrote {png}")


if __name__ == "__main__":  # worker processes import this file: fit only in the parent
    main()
