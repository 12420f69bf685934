#!/usr/bin/env bash
# How far are the closed-form approximants (seed, corrected; docs/physics.md §3) from the exact
# ring-reduced model (§2)? Relative error of T_x, T_y, M_z over eps = 1e-4 ... 1e4 for uniform,
# Hertz and parabolic pressure and kappa in {0.5, 1, 2}, (i) with a, b, m (b_tilde, p0) from the
# pressure law and (ii) with them fitted by `frictionid fit` to noise-free exact data (f, kappa,
# h fixed at the truth), once with the tool's default weighting and once with 1 % relative
# sigmas. See the "Approximation error" section of experiments/README.md.
#
#   experiments/approximation_error/run.sh     # binary: $FRICTIONID, else build/frictionid
#
# Writes results.csv, results.md and error_<law>_<coefficients>.svg here; scratch to out/.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../common.sh"

LAWS=(uniform hertz parabolic)
KAPPAS=(0.5 1 2)
H=0.1              # tilt: T_y = h kappa f N p(eps) is linear in h, so its relative error is not
ROWS=400           # rows of the noise-free fit data, eps log-spaced over the same range

out="$here/out"
rm -rf "$out"
mkdir -p "$out/eval" "$out/data" "$out/fits"
cp "$bin" "$out/frictionid"   # a private copy: a rebuild of build/ cannot interfere
bin="$out/frictionid"
binary_id="$("$bin" --version), sha256 $(sha256sum "$bin" | cut -c1-12)"

# Evaluation grid: 20 points per decade, slip along +x, omega = 1, N = 1, R = 1.
"$py" -c "
import numpy as np
print('v_x,omega,N,R')
for e in np.logspace(-4, 4, 161): print(f'{e!r},1,1,1')" > "$out/grid.csv"

param_json() {  # report.json -> a=..,b=..,... for the fitted coefficients of one model
  "$py" - "$1" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["parameters"]
print(",".join(f"{k}={v['value']!r}" for k, v in p.items() if k not in ("f", "kappa", "h")))
PY
}

start=$(date +%s.%N)
for law in "${LAWS[@]}"; do
  for kappa in "${KAPPAS[@]}"; do
    base="f=1,kappa=$kappa,h=$H"
    tag="${law}_k$kappa"
    "$bin" eval --model exact --pressure "$law" --param "$base" --input "$out/grid.csv" \
      --output "$out/eval/exact_$tag.csv" 2>/dev/null
    for model in seed corrected; do
      "$bin" eval --model "$model" --pressure "$law" --param "$base" --input "$out/grid.csv" \
        --output "$out/eval/${model}_law_$tag.csv" 2>/dev/null
    done
    # Noise-free exact data, and a copy with 1 % relative sigma columns.
    "$bin" generate --model exact --pressure "$law" --param "$base" --rows "$ROWS" \
      --eps-min 1e-4 --eps-max 1e4 --seed 1 --output "$out/data/$tag.csv" > /dev/null 2>&1
    "$py" - "$out/data/$tag.csv" "$out/data/${tag}_rel.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ch = [c for c in ("T_x", "T_y", "M_z", "M_roll") if c in rows[0]]
