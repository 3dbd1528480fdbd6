#!/usr/bin/env bash
# Builds the API documentation of the core library's public headers (core/include/springlab)
# with Doxygen into docs/api/ (git ignores it), or into the folder given. Open docs/api/index.html.
# Usage: scripts/docs.sh [OUTPUT_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(realpath -m "${1:-$root/docs/api}")"
command -v doxygen >/dev/null || { echo "docs: doxygen is missing: run scripts/setup.sh (Debian's doxygen)" >&2; exit 1; }
mkdir -p "$out"
# The version from the top-level project() call, as springlab --version prints it.
version="$(sed -n 's/^project(springlab VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")"
cd "$root"
SPRINGLAB_DOCS_OUT="$out" SPRINGLAB_VERSION="$version" doxygen docs/Doxyfile
echo "docs: $out/index.html"
