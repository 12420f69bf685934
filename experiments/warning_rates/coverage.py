#!/usr/bin/env python3
"""Coverage of the reported 95 % intervals on correctly specified data.

  coverage.py FRICTIONID N 'GENERATE ARGS' 'FIT ARGS' [KEY [JOBS]]

Generates N datasets (`frictionid generate GENERATE ARGS --seed k --truth ...`), fits each
(`frictionid fit FIT ARGS`) and prints, per free parameter, how often the interval KEY of
report.json (ci95, ci95_profile, ci95_sandwich, or ci95_auto: the profile interval where one was
computed, else ci95; default ci95) contains the truth (and, for another KEY, ci95 too), and how often
the parameter had none. With NOISE_FREE=T_x,M_z in the environment those channels are replaced
by their noise-free values (a second generate with --noise 0).

This is the check through the CLI and report.json, a few hundred fits at a time. The same
conditions (few rows, eps only above 1.5, noise-free channels, additive noise) are measured
in-process at 1000 replicates per cell, with noise that differs per channel, by the design cells
of experiments/identification_study (run.sh with CELLS=designs; its "stated" interval is
ci95_auto here).
"""
import collections
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile


def one(tool, gen, fit, key, k, tmp):
    csv, truth, rep = (os.path.join(tmp, f"{p}{k}") for p in ("d", "t", "r"))
    csv += ".csv"
    truth += ".json"
    subprocess.run([tool, "generate", *gen.split(), "--seed", str(k), "--output", csv,
                    "--truth", truth], check=True, capture_output=True)
    exact = [c for c in os.environ.get("NOISE_FREE", "").split(",") if c]
    if exact:
        clean = csv + ".exact.csv"
        args = gen.split()
        args[args.index("--noise") + 1] = "0"
        subprocess.run([tool, "generate", *args, "--seed", str(k), "--output", clean],
                       check=True, capture_output=True)
        with open(csv) as f:
            noisy = [line.rstrip("\n").split(",") for line in f]
        with open(clean) as f:
            free = [line.rstrip("\n").split(",") for line in f]
        cols = [noisy[0].index(c) for c in exact]
        for row, src in zip(noisy[1:], free[1:]):
            for c in cols:
                row[c] = src[c]
        with open(csv, "w") as f:
            f.write("".join(",".join(r) + "\n" for r in noisy))
    r = subprocess.run([tool, "fit", csv, *fit.split(), "--threads", "1", "--report", rep],
                       capture_output=True, text=True)
    if r.returncode != 0:
        return None
    with open(truth) as f:
        t = json.load(f)
    with open(os.path.join(rep, "report.json")) as f:
        j = json.load(f)
    params = t.get("parameters", t)
    out = {}
    for name, p in j["parameters"].items():
        if p.get("fixed"):
            continue
        ci = p.get("ci95_profile") or p.get("ci95") if key == "ci95_auto" else p.get(key)
        true = params.get(name)
        if true is None:
            continue
        out[name] = None if not ci or ci[0] is None else ci[0] <= true <= ci[1]
        if key != "ci95":
            sym = p.get("ci95")
            out[name + " (ci95)"] = None if not sym or sym[0] is None else sym[0] <= true <= sym[1]
    return out


def main():
    tool, n, gen, fit = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
    key = sys.argv[5] if len(sys.argv) > 5 else "ci95"
    jobs = int(sys.argv[6]) if len(sys.argv) > 6 else 2
    hit, none, total = collections.Counter(), collections.Counter(), collections.Counter()
    failed = 0
    with tempfile.TemporaryDirectory() as tmp, \
            concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for res in pool.map(lambda k: one(tool, gen, fit, key, k, tmp), range(1, n + 1)):
            if res is None:
                failed += 1
                continue
            for name, inside in res.items():
                total[name] += 1
                if inside is None:
                    none[name] += 1
                elif inside:
                    hit[name] += 1
    print(f"{n} fits ({failed} failed), interval {key}")
    for name in total:
        with_ci = total[name] - none[name]
        cov = 100.0 * hit[name] / with_ci if with_ci else float("nan")
        print(f"  {name:8s} coverage {cov:5.1f} %  ({hit[name]}/{with_ci}), no interval {none[name]}")


if __name__ == "__main__":
    main()
