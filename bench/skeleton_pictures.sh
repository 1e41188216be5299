#!/usr/bin/env bash
# Pictures for docs/SKELETON.md: each model and its deformed versions side by side with their
# skeletons (thin tubes) inside, once for the ACD skeleton of parts and once for CGAL's
# mean-curvature-flow skeleton. In the ACD pictures the surface is coloured by part, and a part of
# a deformed mesh takes the colour of the original's part it is matched to by shared vertices
# (grey: matched to none), so a part that stays the same keeps its colour. Needs the output of
# bench/skeleton_table.sh (run with --tubes) and f3d + xvfb.
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

for model in ${MODELS:-elephant camel armadillo dino man}; do
    # The camel's length runs along z: turn it a quarter about y so that it is seen from the side.
    turn=0
    [[ $model == camel ]] && turn=1
    for kind in ${KINDS:-acd mcf}; do
        /usr/bin/python3 - "$IN/$model" "$kind" "$TMP/scene.obj" "$turn" <<'PYEOF'
import glob, json, os, sys

folder, kind, dst, turn = sys.argv[1:5]

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

# Twelve colours that tell apart well (Paul Tol's muted and bright schemes).
PALETTE = ['CC6677', '332288', 'DDCC77', '117733', '88CCEE', '882255', '44AA99', '999933', 'AA4499',
           'EE7733', '0077BB', 'EE3377']

def rgb(h):
    return ' '.join('%.3f' % (int(h[i:i + 2], 16) / 255) for i in (0, 2, 4))

names = ['original'] + sorted((os.path.basename(p)[:-4] for p in glob.glob(folder + '/deformed_*.off')
                               if not p.endswith('_tubes.off')), key=lambda n: int(n.split('_')[1]))
out, base, shift = ['mtllib scene.mtl\n'], 0, 0.0
for name in names:
    verts, faces = read_off('%s/%s.off' % (folder, name))
    tubes = read_off('%s/%s.%s_skeleton_tubes.off' % (folder, name, kind))
    groups = {'skin': faces}
    if kind == 'acd':
        sk = json.load(open('%s/%s.acd_skeleton.json' % (folder, name)))
        vp = sk['vertex_parts']
        match = sk.get('original_part', list(range(len(sk['part_components']))))
        groups = {}
        for f in faces:
            part = max(set(vp[i] for i in f), key=lambda p: sum(vp[i] == p for i in f))
            colour = match[part] if part >= 0 and match[part] >= 0 else -1
            groups.setdefault('grey' if colour < 0 else 'part%d' % (colour % len(PALETTE)), []).append(f)
    lo = min(v[0] for v in verts)
    hi = max(v[0] for v in verts)
    dx = shift - lo   # place the models left to right along x, a tenth of a width apart
    out.append('o %s_model\n' % name)
    out.extend('v %.6g %.6g %.6g\n' % (v[0] + dx, v[1], v[2]) for v in verts)
    for mat, fs in sorted(groups.items()):
        out.append('usemtl %s\n' % mat)
        out.extend('f ' + ' '.join(str(i + 1 + base) for i in f) + '\n' for f in fs)
    base += len(verts)
    out.append('o %s_skeleton\nusemtl bone\n' % name)
    out.extend('v %.6g %.6g %.6g\n' % (v[0] + dx, v[1], v[2]) for v in tubes[0])
    out.extend('f ' + ' '.join(str(i + 1 + base) for i in f) + '\n' for f in tubes[1])
    base += len(tubes[0])
    shift += (hi - lo) * 1.1
mtl = ('newmtl skin\nKa 0.2 0.15 0.1\nKd 0.80 0.62 0.42\nd 0.3\n\n'
       'newmtl grey\nKa 0.1 0.1 0.1\nKd 0.6 0.6 0.6\nd 0.45\n\n'
       'newmtl bone\nKa 0.02 0.02 0.02\nKd 0.05 0.05 0.05\nd 1\n\n' +
       ''.join('newmtl part%d\nKa 0.1 0.1 0.1\nKd %s\nd 0.45\n\n' % (i, rgb(h)) for i, h in enumerate(PALETTE)))
open(dst, 'w').writelines(out)
for name in (dst + '.mtl', os.path.join(os.path.dirname(dst), 'scene.mtl')):
    open(name, 'w').write(mtl)
PYEOF
        xvfb-run -a -s "-screen 0 1920x1080x24" f3d "$TMP/scene.obj" --output="$IMAGES/skeleton-$model-$kind.png" \
            --resolution=2100,420 --up=+Y --camera-azimuth-angle=0 --camera-elevation-angle=10 --camera-view-angle=7.5 \
            --bg-color=1,1,1 --depth-peeling >/dev/null 2>&1
        echo "wrote $IMAGES/skeleton-$model-$kind.png"
    done
done
