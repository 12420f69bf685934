#!/usr/bin/env python3
"""Hostile names in headless Chromium: a batch whose file names hold a right-to-left override
(U+202E) and a formula, and a fit coloured by values with control characters and Latin-1 bytes.

  hostile_names_in_browser.py --exe build/frictionid

Checks:
  - summary.html opened as summary.html#sort=%E0%A4%A (a malformed escape) throws no uncaught
    error in its script (Chromium logs one as "Uncaught URIError" on the console), and
    #sort=-rows%ZZ (malformed too) leaves the rows in label order;
  - in the DOM, every text that holds U+202E is inside a <bdi> element or is an attribute;
  - the standalone collapse_T_x.svg of the coloured fit is drawn: Chromium shows no XML parse
    error page, and the DOM holds the Latin-1 value escaped as caf\\xe9.
Exit 0: passed; 1: failed; 77: skipped (Chromium not installed; ctest's SKIP_RETURN_CODE).
Python standard library only; the Chromium helpers are report_in_browser.py's.
"""

import argparse
import html.parser
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from report_in_browser import CHROMIUM_FLAGS, WINDOW, chromium, run  # noqa: E402

RLO = "\u202e"
BAD_ROWS = "v_x,omega,N,R,T_x\n0.1,2,1000,0.05,abc\n"


class BidiTexts(html.parser.HTMLParser):
    """Texts that hold U+202E outside a <bdi> element, and the runs table's labels in order."""

    def __init__(self):
        super().__init__()
        self.bdi_depth = 0
        self.loose = []
        self.order = []

    def handle_starttag(self, tag, attrs):
        if tag == "bdi":
            self.bdi_depth += 1
        if tag == "tr":
            label = dict(attrs).get("data-label")
            if label is not None:
                self.order.append(label)

    def handle_endtag(self, tag):
        if tag == "bdi":
            self.bdi_depth -= 1

    def handle_data(self, data):
        if RLO in data and self.bdi_depth == 0:
            self.loose.append(data)


def open_page(browser, tmp, url):
    """The DOM after the page's scripts ran, and Chromium's console log."""
    cmd = [browser] + CHROMIUM_FLAGS + [
        "--user-data-dir=" + os.path.join(tmp, "profile"), "--window-size=%d,%d" % WINDOW,
        "--enable-logging=stderr", "--v=0", "--dump-dom", url]
    done = subprocess.run(cmd, capture_output=True, timeout=180)
    return (done.stdout.decode("utf-8", "replace"), done.stderr.decode("utf-8", "replace"))


def console_errors(log):
    return [line for line in log.splitlines() if "CONSOLE" in line and "Uncaught" in line]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    args = ap.parse_args()
    browser = chromium()
    if browser is None:
        return 77
    exe = os.path.abspath(args.exe)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        runs = os.path.join(tmp, "runs")
        os.mkdir(runs)
        good = os.path.join(tmp, "good.csv")
        if not run([exe, "generate", "--rows", "200", "--seed", "1", "--output", good]):
            return 1
        with open(good) as f:
            good_text = f.read()
        for name in ("r" + RLO + "abc", "=1+2", "plain"):
            with open(os.path.join(runs, name + ".csv"), "w") as f:
                f.write(good_text)
        with open(os.path.join(runs, "bad" + RLO + "xyz.csv"), "w") as f:
            f.write(BAD_ROWS)
        out = os.path.join(tmp, "campaign")
        done = subprocess.run([exe, "batch", runs, "--report", out], capture_output=True)
        if done.returncode != 4:
            print("batch exited with %d\n%r" % (done.returncode, done.stdout + done.stderr))
            return 1
        page = "file://" + os.path.join(out, "summary.html")

        dom, log = open_page(browser, tmp, page + "#sort=%E0%A4%A")
        failures += ["#sort=%%E0%%A4%%A: %s" % e for e in console_errors(log)]
        parsed = BidiTexts()
        parsed.feed(dom)
        if len(parsed.order) != 4:
            failures.append("the runs table has %d rows, expected 4" % len(parsed.order))
        failures += ["U+202E outside <bdi>: %r" % text for text in parsed.loose]

        dom, log = open_page(browser, tmp, page + "#sort=-rows%ZZ")
        failures += ["#sort=-rows%%ZZ: %s" % e for e in console_errors(log)]
        unsorted = BidiTexts()
        unsorted.feed(dom)
        if unsorted.order != parsed.order:
            failures.append("#sort=-rows%%ZZ reordered the rows: %r" % unsorted.order)

        # A fit coloured by values with a control character and a Latin-1 byte.
        lines = good_text.splitlines()
        values = [b"a\x01b", b"x\x0cy", b"caf\xe9"]
        colored = os.path.join(tmp, "colored.csv")
        with open(colored, "wb") as f:
            f.write(lines[0].encode() + b",surface\n")
            for k, line in enumerate(lines[1:]):
                f.write(line.encode() + b"," + values[k % 3] + b"\n")
        report = os.path.join(tmp, "report")
        if not run([exe, "fit", colored, "--color-by", "surface", "--report", report]):
            return 1
        dom, log = open_page(browser, tmp, "file://" + os.path.join(report, "collapse_T_x.svg"))
        if "parsererror" in dom or "This page contains the following errors" in dom:
            failures.append("collapse_T_x.svg is not well-formed: Chromium shows a parse error")
        if "caf\\xe9" not in dom:
            failures.append("collapse_T_x.svg: the value caf\\xe9 is not in the DOM")
        failures += ["collapse_T_x.svg: %s" % e for e in console_errors(log)]
        print("summary.html: %d rows; collapse_T_x.svg: %d bytes of DOM" % (len(parsed.order),
                                                                           len(dom)))
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
