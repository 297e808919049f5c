#!/usr/bin/env python3
"""Checks the instruments' desktop screenshot (instruments_screenshot_test.sh): the Particle
plot tab draws the selected particle's x(t) curve, and its row of the particle table is
highlighted. Standard library only; reads the PNG with check_screenshot.py's decoder.

Usage: check_instruments.py SHOT.png
"""
import sys

from check_screenshot import count, read_png


def x_curve(r, g, b):
    """The x(t) line: the dark theme's particle_track (120, 230, 140)."""
    return abs(r - 120) <= 40 and abs(g - 230) <= 30 and abs(b - 140) <= 40


def amber(r, g, b):
    """The highlighted row: the dark theme's selected_row (120, 85, 20), app/access/theme_palette.cpp."""
    return r >= 110 and r - b >= 60 and 0.6 * r <= g <= 0.95 * r


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    width, height, rows = read_png(sys.argv[1])
    curve = count(rows, width - 390, width, 90, height - 100, x_curve)
    row = count(rows, 0, 340, 470, height, amber)
    checks = [
        ("window is 1280x720", width == 1280 and height == 720, f"{width}x{height}"),
        ("the Particle tab draws x(t)", curve > 300, f"{curve} pixels of its colour"),
        ("the selected particle's table row is highlighted", row > 400, f"{row} amber pixels"),
    ]
    ok = True
    for name, passed, detail in checks:
        print(f"  {'ok  ' if passed else 'FAIL'} {name} ({detail})")
        ok = ok and passed
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
