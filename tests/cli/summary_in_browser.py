#!/usr/bin/env python3
"""Runs a small batch (three generated runs at different loads and one broken file, through a
manifest), opens its summary.html in headless Chromium and checks what it renders.

  summary_in_browser.py --exe build/frictionid

Checks:
  - the DOM holds every successful run's parameter values and stderrs of summary.json exactly
    (data-value of the cells), and marks the failed run with its error;
  - there is one trend plot per parameter, and every plot has a nonzero rendered size (the
    page's script writes it into data-rendered-size on load);
  - every label link names a report file that exists;
  - no http(s) URL anywhere in the page or its DOM;
  - the screenshot is not blank;
  - at a 390 px window the page is no wider than the window, its text is readable and the trend
    plots stand in one column; at 1400 px three side by side (factorial_in_browser.py's checks);
  - sorting works: opened as summary.html#sort=-load the rows are in descending load, and as
    #sort=f in ascending f with the failed run (no f) last;
  - the headers are buttons: a click on f's sets its cell's aria-sort to ascending (the rows in
    ascending f, the failed run last), a second to descending (the failed run still last); the
    other headers' aria-sort stays none, and the button takes the keyboard's focus.
Exit 0: passed; 1: failed; 77: skipped (Chromium not installed; ctest's SKIP_RETURN_CODE).
Python standard library only; the Chromium helpers are report_in_browser.py's.
"""

import argparse
import html.parser
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_in_browser import CHROMIUM_FLAGS, WINDOW, chromium, png_grey_levels, run  # noqa: E402
from factorial_in_browser import (click_failures, click_header, in_frame,  # noqa: E402
                                  layout_failures, narrow_widths, readable_failures,
                                  width_failures)

LOADS = (1000, 2000, 3000)


class SummaryPage(html.parser.HTMLParser):
    """Rows of the runs table in DOM order, their cells, links and the plot figures."""

    def __init__(self):
        super().__init__()
        self.order = []  # labels in row order
        self.rows = {}  # label -> {"class", "params", "stderrs", "cells", "links"}
        self.figures = []  # (data-param, data-rendered-size)
        self.heads = {}  # th data-key -> data-order
        self._row = None
        self._td = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "tr" and "data-label" in a:
            self._row = {"class": a.get("class", ""), "params": {}, "stderrs": {}, "cells": [],
                         "links": []}
            self.rows[a["data-label"]] = self._row
            self.order.append(a["data-label"])
        elif tag == "td" and self._row is not None:
            self._td = [a.get("data-value"), ""]
            self._row["cells"].append(self._td)
            if "data-param" in a:
                self._row["params"][a["data-param"]] = a.get("data-value")
            if "data-stderr-of" in a:
                self._row["stderrs"][a["data-stderr-of"]] = a.get("data-value")
        elif tag == "a" and self._row is not None:
            self._row["links"].append(a.get("href"))
        elif tag == "th" and "data-key" in a:
            self.heads[a["data-key"]] = a.get("data-order")
        elif tag == "figure" and "plot" in a.get("class", "").split():
            self.figures.append((a.get("data-param"), a.get("data-rendered-size")))

    def handle_data(self, data):
        if self._td is not None:
            self._td[1] += data

    def handle_endtag(self, tag):
        if tag == "td":
            self._td = None
        elif tag == "tr":
            self._row = None


def render(browser, tmp, url, screenshot=None):
    common = CHROMIUM_FLAGS + ["--user-data-dir=" + os.path.join(tmp, "profile"),
                               "--window-size=%d,%d" % WINDOW]
    if screenshot:
        subprocess.run([browser] + common + ["--screenshot=" + screenshot, url],
                       capture_output=True, timeout=180)
    dom = subprocess.run([browser] + common + ["--dump-dom", url], capture_output=True,
                         text=True, timeout=180).stdout
    parsed = SummaryPage()
    parsed.feed(dom)
    return dom, parsed


def make_batch(exe, tmp):
    """Three runs at loads LOADS and a broken file, in a manifest; returns the batch directory."""
    lines = ["path,label,load"]
    for i, load in enumerate(LOADS, 1):
        path = os.path.join(tmp, "load%d.csv" % load)
        if not run([exe, "generate", "--model", "seed", "--rows", "400", "--noise", "0.01",
                    "--seed", str(i), "--loads", str(load), "--output", path]):
            return None
        lines.append("load%d.csv,at_%d,%d" % (load, load, load))
    with open(os.path.join(tmp, "broken.csv"), "w") as f:
        f.write("v_x,omega,N,R,T_x\n0.1,2,1000,0.05,abc\n")
    lines.append("broken.csv,broken,")
    manifest = os.path.join(tmp, "manifest.csv")
    with open(manifest, "w") as f:
        f.write("\n".join(lines) + "\n")
    out = os.path.join(tmp, "campaign")
    done = subprocess.run([exe, "batch", manifest, "--per-run-reports", "full", "--trend-x",
                           "load", "--report", out], capture_output=True, text=True)
    if done.returncode != 4:  # 4: some runs (the broken one) failed
        print("batch exited with %d\n%s%s" % (done.returncode, done.stdout, done.stderr))
        return None
    return out


