#!/usr/bin/env bash
# Ensembles as a research group would run them: swarmlab ensemble here, the same runs from the
# manifest through GNU parallel (locally and on two "hosts" through an ssh stand-in) and through
# the Slurm array script; they must be the same bits and merge to the same report. Then a
# killed ensemble resumed, a corrupted run, and bad input.
# Usage: ensemble_test.sh SWARMLAB PRESET_DIR
source "$(dirname "$0")/harness.sh"

# An ideal gas (J = 0) starting in equilibrium: uniform in the ball, Maxwellian, CM at rest.
gas='{"version": 1, "name": "ideal gas", "J": 0, "particles": {"count": 200, "position_radius": 0.999, "velocity": {"temperature": 1}, "cm_at_rest": true, "seed": 5}, "container": {"radius": 1}, "dt": 0.001, "duration": 0.5}'
printf '%s' "$gas" >"$work/gas.json"

# The ensemble here, and the report's documented keys.
if "$bin" ensemble "$work/gas.json" --seeds 6 --seed 11 --out "$work/here" --jobs 2 --quiet; then
  python3 - "$work/here/report.json" <<'PY' && ok || bad "report keys"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["runs"] == 6 and r["missing"] == [] and r["failed"] == []
for name in ("P", "T"):
    q = r["quantities"][name]
    assert len(q["values"]) == 6 and q["ci95"][0] < q["mean"] < q["ci95"][1], name
    assert q["sd"] > 0 and abs(q["se"] - q["sd"] / 6 ** 0.5) < 1e-12 * q["sd"]
    assert q["within_se"] > 0 and q["spread_ratio"] > 0 and q["runs_for_half_width"]["runs"] >= 2
assert len(r["bands"]["time"]["t"]) == len(r["bands"]["time"]["P"]["mean"]) > 10
PY
  [ "$(wc -l <"$work/here/runs.csv")" -eq 7 ] && head -1 "$work/here/runs.csv" | grep -q '^index,seed,P,T,' && ok || bad "runs.csv"
else
  bad "ensemble failed"
fi

# The report draws the ensemble's bands.
"$bin" report "$work/here/report.json" --plots "$work/here/figures" --quiet &&
  grep -q "95 % interval over runs" "$work/here/figures/ensemble-time.svg" && ok || bad "report of an ensemble"

# The same runs from a manifest: each line a plain swarmlab run, the same bits as the ensemble.
same_runs() {  # DIR: every runs/<k>.json equals the ensemble's, byte for byte
  for k in 0 1 2 3 4 5; do cmp -s "$work/here/runs/$k.json" "$1/runs/$k.json" || return 1; done
}
same_report() {  # DIR: the merge gives the ensemble's quantities
  "$bin" merge "$1" --quiet && python3 - "$work/here/report.json" "$1/report.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert a["quantities"] == b["quantities"] and a["bands"] == b["bands"]
PY
}
"$bin" plan "$work/gas.json" --seeds 6 --seed 11 --out "$work/local" --quiet || bad "plan"
[ "$(wc -l <"$work/local/manifest.txt")" -eq 6 ] && ok || bad "manifest: one line per run"
if command -v parallel >/dev/null; then
  parallel --will-cite --joblog "$work/local/joblog" --resume-failed -S : <"$work/local/manifest.txt" &&
    same_runs "$work/local" && same_report "$work/local" && ok || bad "GNU parallel -S : gives other runs"
  # Two hosts: an ssh stand-in that runs the command here, whatever host it is given
  # (parallel calls it as: HOST -- COMMAND...). A login over ssh sets SHELL, which parallel's
  # remote wrapper execs; CI's environment may not have it (then every job silently does nothing).
  printf '#!/bin/sh\nshift\n[ "$1" = "--" ] && shift\nexport SHELL=/bin/sh\nexec sh -c "$*"\n' >"$work/fake-ssh" && chmod +x "$work/fake-ssh"
  "$bin" plan "$work/gas.json" --seeds 6 --seed 11 --out "$work/hosts" --quiet &&
    parallel --will-cite --ssh "$work/fake-ssh" -S 1/host-a,1/host-b <"$work/hosts/manifest.txt" &&
    same_runs "$work/hosts" && same_report "$work/hosts" && ok || bad "GNU parallel on two hosts gives other runs"
else
  bad "GNU parallel is not installed (scripts/deps.sh native)"
fi
# The Slurm array script, each index run as Slurm would run it.
"$bin" plan "$work/gas.json" --seeds 6 --seed 11 --out "$work/slurm" --slurm --at-once 3 --quiet &&
  grep -q '^#SBATCH --array=0-5%3$' "$work/slurm/array.sbatch" || bad "array.sbatch"
