#!/usr/bin/env bash
# Measures the performance targets (README, Performance) on this machine and prints each beside its
# target: the README's commands, each timed with `springlab bench --repeat` (fastest run and median),
# so that the figures can be taken again in one go. Builds first. Takes about two minutes.
# Usage: scripts/perf-targets.sh [repeats, default 11]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_BUILD_DIR:-$root/build}"
repeats="${1:-11}"
"$root/scripts/build.sh" >/dev/null
bin="$build/springlab"

# key=value lines of `springlab bench`, one key's value. (--repeat times the same number of steps
# again as the simulation goes on: for the explicit methods, the same work each time.)
value() { sed -n "s/^$1=//p"; }
# bench ARGS: "fastest median" ns a spring-step.
bench() {
  local out
  out="$("$bin" bench "$@" --repeat "$repeats")"
  echo "$(value ns_per_spring_step <<<"$out") $(value ns_per_spring_step_median <<<"$out")"
}
row() { printf '%-46s %-26s %s\n' "$1" "$2" "$3"; }

cloth() { echo "cloth --set cloth.width=$1 --set cloth.height=$1"; }
row "what" "fastest / median (ns)" "target"
read -r f m <<<"$(bench $(cloth 64) --dt 5e-4 --steps 4000 --threads 2)"
row "cloth 64 x 64, symplectic Euler, 2 threads" "$f / $m" "<= 1.5 ns"
read -r f1 m1 <<<"$(bench $(cloth 64) --dt 5e-4 --steps 4000 --threads 1)"
row "the same, 1 thread" "$f1 / $m1" ""
read -r f m <<<"$(bench rope --set rope.nodes=1000 --method symplectic-euler --dt 1e-5 --steps 40000 --threads 1)"
row "rope 1000 nodes, 1 thread" "$f / $m" "<= 2 ns"
read -r a _ <<<"$(bench $(cloth 128) --dt 2.5e-4 --steps 1000 --threads 1)"
read -r b _ <<<"$(bench $(cloth 128) --dt 2.5e-4 --steps 1000 --threads 2)"
row "cloth 128 x 128, 1 / 2 threads (fastest)" "$a / $b: $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f x", a / b }')" ">= 1.7 x"
sizes=""
for spec in "32 1e-3 8000" "64 5e-4 4000" "128 2.5e-4 1000" "256 6e-5 200" "512 3e-5 60"; do
  read -r side dt steps <<<"$spec"
  read -r f _ <<<"$(bench $(cloth "$side") --dt "$dt" --steps "$steps" --threads 1)"
  sizes="$sizes $f"
done
row "cloth 32 .. 512 a side, 1 thread (fastest)" "$sizes" "within 25 %: $(tr ' ' '\n' <<<"$sizes" |
  awk 'NF { lo = (lo == "" || $1 < lo) ? $1 : lo; hi = ($1 > hi) ? $1 : hi } END { printf "%.0f %% apart", 100 * (hi / lo - 1) }')"
# One run from the start: the solver's iterations fall as the cloth settles, so later runs do less.
out="$("$bin" bench $(cloth 64) --method implicit-euler --dt 0.016666666666666666 --steps 200)"
row "implicit Euler, cloth 64, h = 1/60" "$(value steps_per_s <<<"$out") steps/s, $(value solver_iterations_per_step <<<"$out") CG its" ">= 120 steps/s"
rss="$(/usr/bin/time -f %M "$bin" run $(cloth 512) --dt 3e-5 --steps 20 2>&1 >/dev/null | tail -1)"
row "run, cloth 512 x 512: peak memory" "$((rss / 1024)) MB" "< 150 MB"
