#!/usr/bin/env bash
# Every output says what made it (app/report/provenance.h): run --out, the figures' SVG
# (<metadata>), CSV (leading '#' lines) and PNG (iTXt), report's figures, an ensemble's run
# records, report.json and runs.csv. Each names the version `swarmlab --version` prints,
# whether the tree was clean, a compiler, the host, today's UTC date and the seeds used.
# Usage: provenance_test.sh SWARMLAB PRESET_DIR
source "$(dirname "$0")/harness.sh"

version=$("$bin" --version | awk '{print $NF}')
[ -n "$version" ] && ok || bad "swarmlab --version printed nothing"
export VERSION=$version

# check.py: the checks every output shares, as functions the snippets below import.
cat >"$work/check.py" <<'PY'
import csv, datetime, os, re, struct, zlib
import xml.etree.ElementTree as ET

VERSION = os.environ["VERSION"]

def recent(date):
    """An ISO 8601 UTC date to the second, within five minutes of now."""
    t = datetime.datetime.strptime(date, "%Y-%m-%dT%H:%M:%SZ").replace(tzinfo=datetime.timezone.utc)
    age = abs((datetime.datetime.now(datetime.timezone.utc) - t).total_seconds())
    assert age < 300, (date, age)

def provenance(p, seeds):
    """A "provenance" object: this build, a compiler, a host, now, these seeds."""
    assert p["program"] == "swarmlab" and p["version"] == VERSION, (p, VERSION)
    assert VERSION.startswith(p["commit"]) and p["clean"] == ("-dirty-" not in VERSION), p
    assert p["compiler"].strip() and p["host"]["os"].strip() and p["host"]["machine"].strip(), p
    recent(p["date"])
    assert p["seeds"] == seeds, (p["seeds"], seeds)

def lines_say(lines, seeds_line, prefix=""):
    """Provenance lines (SVG metadata, CSV comments, PNG text): this build, a compiler, a host,
    now, the seeds; prefix: "run: " for a report's line about the run it draws."""
    mine = [l[len(prefix):] for l in lines if (l.startswith(prefix) if prefix else not l.startswith("run"))]
    assert mine[0].startswith("made by swarmlab " + VERSION + " "), mine
    tree = "with uncommitted changes" if "-dirty-" in VERSION else "with a clean tree"
    assert mine[0].endswith(tree), mine[0]
    fields = dict(l.split(": ", 1) for l in mine[1:])
    assert fields["compiler"].strip() and fields["host"].strip(), fields
    recent(fields["date"])
    assert "seeds: " + fields["seeds"] == seeds_line, (fields["seeds"], seeds_line)

def svg_lines(path):
    """The lines of an SVG's <metadata>, which must parse as XML."""
    root = ET.parse(path).getroot()
    meta = root.find("{http://www.w3.org/2000/svg}metadata")
    assert meta is not None and root[0] is meta, path
    return [l for l in meta.text.split("\n") if l]

def csv_parts(path):
    """The comment lines (without "# ") and the rows after them, read by Python's csv."""
    lines = open(path, newline="").readlines()
    comments = [l[2:].rstrip("\n") for l in lines if l.startswith("# ")]
    assert all(l.startswith("# ") for l in lines[:len(comments)]), "comments first"
    rows = list(csv.reader(l for l in lines if not l.startswith("#")))
    # Read whole, as a spreadsheet that does not skip comments would: each comment line is
    # one cell of text starting with '#', never a formula.
    for row in list(csv.reader(lines))[:len(comments)]:
        assert len(row) == 1 and row[0].startswith("# "), row
    return comments, rows

