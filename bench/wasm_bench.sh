#!/bin/bash
# Builds bench/wasm_bench.cpp natively (g++ -O3) and as WebAssembly (Debian's emscripten,
# em++ -O3, one thread) and runs both, several times each; compare the best times.
# Usage: bench/wasm_bench.sh [repeats]   (writes to build-wasm-bench/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/build-wasm-bench"
repeats="${1:-3}"
mkdir -p "$out/include"
# Header-only dependencies through a folder of symlinks, never /usr/include itself (TOOLCHAIN.md).
[ -e "$out/include/nlohmann" ] || ln -s /usr/include/nlohmann "$out/include/nlohmann"
sources=("$root"/core/src/*.cpp "$root/bench/bench_workloads.cpp" "$root/bench/wasm_bench.cpp")
flags=(-std=c++17 -O3 -DNDEBUG -I"$root/core/include" -I"$root/bench" -I/usr/include/eigen3)
g++ "${flags[@]}" -pthread "${sources[@]}" -o "$out/wasm_bench_native"
NODE_PATH=/usr/share/nodejs em++ "${flags[@]}" -I"$out/include" -fexceptions \
  -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=2GB -sENVIRONMENT=node "${sources[@]}" \
  -o "$out/wasm_bench.js"
for i in $(seq "$repeats"); do
  echo "== native, 1 thread";  "$out/wasm_bench_native" 1
  echo "== native, 2 threads"; "$out/wasm_bench_native" 2
  echo "== wasm (node $(node --version))"; node --no-experimental-fetch "$out/wasm_bench.js"
done
