#!/usr/bin/env python3
"""The regularity atlas's throughput (issue 48): certified points per second in this process and
on a local Dask cluster of 1 and 2 workers, Dask's overhead per task, and from them the time of
a 200 x 200 atlas on 100 workers.

    PYTHONPATH=build/python /usr/bin/python3 bench/atlas-cluster.py [--quick]

The family is the six-point interpolatory family "v, 0, w, 0, 1/2 - w - v, 1, ..." of the
Dubuc-Deslauriers example over a w x v grid without refinement (its points are a mix of exact
invariant polytopes, milliseconds, and branch and bound to the work budget, about a second):
the same points in each configuration, so the rates compare. Prints figures, asserts nothing.
"""

import argparse
import os
import sys
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[1]
try:
    import attractor_workbench as awb
except ImportError:
    sys.path.insert(0, str(SOURCE / "build" / "python"))
    import attractor_workbench as awb

MASK = "v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v"
ITEM = "Dubuc–Deslauriers 6-point by its mask (Hölder 6 − log₂ 9)"


def noop(x):
    return x


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a 4 x 4 grid instead of 6 x 6")
    args = ap.parse_args()
    n = 4 if args.quick else 6
    project = awb.open(SOURCE / "examples" / "masks-daubechies-dubuc-ternary.awb")
    family = awb.Family(project.item(ITEM), ["w", "v"], MASK)
    grid = {"w": (-0.25, 0.0, n), "v": (-0.02, 0.03, n)}
    rows = {}
    print(f"six-point family, {n} x {n} grid, work 1e5 products per point, "
          f"{os.cpu_count()} cores")
    print(f"{'where':<28} {'points':>7} {'seconds':>8} {'points/s':>9}")
    for label, client, workers in [("this process (1 core)", "in-process", None),
                                   ("local cluster, 1 worker", None, 1),
                                   ("local cluster, 2 workers", None, 2)]:
        t0 = time.monotonic()
        result = awb.atlas(family, grid, client=client, workers=workers, refine=0)
        seconds = time.monotonic() - t0   # with the cluster's start and stop
        rows[label] = (result["points"], seconds)
        print(f"{label:<28} {result['points']:>7} {seconds:>8.2f} "
              f"{result['points'] / seconds:>9.2f}")
    from dask.distributed import Client, LocalCluster
    t0 = time.monotonic()
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None,
                      silence_logs=40) as cluster, Client(cluster) as client:
        start = time.monotonic() - t0
        client.gather(client.map(noop, range(50)))   # warm
        tasks = 2000
        t0 = time.monotonic()
        client.gather(client.map(noop, range(tasks), pure=False))
        per_task = (time.monotonic() - t0) / tasks
    print(f"Dask: {per_task * 1e3:.2f} ms per task ({tasks} empty tasks, 2 workers; the "
          f"scheduler's rate), {start:.1f} s to start a local cluster of 2")
    points, seconds = rows["this process (1 core)"]
    per_point = seconds / points
    # A 200 x 200 grid refined at its C^k boundaries (about 1.5 times the grid's points in the
    # families tried), in tasks of 8 points: the points' work spread over 100 workers, plus the
    # scheduler's time per task (one scheduler, serial), plus ~8 rounds of a second's latency.
    total = 200 * 200 * 1.5
    estimate = total * per_point / 100 + total / 8 * per_task + 8 * 1.0
    print(f"one point: {per_point:.3f} s on one core. A 200 x 200 atlas (~{total:.0f} points "
          f"with refinement): {total * per_point / 3600:.1f} h on one core, about "
          f"{estimate / 60:.1f} min on 100 workers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
