#!/usr/bin/env bash
# Records every shipped lesson as a video, captions and progress bar burned in, one mp4 a lesson:
# DIR/01-hooke.mp4, DIR/02-damping-vs-drag.mp4, ... (DIR: out/lessons). Builds first. About ten
# minutes on two cores (software rasteriser, 1280x720, 60 frames a second).
# Usage: scripts/lesson-videos.sh [DIR] [render options, e.g. --size 1920x1080]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
dir="${1:-$root/out/lessons}"
shift || true
"$root/scripts/setup.sh"
"$root/scripts/build.sh" --target springlab >/dev/null
bin="${SPRINGLAB_BUILD_DIR:-$root/build}/springlab"
mkdir -p "$dir"
"$bin" lesson list | while read -r number name _; do
  file="$dir/$(printf '%02d' "$number")-$name.mp4"
  "$bin" render --lesson "$name" --video "$file" "$@" | head -1
done
echo "lesson-videos.sh: the course's videos are in $dir"
