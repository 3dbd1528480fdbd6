#!/usr/bin/env bash
# clang-tidy's checks in .clang-tidy (bugprone-*, performance-*, less four), on every C++ source of
# core/, app/ and python/src/, two files at a time. Each file takes about 15 s (the parse of its
# Eigen templates), so the whole tree about 17 minutes on 2 cores: not part of scripts/test.sh
# (CI's 25 minutes hold the build, the suite, the checking build and the browser's), but run before
# a change to the core or the app is merged. Exit 1 naming each warning.
# Usage: scripts/tidy.sh [FILE...]   (default: every source file the build compiles)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_TIDY_DIR:-$root/build-tidy}"
command -v clang-tidy-14 >/dev/null || { echo "tidy: clang-tidy-14 not found: apt-get install clang-tidy-14" >&2; exit 1; }
# A configuration of its own, each file alone (no unity build), its compile commands written out.
if [[ ! -f "$build/compile_commands.json" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DSPRINGLAB_UNITY=OFF -DSPRINGLAB_PCH=OFF \
    -DSPRINGLAB_PYTHON=ON -DSPRINGLAB_BUILD_TESTS=OFF -DSPRINGLAB_BUILD_BENCH=OFF >/dev/null
fi
if (($#)); then
  files=("$@")
else
  mapfile -t files < <(python3 -c "import json,sys; [print(e['file']) for e in json.load(open(sys.argv[1]))]" \
    "$build/compile_commands.json" | grep -E "^$root/(core|app|python)/" | sort -u)
fi
echo "tidy: ${#files[@]} files"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
status=0
printf '%s\n' "${files[@]}" | xargs -P 2 -I{} sh -c 'clang-tidy-14 -p "$0" --quiet "$1" 2>/dev/null || echo "tidy: $1 failed"' "$build" {} >"$out" || status=1
if grep -qE 'warning:|error:|tidy: .* failed' "$out"; then
  grep -E 'warning:|error:|tidy: .* failed' "$out"
  echo "tidy: $(grep -cE 'warning:|error:' "$out") findings"
  exit 1
fi
echo "tidy: no findings"
exit $status
