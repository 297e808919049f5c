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
# Where it breaks and what is wrong, as an editor counts lines and columns, without the
# parser's own "[json.exception.parse_error.101]"; a number out of range without its code too.
expect_error broken-json $'{"J": 1.0,\n  "dt": 0.1,}' \
  "error: $work/broken-json.json: preset: not valid JSON at line 2, column 13: unexpected '}'; expected string literal"
expect_error cut-json $'{"J": 1.0,\n' \
  "error: $work/cut-json.json: preset: not valid JSON at line 2, column 1: unexpected end of input; expected string literal"
expect_error overflow-json "{$good, \"duration\": 1e400}" \
  "error: $work/overflow-json.json: preset: a number cannot be read (number overflow parsing '1e400')"
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
# Appendix B walls and contacts
expect_error wall-speed "{$good, \"duration\": 1, \"container\": {\"radius\": 1, \"moves\": [{\"to\": 0.8, \"speed\": 0}]}}" 'container.moves[0].speed: must be in (0, 1e100]'
expect_error hot-and-moving "{$good, \"duration\": 1, \"container\": {\"radius\": 1, \"wall_temperature\": 1, \"moves\": [{\"to\": 0.8, \"speed\": 1}]}}" 'container.wall_temperature: a wall either moves'
expect_error sphere-too-big "{$good, \"duration\": 1, \"container\": {\"radius\": 1}, \"hard_spheres\": {\"radius\": 0.6}}" 'hard_spheres.radius: must be < container.radius / 2'

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
  head -1 "$work/samples.csv" | grep -q '^"t","P","T","KE","PE","E","hits","R","work","heat","drag_loss","cm_height","size","T_kinetic"$' && ok || bad "csv header"
  [ ! -s "$work/stdout" ] && ok || bad "--quiet printed to stdout"
else
  bad "good run failed"
fi

# Two temperatures (docs/physics.md, "Wall thermometry"): the summary's T_kinetic is (2/3) KE / N in the CM
# frame and maxwellian_p the KS test of the final speeds against the Maxwellian at that T, both
# recomputed here from the final state. J = 0 with speeds uniform in a ball never relaxes (each
# particle keeps its speed at a specular wall): p tiny, and the wall's T below T_kinetic
# (0.168 against 0.2025 in issue 37); a Maxwellian start passes.
for start in '"speed": 1.0' '"temperature": 0.2'; do
  printf '{"J": 0, "particles": {"count": 2000, "position_radius": 0.9, "velocity": {%s}, "cm_at_rest": true, "seed": 5},
    "container": {"radius": 1.0}, "dt": 0.002, "duration": 4, "sample_every": 10}' "$start" >"$work/two-t.json"
  "$bin" run "$work/two-t.json" --out "$work/two-t.out.json" --quiet || bad "two temperatures ($start): run failed"
  python3 - "$work/two-t.out.json" "$start" <<'PY' && ok || bad "two temperatures ($start)"
import json, math, sys
d = json.load(open(sys.argv[1]))
s, ps = d["summary"], d["final"]["particles"]
M = sum(p["m"] for p in ps)
V = [sum(p["m"] * p["v"][i] for p in ps) / M for i in range(3)]
T = sum(p["m"] * sum((p["v"][i] - V[i]) ** 2 for i in range(3)) for p in ps) / (3 * len(ps))
assert abs(s["T_kinetic"] / T - 1) < 1e-9, (s["T_kinetic"], T)
x = sorted(math.sqrt(p["m"] / T) * math.sqrt(sum((p["v"][i] - V[i]) ** 2 for i in range(3))) for p in ps)
F = lambda u: math.erf(u / math.sqrt(2)) - math.sqrt(2 / math.pi) * u * math.exp(-u * u / 2)
n = len(x)
D = max(max((i + 1) / n - F(u), F(u) - i / n) for i, u in enumerate(x))
lam = (math.sqrt(n) + 0.12 + 0.11 / math.sqrt(n)) * D
p = 1.0 if lam < 0.2 else min(1.0, max(0.0, 2 * sum((-1) ** (k - 1) * math.exp(-2 * k * k * lam * lam) for k in range(1, 101))))
assert abs(s["maxwellian_p"] - p) <= 1e-9 + 1e-6 * p, (s["maxwellian_p"], p)
# The wall's T over the second half of the run, hit-weighted as the read-outs average it.
late = [x for x in d["samples"] if x["t"] > 2 and x["hits"] > 0]
T_wall = sum(x["T"] * x["hits"] for x in late) / sum(x["hits"] for x in late)
if "speed" in sys.argv[2]:
    assert p < 1e-6, p
    assert T_wall < 0.9 * T, (T_wall, T)
