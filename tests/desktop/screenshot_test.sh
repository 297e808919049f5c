#!/usr/bin/env bash
# The desktop app as a person sees it: starts the real binary under Xvfb with a shipped preset,
# runs a fixed number of frames, saves the window as PNG and checks that the picture shows the
# particles, the container and the plots.
#
# Usage: tests/desktop/screenshot_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb and python3 (standard library).
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
preset="$presets/fig4-equilibration.json"
shot="$out/desktop-fig4.png"
frames=90

[ -f "$preset" ] || fail "no preset at $preset"

start_xvfb 90 140 "$out/xvfb.log"

echo "running: swarmlab $(basename "$preset") --frames $frames --screenshot $shot (DISPLAY=:$display)"
rm -f "$shot"
DISPLAY=":$display" timeout 300 "$binary" "$preset" --frames "$frames" --screenshot "$shot"
status=$?
[ "$status" -eq 0 ] || fail "swarmlab exited with status $status"
[ -s "$shot" ] || fail "no screenshot written at $shot"

python3 "$here/check_screenshot.py" "$shot" || fail "the screenshot is missing something ($shot)"

# Presentation mode (the projector): light theme, large text, the view and one plot.
shown="$out/desktop-fig4-presentation.png"
echo "running: swarmlab $(basename "$preset") --presentation --frames $frames --screenshot $shown"
rm -f "$shown"
DISPLAY=":$display" timeout 300 "$binary" "$preset" --presentation --frames "$frames" --screenshot "$shown"
status=$?
[ "$status" -eq 0 ] || fail "swarmlab --presentation exited with status $status"
[ -s "$shown" ] || fail "no screenshot written at $shown"
python3 "$here/check_screenshot.py" --presentation "$shown" ||
  fail "the presentation screenshot is missing something ($shown)"
# A lesson (its panel beside the view) and its summary, as after Finish.
lessons="$(cd "$presets/../lessons" && pwd)"
for page in step summary; do
  lesson_shot="$out/desktop-lesson-$page.png"
  extra=()
  [ "$page" = summary ] && extra=(--lesson-summary)
  echo "running: swarmlab 01-one-period.json ${extra[*]} --frames 30 --screenshot $lesson_shot"
  rm -f "$lesson_shot"
  DISPLAY=":$display" timeout 300 "$binary" "$lessons/01-one-period.json" "${extra[@]}" --frames 30 \
    --screenshot "$lesson_shot"
  status=$?
  [ "$status" -eq 0 ] || fail "swarmlab with a lesson ($page) exited with status $status"
  python3 "$here/check_screenshot.py" --lesson "$lesson_shot" ||
    fail "the lesson screenshot ($page) shows no lesson ($lesson_shot)"
done
echo "PASS: the screenshots show particles, the container and the plots ($shot), presentation mode ($shown), a lesson's step and its summary"
