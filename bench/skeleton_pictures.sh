#!/usr/bin/env bash
# Pictures for docs/SKELETON.md: each model and its deformed versions side by side, the model
# translucent and its skeleton (thin tubes) inside, once for the ACD skeleton and once for
# CGAL's mean-curvature-flow skeleton. Needs the output of bench/skeleton_table.sh (run with
# --tubes) and f3d + xvfb.
#
#   bench/skeleton_pictures.sh [TABLE_OUT (default out/skeleton)] [IMAGES (default docs/images)]
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
IN="${1:-$ROOT/out/skeleton}"
IMAGES="${2:-$ROOT/docs/images}"
command -v f3d >/dev/null 2>&1 || { echo "skeleton_pictures: f3d is not installed" >&2; exit 1; }
mkdir -p "$IMAGES"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

for model in elephant camel armadillo; do
    # The camel's length runs along z: turn it a quarter about y so that it is seen from the side.
    turn=0
    [[ $model == camel ]] && turn=1
    for kind in acd mcf; do
        /usr/bin/python3 - "$ROOT/data/meshes/$model.off" "$IN/$model" "$kind" "$TMP/scene.obj" "$turn" <<'PYEOF'
import glob, os, sys

original, folder, kind, dst, turn = sys.argv[1:6]

def read_off(path):
    toks = [l.split() for l in open(path) if l.strip() and not l.startswith('#')]
    if toks[0][0] == 'OFF' and len(toks[0]) > 1:
        toks[0:1] = [['OFF'], toks[0][1:]]
    nv, nf = int(toks[1][0]), int(toks[1][1])
    verts = [[float(x) for x in t[:3]] for t in toks[2:2 + nv]]
    faces = [[int(x) for x in t[1:1 + int(t[0])]] for t in toks[2 + nv:2 + nv + nf]]
    if turn == '1':
        verts = [[v[2], v[1], -v[0]] for v in verts]
    return verts, faces

names = ['original'] + sorted(os.path.basename(p)[:-4] for p in glob.glob(folder + '/deformed_*.off')
                              if not p.endswith('_tubes.off'))
out, base, shift = ['mtllib scene.mtl\n'], 0, 0.0
for name in names:
    model = read_off(original if name == 'original' else '%s/%s.off' % (folder, name))
    tubes = read_off('%s/%s.%s_skeleton_tubes.off' % (folder, name, kind))
    lo = min(v[0] for v in model[0])
    hi = max(v[0] for v in model[0])
    dx = shift - lo   # place the models left to right along x, a tenth of a width apart
    for label, (verts, faces), mat in (('model', model, 'skin'), ('skeleton', tubes, 'bone')):
        out.append('o %s_%s\nusemtl %s\n' % (name, label, mat))
        out.extend('v %.6g %.6g %.6g\n' % (v[0] + dx, v[1], v[2]) for v in verts)
        out.extend('f ' + ' '.join(str(i + 1 + base) for i in f) + '\n' for f in faces)
        base += len(verts)
    shift += (hi - lo) * 1.1
mtl = ('newmtl skin\nKa 0.2 0.15 0.1\nKd 0.80 0.62 0.42\nd 0.3\n\n'
       'newmtl bone\nKa 0.02 0.04 0.15\nKd 0.10 0.25 0.85\nd 1\n')
open(dst, 'w').writelines(out)
for name in (dst + '.mtl', os.path.join(os.path.dirname(dst), 'scene.mtl')):
    open(name, 'w').write(mtl)
PYEOF
        xvfb-run -a -s "-screen 0 1920x1080x24" f3d "$TMP/scene.obj" --output="$IMAGES/skeleton-$model-$kind.png" \
            --resolution=1800,520 --up=+Y --camera-azimuth-angle=0 --camera-elevation-angle=10 --camera-view-angle=13 \
            --bg-color=1,1,1 --depth-peeling >/dev/null 2>&1
        echo "wrote $IMAGES/skeleton-$model-$kind.png"
    done
done
