#!/usr/bin/env bash
# scripts/i18n.py check on tables a hostile translator wrote: each translation is held to the
# rules of its English field (a lesson title's length, something visible, no control character),
# one line per problem naming the language, the rule and the text, and exit 1.
# The language table (languages.json) is held to its rules and to the folder's tables too.
# Usage: i18n_test.sh (from anywhere; uses the repository's scripts/i18n.py and assets/i18n/)
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

cp "$root"/assets/i18n/*.json "$work/"
python3 "$root/scripts/i18n.py" check "$work" >"$work/out" 2>/dev/null || bad "the shipped tables: $(cat "$work/out")"

# The first lesson's title 8,000 bytes long in German, a Spanish option of only U+202E, a
# French text of zero-width characters and direction marks, and DEL and a C1 control.
python3 - "$root" "$work" <<'PY'
import json, pathlib, sys
root, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
lesson = json.loads((root / "assets/lessons/01-one-period.json").read_text())
title = lesson["title"]
option = next(o for s in lesson["steps"] if s.get("task", {}).get("options") for o in s["task"]["options"])
def edit(code, key, value):
    path = work / f"{code}.json"
    table = json.loads(path.read_text())
    table[key] = value
    path.write_text(json.dumps(table, ensure_ascii=False))
edit("de", title, "Eine Periode " * 615)
edit("es", option, "\u202e")
edit("fr", "Pause", "\u200b\u200e\u2066\ufeff")
edit("pt-BR", "Pause", "Pau\u007fsa")
edit("zh-CN", "Pause", "\u6682\u0085\u505c")
(work / "title").write_text(title)
PY
python3 "$root/scripts/i18n.py" check "$work" >"$work/out" 2>/dev/null
code=$?
[ $code -eq 1 ] || bad "hostile tables: exit $code, expected 1"
expect() { grep -qF -- "$1" "$work/out" || bad "expected a line with '$1', got: $(cat "$work/out")"; }
expect "de: a lesson title, at most 120 bytes as in English (it has 7995): '$(head -c 40 "$work/title")"
expect "es: shows nothing (only spaces or invisible characters such as U+202E)"
expect "fr: shows nothing (only spaces or invisible characters such as U+200B): 'Pause'"
expect "pt-BR: control character U+007F (only line breaks are allowed): 'Pause'"
expect "zh-CN: control character U+0085 (only line breaks are allowed): 'Pause'"
[ "$(wc -l <"$work/out")" -eq 5 ] || bad "five problems, one line each: $(cat "$work/out")"

# The language table and the folder agree (docs/i18n.md, "Adding a language"): a table without
# its row, and a row with a malformed field, each named.
cp "$root"/assets/i18n/*.json "$work/"
cp "$work/es.json" "$work/it.json"
python3 "$root/scripts/i18n.py" check "$work" >"$work/out" 2>/dev/null
code=$?
[ $code -eq 1 ] || bad "a table without its language: exit $code, expected 1"
expect "it.json: not a language of languages.json (add its row)"
rm "$work/it.json"
python3 - "$work" <<'PY'
import json, pathlib, sys
path = pathlib.Path(sys.argv[1]) / "languages.json"
rows = json.loads(path.read_text())
rows[2]["decimal_separator"] = ";"
path.write_text(json.dumps(rows, ensure_ascii=False))
PY
python3 "$root/scripts/i18n.py" check "$work" >"$work/out" 2>/dev/null
code=$?
[ $code -eq 1 ] || bad "a malformed languages.json: exit $code, expected 1"
expect 'languages.json: [2].decimal_separator: must be "." or ","'
[ $failed -eq 0 ] && echo "i18n check: hostile tables refused" 
exit $((failed > 0))
