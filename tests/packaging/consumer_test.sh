#!/usr/bin/env bash
# find_package(acd) from an installed prefix: builds and runs tests/packaging/consumer against
#   PREFIX (given), or an install of BUILD_DIR's dev component into a temporary prefix.
#   consumer_test.sh BUILD_DIR VERSION [PREFIX]
set -euo pipefail
BUILD="$1" VERSION="$2" PREFIX="${3:-}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

if [[ -z "$PREFIX" ]]; then
    PREFIX="$TMP/prefix"
    cmake --install "$BUILD" --prefix "$PREFIX" --component dev >/dev/null
fi
# Only the prefix may provide acd: no package registry, no build tree.
cmake -S "$HERE/consumer" -B "$TMP/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PREFIX" \
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$TMP/configure.log" 2>&1 || { cat "$TMP/configure.log"; exit 1; }
grep -q "acd $VERSION from $PREFIX/" "$TMP/configure.log" || { echo "acd not found in $PREFIX:"; cat "$TMP/configure.log"; exit 1; }
cmake --build "$TMP/build" -j2 >"$TMP/build.log" 2>&1 || { cat "$TMP/build.log"; exit 1; }
out="$("$TMP/build/consumer")"
echo "$out"
[[ "$out" == "acd $VERSION: "*" components, "* ]]
