#!/usr/bin/env bash
# Builds the browser version of Swarm Lab into build/web/ and serves it.
#   scripts/web.sh               build, then serve on http://127.0.0.1:8080 (this machine only)
#   scripts/web.sh --build-only  build only
#   scripts/web.sh --no-build    serve what build/web holds, without building
#   scripts/web.sh --lan         build, then serve on all interfaces (0.0.0.0:8080) for a classroom
#   scripts/web.sh --port N      another port (also: PORT=N)
# The server is Debian's caddy with web/serve/Caddyfile (compressed copies, cache headers), in
# the foreground: Ctrl-C stops it. The first run prepares SDL2/ImGui for wasm
# (scripts/web-deps.sh, a few minutes, needs root for apt-get); later runs only rebuild what
# changed. Environment: WEB_JOBS (parallel compile jobs, default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

build_only=0
build=1
bind=127.0.0.1
port=${PORT:-8080}
while [ $# -gt 0 ]; do
  case $1 in
    --build-only) build_only=1 ;;
    --no-build) build=0 ;;
    --lan) bind=0.0.0.0 ;;
    --port) port=$2; shift ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "web.sh: unknown option $1 (try --help)" >&2; exit 2 ;;
  esac
  shift
done

export NODE_PATH=/usr/share/nodejs
jobs=${WEB_JOBS:-2}
say() { printf '[web] %s\n' "$*" >&2; }

if [ $build -eq 1 ]; then
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
  # swarmlab_publish: the page, its files under their hashed names with compressed copies, the
  # manifest and the service worker (web/CMakeLists.txt, web/publish.py).
  nice cmake --build "$bdir" -j"$jobs" --target swarmlab_publish
  # (The published names carry their content's hash: swarmlab.3f2a9c1b.wasm.)
  for f in index.html service_worker.js manifest.webmanifest 'swarmlab.*.js' 'swarmlab.*.wasm'; do
    compgen -G "build/web/$f" >/dev/null || { say "missing build/web/$f"; exit 1; }
  done
  kib() { echo $(( $(stat -c %s "$1") / 1024 )); }
  sizes() { echo "$(kib "$1") KiB ($(kib "$1.br") KiB as br, $(kib "$1.gz") KiB as gz)"; }
  say "built build/web/ in $(( $(date +%s) - t0 ))s: swarmlab.wasm $(sizes build/web/swarmlab.*.wasm), swarmlab.js $(sizes build/web/swarmlab.*.js)"
fi

[ $build_only -eq 1 ] && exit 0
[ -f build/web/index.html ] || { say "build/web holds no page: run scripts/web.sh without --no-build"; exit 1; }
scripts/deps.sh serve

if [ "$bind" = 0.0.0.0 ]; then
  say "serving build/web for the classroom on port $port. Students open one of:"
  for ip in $(hostname -I 2>/dev/null); do
    case $ip in *:*) ;; *) say "    http://$ip:$port/" ;; esac
  done
  say "(the computers must be on the same network, and a firewall must allow port $port). Ctrl-C stops."
else
  say "serving on http://127.0.0.1:$port/ (this computer only; --lan for a classroom). Ctrl-C stops."
fi
exec 9>&-  # do not hold the build lock while serving
# Caddy's own folders (it keeps a copy of its running config there) inside build/.
mkdir -p build/serve
export XDG_CONFIG_HOME="$root/build/serve/config" XDG_DATA_HOME="$root/build/serve/data"
export SWARMLAB_ROOT="$root/build/web" SWARMLAB_BIND="$bind" SWARMLAB_PORT="$port"
exec caddy run --adapter caddyfile --config web/serve/Caddyfile
