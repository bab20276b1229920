"""An animation's frames on a Dask cluster (issue 48): frame k is the item at time k / fps drawn
as `attractor-cli animate --frame K` draws it (Item.frame: the animated copy, the time and
values in the caption), every frame in the one framing of the union of their contents. Each
frame is one task; its PNG comes back to this process, which writes frame-0000.png, ... in
the folder, so the workers need no shared disk. A frame depends only on the project, the time
and the framing: the same files wherever they were drawn.
"""

import json
import math
import os
import sys
import time

from . import _native
from ._cluster import Bar, Session, add_where_arguments, failer, where_of
from ._render import _item

__all__ = ["run_animate", "main"]


def _frame(project_json, name, t, size, bounds):
    """A task: the PNG of the frame at time t (runs on a worker)."""
    return _item(project_json, name).frame(t, size=size, bounds=bounds)


def _union(rects):
    rects = [r for r in rects if r is not None]
    if not rects:
        return None
    return (min(r[0] for r in rects), min(r[1] for r in rects),
            max(r[2] for r in rects), max(r[3] for r in rects))


def run_animate(item, out_dir, client=None, *, fps=None, size=(900, 700), bounds=None,
                workers=None, progress=None):
    """Writes the frames of `item`'s animation into `out_dir` (frame-0000.png, ...), drawn on
    `client` (a Client; None: a local cluster; "in-process": here). Returns {"frames",
    "bounds", "seconds", "workers", "scheduler"}."""
    times = item.animation_times(fps)
    size = tuple(size)
    if bounds is None:
        bounds = _union(item.frame(t, size=size, measure=True) for t in times)
    os.makedirs(out_dir, exist_ok=True)
    digits = max(4, len(str(len(times) - 1)))
    project_json = json.dumps(item.project.to_json())
    report = progress if callable(progress) else Bar(progress or "none", "animate", "frames")
    start = time.monotonic()
    done = 0

    def write(k, png):
        nonlocal done
        with open(os.path.join(out_dir, f"frame-{k:0{digits}d}.png"), "wb") as f:
            f.write(png)
        done += 1
        report({"event": "progress", "done": done, "total": len(times),
                "elapsed": time.monotonic() - start})

    report({"event": "round", "round": 1, "points": len(times)})
    with Session(client, workers) as session:
        if session.in_process:
            for k, t in enumerate(times):
                write(k, _frame(project_json, item.name, t, size, bounds))
        else:
            from dask.distributed import as_completed
            session.futures = [session.client.submit(_frame, project_json, item.name, t, size,
                                                     bounds, pure=False, retries=2)
                               for t in times]
            index = {f.key: k for k, f in enumerate(session.futures)}
            for future in as_completed(session.futures):
                write(index[future.key], future.result())
                future.release()
            session.futures = []
        scheduler, count = session.scheduler, session.workers()
    result = {"frames": len(times), "bounds": bounds, "seconds": time.monotonic() - start,
              "workers": count, "scheduler": scheduler}
    report({"event": "done", "frames": len(times), "seconds": result["seconds"]})
    return result


def main(argv=None):
    import argparse
    from ._render import _size
    p = argparse.ArgumentParser(
        prog="python3 -m attractor_workbench.animate",
        description="The frames of an item's animation drawn on a Dask cluster (a local one of "
                    "this machine's cores, or the one at --scheduler), written as "
                    "frame-0000.png, ... into a folder: the frames attractor-cli animate draws.")
    p.add_argument("project", help="the project file (.awb)")
    p.add_argument("--item", help="the animated item (default: the first with an animation)")
    p.add_argument("--out", required=True, help="the folder of the frames (made if missing)")
    p.add_argument("--fps", type=float, help="frames per second (default: the animation's)")
    p.add_argument("--size", default="900x700", help="WIDTHxHEIGHT pixels (default 900x700)")
    add_where_arguments(p, "frame")
    args = p.parse_args(sys.argv[1:] if argv is None else argv)
    fail = failer("animate")
    try:
        size = _size(args.size)
        client, progress = where_of(args)
    except ValueError as e:
        return fail(str(e))
    if args.fps is not None and not (math.isfinite(args.fps) and 1 <= args.fps <= 120):
        return fail(f"--fps must be 1 to 120, got {args.fps}")
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        return fail(f"--out '{args.out}' is a file; the frames go into a folder")
    try:
        project = _native.open(args.project)
    except _native.Error as e:
        return fail(str(e), 1)
    try:
        if args.item:
            item = project.item(args.item)
        else:
            item = next(i for i in project.items
                        if i.to_json().get("animation", {}).get("tracks"))
    except (_native.Error, StopIteration):
        return fail(f"no item '{args.item}' in {args.project}" if args.item
                    else f"{args.project} has no animated item")
    try:
        result = run_animate(item, args.out, client=client, fps=args.fps, size=size,
                             workers=args.workers, progress=progress)
    except KeyboardInterrupt:
        return fail("cancelled; the cluster's tasks were cancelled", 130)
    except (_native.Error, RuntimeError, OSError) as e:
        return fail(str(e), 1)
    print(f"animate: {result['frames']} frames in {args.out}, {result['seconds']:.1f} s on "
          f"{result['workers']} worker(s) ({result['scheduler']})", file=sys.stderr)
    return 0
