#!/usr/bin/env bash
# The desktop window starts with every flag its --help documents, alone and all at once (issue
# 39: `swarmlab --threads N` crashed on start, the flag read before the app existed). The flags
# are read from `swarmlab --help`: one that this test gives no value to fails it, so a new flag
# is tried as soon as it is documented.
#
# Usage: tests/desktop/flags_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb.
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
preset="$presets/hot-wall.json"
lesson="$(cd "$presets/../lessons" && pwd)/01-one-period.json"

start_xvfb 291 340 "$out/xvfb-flags.log"

# Each window flag with a value to try; --help and --version print and exit.
declare -A tried=(
  [--frames]="--frames 3"
  [--screenshot]="--screenshot $out/flags.png"
  [--select]="--select 2"
  [--plot-tab]="--plot-tab 6"
  [--presentation]="--presentation"
  [--sound]="--sound"
  [--lesson-summary]="--lesson-summary"
  [--lang]="--lang de"
  [--threads]="--threads 3"
  [--items]="--items $out/items.json"
)
# The documented flags: the Options section of --help, up to the subcommands.
documented=$("$binary" --help | sed -n '/^Options:/,/^Subcommands:/p' | grep -oE '^  -{1,2}[a-z][-a-z,]*' |
  sed 's/^ *//; s/.*,//' | grep -vE '^--(help|version)$')
[ -n "$documented" ] || fail "no flags read from swarmlab --help"

# start NAME ARG...: the window with a preset (the lesson for --lesson-summary; none when
# $bare is set), 3 frames.
start() {
  local name=$1
  shift
  local file=("$preset")
  [[ " $* " == *" --lesson-summary "* ]] && file=("$lesson")
  [ -n "${bare:-}" ] && file=()
  echo "running: swarmlab ${file[*]##*/} $* --frames 3"
  DISPLAY=":$display" SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE="$out/$name.raw" \
    timeout 300 "$binary" "${file[@]}" "$@" --frames 3 >"$out/$name.txt" 2>"$out/$name.err"
  local status=$?
  [ "$status" -eq 0 ] || fail "swarmlab $* exited with status $status: $(tail -3 "$out/$name.err")"
}

all=()
for flag in $documented; do
  [ -n "${tried[$flag]:-}" ] || fail "swarmlab --help documents $flag, which this test does not try"
  [ "$flag" = --frames ] && continue  # every start gives it
  # shellcheck disable=SC2206  # the values hold no spaces
  args=(${tried[$flag]})
  start "${flag#--}" "${args[@]}"
  [ "$flag" = --lesson-summary ] || all+=("${args[@]}")
done
bare=1 start threads-without-preset --threads 1
start all "${all[@]}"
[ -s "$out/flags.png" ] || fail "--screenshot wrote nothing"
[ -s "$out/items.json" ] || fail "--items wrote nothing"
echo "PASS: the window started with each of $(echo "$documented" | wc -w) documented flags and with all of them"
