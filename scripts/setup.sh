#!/usr/bin/env bash
# Installs what a fresh Debian 12 machine lacks (apt-get, as root or through sudo) and
# builds Amazeballs into build/. Safe to run again: it installs only what is missing and
# rebuilds only what changed. AMAZEBALLS_BUILD_DIR builds elsewhere (build-asan, ...) and
# AMAZEBALLS_EXTRA_PACKAGES names more packages to install (clang for the fuzz targets).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-svg-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n libeigen3-dev libgl-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev nlohmann-json3-dev
  xvfb xauth libgl1-mesa-dri fontconfig fonts-dejavu-core
  appstream desktop-file-utils dpkg-dev poppler-utils libcli11-dev groff-base zsh)
read -r -a extra <<< "${AMAZEBALLS_EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
build_dir=${AMAZEBALLS_BUILD_DIR:-build}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  echo "setup: installing ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths relative to the checkout, so that another clone of the same sources reuses the cache.
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
