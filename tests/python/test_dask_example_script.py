"""examples/python/fit_campaign_dask.py runs headless on a LocalCluster: it fits every load of
its generated campaign, recovers the f it was made with at each load, and writes the PNG."""

import subprocess
import sys


def test_the_campaign_example_recovers_f_at_every_load_and_writes_a_png(source_dir, tmp_path):
    script = source_dir / "examples" / "python" / "fit_campaign_dask.py"
    p = subprocess.run([sys.executable, str(script), "--output", str(tmp_path), "--workers", "2"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = [line.split() for line in p.stdout.splitlines() if line.strip().startswith("load_")]
    assert [r[0] for r in rows] == [f"load_{n}" for n in (1000, 2000, 3000, 4000, 5000)]
    for label, status, mean_n, f, *_ in rows:
        assert status == "ok"
        assert abs(float(f) - (0.9 - 4e-5 * float(mean_n))) < 0.01, label  # the script's truth
    png = (tmp_path / "f_vs_load.png").read_bytes()
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 10_000
