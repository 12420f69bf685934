#!/usr/bin/env python3
"""A full-factorial design (every load x slip angle, lateral slip included, x spin sign), fitted
and compared; report.html and compare.html opened in headless Chromium and their plots read
back from the DOM.

  factorial_in_browser.py --exe build/frictionid

The design: loads 1, 2 and 4 kN; slip angles 0, 45, 90 (lateral slip) and 135 degrees; both
spin signs; 64 values of eps from 0.03 to 30 (1536 rows, 192 or more per colour group, so that
a group's sample SD is within about +-0.05 of its true value). The exact model (Hertz) gives
the resistances (`frictionid eval --input`); this script adds Gaussian noise of sd
sqrt(a^2 + (0.02 y)^2) with a fixed seed, a per channel (an affine noise, which the default
noise model can find).

Checks:
  - report.html, every residual plot (residuals_<c>.svg): the whitened residuals, read back from
    the dots' pixel positions through the plot's own y tick labels, have a standard deviation
    within 0.8-1.25 in every colour group (a correct fit whitened by the sigma it used);
  - report.html, collapse_T_y.svg: one fitted line per slip direction and spin sign of the
    design, and along each line (sorted by eps) the collapsed T_y changes sign at most once
    (a line through both spin signs' rows would alternate);
  - compare.html (seed and exact): this data set makes the worse model (seed) reach a smaller
    own chi2 than exact (checked in compare.json, or the check below would be idle); the page
    names exact as preferred, the chi2 column it shows ranks exact first, and it does not claim
    one whitening for every model;
  - both pages show the input's SHA-256 (computed here) and the command line;
  - at a 390 px wide window neither page is wider than the window (wide tables and plots scroll
    inside their box): the page's script writes scrollWidth x innerWidth into body[data-widths];
    the page is shown in a 390 px iframe, since Chromium's headless window is at least 500 px;
  - at 390 px the text is readable: the body's font is 14 px or more, and every plot's smallest
    text is drawn at 9.9 px or more (the page's script writes the size into the figure's
    data-text-px: the SVG's font size times its drawn width over its viewBox width);
  - the plots of one kind (collapse, measured and fitted, ...), one per channel, stand side by
    side at 1400 px: the three channels' figures have the same top and increasing left edges
    (data-rendered-at, written by the page's script); at 390 px in one column: the same left
    edge and increasing tops;
  - report.html's parameter table sorts from its header: each header cell holds a <button>
    (focusable, so the keyboard reaches it), and a click on the value header's sets the cell's
    aria-sort to ascending, a second click to descending, and the rows follow.
Exit 0: passed; 1: failed; 77: skipped (no Chromium). Python standard library only.
"""

import argparse
import csv
import hashlib
import html.parser
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_in_browser import CHROMIUM_FLAGS, chromium, run  # noqa: E402

LOADS = (1000.0, 2000.0, 4000.0)
ANGLES = (0.0, 45.0, 90.0, 135.0)
SPINS = (1.0, -1.0)
EPS = [0.03 * 1000.0 ** (k / 63.0) for k in range(64)]
R, OMEGA = 0.05, 2.0
CHANNELS = ("T_x", "T_y", "M_z")


def write_design(path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["v_x", "v_y", "omega", "N", "R"])
        for n in LOADS:
            for a in ANGLES:
                for s in SPINS:
                    for e in EPS:
                        v = e * OMEGA * R
                        t = math.radians(a)
                        # cos(90 deg) is 6e-17, not 0: lateral slip has v_x = 0 exactly.
                        vx = 0.0 if a == 90.0 else v * math.cos(t)
                        w.writerow(["%.17g" % x for x in (vx, v * math.sin(t), s * OMEGA, n, R)])


def add_noise(model_csv, out_csv, seed=20261126):
    rng = random.Random(seed)
    with open(model_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    floor = {}
    for c in CHANNELS:
        ys = [abs(float(r[c])) for r in rows]
        floor[c] = 0.004 * sum(ys) / len(ys)
    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["v_x", "v_y", "omega", "N", "R"] + list(CHANNELS))
        for r in rows:
            out = [r[k] for k in ("v_x", "v_y", "omega", "N", "R")]
            for c in CHANNELS:
                y = float(r[c])
                sd = math.hypot(floor[c], 0.02 * y)
                out.append("%.17g" % (y + rng.gauss(0.0, sd)))
            w.writerow(out)


