#!/usr/bin/env bash
# A minimised desktop window draws nothing, then goes on where it was (issue 26): the real
# binary under Xvfb runs a scripted number of frames with its items written after each
# (--frames, --items) while the window is minimised and restored by xdotool, as a window
# manager does it (the window unmapped and mapped again; SDL reports SDL_WINDOWEVENT_HIDDEN and
# _MINIMIZED, then _RESTORED and _SHOWN; Xvfb runs no window manager, so a request to iconify
# would go unanswered). The checks are minimise_window.py's; the last frame's screenshot must
# show the particles, the container and the plots (check_screenshot.py).
#
# Usage: tests/desktop/minimise_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb, xdotool and python3.
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
command -v xdotool >/dev/null || fail "xdotool is not installed (apt-get install xdotool)"
preset="$presets/fig4-equilibration.json"
[ -f "$preset" ] || fail "no preset at $preset"
# Enough frames that the window is minimised twice long before the last (at frames 10 and 15 or so).
frames=240
shot="$out/desktop-minimised-restored.png"
items="$out/minimise-items.json"
log="$out/minimise-app.log"

start_xvfb 241 290 "$out/xvfb-minimise.log"
rm -f "$shot" "$items"
DISPLAY=":$display" "$binary" "$preset" --frames "$frames" --screenshot "$shot" --items "$items" \
  >"$log" 2>&1 &
app=$!
trap 'kill "$app" 2>/dev/null; wait "$app" 2>/dev/null; kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null' EXIT

DISPLAY=":$display" timeout 600 python3 "$here/minimise_window.py" "$items" "$log" "$app" "$frames"
status=$?
[ "$status" -eq 0 ] || fail "minimised and restored: see above; the window's log: $(cat "$log")"
wait "$app"
app_status=$?
[ "$app_status" -eq 0 ] || fail "swarmlab exited with status $app_status: $(cat "$log")"
[ -s "$shot" ] || fail "no screenshot written at $shot"
python3 "$here/check_screenshot.py" "$shot" || fail "after the restore the window does not show the swarm ($shot)"
echo "PASS: minimised, the window ran no frame and slept; restored, it went on from where it was and its last frame shows the swarm ($shot)"
