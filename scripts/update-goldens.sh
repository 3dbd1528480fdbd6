#!/usr/bin/env bash
# Regenerates the golden images (tests/golden/*.png) from the current build, on purpose. Review
# the new images (git diff shows which changed) before committing them.
# Usage: scripts/update-goldens.sh [gtest filter, e.g. '*rope*']
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
SPRINGLAB_UPDATE_GOLDENS=1 "${SPRINGLAB_BUILD_DIR:-$root/build}/tests/golden_tests" \
  --gtest_filter="Cases/Golden.*${1:-}:GoldenCharts.*${1:-}"
