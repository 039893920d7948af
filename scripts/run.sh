#!/usr/bin/env bash
# Installs, builds, and starts Amazeballs on its default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec build/app/amazeballs-cli run bounce1d --summary "$@"
