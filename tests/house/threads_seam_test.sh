#!/usr/bin/env bash
# One way into threads: no OpenMP pragma (`#pragma omp`, `_Pragma("omp ...")` or MSVC's
# `__pragma(omp ...)`: a region or a simd hint: SPRINGLAB_VECTORISE), OpenMP runtime call,
# std::thread, std::jthread, std::async or pthread_create outside the core's seam
# (core/src/dynamics/threads.*) and the app's worker
# (app/util/worker.hpp). A second way in is how a program collapses when another shares the cores
# (a barrier waits for a thread the scheduler parked): every parallel loop goes through
# threads::for_each_piece or the team, every app thread through Worker.
# bench/ is left out: floor_bench.cpp's hand-made pair of threads measures the machine's floor
# without the seam, on purpose.
# So that a pattern that matches nothing cannot pass, the seam's and the worker's own uses must be
# found too: at least MIN_SEAM_USES lines (default 5; the tree has 13).
# Usage: tests/house/threads_seam_test.sh [ROOT [MIN_SEAM_USES]]
#          (exit 1 and the offending lines when one appears)
#        tests/house/threads_seam_test.sh --self-test
#          (runs itself on tests/house/fixtures/threads_seam/, where core/src/planted.cpp starts
#          threads each way, and expects it to fail naming each; and with the default floor, and
#          expects it to fail for finding too few of the seam's uses)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

if [[ "${1:-}" == "--self-test" ]]; then
  fixture="$here/fixtures/threads_seam"
  problems=0
  set +e
  out=$(bash "$0" "$fixture" 1 2>&1); rc=$?
  set -e
  echo "\$ threads_seam_test.sh tests/house/fixtures/threads_seam 1  -> exit $rc"
  echo "$out"
  if [[ $rc -ne 1 ]]; then echo "self-test: the planted threads passed (exit $rc)" >&2; problems=1; fi
  # Each planted way in, by its line in core/src/planted.cpp; the seam's own line must not be named.
  for line in 5 6 9 13 14 15 16 17 18; do
    if ! grep -q "^core/src/planted.cpp:$line:" <<<"$out"; then
      echo "self-test: core/src/planted.cpp:$line was not named" >&2; problems=1
    fi
  done
  if grep -q '^core/src/dynamics/threads.hpp:' <<<"$out"; then
    echo "self-test: the seam's own use was named" >&2; problems=1
  fi
  set +e
  out=$(bash "$0" "$fixture" 2>&1); rc=$?  # the default floor: the fixture's one seam use is too few
  set -e
  echo "\$ threads_seam_test.sh tests/house/fixtures/threads_seam  -> exit $rc"
  echo "$out"
  if [[ $rc -eq 0 ]] || ! grep -q 'too few' <<<"$out"; then
    echo "self-test: the fixture's one seam use passed the default floor" >&2; problems=1
  fi
  if [[ $problems -ne 0 ]]; then echo "self-test: FAILED"; exit 1; fi
  echo "self-test: the check fails on each planted thread and on too few of the seam's uses"
  exit 0
fi

root="${1:-$(cd "$here/../.." && pwd)}"
min_seam="${2:-5}"
cd "$root"
pattern='#[[:space:]]*pragma[[:space:]]+omp\b|_Pragma[[:space:]]*\([[:space:]]*"[[:space:]]*omp\b|__pragma[[:space:]]*\([[:space:]]*omp\b'
pattern+='|\bomp_[a-z_]+[[:space:]]*\(|std::j?thread\b|std::async\b|pthread_create'
seam='^(core/src/dynamics/threads\.(hpp|cpp)|app/util/worker\.hpp):'
dirs=()
for d in core app python; do [[ -d "$d" ]] && dirs+=("$d"); done
if [[ ${#dirs[@]} -eq 0 ]]; then
  echo "threads: none of core/, app/, python/ under $root: is it the project's root?"
  exit 1
fi
rc=0
all=$(grep -rnE "$pattern" "${dirs[@]}" --include='*.cpp' --include='*.hpp' --include='*.h') || rc=$?
if [[ $rc -gt 1 ]]; then echo "threads: grep failed (exit $rc)"; exit 1; fi
found=$(grep -vE "$seam" <<<"$all" | grep . || true)
seam_uses=$(grep -cE "$seam" <<<"$all" || true)
files=$(find "${dirs[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) | wc -l)
outside=$(grep -c . <<<"$found" || true)
echo "threads_seam_test: ${files} files searched in ${dirs[*]}; ${seam_uses} uses in the seam and the worker" \
     "(at least ${min_seam} expected), ${outside} outside"
status=0
if [[ -n "$found" ]]; then
  echo "threads outside the seam (core/src/dynamics/threads.*) and the worker (app/util/worker.hpp):"
  echo "$found"
  status=1
fi
if [[ $seam_uses -lt $min_seam ]]; then
  echo "too few uses found in the seam and the worker (${seam_uses}, fewer than ${min_seam}): is $root the" \
       "project's root, or has the pattern stopped matching?"
  status=1
fi
if [[ $status -eq 0 ]]; then echo "threads: only through the seam and the worker"; fi
exit $status
