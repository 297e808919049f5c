#!/usr/bin/env bash
# Builds the browser version of Swarm Lab into build/web/ and serves it.
#   scripts/web.sh               build, then serve on http://127.0.0.1:8080 (this machine only)
#   scripts/web.sh --build-only  build only
#   scripts/web.sh --lan         build, then serve on all interfaces (0.0.0.0:8080) for a classroom
#   scripts/web.sh --port N      another port (also: PORT=N)
# The first run prepares SDL2/ImGui for wasm (scripts/web-deps.sh, a few minutes, needs root for
# apt-get); later runs only rebuild what changed. Environment: WEB_JOBS (parallel compile jobs,
# default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

build_only=0
bind=127.0.0.1
port=${PORT:-8080}
while [ $# -gt 0 ]; do
  case $1 in
    --build-only) build_only=1 ;;
    --lan) bind=0.0.0.0 ;;
    --port) port=$2; shift ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "web.sh: unknown option $1 (try --help)" >&2; exit 2 ;;
  esac
  shift
done

export NODE_PATH=/usr/share/nodejs
jobs=${WEB_JOBS:-2}
say() { printf '[web] %s\n' "$*" >&2; }

t0=$(date +%s)
scripts/web-deps.sh

bdir=build-wasm
mkdir -p build
# One build of build/web at a time (another caller, e.g. the browser test, waits).
if command -v flock >/dev/null; then exec 9>build/.web-build.lock; flock 9; fi
generator=()
if [ ! -f "$bdir/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
say "configuring ($bdir)"
emcmake cmake -S . -B "$bdir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DSWARMLAB_WEB=ON >"$root/build/web-configure.log" 2>&1 \
  || { cat "$root/build/web-configure.log" >&2; say "configure failed"; exit 1; }
say "building with -j$jobs"
# swarmlab_offline: the manifest, icons and service worker (web/CMakeLists.txt), after the page.
nice cmake --build "$bdir" -j"$jobs" --target swarmlab_web swarmlab_offline
for f in index.html swarmlab.js swarmlab.wasm service_worker.js manifest.webmanifest; do
  [ -f "build/web/$f" ] || { say "missing build/web/$f"; exit 1; }
done
wasm_bytes=$(stat -c %s build/web/swarmlab.wasm)
say "built build/web/ in $(( $(date +%s) - t0 ))s: swarmlab.wasm $(( wasm_bytes / 1024 )) KiB, swarmlab.js $(( $(stat -c %s build/web/swarmlab.js) / 1024 )) KiB"

[ $build_only -eq 1 ] && exit 0

if [ "$bind" = 0.0.0.0 ]; then
  say "serving build/web for the classroom on port $port. Students open one of:"
  for ip in $(hostname -I 2>/dev/null); do
    case $ip in *:*) ;; *) say "    http://$ip:$port/" ;; esac
  done
  say "(the computers must be on the same network, and a firewall must allow port $port)"
else
  say "serving on http://127.0.0.1:$port/ (this computer only; --lan for a classroom). Ctrl-C stops."
fi
exec 9>&-  # do not hold the build lock while serving
exec python3 -m http.server --bind "$bind" --directory build/web "$port"
