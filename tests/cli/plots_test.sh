#!/usr/bin/env bash
# Drives `swarmlab run --plots` and `swarmlab report` as a user would: the figures a run has,
# well-formed SVG with the CSV behind each, the overlay of two saved runs, and one clear error
# (exit 1, no file) for a directory that cannot be written.
# Usage: plots_test.sh SWARMLAB PRESET_DIR
source "$(dirname "$0")/harness.sh"

# has_figures DIR NAME...: each NAME.svg parses as SVG and NAME.csv has the header and rows.
has_figures() {
  local dir=$1
  shift
  for name in "$@"; do
    python3 - "$dir/$name.svg" "$dir/$name.csv" 2>/dev/null <<'PY' && ok || bad "$dir/$name: not a good SVG + CSV pair"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag.endswith("svg"), root.tag
assert any(e.tag.endswith("polyline") or e.tag.endswith("circle") for e in root.iter())
import csv
# What made the figure comes first, as comment lines (tests/cli/provenance_test.sh).
rows = list(csv.reader(l for l in open(sys.argv[2], newline="") if not l.startswith("#")))
assert rows[0][:2] == ["panel", "series"] and rows[0][-1] == "y" and len(rows) > 2, rows[:2]
assert all(len(r) == 4 for r in rows[1:]) and [float(r[2]) + float(r[3]) for r in rows[1:]], rows[1]
PY
  done
}

# Orbits of a small explicit system, with its energies.
"$bin" run "$presets/fig1-four-masses.json" --plots "$work/fig1" --quiet && ok || bad "fig1 run"
has_figures "$work/fig1" energy orbits orbits-return
# Methods side by side.
"$bin" run "$presets/methods-vs-analytic.json" --plots "$work/methods" --quiet && ok || bad "methods run"
has_figures "$work/methods" methods-energy methods-position-error
# A small expansion, saved twice with different stage lengths, then overlaid.
expansion='"J": 0.002, "particles": {"count": 100, "mass": {"min": 4, "max": 5}, "position_radius": 1,
  "velocity": {"speed": 1}, "seed": 3},
  "container": {"radius": 1}, "dt": 0.01'
printf '{%s, "expansion": {"factor": 1.1, "stages": 5, "tau": 2}}' "$expansion" >"$work/short.json"
printf '{%s, "expansion": {"factor": 1.1, "stages": 5, "tau": 8}}' "$expansion" >"$work/long.json"
"$bin" run "$work/short.json" --plots "$work/short" --out "$work/short.result.json" >"$work/stdout" &&
  grep -q "wrote 8 figures to $work/short" "$work/stdout" && ok || bad "expansion run: $(cat "$work/stdout")"
has_figures "$work/short" energy wall-history stages-T-V stages-P-V stages-P-T loglog-T-V loglog-P-V loglog-P-T
"$bin" run "$work/long.json" --out "$work/long.result.json" --quiet && ok || bad "second expansion run"
"$bin" report "$work/long.result.json" "$work/short.result.json" --plots "$work/overlay" --quiet && ok || bad "report overlay"
has_figures "$work/overlay" overlay-T-V overlay-P-V overlay-P-T
grep -q 'stroke-dasharray="7 4"' "$work/overlay/overlay-P-V.svg" && ok || bad "overlay: second run not dashed"
# One saved run gives the same figures as --plots did: the same drawing, to the byte, apart
# from the <metadata> that says what made each file (the report's date is not the run's).
"$bin" report "$work/short.result.json" --plots "$work/again" --quiet && ok || bad "report one result"
drawing() { sed '/^<metadata/,/^<\/metadata>/d' "$1"; }
[ "$(drawing "$work/short/loglog-P-V.svg")" = "$(drawing "$work/again/loglog-P-V.svg")" ] &&
  grep -q '^<metadata' "$work/again/loglog-P-V.svg" && ok || bad "report differs from run --plots"
# Nothing temporary is left behind.
ls -A "$work/short" | grep -q '^\.' && bad "hidden temporary left in the plot directory" || ok

# A plot directory that cannot be made: one line, exit 1, and no other output written.
touch "$work/a-file"
for target in "$work/a-file" "$work/a-file/sub"; do
  "$bin" run "$presets/fig1-four-masses.json" --plots "$target" --out "$work/refused.json" \
    >/dev/null 2>"$work/stderr"
  code=$?
  if [ $code -ne 1 ]; then bad "--plots $target: exit $code"; continue; fi
  [ "$(wc -l <"$work/stderr")" -eq 1 ] && grep -q "^error: $target" "$work/stderr" && ok ||
    bad "--plots $target: $(cat "$work/stderr")"
  [ -e "$work/refused.json" ] && bad "--plots $target: wrote --out anyway" || ok
