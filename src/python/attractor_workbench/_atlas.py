"""The regularity atlas of a family of schemes, on this machine or a Dask cluster (issue 48).

The plan (AtlasPlan, the core's RegularityAtlas) hands out batches of parameter points; each
point is one certified joint-spectral-radius computation of the family's member
(Family.evaluate, the same code as `attractor-cli regularity-interval` and the window). This
file only moves the points: to Dask workers as tasks of a few points each, or one after another
in this process. Each point runs under a budget of work, not time, so the rows are the same
wherever they ran; a worker lost mid-run changes nothing (Dask runs its tasks elsewhere).
"""

import json
import math
import os
import sys
import time

from . import _native
from ._cluster import IN_PROCESS, Bar, Session, add_where_arguments, failer, where_of

__all__ = ["parse_grid", "run_atlas", "main"]

def parse_grid(texts):
    """["w=0:0.25:26", "v=-0.02:0.02:11"] -> {"w": (0.0, 0.25, 26), ...} (ValueError on a typo)."""
    grid = {}
    for text in texts:
        name, sep, spec = text.partition("=")
        parts = spec.split(":")
        if not sep or not name.strip() or len(parts) != 3:
            raise ValueError(f"--grid '{text}': expected NAME=FROM:TO:COUNT, e.g. w=0:0.25:26")
        try:
            lo, hi, count = float(parts[0]), float(parts[1]), int(parts[2])
        except ValueError:
            raise ValueError(f"--grid '{text}': FROM and TO must be numbers and COUNT a whole "
                             f"number") from None
        if name.strip() in grid:
            raise ValueError(f"--grid: the parameter '{name.strip()}' is given twice")
        grid[name.strip()] = (lo, hi, count)
    if not 1 <= len(grid) <= 2:
        raise ValueError(f"an atlas has one or two parameters (--grid), got {len(grid)}")
    return grid


def _evaluate_chunk(family, points, options):
    """A task: the rows of a few points (runs on a worker)."""
    return [family.evaluate(p, options) for p in points]


def run_atlas(item, grid, client=None, *, parameters=None, mask=None, smoothness=1,
              progress=None, workers=None, on_batch=None, **options):
    """The atlas of `item`'s family over `grid` (see attractor_workbench.atlas)."""
    if isinstance(grid, (list, tuple)):
        grid = parse_grid(grid)
    names = list(grid)
    family = item if isinstance(item, _native.Family) else _native.Family(
        item, parameters or names, mask)
    if list(family.parameters) != names:
        raise _native.Error(f"the grid's parameters {names} are not the family's "
                            f"{list(family.parameters)}")
    opts = dict(options)
    opts["smoothness"] = smoothness
    plan = _native.AtlasPlan([(n, *grid[n]) for n in names], opts)
    opts = plan.options
    report = progress if callable(progress) else Bar(progress or "none")
    start = time.monotonic()
    with Session(client, workers) as session:
        rows_so_far = 0
        while True:
            batch = plan.next_batch()
            if not batch:
                break
            report({"event": "round", "round": plan.round, "points": len(batch)})
            done = 0

            def tick(new_rows):
                nonlocal done
                done += len(new_rows)
                report({"event": "progress", "round": plan.round, "done": done,
                        "total": len(batch), "rows": rows_so_far + done,
                        "elapsed": time.monotonic() - start, "new": new_rows})

            if session.in_process:
                rows = []
                for p in batch:
                    rows.append(family.evaluate(p, opts))
                    tick(rows[-1:])
            else:
                from dask.distributed import as_completed
                # A few tasks per worker and round, each a handful of points: the scheduler's
                # ~1 ms per task stays small beside the points' work, and a cancelled run
                # leaves each worker at most 8 points to finish (a running task cannot be
                # stopped).
                size = max(1, min(8, math.ceil(len(batch) / (4 * session.workers()))))
                chunks = [batch[i:i + size] for i in range(0, len(batch), size)]
                session.futures = session.client.map(
                    _evaluate_chunk, [family] * len(chunks), chunks, [opts] * len(chunks),
                    pure=False, retries=2)
                index = {f.key: i for i, f in enumerate(session.futures)}
                results = [None] * len(chunks)
                for future in as_completed(session.futures):
                    results[index[future.key]] = future.result()
                    tick(results[index[future.key]])
                session.futures = []
                rows = [row for chunk in results for row in chunk]
            plan.accept(rows)
            rows_so_far += len(rows)
            if on_batch:
                on_batch(plan)
        scheduler, count = session.scheduler, session.workers()
    rows = plan.rows()
    result = {
        "family": family.to_json(),
        "axes": [{"name": n, "from": a, "to": b, "count": c} for n, a, b, c in plan.axes],
        "smoothness": smoothness,
        "options": opts,
        "rows": rows,
        "runs": plan.runs(),
        "points": len(rows),
        "rounds": plan.round,
        "seconds": time.monotonic() - start,
        "scheduler": scheduler,
        "workers": count,
    }
    report({"event": "done", "points": len(rows), "seconds": result["seconds"]})
    return result


