#!/usr/bin/env bash
# Shows that the tests do not flake: runs the browser suites, the walkthroughs and the desktop
# window tests RUNS times in a row (default 5) while two busy loops keep both cores loaded, and
# prints a table of each run's results and time. Builds first (scripts/build.sh, and the page
# through ctest's web fixture). Hours on 2 cores with the walkthroughs.
#   scripts/soak.sh [--runs N] [--labels 'web|desktop|walkthrough'] [--no-load] [--no-build]
# --no-build runs the tests on what is built (no build, no page preparation): the soak then
# tests one fixed build even while the sources change beside it.
# Exits non-zero if any run failed; each run's ctest log is in build/soak/.
set -uo pipefail
cd "$(dirname "$0")/.."

runs=5
labels='web|desktop|walkthrough'
load=1
build=1
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift ;;
    --labels) labels=$2; shift ;;
    --no-load) load=0 ;;
    --no-build) build=0 ;;
    *) echo "soak.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

[ $build -eq 0 ] || scripts/build.sh >/dev/null || exit 1
mkdir -p build/soak
busy=()
stop_load() { [ ${#busy[@]} -gt 0 ] && kill "${busy[@]}" 2>/dev/null; busy=(); }
trap stop_load EXIT
# The page is built before the load starts: the soak is of the tests, not of the compiler.
[ $build -eq 0 ] || (cd build && ctest -R '^web_prepare$' --output-on-failure >/dev/null) ||
  { echo "soak.sh: the page did not build" >&2; exit 1; }
# The page's fixture (web_prepare, labelled web as well) runs before the load or not at all:
# in a run it would rebuild the page whenever the sources had changed beside the soak.
fixtures=(-E '^web_prepare$' -FA '.*')
if [ $load -eq 1 ]; then
  for _ in 1 2; do (while :; do :; done) & busy+=($!); done
fi

results=()
failed=0
for run in $(seq 1 "$runs"); do
  log="build/soak/run-$run.log"
  t0=$(date +%s)
  (cd build && ctest -L "$labels" -j2 ${fixtures[@]+"${fixtures[@]}"} --output-on-failure) >"$log" 2>&1
  status=$?
  summary=$(grep -E '^[0-9]+% tests passed' "$log" | tail -1)
  fails=$(grep -E '^\s+[0-9]+ - ' "$log" | sed 's/^ *[0-9]* - //' | tr '\n' ' ')
  [ $status -eq 0 ] || failed=1
  results+=("$(printf 'run %d: %5ss  %s %s' "$run" "$(( $(date +%s) - t0 ))" "${summary:-no summary}" "${fails:+ failed: $fails}")")
  echo "${results[-1]}"
done
stop_load
echo
echo "== soak: ctest -L '$labels', $runs runs, $([ $load -eq 1 ] && echo 'two busy loops on both cores' || echo 'no load'), $(date -u +%Y-%m-%dT%H:%MZ)"
printf '%s\n' "${results[@]}"
exit $failed