def png_text(path):
    """The iTXt chunks of a PNG, each CRC checked with zlib."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    text, at = {}, 8
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        assert struct.unpack(">I", data[at + 8 + n:at + 12 + n])[0] == zlib.crc32(kind + body), kind
        if kind == b"iTXt":
            key, rest = body.split(b"\0", 1)
            text[key.decode()] = rest[4:].decode()  # flag, method, empty language and key
        at += 12 + n
    return text
PY
export PYTHONPATH=$work

# One run: --out, --csv, and its figures with a PNG.
gas='{"version": 1, "name": "ideal gas", "J": 0, "particles": {"count": 100, "position_radius": 0.9, "velocity": {"temperature": 1}, "seed": 5}, "container": {"radius": 1}, "dt": 0.001, "duration": 0.2}'
printf '%s' "$gas" >"$work/gas.json"
png=()
command -v rsvg-convert >/dev/null && png=(--png)
if "$bin" run "$work/gas.json" --out "$work/gas.result.json" --csv "$work/samples.csv" \
  --plots "$work/figures" "${png[@]}" --quiet; then
  python3 - "$work/gas.result.json" <<'PY' && ok || bad "run --out: provenance"
import json, sys, check
check.provenance(json.load(open(sys.argv[1]))["provenance"], {"seed": 5})
PY
  python3 - "$work/figures/equilibration.svg" "$work/figures/equilibration.csv" <<'PY' && ok || bad "run --plots: SVG metadata, CSV comments"
import sys, check
check.lines_say(check.svg_lines(sys.argv[1]), "seeds: 5")
comments, rows = check.csv_parts(sys.argv[2])
check.lines_say(comments, "seeds: 5")
assert rows[0] == ["panel", "series", "time t", "y"] and len(rows) > 10, rows[:2]
assert all(len(r) == 4 for r in rows[1:]) and [float(r[3]) for r in rows[1:]]
PY
  # The samples CSV is a plain table: its header stays the first line (docs/command-line.md, --csv).
  head -1 "$work/samples.csv" | grep -q '^"t","P","T",' && ok || bad "samples CSV: the header is not the first line"
  if [ ${#png[@]} -gt 0 ]; then
    python3 - "$work/figures/equilibration.png" <<'PY' && ok || bad "run --png: text chunks"
import sys, check
text = check.png_text(sys.argv[1])
lines = text["Comment"].split("\n")
check.lines_say(lines, "seeds: 5")
assert text["Software"] == lines[0]
PY
  fi
else
  bad "run of the gas failed"
fi

# report of the saved run: this report's provenance, and the run's behind "run: ".
"$bin" report "$work/gas.result.json" --plots "$work/report" --quiet &&
  python3 - "$work/report/energy.svg" "$work/report/energy.csv" "$work/gas.result.json" <<'PY' && ok || bad "report: provenance of the report and of the run"
import json, sys, check
lines = check.svg_lines(sys.argv[1])
check.lines_say(lines, "seeds: 5")
check.lines_say(lines, "seeds: 5", prefix="run: ")
run = json.load(open(sys.argv[3]))["provenance"]
assert "run: date: " + run["date"] in lines, lines
comments, rows = check.csv_parts(sys.argv[2])
assert comments == lines and rows[0][:2] == ["panel", "series"]
PY

# A RESULT.json whose provenance holds markup, a line break and a formula: the SVG is still
# well-formed XML with the text as text, and each CSV comment stays one line and one cell.
python3 - "$work/gas.result.json" "$work/hostile.result.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
r["provenance"]["compiler"] = 'x</metadata><script>&amp;\n,=HYPERLINK("http://x");@SUM(1)'
json.dump(r, open(sys.argv[2], "w"))
PY
"$bin" report "$work/hostile.result.json" --plots "$work/hostile" --quiet &&
  python3 - "$work/hostile/energy.svg" "$work/hostile/energy.csv" <<'PY' && ok || bad "report: hostile provenance text"
import sys, check
lines = check.svg_lines(sys.argv[1])
assert 'run: compiler: x</metadata><script>&amp;\\n,=HYPERLINK("http://x");@SUM(1)' in lines, lines
comments, rows = check.csv_parts(sys.argv[2])
assert "run: compiler: x</metadata><script>&amp \\n =HYPERLINK( http://x ) @SUM(1)" in comments, comments
PY

# An ensemble: each run's record, report.json and runs.csv, and report's figures of it.
if "$bin" ensemble "$work/gas.json" --seeds 3 --seed 7 --out "$work/ens" --jobs 2 --quiet; then
  python3 - "$work/ens" <<'PY' && ok || bad "ensemble: provenance of the runs, report.json, runs.csv"
import json, sys, check
d = sys.argv[1]
report = json.load(open(d + "/report.json"))
check.provenance(report["provenance"], {"base": 7, "runs": 3})
seeds = []
for k in range(3):
    r = json.load(open("%s/runs/%d.json" % (d, k)))
    check.provenance(r["provenance"], {"seed": r["seed"]})
    seeds.append(r["seed"])
comments, rows = check.csv_parts(d + "/runs.csv")
check.lines_say(comments, "seeds: master seed 7 and runs 0 to 2 (run k starts from run_seed of the two)")
assert rows[0][:2] == ["index", "seed"] and [int(r[1]) for r in rows[1:]] == seeds, rows
PY
  "$bin" report "$work/ens/report.json" --plots "$work/ens/figures" --quiet &&
    python3 - "$work/ens/figures/ensemble-time.svg" <<'PY' && ok || bad "report of an ensemble: provenance"
import sys, check
check.lines_say(check.svg_lines(sys.argv[1]), "seeds: master seed 7 and runs 0 to 2 (run k starts from run_seed of the two)")
PY
  # A record whose provenance was edited (another host) no longer matches its digest.
  python3 - "$work/ens/runs/1.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
r["provenance"]["host"]["os"] = "elsewhere"
json.dump(r, open(sys.argv[1], "w"))
PY
  "$bin" merge "$work/ens" --quiet && python3 - "$work/ens/report.json" <<'PY' && ok || bad "an edited provenance passed the digest"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["runs"] == 2 and [c["index"] for c in r["corrupted"]] == [1], r["corrupted"]
assert r["corrupted"][0]["error"].startswith("digest: does not match"), r["corrupted"]
PY
else
  bad "ensemble failed"
fi

finish
