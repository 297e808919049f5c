#!/usr/bin/env bash
# The desktop app's wall clicks through SDL audio: the real binary under Xvfb with SDL's "disk"
# audio driver, which writes what the device plays to a file in real time. A gas in a container
# with --sound must be heard as clicks of the app's click shape, as many as it says it played
# and, for its wall hits, as many as the thinning rule of access/wall_clicks.h gives; an
# isolated swarm (no wall) is silent; without --sound no audio device is opened at all.
#
# Usage: tests/desktop/sound_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb and python3 (standard library).
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
frames=150

start_xvfb 191 240 "$out/xvfb-sound.log"

# run NAME PRESET [FLAGS...]: the app for $frames frames, its audio in $out/NAME.raw and its
# summary in $out/NAME.txt.
run() {
  local name=$1 preset=$2
  shift 2
  rm -f "$out/$name.raw"
  echo "running: swarmlab $(basename "$preset") $* --frames $frames (SDL_AUDIODRIVER=disk)"
  DISPLAY=":$display" SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE="$out/$name.raw" \
    timeout 300 "$binary" "$preset" "$@" --frames "$frames" >"$out/$name.txt" 2>"$out/$name.err"
  local status=$?
  [ "$status" -eq 0 ] || fail "swarmlab $* exited with status $status: $(cat "$out/$name.err")"
}

run gas "$presets/hot-wall.json" --sound
python3 "$here/check_sound.py" clicks "$out/gas.raw" "$out/gas.txt" || fail "the gas at the wall was not heard right"

run isolated "$presets/fig1-four-masses.json" --sound
python3 "$here/check_sound.py" silent "$out/isolated.raw" "$out/isolated.txt" ||
  fail "a swarm with no wall was not silent"

run quiet "$presets/hot-wall.json"
[ ! -e "$out/quiet.raw" ] || fail "without --sound an audio device was opened ($out/quiet.raw exists)"
echo "ok: without --sound no audio device is opened"

echo PASS
