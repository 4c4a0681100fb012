#!/usr/bin/env bash
# Installs what Lucerna needs to build, test and run, from Debian 12's packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; fi
packages=(cmake make g++ pkg-config qt6-base-dev libqt6opengl6-dev libembree-dev libtbb-dev
          libopenmesh-dev libopenexr-dev openexr libassimp-dev libegl1-mesa-dev libgl1-mesa-dri xvfb xauth
          libopenmpi-dev openmpi-bin poppler-utils)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