class Figures(html.parser.HTMLParser):
    """Per figure (data-file): its paths (attributes) and texts (attributes, text), the grid it
    stands in (data-kind of its div.plot-grid) and what the page's script measured; the page's
    data-widths, data-font-px, the body's data-result (set by a test's outer page) and all
    text."""

    def __init__(self):
        super().__init__()
        self.figures = {}
        self.widths = None
        self.font_px = None
        self.result = None
        self.text = ""
        self._file = None
        self._text = None
        self._divs = []  # per open div: the grid's kind, or None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body" and self.widths is None:
            self.widths = a.get("data-widths")
            self.font_px = a.get("data-font-px")
            self.result = a.get("data-result")
        if tag == "div":
            grid = "plot-grid" in (a.get("class") or "").split()
            self._divs.append(a.get("data-kind", "") if grid else None)
        if tag == "figure" and ("data-file" in a or "data-param" in a):
            self._file = a.get("data-file") or a["data-param"]
            kinds = [k for k in self._divs if k is not None]
            self.figures[self._file] = {
                "paths": [], "texts": [], "grid": kinds[-1] if kinds else None,
                "at": a.get("data-rendered-at"), "text_px": a.get("data-text-px")}
        elif self._file and tag == "path":
            self.figures[self._file]["paths"].append(a)
        elif self._file and tag == "text":
            self._text = [a, ""]

    def handle_data(self, data):
        self.text += data
        if self._text is not None:
            self._text[1] += data

    def handle_endtag(self, tag):
        if tag == "div" and self._divs:
            self._divs.pop()
        if tag == "text" and self._text is not None and self._file:
            self.figures[self._file]["texts"].append(tuple(self._text))
            self._text = None
        elif tag == "figure":
            self._file = None


def y_axis(figure):
    """value = a + b * pixel, from the y tick labels (right-aligned, 4 px below the tick)."""
    ticks = [(float(t[0]["y"]) - 4.0, float(t[1])) for t in figure["texts"]
             if t[0].get("text-anchor") == "end"]
    assert len(ticks) >= 2, "fewer than two y ticks"
    (p0, v0), (p1, v1) = ticks[0], ticks[-1]
    b = (v1 - v0) / (p1 - p0)
    return lambda px: v0 + b * (px - p0)


def points(d):
    return [(float(x), float(y)) for x, y in re.findall(r"[ML](-?[\d.]+) (-?[\d.]+)", d)]


def render(browser, tmp, page):
    common = CHROMIUM_FLAGS + ["--user-data-dir=" + os.path.join(tmp, "profile"),
                               "--window-size=1200,1800"]
    done = subprocess.run([browser] + common + ["--dump-dom", "file://" + page],
                          capture_output=True, text=True, timeout=180)
    parsed = Figures()
    parsed.feed(done.stdout)
    return parsed


def residual_failures(parsed, tag_prefix=""):
    failures = []
    for c in CHANNELS:
        fig = parsed.figures.get("residuals_%s.svg" % c)
        if fig is None:
            failures.append("report.html: no residuals_%s.svg" % c)
            continue
        value = y_axis(fig)
        groups = 0
        for path in fig["paths"]:
            tag = path.get("data-tag")
            if not tag or path.get("stroke-linecap") != "round":
                continue
            z = [value(y) for _, y in points(path["d"])]
            if len(z) < 30:
                continue
            groups += 1
            mean = sum(z) / len(z)
            sd = math.sqrt(sum((v - mean) ** 2 for v in z) / (len(z) - 1))
            print("residuals %s, %s: %d dots, SD %.3f" % (c, tag, len(z), sd))
            if not 0.8 <= sd <= 1.25:
                failures.append("residuals_%s.svg, group %s: SD %.3f of %d whitened residuals, "
                                "not within 0.8-1.25" % (c, tag, sd, len(z)))
        if groups < 3:
            failures.append("residuals_%s.svg: %d colour groups with 30 dots or more" % (c, groups))
    return failures


