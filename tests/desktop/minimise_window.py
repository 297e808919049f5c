#!/usr/bin/env python3
"""Minimises the desktop window and restores it, as a window manager does, and checks what the
app does meanwhile: no frame while minimised, the process asleep, and afterwards the frames and
the run going on from where they were.

The window is found by its process (xdotool search --pid), unmapped, and mapped again (Xvfb has
no window manager to iconify it; unmapping is what one does, and SDL reports it as
SDL_WINDOWEVENT_HIDDEN and _MINIMIZED). Each wait is on a state the app shows: its line on
stdout when it holds its frames and when they go on (app/ui/gl_context_life.h), the frame
number of its items file (swarmlab --items). While minimised one span of a few seconds is
watched in which nothing may happen: no frame written, and under 5 % of one core used (the
CPU time of all the process's threads, Mesa's renderers included), however loaded the machine.

Usage: minimise_window.py ITEMS_JSON APP_LOG PID FRAMES
Prints one line per check; exits 1 at the first failure.
"""
import json
import os
import re
import subprocess
import sys
import time

items_path, log_path = sys.argv[1], sys.argv[2]
pid, frames = int(sys.argv[3]), int(sys.argv[4])
WAIT_S = 120  # a loaded machine draws a frame in well under a second; this is for a stall
QUIET_S = 3.0  # how long the minimised window is watched
MOST_CPU = 0.05  # of one core, while minimised

HELD = r"the window is minimised: no frames until it shows again \(t = (\S+)\)"
GOES_ON = r"the window shows again: frames go on \(t = (\S+)\)"


def fail(message):
    print(f"FAIL  {message}")
    sys.exit(1)


def ok(message):
    print(f"ok    {message}")


def alive():
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def frame():
    """The number of the last frame the window wrote its items for (-1: none yet)."""
    try:
        with open(items_path) as f:
            return json.load(f)["frame"]
    except (OSError, ValueError, KeyError):
        return -1  # not written yet (the file is renamed into place whole)


def wait_for(what, get):
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        found = get()
        if found:
            return found
        if not alive():
            fail(f"the window closed while waiting for {what}")
        time.sleep(0.05)
    fail(f"waited {WAIT_S} s for {what}")


def cpu_seconds():
    """User and system CPU time of the whole process (every thread), in seconds."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def xdotool(*args):
    return subprocess.run(["xdotool", *args], check=True, capture_output=True, text=True).stdout


def said_nth(pattern, n):
    """The n-th (from 1) match of pattern in the window's log, or None."""
    try:
        with open(log_path) as f:
            found = re.findall(pattern, f.read())
    except OSError:
        return None
    return float(found[n - 1]) if len(found) >= n else None


def minimise_and_restore(n, window):
    """The n-th time: minimised, watched, restored; returns the run's time while held."""
    xdotool("windowunmap", "--sync", window)
    held_t = wait_for(f"the window's word that it holds its frames ({n})", lambda: said_nth(HELD, n))
    held = frame()
    if held >= frames:
        fail(f"the run reached its last frame ({held}) before the window was minimised")
    ok(f"minimised ({n}) at frame {held}: the window says it holds its frames (t = {held_t:.6g})")

    cpu_before, start = cpu_seconds(), time.monotonic()
    time.sleep(QUIET_S)
    used = (cpu_seconds() - cpu_before) / (time.monotonic() - start)
    still = frame()
    if still != held:
        fail(f"frames ran while minimised: frame {held} -> {still} in {QUIET_S} s")
    ok(f"no frame while minimised: frame {held} for {QUIET_S} s")
    if used >= MOST_CPU:
        fail(f"minimised, the window used {100 * used:.1f} % of a core (at most {100 * MOST_CPU:.0f} %)")
    ok(f"minimised, the window slept: {100 * used:.2f} % of a core")

    xdotool("windowmap", "--sync", window)
    on_t = wait_for(f"the window's word that its frames go on ({n})", lambda: said_nth(GOES_ON, n))
    if on_t != held_t:
        fail(f"restored, the run did not go on from where it was: t = {held_t:.9g} held, {on_t:.9g} after")
    ok(f"restored ({n}): the frames go on from t = {on_t:.6g}, where the run was held")
    wait_for("a frame after the restore", lambda: frame() > held)
    return held_t, held


wait_for("the window's first frames", lambda: frame() >= 10)
window = xdotool("search", "--sync", "--onlyvisible", "--pid", str(pid)).split()[0]
ok(f"the window runs (frame {frame()}), X window {window}")
# Twice: the run's time at the second minimising shows that it went on after the first.
first_t, first = minimise_and_restore(1, window)
second_t, second = minimise_and_restore(2, window)
if not second_t > first_t:
    fail(f"after the restore the run did not go on: t = {first_t:.6g}, then {second_t:.6g}")
ok(f"between the two, the run went on: t = {first_t:.6g} -> {second_t:.6g} (frame {first} -> {second})")
last = wait_for(f"the last frame ({frames})", lambda: frame() if frame() >= frames else None)
ok(f"restored, the frames went on to the last: frame {second} -> {last}")
