"""The scripts of examples/python/ run standalone (a child interpreter, OUTDIR = tmp_path) and
write the figures they promise: non-trivial PNGs, and the numbers they print are right."""

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import EXAMPLES, SOURCE, subprocess_env

SCRIPTS = SOURCE / "examples" / "python"


def run_script(name, outdir):
    result = subprocess.run([sys.executable, str(SCRIPTS / name), str(outdir)],
                            capture_output=True, text=True, env=subprocess_env(), timeout=600,
                            cwd=outdir)
    assert result.returncode == 0, f"{name} failed ({result.returncode}):\n{result.stderr}"
    return result.stdout


def assert_png(path):
    assert path.exists(), f"{path.name} was not written"
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path.name} is not a PNG"
    assert len(data) > 1024, f"{path.name} is only {len(data)} bytes"


@pytest.mark.subprocess
def test_four_point_regularity(tmp_path):
    out = run_script("four_point_regularity.py", tmp_path)
    assert_png(tmp_path / "four-point-regularity.png")
    sweep = [line for line in out.splitlines() if re.match(r"\s*-?0\.\d{4}\s", line)]
    assert len(sweep) == 40
    omegas = [float(line.split()[0]) for line in sweep]
    assert -0.1 < min(omegas) and max(omegas) < 0.3
    m = re.search(r"omega\* bracket: \[([0-9.]+), ([0-9.]+)\]", out)
    assert m, out
    inner, outer = float(m.group(1)), float(m.group(2))
    roots = np.roots([32.0, 0.0, 4.0, -1.0])
    root = float(min(roots, key=lambda z: abs(z.imag)).real)
    assert abs(root - 0.19273) < 1e-5
    # (printed to 12 digits: a bracket narrower than that prints as one number twice)
    assert inner <= outer and inner <= root <= outer and outer - inner < 1e-3
    m = re.search(r"r\(1/16\) in \[([0-9.]+), ([0-9.]+)\]", out)
    assert m and abs(float(m.group(1)) - 2) < 1e-9 and abs(float(m.group(2)) - 2) < 1e-9


@pytest.mark.subprocess
def test_bspline_eigenvalues(tmp_path):
    out = run_script("bspline_eigenvalues.py", tmp_path)
    assert_png(tmp_path / "bspline-eigenvalues.png")
    rows = [line.split() for line in out.splitlines() if re.match(r"\s+\d\s+S_[01]\s", line)]
    assert len(rows) == 12  # degrees 1..6, S_0 and S_1
    for row in rows:
        degree = int(row[0])
        values = [float(x.rstrip(",")) for x in row[2:-1]]
        assert values == [2.0 ** -k for k in range(degree + 1)]
    m = re.search(r"largest deviation from 1/2\^k: ([0-9.e+-]+)", out)
    assert m and float(m.group(1)) <= 1e-12


@pytest.mark.subprocess
def test_paper_figures(awb, tmp_path):
    out = run_script("paper_figures.py", tmp_path)
    expected = sum(len(awb.open(p)) for p in EXAMPLES.glob("000-fig*.awb"))
    names = [line for line in out.splitlines() if line.endswith(".png")]
    assert len(names) == expected >= 10
    for name in names:
        assert_png(tmp_path / name)
    assert sorted(p.name for p in tmp_path.glob("*.png")) == sorted(names)


@pytest.mark.subprocess
def test_scripts_default_to_a_temporary_folder(tmp_path):
    """Without OUTDIR a script writes into a new temporary folder (here under TMPDIR, inside
    tmp_path), never into the current folder."""
    cwd, tmp = tmp_path / "cwd", tmp_path / "tmp"
    cwd.mkdir()
    tmp.mkdir()
    env = dict(subprocess_env(), TMPDIR=str(tmp))
    result = subprocess.run([sys.executable, str(SCRIPTS / "bspline_eigenvalues.py")],
                            capture_output=True, text=True, env=env, timeout=300, cwd=cwd)
    assert result.returncode == 0, result.stderr
    png = Path(result.stdout.strip().splitlines()[-1])
    assert png.name == "bspline-eigenvalues.png" and png.parent.parent == tmp
    assert_png(png)
    assert list(cwd.iterdir()) == []
