#!/usr/bin/env bash
# A lesson in the desktop window as a person takes it: lesson 1 under Xvfb, walked to its
# summary with real mouse clicks and key presses (xdotool), finding what to press by role and
# name in the items the window mirrors (swarmlab --items: the parallel DOM, whose item hooks
# the desktop's ImGui is built with). The walk itself is walk_lesson.py.
#
# Usage: tests/desktop/lesson_walk_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb, xdotool and python3.
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
lessons="$(cd "$presets/../lessons" && pwd)"
lesson="$lessons/01-one-period.json"
command -v xdotool >/dev/null || fail "xdotool is not installed (apt-get install xdotool)"

start_xvfb 191 240 "$out/xvfb-lesson-walk.log"
items="$out/lesson-walk-items.json"
rm -f "$items"
# A home of its own: the student's progress starts empty and theirs is left alone.
rm -rf "$out/home" && mkdir -p "$out/home"
HOME="$out/home" XDG_CONFIG_HOME="$out/home/.config" DISPLAY=":$display" \
  "$binary" "$lesson" --items "$items" >"$out/lesson-walk-app.log" 2>&1 &
app=$!
trap 'kill "$app" 2>/dev/null; wait "$app" 2>/dev/null; kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null' EXIT

DISPLAY=":$display" timeout 900 python3 "$here/walk_lesson.py" "$items" "$lesson" "$presets"
status=$?
kill -0 "$app" 2>/dev/null || fail "the window closed during the walk: $(cat "$out/lesson-walk-app.log")"
[ "$status" -eq 0 ] || fail "the walk stopped (status $status); the window's log: $(cat "$out/lesson-walk-app.log")"