else:
    assert p > 0.001, p
    assert abs(T_wall / T - 1) < 0.05, (T_wall, T)
PY
done

# An unwritable output is refused before the run, leaving nothing behind.
"$bin" run "$work/good.json" --out "$work/no/such/dir/r.json" --quiet 2>"$work/stderr" &&
  bad "unwritable output accepted" || { grep -q "cannot write here" "$work/stderr" && ok || bad "unwritable: $(cat "$work/stderr")"; }

# --threads takes any count, and the run's numbers do not change with it: 1, 2 and 7 threads
# (more than this machine's cores) write the same result, summary and final state to the bit.
printf '%s' '{"J": 5.6e-05, "particles": {"count": 4000, "mass": {"min": 4.0, "max": 5.0},
  "position_radius": 1.0, "velocity": {"speed": 1.0}, "seed": 7}, "container": {"radius": 1.0},
  "dt": 0.01, "duration": 20, "sample_every": 100}' >"$work/threads.json"
for t in 1 2 7; do
  "$bin" run "$work/threads.json" --threads $t --out "$work/threads-$t.json" --quiet ||
    bad "--threads $t failed"
done
python3 - "$work"/threads-{1,2,7}.json <<'PY' && ok || bad "--threads changed the results"
import json, sys
runs = [json.load(open(p)) for p in sys.argv[1:]]
assert runs[0]["summary"]["wall_hits"] > 100
for r in runs[1:]:
    assert r["final"] == runs[0]["final"] and r["samples"] == runs[0]["samples"]
PY
"$bin" run "$work/threads.json" --threads 0 --quiet 2>/dev/null && bad "--threads 0 accepted" || ok
# A count typed by mistake is refused with the rule, not thousands of threads started.
msg=$("$bin" run "$work/threads.json" --threads 65535 --quiet 2>&1) && bad "--threads 65535 accepted" ||
  { case $msg in *threads*256*) ok ;; *) bad "--threads 65535: no message naming the limit: $msg" ;; esac; }

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

# Hostile but well-formed presets: refused at validation, fast, naming the field that drives
# the cost or the overflow.
expect_error samples-fill '{"J":1,"particles":{"count":1,"position_radius":1,"velocity":{"speed":1}},"dt":1e-3,"duration":1e6,"sample_every":1}' 'sample_every: 1e+09 samples need ~240 GB of memory (limit ~12 GB); raise sample_every'
expect_error repulsive-700 '{"J": -1, "particles": [{"m": 1, "r": [0.5,0,0], "v": [0,0,0]}, {"m": 1, "r": [-0.5,0,0], "v": [0,0,0]}], "dt": 0.01, "duration": 494.97474683058323}' "duration: an isolated repulsive system's energies grow as exp(2 Omega t)"
expect_error overflow-J '{"J": 1e308, "particles": [{"m": 1, "r": [0,0,0], "v": [0,0,0]}, {"m": 1, "r": [0.1,0,0], "v": [0,0,0]}], "dt": 0.1, "duration": 1}' 'J: J * M = inf must stay within +-1e300'
expect_error overflow-mass '{"J": 1, "particles": [{"m": 1e308, "r": [0,0,0], "v": [0,0,0]}, {"m": 1e308, "r": [0,0,0], "v": [0,0,0]}], "dt": 0.1, "duration": 1}' 'particles: the total mass M = inf must stay <= 1e300'
expect_error overflow-r '{"J": 1, "particles": [{"m": 1, "r": [1e200,0,0], "v": [0,0,0]}], "dt": 0.1, "duration": 1}' 'particles: the energies at t = 0 could reach inf'
expect_error expansion-factor '{"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}}, "container": {"radius": 1}, "dt": 1e-3, "expansion": {"factor": 1e308, "stages": 1000, "tau": 1e-3}}' 'expansion.factor: the container would grow to R * factor^(stages - 1) = inf'
expect_error tau-over-dt '{"J": 1, "particles": {"count": 10, "position_radius": 1, "velocity": {"speed": 1}}, "container": {"radius": 1}, "dt": 1e-300, "expansion": {"factor": 1.1, "stages": 1000000, "tau": 1e300}}' 'expansion.tau: tau / dt = inf steps per stage'
expect_error months-of-work '{"J":1,"particles":{"count":10000000,"position_radius":1,"velocity":{"speed":1}},"dt":1e-3,"duration":1e6,"sample_every":1000000}' 'duration: 1e+07 particles x 1e+09 steps = 1e+16 particle-steps (limit 4e+12)'
# Gravity, a floor and drag (Appendix B): one message naming the field and the rule.
two='"particles":[{"m":1,"r":[0,0,1],"v":[1,0,0]},{"m":2,"r":[0,0.5,2],"v":[0,0,0]}]'
expect_error floor-restitution "{\"J\":1,$two,\"dt\":0.01,\"duration\":1,\"floor\":{\"z\":0,\"restitution\":2}}" 'floor.restitution: must be in [0, 1]'
expect_error floor-above "{\"J\":1,$two,\"dt\":0.01,\"duration\":1,\"floor\":{\"z\":1.5}}" 'particles[0].r: starts below the floor (z = 1 < floor.z = 1.5)'
expect_error drag-b-analytic "{\"J\":1,$two,\"dt\":0.01,\"duration\":1,\"drag\":{\"b\":1,\"particles\":[0]}}" 'drag.b: drag on chosen particles breaks the centre-of-mass picture'
expect_error gravity-short "{\"J\":1,$two,\"dt\":0.01,\"duration\":1,\"gravity\":[0,-9.8]}" 'gravity: must be an array of 3 numbers [x, y, z]'
expect_error duplicate-key "{$good, \"duration\": 1, \"J\": 2}" 'J: given twice (each key at most once)'
expect_error trailing "{$good, \"duration\": 1} {}" 'preset: not valid JSON'

