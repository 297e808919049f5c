#!/usr/bin/env bash
# Unpacks Dear ImGui 1.86's sources from Debian's source package into build/imgui-src and
# applies Swarm Lab's patches (third_party/imgui/patches/*.patch, in order), for the desktop and
# the browser builds alike: both compile this one copy, so that its item hooks
# (IMGUI_ENABLE_TEST_ENGINE, which Debian's packaged libimgui leaves out) feed the parallel DOM
# (app/ui/parallel_dom/README.md). Idempotent: the stamp names the source package and each
# patch's SHA-256; while it matches, a run takes no time. When a patch changes, the sources are
# unpacked afresh into a new folder, patched there and only then put in place of the old, so a
# tree is never patched twice and a failed patch leaves no half-patched tree behind.
# Needs root (or sudo) the first time, for apt-get (dpkg-dev, deb-src entries).
set -euo pipefail
export LC_ALL=C  # the patches' order, and the stamp's, is the C locale's

root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/build/imgui-src"
dl="$root/build/imgui-dl"
patches="$root/third_party/imgui/patches"
stamp="$out/.stamp-v2"  # third_party/imgui/imgui_library.cmake reads it

say() { printf '[imgui-sources] %s\n' "$*" >&2; }
die() { printf '[imgui-sources] ERROR: %s\n' "$*" >&2; exit 1; }

mkdir -p "$root/build"
if command -v flock >/dev/null; then exec 8>"$root/build/.imgui-sources.lock"; flock 8; fi
# What the stamp says of a tree made now: the source package, then "SHA-256  name" per patch.
wanted_stamp() { basename "$1" .dsc; (cd "$patches" && sha256sum -- *.patch); }
if [ -f "$stamp" ] && [ -f "$out/imgui.cpp" ]; then
  dsc=$(ls "$dl"/imgui_*.dsc 2>/dev/null | sort -V | tail -1) || true
  [ -n "$dsc" ] && [ "$(wanted_stamp "$dsc")" = "$(cat "$stamp")" ] && exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null; then sudo="sudo"; fi
updated=0
update() { [ $updated -eq 1 ] || { say "apt-get update"; $sudo apt-get update -qq; updated=1; }; }

if ! command -v dpkg-source >/dev/null || ! command -v patch >/dev/null; then
  update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends dpkg-dev patch >&2
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
new="$out.new"
rm -rf "$new"
dpkg-source --no-check -x "$dsc" "$new" >/dev/null 2>&1 || die "dpkg-source -x $dsc failed"
for f in imgui.cpp backends/imgui_impl_sdl.cpp backends/imgui_impl_opengl3.cpp misc/cpp/imgui_stdlib.cpp; do
  [ -f "$new/$f" ] || die "ImGui sources incomplete: no $f in $new"
done
version=$(sed -n 's/^#define IMGUI_VERSION *"\(.*\)"/\1/p' "$new/imgui.h")

# Each patch must apply exactly (no fuzz; a shifted line is fine): tried first, then applied.
for p in "$patches"/*.patch; do
  name=${p#"$root"/}
  if ! log=$(patch -d "$new" -p1 --dry-run --forward --batch --fuzz=0 <"$p" 2>&1); then
    printf '%s\n' "$log" >&2
    die "$name does not apply to Debian's imgui $version ($(basename "$dsc" .dsc)):" \
        "the patches are made for 1.86 (docs/architecture.md, \"A newer Dear ImGui\")"
  fi
  patch -d "$new" -p1 --forward --batch --fuzz=0 --no-backup-if-mismatch --quiet <"$p" \
    || die "$name failed after its dry run succeeded"
done
[ "$version" = "1.86" ] || die "Debian's imgui is $version; third_party/imgui/patches are for 1.86"

wanted_stamp "$dsc" >"$new/.stamp-v2"
rm -rf "$out"
mv "$new" "$out"
say "ImGui $version unpacked into build/imgui-src with $(ls "$patches"/*.patch | wc -l) patches"
