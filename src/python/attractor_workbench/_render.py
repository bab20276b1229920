"""Huge renders on a Dask cluster (issue 48): the samples of a random-iteration picture split
into chunks, each a render of the item's raw density (Item.density, the path of
`attractor-cli render --out F.exr`) from its own seed, summed in chunk order in float64 and
written as render("F.exr") writes (float32 OpenEXR, or the 16-bit log-density PNG).

Chunk c draws its share of the samples (the first ones one more when they do not divide)
from seed_c = seed for c = 0 and (seed + 0x9E3779B97F4A7C15 * c) mod 2^62 after: the chunks
depend on the samples, the seed and the number of chunks only, so the result is the same in
one process (--in-process), on a local cluster or on any cluster, whichever worker ran which
chunk, also when a worker was lost mid-run; one chunk is Item.density itself.
"""

import hashlib
import json
import math
import os
import sys
import tempfile
import time

import numpy as np

from . import _native
from ._cluster import Bar, Session, add_where_arguments, failer, where_of

__all__ = ["chunk_plan", "run_render", "main"]

CHUNK_SAMPLES = 2.5e8   # default samples per chunk (about 2.5 s of one core)
_projects = {}          # a worker's projects, by the hash of their JSON


def chunk_plan(samples, seed, chunks=None):
    """[(samples_c, seed_c), ...]: the chunks of a render of `samples` points from `seed`."""
    samples = int(samples)
    if samples < 1:
        raise ValueError(f"the samples must be at least 1, got {samples}")
    n = chunks or max(1, math.ceil(samples / CHUNK_SAMPLES))
    if not 1 <= n <= min(100000, samples):
        raise ValueError(f"the chunks must be 1 to {min(100000, samples)}, got {n}")
    base, extra = divmod(samples, n)
    return [(base + (1 if c < extra else 0),
             seed if c == 0 else (seed + 0x9E3779B97F4A7C15 * c) % (1 << 62))
            for c in range(n)]


def _item(project_json, name):
    """The item `name` of a project given as JSON text (opened once per worker)."""
    key = hashlib.sha256(project_json.encode()).hexdigest()
    project = _projects.get(key)
    if project is None:
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "render.awb")
            with open(path, "w", encoding="utf-8") as f:
                f.write(project_json)
            project = _native.open(path)
        _projects.clear()
        _projects[key] = project
    return project.item(name)


def _render_chunk(project_json, name, size, samples, seed, threads):
    """A task: one chunk's density (runs on a worker)."""
    d = _item(project_json, name).density(size=size, samples=samples, seed=seed,
                                          threads=threads)
    return d["rgba"], d["world"], d["images"]


def run_render(item, samples, out=None, client=None, *, size=(900, 700), seed=None,
               chunks=None, workers=None, progress=None, threads=0):
    """The density of `samples` points of `item`'s attractor, rendered in chunks on `client`
    (a dask.distributed Client; None: a local cluster; "in-process": here). Returns
    {"rgba": float64 (height, width, 4), "world", "chunks", "samples", "seconds", "workers",
    "scheduler"}; with `out` (.exr or .png) also written there."""
    name = item.name
    project_json = json.dumps(item.project.to_json())
    if seed is None:
        seed = int(item.to_json().get("algorithm", {}).get("seed", 1))
    plan = chunk_plan(samples, seed, chunks)
    report = progress if callable(progress) else Bar(progress or "none", "render", "chunks")
    start = time.monotonic()
    total = None
    world = None
    done = 0

    def add(chunk):
        nonlocal total, world
        rgba, w, _ = chunk
        if world is None:
            world = w
        elif tuple(w) != tuple(world):
            raise _native.Error(f"render: chunk frames differ ({w} and {world})")
        if total is None:
            total = rgba.astype(np.float64)
        else:
            total += rgba

    def tick():
        report({"event": "progress", "done": done, "total": len(plan),
                "elapsed": time.monotonic() - start})

    report({"event": "round", "round": 1, "points": len(plan)})
    with Session(client, workers) as session:
        if session.in_process:
            for n, s in plan:
                add(_render_chunk(project_json, name, tuple(size), n, s, threads))
                done += 1
                tick()
        else:
            from dask.distributed import as_completed
            session.futures = [
                session.client.submit(_render_chunk, project_json, name, tuple(size), n, s, 1,
                                      pure=False, retries=2)
                for n, s in plan]
            index = {f.key: i for i, f in enumerate(session.futures)}
            # Summed in chunk order, whatever order they finish in: the same float64 sums.
            pending, next_index = {}, 0
            for future in as_completed(session.futures):
                pending[index[future.key]] = future.result()
                future.release()
                done += 1
                while next_index in pending:
                    add(pending.pop(next_index))
                    next_index += 1
                tick()
            session.futures = []
        scheduler, count = session.scheduler, session.workers()
    result = {"rgba": total, "world": tuple(world), "chunks": len(plan),
              "samples": int(samples), "seed": seed, "seconds": time.monotonic() - start,
              "workers": count, "scheduler": scheduler}
    if out is not None:
        _native.write_density(out, total, item, world,
                              f"{name}: {int(samples)} random points in {len(plan)} chunks")
    report({"event": "done", "chunks": len(plan), "seconds": result["seconds"]})
    return result