for i in 0 1 2 3 4 5; do SLURM_ARRAY_TASK_ID=$i bash "$work/slurm/array.sbatch" || bad "slurm task $i"; done
same_runs "$work/slurm" && same_report "$work/slurm" && ok || bad "the Slurm array gives other runs"

# Resume: killed mid-way, started again, only the missing runs run (the done ones keep their
# inode and time), and the report is the same as one uninterrupted ensemble's.
long='{"version": 1, "name": "ideal gas", "J": 0, "particles": {"count": 2000, "position_radius": 0.999, "velocity": {"temperature": 1}, "cm_at_rest": true, "seed": 5}, "container": {"radius": 1}, "dt": 0.001, "duration": 3}'
printf '%s' "$long" >"$work/long.json"
"$bin" ensemble "$work/long.json" --seeds 12 --out "$work/killed" --jobs 1 --quiet &
pid=$!
for _ in $(seq 1 600); do
  [ "$(ls "$work/killed/runs" 2>/dev/null | wc -l)" -ge 2 ] && break
  sleep 0.05
done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
before=$(cd "$work/killed/runs" && ls | sort)
kept=$(cd "$work/killed/runs" && stat -c '%n %i %Y' $before)
count=$(echo "$before" | wc -w)
if [ "$count" -ge 2 ] && [ "$count" -lt 12 ]; then
  "$bin" ensemble "$work/long.json" --seeds 12 --out "$work/killed" --jobs 2 2>"$work/stderr" >/dev/null || bad "resume failed"
  grep -q "$count of 12 runs already done" "$work/stderr" && ok || bad "resume: $(cat "$work/stderr")"
  [ "$(cd "$work/killed/runs" && stat -c '%n %i %Y' $before)" = "$kept" ] && ok || bad "resume ran a done run again"
  [ "$(ls "$work/killed/runs" | wc -l)" -eq 12 ] && ok || bad "resume left runs missing"
else
  bad "resume: the ensemble was killed with $count runs done (expected some but not all)"
fi
# Nothing is left half-written by the kill: every run file is a whole record.
"$bin" merge "$work/killed" --quiet && python3 -c "
import json,sys; r=json.load(open('$work/killed/report.json')); sys.exit(r['runs'] != 12 or r['corrupted'] != [])" &&
  ok || bad "resumed ensemble does not merge whole"

# A corrupted run is named, never merged, and run again by the next ensemble.
head -c 100 "$work/here/runs/3.json" >"$work/here/runs/3.tmp" && mv "$work/here/runs/3.tmp" "$work/here/runs/3.json"
"$bin" merge "$work/here" --quiet && python3 -c "
import json,sys; r=json.load(open('$work/here/report.json')); sys.exit(r['runs'] != 5 or [c['index'] for c in r['corrupted']] != [3])" &&
  ok || bad "a corrupted run was merged or not named"
"$bin" ensemble "$work/gas.json" --seeds 6 --seed 11 --out "$work/here" --quiet 2>"$work/stderr" &&
  grep -q "runs/3.json: not a complete JSON object" "$work/stderr" && same_runs "$work/local" && ok ||
  bad "a corrupted run was not run again: $(cat "$work/stderr")"

