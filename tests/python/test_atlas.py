"""The regularity atlas on Dask (issue 48): the four-point scheme's C^1 region is (0, omega*),
omega* = 0.19273 the real root of 32 w^3 + 4 w - 1 (Hechler, Mößner & Reif 2009), the same
rows in one process and on a real scheduler with two workers, also when one worker is killed
during the run; the six-point family (v, 0, w, 0, 1/2 - w - v, 1, ...) in two parameters on the
cluster; Ctrl+C cancels the cluster's tasks. The schedulers and workers are real processes
(dask-scheduler, dask-worker of Debian's python3-distributed)."""

import json
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import FOUR_POINT, FOUR_POINT_FILE, subprocess_env


SIX_POINT_MASK = "v, 0, w, 0, 1/2 - w - v, 1, 1/2 - w - v, 0, w, 0, v"


def omega_star():
    w = 0.2
    for _ in range(50):
        w -= (32 * w ** 3 + 4 * w - 1) / (96 * w * w + 4)
    return w


def summary(result):
    return [(tuple(r["params"].values()), r["lower"], r["upper"], r["exact"], r["verdict"])
            for r in result["rows"]]


@pytest.fixture(scope="module")
def four_point_in_process(awb):
    item = awb.open(FOUR_POINT_FILE).item(FOUR_POINT)
    return awb.atlas(item, {"omega": (0.0, 0.25, 11)}, client="in-process", tolerance=1e-5)


def test_four_point_region_is_zero_to_omega_star(four_point_in_process):
    result = four_point_in_process
    assert result["workers"] == 1 and result["scheduler"] == "in-process"
    (run,) = result["runs"]
    # omega = 0 is piecewise linear (r = 1 exactly): the region opens at 0.
    assert run["from"]["outer"] == 0.0 and 0 < run["from"]["inner"] <= 1e-5
    star = omega_star()
    assert abs(star - 0.19273) < 5e-6
    lo, hi = run["to"]["inner"], run["to"]["outer"]
    assert run["to"]["certified_not"]
    assert lo < star < hi and hi - lo <= 1e-5, (lo, hi)
    assert abs(lo - 0.19273) < 1e-5
    rows = result["rows"]
    assert rows == sorted(rows, key=lambda r: r["params"]["omega"])
    for r in rows:
        w = r["params"]["omega"]
        if 1e-5 < w < star - 1e-5:
            assert r["verdict"] == 1 and r["lower"] > 1, r
        if w > star + 1e-5:
            assert r["verdict"] == -1, r


@pytest.mark.subprocess
def test_same_rows_on_a_cluster_with_a_worker_killed(awb, scheduler, four_point_in_process):
    item = awb.open(FOUR_POINT_FILE).item(FOUR_POINT)
    scheduler.wait_for_workers(2, timeout=60)
    pids = scheduler.run(os.getpid)
    assert len(pids) == 2
    killed = []

    def progress(event):
        # During the second round (the brackets' points; those near omega = 0 take a second
        # each), kill one worker outright: its tasks must run on the other.
        if event["event"] == "progress" and event["round"] == 2 and not killed:
            victim = sorted(pids.values())[0]
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    result = awb.atlas(item, {"omega": (0.0, 0.25, 11)}, client=scheduler, tolerance=1e-5,
                       progress=progress)
    assert killed
    assert result["scheduler"] == scheduler.scheduler.address
    assert summary(result) == summary(four_point_in_process)
    assert result["runs"] == four_point_in_process["runs"]


@pytest.mark.subprocess
def test_six_point_plane_on_the_cluster(awb, scheduler, tmp_path):
    project = awb.Project()
    item = project.add({"type": "subdivision-curve", "name": "six-point",
                        "scheme": {"kind": "mask", "arity": 2, "offset": -5,
                                   "mask": ["3/256", 0, "-25/256", 0, "75/128", 1, "75/128",
                                            0, "-25/256", 0, "3/256"]},
                        "control_points": [[0, 0], [1, 2], [2, 1], [3, 3], [4, 0], [5, 1],
                                           [6, 2], [7, 0], [8, 1], [9, 0], [10, 2], [11, 1]]})
    grid = {"w": (-0.5, 0.0, 3), "v": (-0.02, 0.02, 3)}
    scheduler.wait_for_workers(2, timeout=60)
    result = awb.atlas(item, grid, client=scheduler, mask=SIX_POINT_MASK, refine=1, work=2e4)
    assert result["rounds"] == 2 and result["points"] > 9
    assert result["runs"] == []   # two parameters: a map, not intervals
    by_point = {tuple(r["params"].values()): r for r in result["rows"]}
    # v = 0, w = -1/8: the four-point scheme with omega = 1/8 (C^1, r = 1.385).
    four = by_point[(-0.125, 0.0)]
    assert four["smoothness"] == "C^1" and abs(four["lower"] - 1.38517) < 1e-4
    # The same family member evaluated alone gives the same row (rows are reproducible).
    family = awb.Family(item, ["w", "v"], SIX_POINT_MASK)
    alone = family.evaluate([-0.125, 0.0], result["options"])
    assert alone["lower"] == four["lower"] and alone["upper"] == four["upper"]
    # Dubuc-Deslauriers' six-point scheme (w = -25/256, v = 3/256) is C^2 (Hölder 2.83).
    dd = family.evaluate([-25 / 256, 3 / 256], {"smoothness": 2})
    assert dd["smoothness"] == "C^2" and dd["verdict"] == 1 and 2.8 < dd["lower"] < 2.84