# The energy books are printed for every run that exchanges energy with the outside, walls
# included, and they balance: E_end - E0 - books is rounding.
gas='"J":0,"particles":{"count":200,"position_radius":0.9,"velocity":{"temperature":1},"seed":3},"dt":0.001,"duration":0.4'
printf '{%s,"container":{"radius":1,"moves":[{"to":0.8,"speed":1}]}}' "$gas" >"$work/moving.json"
printf '{%s,"container":{"radius":1,"wall_temperature":3}}' "$gas" >"$work/hot.json"
for wall in moving hot; do
  "$bin" run "$work/$wall.json" >"$work/stdout" 2>"$work/stderr" || { bad "$wall wall run: $(cat "$work/stderr")"; continue; }
  python3 - "$work/stdout" "$wall" <<'PY' && ok || bad "$wall wall: the books in the summary: $(cat "$work/stdout")"
import sys
rows = dict(l.split(None, 1) for l in open(sys.argv[1]) if len(l.split()) == 2)
E0, E_end = float(rows["E0"]), float(rows["E_end"])
books = float(rows["work"]) + float(rows["heat"]) - float(rows["drag_loss"])
assert abs(books) > 1e-3 * E0, "nothing booked"
assert abs(E_end - E0 - books) < 1e-9 * E0 and abs(float(rows["E_end-E0-books"])) < 1e-9 * E0
assert (float(rows["heat"]) != 0) == (sys.argv[2] == "hot")
PY
done

# Ten million particles run in the CLI, but not with RESULT.json (~17 GB): refused at once.
printf '{"J":1,"particles":{"count":10000000,"position_radius":1,"velocity":{"speed":1}},"dt":1e-3,"duration":1e-3}' >"$work/ten-million.json"
"$bin" validate "$work/ten-million.json" >/dev/null 2>&1 && ok || bad "ten million particles: not valid"
start=$(date +%s.%N)
"$bin" run "$work/ten-million.json" --out "$work/ten-million.out.json" 2>"$work/stderr" >/dev/null &&
  bad "ten million particles with --out: exit 0" || {
  grep -qF 'particles.count: 1e+07 particles need ~16.6 GB of memory (limit ~12 GB), RESULT.json included; use fewer particles' "$work/stderr" &&
    ok || bad "ten million with --out: $(cat "$work/stderr")"; }
python3 -c "import sys; sys.exit(0 if $(date +%s.%N) - $start < 2 else 1)" && ok || bad "ten million with --out: refused after more than 2 s"
[ ! -e "$work/ten-million.out.json" ] && ok || bad "ten million with --out: wrote a file"

