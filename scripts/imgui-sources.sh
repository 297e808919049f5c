#!/usr/bin/env bash
# Unpacks Dear ImGui 1.86's sources from Debian's source package into build/imgui-src, for the
# desktop and the browser builds alike: both compile ImGui themselves so that its item hooks
# (IMGUI_ENABLE_TEST_ENGINE, which Debian's packaged libimgui leaves out) feed the parallel DOM
# (app/ui/parallel_dom/README.md). Idempotent: a second run checks a stamp and takes no time.
# Needs root (or sudo) the first time, for apt-get (dpkg-dev, deb-src entries).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/build/imgui-src"
dl="$root/build/imgui-dl"
stamp="$out/.stamp-v1"

say() { printf '[imgui-sources] %s\n' "$*" >&2; }
die() { printf '[imgui-sources] ERROR: %s\n' "$*" >&2; exit 1; }

mkdir -p "$root/build"
if command -v flock >/dev/null; then exec 8>"$root/build/.imgui-sources.lock"; flock 8; fi
[ -f "$stamp" ] && [ -f "$out/imgui.cpp" ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then sudo="sudo"; fi
updated=0
update() { [ $updated -eq 1 ] || { say "apt-get update"; $sudo apt-get update -qq; updated=1; }; }

if ! command -v dpkg-source >/dev/null; then
  update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends dpkg-dev >&2
fi

# deb-src entries in a file of their own (the original is left alone).
srclist=/etc/apt/sources.list.d/debian-src.sources
if [ ! -f "$srclist" ]; then
  say "enabling deb-src in $srclist"
  [ -f /etc/apt/sources.list.d/debian.sources ] || die "/etc/apt/sources.list.d/debian.sources not found"
  sed 's/^Types:.*/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $sudo tee "$srclist" >/dev/null
  updated=0
fi

mkdir -p "$dl"
if ! ls "$dl"/imgui_*.dsc >/dev/null 2>&1; then
  say "downloading Debian source package imgui"
  if ! (cd "$dl" && apt-get source --download-only -qq imgui >&2 2>/dev/null); then
    updated=0; update
    (cd "$dl" && apt-get source --download-only -qq imgui >&2) || die "apt-get source imgui failed"
  fi
fi

dsc=$(ls "$dl"/imgui_*.dsc | sort -V | tail -1)
rm -rf "$out"
dpkg-source --no-check -x "$dsc" "$out" >/dev/null 2>&1 || die "dpkg-source -x $dsc failed"
for f in imgui.cpp backends/imgui_impl_sdl.cpp backends/imgui_impl_opengl3.cpp misc/cpp/imgui_stdlib.cpp; do
  [ -f "$out/$f" ] || die "ImGui sources incomplete: no $f in $out"
done
version=$(sed -n 's/^#define IMGUI_VERSION *"\(.*\)"/\1/p' "$out/imgui.h")
[ "$version" = "1.86" ] || die "Debian's imgui is $version; app/ui/parallel_dom/imgui_hooks.cmake edits 1.86"
echo "$(basename "$dsc" .dsc)" >"$stamp"
say "ImGui $version unpacked into build/imgui-src"