# Bad input: one clear message each, a non-zero exit, and no report written.
refused() {  # NAME MESSAGE COMMAND...
  local name=$1 message=$2
  shift 2
  rm -f "$work/stderr"
  if "$@" >/dev/null 2>"$work/stderr"; then bad "$name: exit 0"; return; fi
  grep -qF -- "$message" "$work/stderr" && ok || bad "$name: expected '$message', got: $(cat "$work/stderr")"
}
cp "$work/local/runs/0.json" "$work/mixed.json"
"$bin" ensemble "$work/long.json" --seeds 2 --out "$work/other" --quiet || bad "other ensemble"
cp "$work/other/runs/1.json" "$work/local/runs/1.json"
rm -f "$work/local/report.json"
refused mixed "runs/1.json: a run of another preset" "$bin" merge "$work/local"
[ ! -e "$work/local/report.json" ] && ok || bad "mixed: a report was written"
# A run whose seed is not the plan's (an edited manifest line) is named, not merged.
python3 - "$work/here/runs/4.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); r["seed"] += 1; json.dump(r, open(sys.argv[1], "w"))
PY
refused wrong-seed "runs/4.json: started from seed" "$bin" merge "$work/here"
mkdir -p "$work/empty"
refused empty "plan.json: missing: not an ensemble folder" "$bin" merge "$work/empty"
"$bin" plan "$work/gas.json" --seeds 3 --out "$work/none" --quiet
refused nothing-run "no run has finished yet (3 missing" "$bin" merge "$work/none"
refused seeds-zero "--seeds" "$bin" ensemble "$work/gas.json" --seeds 0 --out "$work/z"
refused seeds-negative "--seeds" "$bin" plan "$work/gas.json" --seeds -4 --out "$work/z"
printf '{"J": 1, "particles": [{"m": 1, "r": [0.5, 0, 0], "v": [0, 1, 0]}, {"m": 1, "r": [-0.5, 0, 0], "v": [0, -1, 0]}], "dt": 0.01, "duration": 1}' >"$work/listed.json"
refused listed "particles: listed particles start every run the same" "$bin" ensemble "$work/listed.json" --seeds 4 --out "$work/l"
"$bin" ensemble "$work/listed.json" --seeds 4 --out "$work/l" --perturb 0.01 --quiet && ok || bad "listed with --perturb"
big='{"J": 1, "particles": {"count": 1000000, "position_radius": 1, "velocity": {"speed": 1}}, "dt": 0.001, "duration": 1000, "sample_every": 100000}'
printf '%s' "$big" >"$work/big.json"
refused budget "--seeds: 1000 runs need" "$bin" ensemble "$work/big.json" --seeds 1000 --out "$work/big" --jobs 2
refused changed "--preset-hash: the preset has changed since the plan" \
  "$bin" run "$work/gas.json" --seed 1 --run-index 0 --preset-hash 0123456789abcdef --record "$work/r.json"
refused other-plan "holds another ensemble (12 seeds)" "$bin" ensemble "$work/long.json" --seeds 5 --out "$work/killed"

# A sweep: a grid over two keys of the base preset, its points' values in the report and in
# runs.csv, the same seeds at every point, and the same runs through the manifest.
printf '{"preset": "gas.json", "grid": {"particles.count": [100, 300], "container.radius": [1.0, 1.5]}, "seeds": 3}' >"$work/sweep.json"
if "$bin" ensemble "$work/sweep.json" --out "$work/sweep" --quiet; then
  python3 - "$work/sweep/report.json" "$work/sweep/runs.csv" <<'PY' && ok || bad "sweep report"
import csv, json, sys
r = json.load(open(sys.argv[1]))
assert r["runs"] == 12 and len(r["points"]) == 4
vals = [p["values"] for p in r["points"]]
assert vals == [{"container.radius": R, "particles.count": n} for R in (1.0, 1.5) for n in (100, 300)], vals
# The ideal gas: P grows with N (3x the particles, about 3x P) and falls with V (the bigger
# sphere is still filling in 0.5 time units, so by more than the volume ratio 3.4).
P = {(p["values"]["container.radius"], p["values"]["particles.count"]): p["quantities"]["P"]["mean"] for p in r["points"]}
assert 2.4 < P[(1.0, 300)] / P[(1.0, 100)] < 3.6 and P[(1.0, 100)] / P[(1.5, 100)] > 2.4, P
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(rows) == 12 and rows[0]["particles.count"] == "100" and rows[3]["particles.count"] == "300"
assert rows[0]["seed"] == rows[3]["seed"] == rows[6]["seed"]   # the same seeds at every point
PY
else
  bad "sweep ensemble"
fi
"$bin" plan "$work/sweep.json" --out "$work/sweep-plan" --quiet &&
  [ "$(wc -l <"$work/sweep-plan/manifest.txt")" -eq 12 ] &&
  grep -q "sweep-plan/points/3.json' --seed" "$work/sweep-plan/manifest.txt" && ok || bad "sweep manifest"
"$bin" report "$work/sweep/report.json" --plots "$work/sweep/figures" --quiet &&
  [ -s "$work/sweep/figures/point3-ensemble-time.svg" ] && ok || bad "report of a sweep"
(cd "$work" && bash sweep-plan/manifest.txt >/dev/null) && cmp -s "$work/sweep/runs/7.json" "$work/sweep-plan/runs/7.json" &&
  ok || bad "a sweep's manifest line gives another run"
printf '{"preset": "gas.json", "grid": {"particles.countt": [100, 300]}, "seeds": 3}' >"$work/sweep-bad.json"
refused sweep-unknown-key "particles.countt: not a key of the base preset" "$bin" ensemble "$work/sweep-bad.json" --out "$work/sb"
printf '{"preset": "gas.json", "points": [{"J": 0}, {"particles.count": -5}], "seeds": 2}' >"$work/sweep-bad2.json"
refused sweep-bad-value 'point {"particles.count":-5}: particles.count' "$bin" plan "$work/sweep-bad2.json" --out "$work/sb2"

finish
