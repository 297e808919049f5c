#!/usr/bin/env bash
# scripts/fresh-check.sh --list, the quick mode: the shipped pages' command lines all have an
# entry point or a stated reason; a page with a command in neither fails, naming that line,
# while its prose, its JSON and a command an entry point runs pass.
# Usage: fresh_check_test.sh (from anywhere; no root, no network)
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

"$root/scripts/fresh-check.sh" --list >"$work/shipped" 2>&1 ||
  bad "the shipped pages: $(grep -B1 'NOT COVERED' "$work/shipped")"
grep -q '^README.md: scripts/run.sh$' "$work/shipped" || bad "the README's first command is not listed"
grep -q '^docs/command-line.md: build/app/swarmlab ensemble assets/presets/hot-wall.json' "$work/shipped" ||
  bad "a page of docs/ is not read"

cat >"$work/page.md" <<'MD'
# A page

Prose naming `scripts/web.sh --prose` is not a code block.

    scripts/web.sh --build-only   # only builds
    swarmlab run assets/presets/point-gas.json --plots somewhere
    {"J": 1, "dt": 0.01}

```sh
scripts/made-up.sh --now
```
MD
"$root/scripts/fresh-check.sh" --list "$work/page.md" >"$work/listed" 2>&1
code=$?
paste -d '|' - - <"$work/listed" >"$work/out"  # each command line beside what became of it
[ $code -eq 1 ] || bad "a page with uncovered commands: exit $code, expected 1: $(cat "$work/out")"
expect() { grep -qF -- "$1" "$work/out" || bad "expected '$1' in: $(cat "$work/out")"; }
expect "$work/page.md: scripts/web.sh --build-only|    run by entry web"
expect "$work/page.md: build/app/swarmlab run assets/presets/point-gas.json --plots somewhere|    NOT COVERED"
expect "$work/page.md: scripts/made-up.sh --now|    NOT COVERED"
[ "$(wc -l <"$work/out")" -eq 3 ] || bad "three command lines, no prose or JSON: $(cat "$work/out")"
[ $failed -eq 0 ] && echo "fresh check --list: every shown command has an entry point or a reason"
exit $((failed > 0))
