#!/usr/bin/env bash
# Browser end-to-end test of the web build: (re)builds build/web (scripts/web.sh --build-only,
# seconds when nothing changed; --no-build skips it), installs tests/web/package.json's npm
# packages (playwright-core; lighthouse and axe-core for audit.mjs) into tests/web/node_modules
# if needed, then runs e2e.mjs and every *_e2e.mjs suite beside it
# (each its own Chromium, sharing harness.mjs) in Debian's headless Chromium.
#   tests/web/run.sh [--no-build] [SUITE...]   SUITE: e2e, time, touch, ... (default: all)
#   tests/web/run.sh --prepare                 only build and install (ctest's web fixture)
# Each suite ends with "N passed, M failed"; the exit code is non-zero if any suite failed.
# Screenshots and console logs: build/web-test/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

build=1
prepare_only=0
suites=()
for arg in "$@"; do
  case $arg in
    --no-build) build=0 ;;
    --prepare) prepare_only=1 ;;
    -*) echo "run.sh: unknown option $arg" >&2; exit 2 ;;
    *) name=$(basename "${arg%.mjs}"); name=${name%_e2e}
       suite="$here/${name}_e2e.mjs"; [ "$name" = e2e ] && suite="$here/e2e.mjs"
       [ -f "$suite" ] || { echo "run.sh: no suite $arg (no $suite)" >&2; exit 2; }
       suites+=("$suite") ;;
  esac
done
[ ${#suites[@]} -gt 0 ] || suites=("$here/e2e.mjs" "$here"/*_e2e.mjs)

"$root/scripts/deps.sh" web webtest
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || { echo "run.sh: ${CHROMIUM:-/usr/bin/chromium} is missing (apt-get install chromium)" >&2; exit 1; }

if [ $build -eq 1 ]; then
  "$root/scripts/web.sh" --build-only
fi

stamp="$here/node_modules/.installed-stamp"
if [ ! -f "$here/node_modules/playwright-core/package.json" ] || [ "$here/package.json" -nt "$stamp" ] \
   || { [ -f "$here/package-lock.json" ] && [ "$here/package-lock.json" -nt "$stamp" ]; }; then
  echo "[web-test] npm install (playwright-core, lighthouse, axe-core)" >&2
  if [ -f "$here/package-lock.json" ]; then
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
  else
    (cd "$here" && npm install --no-audit --no-fund --loglevel=error)
  fi
  touch "$stamp"
fi

[ $prepare_only -eq 1 ] && exit 0

cd "$root"
export NODE_PATH=/usr/share/nodejs
status=0
for suite in "${suites[@]}"; do
  echo "== $(basename "$suite")"
  # Room for a loaded machine (layout took 121 s at a load of 21); each suite's own watchdog
  # (runSuite) ends it sooner with its tally.
  limit=300
  # The walkthroughs go through every lesson on four devices: about 16 minutes, 22 with both
  # cores loaded.
  [ "$(basename "$suite")" = walkthrough_e2e.mjs ] && limit=1800
  timeout "$limit" node "$suite" || status=1
done
exit $status
