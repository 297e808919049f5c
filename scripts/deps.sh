#!/usr/bin/env bash
# Installs the Debian packages Swarm Lab needs, only those still missing, so a second run
# costs a second. Usage: scripts/deps.sh [native] [desktop] [web] [serve] [webtest] [fuzz]
set -euo pipefail

# Each group holds everything its own build or run needs, so that any one script works on a
# fresh machine with only the groups it asks for (scripts/fresh-check.sh checks that).
declare -A groups=(
  [native]="g++ cmake make python3 libeigen3-dev nlohmann-json3-dev doctest-dev libcli11-dev libbenchmark-dev librsvg2-bin parallel"
  [desktop]="dpkg-dev libsdl2-dev libstb-dev fonts-dejavu-core fonts-noto-cjk fonttools xvfb xauth xdotool"
  [web]="emscripten nodejs npm cmake make python3 dpkg-dev libeigen3-dev nlohmann-json3-dev doctest-dev libstb-dev fonts-noto-cjk fonttools librsvg2-bin brotli gzip"
  # The web server of scripts/web.sh (web/serve/Caddyfile).
  [serve]="caddy"
  [webtest]="chromium"
  [fuzz]="clang libclang-rt-14-dev cmake git libeigen3-dev nlohmann-json3-dev nodejs"
)

wanted=()
for group in "${@:-native}"; do
  for pkg in ${groups[$group]}; do
    # node and npm may come from elsewhere than Debian (e.g. NodeSource): a working command counts.
    case $pkg in nodejs) command -v node >/dev/null && continue ;; npm) command -v npm >/dev/null && continue ;; esac
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || wanted+=("$pkg")
  done
done
[ ${#wanted[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "deps: need root or sudo to install: ${wanted[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "deps: installing ${wanted[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${wanted[@]}" >&2