def test_family_pickles_and_refuses(awb, curve):
    import pickle
    family = awb.Family(curve, "omega")
    again = pickle.loads(pickle.dumps(family))
    assert again.to_json() == family.to_json()
    assert again.evaluate([1 / 16])["lower"] == family.evaluate([1 / 16])["lower"]
    with pytest.raises(awb.Error, match="no parameter 'w'"):
        awb.Family(curve, "w")
    with pytest.raises(awb.Error, match="expected 1 values"):
        family.evaluate([0.1, 0.2])
    with pytest.raises(awb.Error, match="unknown atlas option 'speed'"):
        family.evaluate([0.1], {"speed": 3})
    with pytest.raises(awb.Error, match="from < to"):
        awb.atlas(curve, {"omega": (0.3, 0.1, 5)}, client="in-process")
    with pytest.raises(awb.Error, match="not the family's"):
        awb.atlas(family, {"w": (0.0, 0.1, 5)}, client="in-process")


def run_module(*args, timeout=120):
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    return subprocess.run([sys.executable, "-m", "attractor_workbench.atlas", *map(str, args)],
                          capture_output=True, text=True, env=env, timeout=timeout)


@pytest.mark.subprocess
def test_command_line(tmp_path, scheduler):
    scheduler.wait_for_workers(2, timeout=60)
    out = tmp_path / "atlas.json"
    done = run_module(FOUR_POINT_FILE, "--item", FOUR_POINT, "--grid", "omega=0.1:0.25:7",
                      "--tolerance", "1e-4", "--scheduler", scheduler.scheduler.address,
                      "--json", out)
    assert done.returncode == 0, done.stderr
    result = json.loads(out.read_text())
    assert result["item"] == FOUR_POINT and result["workers"] == 2
    (run,) = result["runs"]
    assert run["from"]["range_end"] and abs(run["to"]["inner"] - 0.19273) < 1e-4
    assert "C^1 from 0.1 (the grid's end) to [0.19" in done.stderr
    for args, message in [
        (["--grid", "omega=0:1"], "expected NAME=FROM:TO:COUNT"),
        (["--grid", "omega=0:1:x"], "COUNT a whole number"),
        (["--grid", "omega=0:1:5", "--grid", "omega=0:1:5"], "given twice"),
        (["--grid", "w=0:1:5"], "no parameter 'w'"),
        (["--grid", "omega=0:1:1"], "2 to 100000 values"),
        (["--grid", "omega=0:1:5", "--item", "nothing"], "no item 'nothing'"),
        (["--grid", "omega=0:1:5", "--workers", "0"], "--workers must be 1 to 1024"),
    ]:
        bad = run_module(FOUR_POINT_FILE, *args, "--in-process", "--json", tmp_path / "x.json")
        if "--workers" in args:
            bad = run_module(FOUR_POINT_FILE, *args, "--json", tmp_path / "x.json")
        assert bad.returncode in (1, 2) and message in bad.stderr, (args, bad.stderr)


@pytest.mark.subprocess
def test_ctrl_c_cancels_the_cluster(tmp_path, scheduler):
    """SIGINT during a run: exit 130 at once, and the scheduler has no task of it left."""
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    proc = subprocess.Popen([sys.executable, "-m", "attractor_workbench.atlas", FOUR_POINT_FILE,
                             "--grid", "omega=0.1:0.18:50000",
                             "--scheduler", scheduler.scheduler.address, "--progress", "jsonl",
                             "--json", tmp_path / "never.json"],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = json.loads(proc.stdout.readline())
    assert first["event"] == "round" and first["points"] == 50000
    time.sleep(1.0)
    start = time.monotonic()
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "cancelled" in err
    assert time.monotonic() - start < 20
    assert not (tmp_path / "never.json").exists()
    # The cancelled tasks leave the scheduler.
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        tasks = scheduler.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks))
        if tasks == 0:
            break
        time.sleep(0.5)
    assert tasks == 0
    # (The workers finish the task they had begun, at most 8 points: here milliseconds.)
