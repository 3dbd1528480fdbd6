#!/usr/bin/env bash
# Builds the API documentation (scripts/docs.sh) into a scratch folder and checks that each main
# type of the public headers has its page, with its brief description on it: a type whose ///
# comment is lost has no page (docs/Doxyfile: EXTRACT_ALL = NO), and this test fails naming it.
# Usage: tests/docs/api_pages_test.sh SCRATCH_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="$1"
rm -rf "$out"
"$root/scripts/docs.sh" "$out" >/dev/null

# page: words its brief description must contain
pages=(
  "structspringlab_1_1Model.html:the constants of a scene"
  "structspringlab_1_1State.html:what an integrator advances"
  "classspringlab_1_1Simulation.html:advanced step by step"
  "classspringlab_1_1StabilityAnalysis.html:computed once"
  "structspringlab_1_1MethodInfo.html:row of the method table"
  "classspringlab_1_1Points.html:N x 3 doubles"
)
missing=0
for entry in "${pages[@]}"; do
  page="${entry%%:*}" words="${entry#*:}"
  if [[ ! -f "$out/$page" ]]; then
    echo "missing page: $page" >&2
    missing=1
  elif ! grep -q "$words" "$out/$page"; then
    echo "$page: no '$words' in it (its /// comment?)" >&2
    missing=1
  fi
done
[[ -f "$out/index.html" ]] || { echo "missing page: index.html" >&2; missing=1; }
((missing == 0)) && echo "docs: ${#pages[@]} main types' pages present"
exit "$missing"