done
"$bin" report "$work/nope.json" --plots "$work/x" 2>"$work/stderr" && bad "report of a missing file: exit 0" ||
  { grep -q "nope.json: cannot open the file" "$work/stderr" && ok || bad "report missing: $(cat "$work/stderr")"; }
"$bin" report "$presets/fig1-four-masses.json" --plots "$work/x" 2>"$work/stderr" && bad "report of a preset: exit 0" ||
  { grep -q "not a RESULT.json" "$work/stderr" && ok || bad "report preset: $(cat "$work/stderr")"; }
# A RESULT.json cut short: where it breaks, in one line, without nlohmann's exception code.
"$bin" run "$presets/fig1-four-masses.json" --out "$work/whole.json" --quiet && head -c 300 "$work/whole.json" >"$work/cut.json"
"$bin" report "$work/cut.json" --plots "$work/x" 2>"$work/stderr" && bad "report of a cut RESULT.json: exit 0" ||
  { grep -q "cut.json: not valid JSON at line [0-9]*, column [0-9]*: " "$work/stderr" && ! grep -q "json.exception" "$work/stderr" &&
    [ "$(wc -l <"$work/stderr")" -eq 1 ] && ok || bad "report cut: $(cat "$work/stderr")"; }
# A lesson given to run: said to be a lesson, with what opens it (not "lesson: unknown key").
"$bin" run "$presets/../lessons/01-one-period.json" --out "$work/lesson-run.json" 2>"$work/stderr" &&
  bad "run of a lesson: exit 0" ||
  { grep -q "01-one-period.json: a lesson, not a preset: open it in the app" "$work/stderr" &&
    [ "$(wc -l <"$work/stderr")" -eq 1 ] && [ ! -e "$work/lesson-run.json" ] && ok || bad "run lesson: $(cat "$work/stderr")"; }
"$bin" run "$presets/fig1-four-masses.json" --png 2>/dev/null && bad "--png without --plots accepted" || ok
"$bin" run --help | grep -q -- --plots && ok || bad "run --help lacks --plots"

# Two temperatures: where a figure draws the wall's T it draws T kinetic = (2/3) KE / N (CM
# frame) beside it. Checked against the run's own final particles (RESULT.json), not the code.
# series_of CSV NAME: the y values of the series called NAME, in order.
series_of() {
  python3 - "$1" "$2" <<'PY'
import csv, sys
rows = csv.reader(l for l in open(sys.argv[1], newline="") if not l.startswith("#"))
next(rows)
print(" ".join(r[3] for r in rows if r[1] == sys.argv[2]))
PY
}
kinetic='T kinetic, (2/3) KE/N'
# A J = 0 Maxwellian gas, expanded in three stages: the last sample's T kinetic is that of the
# final state to the CSV's 8 digits; each stage's (KE is kept by still, elastic walls; only the
# CM's share moves with the wall's impulses) within 0.5 % of it; the wall's T agrees within
# 3 standard errors: a hitter's 1/2 m v^2 is Gamma(2, T) distributed, so the wall's T over n
# hits has a relative error of 1 / sqrt(2 n).
printf '{"J": 0, "particles": {"count": 1000, "position_radius": 1, "velocity": {"temperature": 0.5},
  "cm_at_rest": true, "seed": 7}, "container": {"radius": 1}, "dt": 0.002,
  "expansion": {"factor": 1.05, "stages": 3, "tau": 4}}' >"$work/maxwell.json"
"$bin" run "$work/maxwell.json" --plots "$work/maxwell" --out "$work/maxwell.result.json" --quiet &&
  ok || bad "J = 0 expansion run"
python3 - "$work/maxwell.result.json" "$(series_of "$work/maxwell/wall-history.csv" "$kinetic")" \
  "$(series_of "$work/maxwell/stages-T-V.csv" "$kinetic, over the same window")" \
  "$(series_of "$work/maxwell/stages-T-V.csv" "T at the wall at the end of each stage")" <<'PY' &&
import json, sys
final = json.load(open(sys.argv[1]))["final"]["particles"]
M = sum(p["m"] for p in final)
V = [sum(p["m"] * p["v"][k] for p in final) / M for k in range(3)]
ke_cm = sum(0.5 * p["m"] * sum((p["v"][k] - V[k]) ** 2 for k in range(3)) for p in final)
T = 2 * ke_cm / (3 * len(final))
history = [float(x) for x in sys.argv[2].split()]
stages = [float(x) for x in sys.argv[3].split()]
wall = [float(x) for x in sys.argv[4].split()]
hits = [s["hits"] for s in json.load(open(sys.argv[1]))["stages"]]
assert abs(history[-1] / T - 1) < 1e-7, (history[-1], T)
assert len(stages) == 3 and all(abs(s / T - 1) < 0.005 for s in stages), (stages, T)
assert len(wall) == 3 and all(abs(w / T - 1) < 3 / (2 * n) ** 0.5 for w, n in zip(wall, hits)), (wall, hits, T)
PY
  ok || bad "J = 0 Maxwellian: T kinetic in wall-history and stages-T-V"
