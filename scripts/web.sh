#!/usr/bin/env bash
# springlab in the browser: installs what is missing (Debian's emscripten, Chromium and Node's
# npm; Dear ImGui's sources from Debian's source package), builds the app for WebAssembly +
# WebGL2 and writes the static site into build-web/: index.html, springlab.js, springlab.wasm,
# springlab.data, and for offline use and a phone's home screen sw.js (the service worker),
# manifest.webmanifest, two icons and Homework 8's scripts, which any static web host serves as
# they are: build-web/ holds the site and nothing else (the build tree is build-wasm/).
# Usage: scripts/web.sh            build, and print the site's size
#        scripts/web.sh --serve    build, then serve build-web/ on http://127.0.0.1:PORT/ (PORT: 8765,
#                                  or $SPRINGLAB_WEB_PORT) until Ctrl-C
#        scripts/web.sh --test     build, then run the browser tests (tests/web/run.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
site="$root/build-web"
build="$root/build-wasm"
deps="$build/_deps"
mode="${1:-}"
case "$mode" in
  ""|--serve|--test) ;;
  *) echo "scripts/web.sh: unknown option '$mode' (use --serve or --test)" >&2; exit 2 ;;
esac

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "web.sh: not root and no sudo: run as root once to install packages" >&2; exit 1; }
  sudo=(sudo)
fi
apt() { DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=300 -q "$@"; }

# Debian's packages, only those missing. (Node: the machine's own when it has one.)
packages=(emscripten node-acorn chromium cmake ninja-build libeigen3-dev nlohmann-json3-dev libboost-dev googletest fonts-dejavu-core
          fonts-noto-cjk python3-fonttools python3 xz-utils)
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "web.sh: installing ${missing[*]}"
  apt update
  apt install -y --no-install-recommends "${missing[@]}"
fi

# Dear ImGui 1.86's sources (libimgui-dev ships it compiled for the desktop only), from Debian's
# source package: needs a deb-src line for bookworm main.
imgui="$deps/imgui-1.86"
if [[ ! -f "$imgui/imgui.cpp" ]]; then
  mkdir -p "$deps"
  if ! (cd "$deps" && apt-get source --download-only imgui >/dev/null 2>&1); then
    if ! grep -rqs "deb-src\|Types:.*deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
      echo "web.sh: adding Debian's source packages (deb-src, bookworm main) to apt's sources"
      printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
        "${sudo[@]}" tee /etc/apt/sources.list.d/springlab-deb-src.sources >/dev/null
    fi
    apt update
    (cd "$deps" && apt-get source --download-only imgui >/dev/null 2>&1)
  fi
  tar -xf "$deps"/imgui_1.86*.orig.tar.xz -C "$deps"
fi

# The build tree of older clones, inside the site (build-web/_build): gone, so that the folder a
# teacher copies is the site alone.
if [[ -d "$site/_build" ]]; then
  echo "web.sh: the build tree moved from build-web/_build to build-wasm/: removing the old one"
  rm -rf "$site/_build"
fi

# Build. Debian's emscripten: its JavaScript optimiser needs Debian's acorn (NODE_PATH), and its
# system libraries come prebuilt in its own cache (EM_CACHE left alone).
export NODE_PATH=/usr/share/nodejs
if [[ ! -f "$build/build.ninja" ]]; then
  emcmake cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DSPRINGLAB_WEB_SITE_DIR="$site" -DSPRINGLAB_IMGUI_DIR="$imgui" >/dev/null
fi
cmake --build "$build" --parallel "$(nproc)"

files=(index.html springlab.js springlab.wasm springlab.data sw.js manifest.webmanifest icon-192.png icon-512.png homework.js acorn.js acorn-walk.js access.js)
bytes=0 gz=0
for f in "${files[@]}"; do
  bytes=$((bytes + $(stat -c %s "$site/$f")))
  gz=$((gz + $(gzip -9c "$site/$f" | wc -c)))
done
awk -v b="$bytes" -v g="$gz" -v f="${files[*]}" \
  'BEGIN { printf "web.sh: build-web/ holds the site (%s): %.2f MB, %.2f MB gzipped\n", f, b / 1e6, g / 1e6 }'
sed -n 's/^const CACHE = "\(.*\)";$/web.sh: its service worker keeps it offline in the cache \1/p' "$site/sw.js"

case "$mode" in
  --serve)
    port="${SPRINGLAB_WEB_PORT:-8765}"
    echo "web.sh: springlab at http://127.0.0.1:$port/ (Ctrl-C stops)"
    exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
    ;;
  --test)
    exec "$root/tests/web/run.sh"
    ;;
esac
