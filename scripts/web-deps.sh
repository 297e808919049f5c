#!/usr/bin/env bash
# Prepares everything the browser (wasm) build of Swarm Lab needs, cached under build/web-deps:
#   build/web-deps/sdl2-prefix   SDL2 2.26.x built for wasm from Debian's own source package
#   build/web-deps/imgui         Dear ImGui 1.86 sources, patched: a link to build/imgui-src (scripts/imgui-sources.sh)
#   build/web-deps/include       symlinks nlohmann -> /usr/include/nlohmann, doctest -> /usr/include/doctest
#                                (never put /usr/include itself on the wasm include path)
# Idempotent: a second run only checks stamp files and takes about a second.
# Needs root (or sudo) the first time, for apt-get (emscripten, nodejs, npm, deb-src sources).
# Usage: scripts/web-deps.sh [--force]   (--force rebuilds SDL2)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
deps="$root/build/web-deps"
src="$deps/src"
dl="$deps/dl"
prefix="$deps/sdl2-prefix"
stamp="$deps/.stamp-v2"
jobs=${WEB_JOBS:-2}
export NODE_PATH=/usr/share/nodejs

say() { printf '[web-deps] %s\n' "$*" >&2; }
die() { printf '[web-deps] ERROR: %s\n' "$*" >&2; exit 1; }

# One preparation at a time (a second caller waits, then finds the stamp).
mkdir -p "$deps"
if command -v flock >/dev/null; then exec 9>"$deps/.lock"; flock 9; fi

[ "${1:-}" = "--force" ] && rm -f "$stamp"
"$root/scripts/deps.sh" web  # emscripten, node, and the headers the wasm build includes

mk_includes() {
  mkdir -p "$deps/include"
  local name
  for name in nlohmann doctest; do
    [ -e "/usr/include/$name" ] || { say "note: /usr/include/$name missing (apt-get install ${name/doctest/doctest-dev}${name/nlohmann/-json3-dev})"; continue; }
    ln -sfn "/usr/include/$name" "$deps/include/$name"
  done
}

if [ -f "$stamp" ] && [ -f "$prefix/lib/libSDL2.a" ] && [ -f "$deps/imgui/imgui.cpp" ]; then
  "$root/scripts/imgui-sources.sh"  # makes the patched copy again if a patch changed (seconds)
  mk_includes
  say "up to date ($(cat "$stamp"))"
  exit 0
fi

t0=$(date +%s)
sudo=""  # apt-get needs root; without root or sudo the apt-get steps fail with apt's own message
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then sudo="sudo"; fi
apt_updated=0
apt_update() { [ $apt_updated -eq 1 ] || { say "apt-get update"; $sudo apt-get update -qq; apt_updated=1; }; }

say "emcc: $(emcc --version 2>/dev/null | head -1)"

# 2. ImGui 1.86's sources, shared with the desktop build (this also turns on the deb-src
# entries that the SDL2 source package below needs).
"$root/scripts/imgui-sources.sh"
ln -sfn "$root/build/imgui-src" "$deps/imgui"
imgui_ver=$(sed -n 's/^#define IMGUI_VERSION *"\(.*\)"/\1/p' "$deps/imgui/imgui.h")
say "ImGui $imgui_ver ready at ${deps#"$root"/}/imgui"

# 3. Fetch the Debian source packages (cached in build/web-deps/dl).
mkdir -p "$dl" "$src"
fetch() { # $1 = source package name
  if ls "$dl/$1"_*.dsc >/dev/null 2>&1; then say "source package $1 already downloaded"; return; fi
  say "downloading Debian source package $1"
  if ! (cd "$dl" && apt-get source --download-only -qq "$1" >&2 2>/dev/null); then
    apt_updated=0; apt_update
    (cd "$dl" && apt-get source --download-only -qq "$1" >&2) || die "apt-get source $1 failed"
  fi
}
fetch libsdl2

unpack() { # $1 = source package name, $2 = destination dir; unpacks with Debian's patches applied
  local dsc; dsc=$(ls "$dl/$1"_*.dsc | sort -V | tail -1)
  rm -rf "$2"
  say "unpacking $(basename "$dsc") into ${2#"$root"/}"
  dpkg-source --no-check -x "$dsc" "$2" >/dev/null 2>&1 || die "dpkg-source -x $dsc failed"
}

# 4. SDL2 for wasm, built as Emscripten's own port builds it (tools/ports/sdl2.py): the sources
# of what a browser has (the Emscripten video, events, audio and timer drivers, the GLES2
# renderer, the generic threads of a build without pthreads), each compiled with the
# SDL_config.h that SDL ships for Emscripten (include/SDL_config_emscripten.h). SDL's CMake
# configure would run some 300 compile checks through emcc first: about 4 minutes here.
unpack libsdl2 "$src/sdl2"
rm -rf "$deps/sdl2-build" "$prefix"
mkdir -p "$deps/sdl2-build" "$prefix/lib" "$prefix/include/SDL2"
sdl_src="$src/sdl2/src"
sdl_dirs="atomic audio audio/disk audio/dummy audio/emscripten cpuinfo dynapi events file
  filesystem/emscripten haptic haptic/dummy hidapi joystick joystick/emscripten joystick/virtual
  loadso/dlopen locale locale/emscripten main/dummy misc misc/emscripten power power/emscripten
  render render/opengles2 render/software sensor sensor/dummy stdlib thread thread/generic timer
  timer/unix video video/dummy video/emscripten video/yuv2rgb"
say "building SDL2 for wasm with -j$jobs (about a minute on 2 cores; log: build/web-deps/sdl2-build.log)"
# shellcheck disable=SC2086  # the directories are words
(for d in "" $sdl_dirs; do ls "$sdl_src${d:+/$d}"/*.c; done) >"$deps/sdl2-build/sources"
# Each object named for its path under src/ (two files may share a name).
compile_sdl() { local o; o=${1#"$sdl_src"/}; nice emcc -c "$1" -o "$deps/sdl2-build/${o//\//_}.o" -I"$src/sdl2/include" -O2 -w; }
export -f compile_sdl; export sdl_src deps src
xargs -P "$jobs" -I{} bash -c 'compile_sdl "$1"' _ {} <"$deps/sdl2-build/sources" >"$deps/sdl2-build.log" 2>&1 \
  || { tail -30 "$deps/sdl2-build.log" >&2; die "SDL2 build failed (log: $deps/sdl2-build.log)"; }
emar rcs "$prefix/lib/libSDL2.a" "$deps/sdl2-build"/*.o
cp "$src/sdl2/include"/*.h "$prefix/include/SDL2/"
[ -f "$prefix/lib/libSDL2.a" ] || die "libSDL2.a not installed in $prefix"
sdl_ver=$(basename "$(ls -d "$dl"/libsdl2_*.dsc)" .dsc | sed 's/^libsdl2_//')
say "SDL2 $sdl_ver installed in ${prefix#"$root"/}"

mk_includes
echo "SDL2 $sdl_ver, ImGui $imgui_ver" >"$stamp"
say "done in $(( $(date +%s) - t0 ))s"
