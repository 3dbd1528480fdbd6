#!/usr/bin/env bash
# The browser build's performance beside the desktop's (docs/web.md, Performance): frames per
# second of the app in headless Chromium (SwiftShader) and of the desktop app under Xvfb (its
# --frames mode: as fast as frames come, no pacing) for rope, cloth 24 x 24 and cloth 64 x 64;
# and ns per spring-step of the core, one thread, compiled to WebAssembly and native, same scenes.
# Builds both first. A few minutes. Not a test: nothing is asserted.
# Usage: scripts/web-bench.sh
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/web.sh"
NODE_PATH=/usr/share/nodejs cmake --build "$root/build-wasm" --target step_bench_web --parallel "$(nproc)"
"$root/scripts/build.sh" >/dev/null
bin="${SPRINGLAB_BUILD_DIR:-$root/build}/springlab"

# The core: the same scene, method, step and step count natively and in the browser.
runs=("scene=cloth set=cloth.width=64 set=cloth.height=64 method=symplectic-euler dt=5e-4 steps=2000"
      "scene=rope set=rope.nodes=1000 method=symplectic-euler dt=1e-5 steps=20000"
      "scene=cloth method=rk4 dt=1e-3 steps=4000")
echo "== core, one thread: ns per spring-step (fastest of 5)"
for r in "${runs[@]}"; do
  args=()
  for word in $r; do
    key="${word%%=*}" value="${word#*=}"
    case "$key" in
      scene) args=("$value" "${args[@]}") ;;
      *) args+=("--$key" "$value") ;;
    esac
  done
  ns="$("$bin" bench "${args[@]}" --threads 1 --repeat 5 | sed -n 's/^ns_per_spring_step=//p')"
  echo "native $r: ns_per_spring_step=$ns"
done

echo "== the browser (headless Chromium, SwiftShader), and the core in WebAssembly"
SPRINGLAB_BENCH_STEPS="$(IFS=';'; echo "${runs[*]}")" "$root/tests/web/node.sh" "$root/bench/web/web_bench.cjs"

echo "== the desktop app under Xvfb (springlab view SCENE --frames 600: unpaced)"
for spec in "rope" "cloth" "cloth --set cloth.width=64 --set cloth.height=64"; do
  # shellcheck disable=SC2086
  line="$(xvfb-run -a -s "-screen 0 1280x720x24" "$bin" view $spec --frames 600 | sed -n 's/^frames *//p')"
  echo "desktop $spec: $line"
done
