"""Where the atlas's points and the render's chunks run (issue 48): a Dask client -- to a local
cluster of this machine's cores, or to a scheduler by address -- or this one process. Nothing
here schedules work itself: Dask does, and reruns the tasks of a lost worker elsewhere.
"""

import json
import os
import signal
import sys
import time

IN_PROCESS = "in-process"


class Bar:
    """A progress bar on a terminal (stderr), or JSON lines (for the window), or nothing."""

    def __init__(self, mode, name="atlas", unit="points", stream=sys.stderr):
        self.mode = mode
        self.name = name
        self.unit = unit
        self.stream = stream
        self.last = 0.0

    def __call__(self, event):
        if self.mode == "jsonl":
            print(json.dumps(event), file=sys.stdout, flush=True)
        elif self.mode == "bar" and event["event"] == "progress":
            now = time.monotonic()
            if now - self.last < 0.1 and event["done"] < event["total"]:
                return
            self.last = now
            width = 30
            filled = int(width * event["done"] / max(1, event["total"]))
            round_text = f"round {event['round']} " if "round" in event else ""
            total = f"{event['rows']} in all, " if "rows" in event else ""
            self.stream.write(f"\r{self.name}: {round_text}"
                              f"[{'#' * filled}{'.' * (width - filled)}] "
                              f"{event['done']}/{event['total']} {self.unit}, "
                              f"{total}{event['elapsed']:.1f} s ")
            if event["done"] == event["total"]:
                self.stream.write("\n")
            self.stream.flush()


def client_for(client, workers):
    """(client, owned cluster or None): an existing client, one to an address, or a local one."""
    if client is not None and not isinstance(client, str):
        return client, None
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise RuntimeError("a cluster needs Dask (Debian: python3-distributed); "
                           "without it, run it in this process (--in-process, or "
                           "client=\"in-process\")") from None
    if isinstance(client, str):
        return Client(client, timeout="20s"), None
    n = workers or os.cpu_count() or 1
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                           dashboard_address=None, silence_logs=40)
    return Client(cluster), cluster


def worker_count(client):
    try:
        return max(1, len(client.scheduler_info().get("workers", {})))
    except Exception:  # noqa: BLE001 - the count only sizes the tasks
        return 1


class Session:
    """Where one run's tasks go: `client` a Client, an address, None (a local cluster of
    `workers` processes, default one per core) or IN_PROCESS. As a context manager it cancels
    the tasks in `futures` when the run stops early (Ctrl+C, an error) and closes a cluster it
    started."""

    def __init__(self, client, workers=None):
        self.in_process = isinstance(client, str) and client == IN_PROCESS
        self.client, self.cluster = (None, None) if self.in_process else client_for(client,
                                                                                     workers)
        self.scheduler = IN_PROCESS if self.in_process else self.client.scheduler.address
        self.futures = []

    def workers(self):
        return 1 if self.in_process else worker_count(self.client)

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        try:
            if kind is not None and self.futures:
                try:
                    self.client.cancel(self.futures, force=True)
                except Exception:  # noqa: BLE001 - the cluster may be gone already
                    pass
        finally:
            if self.cluster is not None:
                self.client.close()
                self.cluster.close()
        return False


def add_where_arguments(parser, unit="point"):
    """--scheduler | --workers | --in-process, and --progress: the same in every command."""
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--workers", type=int, metavar="K",
                       help="a local cluster of K worker processes (default: one per core)")
    where.add_argument("--in-process", action="store_true",
                       help=f"no cluster: every {unit} in this process, one after another")
    parser.add_argument("--progress", choices=["bar", "jsonl", "none"],
                        help="a bar on the terminal (default when stderr is one), JSON lines "
                             "on standard output (for a program: the window), or none")


def where_of(args):
    """(client, progress) of the parsed arguments; ValueError for a bad --workers. SIGTERM
    (the window's Cancel) then stops the run as Ctrl+C does."""
    if args.workers is not None and not 1 <= args.workers <= 1024:
        raise ValueError(f"--workers must be 1 to 1024, got {args.workers}")
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    progress = args.progress or ("bar" if sys.stderr.isatty() else "none")
    return (IN_PROCESS if args.in_process else args.scheduler), progress


def failer(command):
    """fail(message, code=2): the command's message on stderr, and its exit status."""
    def fail(message, code=2):
        print(f"{command}: {message}", file=sys.stderr)
        return code
    return fail
