#!/usr/bin/env bash
# Installs what is missing, builds, and starts springlab.
#   With a display:    the interactive app (scripts/run.sh view cloth opens another scene).
#   Without a display: renders a demo video headlessly, out/demo.mp4, and a lesson,
#                      out/lesson-euler-explodes.mp4, and says where they are.
# Any arguments are passed to springlab: scripts/run.sh run rope --method verlet
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh" --target springlab  # (the tests, benchmarks and Python module: scripts/test.sh)
bin="$root/build/springlab"
if [[ $# -gt 0 ]]; then
  exec "$bin" "$@"
fi
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
  exec "$bin" view
fi
mkdir -p "$root/out"
echo "No display: rendering the demo (the rope exercise, dragged, switched from explicit Euler to RK4) headlessly."
"$bin" render rope --script "$root/assets/scripts/rope-drag-euler-to-rk4.json" --ui --video "$root/out/demo.mp4"
echo "Rendering lesson 3 (explicit Euler gains energy) with its captions burned in."
"$bin" render --lesson euler-explodes --video "$root/out/lesson-euler-explodes.mp4"
echo "Videos: $root/out/demo.mp4 and $root/out/lesson-euler-explodes.mp4 (on a desktop, scripts/run.sh opens the app;"
echo "springlab lesson list shows the other lessons, springlab render --lesson NAME --video FILE records one)"
