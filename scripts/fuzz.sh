#!/usr/bin/env bash
# Fuzzes preset parsing, validation and the resource estimate with libFuzzer (Debian's clang,
# AddressSanitizer and UndefinedBehaviorSanitizer), seeded with the shipped presets, the reader
# of ensembles' run records (tests/fuzz/run_record_fuzz.cpp, seeded with tests/fuzz/run_records/),
# and the browser's share-link decoding under node (tests/fuzz/share_link_fuzz.mjs), as well as the
# embed bridge's message parser (tests/fuzz/embed_bridge_fuzz.mjs).
# Usage: scripts/fuzz.sh [seconds] (default 60). New interesting inputs collect in
# build-fuzz/corpus and make the next run start further; a crash leaves build-fuzz/crash-*,
# which `build-fuzz/preset_fuzz FILE` (or run_record_fuzz) replays.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
scripts/deps.sh fuzz

out=build-fuzz
mkdir -p "$out/obj" "$out/corpus" "$out/generated"
# A run record says what made it (app/report/provenance.cpp), which names the build's version:
# the header the CMake build writes, written here the same way.
cmake -DSRC="$PWD" -DOUT="$out/generated/swarmlab_version.h" -P app/ensemble/program_version.cmake
# Line tables are all a sanitizer's report needs (file and line of each frame), at a fraction
# of full debug information's compile time.
flags=(-std=c++17 -gline-tables-only -O1 -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
       -Icore/include -Icore/src -Iapp -I"$out/generated" -I/usr/include/eigen3)
launcher=()
command -v ccache >/dev/null && launcher=(ccache)

# The core compiles one unit a folder (a file that includes the folder's sources: each header
# parsed once for the folder, half the CPU time of a file at a time: 42 against 83 s,
# 2026-11-28), on every core; a unit is rebuilt when its folder's sources or a header changed.
objects=()
jobs=$(nproc 2>/dev/null || echo 2)
headers=$(find core/include core/src -name '*.h')
# stale OBJECT FILE...: the object is missing or older than one of the files.
stale() {
  local obj=$1
  shift
  [ ! -f "$obj" ] || [ -n "$(find "$@" -newer "$obj" -print -quit)" ]
}
# compile SOURCE OBJECT: in the background, at most one compiler a core.
compile() {
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  "${launcher[@]}" clang++ "${flags[@]}" -c "$1" -o "$2" &
}
for folder in core/src/*/; do
  unit="$out/obj/core_$(basename "$folder").cpp"
  listing=$(for src in "$folder"*.cpp; do echo "#include \"$PWD/$src\""; done)
  [ "$(cat "$unit" 2>/dev/null)" = "$listing" ] || echo "$listing" >"$unit"
  # shellcheck disable=SC2086 # the headers' paths have no spaces
  stale "${unit%.cpp}.o" "$unit" "$folder"*.cpp $headers && compile "$unit" "${unit%.cpp}.o"
  objects+=("${unit%.cpp}.o")
done
# shellcheck disable=SC2086
stale "$out/obj/preset_fuzz.o" tests/fuzz/preset_fuzz.cpp $headers &&
  compile tests/fuzz/preset_fuzz.cpp "$out/obj/preset_fuzz.o"
# The run-record reader: its three app files and the target.
record_objects=()
for src in app/ensemble/run_record.cpp app/files/sha256.cpp app/report/provenance.cpp \
           tests/fuzz/run_record_fuzz.cpp; do
  obj="$out/obj/$(basename "${src%.cpp}").o"
  # shellcheck disable=SC2086
  stale "$obj" "$src" app/ensemble/*.h app/files/sha256.h app/report/provenance.h "$out/generated/swarmlab_version.h" \
    $headers && compile "$src" "$obj"
  record_objects+=("$obj")
done
while [ "$(jobs -rp | wc -l)" -gt 0 ]; do wait -n; done
clang++ -fsanitize=fuzzer,address,undefined "${objects[@]}" "$out/obj/preset_fuzz.o" -o "$out/preset_fuzz" -lpthread
clang++ -fsanitize=fuzzer,address,undefined "${objects[@]}" "${record_objects[@]}" \
  -o "$out/run_record_fuzz" -lpthread

# The share links' decoding in the page's JavaScript, under node, for a third of the time.
echo "== share-link decoding (web/share_link.js) under node"
node tests/fuzz/share_link_fuzz.mjs "$(( seconds / 3 > 0 ? seconds / 3 : 1 ))"
# The embed bridge's messages and its ?origins= list (JavaScript too), as long.
echo "== embed-bridge messages (web/embed_bridge.js) under node"
node tests/fuzz/embed_bridge_fuzz.mjs "$(( seconds / 3 > 0 ? seconds / 3 : 1 ))"

# The two libFuzzer targets share the time one had. The first corpus folder receives new
# inputs; the shipped presets and records are read-only seeds.
half=$(( seconds / 2 > 0 ? seconds / 2 : 1 ))
echo "== preset parsing, validation and the resource estimate under libFuzzer"
cd "$out"
./preset_fuzz -max_total_time="$half" -timeout=10 -rss_limit_mb=4096 -max_len=16384 \
  -print_final_stats=1 corpus ../assets/presets
echo "== ensemble run records (swarmlab merge's reader) under libFuzzer"
mkdir -p corpus-run-records
./run_record_fuzz -max_total_time="$half" -timeout=10 -rss_limit_mb=4096 -max_len=65536 \
  -print_final_stats=1 corpus-run-records ../tests/fuzz/run_records
