#!/usr/bin/python3
"""The Hölder regularity of the four-point scheme as its tension ω moves.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/four_point_regularity.py [OUTDIR]

Writes OUTDIR/four-point-regularity.png (OUTDIR: default a new temporary folder, printed at the
end) and prints the sweep.

What it shows: the certified Hölder exponent r(ω) (item.regularity(): lower and upper bound) of
the four-point scheme of 000 Fig. 5 (Schaefer, Levin & Goldman; the scheme of Dyn, Levin &
Gregory 1987) for 40 values of ω in (-0.1, 0.3), set through item.parameters["scheme.omega"]
inside one `project.edit()` block, which one undo then takes back. It reproduces

* r = 2 at ω = 1/16 (the standard four-point scheme: C^1, reproducing cubics; 000 Fig. 5),
* r = 1 at ω = 0 (linear interpolation), below 1 (fractal curves) for ω < 0,
* C^1 (r > 1) on (0, ω*) with ω* ≈ 0.19273, the real root of 32ω³ + 4ω − 1 (Hechler, Mößner &
  Reif 2009; docs/mathematics.md), Dyn–Gregory–Levin's C^1 range (0, 1/8] included.

ω* is bracketed twice: between two values of the sweep, then by bisection on certified values
(inner: lower bound > 1, C^1; outer: upper bound < 1, not C^1). The script prints
"omega* bracket: [inner, outer]" and fails (exit status 1) if the root of the cubic is not in it.
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

EXAMPLE = SOURCE / "examples" / "000-fig05-four-point-from-segment.awb"


def omega_star():
    """The real root of 32 w^3 + 4 w - 1."""
    roots = np.roots([32.0, 0.0, 4.0, -1.0])
    return float(min(roots, key=lambda z: abs(z.imag)).real)


def certified(item, omega):
    item.parameters["scheme.omega"] = float(omega)
    r = item.regularity()
    return r["lower"], r["upper"]


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="awb-"))
    out.mkdir(parents=True, exist_ok=True)
    project = awb.open(EXAMPLE)
    curve = project.items[0]
    assert curve.parameters["scheme.omega"] == 1 / 16

    omegas = np.linspace(-0.1, 0.3, 42)[1:-1]  # 40 values inside (-0.1, 0.3)
    lower, upper = [], []
    with project.edit("Sweep omega"):
        print(f"{'omega':>9} {'lower':>10} {'upper':>10}  smoothness")
        for w in omegas:
            lo, up = certified(curve, w)
            lower.append(lo)
            upper.append(up)
            smooth = "C^1" if lo > 1 else ("not C^1" if up < 1 else "undecided")
            print(f"{w:9.4f} {lo:10.6f} {up:10.6f}  {smooth}")
        at_sixteenth = certified(curve, 1 / 16)
        # omega* from the sweep: the last certified C^1 value and the next certified not C^1
        inner = max(w for w, lo in zip(omegas, lower) if lo > 1)
        outer = min(w for w, up in zip(omegas, upper) if up < 1 and w > inner)
        print(f"sweep bracket of omega*: [{inner:.4f}, {outer:.4f}]")
        for _ in range(40):  # bisection on certified values
            mid = (inner + outer) / 2
            lo, up = certified(curve, mid)
            if lo > 1:
                inner = mid
            elif up < 1:
                outer = mid
            else:
                break
    project.undo()  # the whole sweep was one undo step
    assert curve.parameters["scheme.omega"] == 1 / 16 and not project.can_undo

    root = omega_star()
    print(f"r(1/16) in [{at_sixteenth[0]:.12f}, {at_sixteenth[1]:.12f}] (000 Fig. 5: 2)")
    print(f"omega* bracket: [{inner:.12f}, {outer:.12f}]")
    print(f"omega* = {root:.12f} (the real root of 32w^3 + 4w - 1)")

    fig, ax = plt.subplots(figsize=(8, 5), dpi=100)
    ax.fill_between(omegas, lower, upper, color="tab:blue", alpha=0.3)
    ax.plot(omegas, lower, "o-", ms=3, color="tab:blue", label="Hölder exponent r(ω), certified")
    ax.axhline(1, color="grey", lw=0.8, ls="--")
    ax.axhline(2, color="grey", lw=0.5, ls=":")
    ax.axvline(root, color="tab:red", lw=1.2,
               label=f"ω* = {root:.5f}: 32ω³ + 4ω − 1 = 0 (C¹ boundary)")
    ax.plot([1 / 16], [at_sixteenth[0]], "s", color="black", label="ω = 1/16: r = 2 (000 Fig. 5)")
    ax.axvspan(0, root, color="tab:green", alpha=0.08, label="C¹ (r > 1)")
    ax.set_xlabel("tension ω")
    ax.set_ylabel("Hölder regularity r")
    ax.set_title("Four-point scheme: regularity against tension")
    ax.set_xlim(-0.1, 0.3)
    ax.legend(loc="upper right", fontsize=8)
    png = out / "four-point-regularity.png"
    fig.tight_layout()
    fig.savefig(png)
    print(png)

    ok = inner < root < outer and abs(at_sixteenth[0] - 2) < 1e-9
    if not ok:
        print("FAILED: omega* is not in the bracket, or r(1/16) != 2", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
