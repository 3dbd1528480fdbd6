#!/usr/bin/env bash
# Measures the performance targets (docs/performance.md) on this machine and prints each beside its
# target: the commands of docs/performance.md's first table (not its video and window rows), each timed with
# `springlab bench --repeat N` (fastest run and median), so that the figures can be taken again in
# one go. Builds first. Takes about a minute with N = 11. A command that fails stops the script.
# Usage: scripts/perf-targets.sh [N, repeats of each command, default 11]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_BUILD_DIR:-$root/build}"
repeats="${1:-11}"
if ! [[ "$repeats" =~ ^[1-9][0-9]{0,2}$ ]]; then
  echo "scripts/perf-targets.sh: N must be a whole number from 1 to 999, got '$repeats'" >&2
  exit 2
fi
"$root/scripts/build.sh" >/dev/null
bin="$build/springlab"

# A key's value in the key=value lines of `springlab bench`.
value() { sed -n "s/^$1=//p" <<<"$2"; }
# bench ARGS: sets fastest and median, ns a spring-step (one run: no median line, the same figure).
# Called directly, not in $(...): a failing command then stops the script (set -e).
bench() {
  local out
  out="$("$bin" bench "$@" --repeat "$repeats")"
  fastest="$(value ns_per_spring_step "$out")"
  median="$(value ns_per_spring_step_median "$out")"
  median="${median:-$fastest}"
}
row() { printf '%-46s %-28s %s\n' "$1" "$2" "$3"; }
cloth() { echo "cloth --set cloth.width=$1 --set cloth.height=$1"; }

row "what" "fastest / median (ns)" "target"
bench $(cloth 64) --dt 5e-4 --steps 4000 --threads 2
row "cloth 64 x 64, symplectic Euler, 2 threads" "$fastest / $median" "<= 1.5 ns"
bench $(cloth 64) --dt 5e-4 --steps 4000 --threads 1
row "the same, 1 thread" "$fastest / $median" ""
bench rope --set rope.nodes=1000 --method symplectic-euler --dt 1e-5 --steps 40000 --threads 1
row "rope 1000 nodes, 1 thread" "$fastest / $median" "<= 2 ns"
bench $(cloth 128) --dt 2.5e-4 --steps 1000 --threads 1
one="$fastest"
bench $(cloth 128) --dt 2.5e-4 --steps 1000 --threads 2
row "cloth 128 x 128, 1 / 2 threads (fastest)" \
  "$one / $fastest: $(awk -v a="$one" -v b="$fastest" 'BEGIN { printf "%.2f x", a / b }')" ">= 1.7 x"
sizes=()
for spec in "32 1e-3 8000" "64 5e-4 4000" "128 2.5e-4 1000" "256 6e-5 200" "512 3e-5 60"; do
  read -r side dt steps <<<"$spec"
  bench $(cloth "$side") --dt "$dt" --steps "$steps" --threads 1
  sizes+=("$fastest")
done
spread="$(printf '%s\n' "${sizes[@]}" | awk 'NR == 1 || $1 < lo { lo = $1 } $1 > hi { hi = $1 }
  END { printf "%.0f %% apart", 100 * (hi / lo - 1) }')"
row "cloth 32 .. 512 a side, 1 thread (fastest)" "${sizes[*]}" "within 25 %: $spread"
# Once from the start: the solver's iterations fall as the cloth settles, so later runs do less.
out="$("$bin" bench $(cloth 64) --method implicit-euler --dt 0.016666666666666666 --steps 200)"
row "implicit Euler, cloth 64, h = 1/60" \
  "$(value steps_per_s "$out") steps/s, $(value solver_iterations_per_step "$out") CG its" ">= 120 steps/s"
rss="$(/usr/bin/time -f %M "$bin" run $(cloth 512) --dt 3e-5 --steps 20 2>&1 >/dev/null | tail -1)"
row "run, cloth 512 x 512: peak memory" "$((rss / 1024)) MB" "< 150 MB"