def collapse_failures(parsed):
    failures = []
    fig = parsed.figures.get("collapse_T_y.svg")
    if fig is None:
        return ["report.html: no collapse_T_y.svg"]
    value = y_axis(fig)
    curves = set()
    for path in fig["paths"]:
        tag = path.get("data-tag") or ""
        m = re.search(r"direction=(-?[\d.e+-]+) spin=(-?1)", tag)
        if not m or path.get("stroke-linecap") == "round":
            continue
        curves.add((round(float(m.group(1))), int(m.group(2))))
        ys = [value(y) for _, y in points(path["d"])]
        scale = max(abs(v) for v in ys)
        signs = [v > 0 for v in ys if abs(v) > 0.02 * scale]
        changes = sum(1 for a, b in zip(signs, signs[1:]) if a != b)
        if changes > 1:
            failures.append("collapse_T_y.svg, line %s: the collapsed T_y changes sign %d times "
                            "along eps" % (tag, changes))
    expected = {(int(a), int(s)) for a in ANGLES for s in SPINS}
    if curves != expected:
        failures.append("collapse_T_y.svg: lines for (direction, spin) %s, the design has %s"
                        % (sorted(curves), sorted(expected)))
    print("collapse_T_y.svg: %d curves (direction, spin sign)" % len(curves))
    return failures


def compare_failures(parsed, compare_json):
    failures = []
    by_model = {m["model"]: m for m in compare_json["models"]}
    seed, exact = by_model["seed"], by_model["exact"]
    print("own chi2: seed %.6g, exact %.6g; AIC seed %.6g, exact %.6g; one-noise chi2: seed "
          "%.6g, exact %.6g" % (seed["chi2"], exact["chi2"], seed["aic"], exact["aic"],
                                seed["chi2_one_noise"], exact["chi2_one_noise"]))
    if not seed["chi2"] < exact["chi2"]:
        failures.append("the data were meant to give the worse model (seed) the smaller own chi2 "
                        "(%g, exact %g): the check below would not test anything"
                        % (seed["chi2"], exact["chi2"]))
    text = " ".join(parsed.text.split())
    if "Preferred by AIC: exact; by BIC: exact" not in text:
        failures.append("compare.html does not name exact as preferred by AIC and BIC")
    if "same whitening" in text or "same rows, channels and whitening" in text:
        failures.append("compare.html claims the same whitening for every model")
    if not exact["chi2_one_noise"] < seed["chi2_one_noise"]:
        failures.append("the chi2 compare.html shows ranks seed (%g) before exact (%g)"
                        % (seed["chi2_one_noise"], exact["chi2_one_noise"]))
    return failures


def traceability_failures(name, parsed, sha256):
    failures = []
    if sha256 not in parsed.text:
        failures.append("%s does not show the input's SHA-256" % name)
    if "frictionid" not in parsed.text or "--report" not in parsed.text:
        failures.append("%s does not show the command line" % name)
    return failures


def in_frame(browser, tmp, page, width, script=""):
    """The page rendered in an iframe `width` px wide (Chromium's headless window is at least
    500 px wide), as an outer page's script copies it once loaded (file access between files
    allowed): the inner body's data attributes onto the outer body, and the inner body's DOM
    (with what the page's script measured) after the iframe. `script` then runs in the outer
    page with `d`, the inner document, and may set document.body.dataset.result."""
    outer = os.path.join(tmp, "frame%d.html" % width)
    with open(outer, "w") as f:
        f.write('<!DOCTYPE html><html><body><iframe id="f" src="file://%s" '
                'style="width:%dpx;height:1200px;border:0"></iframe><script>'
                'const f = document.getElementById("f");'
                'f.onload = () => { const d = f.contentDocument;'
                'Object.assign(document.body.dataset, d.body.dataset);'
                'document.body.insertAdjacentHTML("beforeend", d.body.innerHTML);'
                '%s };</script></body></html>' % (page, width, script))
    common = CHROMIUM_FLAGS + ["--user-data-dir=" + os.path.join(tmp, "profile"),
                               "--allow-file-access-from-files",
                               "--window-size=%d,1200" % max(800, width + 100)]
    done = subprocess.run([browser] + common + ["--dump-dom", "file://" + outer],
                          capture_output=True, text=True, timeout=180)
    parsed = Figures()
    parsed.feed(done.stdout)
    return parsed


