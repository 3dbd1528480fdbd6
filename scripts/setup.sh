#!/usr/bin/env bash
# Installs the Debian packages springlab needs, only those missing (idempotent).
# Usage: scripts/setup.sh        (uses sudo when not root)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev nlohmann-json3-dev libcli11-dev libboost-dev
  libglfw3-dev libimgui-dev libstb-dev libepoxy-dev libpng-dev
  libegl-dev libgl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0 libgl1
  libgtest-dev libbenchmark-dev
  xvfb xauth ffmpeg fonts-dejavu-core
  fonts-noto-cjk python3-fonttools gettext
  clang clang-format-14 clang-tidy-14 libclang-rt-14-dev libomp-dev
  python3-dev python3-venv python3-pybind11 python3-numpy python3-pytest python3-pip python3-setuptools python3-wheel
  python3-nbconvert python3-ipykernel python3-matplotlib doxygen
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: not root and no sudo; install as root: apt-get install ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get -o DPkg::Lock::Timeout=300 update -q
"${sudo[@]}" apt-get -o DPkg::Lock::Timeout=300 install -y -q --no-install-recommends "${missing[@]}"
