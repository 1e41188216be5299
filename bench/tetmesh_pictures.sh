#!/usr/bin/env bash
# The pictures of docs/TETMESH.md's coarsening: the elephant's hull mesh at tau 0.2 as refined
# (--no-coarsen --surface-distance 0.5: where the coarse mode starts) and as coarsened (the
# default), each label's outer faces drawn with their edges.
#   bench/tetmesh_pictures.sh [IMAGE_DIR]     (default docs/images; needs f3d, see scripts/render.sh)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
IMAGES="${1:-$ROOT/docs/images}"
BIN="${TETMESH_BIN:-$ROOT/build/bin/tetmesh}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
"$BIN" "$ROOT/data/meshes/elephant.off" -t 0.2 -q -o "$TMP/coarse.mesh" > /dev/null
"$BIN" "$ROOT/data/meshes/elephant.off" -t 0.2 -q --no-coarsen --surface-distance 0.5 -o "$TMP/refined.mesh" > /dev/null
for name in refined coarse; do
  # The faces of one tet only (the mesh's boundary), one OBJ object per component label.
  /usr/bin/python3 - "$TMP/$name.mesh" "$TMP/$name.obj" <<'PY'
import collections, sys
lines = open(sys.argv[1]).read().split("\n")
points, tets, i = [], [], 0
while i < len(lines):
    word = lines[i].strip()
    if word in ("Vertices", "Tetrahedra"):
        n = int(lines[i + 1])
        rows = [lines[i + 2 + k].split() for k in range(n)]
        if word == "Vertices":
            points = [r[:3] for r in rows]
        else:
            tets = [list(map(int, r)) for r in rows]
        i += 2 + n
        continue
    i += 1
owners = collections.defaultdict(list)
for t in tets:
    a, b, c, d, label = t
    for f in ((a, c, b), (a, b, d), (a, d, c), (b, c, d)):  # outward for a positive tet
        owners[tuple(sorted(f))].append((label, f))
by_label = collections.defaultdict(list)
for faces in owners.values():
    if len(faces) == 1:
        by_label[faces[0][0]].append(faces[0][1])
with open(sys.argv[2], "w") as out:
    for p in points:
        out.write("v %s %s %s\n" % tuple(p))
    for label in sorted(by_label):
        out.write("o component_%d\n" % label)
        for f in by_label[label]:
            out.write("f %d %d %d\n" % f)
PY
  RENDER_EDGES=1 RENDER_RESOLUTION=900,650 RENDER_UP=+Y RENDER_AZIMUTH=30 RENDER_ELEVATION=15 RENDER_VIEW_ANGLE=24 \
    "$ROOT/scripts/render.sh" "$TMP/$name.obj" "$IMAGES/tetmesh-elephant-$name.png"
done
