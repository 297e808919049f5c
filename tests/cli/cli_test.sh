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

# Output files that cannot hurt (app/files/atomic_file.h). A run of a few seconds, to tell a
# refusal before the run from one after it, and to interrupt.
printf '{"J": 1, "method": "rk4", "particles": {"count": 400, "position_radius": 1, "velocity": {"speed": 1}}, "dt": 0.001, "duration": 6}' >"$work/long.json"
ms() { date +%s%3N; }
# refused_before NAME MESSAGE ARGS...: run long.json with ARGS: exit 1 within a second (the
# run itself takes seconds), MESSAGE on stderr.
refused_before() {
  local name=$1 message=$2
  shift 2
  local t0 code
  t0=$(ms)
  timeout 20 "$bin" run "$work/long.json" --quiet "$@" >/dev/null 2>"$work/stderr"
  code=$?
  local elapsed=$(($(ms) - t0))
  if [ $code -ne 1 ]; then bad "$name: exit $code ($(cat "$work/stderr"))"; return; fi
  grep -qF -- "$message" "$work/stderr" && ok || bad "$name: expected '$message', got: $(cat "$work/stderr")"
  [ $elapsed -lt 1000 ] && ok || bad "$name: refused after ${elapsed} ms, not before the run"
}
if [ -c /dev/full ]; then
  refused_before "--out /dev/full" "/dev/full: is a device, FIFO or socket" --out /dev/full
  [ -c /dev/full ] && ok || bad "/dev/full is no longer a character device"
fi
mkfifo "$work/fifo"
refused_before "--out FIFO" "fifo: is a device, FIFO or socket" --out "$work/fifo"
[ -p "$work/fifo" ] && ok || bad "the FIFO was replaced"
mkdir "$work/a-dir"
refused_before "--out DIR" "a-dir: is a directory" --out "$work/a-dir"
refused_before "--csv DIR" "a-dir: is a directory" --csv "$work/a-dir"
refused_before "missing folder" "cannot write here (the folder" --csv "$work/no/such.csv"
refused_before "same file twice" "is given twice as an output" --out "$work/same" --csv "$work/./same"
ln -s nowhere "$work/dangling"
refused_before "dangling symlink" "is a symlink to nothing" --out "$work/dangling"
if [ "$(id -u)" -ne 0 ]; then
  mkdir "$work/locked" && chmod a-w "$work/locked"
  refused_before "unwritable folder" "no permission to create files" --out "$work/locked/r.json"
fi

# A symlink is written through: its target gets the result, the link stays a link.
echo old >"$work/real.json"
ln -s real.json "$work/link.json"
"$bin" run "$work/good.json" --out "$work/link.json" --quiet 2>"$work/stderr" && ok || bad "--out symlink: $(cat "$work/stderr")"
[ -L "$work/link.json" ] && [ "$(readlink "$work/link.json")" = real.json ] && ok || bad "the symlink was replaced"
grep -q '"summary"' "$work/real.json" && ok || bad "the symlink's target was not written"

# A user's files named like a temporary or a probe are never touched, and nothing is left over.
mkdir "$work/names"
for name in r.json.probe r.json.tmp r.json.tmp1 .r.json.swarmlab-1-0-00000000.tmp .swarmlab-probe-1; do
  echo mine >"$work/names/$name"
done
"$bin" run "$work/good.json" --out "$work/names/r.json" --csv "$work/names/r.csv" --quiet && ok || bad "run into names/"
for name in r.json.probe r.json.tmp r.json.tmp1 .r.json.swarmlab-1-0-00000000.tmp .swarmlab-probe-1; do
  [ "$(cat "$work/names/$name")" = mine ] && ok || bad "a user's file $name was changed"
done
[ "$(ls -A "$work/names" | wc -l)" -eq 7 ] && ok || bad "files left over: $(ls -A "$work/names")"

# Outputs commit together: when the --csv cannot be written at the end (its path became a FIFO
# during the run), the existing --out keeps its old content and no temporary is left.
mkdir "$work/both"
echo old-result >"$work/both/r.json"
"$bin" run "$work/long.json" --out "$work/both/r.json" --csv "$work/both/r.csv" --quiet 2>"$work/stderr" &
pid=$!
sleep 0.5
mkfifo "$work/both/r.csv"
wait $pid && bad "a --csv that became a FIFO was accepted" || {
  grep -q "r.csv: is a device, FIFO or socket" "$work/stderr" && ok || bad "late FIFO: $(cat "$work/stderr")"; }
[ "$(cat "$work/both/r.json")" = old-result ] && ok || bad "a failed --csv changed the existing --out"
[ "$(ls -A "$work/both" | sort | tr '\n' ' ')" = "r.csv r.json " ] && ok || bad "left in both/: $(ls -A "$work/both")"

# SIGINT or SIGTERM during a run with outputs: the conventional status, no temporary left, the
# old --out untouched. (A background job ignores SIGINT; env gives it back its default.)
for signal in INT TERM; do
  mkdir "$work/stop-$signal"
  echo old-result >"$work/stop-$signal/r.json"
  env --default-signal=INT "$bin" run "$work/long.json" --out "$work/stop-$signal/r.json" \
    --csv "$work/stop-$signal/r.csv" --plots "$work/stop-$signal/plots" --quiet 2>/dev/null &
  pid=$!
  sleep 1
  kill -$signal $pid
  wait $pid
  code=$?
  expected=$((128 + $(kill -l $signal)))
  [ $code -eq $expected ] && ok || bad "SIG$signal: exit $code, expected $expected"
  [ "$(ls -A "$work/stop-$signal" | tr '\n' ' ')" = "plots r.json " ] && [ -z "$(ls -A "$work/stop-$signal/plots")" ] &&
    ok || bad "SIG$signal left: $(ls -AR "$work/stop-$signal")"
  [ "$(cat "$work/stop-$signal/r.json")" = old-result ] && ok || bad "SIG$signal changed the old --out"
done

# A run longer than a second shows a progress bar on stderr; --quiet hides it.
printf '{"J": 1, "method": "rk4", "particles": {"count": 500, "position_radius": 1, "velocity": {"speed": 1}}, "dt": 0.001, "duration": 8}' >"$work/slow.json"
"$bin" run "$work/slow.json" 2>"$work/stderr" >/dev/null
grep -q 'running \[#' "$work/stderr" && ok || bad "no progress bar on a long run"

finish
