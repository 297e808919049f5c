#!/usr/bin/env bash
# Configures and builds the native tree in build/ (incremental after the first time).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh native desktop
jobs=$(nproc 2>/dev/null || echo 2)
# The desktop window compiles ImGui from Debian's sources, with the parallel DOM's item hooks.
grep -q 'SWARMLAB_DESKTOP:BOOL=OFF' build/CMakeCache.txt 2>/dev/null || scripts/imgui-sources.sh
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs" "$@"
