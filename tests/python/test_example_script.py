"""examples/python/fit_example.py runs headless: it prints the summary of the bundled example's
fit and writes the plot as a PNG."""

import subprocess
import sys


def test_the_example_script_prints_the_summary_and_writes_a_png(source_dir, tmp_path):
    script = source_dir / "examples" / "python" / "fit_example.py"
    p = subprocess.run([sys.executable, str(script), "--output", str(tmp_path)],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert "[[Variables]]" in p.stdout
    # The example was made with f = 0.9 (data/example_hertz_truth.json).
    f_line = next(line for line in p.stdout.splitlines() if line.strip().startswith("f:"))
    assert abs(float(f_line.split()[1]) - 0.9) < 0.01
    png = (tmp_path / "fit_example.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 10_000