with open(sys.argv[2], "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(rows[0]) + ["sigma_" + c for c in ch])
    w.writeheader()
    for r in rows:
        for c in ch:
            r["sigma_" + c] = repr(max(0.01 * abs(float(r[c])), 1e-300))
        w.writerow(r)
PY
    for model in seed corrected; do
      for weight in fit fitrel; do
        data="$out/data/$tag.csv"
        [[ $weight = fitrel ]] && data="$out/data/${tag}_rel.csv"
        dir="$out/fits/${model}_${weight}_$tag"
        "$bin" fit "$data" --model "$model" --pressure "$law" --fix "$base" --seed 1 \
          --report "$dir" > "$dir.log" 2>&1 || { echo "fit failed: $dir" >&2; exit 1; }
        "$bin" eval --model "$model" --pressure "$law" \
          --param "$base,$(param_json "$dir/report.json")" --input "$out/grid.csv" \
          --output "$out/eval/${model}_${weight}_$tag.csv" 2>/dev/null
      done
    done
  done
done
end=$(date +%s.%N)

"$py" - "$out" "$here" "$binary_id" "$(echo "$end - $start" | bc)" "$H" "$ROWS" <<'PY'
import csv, json, os, sys
import numpy as np
out, here, binary_id, wall, H, ROWS = sys.argv[1:7]
laws, kappas = ("uniform", "hertz", "parabolic"), ("0.5", "1", "2")
sources = (("law", "from the pressure law"), ("fit", "fitted, default weighting"),
           ("fitrel", "fitted, 1 % relative σ"))
channels = ("T_x", "T_y", "M_z")
load = lambda p: np.genfromtxt(p, delimiter=",", names=True)
rows = []
for law in laws:
    for k in kappas:
        tag = f"{law}_k{k}"
        ex = load(os.path.join(out, "eval", f"exact_{tag}.csv"))
        eps = ex["v_x"]
        for model in ("seed", "corrected"):
            for src, _ in sources:
                ap = load(os.path.join(out, "eval", f"{model}_{src}_{tag}.csv"))
                err = {c: (ap[c] - ex[c]) / np.abs(ex[c]) for c in channels}
                np.savetxt(os.path.join(out, "eval", f"err_{model}_{src}_{tag}.dat"),
                           np.column_stack([eps] + [err[c] for c in channels]),
                           header="eps rel_T_x rel_T_y rel_M_z")
                coeffs = {}
                if src == "law":
                    c = json.loads(os.popen(f"{out}/frictionid coefficients --pressure {law} --kappa {k}").read())
                    coeffs = {"a": c["a"], "b": c["b"], "m": c["m"]} if model == "seed" else \
                             {"a": c["a"], "b_tilde": c["b_tilde"], "m": c["m"], "p0": c["p0"]}
                else:
                    p = json.load(open(os.path.join(out, "fits", f"{model}_{src}_{tag}", "report.json")))["parameters"]
                    coeffs = {n: v["value"] for n, v in p.items() if n not in ("f", "kappa", "h")}
                row = dict(law=law, kappa=k, model=model, coefficients=src,
                           values=" ".join(f"{n}={v:.4g}" for n, v in coeffs.items()))
                for c in channels:
                    i = int(np.argmax(np.abs(err[c])))
                    row[f"worst_{c}"] = float(err[c][i])
                    row[f"eps_{c}"] = float(eps[i])
                rows.append(row)
with open(os.path.join(here, "results.csv"), "w", newline="") as fh:
    w = csv.DictWriter(fh, fieldnames=list(rows[0]))
    w.writeheader(); w.writerows(rows)

pct = lambda x: f"{100 * x:+.1f} %" if abs(x) >= 1e-3 else f"{100 * x:+.1e} %"
L = [f"Relative error (approximant − exact)/exact on 161 points ε = 1e-4 … 1e4 (slip along +x, "
     f"h = {H}); worst value and the ε where it occurs. Fits: `frictionid fit --fix f=1,kappa=κ,h={H}` "
     f"on {ROWS} noise-free exact rows over the same ε range. {binary_id}; whole run {float(wall):.0f} s.", "",
     "| law | κ | model | coefficients | values | worst T_x (at ε) | worst T_y (at ε) | worst M_z (at ε) |",
     "|---|---:|---|---|---|---:|---:|---:|"]
for r in rows:
    L.append(f"| {r['law']} | {r['kappa']} | {r['model']} | {r['coefficients']} | {r['values']} | " +
             " | ".join(f"{pct(r['worst_' + c])} ({r['eps_' + c]:.3g})" for c in channels) + " |")
open(os.path.join(here, "results.md"), "w").write("\n".join(L) + "\n")
print("\n".join(L))

# Plots: one SVG per law and coefficient source, |relative error| of the three channels.
for law in laws:
    for src, title in sources:
        gp = os.path.join(out, f"plot_{law}_{src}.gp")
        with open(gp, "w") as g:
            g.write('set terminal svg size 1500,480 dynamic enhanced font "Helvetica,12"\n')
            g.write(f'set output "{os.path.join(here, f"error_{law}_{src}.svg")}"\n')
            g.write(f'set multiplot layout 1,3 title "{law} pressure, coefficients {title}: '
                    f'|approximant − exact| / exact"\n')
            g.write('set logscale xy\nset xrange [1e-4:1e4]\nset yrange [1e-8:10]\nset grid\n')
            g.write('set format x "10^{%L}"\nset format y "10^{%L}"\nset xlabel "ε = v/(|ω|R)"\n')
            g.write('set key bottom left font ",10"\n')
            for col, c in ((2, "T_x"), (3, "T_y"), (4, "M_z")):
                g.write(f'set title "{c.replace("_", "_{") + "}"}"\n')
                parts = []
                for model, dt in (("seed", 1), ("corrected", 2)):
                    for lc, k in ((1, "0.5"), (2, "1"), (4, "2")):
                        f = os.path.join(out, "eval", f"err_{model}_{src}_{law}_k{k}.dat")
                        parts.append(f'"{f}" using 1:(abs(${col})) with lines lc {lc} dt {dt} lw 2 '
                                     f'title "{model}, κ = {k}"')
                g.write("plot " + ", \\\n     ".join(parts) + "\n")
            g.write("unset multiplot\n")
        os.system(f"gnuplot {gp}")
PY
echo "run.sh: wrote $here/results.md, results.csv, error_*.svg" >&2
