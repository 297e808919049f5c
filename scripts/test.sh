#!/usr/bin/env bash
# The test suite, in two tiers (README, "Tests"):
#   scripts/test.sh          everything, as CI runs it (.ci/run): builds natively and with
#                            Emscripten, then the doctest suite natively and under node, the CLI
#                            as a process, the desktop window under Xvfb, native == wasm, the
#                            browser suites and the walkthroughs in headless Chromium, and a
#                            minute of fuzzing. About 35 minutes on a fresh clone of a 2-core
#                            machine.
#   scripts/test.sh --quick  before a commit: the doctest suite, the CLI tests and one browser
#                            smoke test, under 3 minutes once built.
# Installs what is missing first. Each stage runs through ctest's labels (unit, cli, desktop,
# wasm, web, walkthrough, fuzz, smoke) where it can; a failed test stage does not stop the later
# ones; after the builds the browser tests run beside the others. Ends with a table of the
# stages and their times; exits non-zero if any stage failed.
set -uo pipefail
cd "$(dirname "$0")/.."

quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "test.sh: unknown option $1 (--quick, or nothing for the whole suite)" >&2; exit 2 ;;
esac

# Each stage's row of the table goes to a file, so that stages run in a background lane count.
rows=$(mktemp)
t_all=$(date +%s)
# stage NAME COMMAND...: runs it, times it, records ok or FAILED.
stage() {
  local name=$1 t0 result
  shift
  echo "== $name"
  t0=$(date +%s)
  if "$@"; then result=ok; else result=FAILED; fi
  printf '%-66s %6ss  %s\n' "$name" "$(( $(date +%s) - t0 ))" "$result" >>"$rows"
  [ "$result" = ok ]
}
failed() { grep -q 'FAILED$' "$rows"; }
table() {
  echo
  echo "== stages ($([ $quick -eq 1 ] && echo quick || echo full))"
  cat "$rows"
  printf '%-66s %6ss  %s\n' "total" "$(( $(date +%s) - t_all ))" "$(failed && echo FAILED || echo ok)"
  rm -f "$rows"
}
trap table EXIT
# A build that fails leaves nothing to test: stop there.
build() { stage "$@" || exit 1; }

export NODE_PATH=/usr/share/nodejs
native_ctest() { (cd build && ctest --output-on-failure "$@"); }

if [ $quick -eq 1 ]; then
  build "native build" scripts/build.sh
  stage "doctest suite and CLI tests (ctest -L 'unit|cli')" native_ctest -L 'unit|cli' -j2
  stage "browser smoke test (ctest -L smoke)" native_ctest -L smoke
  failed && exit 1
  exit 0
fi

build "packages (scripts/deps.sh)" scripts/deps.sh native desktop web webtest fuzz
wasm_build() {
  scripts/web-deps.sh &&
    { [ -f build-wasm/CMakeCache.txt ] || emcmake cmake -S . -B build-wasm -DCMAKE_BUILD_TYPE=Release >/dev/null; } &&
    cmake --build build-wasm -j"$(nproc)" --target swarm_tests swarmlab swarmlab_web
}
build "native build" scripts/build.sh
build "wasm build: core, tests, CLI for node, the page" wasm_build

# Two lanes at once: the browser (its suites one at a time, then the walkthroughs two at a
# time, a core a page) beside the native, wasm and fuzzing checks. The browser suites' timing
# limits leave room for a loaded machine, not for three pages at once: they never run beside
# the walkthroughs. Each lane's output goes to its log, shown after.
mkdir -p build/test-logs
browser_lane() {
  stage "browser suites, one at a time (ctest -L web)" native_ctest -L web
  stage "walkthroughs: every lesson on four devices, two at a time (ctest -L walkthrough)" \
    native_ctest -L walkthrough -j2
}
checks_lane() {
  stage "doctest, CLI, desktop window (ctest -L 'unit|cli|desktop')" native_ctest -L 'unit|cli|desktop' -j2
  stage "doctest suite under node (ctest in build-wasm)" bash -c 'cd build-wasm && ctest --output-on-failure'
  stage "native and wasm reach the same final state" python3 tests/wasm/same_final_state.py \
    build/app/swarmlab build-wasm/app/swarmlab.js \
    tests/wasm/maxwell-repulsive.json assets/presets/fig4-equilibration.json \
    assets/presets/fig1-four-masses.json assets/presets/euler-vs-euler-cromer.json
  stage "fuzzing, a minute (ctest -L fuzz)" native_ctest -L fuzz
}
echo "== two lanes: browser (build/test-logs/browser.log) and checks (build/test-logs/checks.log)"
browser_lane >build/test-logs/browser.log 2>&1 &
browser=$!
checks_lane >build/test-logs/checks.log 2>&1
wait $browser
cat build/test-logs/checks.log build/test-logs/browser.log
failed && exit 1
exit 0
