#!/usr/bin/env bash
# clang-tidy's checks in .clang-tidy (bugprone-*, performance-*, less six) on every C++ source of
# core/, app/ and python/src/. It reads the unity build's translation units (a folder's files a few
# to a unit, as the build compiles them), so Eigen's templates are parsed once a unit rather than
# once a file: 29 units, 2 min 48 s on 2 cores where file by file took about 17 min. The sources a
# unit includes are checked as the unit's own (HeaderFilterRegex). Exit 1 naming each finding once.
# Usage: scripts/tidy.sh [FILE...]   (FILE: a source or a unit; default: every unit of the build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_TIDY_DIR:-$root/build-tidy}"
command -v clang-tidy-14 >/dev/null || { echo "tidy: clang-tidy-14 not found: apt-get install clang-tidy-14" >&2; exit 1; }
# A configuration of its own: unity units without a precompiled header (clang cannot read GCC's),
# its compile commands written out. Configuring is all it needs: nothing is compiled.
if [[ ! -f "$build/compile_commands.json" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_BUILD_TYPE=Release \
    -DSPRINGLAB_UNITY=ON -DSPRINGLAB_PCH=OFF -DSPRINGLAB_PYTHON=ON -DSPRINGLAB_BUILD_TESTS=OFF \
    -DSPRINGLAB_BUILD_BENCH=OFF >/dev/null
fi
if (($#)); then
  files=("$@")
else
  mapfile -t files < <(python3 -c "import json,sys; [print(e['file']) for e in json.load(open(sys.argv[1]))]" \
    "$build/compile_commands.json" | grep -E "^($root/(core|app|python)/|$build/(core|app|python)/.*/Unity/)" | sort -u)
fi
echo "tidy: ${#files[@]} units"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
# --config-file: a unit lives in the build folder, beyond the reach of the tree's .clang-tidy. A
# unit that clang-tidy ends with an error and no finding at all (it could not start) fails.
tidy_unit='out="$(clang-tidy-14 --config-file="$1/.clang-tidy" -p "$0" --quiet "$2" 2>&1)" ||
  grep -qE "(warning|error): .*\[[a-z-]+(,-warnings-as-errors)?\]$" <<<"$out" ||
  echo "tidy: $2 failed: $(grep -m1 error <<<"$out")"
echo "$out"'
printf '%s\n' "${files[@]}" | xargs -P 2 -I{} bash -c "$tidy_unit" "$build" "$root" {} >"$out" || true
# The units include their sources (.cpp) on purpose: bugprone-suspicious-include's finding in a
# unit itself is not the tree's. It still fires on a source of the tree that includes a .cpp.
findings="$(grep -E "^/[^:]+:[0-9]+:[0-9]+: (warning|error):|^tidy: .* failed" "$out" |
  grep -vE "^$build/.*\[bugprone-suspicious-include" | sort -u || true)"
if [[ -n "$findings" ]]; then
  echo "$findings"
  echo "tidy: $(grep -cE '(warning|error):' <<<"$findings") findings"
  exit 1
fi
echo "tidy: no findings in ${#files[@]} units"