def value_failures(what, cell, expected):
    if expected is None:
        return [] if cell is None else ["%s: DOM holds %s where summary.json has none" % (what, cell)]
    if cell is None or float(cell) != expected:
        return ["%s: DOM holds %s, summary.json %r" % (what, cell, expected)]
    return []


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--screenshot", help="copy the screenshot of summary.html here")
    args = ap.parse_args()
    browser = chromium()
    if browser is None:
        return 77

    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        out = make_batch(os.path.abspath(args.exe), tmp)
        if out is None:
            return 1
        page = os.path.join(out, "summary.html")
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        with open(page, encoding="utf-8") as f:
            source = f.read()
        shot = args.screenshot or os.path.join(tmp, "shot.png")
        dom, parsed = render(browser, tmp, "file://" + page, shot)

        # The table holds summary.json's numbers.
        if sorted(parsed.rows) != sorted(r["label"] for r in summary["runs"]):
            failures.append("rows %s, summary.json runs %s"
                            % (sorted(parsed.rows), [r["label"] for r in summary["runs"]]))
        params = []
        for r in summary["runs"]:
            row = parsed.rows.get(r["label"])
            if row is None:
                continue
            if r["status"] == "failed":
                if "failed" not in row["class"].split():
                    failures.append("failed run %s is not marked" % r["label"])
                if not any(r["error"] == text for _, text in row["cells"]):
                    failures.append("failed run %s: error %r not in its row" % (r["label"], r["error"]))
                if row["links"]:
                    failures.append("failed run %s links to %s" % (r["label"], row["links"]))
            for name, p in r["parameters"].items():
                if name not in params:
                    params.append(name)
                what = "%s %s" % (r["label"], name)
                failures += value_failures(what, row["params"].get(name), p["value"])
                failures += value_failures(what + " stderr", row["stderrs"].get(name), p["stderr"])
            for href in row["links"]:
                if not os.path.isfile(os.path.join(out, href)):
                    failures.append("%s links to %s, which does not exist" % (r["label"], href))
            if r["status"] == "ok" and not row["links"]:
                failures.append("run %s has no link to its report" % r["label"])

        # One plot per parameter, each drawn with a size.
        if sorted(p for p, _ in parsed.figures) != sorted(params):
            failures.append("plots of %s, parameters %s"
                            % ([p for p, _ in parsed.figures], params))
        for param, size in parsed.figures:
            w, _, h = (size or "0x0").partition("x")
            if not (int(w) > 0 and int(h) > 0):
                failures.append("plot of %s rendered with size %s" % (param, size))

        for text, where in ((source, "page"), (dom, "DOM")):
            for scheme in ("http://", "https://"):
                if scheme in text:
                    failures.append("the %s holds a %s URL" % (where, scheme))

        # At a 390 px window the page is no wider than the window (the table scrolls in its box),
        # its text is readable and the plots stand in one column; at 1400 px, three in a row.
        narrow = narrow_widths(browser, tmp, page)
        failures += width_failures("summary.html", narrow)
        failures += readable_failures("summary.html", narrow)
        failures += layout_failures("summary.html", in_frame(browser, tmp, page, 1400), narrow)

        if not os.path.exists(shot):
            failures.append("no screenshot")
        else:
            levels = png_grey_levels(shot, WINDOW[0] // 2)
            mean = sum(levels) / len(levels)
            variance = sum((g - mean) ** 2 for g in levels) / len(levels)
            dark = sum(1 for g in levels if g < 200) / len(levels)
            print("screenshot: grey mean %.1f, variance %.1f, %.1f %% pixels darker than 200"
                  % (mean, variance, 100 * dark))
            if variance < 100 or dark < 0.01:
                failures.append("the screenshot is blank")

        # Sorting on load from the URL's #sort=..., read back from the DOM.
        by_load = ["at_%d" % load for load in reversed(LOADS)] + ["broken"]
        _, sorted_page = render(browser, tmp, "file://" + page + "#sort=-load")
        if sorted_page.order != by_load:
            failures.append("#sort=-load: rows %s, expected %s" % (sorted_page.order, by_load))
        if sorted_page.heads.get("load") != "down":
            failures.append("#sort=-load: the load header is not marked descending")
        ok = [r for r in summary["runs"] if r["status"] == "ok"]
        by_f = [r["label"] for r in sorted(ok, key=lambda r: r["parameters"]["f"]["value"])]
        _, sorted_page = render(browser, tmp, "file://" + page + "#sort=f")
        if sorted_page.order != by_f + ["broken"]:
            failures.append("#sort=f: rows %s, expected %s" % (sorted_page.order, by_f + ["broken"]))
        # A click on f's header button, and a second one.
        failures += click_failures(
            "summary.html, f",
            click_header(browser, tmp, page, 'th[data-key="f"]', "data-label"),
            by_f + ["broken"], by_f[::-1] + ["broken"])
        print("summary.html: %d runs, %d plots" % (len(parsed.rows), len(parsed.figures)))
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
