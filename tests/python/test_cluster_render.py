"""Huge renders on Dask (issue 48): the samples split into chunks, each Item.density from its
own seed, summed in chunk order; the result is the same array in one process and on a real
scheduler with two workers, also when a worker is killed during the run; one chunk is
Item.density itself; the file is what render("F.exr") writes (the project in it)."""

import os
import signal
import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, subprocess_env


SIERPINSKI = EXAMPLES / "000-fig11-sierpinski-with-control-points.awb"


@pytest.fixture
def gasket(awb):
    return awb.open(SIERPINSKI).items[0]


def test_chunk_plan():
    from attractor_workbench.render import chunk_plan
    plan = chunk_plan(10, 7, 3)
    assert [n for n, _ in plan] == [4, 3, 3] and plan[0][1] == 7
    assert len({s for _, s in plan}) == 3
    assert chunk_plan(1e9, 1) == chunk_plan(1e9, 1, 4)   # 2.5e8 samples per chunk
    with pytest.raises(ValueError, match="chunks must be 1 to 5"):
        chunk_plan(5, 1, 6)


def test_one_chunk_is_item_density(awb, gasket):
    alone = gasket.density(size=(200, 150), samples=1e6, seed=3)
    result = awb.render_density(gasket, 1e6, client="in-process", size=(200, 150), seed=3,
                                chunks=1)
    assert result["chunks"] == 1 and result["world"] == alone["world"]
    assert np.array_equal(result["rgba"], alone["rgba"].astype(np.float64))
    assert result["rgba"][..., 3].sum() == 1e6   # every sample lands in the frame


@pytest.mark.subprocess
def test_same_density_on_a_cluster_with_a_worker_killed(awb, gasket, scheduler, tmp_path):
    scheduler.wait_for_workers(2, timeout=60)
    here = awb.render_density(gasket, 4e7, client="in-process", size=(240, 180), chunks=16)
    pids = scheduler.run(os.getpid)
    killed = []

    def progress(event):
        if event["event"] == "progress" and event["done"] >= 2 and not killed:
            os.kill(sorted(pids.values())[0], signal.SIGKILL)
            killed.append(True)

    there = awb.render_density(gasket, 4e7, out=tmp_path / "gasket.png", client=scheduler,
                               size=(240, 180), chunks=16, progress=progress)
    assert killed and there["workers"] >= 1
    assert there["world"] == here["world"]
    assert np.array_equal(there["rgba"], here["rgba"])
    assert there["rgba"][..., 3].sum() == 4e7
    # The 16-bit density PNG carries the project, as render(..., bits 16) writes it.
    assert awb.open(tmp_path / "gasket.png").items[0].name == gasket.name


def run_module(*args):
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    return subprocess.run([sys.executable, "-m", "attractor_workbench.render", *map(str, args)],
                          capture_output=True, text=True, env=env, timeout=120)


@pytest.mark.subprocess
def test_command_line(tmp_path, scheduler):
    scheduler.wait_for_workers(2, timeout=60)
    out = tmp_path / "gasket.png"
    done = run_module(SIERPINSKI, "--samples", "2e7", "--chunks", "4", "--size", "300x200",
                      "--scheduler", scheduler.scheduler.address, "--out", out)
    assert done.returncode == 0, done.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "20000000 samples in 4 chunks" in done.stderr and "2 worker(s)" in done.stderr
    for args, message in [
        (["--samples", "1e20"], "--samples must be a whole number"),
        (["--samples", "1e6", "--size", "10x10"], "16 to 20000 pixels"),
        (["--samples", "5", "--chunks", "6"], "chunks must be 1 to 5"),
        (["--samples", "1e6", "--out", tmp_path / "x.jpg"], "written to .exr or .png"),
        (["--samples", "1e6", "--item", "nothing"], "no item 'nothing'"),
    ]:
        if "--out" not in args:
            args = args + ["--out", tmp_path / "x.exr"]
        bad = run_module(SIERPINSKI, *args, "--in-process")
        assert bad.returncode in (1, 2) and message in bad.stderr, (args, bad.stderr)
    # A surface is drawn in space: its raw density is refused with the renderer's reason.
    bad = run_module(EXAMPLES / "000-fig06-bicubic-patch.awb", "--samples", "1e5",
                     "--in-process", "--out", tmp_path / "x.exr")
    assert bad.returncode == 1 and "drawn in space" in bad.stderr, bad.stderr


ANIMATION = EXAMPLES / "animation-four-point-omega-and-complex-t.awb"


@pytest.mark.subprocess
def test_animation_frames_on_a_cluster(awb, scheduler, tmp_path):
    """The frames attractor-cli animate draws, the same files from the cluster."""
    scheduler.wait_for_workers(2, timeout=60)
    project = awb.open(ANIMATION)
    item = next(i for i in project.items if i.to_json().get("animation", {}).get("tracks"))
    times = item.animation_times(fps=2)
    here = awb.animate_frames(item, tmp_path / "here", client="in-process", fps=2,
                              size=(240, 180))
    there = awb.animate_frames(item, tmp_path / "there", client=scheduler, fps=2,
                               size=(240, 180))
    assert here["frames"] == there["frames"] == len(times) >= 3
    assert here["bounds"] == there["bounds"]
    names = sorted(os.listdir(tmp_path / "here"))
    assert names == sorted(os.listdir(tmp_path / "there"))
    assert names[0] == "frame-0000.png"
    for name in names:
        assert (tmp_path / "here" / name).read_bytes() == (tmp_path / "there" / name).read_bytes()
    # Frame 1 is attractor-cli animate's frame 1 with the same framing, pixel for pixel.
    x0, y0, x1, y1 = here["bounds"]
    cli = tmp_path / "cli.png"
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    done = subprocess.run([os.environ.get("AWB_CLI") or str(EXAMPLES.parent / "build" / "bin" /
                                                            "attractor-cli"),
                           "animate", ANIMATION, "--item", item.name, "--fps", "2", "--frame",
                           "1", "--size", "240x180", "--bounds", f"{x0},{y0},{x1},{y1}",
                           "--out", cli], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    mine = awb.open(tmp_path / "here" / "frame-0001.png").items[0].to_json()
    theirs = awb.open(cli).items[0].to_json()
    assert mine == theirs   # the same animated copy inside both PNGs
    with pytest.raises(awb.Error, match="has no animation"):
        awb.open(SIERPINSKI).items[0].animation_times()
