#!/usr/bin/env bash
# The app's speed in a window under Xvfb (llvmpipe), as the README reports it: frames per second
# and the real-time factor (simulated seconds per wall second) of the cloth at 64x64 and 128x128
# with automatic sub-steps, per method. Each case runs twice, N1 and N2 frames, and the figures
# come from the difference, so the start (the window, the scene, its stability analysis) cancels.
# In --frames mode every frame advances 1/60 s, as fast as it can: a real-time factor above 1
# means the app keeps up with real time with room to spare (it then waits for the display).
# Usage: scripts/window-perf.sh [N1 N2]   (default 10 40)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="${SPRINGLAB_BUILD_DIR:-$root/build}/springlab"
n1="${1:-10}" n2="${2:-40}"

# Prints "frames wall t substeps" for one run.
measure() {
  local out
  out="$(xvfb-run -a -s '-screen 0 1280x720x24' "$exe" view "$@" 2>/dev/null)"
  awk '/^frames/ {f = $2; w = $4} /^lane/ {t = $6} END {print f, w, t}' <<<"$out"
}

printf '%-8s %-17s %9s %12s %s\n' cloth method frames/s "real time" "sub-steps (run)"
for size in 64 128; do
  methods="symplectic-euler verlet rk4 midpoint modified-euler euler implicit-euler"
  for method in $methods; do
    args=(cloth --set "cloth.width=$size" --set "cloth.height=$size" --method "$method")
    read -r f1 w1 t1 < <(measure "${args[@]}" --frames "$n1")
    read -r f2 w2 t2 < <(measure "${args[@]}" --frames "$n2")
    substeps="$("$exe" run "${args[@]}" --duration 0.001 2>/dev/null | sed -n 's/^method.* s, \([0-9]* substeps\{0,1\} ([a-z]*\).*/\1)/p')"
    awk -v f1="$f1" -v w1="$w1" -v t1="$t1" -v f2="$f2" -v w2="$w2" -v t2="$t2" -v s="${size}x$size" \
        -v m="$method" -v subs="$substeps" 'BEGIN {
      dw = w2 - w1; printf "%-8s %-17s %9.1f %11.3gx %s\n", s, m, (f2 - f1) / dw, (t2 - t1) / dw, subs }'
  done
done
