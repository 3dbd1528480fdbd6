#!/usr/bin/env bash
# The app's speed in a window under Xvfb (llvmpipe), as docs/performance.md reports it: frames per second
# and the real-time factor (simulated seconds per wall second) of the cloth at 64x64 and 128x128
# with automatic sub-steps, per method, after the first frame (which waits for the scene's
# stability analysis). In --frames mode every frame advances 1/60 s as fast as it can: a
# real-time factor above 1 means the app keeps up with room to spare (it then waits for vsync).
# Usage: scripts/window-perf.sh [FRAMES] [SIZES] [METHODS]   (default 60, "64 128", all fixed-step)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="${SPRINGLAB_BUILD_DIR:-$root/build}/springlab"
frames="${1:-60}"
sizes="${2:-64 128}"
methods="${3:-symplectic-euler verlet rk4 midpoint modified-euler euler implicit-euler}"

printf '%-8s %-17s %9s %11s  %s\n' cloth method frames/s "real time" "sub-steps"
for size in $sizes; do
  for method in $methods; do
    args=(cloth --set "cloth.width=$size" --set "cloth.height=$size" --method "$method")
    out="$(xvfb-run -a -s '-screen 0 1280x720x24' "$exe" view "${args[@]}" --frames "$frames" 2>/dev/null)"
    substeps="$("$exe" run "${args[@]}" --duration 0.001 2>/dev/null |
      sed -n 's/^method.* s, \([0-9]* substeps\{0,1\} ([a-z]*\).*/\1)/p')"
    awk -v s="${size}x$size" -v m="$method" -v subs="$substeps" \
      '/^steady/ {printf "%-8s %-17s %9s %11s  %s\n", s, m, $2, $4, subs}' <<<"$out"
  done
done
