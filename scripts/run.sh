#!/usr/bin/env bash
# Installs, builds, and starts Amazeballs: the window on stage 1 (arguments go to it,
# e.g. --scene many-balls --play). Without a display it says so and prints the
# command line's summary of stage 1 instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; then
  exec build/app/amazeballs "$@"
fi
echo "run: no display (DISPLAY is not set), so no window; stage 1 from the command line instead:" >&2
exec build/app/amazeballs-cli run bounce1d --summary
