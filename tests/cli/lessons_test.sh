#!/usr/bin/env bash
# swarmlab validate LESSON.json: a lesson (a file with a "lesson" key) is checked as a lesson,
# with one field-named message and a non-zero exit when it breaks a rule.
# Usage: lessons_test.sh SWARMLAB LESSON_DIR
source "$(dirname "$0")/harness.sh"
lessons=$presets
preset_dir="$(dirname "$lessons")/presets"

# Every shipped lesson whose presets are shipped validates. A lesson may name a preset another
# part of the project ships; until it exists the lesson is reported, not failed.
for l in "$lessons"/*.json; do
  missing=""
  for name in $(grep -o '"preset": *"[^"]*"' "$l" | sed 's/.*"\([^"]*\)"$/\1/'); do
    [ -f "$preset_dir/$name" ] || missing="$missing $name"
  done
  if [ -n "$missing" ]; then
    echo "skipped $(basename "$l"): needs the presets$missing"
    continue
  fi
  "$bin" validate "$l" >"$work/stdout" 2>"$work/stderr" && grep -q "valid lesson" "$work/stdout" && ok ||
    bad "validate $l: $(cat "$work/stderr")"
done

# expect_lesson_error NAME TEXT MESSAGE: one line on stderr with MESSAGE, exit 1.
expect_lesson_error() {
  local name=$1 text=$2 message=$3
  printf '%s' "$text" >"$work/$name.json"
  "$bin" validate "$work/$name.json" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  if [ $code -ne 1 ]; then bad "$name: exit $code, expected 1"; return; fi
  if ! grep -qF -- "error: $work/$name.json: $message" "$work/stderr"; then
    bad "$name: expected '$message', got: $(cat "$work/stderr")"
    return
  fi
  [ "$(wc -l <"$work/stderr")" -eq 1 ] && [ ! -s "$work/stdout" ] && ok || bad "$name: more than one line, or output"
}

step='{"text": "Watch.", "preset": "two-body-circular.json"}'
head='"lesson": 1, "id": "t", "title": "T", "summary": "S"'
expect_lesson_error version '{"lesson": 2}' 'lesson: must be 1 (the only lesson version so far)'
expect_lesson_error no-steps "{$head}" 'steps: missing (a list of 1 to 100 steps)'
expect_lesson_error bad-preset-name "{$head, \"steps\": [{\"text\": \"a\", \"preset\": \"nope.json\"}]}" \
  'steps[0].preset: no shipped preset "nope.json"'
expect_lesson_error preset-path "{$head, \"steps\": [{\"text\": \"a\", \"preset\": \"../presets/two-body-circular.json\"}]}" \
  'steps[0].preset: "../presets/two-body-circular.json" is not a shipped preset'
expect_lesson_error inline-preset "{$head, \"steps\": [{\"text\": \"a\", \"preset\": {\"J\": 1, \"particles\": [], \"dt\": 0.1}}]}" \
  'steps[0].preset.particles: must hold at least one particle'
expect_lesson_error tolerance "{$head, \"steps\": [$step, {\"text\": \"b\", \"task\": {\"kind\": \"measure\", \"prompt\": \"p\", \"quantity\": \"period\", \"tolerance\": 0}}]}" \
  'steps[1].task.tolerance: must be > 0'
expect_lesson_error answer "{$head, \"steps\": [$step, {\"text\": \"b\", \"task\": {\"kind\": \"choice\", \"prompt\": \"p\", \"options\": [\"x\", \"y\"], \"answer\": 2}}]}" \
  'steps[1].task.answer: must be an index into options (0 to 1)'
expect_lesson_error twice "{$head, \"id\": \"u\", \"steps\": [$step]}" 'id: given twice (each key at most once)'
expect_lesson_error trailing "{$head, \"steps\": [$step]} x" 'lesson: not valid JSON'
expect_lesson_error cut-short $'{"lesson": 1,\n  "id": ' 'lesson: not valid JSON at line 2, column 9: '
# A translation is held to the rules of the field it translates: a title to a title's length,
# something to see, no control character (DEL and C1 as C0).
long=$(head -c 8000 /dev/zero | tr '\0' x)
expect_lesson_error long-title "{$head, \"steps\": [$step], \"translations\": {\"de\": {\"T\": \"$long\"}}}" \
  'translations.de."T" (title): must be at most 120 bytes long, as the English is (it has 8000)'
expect_lesson_error blank-translation "{$head, \"steps\": [$step], \"translations\": {\"es\": {\"Watch.\": \"\\u202e\"}}}" \
  'translations.es."Watch." (steps[0].text): must show something (it holds only spaces or invisible characters such as U+202E)'
expect_lesson_error c1-translation "{$head, \"steps\": [$step], \"translations\": {\"fr\": {\"S\": \"R\\u009bsum\"}}}" \
  'translations.fr."S" (summary): control character U+009B (only line breaks are allowed)'
expect_lesson_error del-title "{\"lesson\": 1, \"id\": \"t\", \"title\": \"T\\u007f\", \"summary\": \"S\", \"steps\": [$step]}" \
  'title: control character U+007F (only line breaks are allowed)'

# A good inline lesson validates and says what it is.
printf '%s' "{$head, \"steps\": [$step]}" >"$work/good.json"
"$bin" validate "$work/good.json" >"$work/stdout" 2>&1 && grep -qF 'valid lesson "t" (1 step)' "$work/stdout" && ok ||
  bad "good lesson: $(cat "$work/stdout")"
# A preset is still validated as a preset.
"$bin" validate "$preset_dir/two-body-circular.json" >"$work/stdout" 2>&1 && grep -q "valid (analytic" "$work/stdout" && ok ||
  bad "preset: $(cat "$work/stdout")"

finish
