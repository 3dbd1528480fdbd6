#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test with CTest: the normal build's suite
# (labels core, cli, golden, app, soak, install, python, docs), then clang-tidy's defect checks on
# every source (scripts/tidy.sh), then the checking build's (scripts/sanitize.sh: the core
# tests under AddressSanitizer and UndefinedBehaviorSanitizer, and a bounded run of each fuzz
# target), then the browser build's (scripts/web.sh --test: the app in headless Chromium, and the
# core's tests compiled to WebAssembly; a few minutes). CI runs this with no options.
# Usage: scripts/test.sh [ctest options, e.g. -L core or -R Stability]
#   With ctest options, only the normal suite runs, with those options (a quick check while
#   working); scripts/sanitize.sh takes the same options for the checking build.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
# Each phase's time, said as it ends (CI's budget is 25 minutes: where it goes).
phase_start=$SECONDS
took() { echo "test.sh: $1 took $((SECONDS - phase_start)) s (all so far: $SECONDS s)"; phase_start=$SECONDS; }
"$root/scripts/setup.sh"
took "setting up"
"$root/scripts/build.sh"
took "building"
# Two tests at once, each with its OpenMP threads: waiting threads sleep instead of spinning (a
# spinning team took the cores from the other test: the suite ran 254 s instead of 175 s).
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
(cd "${SPRINGLAB_BUILD_DIR:-$root/build}" && ctest --output-on-failure --parallel "$(nproc)" --timeout 600 "$@")
took "the normal suite"
if [[ $# -eq 0 ]]; then
  "$root/scripts/tidy.sh"
  took "clang-tidy's defect checks (tidy.sh)"
  "$root/scripts/sanitize.sh"
  took "the checking build and its suite (sanitize.sh)"
  "$root/scripts/web.sh" --test
  took "the browser build and its checks (web.sh --test)"
fi
