#!/usr/bin/env python3
"""Checks the audio that SDL's disk driver wrote for the desktop app (tests/desktop/sound_test.sh).

  check_sound.py clicks AUDIO.raw SUMMARY.txt   the file holds clicks, as the summary says
  check_sound.py silent AUDIO.raw SUMMARY.txt   the file holds silence only

AUDIO.raw is mono 32-bit float at 44.1 kHz (what the app asks SDL for). SUMMARY.txt is the app's
--frames output with its line "swarmlab: sound: C clicks played, D dropped, for H wall hits in S s".
A click is the Geiger counter's of app/ui/platform/wall_sound_sdl.cpp: 0.5 sin(2 pi 2500 t) exp(-t / 1.2 ms).
"""
import array
import math
import re
import sys

RATE = 44100
TONE = 2500.0  # Hz
PEAK = 0.5 * math.exp(-0.25 / TONE / 0.0012)  # the first crest, a quarter period in


def click_rate(hit_rate):
    """Clicks per second heard at a steady hit rate: every hit up to 20 per second, then
    20 (1 + ln(rate / 20) / 2), at most 60 (the rule stated in access/wall_clicks.h)."""
    if hit_rate <= 20:
        return hit_rate
    return min(20 * (1 + math.log(hit_rate / 20) / 2), 60)


def onsets(samples):
    """Sample indices where a click starts: above 5% of full scale after 2 ms of silence."""
    found, quiet = [], 10**9
    for i, x in enumerate(samples):
        if abs(x) > 0.05:
            if quiet >= 88:
                found.append(i)
            quiet = 0
        else:
            quiet += 1
    return found


def main():
    mode, audio, summary = sys.argv[1:4]
    with open(audio, 'rb') as f:
        samples = array.array('f')
        samples.frombytes(f.read())
    text = open(summary).read()
    m = re.search(r'sound: (\d+) clicks played, (\d+) dropped, for (\d+) wall hits in ([\d.]+) s', text)
    if not m:
        print(f'no sound summary in {summary}: {text!r}')
        return 1
    played, dropped, hits, seconds = int(m[1]), int(m[2]), int(m[3]), float(m[4])
    heard = onsets(samples)
    print(f'{len(samples) / RATE:.2f} s of audio, {len(heard)} clicks heard; the app: {played} played, '
          f'{dropped} dropped, {hits} wall hits in {seconds:.2f} s')
    if len(samples) < 0.5 * seconds * RATE:
        print(f'the audio lasts {len(samples) / RATE:.2f} s, less than half the {seconds:.2f} s the sound was on')
        return 1
    if mode == 'silent':
        loudest = max((abs(x) for x in samples), default=0.0)
        if hits != 0 or played != 0 or loudest > 1e-6:
            print(f'not silent: {hits} hits, {played} clicks, loudest sample {loudest:.3g}')
            return 1
        print('ok: silent, as a swarm with no wall makes no wall hits')
        return 0

    ok = True
    # Every click played reaches the output, but closing the device at exit drops what is still
    # queued: at most 0.15 s (the app's limit) and the last frame, at most 60 clicks a second.
    lost_at_exit = 25
    if not (played - lost_at_exit <= len(heard) <= played):
        print(f'{len(heard)} clicks heard of the {played} played (at most {lost_at_exit} may be cut off at exit)')
        ok = False
    # Each is the click's shape: its first crest and its tone (zero crossings over 1.5 ms).
    bad = []
    window = int(0.0015 * RATE)
    for start in heard:
        if start + window > len(samples):
            continue  # cut off by closing the device at exit, as the count above allows
        piece = samples[start:start + window]
        crest = max(abs(x) for x in piece)
        crossings = sum(1 for a, b in zip(piece, piece[1:]) if (a < 0) != (b < 0))
        tone = crossings / 2 / (len(piece) / RATE)
        if abs(crest / PEAK - 1) > 0.15 or abs(tone / TONE - 1) > 0.2:
            bad.append(f'at {start / RATE:.3f} s: crest {crest:.3f} (expected {PEAK:.3f}), tone {tone:.0f} Hz')
    if bad:
        print(f'{len(bad)} clicks not of the click shape, e.g. ' + '; '.join(bad[:3]))
        ok = False
    # The rate heard follows the wall's hit rate by the thinning rule. The rule smooths the hit
    # rate over half a second, from zero when sound starts, and keeps every hit while the
    # smoothed rate is low: about the first second may click at up to the cap (60 a second,
    # at least one a frame), so up to 60 clicks more than the steady rule.
    expected = click_rate(hits / seconds) * seconds
    made = played + dropped
    if not (0.6 * expected <= made <= expected + 60):
        print(f'{made} clicks for {hits} hits in {seconds:.2f} s; the thinning rule gives about {expected:.0f} '
              f'(+60 at the start)')
        ok = False
    if ok:
        print(f'ok: {len(heard)} clicks of the click shape for {hits} wall hits '
              f'({hits / seconds:.0f} per second heard as {len(heard) / seconds:.1f} clicks per second; rule: {click_rate(hits / seconds):.1f})')
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
