#!/usr/bin/env bash
# One-shot, idempotent project setup on Debian 12:
#   1. install missing Debian packages (apt-get, non-interactive),
#   2. extract the mesh corpus into data/meshes/ (scripts/fetch_corpus.sh),
#   3. configure and build in Release into build/: the given targets, or everything.
#      scripts/run_main.sh builds only acd_cli (the command) so that a newcomer's first
#      decomposition does not wait for the applications, the Python module and the packaging.
#   scripts/setup.sh [TARGET...]
set -euo pipefail
TARGETS=("$@")

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

# Required: the build, the tests, the benchmarks and the corpus. Simulator output: tinyxml2
# (URDF/MJCF/SDF) and tinygltf (glTF) for acd itself; urdfdom, sdformat and Bullet only for the
# tests that read those files back (23 packages, 24 MB installed). clang and its runtime: the
# sanitizer build and the fuzz harnesses (scripts/run_sanitizers.sh, fuzz/).
CORE_PKGS=(
    build-essential cmake ccache
    libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev libboost-dev libtbb-dev
    libcli11-dev nlohmann-json3-dev libgtest-dev googletest
    libcgal-demo time jq python3
    libtet1.5-dev libompl-dev libfcl-dev libyaml-cpp-dev libassimp-dev libglpk-dev
    libboost-filesystem-dev libboost-serialization-dev libboost-graph-dev
    python3-matplotlib python3-networkx
    python3-distributed python3-tqdm chromium python3-pil
    libtinyxml2-dev libtinygltf-dev
    liburdfdom-dev libsdformat-dev libbullet-dev
    clang libclang-rt-14-dev
    pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest dpkg-dev
)
# Optional: off-screen pictures (scripts/render.sh). Failure here is not fatal.
PICTURE_PKGS=(f3d xvfb xauth)

SUDO=()
if [[ "$(id -u)" -ne 0 ]]; then
    if command -v sudo >/dev/null 2>&1; then SUDO=(sudo); fi
fi
export DEBIAN_FRONTEND=noninteractive

missing_of() {
    local p
    for p in "$@"; do
        dpkg -s "$p" >/dev/null 2>&1 || echo "$p"
    done
}

APT_UPDATED=0
apt_install() {
    if (( APT_UPDATED == 0 )); then
        "${SUDO[@]}" apt-get update -qq
        APT_UPDATED=1
    fi
    "${SUDO[@]}" apt-get install -y -qq --no-install-recommends "$@"
}

LOG="$(mktemp)"
trap 'rm -f "$LOG"' EXIT

mapfile -t missing_core < <(missing_of "${CORE_PKGS[@]}")
if (( ${#missing_core[@]} > 0 )); then
    echo "[setup] installing packages: ${missing_core[*]}"
    if ! apt_install "${missing_core[@]}" >"$LOG" 2>&1; then
        cat "$LOG" >&2
        echo "[setup] ERROR: could not install required packages: ${missing_core[*]}" >&2
        exit 1
    fi
else
    echo "[setup] required packages present"
fi

mapfile -t missing_pic < <(missing_of "${PICTURE_PKGS[@]}")
if (( ${#missing_pic[@]} > 0 )); then
    # (capture first: `apt-cache ... | grep -q` can fail under pipefail via SIGPIPE)
    f3d_candidate() { apt-cache policy f3d 2>/dev/null | sed -n 's/^ *Candidate: *//p'; }
    cand="$(f3d_candidate || true)"
    if [[ -z "$cand" || "$cand" == "(none)" ]] && (( APT_UPDATED == 0 )); then
        # apt-cache may know nothing before the first update.
        "${SUDO[@]}" apt-get update -qq >/dev/null 2>&1 || true
        APT_UPDATED=1
        cand="$(f3d_candidate || true)"
    fi
    if [[ -n "$cand" && "$cand" != "(none)" ]]; then
        echo "[setup] installing picture packages: ${missing_pic[*]}"
        if ! apt_install "${missing_pic[@]}" >"$LOG" 2>&1; then
            echo "[setup] WARNING: picture packages failed to install (rendering disabled): ${missing_pic[*]}" >&2
        fi
    else
        echo "[setup] WARNING: f3d not available from apt; pictures disabled" >&2
    fi
else
    echo "[setup] picture packages present"
fi

echo "[setup] fetching mesh corpus"
scripts/fetch_corpus.sh | sed 's/^/  /'

echo "[setup] configuring (Release) into build/"
if ! cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >"$LOG" 2>&1; then
    cat "$LOG" >&2
    echo "[setup] ERROR: cmake configure failed" >&2
    exit 1
fi

target_args=()
for t in "${TARGETS[@]}"; do target_args+=(--target "$t"); done
echo "[setup] building ${TARGETS[*]:-everything} with $(nproc) jobs"
if ! cmake --build build -j"$(nproc)" "${target_args[@]}" >"$LOG" 2>&1; then
    tail -n 60 "$LOG" >&2
    echo "[setup] ERROR: build failed" >&2
    exit 1
fi
echo "[setup] done"
