"""Reference graph edit distances from networkx, for skeleton_tests.

Input (stdin): one graph pair per line, "n1 u-v,u-v,... | n2 u-v,..." (edge list may be empty).
Output: one exact distance per line (networkx's default unit costs), or "timeout" when networkx
did not finish in time (its answer would then not be proven exact).
Exit code 3 when networkx cannot be imported.
"""
import sys
import time

try:
    import networkx as nx
except ImportError:
    sys.exit(3)

LIMIT = 30.0


def parse(part):
    fields = part.split()
    g = nx.Graph()
    g.add_nodes_from(range(int(fields[0])))
    if len(fields) > 1:
        for e in fields[1].split(","):
            a, b = e.split("-")
            g.add_edge(int(a), int(b))
    return g


for line in sys.stdin:
    line = line.strip()
    if not line:
        continue
    left, right = line.split("|")
    start = time.monotonic()
    d = nx.graph_edit_distance(parse(left), parse(right), timeout=LIMIT)
    finished = time.monotonic() - start < LIMIT
    print(int(d) if finished and d is not None else "timeout", flush=True)
