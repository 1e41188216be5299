#!/usr/bin/python3
"""The rules by which acd's parts are compared with a peer's at equal fidelity (docs/BENCHMARKS.md,
"How the comparison is scored"). Fixed before any result was looked at; tests/test_bench_scripts.py
pins them.

A series is acd's runs on one model at the fixed tau list, coarse to fine. For a peer run with
`parts` hulls and a figure (IoU: higher is better; excess: lower is better):

- acd's parts at that figure are interpolated only between two adjacent tau of the series: the
  coarsest run k from which on every finer run meets the figure, and run k - 1 before it, which
  misses it; linearly in log(parts) against the figure. Parts and figure of a run always come
  from that same run (no envelope across runs).
- When even the coarsest run meets it, acd's parts are at most that run's: the ratio is an upper
  bound, counted at its value.
- When the finest run misses it (or a later, finer run misses again up to the finest), the pair is
  not bracketed: it is a loss, counted with the ratio max(1, finest parts / peer parts).
"""
import math

LOSS = "loss"        # not bracketed: acd's finest run does not reliably meet the figure
AT_MOST = "<="       # the coarsest run already meets it: an upper bound
BRACKETED = ""


def meets(figure, value, target):
    return value <= target if figure == "excess" else value >= target


def parts_at(series, figure, target):
    """(parts, kind, runs used). `series`: dicts with tau, parts and the figure, in any order."""
    runs = sorted(series, key=lambda r: -r["tau"])
    if not runs:
        return None, LOSS, []
    k = len(runs)
    while k > 0 and meets(figure, runs[k - 1][figure], target):
        k -= 1
    if k == len(runs):
        return runs[-1]["parts"], LOSS, [runs[-1]]
    if k == 0:
        return runs[0]["parts"], AT_MOST, [runs[0]]
    lo, hi = runs[k - 1], runs[k]
    span = hi[figure] - lo[figure]
    w = (target - lo[figure]) / span if span != 0 else 1.0
    w = min(1.0, max(0.0, w))
    logp = math.log(lo["parts"]) + w * (math.log(hi["parts"]) - math.log(lo["parts"]))
    return math.exp(logp), BRACKETED, [lo, hi]


def ratio(series, figure, peer_parts, target):
    """(ratio counted, kind): acd's parts over the peer's at the peer's figure, by the rules above."""
    parts, kind, _ = parts_at(series, figure, target)
    if parts is None:
        return None, LOSS
    r = parts / peer_parts
    return (max(1.0, r), kind) if kind == LOSS else (r, kind)


def median(xs):
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def geomean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else None