# Text after a NUL byte was once ignored.
printf '{%s, "duration": 1}\0{"J": 5}' "$good" >"$work/nul.json"
"$bin" validate "$work/nul.json" 2>"$work/stderr" >/dev/null && bad "NUL byte: valid" || {
  grep -qF 'preset: a NUL byte at offset' "$work/stderr" && ok || bad "NUL byte: $(cat "$work/stderr")"; }

# A 15 MB method name (100 MB once took 24-28 s and 600 MB to an error echoing it whole) is
# refused by a scan before parsing, within a few seconds, quoting a short prefix; a file over
# 16 MB is refused before it is read (tests/cli/ensemble_test.sh).
python3 -c "import sys; sys.stdout.write('{\"J\": 1, \"method\": \"' + 'x' * 15_000_000 + '\", \"particles\": [{\"m\": 1, \"r\": [0,0,0], \"v\": [0,0,0]}], \"dt\": 0.1, \"duration\": 1}')" >"$work/long-method.json"
start=$(date +%s.%N)
"$bin" validate "$work/long-method.json" 2>"$work/stderr" >/dev/null && bad "15 MB method: valid" || {
  [ "$(wc -c <"$work/stderr")" -lt 300 ] && grep -qF 'preset: the string at offset 20 ("xxxxxxxx' "$work/stderr" && ok ||
    bad "15 MB method: $(head -c 300 "$work/stderr")"; }
python3 -c "import sys; sys.exit(0 if $(date +%s.%N) - $start < 10 else 1)" && ok || bad "15 MB method: more than 10 s"
rm -f "$work/long-method.json"

# A name with terminal escape sequences is printed escaped, never raw.
printf '{"name": "\\u001b]0;pwned\\u0007\\u001b[2J", %s, "duration": 1}' "$good" >"$work/escape.json"
"$bin" run "$work/escape.json" >"$work/stdout" 2>&1 && ok || bad "escape name: run failed"
if grep -qP '\x1b|\x07' "$work/stdout"; then bad "escape name: raw control characters printed"; else ok; fi
grep -qF '\u001b]0;pwned\u0007\u001b[2J' "$work/stdout" && ok || bad "escape name: not shown escaped"

# report reads RESULT.json files with nulls (written by runs before non-finite numbers
# stopped a run).
"$bin" run "$work/good.json" --out "$work/with-nulls.json" --quiet &&
  python3 - "$work/with-nulls.json" <<'PY' && ok || bad "could not write a RESULT.json with nulls"
import json, sys
d = json.load(open(sys.argv[1]))
d["samples"][-1]["E"] = None
d["summary"]["E_end"] = None
d["summary"]["energy_drift"] = None
json.dump(d, open(sys.argv[1], "w"))
PY
"$bin" report "$work/with-nulls.json" --plots "$work/null-plots" --quiet 2>"$work/stderr" && ok ||
  bad "report refuses nulls: $(cat "$work/stderr")"

# A big run shows its progress about once a second (the bar once moved every steps/1000
# steps: for 1e6 particles 1e9 particle-steps between draws, minutes apart). Watched for 10 s,
# then stopped. The run sizes its chunks to 0.05-0.2 s and the bar draws after a second, so a
# gap is about 1 s; on a machine whose two cores carry the suite's other lane it was 1.00 and
# 1.14 s, so up to 2 s passes.
printf '{"J":1,"particles":{"count":1000000,"position_radius":1,"velocity":{"speed":1}},"container":{"radius":1},"dt":1e-3,"duration":1000}' >"$work/big.json"
python3 - "$bin" "$work/big.json" <<'PY' && ok || bad "big run: progress less often than every 2 s"
import os, subprocess, sys, time, select
p = subprocess.Popen([sys.argv[1], "run", sys.argv[2]], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
start = time.monotonic(); draws = []
os.set_blocking(p.stderr.fileno(), False)
while time.monotonic() - start < 10:
    select.select([p.stderr], [], [], 0.05)
    chunk = p.stderr.read()
    if chunk and b"running [" in chunk: draws.append(time.monotonic() - start)
p.kill(); p.wait()
gaps = [b - a for a, b in zip(draws, draws[1:])]
print("progress draws at", ["%.2f" % t for t in draws[:3]], "largest gap %.2f s" % max(gaps or [99]))
sys.exit(0 if draws and draws[0] < 8 and max(gaps or [99]) <= 2.0 else 1)
PY

finish
