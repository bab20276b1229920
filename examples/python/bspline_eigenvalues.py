#!/usr/bin/python3
"""The spectra of the subdivision matrices S_i of uniform B-splines, degree 1 to 6.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/bspline_eigenvalues.py [OUTDIR]

Writes OUTDIR/bspline-eigenvalues.png (OUTDIR: default a new temporary folder, printed at the
end) and prints a table.

What it shows: a B-spline curve of degree d with d + 1 control points is the attractor of the IFS
f_i(X) = X P^-1 S_i P (000 §2; 004 Ch. 3), and the eigenvalues of both S_i are exactly
1, 1/2, 1/4, ..., 1/2^d: the eigenvalue 1 (affine invariance), the subdominant 1/2 (the
curve's parameter halves with each map), and the powers of 1/2 that make the pieces
C^(d-1) (000 Fig. 2 prints 1, 1/2, 1/4, 1/8 for the cubic; 004 Figs. 3.1, 3.2). Each curve is
built from its JSON object with project.add() (the "scheme" object of
examples/000-fig02-cubic-bspline-from-point.awb with another degree) and read with
item.maps(). The plot puts the family in the complex plane with the unit circle (all inside:
the maps of the lifted IFS contract) and, beside it, -log2 |lambda_k| against k: the line
k for every degree. The script fails (exit status 1) if an eigenvalue differs from 1/2^k by more
than 1e-12.
"""

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

DEGREES = range(1, 7)


def bspline(degree):
    """A uniform B-spline of `degree` on degree + 1 control points, as project.add() takes it."""
    return {
        "type": "subdivision-curve",
        "name": f"Uniform B-spline, degree {degree}",
        "scheme": {"kind": "bspline", "degree": degree},
        "control_points": [[float(k), float((k * k) % 3)] for k in range(degree + 1)],
        "start_set": {"kind": "point", "points": [[0.0, 0.0]]},
    }


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="awb-"))
    out.mkdir(parents=True, exist_ok=True)
    project = awb.Project()
    family = {}
    worst = 0.0
    print(f"{'degree':>6}  {'map':>3}  eigenvalues of S_i{'':<40} max |lambda_k - 2^-k|")
    for d in DEGREES:
        item = project.add(bspline(d))
        expected = np.array([2.0 ** -k for k in range(d + 1)])
        for m in item.maps():
            ev = m["eigenvalues"]
            error = float(np.max(np.abs(ev - expected))) if len(ev) == d + 1 else np.inf
            worst = max(worst, error)
            text = ", ".join(f"{z.real:g}" if abs(z.imag) < 1e-12 else f"{z:g}" for z in ev)
            print(f"{d:>6}  S_{m['index']}  {text:<58} {error:.1e}")
        family[d] = item.maps()[0]["eigenvalues"]
    print(f"{len(project)} curves; the largest deviation from 1/2^k: {worst:.1e}")

    fig, (plane, logs) = plt.subplots(1, 2, figsize=(11, 5), dpi=100)
    t = np.linspace(0, 2 * np.pi, 400)
    plane.plot(np.cos(t), np.sin(t), color="grey", lw=0.8, label="unit circle")
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(DEGREES)))
    for (d, ev), c in zip(family.items(), colors):
        # each degree on its own ring size, so that the shared values 1, 1/2, ... stay visible
        plane.scatter(ev.real, ev.imag, s=30 + 45 * (len(DEGREES) - d), facecolors="none",
                      edgecolors=[c], lw=1.4, label=f"degree {d}")
        k = np.arange(len(ev))
        logs.plot(k, -np.log2(np.abs(ev)), "o-", color=c, label=f"degree {d}")
    plane.set_aspect("equal")
    plane.set_xlim(-1.1, 1.1)
    plane.set_ylim(-1.1, 1.1)
    plane.axhline(0, color="grey", lw=0.4)
    plane.axvline(0, color="grey", lw=0.4)
    plane.set_title("eigenvalues of S_i: 1, 1/2, ..., 1/2^d")
    plane.set_xlabel("Re λ")
    plane.set_ylabel("Im λ")
    plane.legend(fontsize=7, loc="lower left")
    logs.set_xlabel("k")
    logs.set_ylabel("−log2 |λ_k|")
    logs.set_title("λ_k = 2^-k for every degree")
    logs.grid(alpha=0.3)
    logs.legend(fontsize=7)
    fig.suptitle("Uniform B-splines as IFS: spectra of the subdivision matrices")
    fig.tight_layout()
    png = out / "bspline-eigenvalues.png"
    fig.savefig(png)
    print(png)
    if worst > 1e-12:
        print("FAILED: an eigenvalue is not 1/2^k", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
