#!/usr/bin/env bash
# The app installed as scripts/install.sh installs it (cmake --install, component app) runs from
# its prefix alone: from a scratch folder, with the source tree out of its sight, it loads a
# shipped scene, renders a frame with its shaders and its Chinese font, and says where its data is.
# Usage: app_test.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1" work="$2"
rm -rf "$work" && mkdir -p "$work/elsewhere"
cmake --install "$build" --component app --prefix "$work/prefix" >/dev/null
for f in bin/springlab share/springlab/assets/scenes/rope.json share/springlab/shaders share/springlab/fonts/springlab-cjk.otf; do
  [[ -e "$work/prefix/$f" ]] || { echo "the install lacks $f"; exit 1; }
done
cd "$work/elsewhere"
unset SPRINGLAB_DATA
"$work/prefix/bin/springlab" run rope --duration 0.05 --csv rope.csv
"$work/prefix/bin/springlab" render spring --lang zh-CN --ui --frames 1 --out frames | tee render.txt
ls frames/*.png >/dev/null
# Its data is the prefix's (share/springlab beside the executable's bin), not the source tree's: a scene
# only the prefix has is found by name.
cp "$work/prefix/share/springlab/assets/scenes/spring.json" "$work/prefix/share/springlab/assets/scenes/only-installed.json"
"$work/prefix/bin/springlab" run only-installed --duration 0.05 >/dev/null
echo "the installed app ran from $work/prefix"