def _size(text):
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise ValueError(f"--size '{text}': expected WIDTHxHEIGHT, e.g. 1600x1200") from None
    if not (16 <= w <= 20000 and 16 <= h <= 20000):
        raise ValueError(f"--size '{text}': 16 to 20000 pixels each way")
    return w, h


def main(argv=None):
    import argparse
    p = argparse.ArgumentParser(
        prog="python3 -m attractor_workbench.render",
        description="A random-iteration picture of many samples rendered in chunks on a Dask "
                    "cluster (a local one of this machine's cores, or the one at --scheduler); "
                    "the chunks' densities are summed and written as .exr (float32 counts) or "
                    ".png (16-bit log density), the same wherever the chunks ran.")
    p.add_argument("project", help="the project file (.awb)")
    p.add_argument("--item", help="the item (default: the first with an attractor)")
    p.add_argument("--samples", required=True, help="random points in all, e.g. 1e11")
    p.add_argument("--out", required=True, help="the file: .exr or .png")
    p.add_argument("--size", default="900x700", help="WIDTHxHEIGHT pixels (default 900x700)")
    p.add_argument("--seed", type=int, help="the seed of chunk 0 (default: the item's)")
    p.add_argument("--chunks", type=int,
                   help=f"how many chunks (default: one per {CHUNK_SAMPLES:g} samples)")
    add_where_arguments(p, "chunk")
    args = p.parse_args(sys.argv[1:] if argv is None else argv)
    fail = failer("render")

    try:
        samples = float(args.samples)
        if not (math.isfinite(samples) and 1 <= samples <= 1e15 and samples == int(samples)):
            raise ValueError
    except ValueError:
        return fail(f"--samples must be a whole number from 1 to 1e15, got '{args.samples}'")
    try:
        size = _size(args.size)
        chunk_plan(samples, args.seed or 0, args.chunks)
        client, progress = where_of(args)
    except ValueError as e:
        return fail(str(e))
    if os.path.splitext(args.out)[1].lower() not in (".exr", ".png"):
        return fail(f"--out '{args.out}': the density is written to .exr or .png")
    try:
        project = _native.open(args.project)
    except _native.Error as e:
        return fail(str(e), 1)
    try:
        item = project.item(args.item) if args.item else next(
            i for i in project.items if i.kind not in ("eigenvalue-plot",))
    except (_native.Error, StopIteration):
        return fail(f"no item '{args.item}' in {args.project}" if args.item
                    else f"{args.project} has no item to render")
    try:
        result = run_render(item, int(samples), args.out, client=client, size=size,
                            seed=args.seed, chunks=args.chunks, workers=args.workers,
                            progress=progress)
    except KeyboardInterrupt:
        return fail("cancelled; the cluster's tasks were cancelled (no file written)", 130)
    except (_native.Error, RuntimeError, OSError) as e:
        return fail(str(e), 1)
    print(f"render: {args.out}: {int(samples)} samples in {result['chunks']} chunks, "
          f"{result['seconds']:.1f} s on {result['workers']} worker(s) ({result['scheduler']})",
          file=sys.stderr)
    return 0
