#!/usr/bin/env bash
# The stated stability limits checked on every shipped scene with springs (and the 64- and
# 1000-node ropes and the 64 x 64 cloth), for every fixed-step method, each run for the scene's
# whole duration: at 0.95 times the limit it holds, at 1.25 times it diverges, or its limiting
# mode grows at the predicted rate (tests/core/limits_test.cpp; the normal suite runs the same
# with a budget of work a run). Prints a line per scene and method. About an hour on 2 cores.
# Usage: scripts/limits.sh [gtest filter on the scene, e.g. 'rope*']
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
SPRINGLAB_LIMITS_BUDGET=1e14 "${SPRINGLAB_BUILD_DIR:-$root/build}/tests/core_tests" \
  --gtest_filter="Scenes/Limits.*${1:-}"