def narrow_widths(browser, tmp, page):
    """The page in a 390 px wide iframe (in_frame)."""
    return in_frame(browser, tmp, page, 390)


def readable_failures(name, parsed):
    """At 390 px: a body font of 14 px or more, every plot's text drawn at 9.9 px or more."""
    failures = []
    font = float(parsed.font_px or 0)
    if font < 14:
        failures.append("%s at 390 px: the body's font is %s px" % (name, parsed.font_px))
    sizes = {f: fig["text_px"] for f, fig in parsed.figures.items()}
    small = {f: px for f, px in sizes.items() if px is None or float(px) < 9.9}
    print("%s at 390 px: body font %s px, plot text %s to %s px" % (
        name, parsed.font_px, min((float(p) for p in sizes.values() if p), default=None),
        max((float(p) for p in sizes.values() if p), default=None)))
    if not sizes:
        failures.append("%s at 390 px: no plots" % name)
    for f, px in sorted(small.items()):
        failures.append("%s at 390 px: the text of %s is drawn at %s px" % (name, f, px))
    return failures


def grids(parsed):
    """Per grid kind: its figures' (left, top) in page order."""
    out = {}
    for fig in parsed.figures.values():
        if fig["grid"] is None:
            continue
        left, _, top = (fig["at"] or "nan,nan").partition(",")
        out.setdefault(fig["grid"], []).append((float(left), float(top)))
    return out


def layout_failures(name, wide, narrow, per_row=3):
    """At 1400 px the first `per_row` figures of every grid that has as many are one row (equal
    tops, increasing left edges); at 390 px every grid is one column (equal left edges,
    increasing tops)."""
    failures = []
    rows = 0
    for kind, at in grids(wide).items():
        if len(at) < per_row:
            continue
        rows += 1
        row = at[:per_row]
        tops = [t for _, t in row]
        lefts = [l for l, _ in row]
        if max(tops) - min(tops) > 1 or any(b <= a for a, b in zip(lefts, lefts[1:])):
            failures.append("%s at 1400 px, %s: figures at %s, not one row" % (name, kind, row))
    if rows == 0:
        failures.append("%s at 1400 px: no grid of %d plots" % (name, per_row))
    for kind, at in grids(narrow).items():
        lefts = [l for l, _ in at]
        tops = [t for _, t in at]
        if max(lefts) - min(lefts) > 1 or any(b <= a for a, b in zip(tops, tops[1:])):
            failures.append("%s at 390 px, %s: figures at %s, not one column" % (name, kind, at))
    print("%s: %d grids of %d side by side at 1400 px, one column at 390 px"
          % (name, rows, per_row))
    return failures


# Presses a header's button twice (the header cell chosen by `cell`, a CSS selector in the inner
# document), and records the cells' aria-sort, the button's tag and focus, and the rows' order
# (by `row_key`, an attribute of the body rows) after each press.
CLICK_SCRIPT = """
const th = d.querySelector(%(cell)s), button = th && th.querySelector('button');
const table = th && th.closest('table');
const order = () => Array.from(table.tBodies[0].rows).map((tr) => tr.getAttribute(%(key)s));
const others = () => Array.from(table.tHead.rows[0].cells).filter((c) => c !== th)
    .map((c) => c.getAttribute('aria-sort'));
const r = {before: th && th.getAttribute('aria-sort'), tag: button ? button.tagName : null};
if (button) {
  button.focus();
  r.focused = d.activeElement === button;
  r.tabIndex = button.tabIndex;
  button.click();
  r.first = th.getAttribute('aria-sort');
  r.firstOrder = order();
  r.othersFirst = others();
  button.click();
  r.second = th.getAttribute('aria-sort');
  r.secondOrder = order();
}
document.body.dataset.result = JSON.stringify(r);
"""


