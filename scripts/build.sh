#!/usr/bin/env bash
# Configures and builds springlab (Release, Ninja) into build/: everything (the app, the tests,
# the benchmarks and the Python module), or only the targets named with --target.
# Used by run.sh (the app alone: the first frame sooner) and test.sh (everything).
# Usage: scripts/build.sh [--target NAME]... [extra cmake -D options, e.g. -DSPRINGLAB_PYTHON=OFF]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_BUILD_DIR:-$root/build}"
targets=()
while [[ $# -ge 2 && $1 == --target ]]; do
  targets+=(--target "$2")
  shift 2
done
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPRINGLAB_PYTHON=ON "$@" >/dev/null
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
