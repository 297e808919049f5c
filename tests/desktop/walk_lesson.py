#!/usr/bin/env python3
"""Walks lesson 1 in the desktop window as a person does, with the mouse and the keyboard.

What to press is found by role and name in the items the window mirrors (swarmlab --items, the
parallel DOM's items_json), and pressed with real X events (xdotool): a click at the middle of
the item, typed text and Enter. Each wait is on a state the app keeps (a step's heading, its
feedback), never on a frame count or a sleep. The right answers come from the physics, not
from the app: the period 2 pi / sqrt(J M) of the lesson's presets, computed here.

Usage: walk_lesson.py ITEMS_JSON LESSON_JSON PRESET_DIR
Prints one line per check; exits 1 at the first failure.
"""
import json
import math
import os
import subprocess
import sys
import time

items_path, lesson_path, preset_dir = sys.argv[1:4]
lesson = json.load(open(lesson_path))
WAIT_S = 120  # a loaded machine draws a frame in well under a second; this is for a stall


def fail(message):
    print(f"FAIL  {message}")
    sys.exit(1)


def ok(message):
    print(f"ok    {message}")


def snapshot():
    """(frame number, what the window shows, whether it then idles) of the last frame written:
    "items", "editing"..."""
    try:
        with open(items_path) as f:
            written = json.load(f)
        return written["frame"], written["dom"], written["still"]
    except (OSError, ValueError, KeyError):
        return -1, {"items": []}, False  # not written yet (the file is renamed into place whole)


def items():
    return snapshot()[1]["items"]


def wait_for(what, predicate):
    """The first result of predicate on a frame's items that holds, or FAIL naming what."""
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        found = predicate(items())
        if found:
            return found
        time.sleep(0.05)
    names = [(i["role"], i["name"][:50]) for i in items() if i["region"] == "Controls"]
    fail(f"waited {WAIT_S} s for {what}; the Controls panel holds {names[:40]}")


def stable(what, predicate):
    """As wait_for, for an item at the same place in two frames in a row, or in the frame after
    which the window idles (nothing moves until the next input): a panel that scrolls new
    feedback into view moves its buttons on the frame after (Playwright waits so too)."""
    deadline = time.monotonic() + WAIT_S
    last_frame, last = -1, None
    while time.monotonic() < deadline:
        frame, shows, still = snapshot()
        found = predicate(shows["items"])
        if found and still:
            return found
        if found and frame > last_frame:
            place = (found["x"], found["y"], found["width"], found["height"])
            if last is not None and frame == last_frame + 1 and place == last:
                return found
            last_frame, last = frame, place
        time.sleep(0.01)
    fail(f"waited {WAIT_S} s for {what} to hold still")


def shown(role, name, starts=False):
    """A predicate: the item of that role and name, in sight."""
    def find(all_items):
        for i in all_items:
            if i["role"] == role and not i.get("clipped") and not i.get("disabled") and (
                    i["name"].startswith(name) if starts else i["name"] == name):
                return i
        return None
    return find


def xdotool(*args):
    subprocess.run(["xdotool", *args], check=True)


window = subprocess.run(["xdotool", "search", "--sync", "--name", "^Swarm Lab"], check=True,
                        capture_output=True, text=True, timeout=WAIT_S).stdout.split()[0]
xdotool("windowfocus", "--sync", window)  # what a window manager does on the first click


def click(item):
    x = round(item["x"] + item["width"] / 2)
    y = round(item["y"] + item["height"] / 2)
    xdotool("mousemove", "--window", window, str(x), str(y), "click", "1")


def press(role, name, starts=False):
    click(stable(f'{role} "{name}"', shown(role, name, starts)))


def step_heading(n):
    return shown("paragraph", f"Step {n} of {len(lesson['steps'])}")


def next_step(n):
    """Next, and the lesson at step n."""
    press("button", "Next \u2192")
    wait_for(f"step {n} after a click on Next", step_heading(n))


def type_answer(text):
    """Clicks the answer field, replaces what it holds with text and presses Enter."""
    field = stable('textbox "Your answer"', shown("textbox", "Your answer"))
    click(field)
    wait_for("the answer field open for typing",
             lambda _: snapshot()[1].get("editing") == field["id"])
    xdotool("key", "ctrl+a")
    xdotool("type", "--delay", "20", text)
    xdotool("key", "Return")


def feedback_after(text_start):
    return shown("paragraph", text_start, starts=True)


def period_of(preset_name):
    preset = json.load(open(os.path.join(preset_dir, preset_name)))
    total_mass = sum(p["m"] for p in preset["particles"])
    return 2 * math.pi / math.sqrt(preset["J"] * total_mass)


steps = lesson["steps"]
wait_for("lesson 1's first step", step_heading(1))
ok(f'the window opens "{lesson["title"]}" at step 1 of {len(steps)}')

# Step 1: read, then Next (a click of the mouse).
next_step(2)
ok("a click on Next opens step 2")

# Step 2: the period of the two-body orbit, typed: first wrongly, then rightly.
period = period_of(steps[0]["preset"])
type_answer("1")
wait_for("feedback on a wrong period", lambda all_items: any(
    i["role"] == "paragraph" and i["name"].startswith("Not") for i in all_items))
ok("a wrong period, typed and entered, is marked wrong")
type_answer(f"{period:.4f}")
wait_for("feedback on the right period", lambda all_items: any(
    i["role"] == "paragraph" and i["name"].startswith("Right") for i in all_items))
ok(f"the period 2 pi / sqrt(J M) = {period:.4f}, typed and entered, is marked right")

# Step 3: a prediction, by a click on its button.
next_step(3)
press("button", "Predict C", starts=True)
wait_for("the prediction recorded", shown("paragraph", "Your prediction:"))
ok("a click on a prediction records it and shows the outcome")

# Step 4: the period of ball 4 in Fig. 1's four masses.
next_step(4)
period = period_of(steps[2]["preset"])
type_answer(f"{period:.4f}")
wait_for("feedback on ball 4's period", lambda all_items: any(
    i["role"] == "paragraph" and i["name"].startswith("Right") for i in all_items))
ok(f"ball 4's period {period:.4f} is marked right")

# Step 5: a choice, the right one as the lesson's physics says (force and inertia both ~ m).
next_step(5)
right = steps[4]["task"]["answer"]
press("button", f"Pick {chr(ord('A') + right)}", starts=True)
wait_for("feedback on the choice", shown("paragraph", "Right", starts=True))
ok("a click on the right choice is marked right")

# Steps 6 and 7 left unanswered, then Finish: the summary says so.
next_step(6)
next_step(7)
press("button", "Finish")
summary = wait_for("the summary", shown("heading", "Summary"))
finished = wait_for("the summary's count", shown("paragraph", "Finished:", starts=True))
tasks = sum(1 for s in steps if s.get("task"))
if not finished["name"].startswith(f"Finished: 4 of {tasks} tasks done"):
    fail(f'the summary counts "{finished["name"]}", expected 4 of {tasks}')
answers = [i["name"] for i in items() if i["role"] == "paragraph" and
           (i["name"].startswith("Your answer:") or i["name"] == "Not answered.")]
ok(f'Finish shows the summary: "{finished["name"]}"; answers {answers}')
if not any("right (after 2 tries)" in a for a in answers):
    fail(f"the summary does not show the period right after 2 tries: {answers}")
ok("the summary shows the period as right after 2 tries")

press("button", "Restart lesson")
wait_for("step 1 after Restart", step_heading(1))
ok("Restart lesson opens step 1 again")
print("PASS: lesson 1 walked to its summary in the desktop window by mouse and keyboard")
