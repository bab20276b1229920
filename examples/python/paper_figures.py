#!/usr/bin/python3
"""A batch of the figures of 000 (Schaefer, Levin & Goldman, "Subdivision schemes and attractors",
SGP 2005), Figs. 2 to 11, from the example projects examples/000-fig*.awb.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/paper_figures.py [OUTDIR]

Writes one PNG per item into OUTDIR (default: a new temporary folder) and prints each file's
name.

What it shows: every item of every 000-fig*.awb opened with attractor_workbench.open() and drawn
with item.render() — the same figure code as attractor-cli render and File > Export Figure —
as the paper prints it: B-spline curves from a point (Fig. 2) and an end-interpolating cubic
from a triangle (Fig. 3), a union of two Bézier curves (Fig. 4), the four-point curve from a
segment (Fig. 5), surfaces (Figs. 6-9), and the Koch curve and the Sierpinski gasket given
control points (Figs. 10, 11). An eigenvalue-plot item (the spectra of S_i or A_i beside Figs. 2
and 5) has no attractor to render: its spectra are read from its curve's item.maps() and drawn
with matplotlib (Agg) in the complex plane with the unit circle, as the window's plot shows them.
"""

import re
import sys
import tempfile
from pathlib import Path

import numpy as np

SOURCE = Path(__file__).resolve().parents[2]
try:
    import attractor_workbench as awb
except ImportError:  # run from the source tree without PYTHONPATH
    sys.path.insert(0, str(SOURCE / "build" / "python"))
    import attractor_workbench as awb

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SIZE = (600, 450)


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-").lower()[:60]


def spectrum_figure(project, plot, png):
    """The eigenvalue plot `plot` (JSON: "source" item, "matrices" "S" or "A") with matplotlib."""
    obj = plot.to_json()
    which = "eigenvalues" if obj.get("matrices", "S") == "S" else "eigenvalues_A"
    fig, ax = plt.subplots(figsize=(SIZE[0] / 100, SIZE[1] / 100), dpi=100)
    t = np.linspace(0, 2 * np.pi, 400)
    ax.plot(np.cos(t), np.sin(t), color="grey", lw=0.8)
    for m in project[obj["source"]].maps():
        ev = m[which]
        ax.plot(ev.real, ev.imag, "o", mfc="none", ms=8 + 4 * m["index"],
                label=f"{'S' if which == 'eigenvalues' else 'A'}_{m['index'] + 1}")
    ax.set_aspect("equal")
    ax.axhline(0, color="grey", lw=0.4)
    ax.axvline(0, color="grey", lw=0.4)
    ax.set_title(plot.name, fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="awb-"))
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in sorted((SOURCE / "examples").glob("000-fig*.awb")):
        project = awb.open(path)
        for item in project:
            png = out / f"{path.stem}--{slug(item.name)}.png"
            if item.dimension == 0:
                spectrum_figure(project, item, png)
            else:
                item.render(png, size=SIZE)
            written.append(png)
            print(png.name)
    print(f"{len(written)} figures in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
