#!/usr/bin/env bash
# Step throughput beside other programs: the 64 x 64 cloth (symplectic Euler, 1000 steps, as in
# the README's Performance section) alone and beside one and two busy processes (a shell loop
# each, one a core), at the default thread count and at one thread, the two run alternately so
# that both see the same phases of the machine. Prints each setting's runs, median and worst (ns
# per spring per step), and the default's median and worst over one thread's.
# Usage: scripts/load-bench.sh [RUNS] [BUSY...]     (default: 5 runs, beside 0, 1 and 2 busy)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
springlab="${SPRINGLAB_BUILD_DIR:-$root/build}/springlab"
[[ -x "$springlab" ]] || { echo "load-bench: build first (scripts/build.sh)" >&2; exit 1; }
runs="${1:-5}"
shift || true
loads=("$@")
((${#loads[@]})) || loads=(0 1 2)

one_run() {  # [--threads N] -> ns per spring-step
  "$springlab" bench cloth --set cloth.width=64 --set cloth.height=64 --dt 5e-4 --substeps 1 \
    --method symplectic-euler --steps 1000 "$@" | awk -F= '/^ns_per_spring_step=/{print $2}'
}
stats() {  # values... -> "median worst"
  printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {printf "%s %s", v[int((NR+1)/2)], v[NR]}'
}

pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; }
trap cleanup EXIT
for busy in "${loads[@]}"; do
  cleanup
  pids=()
  for ((i = 0; i < busy; i++)); do (while :; do :; done) & pids+=($!); done
  sleep 0.5
  default=() single=()
  for ((r = 0; r < runs; r++)); do
    default+=("$(one_run)")
    single+=("$(one_run --threads 1)")
  done
  read -r dm dw <<<"$(stats "${default[@]}")"
  read -r sm sw <<<"$(stats "${single[@]}")"
  echo "beside $busy busy: default threads ${default[*]} (median $dm, worst $dw); 1 thread ${single[*]} (median $sm, worst $sw)"
  awk -v a="$dm" -v b="$sm" -v c="$dw" -v d="$sw" \
    'BEGIN {printf "  default / 1 thread: median %.2fx, worst %.2fx\n", a / b, c / d}'
done
