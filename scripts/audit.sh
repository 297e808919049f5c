#!/usr/bin/env bash
# Lighthouse (mobile and desktop presets) and axe-core (a phone and a laptop) on the browser
# page, served by scripts/web.sh's own server (tests/web/audit.mjs says what is judged).
#   scripts/audit.sh             build build/web if needed, install the npm packages, audit
#   scripts/audit.sh --no-build  audit what build/web holds
# Scores and figures: build/web-test/audit.json (Lighthouse's reports beside it); a table on
# stdout. Exits non-zero on an axe violation not in tests/web/audit_allowed.json or on
# Lighthouse accessibility or best-practices below 100. About a minute and a half.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=()
case "${1:-}" in
  --no-build) build=(--no-build) ;;
  "") ;;
  *) echo "audit.sh: unknown option $1 (--no-build, or nothing)" >&2; exit 2 ;;
esac
# The page (scripts/web.sh --build-only), Chromium, and lighthouse, axe-core and
# playwright-core from npm into tests/web/node_modules (tests/web/package.json pins them).
"$root/tests/web/run.sh" --prepare "${build[@]}"
export NODE_PATH=/usr/share/nodejs
exec node "$root/tests/web/audit.mjs"
