#!/usr/bin/env bash
# Installs, builds, and runs every test (CTest; the window's GL tests in Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
