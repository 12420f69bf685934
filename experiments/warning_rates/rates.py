#!/usr/bin/env python3
"""False-alarm rates of the fit warnings on correctly specified data.

Each replicate generates a dataset from a model (`frictionid generate ... --seed k`) and fits it
with the same model (`frictionid fit`); every warning it reports is a false alarm. Prints, per
warning kind (a key phrase of its text), how many fits raised it.

  rates.py FRICTIONID CASE N [JOBS]

CASE is one of the cases below (the generate and fit arguments).
"""
import collections
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

CASES = {
    # Exact model, 1 % relative noise, four slip directions.
    "exact": ("--model exact --param f=0.9,kappa=1.15,h=0.08 --slip-angles 0,30,60,-30 "
              "--rows 600 --noise 0.01", "--model exact"),
    # Exact model, 1 % relative noise stated in sigma columns (no noise model estimated).
    "exact_sigma": ("--model exact --param f=0.9,kappa=1.15,h=0.08 --slip-angles 0,30,60,-30 "
                    "--rows 600 --noise 0.01 --sigma-columns", "--model exact"),
    # Exact model, 20 rows: leverages up to ~0.9.
    "exact_small": ("--model exact --param f=0.9,kappa=1.15,h=0.08 --rows 20 --noise 0.01",
                    "--model exact"),
    # The seed model's own data: a, b, m at the Hertz law's values (exact law).
    "seed_law": ("--model seed --param f=0.9,kappa=1.15,h=0.08 --rows 600 --noise 0.01",
                 "--model seed"),
    # The seed model, eps only above 1.5: kappa, b and m nearly collinear.
    "seed_outer": ("--model seed --param f=0.9,kappa=1.15,h=0.08 --rows 600 --noise 0.01 "
                   "--eps-min 1.5 --eps-max 100", "--model seed"),
    # The seed model, few rows.
    "seed_small": ("--model seed --param f=0.9,kappa=1.15,h=0.08 --rows 20 --noise 0.01",
                   "--model seed"),
}

KINDS = [
    ("beyond 6 sigma", "beyond 6"),
    ("outlier", "looks like an outlier"),
    ("misfit (6 sigma)", "the model misses this channel"),
    ("R^2 low", "of the variation of"),
    ("runs test", "have structure against eps"),
    ("sandwich", "HC3 sandwich"),
    ("sandwich, earlier rule", "(earlier sandwich rule)"),
    ("differs from the law", "differs from the value"),
    ("poorly determined", "poorly determined"),
    ("strongly correlated", "strongly correlated"),
    ("noise-free channel", "rounding level"),
    ("residuals grow", "grow with the measured magnitude"),
    ("not determined", "not determined by the data"),
    ("not converged", "did not converge"),
]


def one(tool, case, k, tmp):
    gen, fit = CASES[case]
    csv = os.path.join(tmp, f"d{k}.csv")
    rep = os.path.join(tmp, f"r{k}")
    subprocess.run([tool, "generate", *gen.split(), "--seed", str(k), "--output", csv],
                   check=True, capture_output=True)
    r = subprocess.run([tool, "fit", csv, *fit.split(), "--threads", "1", "--report", rep],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return ["fit failed: " + r.stderr.strip()]
    with open(os.path.join(rep, "report.json")) as f:
        j = json.load(f)
    # The rule of earlier versions, for comparison: the standard errors 25 % apart.
    old = [p for p in j["parameters"].values()
           if p.get("stderr") and p.get("stderr_sandwich") and not p.get("at_bound")
           and abs(p["stderr_sandwich"] - p["stderr"]) > 0.25 * p["stderr"]]
    return j["warnings"] + (["(earlier sandwich rule)"] if old else [])


def main():
    tool, case, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    jobs = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    counts = collections.Counter()
    other = collections.Counter()
    with tempfile.TemporaryDirectory() as tmp, \
            concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for warnings in pool.map(lambda k: one(tool, case, k, tmp), range(1, n + 1)):
            seen = set()
            for w in warnings:
                if os.environ.get("SHOW") and os.environ["SHOW"] in w:
                    print("  |", w)
                kinds = [name for name, phrase in KINDS if phrase in w]
                seen.update(kinds)
                if not kinds:
                    other[w[:60]] += 1
            counts.update(seen)
    print(f"{case}: {n} fits")
    for name, _ in KINDS:
        print(f"  {name:22s} {counts[name]:4d}  ({100.0 * counts[name] / n:.1f} %)")
    for w, c in other.most_common():
        print(f"  other: {c:4d}  {w}")


if __name__ == "__main__":
    main()
