#!/usr/bin/env bash
# Step throughput beside other programs, for each solver that uses threads: the 64 x 64 cloth
# under symplectic Euler (its force pass; h = 5e-4 s, 1000 steps), implicit Euler's conjugate
# gradients, local-global and vertex block descent (h = 1/60 s, one sub-step), XPBD coloured (h =
# 2e-4 s, 1000 steps), alone and beside
# BUSY busy processes (a shell loop each, one a core), at the default thread count and at one
# thread, the two run alternately so that both see the same phases of the machine. Prints each
# setting's runs (steps a second), median and worst, and the default's median and worst over one
# thread's (below 1: the default is faster). The tool is the core alone (bench/thread_scaling.cpp).
# Usage: scripts/load-bench.sh [RUNS] [BUSY...]     (default: 5 runs, beside 0 and 2 busy)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tool="${SPRINGLAB_BUILD_DIR:-$root/build}/bench/springlab_threads"
[[ -x "$tool" ]] || { echo "load-bench: build first (scripts/build.sh)" >&2; exit 1; }
runs="${1:-5}"
shift || true
loads=("$@")
((${#loads[@]})) || loads=(0 2)
cloth="$root/assets/scenes/cloth.json"

one_run() {  # METHOD DT STEPS THREADS -> steps a second
  "$tool" "$cloth" "$1" "$2" "$3" "$4" --set cloth.width=64 --set cloth.height=64 |
    sed -n 's/.*steps_per_s=\([0-9.e+]*\).*/\1/p'
}
stats() {  # values... -> "median worst" (worst: the slowest)
  printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {printf "%s %s", v[int((NR+1)/2)], v[1]}'
}

pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT
for busy in "${loads[@]}"; do
  cleanup
  pids=()
  for ((i = 0; i < busy; i++)); do (while :; do :; done) & pids+=($!); done
  sleep 0.5
  echo "beside $busy busy ($(nproc) cores):"
  for m in symplectic-euler:5e-4:1000 implicit-euler:0.016666666666666666:30 local-global:0.016666666666666666:60 vbd:0.016666666666666666:60 xpbd:2e-4:1000; do
    IFS=: read -r method dt steps <<<"$m"
    default=() single=()
    for ((r = 0; r < runs; r++)); do
      default+=("$(one_run "$method" "$dt" "$steps" 0)")
      single+=("$(one_run "$method" "$dt" "$steps" 1)")
    done
    read -r dm dw <<<"$(stats "${default[@]}")"
    read -r sm sw <<<"$(stats "${single[@]}")"
    awk -v m="$method" -v d="${default[*]}" -v s="${single[*]}" -v a="$dm" -v b="$sm" -v c="$dw" -v e="$sw" \
      'BEGIN {printf "  %-16s default %s (median %s, worst %s); 1 thread %s (median %s, worst %s); time, default over 1 thread: median %.2fx, worst %.2fx\n", m, d, a, c, s, b, e, b / a, e / c}'
  done
done
