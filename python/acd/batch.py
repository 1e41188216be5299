"""acd batch on a Dask distributed cluster: one task per mesh.

    python3 -m acd.batch INPUT... -o OUT --scheduler tcp://HOST:8786 [acd batch options]
    python3 -m acd.batch INPUT... -o OUT --scheduler local:2          [acd batch options]
    python3 path/to/acd/batch.py ...     (the same; needs nothing else of the package)

The meshes, their names and the per-mesh command come from `acd batch --plan`; each Dask task
runs that command (`acd batch --worker MESH --name NAME -o OUT ...`), which decomposes the mesh in
a capped child process exactly as the local batch does, with the same cache (OUT/cache, or
--cache: a folder every host sees) and prints the mesh's JSON record. This process writes the
records to OUT/batch.jsonl as tasks finish, shows a progress bar on a terminal, then prints
`acd batch --summary` and exits with its code (0 ok, 4 some unresolved, 7 some failed).
A task whose worker process is lost (node gone, acd killed from outside) is retried
(--retries); a mesh that crashes or hits a cap is a result, recorded, not retried.
Options not listed below are passed on to `acd batch` (decomposition options, --time-limit,
--memory-limit, --threads, --cache, --retry-failed). acd must be at the same path on every
host, and OUT (and --cache) on a shared filesystem.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import time


def run_worker(command, cwd):
    """The Dask task: run one `acd batch --worker` command and return the mesh's record."""
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    lines = [line for line in done.stdout.splitlines() if line.strip()]
    if not lines:
        raise RuntimeError("acd batch --worker ended with code %d and no record: %s"
                           % (done.returncode, done.stderr.strip()[-400:]))
    record = json.loads(lines[-1])
    record["host"] = os.uname().nodename
    return record


def default_acd():
    """build/bin/acd next to this package (source or staged build tree), else acd on PATH."""
    here = os.path.dirname(os.path.abspath(__file__))
    for candidate in (os.path.join(here, "..", "..", "build", "bin", "acd"),  # python/acd in the source tree
                      os.path.join(here, "..", "..", "bin", "acd")):         # build/python/acd
        if os.access(candidate, os.X_OK):
            return os.path.normpath(candidate)
    return shutil.which("acd") or "acd"


def client_for(scheduler, threads):
    from dask.distributed import Client, LocalCluster
    if scheduler.startswith("local:"):
        workers = int(scheduler.split(":", 1)[1])
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=40)
        return Client(cluster), cluster
    return Client(scheduler), None


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m acd.batch",
        description="acd batch on a Dask distributed cluster (one task per mesh); other options go to acd batch.")
    parser.add_argument("-o", "--out", required=True, help="output folder (shared by every host)")
    parser.add_argument("--scheduler", required=True,
                        help="Dask scheduler address (tcp://HOST:8786, or a scheduler file path), "
                             "or local:N for a LocalCluster of N worker processes on this machine")
    parser.add_argument("--acd", default=default_acd(), help="the acd executable (same path on every host)")
    parser.add_argument("--retries", type=int, default=2, help="retries of a task whose worker is lost")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar and no summary table")
    ours, rest = parser.parse_known_args(argv)
    out = os.path.abspath(ours.out)

    plan = subprocess.run([ours.acd, "batch", "--plan", *rest, "-o", out], stdout=subprocess.PIPE, text=True)
    if plan.returncode != 0:
        return plan.returncode
    meshes = [json.loads(line) for line in plan.stdout.splitlines() if line.strip()]
    if not meshes:
        print("acd: batch: no meshes (.off .obj .ply .stl) in the inputs", file=sys.stderr)
        return 2

    scheduler = ours.scheduler
    if os.path.isfile(scheduler):
        from dask.distributed import Client
        client, cluster = Client(scheduler_file=scheduler), None
    else:
        client, cluster = client_for(scheduler, 1)
    start = time.monotonic()
    os.makedirs(out, exist_ok=True)
    code = 0
    try:
        from dask.distributed import as_completed
        futures = {client.submit(run_worker, m["command"], m["cwd"], key="acd-batch-%s-%d" % (m["name"], os.getpid()),
                                 retries=ours.retries, pure=False): m for m in meshes}
        bar = None
        if not ours.quiet and sys.stderr.isatty():
            try:
                from tqdm import tqdm
                bar = tqdm(total=len(meshes), unit="mesh", file=sys.stderr)
            except ImportError:
                bar = None
        with open(os.path.join(out, "batch.jsonl"), "w") as jsonl:
            for future in as_completed(futures):
                mesh = futures[future]
                try:
                    record = future.result()
                except Exception as error:  # the task itself failed on every try
                    record = {"name": mesh["name"], "input": mesh["input"], "status": "failed",
                              "error": "task failed %d times: %s" % (ours.retries + 1, error), "cached": False}
                if record.get("status") == "bad_options":  # the options, not the mesh: stop
                    for other in futures:
                        other.cancel()
                    print("acd: batch: the decomposition options were refused: %s" % record.get("error", ""),
                          file=sys.stderr)
                    code = record.get("exit_code") or 1
                    break
                jsonl.write(json.dumps(record) + "\n")
                jsonl.flush()  # an interrupted batch keeps its lines
                if bar is not None:
                    bar.update(1)
        if bar is not None:
            bar.close()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    if code:
        return code
    wall = time.monotonic() - start
    summary = subprocess.run([ours.acd, "batch", "--summary", "-o", out],
                             stdout=subprocess.DEVNULL if ours.quiet else None)
    if not ours.quiet:
        print("  wall %.1f s, %.1f meshes/min on the Dask cluster (%s)" % (wall, 60.0 * len(meshes) / wall, scheduler))
    if "--report" in rest:
        written = subprocess.run([ours.acd, "report", out])
        if written.returncode != 0:
            return written.returncode
    return summary.returncode


if __name__ == "__main__":
    sys.exit(main())