[ -n "$(series_of "$work/maxwell/stages-P-T.csv" "P against $kinetic")" ] &&
  [ -n "$(series_of "$work/maxwell/loglog-T-V.csv" "$kinetic (not fitted)")" ] &&
  grep -q "$kinetic" "$work/maxwell/stages-P-T.svg" && ok || bad "P-T and log-log: no T kinetic"
# Speeds uniform in a ball (not Maxwellian, J = 0: each particle keeps its speed). A particle
# hits the wall at a rate proportional to its speed, so the wall's T, half the hitters' mean
# 1/2 m v^2, is (1/4) sum m v^3 / sum v, below T kinetic: 1/6 against 1/5 for these speeds.
# The fixed container's figure draws both over the wall's mean, so T kinetic's series is
# their ratio, 1.2.
printf '{"J": 0, "particles": {"count": 2000, "position_radius": 1, "velocity": {"speed": 1},
  "cm_at_rest": true, "seed": 14}, "container": {"radius": 1}, "dt": 0.001, "duration": 8,
  "sample_every": 10}' >"$work/ball.json"
"$bin" run "$work/ball.json" --plots "$work/ball" --out "$work/ball.result.json" --quiet &&
  ok || bad "ball-speeds run"
python3 - "$work/ball.result.json" "$(series_of "$work/ball/equilibration.csv" "$kinetic, over the same mean")" <<'PY' &&
import json, sys
final = json.load(open(sys.argv[1]))["final"]["particles"]
speeds = [sum(x * x for x in p["v"]) ** 0.5 for p in final]
T_wall = 0.25 * sum(p["m"] * v ** 3 for p, v in zip(final, speeds)) / sum(speeds)
T_kinetic = sum(p["m"] * v * v for p, v in zip(final, speeds)) / (3 * len(final))
ratio = [float(x) for x in sys.argv[2].split()]
expected = T_kinetic / T_wall
assert 1.15 < expected < 1.25, expected
assert ratio and all(abs(r / expected - 1) < 0.025 for r in ratio), (min(ratio), max(ratio), expected)
PY
  ok || bad "ball speeds: T kinetic over the wall's T is not (sum m v^2 / 3N) / ((1/4) sum m v^3 / sum v)"
grep -q "T at the wall" "$work/ball/equilibration.svg" && grep -q "$kinetic" "$work/ball/equilibration.svg" &&
  ok || bad "equilibration.svg: the two temperatures not named"
# A RESULT.json written before T kinetic was recorded still reads; its figures have only T.
python3 - "$work/maxwell.result.json" "$work/old.result.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
for row in j["samples"] + j["stages"]:
    del row["T_kinetic"]
json.dump(j, open(sys.argv[2], "w"))
PY
"$bin" report "$work/old.result.json" --plots "$work/old" --quiet && ! grep -q "$kinetic" "$work/old"/*.csv &&
  has_figures "$work/old" wall-history stages-T-V && ok || bad "a RESULT.json without T_kinetic"

# A stage without a wall hit has no wall T: a gap in the T-V line and "nan" in its CSV, not 0.
python3 - "$work/short.result.json" "$work/no-hits.result.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
j["stages"][2]["hits"], j["stages"][2]["T"], j["stages"][2]["P"] = 0, 0, 0
json.dump(j, open(sys.argv[2], "w"))
PY
"$bin" report "$work/no-hits.result.json" --plots "$work/no-hits" --quiet &&
  python3 - "$work/no-hits/stages-T-V.csv" "$work/no-hits/stages-T-V.svg" "$work/no-hits.result.json" <<'PY' && ok || bad "a stage without hits drawn at T = 0"
import csv, json, sys
rows = [r for r in csv.reader(l for l in open(sys.argv[1]) if not l.startswith("#"))][1:]
wall = [r[3] for r in rows if r[1].startswith("T at the wall")]
hits = [s["hits"] for s in json.load(open(sys.argv[3]))["stages"]]
assert len(wall) == 5 and wall[2] == "nan", wall
assert all((w == "nan") == (h == 0) and (h == 0 or float(w) > 0) for w, h in zip(wall, hits)), (wall, hits)
svg = open(sys.argv[2]).read()
assert svg.count("<polyline") >= 3, svg.count("<polyline")  # the wall's T in two pieces, T kinetic whole
PY

# PNGs where rsvg-convert is installed (scripts/deps.sh native installs it).
if command -v rsvg-convert >/dev/null; then
  "$bin" run "$presets/fig1-four-masses.json" --plots "$work/png" --png --quiet &&
    [ "$(head -c 4 "$work/png/orbits.png" | tail -c 3)" = PNG ] && ok || bad "--png"
fi

finish