def _arguments(argv):
    import argparse
    p = argparse.ArgumentParser(
        prog="python3 -m attractor_workbench.atlas",
        description="The certified regularity atlas of a curve item's family of schemes over "
                    "a grid of one or two parameters, refined where C^k changes; on a local "
                    "Dask cluster of this machine's cores, or on the cluster at --scheduler.")
    p.add_argument("project", help="the project file (.awb)")
    p.add_argument("--item", help="the curve item (default: the first subdivision curve)")
    p.add_argument("--grid", action="append", required=True, metavar="NAME=FROM:TO:COUNT",
                   help="a parameter's grid, e.g. w=0:0.25:26; twice for two parameters")
    p.add_argument("--mask", help="for a mask item: its coefficients with the parameters in "
                                  "them, e.g. \"v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, "
                                  "0, v\"")
    p.add_argument("--smoothness", type=int, default=1, metavar="K",
                   help="the class C^K asked for (default 1)")
    p.add_argument("--tolerance", type=float, default=1e-6,
                   help="one parameter: a boundary's bracket width (default 1e-6)")
    p.add_argument("--refine", type=int, default=3,
                   help="two parameters: levels of refinement at the boundaries (default 3)")
    p.add_argument("--work", type=float, default=1e5,
                   help="joint-spectral-radius products per point (default 1e5)")
    add_where_arguments(p)
    p.add_argument("--json", metavar="OUT", required=True,
                   help="where the result goes (JSON; - for standard output)")
    return p.parse_args(argv)


_fail = failer("atlas")


def main(argv=None):
    args = _arguments(sys.argv[1:] if argv is None else argv)
    try:
        grid = parse_grid(args.grid)
        client, progress = where_of(args)
    except ValueError as e:
        return _fail(str(e))
    try:
        project = _native.open(args.project)
    except _native.Error as e:
        return _fail(str(e), 1)
    if args.item:
        try:
            item = project.item(args.item)
        except _native.Error:
            item = None
        if item is None:
            return _fail(f"no item '{args.item}' in {args.project}")
    else:
        item = next((i for i in project.items if i.kind == "subdivision-curve"), None)
        if item is None:
            return _fail(f"{args.project} has no subdivision curve")
    try:
        result = run_atlas(item, grid, client=client, mask=args.mask,
                           smoothness=args.smoothness, progress=progress,
                           workers=args.workers, tolerance=args.tolerance,
                           refine=args.refine, work=args.work)
    except KeyboardInterrupt:
        return _fail("cancelled; the cluster's tasks were cancelled", 130)
    except (_native.Error, RuntimeError, OSError) as e:
        return _fail(str(e), 1)
    result["project"] = os.path.abspath(args.project)
    result["item"] = item.name
    text = json.dumps(result, indent=1)
    if args.json == "-":
        print(text)
    else:
        with open(args.json, "w", encoding="utf-8") as f:
            f.write(text + "\n")
    if progress != "jsonl":
        for run in result["runs"]:
            a, b = run["from"], run["to"]
            print(f"atlas: C^{args.smoothness} from {_end(a)} to {_end(b)}", file=sys.stderr)
        print(f"atlas: {result['points']} points in {result['rounds']} rounds, "
              f"{result['seconds']:.1f} s on {result['workers']} worker(s) "
              f"({result['scheduler']})", file=sys.stderr)
    return 0


def _end(b):
    if b["range_end"]:
        return f"{b['inner']:.10g} (the grid's end)"
    lo, hi = sorted((b["inner"], b["outer"]))
    return f"[{lo:.10g}, {hi:.10g}]"
