#!/usr/bin/env bash
# Installs what is missing, builds, and starts springlab.
#   With a display: the interactive app (extra arguments go to it, e.g. scripts/run.sh view rope).
#   Without one: a demo run of every scene, headless, printing what it did.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
bin="$root/build/springlab"
if [[ $# -gt 0 ]]; then
  exec "$bin" "$@"
fi
echo "No display and no arguments: simulating each shipped scene headlessly."
for scene in $("$bin" list | awk '$1 == "scene" {print $2}'); do
  echo
  echo "== springlab run $scene"
  "$bin" run "$scene" --duration 3 || echo "(exit status $?: see the message above)"
done
