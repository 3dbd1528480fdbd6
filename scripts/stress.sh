#!/usr/bin/env bash
# The threads beside the frame loop under a sanitizer: the app built whole with clang and
# AddressSanitizer + UndefinedBehaviorSanitizer (asan) or ThreadSanitizer (tsan) into
# build-asan/ or build-tsan/, then, for ROUNDS rounds (0: until stopped):
#   - the app's stress test (tests/app/stress_test.cpp: analyses, sweeps and lesson steps
#     replacing the session, frame after frame) for SECONDS;
#   - `render --lesson` of every lesson, short (frames written by the writer's thread), and one
#     of them to an mp4 (the ffmpeg pipe);
#   - `view --lesson` of a lesson under Xvfb with its analyses on worker threads, ended by
#     SIGTERM after a few seconds (while one may be in flight).
# Any report stops it with the sanitizer's output. Reports from the GL driver (Mesa) and the
# OpenMP runtime (not built with the sanitizer) are suppressed (scripts/sanitizer-suppressions/),
# and under ASan the driver is kept loaded (keep_loaded.c); springlab's own code is not.
# Usage: scripts/stress.sh [asan|tsan] [ROUNDS (default 1)] [SECONDS (default 20)]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
kind="${1:-asan}"
rounds="${2:-1}"
seconds="${3:-20}"
case "$kind" in
  asan) sanitizer=address ;;
  tsan) sanitizer=thread ;;
  *) echo "stress: the first argument is asan or tsan, got '$kind'" >&2; exit 2 ;;
esac
"$root/scripts/setup.sh"
build="$root/build-$kind"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSPRINGLAB_SANITIZE=ON \
  -DSPRINGLAB_SANITIZER="$sanitizer" -DSPRINGLAB_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target springlab app_tests

suppressions="$root/scripts/sanitizer-suppressions"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$suppressions/lsan.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="suppressions=$suppressions/tsan.txt:halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1"
export OMP_WAIT_POLICY=passive
springlab="$build/springlab"
out="$(mktemp -d)"
# The app's own processes keep every library loaded under ASan (keep_loaded.c says why).
preload=()
if [[ "$kind" == asan ]]; then
  clang -shared -fPIC -o "$build/keep_loaded.so" "$suppressions/keep_loaded.c"
  preload=(env LD_PRELOAD="$build/keep_loaded.so")
fi
trap 'rm -rf "$out"' EXIT

round=0
while ((rounds == 0 || round < rounds)); do
  round=$((round + 1))
  echo "stress ($kind): round $round"
  SPRINGLAB_STRESS_SECONDS="$seconds" "$build/tests/app_tests" --gtest_filter='Stress.*:StabilityJobs.*' --gtest_brief=1
  while read -r lesson; do
    "${preload[@]}" "$springlab" render --lesson "$lesson" --software --size 320x180 --fps 15 --out "$out/$lesson" >/dev/null
    rm -rf "${out:?}/$lesson"
  done < <("$springlab" lesson list | awk '{print $2}')
  "${preload[@]}" "$springlab" render --lesson implicit-stiff --software --size 320x180 --fps 15 --video "$out/l.mp4" >/dev/null
  # The window, its analyses on worker threads, ended while they run.
  for view in "--lesson damping-buys-a-limit" "cloth --set cloth.width=64 --set cloth.height=64"; do
    status=0
    # shellcheck disable=SC2086
    timeout -s TERM 8 xvfb-run -a -s "-screen 0 1280x720x24" "${preload[@]}" "$springlab" view $view >/dev/null 2>"$out/view.err" ||
      status=$?
    # 124: ended by the timeout's SIGTERM (the app's own status for it is 143, which xvfb-run may
    # report instead); anything else is a crash or a report.
    if ((status != 124 && status != 143 && status != 0)); then
      cat "$out/view.err" >&2
      echo "stress: view $view ended with status $status" >&2
      exit 1
    fi
  done
done
echo "stress ($kind): $round rounds clean"
