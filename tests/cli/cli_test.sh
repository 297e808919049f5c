#!/usr/bin/env bash
# Drives the swarmlab binary as a user would: exit codes, messages, and no partial files.
# Usage: cli_test.sh SWARMLAB PRESET_DIR
source "$(dirname "$0")/harness.sh"

# expect_error NAME PRESET_TEXT MESSAGE: validate and run must both refuse with MESSAGE on one
# line of stderr, exit non-zero, and leave no output file.
expect_error() {
  local name=$1 text=$2 message=$3
  printf '%s' "$text" >"$work/$name.json"
  for cmd in validate run; do
    local extra=()
    [ "$cmd" = run ] && extra=(--out "$work/$name.out.json" --csv "$work/$name.out.csv")
    "$bin" "$cmd" "$work/$name.json" "${extra[@]}" >"$work/stdout" 2>"$work/stderr"
    local code=$?
    if [ $code -eq 0 ]; then bad "$name ($cmd): exit 0 on bad input"; continue; fi
    if ! grep -qF -- "$message" "$work/stderr"; then
      bad "$name ($cmd): expected '$message', got: $(cat "$work/stderr")"
      continue
    fi
    if [ "$(wc -l <"$work/stderr")" -ne 1 ]; then bad "$name ($cmd): more than one line"; continue; fi
    if ls "$work/$name".out.* >/dev/null 2>&1; then bad "$name ($cmd): left an output file"; continue; fi
    ok
  done
}

good='"J": 1.0, "particles": [{"m": 1.0, "r": [0.5, 0, 0], "v": [0, 1, 0]}, {"m": 1.0, "r": [-0.5, 0, 0], "v": [0, -1, 0]}], "dt": 0.01'

expect_error not-json '{"J": 1.0,' 'preset: not valid JSON'
expect_error wrong-type '{"J": "one", "particles": [], "dt": 0.1, "duration": 1}' 'J: must be a number'
expect_error missing-dt '{"J": 1.0, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}], "duration": 1}' 'dt: missing'
expect_error unknown-key "{$good, \"duration\": 1, \"colour\": \"red\"}" 'colour: unknown key'
expect_error not-finite "{$good, \"duration\": 1e400}" 'preset: a number cannot be read'
expect_error zero-mass '{"J": 1, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}, {"m": 0, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1, "duration": 1}' 'particles[1].m: must be > 0'
expect_error no-particles '{"J": 1, "particles": [], "dt": 0.1, "duration": 1}' 'particles: must hold at least one particle'
expect_error radius "{$good, \"duration\": 1, \"container\": {\"radius\": 0}}" 'container.radius: must be > 0'
expect_error dt "{\"J\": 1, \"particles\": [{\"m\": 1, \"r\": [0,0,0], \"v\": [0,0,0]}], \"dt\": -0.1, \"duration\": 1}" 'dt: must be > 0'
expect_error outside "{$good, \"duration\": 1, \"container\": {\"radius\": 0.4}}" 'particles[0].r: starts outside the container'
expect_error method "{$good, \"duration\": 1, \"method\": \"leapfrog\"}" 'method: unknown method "leapfrog"'
expect_error huge "{$good, \"duration\": 1e300}" 'duration: must give between 1 and 1e9 steps'

# A missing file is one clear message too.
"$bin" run "$work/nope.json" 2>"$work/stderr" && bad "missing file: exit 0" || {
  grep -q "nope.json: cannot open the file" "$work/stderr" && ok || bad "missing file: $(cat "$work/stderr")"; }

# Help explains every option.
"$bin" --help >"$work/help" && grep -q run "$work/help" && grep -q validate "$work/help" && ok || bad "--help"
"$bin" run --help >"$work/help" && grep -q -- --out "$work/help" && grep -q -- --csv "$work/help" &&
  grep -q -- --quiet "$work/help" && ok || bad "run --help"
"$bin" run --bogus 2>/dev/null && bad "unknown flag accepted" || ok

# Every shipped preset validates.
for p in "$presets"/*.json; do
  "$bin" validate "$p" >/dev/null 2>"$work/stderr" && ok || bad "validate $p: $(cat "$work/stderr")"
done

# A good run writes whole files with the documented keys.
printf '{%s, "duration": 2}' "$good" >"$work/good.json"
if "$bin" run "$work/good.json" --out "$work/result.json" --csv "$work/samples.csv" --quiet >"$work/stdout"; then
  python3 - "$work/result.json" <<'PY' && ok || bad "result.json keys"
import json, sys
d = json.load(open(sys.argv[1]))
s = d["summary"]
for k in ("M", "omega", "E0", "E_end", "energy_drift", "wall_hits", "steps", "t_end"):
    assert k in s, k
assert s["steps"] == 200 and abs(s["omega"] - 2 ** 0.5) < 1e-12
assert all(set(x) >= {"t", "P", "T", "KE", "PE", "E"} for x in d["samples"])
assert len(d["final"]["particles"]) == 2 and abs(d["final"]["t"] - 2) < 1e-9
assert "stages" in d
PY
  head -1 "$work/samples.csv" | grep -q '^t,P,T,KE,PE,E,hits,R$' && ok || bad "csv header"
  [ ! -s "$work/stdout" ] && ok || bad "--quiet printed to stdout"
else
  bad "good run failed"
fi

# An unwritable output is refused before the run, leaving nothing behind.
"$bin" run "$work/good.json" --out "$work/no/such/dir/r.json" --quiet 2>"$work/stderr" &&
  bad "unwritable output accepted" || { grep -q "cannot write here" "$work/stderr" && ok || bad "unwritable: $(cat "$work/stderr")"; }

# A run longer than a second shows a progress bar on stderr; --quiet hides it.
printf '{"J": 1, "method": "rk4", "particles": {"count": 500, "position_radius": 1, "velocity": {"speed": 1}}, "dt": 0.001, "duration": 8}' >"$work/slow.json"
"$bin" run "$work/slow.json" 2>"$work/stderr" >/dev/null
grep -q 'running \[#' "$work/stderr" && ok || bad "no progress bar on a long run"

finish
