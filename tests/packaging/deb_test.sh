#!/usr/bin/env bash
# The .deb: builds it with CPack from BUILD_DIR (already built targets), unpacks it into a
# scratch root with dpkg -x, and runs what it holds: acd --version, a decomposition, the Python
# module with Debian's interpreter, and a find_package(acd) consumer against ROOT/usr.
#   deb_test.sh BUILD_DIR VERSION PYTHON
set -euo pipefail
BUILD="$(cd "$1" && pwd)" VERSION="$2" PYTHON="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

(cd "$TMP" && cpack --config "$BUILD/CPackConfig.cmake" -G DEB -B "$TMP/pkg" >"$TMP/cpack.log" 2>&1) \
    || { cat "$TMP/cpack.log"; exit 1; }
deb="$(ls "$TMP"/pkg/acd_*.deb)"
echo "package: $(basename "$deb") ($(du -h "$deb" | cut -f1))"
[[ "$(dpkg-deb --field "$deb" Version)" == "$VERSION" ]]
depends="$(dpkg-deb --field "$deb" Depends)"
echo "depends: $depends"
[[ "$depends" == *libtbb* && "$depends" == *libcgal-dev* ]]

ROOT="$TMP/root"
dpkg-deb -x "$deb" "$ROOT"
[[ "$("$ROOT/usr/bin/acd" --version)" == "acd $VERSION" ]]
echo "acd --version: acd $VERSION"

# A unit cube: one component.
cat >"$TMP/cube.off" <<'MESH'
OFF
8 12 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7
MESH
"$ROOT/usr/bin/acd" decompose "$TMP/cube.off" -q -o "$TMP/out"
grep -q "\"version\": \"$VERSION\"" "$TMP/out/report.json"

init="$(find "$ROOT/usr/lib" -path '*/acd/__init__.py' | head -n 1)"
if [[ -n "$init" ]]; then
    site="$(dirname "$(dirname "$init")")"
    PYTHONPATH="$site" "$PYTHON" -c "
import acd, sys
assert acd.__file__.startswith('$ROOT'), acd.__file__
assert acd.__version__ == '$VERSION'
r = acd.decompose('$TMP/cube.off')
assert len(r.hulls) == 1
print('python:', acd.__file__.replace('$ROOT', ''))"
fi

"$HERE/consumer_test.sh" "$BUILD" "$VERSION" "$ROOT/usr"