def click_header(browser, tmp, page, cell, key):
    """Presses the header button of the cell `cell` twice (CLICK_SCRIPT) at 800 px; returns the
    record."""
    script = CLICK_SCRIPT % {"cell": json.dumps(cell), "key": json.dumps(key)}
    parsed = in_frame(browser, tmp, page, 800, script)
    return json.loads(parsed.result or "{}")


def click_failures(name, r, ascending, descending):
    """The record of click_header against the rows' expected orders after each press."""
    failures = []
    if r.get("tag") != "BUTTON":
        return ["%s: the header cell holds no button (%s)" % (name, r)]
    if not r.get("focused") or r.get("tabIndex", -1) < 0:
        failures.append("%s: the header's button cannot be focused from the keyboard" % name)
    if (r.get("before"), r.get("first"), r.get("second")) != ("none", "ascending", "descending"):
        failures.append("%s: aria-sort %s, then %s, then %s; expected none, ascending, "
                        "descending" % (name, r.get("before"), r.get("first"), r.get("second")))
    if any(o != "none" for o in r.get("othersFirst", [None])):
        failures.append("%s: the other headers' aria-sort: %s" % (name, r.get("othersFirst")))
    if r.get("firstOrder") != ascending or r.get("secondOrder") != descending:
        failures.append("%s: rows %s then %s; expected %s then %s"
                        % (name, r.get("firstOrder"), r.get("secondOrder"), ascending, descending))
    print("%s: a header click sorts %s, again %s" % (name, r.get("first"), r.get("second")))
    return failures


def width_failures(name, parsed):
    page, _, window = (parsed.widths or "0x0").partition("x")
    print("%s at a 390 px window: page %s px wide, window %s px" % (name, page, window))
    if not (int(window) == 390 and 0 < int(page) <= int(window)):
        return ["%s at a 390 px window: the page is %s px wide, the window %s" % (name, page,
                                                                                   window)]
    return []


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    args = ap.parse_args()
    browser = chromium()
    if browser is None:
        return 77
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        kin, model, data = (os.path.join(tmp, n) for n in ("kin.csv", "model.csv", "data.csv"))
        write_design(kin)
        if not run([args.exe, "eval", "--model", "exact", "--pressure", "hertz", "--param",
                    "f=0.9,kappa=1.15,h=0.08", "--input", kin, "--output", model]):
            return 1
        add_noise(model, data)
        with open(data, "rb") as f:
            sha256 = hashlib.sha256(f.read()).hexdigest()

        report = os.path.join(tmp, "report")
        if not run([args.exe, "fit", data, "--model", "exact", "--pressure", "hertz",
                    "--channels", ",".join(CHANNELS), "--report", report]):
            return 1
        page = os.path.join(report, "report.html")
        parsed = render(browser, tmp, page)
        failures += residual_failures(parsed)
        failures += collapse_failures(parsed)
        failures += traceability_failures("report.html", parsed, sha256)
        narrow = narrow_widths(browser, tmp, page)
        failures += width_failures("report.html", narrow)
        failures += readable_failures("report.html", narrow)
        failures += layout_failures("report.html", in_frame(browser, tmp, page, 1400), narrow)
        with open(os.path.join(report, "report.json")) as f:
            values = {n: p["value"] for n, p in json.load(f)["parameters"].items()}
        ascending = sorted(values, key=values.get)
        failures += click_failures(
            "report.html, value",
            click_header(browser, tmp, page, "#parameter-table th:nth-child(2)", "data-param"),
            ascending, ascending[::-1])

        compare = os.path.join(tmp, "compare")
        if not run([args.exe, "compare", data, "--models", "seed,exact", "--pressure", "hertz",
                    "--channels", ",".join(CHANNELS), "--report", compare]):
            return 1
        with open(os.path.join(compare, "compare.json")) as f:
            compare_json = json.load(f)
        page = os.path.join(compare, "compare.html")
        parsed = render(browser, tmp, page)
        failures += compare_failures(parsed, compare_json)
        failures += traceability_failures("compare.html", parsed, sha256)
        narrow = narrow_widths(browser, tmp, page)
        failures += width_failures("compare.html", narrow)
        failures += readable_failures("compare.html", narrow)
        failures += layout_failures("compare.html", in_frame(browser, tmp, page, 1400), narrow)
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
