#!/usr/bin/env bash
# Render a mesh (.off or .obj) to a PNG off-screen with f3d under Xvfb.
#
#   scripts/render.sh MESH_OR_OBJ OUT.png
#
# An OBJ with several `o` objects (one per convex hull / component) gets one
# distinct colour per object; an OFF file or a single-object OBJ gets one
# colour. The input is never modified: a temporary OBJ + material file is
# written, since f3d colours OBJ parts only by material (it reads FILE.obj.mtl).
#
# Optional environment: RENDER_RESOLUTION (default 1200,900),
# RENDER_AZIMUTH (default 30), RENDER_ELEVATION (default 20),
# RENDER_UP (default +Y), RENDER_BG (default 1,1,1 = white),
# RENDER_VIEW_ANGLE (degrees, default 30; smaller zooms in),
# RENDER_EDGES=1 to draw triangle edges.
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 MESH_OR_OBJ OUT.png" >&2
    exit 2
fi
IN="$1"
OUT="$2"
[[ -f "$IN" ]] || { echo "render: no such file: $IN" >&2; exit 1; }
command -v f3d >/dev/null 2>&1 || { echo "render: f3d is not installed (apt-get install f3d xvfb xauth)" >&2; exit 1; }
PY="$(command -v python3 || true)"
[[ -n "$PY" ]] || { echo "render: python3 is required" >&2; exit 1; }

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
OBJ="$TMP/model.obj"

"$PY" - "$IN" "$OBJ" <<'PYEOF'
import colorsys, os, sys

src, dst = sys.argv[1], sys.argv[2]

def palette(n):
    # Well-separated hues (golden-ratio steps), alternating lightness/saturation.
    cols = []
    for i in range(n):
        h = (0.02 + i * 0.618033988749895) % 1.0
        s = 0.70 if i % 2 == 0 else 0.55
        v = 0.92 if (i // 2) % 2 == 0 else 0.75
        cols.append(colorsys.hsv_to_rgb(h, s, v))
    return cols

def read_off(path):
    toks = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].strip()
            if line:
                toks.append(line.split())
    head = toks[0]
    if head[0].upper().endswith('OFF'):
        rest = head[1:]
        toks = toks[1:]
        if rest:
            toks.insert(0, rest)
    nv, nf = int(toks[0][0]), int(toks[0][1])
    verts = [tuple(t[:3]) for t in toks[1:1 + nv]]
    faces = []
    for t in toks[1 + nv:1 + nv + nf]:
        k = int(t[0])
        faces.append([int(x) for x in t[1:1 + k]])
    return verts, faces

out = []
if src.lower().endswith('.off'):
    verts, faces = read_off(src)
    out.append('o mesh\nusemtl c0\n')
    out.extend('v %s %s %s\n' % v for v in verts)
    out.extend('f ' + ' '.join(str(i + 1) for i in fc) + '\n' for fc in faces)
    nobj = 1
else:
    with open(src) as f:
        lines = f.readlines()
    # Colour by `o` objects; if there are none, by `g` groups; else one colour.
    key = 'o' if any(l.startswith('o ') or l.strip() == 'o' for l in lines) else \
          ('g' if any(l.startswith('g ') for l in lines) else None)
    nobj = 0
    if key is None:
        out.append('usemtl c0\n')
        nobj = 1
    for l in lines:
        w = l.split(None, 1)
        if not w or w[0] in ('mtllib', 'usemtl'):
            continue
        out.append(l if l.endswith('\n') else l + '\n')
        if w[0] == key:
            out.append('usemtl c%d\n' % nobj)
            nobj += 1
    nobj = max(nobj, 1)

cols = palette(nobj) if nobj > 1 else [(0.80, 0.62, 0.42)]
mtl = []
for i, (r, g, b) in enumerate(cols):
    mtl.append('newmtl c%d\nKa %.3f %.3f %.3f\nKd %.3f %.3f %.3f\nKs 0.05 0.05 0.05\nNs 10\nillum 2\n\n'
               % (i, 0.25 * r, 0.25 * g, 0.25 * b, r, g, b))
base = os.path.splitext(os.path.basename(dst))[0]
with open(dst, 'w') as f:
    f.write('mtllib %s.mtl\n' % base)
    f.writelines(out)
# f3d 1.3 reads FILE.obj.mtl; other viewers follow mtllib.
for name in (dst + '.mtl', os.path.join(os.path.dirname(dst), base + '.mtl')):
    with open(name, 'w') as f:
        f.writelines(mtl)
print('render: %d object(s)' % nobj, file=sys.stderr)
PYEOF

ARGS=(
    "$OBJ"
    "--output=$TMP/out.png"
    "--resolution=${RENDER_RESOLUTION:-1200,900}"
    "--camera-azimuth-angle=${RENDER_AZIMUTH:-30}"
    "--camera-elevation-angle=${RENDER_ELEVATION:-20}"
    "--up=${RENDER_UP:-+Y}"
    "--bg-color=${RENDER_BG:-1,1,1}"
    --fxaa --dry-run --quiet
)
[[ "${RENDER_EDGES:-0}" == 1 ]] && ARGS+=(--edges)
[[ -n "${RENDER_VIEW_ANGLE:-}" ]] && ARGS+=("--camera-view-angle=${RENDER_VIEW_ANGLE}")

if [[ -z "${DISPLAY:-}" ]] && command -v xvfb-run >/dev/null 2>&1; then
    xvfb-run -a -s "-screen 0 1920x1080x24" f3d "${ARGS[@]}"
else
    f3d "${ARGS[@]}"
fi
[[ -s "$TMP/out.png" ]] || { echo "render: f3d produced no image" >&2; exit 1; }
mkdir -p "$(dirname "$OUT")"
mv -f "$TMP/out.png" "$OUT"
echo "render: wrote $OUT"
