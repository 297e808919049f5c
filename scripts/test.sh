#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds natively and with Emscripten, runs
# the doctest suite natively and under node, the CLI as a process, the desktop window under
# Xvfb, the browser app in headless Chromium and a minute of fuzzing the preset parser.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh native desktop web
export NODE_PATH=/usr/share/nodejs

echo "== native build"
scripts/build.sh
echo "== native tests (ctest)"
(cd build && ctest --output-on-failure)

echo "== core and its tests compiled with emcc, run under node"
scripts/web-deps.sh
if [ ! -f build-wasm/CMakeCache.txt ]; then
  emcmake cmake -S . -B build-wasm -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build-wasm -j"$(nproc)" --target swarm_tests swarmlab
(cd build-wasm && ctest --output-on-failure)

echo "== the same presets natively and in wasm reach the same final state"
python3 tests/wasm/same_final_state.py build/app/swarmlab build-wasm/app/swarmlab.js \
  tests/wasm/maxwell-repulsive.json assets/presets/fig4-equilibration.json \
  assets/presets/fig1-four-masses.json assets/presets/euler-vs-euler-cromer.json

echo "== the browser app in headless Chromium (build/web, playwright-core)"
tests/web/run.sh

echo "== fuzzing: preset parsing, validation and the resource estimate (libFuzzer, a minute) and share-link decoding (node, 20 s)"
scripts/fuzz.sh 60
