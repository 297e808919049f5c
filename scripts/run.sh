#!/usr/bin/env bash
# The main job: installs what is missing, builds, and opens Swarm Lab with the default preset.
# Without a display (a server, CI) it runs the default preset headless and prints the results.
# Any arguments are passed to swarmlab, e.g. scripts/run.sh run assets/presets/fig4-equilibration.json
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh native desktop
scripts/build.sh --target swarmlab >/dev/null
default=assets/presets/fig1-four-masses.json
if [ $# -gt 0 ]; then
  exec build/app/swarmlab "$@"
elif [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && build/app/swarmlab --help | grep -q -- --frames; then
  exec build/app/swarmlab "$default"
else
  echo "No display: running $default headless (scripts/run.sh PRESET.json opens a window)."
  exec build/app/swarmlab run "$default"
fi
