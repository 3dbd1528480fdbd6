#!/usr/bin/env bash
# The tidy check (scripts/tidy.sh, run on the whole tree by scripts/test.sh) can fail: on
# tests/house/fixtures/tidy/planted.cpp it must exit 1 naming both planted defects at their lines,
# and on clean.cpp, the same work written well, exit 0 with no finding.
# Usage: tidy_self_test.sh ROOT BUILD_DIR   (BUILD_DIR: where tidy.sh configures its own build)
set -uo pipefail
root="$1"
export SPRINGLAB_TIDY_DIR="$2"
fixture="$root/tests/house/fixtures/tidy"
problems=0
out="$("$root/scripts/tidy.sh" "$fixture/planted.cpp" 2>&1)"
status=$?
echo "$ scripts/tidy.sh tests/house/fixtures/tidy/planted.cpp  -> exit $status"
echo "$out"
[[ $status -eq 1 ]] || { echo "tidy self-test: the planted file did not fail the check"; problems=1; }
grep -q "planted.cpp:10:10: .*\[performance-no-automatic-move" <<<"$out" ||
  { echo "tidy self-test: the const local returned (line 10) was not named"; problems=1; }
grep -q "planted.cpp:15:22: .*\[performance-move-const-arg" <<<"$out" ||
  { echo "tidy self-test: the std::move of a const (line 15) was not named"; problems=1; }
out="$("$root/scripts/tidy.sh" "$fixture/clean.cpp" 2>&1)"
status=$?
echo "$ scripts/tidy.sh tests/house/fixtures/tidy/clean.cpp  -> exit $status"
echo "$out"
[[ $status -eq 0 ]] || { echo "tidy self-test: the clean file failed the check"; problems=1; }
((problems == 0)) && echo "tidy self-test: both ways as expected"
exit $problems
