#!/usr/bin/env bash
# Configures and builds springlab (Release, Ninja) into build/, the Python module (python/) too.
# Used by run.sh and test.sh.
# Usage: scripts/build.sh [extra cmake -D options, e.g. -DSPRINGLAB_PYTHON=OFF]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPRINGLAB_PYTHON=ON "$@" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
