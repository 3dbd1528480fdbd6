#!/usr/bin/env bash
# One way into threads: no OpenMP pragma (a region or a simd hint: SPRINGLAB_VECTORISE), OpenMP runtime call, std::thread, std::jthread or
# pthread_create outside the core's seam (core/src/dynamics/threads.*) and the app's worker
# (app/util/worker.hpp). A second way in is how a program collapses when another shares the cores
# (a barrier waits for a thread the scheduler parked): every parallel loop goes through
# threads::for_each_piece or the team, every app thread through Worker.
# bench/ is left out: floor_bench.cpp's hand-made pair of threads measures the machine's floor
# without the seam, on purpose.
# Usage: tests/house/threads_seam_test.sh [ROOT]    (exit 1 and the offending lines when one appears)
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/../.." && pwd)}"
cd "$root"
pattern='#[[:space:]]*pragma[[:space:]]+omp\b|\bomp_[a-z_]+[[:space:]]*\(|std::j?thread\b|pthread_create'
found=$(grep -rnE "$pattern" core app python --include='*.cpp' --include='*.hpp' --include='*.h' \
          | grep -vE '^(core/src/dynamics/threads\.(hpp|cpp)|app/util/worker\.hpp):' || true)
if [[ -n "$found" ]]; then
  echo "threads outside the seam (core/src/dynamics/threads.*) and the worker (app/util/worker.hpp):"
  echo "$found"
  exit 1
fi
echo "threads: only through the seam and the worker"
