#!/usr/bin/env bash
# The instruments as a person sees them on the desktop: the Fig. 1 four masses with particle 2
# selected (--select 2) under Xvfb, for long enough (450 frames of 1/60 s at the default
# speed: 5.2 time units, one and a half periods of 3.49) that the period meter has measured:
# the measured period printed at exit must be within 0.5% of 2 pi / sqrt(J M). Checks that the
# picture shows the Particle plot tab's x(t) curve and the highlighted table row.
#
# Usage: tests/desktop/instruments_screenshot_test.sh [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR]
# Prints PASS or FAIL; exits non-zero on failure. Needs Xvfb and python3.
set -uo pipefail

. "$(dirname "$0")/window_test_setup.sh" "$@"
preset="$presets/fig1-four-masses.json"
shot="$out/desktop-instruments.png"
frames=450

start_xvfb 141 190 "$out/xvfb-instruments.log"

# A particle that does not exist is refused before any frame, naming the flag and the range.
message=$(DISPLAY=":$display" timeout 120 "$binary" "$preset" --frames 2 --select 5 2>&1 >/dev/null)
[ $? -eq 1 ] || fail "--select 5 of 4 particles did not exit 1"
echo "$message" | grep -q -- "--select: must be in \[1, 4\]" || fail "unexpected message: $message"

rm -f "$shot"
log=$(DISPLAY=":$display" timeout 600 "$binary" "$preset" --select 2 --frames "$frames" --screenshot "$shot")
[ $? -eq 0 ] || fail "swarmlab exited with an error"
echo "$log"
# J = 1 and the masses 0.25 + 0.5 + 1 + 1.5 of the preset: 2 pi / sqrt(3.25).
measured=$(echo "$log" | sed -n 's/.*measured period \([0-9.e+-]*\).*/\1/p')
[ -n "$measured" ] || fail "no measured period printed"
python3 -c "import math, sys; f = 2 * math.pi / math.sqrt(3.25); m = float('$measured'); \
print(f'  measured {m}, formula {f:.6f}, difference {100 * (m - f) / f:+.4f}%'); \
sys.exit(0 if abs(m - f) / f < 0.005 else 1)" || fail "measured period $measured is not within 0.5% of 2 pi / sqrt(J M)"
[ -s "$shot" ] || fail "no screenshot written at $shot"

if python3 "$here/check_instruments.py" "$shot"; then
  echo "PASS: the screenshot shows the card, the table row and x(t) ($shot)"
else
  fail "the screenshot is missing something ($shot)"
fi
