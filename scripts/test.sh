#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with CTest.
# Usage: scripts/test.sh [ctest options, e.g. -L core or -R Stability]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
cd "${SPRINGLAB_BUILD_DIR:-$root/build}"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600 "$@"
