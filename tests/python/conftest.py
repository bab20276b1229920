"""Shared fixtures of the attractor_workbench Python tests (pytest 7).

Run from the source tree, after the build (bash scripts/test.sh or scripts/main.sh):

    PYTHONPATH=build/python AWB_CLI=build/bin/attractor-cli AWB_SOURCE=$PWD \
        /usr/bin/python3 -m pytest -q tests/python

AWB_SOURCE is the source tree (default: two folders above this file), AWB_CLI the command-line
tool (default: AWB_SOURCE/build/bin/attractor-cli), and the module is imported from PYTHONPATH
(default: AWB_SOURCE/build/python). Tests write files only into pytest's tmp_path.
"""

import io
import json
import math
import os
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

SOURCE = Path(os.environ.get("AWB_SOURCE") or Path(__file__).resolve().parents[2]).resolve()
CLI = Path(os.environ.get("AWB_CLI") or SOURCE / "build" / "bin" / "attractor-cli").resolve()
MODULE_DIR = SOURCE / "build" / "python"
EXAMPLES = SOURCE / "examples"

try:
    import attractor_workbench  # noqa: F401
except ImportError:
    sys.path.insert(0, str(MODULE_DIR))
    import attractor_workbench  # noqa: F401

FOUR_POINT_FILE = EXAMPLES / "000-fig05-four-point-from-segment.awb"
FOUR_POINT = "000 Fig. 5: four-point scheme from a segment"
KOCH_FILE = EXAMPLES / "001-fig06-koch-curve.awb"
BSPLINE_FILE = EXAMPLES / "000-fig02-cubic-bspline-from-point.awb"


def module_path():
    """Where the imported package lives (for subprocesses: their PYTHONPATH)."""
    return str(Path(attractor_workbench.__file__).resolve().parents[1])


def subprocess_env():
    """The environment of a child Python: the same module, no display needed."""
    env = dict(os.environ)
    parts = [module_path()] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join(parts)
    env.setdefault("QT_QPA_PLATFORM", "offscreen")
    env["AWB_SOURCE"] = str(SOURCE)
    env["AWB_CLI"] = str(CLI)
    return env


def run_cli(*args, check=True):
    """Runs attractor-cli with `args`; returns the CompletedProcess (text)."""
    if not CLI.exists():
        pytest.skip(f"attractor-cli not found at {CLI} (set AWB_CLI)")
    # The sanitizer build's CLI has its own runtime linked in: not the one preloaded into
    # Python (tests/CMakeLists.txt).
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    result = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True,
                            env=env, timeout=300)
    if check and result.returncode != 0:
        raise AssertionError(f"attractor-cli {' '.join(map(str, args))} failed "
                             f"({result.returncode}): {result.stderr}")
    return result


def cli_points(path, item, *options):
    """`attractor-cli points --csv` as an (N, columns) array: x, y[, z], map, view."""
    out = run_cli("points", path, "--item", item, "--csv", *options).stdout
    return np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1, ndmin=2)


def json_diff(a, b, rel=1e-9, abs_tol=1e-12, path="", ignore=("seconds",)):
    """The differences of two JSON values (numbers to `rel`), as a list of strings."""
    out = []
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) - set(ignore) != set(b) - set(ignore):
            out.append(f"{path}: keys {sorted(set(a) ^ set(b))}")
        for k in sorted(set(a) & set(b)):
            if k not in ignore:
                out += json_diff(a[k], b[k], rel, abs_tol, f"{path}.{k}", ignore)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{path}: lengths {len(a)} != {len(b)}")
        else:
            for i, (x, y) in enumerate(zip(a, b)):
                out += json_diff(x, y, rel, abs_tol, f"{path}[{i}]", ignore)
    elif (isinstance(a, (int, float)) and isinstance(b, (int, float))
          and not isinstance(a, bool) and not isinstance(b, bool)):
        if not math.isclose(a, b, rel_tol=rel, abs_tol=abs_tol):
            out.append(f"{path}: {a!r} != {b!r}")
    elif a != b:
        out.append(f"{path}: {a!r:.80} != {b!r:.80}")
    return out


def json_round_trip(value):
    return json.loads(json.dumps(value))


def pytest_configure(config):
    config.addinivalue_line("markers", "subprocess: runs a child Python or attractor-cli")


@pytest.fixture(scope="session")
def awb():
    return attractor_workbench


@pytest.fixture(scope="session")
def source():
    return SOURCE


@pytest.fixture(scope="session")
def examples():
    return EXAMPLES


@pytest.fixture
def four_point(awb):
    """The four-point example (000 Fig. 5), freshly opened: a Project."""
    return awb.open(FOUR_POINT_FILE)


@pytest.fixture
def curve(four_point):
    """Its subdivision curve: an Item."""
    return four_point.item(FOUR_POINT)


@pytest.fixture
def koch(awb):
    return awb.open(KOCH_FILE)


@pytest.fixture
def child_python():
    """Runs a Python snippet in a child interpreter (same module); returns CompletedProcess."""
    def run(code, *args, timeout=120, cwd=None):
        return subprocess.run([sys.executable, "-c", code, *map(str, args)],
                              capture_output=True, text=True, env=subprocess_env(),
                              timeout=timeout, cwd=cwd)
    return run


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="session")
def scheduler(tmp_path_factory):
    """A real Dask scheduler and two single-threaded workers (separate processes): a client."""
    import distributed   # python3-distributed, installed by scripts/setup.sh
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    env = subprocess_env()
    env.pop("LD_PRELOAD", None)
    logs = tmp_path_factory.mktemp("dask")
    procs = [subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler",
                               "--host", "127.0.0.1", "--port", str(port),
                               "--dashboard-address", ":0", "--no-show"],
                              env=env, stdout=subprocess.DEVNULL,
                              stderr=open(logs / "scheduler.log", "w"))]
    for n in range(2):
        procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker",
                                       address, "--nthreads", "1", "--nworkers", "1",
                                       "--no-dashboard", "--name", f"w{n}"],
                                      env=env, stdout=subprocess.DEVNULL,
                                      stderr=open(logs / f"worker{n}.log", "w")))
    client = distributed.Client(address, timeout="30s")
    client.wait_for_workers(2, timeout=60)
    yield client
    client.close()
    for p in procs:
        p.terminate()
    for p in procs:
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            p.kill()
