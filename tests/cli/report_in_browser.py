#!/usr/bin/env python3
"""Fits and compares the bundled example, opens report.html and compare.html in headless
Chromium and checks what they render.

  report_in_browser.py --exe build/frictionid --data data/example_hertz.csv [--screenshot PNG]

Checks, for each page:
  - the DOM holds every parameter value of report.json (compare.json: of every model) exactly
    (the value cell's data-value) and shows it rounded: to the decimal place of its stderr's
    second digit (within 0.05 stderr), or to 6 significant digits without a stderr;
  - every plot file of the report is a figure in the page, and every figure's SVG has a nonzero
    rendered size: the page's own script writes getBoundingClientRect() into the figure's
    data-rendered-size attribute on load, and --dump-dom shows the DOM after load;
  - no http(s) URL anywhere in the page or its DOM, so nothing is fetched;
  - the screenshot is not blank: the grey levels of its left half vary.
Exit 0: passed; 1: failed; 77: skipped (Chromium not installed; ctest's SKIP_RETURN_CODE).
--screenshot copies report.html's screenshot to PNG (docs/report.png is made this way).
Python standard library only.
"""

import argparse
import html.parser
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--hide-scrollbars",
]
WINDOW = (1200, 1800)


def chromium():
    """The browser's path, or None after printing why the test is skipped (exit code 77)."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    print("SKIPPED: Chromium is not installed (apt-get install chromium, or scripts/install-deps)")
    return None


class Page(html.parser.HTMLParser):
    """Parameter rows (name -> data-value and text of the value cell) and plot figures."""

    def __init__(self):
        super().__init__()
        self.params = {}  # fit report: name -> (data-value, text) of the value cell
        self.model_params = {}  # compare: (model, name) -> (data-value, text)
        self.figures = []  # (data-file, data-rendered-size)
        self._param = None
        self._cell = None  # [data-value, text, model] of the cell being read
        self._cells = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "tr" and "data-param" in a:
            self._param, self._cells = a["data-param"], 0
        elif tag == "td" and self._param is not None:
            self._cells += 1
            if "data-model" in a or (self._cells == 2 and not self.model_params):
                self._cell = [a.get("data-value"), "", a.get("data-model")]
        elif tag == "figure" and "plot" in a.get("class", "").split():
            self.figures.append((a.get("data-file"), a.get("data-rendered-size")))

    def handle_data(self, data):
        if self._cell is not None:
            self._cell[1] += data

    def handle_endtag(self, tag):
        if tag == "td" and self._cell is not None:
            value, text, model = self._cell
            if model is None:
                self.params[self._param] = (value, text)
            else:
                self.model_params[(model, self._param)] = (value, text)
            self._cell = None
        elif tag == "tr":
            self._param = None


def png_grey_levels(path, columns):
    """Grey levels of the left `columns` pixels of every row of an 8-bit RGB(A) PNG. PNG filters
    only look left and up, so decoding a left strip of each row is exact."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width, height, bpp = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, "unexpected PNG format"
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * bpp
    n = min(columns, width) * bpp
    previous = bytearray(n)
    levels = []
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        line = bytearray(raw[start + 1:start + 1 + n])
        for i in range(n):
            left = line[i - bpp] if i >= bpp else 0
            up = previous[i]
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                up_left = previous[i - bpp] if i >= bpp else 0
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else up_left)
                line[i] = (line[i] + pred) & 255
        levels.extend((line[i] + line[i + 1] + line[i + 2]) // 3 for i in range(0, n, bpp))
        previous = line
    return levels


def shown_number(text):
    """The number a cell shows: "0.8500", or "1.234\u00a0\u00d7\u00a010\u207b\u2078"."""
    superscripts = str.maketrans("\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079\u207b",
                                 "0123456789-")
    mantissa, _, power = text.replace("\u00a0", "").partition("\u00d710")
    return float(mantissa) * (10.0 ** int(power.translate(superscripts)) if power else 1.0)


def value_failures(label, cell, expected, stderr=None):
    if cell is None:
        return ["%s is not in the DOM" % label]
    exact, shown = cell
    if exact is None or float(exact) != expected:
        return ["%s: DOM holds %s, the JSON report %r" % (label, exact, expected)]
    # Rounded to the place of the stderr's second digit: off by at most half a unit there.
    tolerance = max(1e-5 * abs(expected), 0.05 * stderr if stderr else 0.0)
    if abs(shown_number(shown) - expected) > tolerance:
        return ["%s: shown as %s, the JSON report %r" % (label, shown, expected)]
    return []


def check_page(browser, tmp, directory, page_name, screenshot_copy=None):
    """Renders directory/page_name; returns (parsed DOM, failures)."""
    failures = []
    page = os.path.join(directory, page_name)
    url = "file://" + page
    common = CHROMIUM_FLAGS + ["--user-data-dir=" + os.path.join(tmp, "profile"),
                               "--window-size=%d,%d" % WINDOW]
    dom = subprocess.run([browser] + common + ["--dump-dom", url], capture_output=True,
                         text=True, timeout=180).stdout
    shot = os.path.join(tmp, "shot.png")
    if os.path.exists(shot):
        os.remove(shot)
    subprocess.run([browser] + common + ["--screenshot=" + shot, url], capture_output=True,
                   timeout=180)
    with open(page, encoding="utf-8") as f:
        source = f.read()
    parsed = Page()
    parsed.feed(dom)

    svg_files = sorted(p for p in os.listdir(directory) if p.endswith(".svg"))
    figure_files = sorted(f for f, _ in parsed.figures)
    if not svg_files or figure_files != svg_files:
        failures.append("%s: figures %s, plot files %s" % (page_name, figure_files, svg_files))
    for file, size in parsed.figures:
        w, _, h = (size or "0x0").partition("x")
        if not (int(w) > 0 and int(h) > 0):
            failures.append("%s: plot %s rendered with size %s" % (page_name, file, size))
    for text, where in ((source, "page"), (dom, "DOM")):
        for scheme in ("http://", "https://"):
            if scheme in text:
                failures.append("%s: the %s holds a %s URL" % (page_name, where, scheme))
    if not os.path.exists(shot):
        failures.append("%s: no screenshot" % page_name)
    else:
        levels = png_grey_levels(shot, WINDOW[0] // 2)
        mean = sum(levels) / len(levels)
        variance = sum((g - mean) ** 2 for g in levels) / len(levels)
        dark = sum(1 for g in levels if g < 200) / len(levels)
        print("%s screenshot: grey mean %.1f, variance %.1f, %.1f %% pixels darker than 200"
              % (page_name, mean, variance, 100 * dark))
        if variance < 100 or dark < 0.01:
            failures.append("%s: the screenshot is blank" % page_name)
        if screenshot_copy:
            shutil.copyfile(shot, screenshot_copy)
    print("%s: %d plots" % (page_name, len(parsed.figures)))
    return parsed, failures


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        print(" ".join(cmd) + "\n" + done.stdout + done.stderr)
    return done.returncode == 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--screenshot")
    args = ap.parse_args()

    browser = chromium()
    if browser is None:
        return 77

    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "report")
        if not run([args.exe, "fit", args.data, "--model", "exact", "--pressure", "hertz",
                    "--report", report]):
            return 1
        parsed, f = check_page(browser, tmp, report, "report.html", args.screenshot)
        failures += f
        with open(os.path.join(report, "report.json")) as fj:
            report_json = json.load(fj)
        for name, entry in report_json["parameters"].items():
            failures += value_failures("report.html: parameter " + name,
                                       parsed.params.get(name), entry["value"], entry["stderr"])
        if not any(f == "collapse_T_x.svg" for f, _ in parsed.figures):
            failures.append("report.html: no collapse plot of T_x")

        compare = os.path.join(tmp, "compare")
        if not run([args.exe, "compare", args.data, "--models", "seed,exact", "--pressure",
                    "hertz", "--report", compare]):
            return 1
        parsed, f = check_page(browser, tmp, compare, "compare.html")
        failures += f
        with open(os.path.join(compare, "compare.json")) as fj:
            compare_json = json.load(fj)
        for model in compare_json["models"]:
            for name, entry in model["parameters"].items():
                failures += value_failures(
                    "compare.html: %s parameter %s" % (model["model"], name),
                    parsed.model_params.get((model["model"], name)), entry["value"],
                    None if entry["fixed"] else entry["stderr"])
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
