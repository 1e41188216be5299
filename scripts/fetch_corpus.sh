#!/usr/bin/env bash
# Extract the test corpus (OFF meshes) from Debian's libcgal-demo data tarball
# into data/meshes/ at the repository root (git-ignored, never committed).
#
# If libcgal-demo is installed, its tarball is used directly; otherwise the
# .deb is downloaded with `apt-get download` and unpacked with `dpkg-deb -x`
# (no root needed). Skips extraction when data/meshes/elephant.off exists.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEST="$ROOT/data/meshes"
TARBALL_REL="usr/share/doc/libcgal-dev/data.tar.gz"

# The models the project's tests, examples and benchmarks rely on.
CORPUS=(elephant armadillo bunny00 camel cow dino homer handle knot eight mushroom ChineseDragon-10kv)

find_tarball() {
    # Prefer what dpkg says the package ships; fall back to the known path.
    local t
    t="$(dpkg -L libcgal-demo 2>/dev/null | grep -E '/data\.tar\.gz$' | head -n1 || true)"
    if [[ -n "$t" && -f "$t" ]]; then echo "$t"; return 0; fi
    [[ -f "/$TARBALL_REL" ]] && { echo "/$TARBALL_REL"; return 0; }
    return 1
}

if [[ -f "$DEST/elephant.off" ]]; then
    echo "[fetch_corpus] data/meshes already present, skipping extraction"
else
    mkdir -p "$DEST"
    TMP="$(mktemp -d)"
    chmod 755 "$TMP"   # lets apt's unprivileged _apt user write the download
    trap 'rm -rf "$TMP"' EXIT
    if TARBALL="$(find_tarball)"; then
        echo "[fetch_corpus] extracting meshes from $TARBALL"
    else
        echo "[fetch_corpus] libcgal-demo not installed; downloading the .deb"
        (cd "$TMP" && apt-get download libcgal-demo >/dev/null)
        DEB="$(ls "$TMP"/libcgal-demo_*.deb | head -n1)"
        dpkg-deb -x "$DEB" "$TMP/pkg"
        TARBALL="$TMP/pkg/$TARBALL_REL"
        [[ -f "$TARBALL" ]] || { echo "[fetch_corpus] ERROR: $TARBALL_REL not found in $DEB" >&2; exit 1; }
    fi
    # Only the .off files directly under data/meshes/.
    tar -xzf "$TARBALL" -C "$TMP" --wildcards --no-anchored 'data/meshes/*.off'
    find "$TMP/data/meshes" -maxdepth 1 -type f -name '*.off' -exec cp -f {} "$DEST/" \;
    echo "[fetch_corpus] extracted $(find "$DEST" -maxdepth 1 -name '*.off' | wc -l) .off files into data/meshes/"
fi

missing=()
present=()
for m in "${CORPUS[@]}"; do
    if [[ -f "$DEST/$m.off" ]]; then present+=("$m"); else missing+=("$m"); fi
done
echo "[fetch_corpus] corpus present (${#present[@]}/${#CORPUS[@]}): ${present[*]}"
if (( ${#missing[@]} > 0 )); then
    echo "[fetch_corpus] ERROR: missing corpus models: ${missing[*]}" >&2
    echo "[fetch_corpus] available in data/meshes/:" >&2
    (cd "$DEST" && ls -1 ./*.off 2>/dev/null | sed 's|^\./||; s|\.off$||' | tr '\n' ' ' >&2; echo >&2)
    exit 1
fi
