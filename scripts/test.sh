#!/usr/bin/env bash
# The test suite, in two tiers (CONTRIBUTING.md, "The whole suite"):
#   scripts/test.sh          everything, as CI runs it (.ci/run): builds natively and with
#                            Emscripten, then the doctest suite natively and under node, the CLI
#                            as a process, the desktop window under Xvfb, native == wasm, the
#                            browser suites, Lighthouse and axe-core and the walkthroughs in
#                            headless Chromium, and fuzzing (scripts/fuzz.sh 60: its four targets
#                            take 100 s). About 34 minutes on a fresh clone of a 2-core machine
#                            (2055 s, 2026-12-07, both cores 98 % busy; the walkthroughs 934 s of
#                            it: what is left to cut is work, not waiting).
#   scripts/test.sh --quick  before a commit: the doctest suite, the CLI tests and one browser
#                            smoke test, under 3 minutes once built.
# Installs what is missing first. Each stage runs through ctest's labels (unit, cli, desktop,
# wasm, web, audit, walkthrough, fuzz, smoke) where it can; a failed test stage does not stop the later
# ones; the native and the wasm lane run side by side from the start. Ends with a table of the
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
# The machine's CPU time, busy and all (/proc/stat's first line: user nice system idle iowait
# irq softirq steal, in clock ticks), so that the table says how much of both cores the run used.
cpu_ticks() { awk '/^cpu /{print $2+$3+$4+$7+$8+$9, $2+$3+$4+$5+$6+$7+$8+$9}' /proc/stat; }
cpu_start=$(cpu_ticks)
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
  read -r busy0 all0 <<<"$cpu_start"
  read -r busy1 all1 <<<"$(cpu_ticks)"
  [ "$all1" -gt "$all0" ] && echo "the machine's $(nproc) cores were $(( 100 * (busy1 - busy0) / (all1 - all0) )) % busy over the run (everything on it, /proc/stat)"
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

build "packages (scripts/deps.sh)" scripts/deps.sh native desktop web webtest fuzz serve
# The wasm doctest suite and the CLI for node, in build-wasm (which the page's build made), one
# build there at a time (scripts/web.sh takes the same lock).
wasm_tests_build() {
  flock build/.web-build.lock nice -n 10 cmake --build build-wasm -j"$(nproc)" --target swarm_tests swarmlab
}

# Two lanes from the start, each building what it needs and then testing it, so that one
# lane's single-threaded stretches (configuring, linking, emcc's wasm link, a page waiting on
# its frames) are filled by the other's work. The wasm lane is the long one (its page build,
# then the browser, which needs both cores for a page and its GPU process): the native lane's
# builds and fuzzing run niced beside it, so that they take what it leaves.
#   native: the native build, the doctest, CLI and desktop tests, then, once the page is built,
#           the wasm doctest suite and the CLI for node (built beside the browser suites), the
#           doctest suite under node, native == wasm, fuzzing (its own build), and Lighthouse
#           and axe-core on the page (not a timing check: beside a browser suite is fine);
#   wasm:   SDL2 for wasm and the page (build/web, and playwright-core: the browser suites'
#           fixture), then, once the native build is done (ctest runs from build/), the browser
#           suites one at a time and the walkthroughs two at a time. The browser suites' timing
#           limits leave room for a loaded machine (two busy loops: scripts/soak.sh), not for
#           three pages at once: they never run beside the walkthroughs.
# A lane waits for the other's build through a file in build/test-logs that says how it ended.
# Each lane's output goes to its log, shown after.
logs=build/test-logs
mkdir -p "$logs"
rm -f "$logs"/*.built
built() { echo "$2" >"$logs/$1.built"; }
# await NAME: waits until the build NAME has ended; true if it succeeded.
await() {
  while [ ! -f "$logs/$1.built" ]; do sleep 2; done
  [ "$(cat "$logs/$1.built")" = ok ]
}
# The browser tests without their fixture (the wasm lane prepared it as its build).
browser_ctest() { native_ctest -E '^web_prepare$' -FA '.*' "$@"; }
native_lane() {
  if stage "native build" nice -n 10 scripts/build.sh; then built native ok; else built native failed; return 1; fi
  stage "doctest, CLI, desktop window (ctest -L 'unit|cli|desktop')" native_ctest -L 'unit|cli|desktop' -j2
  await wasm || return 1
  stage "wasm build: the doctest suite and the CLI for node" wasm_tests_build || return 1
  stage "doctest suite under node (ctest in build-wasm)" bash -c 'cd build-wasm && ctest --output-on-failure'
  stage "native and wasm reach the same final state" python3 tests/wasm/same_final_state.py \
    build/app/swarmlab build-wasm/app/swarmlab.js \
    tests/wasm/maxwell-repulsive.json assets/presets/fig4-equilibration.json \
    assets/presets/fig1-four-masses.json assets/presets/euler-vs-euler-cromer.json \
    tests/wasm/gravity-wall.json tests/wasm/gravity-floor.json
  stage "fuzzing, four targets (scripts/fuzz.sh 60, ctest -L fuzz)" nice -n 10 scripts/fuzz.sh 60
  # What ctest's web_audit runs, outside ctest: the wasm lane's ctest runs in build/ meanwhile.
  stage "Lighthouse and axe-core on the page (node tests/web/audit.mjs, ctest -L audit)" \
    nice -n 10 node tests/web/audit.mjs
}
wasm_lane() {
  if stage "wasm build: SDL2 for wasm, the page (tests/web/run.sh --prepare)" tests/web/run.sh --prepare
  then built wasm ok
  else built wasm failed; return 1; fi
  await native || return 1
  stage "browser suites, one at a time (ctest -L web)" browser_ctest -L web
  stage "walkthroughs: every lesson on four devices, two at a time (ctest -L walkthrough)" \
    browser_ctest -L walkthrough -j2
}
echo "== two lanes: native ($logs/native.log) and wasm, then the browser ($logs/wasm.log)"
wasm_lane >"$logs/wasm.log" 2>&1 &
wasm=$!
native_lane >"$logs/native.log" 2>&1
wait $wasm
cat "$logs/native.log" "$logs/wasm.log"
# A build that failed leaves its lane's tests unrun: say so in the table.
for lane in native wasm; do
  [ "$(cat "$logs/$lane.built" 2>/dev/null)" = ok ] ||
    printf '%-66s %6s   %s\n' "tests after the $lane build" "-" "NOT RUN" >>"$rows"
done
failed || grep -q 'NOT RUN$' "$rows" && exit 1
exit 0
