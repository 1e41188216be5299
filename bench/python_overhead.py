#!/usr/bin/python3
"""The Python binding's overhead against the acd command, over the corpus.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--tau 0.05] [--repeat 5]
        [--threads 1] [--models "elephant armadillo ..."] [--acd build/bin/acd]

For every model, alternately (so that drift of the shared machine hits both alike), REPEAT times:
  CLI      `acd decompose data/meshes/MODEL.off -t TAU --threads N -q -o TMP`, wall clock of the process
           (start-up, reading, decomposition, writing components, hulls.obj and report.json);
  binding  `acd.decompose("data/meshes/MODEL.off", tau=TAU, threads=N)` in this process, wall clock of
           the call (reading, decomposition, numpy arrays and the report dict).
Medians are reported, with each side's own library time (report timing.total_seconds), and the
ratio binding / CLI. A single thread by default: the overhead is what is measured, not how two
cores are shared with other work. Prints a Markdown table; the interpreter's start-up and
`import acd` are timed once and shown under it.
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time
import warnings

ROOT = pathlib.Path(__file__).resolve().parents[1]
MODELS = "elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tau", type=float, default=0.05)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--models", default=MODELS)
    parser.add_argument("--acd", default=str(ROOT / "build" / "bin" / "acd"))
    args = parser.parse_args()

    start = time.perf_counter()
    import acd  # noqa: E402  (timed)
    import_seconds = time.perf_counter() - start
    startup = []
    for _ in range(5):  # a fresh interpreter that imports acd: what a script pays once
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", "import acd"], check=True)
        startup.append(time.perf_counter() - t0)
    rows, ratios, totals = [], [], [0.0, 0.0]
    with tempfile.TemporaryDirectory() as tmp:
        for model in args.models.split():
            path = ROOT / "data" / "meshes" / f"{model}.off"
            cli_times, py_times, cli_lib, py_lib = [], [], [], []
            report = None
            for r in range(args.repeat):
                print(f"[python_overhead] {model} run {r + 1}/{args.repeat}", file=sys.stderr)
                out = pathlib.Path(tmp) / model
                t0 = time.perf_counter()
                p = subprocess.run([args.acd, "decompose", str(path), "-t", str(args.tau), "--threads",
                                    str(args.threads), "-q", "-o", str(out)], capture_output=True, text=True)
                cli_times.append(time.perf_counter() - t0)
                if p.returncode not in (0, 4):
                    raise SystemExit(f"{model}: acd exited with {p.returncode}: {p.stderr.strip()}")
                cli_report = json.loads((out / "report.json").read_text())
                cli_lib.append(cli_report["timing"]["total_seconds"])
                t0 = time.perf_counter()
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    result = acd.decompose(str(path), tau=args.tau, threads=args.threads)
                py_times.append(time.perf_counter() - t0)
                py_lib.append(result.report["timing"]["total_seconds"])
                report = result.report
                assert report["totals"]["components"] == cli_report["totals"]["components"]
            c, b = statistics.median(cli_times), statistics.median(py_times)
            ratios.append(b / c)
            totals[0] += c
            totals[1] += b
            rows.append(f"| {model} | {report['input']['faces']} | {report['totals']['components']} | {c:.3f} | "
                        f"{statistics.median(cli_lib):.3f} | {b:.3f} | {statistics.median(py_lib):.3f} | "
                        f"{b / c:.3f} |")
    print(f"τ = {args.tau}, {args.threads} thread(s), median of {args.repeat} alternating runs per side\n")
    print("| model | faces | components | CLI wall (s) | CLI library (s) | binding call (s) | binding library (s) "
          "| binding / CLI |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    print("\n".join(rows))
    print(f"| **total** | | | {totals[0]:.3f} | | {totals[1]:.3f} | | {totals[1] / totals[0]:.3f} |")
    print(f"\nmedian ratio over the models {statistics.median(ratios):.3f}; `import acd` {import_seconds * 1000:.0f} ms; "
          f"`{sys.executable} -c 'import acd'` {statistics.median(startup) * 1000:.0f} ms (median of 5); "
          f"module {acd.__file__}")


if __name__ == "__main__":
    main()
