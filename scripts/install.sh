#!/usr/bin/env bash
# Puts springlab on PATH: builds the app if needed (as scripts/run.sh does) and installs it with
# its scenes, lessons, shaders and fonts into PREFIX (default ~/.local): PREFIX/bin/springlab,
# PREFIX/share/springlab. The documentation's examples write `springlab` for that command (or
# build/springlab, without installing). Uninstall: remove those two.
# Usage: scripts/install.sh [PREFIX]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
prefix="${1:-$HOME/.local}"
"$root/scripts/setup.sh"
"$root/scripts/build.sh" --target springlab
cmake --install "${SPRINGLAB_BUILD_DIR:-$root/build}" --component app --prefix "$prefix" >/dev/null
echo "installed $prefix/bin/springlab (and $prefix/share/springlab)"
if [[ "$(command -v springlab || true)" != "$prefix/bin/springlab" ]]; then
  echo "$prefix/bin is not first on PATH for springlab: add it, e.g. echo 'export PATH=\"$prefix/bin:\$PATH\"' >> ~/.bashrc"
  echo "(Debian's ~/.profile adds ~/.local/bin at the next login once it exists)"
fi
