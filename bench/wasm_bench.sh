#!/bin/bash
# Builds bench/wasm_bench.cpp natively (build/) and as WebAssembly (build-wasm/, Debian's
# emscripten, one thread) and runs both, several times each; compare the best times.
# Usage: bench/wasm_bench.sh [repeats]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
repeats="${1:-3}"
export NODE_PATH=/usr/share/nodejs
scripts/build.sh --target wasm_bench >/dev/null
[ -f build-wasm/CMakeCache.txt ] || emcmake cmake -S . -B build-wasm -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build-wasm -j"$(nproc)" --target wasm_bench >/dev/null
for i in $(seq "$repeats"); do
  echo "== native, 1 thread";  build/bench/wasm_bench 1
  echo "== native, 2 threads"; build/bench/wasm_bench 2
  echo "== wasm (node $(node --version))"; node --no-experimental-fetch build-wasm/bench/wasm_bench.js
done
