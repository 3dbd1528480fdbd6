#!/usr/bin/env bash
# The scaling table: steps a second of each solver on the 128 x 128 cloth at 1, 2, 4, 8 and 16
# threads and at the default (0: every core), and the 128 x 128 cloth's stability analysis at 1,
# 4, 16 threads and the default; then the load table on the 64 x 64 cloth at h = 1/60 beside
# BUSY busy processes (default threads against one thread, alternately, RUNS times each).
# Usage: scripts/scaling.sh [TOOL] [BUSY] [RUNS]
#   TOOL: build/bench/springlab_threads (the core alone: it runs on a machine without the app's
#   libraries when linked statically); BUSY: busy processes for the load table (default: half the
#   cores); RUNS: 5.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tool="${1:-${SPRINGLAB_BUILD_DIR:-$root/build}/bench/springlab_threads}"
cores=$(nproc)
busy="${2:-$((cores / 2))}"
runs="${3:-5}"
cloth="$root/assets/scenes/cloth.json"
big=(--set cloth.width=128 --set cloth.height=128)
small=(--set cloth.width=64 --set cloth.height=64)
counts=(1 2 4 8 16 0)

echo "# $(nproc) cores; threads 0 = the default (every core)"
# The machine: hardware threads a core (a second one gains little), caches and NUMA nodes.
lscpu | grep -E "^(Model name|Thread\(s\) per core|Core\(s\) per socket|Socket\(s\)|L2 cache|L3 cache|NUMA node\(s\))" || true
echo "## scaling: 128 x 128 cloth, h = 1/60 (symplectic Euler and XPBD 2e-4), steps/s"
for m in symplectic-euler:2e-4:400 xpbd:2e-4:400 implicit-euler:0.016666666666666666:12 local-global:0.016666666666666666:20 vbd:0.016666666666666666:30; do
  IFS=: read -r method dt steps <<<"$m"
  echo "### $method"
  "$tool" "$cloth" "$method" "$dt" "$steps" "${counts[@]}" "${big[@]}"
done
echo "## the helpers' spin between passes: local-global, 128 x 128 cloth, 4 and 16 threads, with"
echo "## OMP_WAIT_POLICY=passive (helpers sleep after 50 us: sleeps= counts it) and without (about 1 ms)"
for policy in passive ""; do  # ("": unset, libgomp's default; an empty value it calls invalid)
  env -u OMP_WAIT_POLICY ${policy:+OMP_WAIT_POLICY=$policy} \
    "$tool" "$cloth" local-global 0.016666666666666666 20 4 16 "${big[@]}"
done
echo "## analysis: 128 x 128 cloth, seconds"
"$tool" "$cloth" symplectic-euler 1e-3 1 1 4 16 0 "${big[@]}" --analysis

echo "## load: 64 x 64 cloth, h = 1/60, beside $busy busy processes; default threads, then 1 thread, alternately"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT
for ((i = 0; i < busy; i++)); do (while :; do :; done) & pids+=($!); done
sleep 0.5
for m in symplectic-euler:5e-4:1000 implicit-euler:0.016666666666666666:30 local-global:0.016666666666666666:60 vbd:0.016666666666666666:60; do
  IFS=: read -r method dt steps <<<"$m"
  echo "### $method"
  for ((r = 0; r < runs; r++)); do
    "$tool" "$cloth" "$method" "$dt" "$steps" 0 "${small[@]}"
    "$tool" "$cloth" "$method" "$dt" "$steps" 1 "${small[@]}"
  done
done
