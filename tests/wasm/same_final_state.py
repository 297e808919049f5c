#!/usr/bin/env python3
"""Runs presets with the native swarmlab and with the WebAssembly build under node and checks
that both reach the same final state to 1e-12 relative (per quantity, relative to its RMS
size over the particles), and the same wall-hit count.

Usage: same_final_state.py NATIVE_SWARMLAB WASM_SWARMLAB_JS PRESET..."""
import json
import math
import subprocess
import sys
import tempfile

TOLERANCE = 1e-12


def run(command, preset, out):
    subprocess.run(command + ["run", preset, "--out", out, "--quiet"], check=True)
    with open(out) as f:
        return json.load(f)


def main():
    native, wasm, presets = sys.argv[1], sys.argv[2], sys.argv[3:]
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for preset in presets:
            a = run([native], preset, f"{tmp}/native.json")
            b = run(["node", "--no-experimental-fetch", wasm], preset, f"{tmp}/wasm.json")
            pa, pb = a["final"]["particles"], b["final"]["particles"]
            worst = 0.0
            for key in ("r", "v"):
                scale = math.sqrt(sum(sum(x * x for x in p[key]) for p in pa) / len(pa)) or 1.0
                for p, q in zip(pa, pb):
                    for x, y in zip(p[key], q[key]):
                        worst = max(worst, abs(x - y) / scale)
            same_hits = a["summary"]["wall_hits"] == b["summary"]["wall_hits"]
            ok = len(pa) == len(pb) and worst <= TOLERANCE and same_hits
            print(f"{'ok  ' if ok else 'FAIL'} {preset}: {len(pa)} particles, "
                  f"{a['summary']['steps']} steps, wall hits {a['summary']['wall_hits']} / "
                  f"{b['summary']['wall_hits']}, largest relative difference {worst:.2e}")
            passed += ok
            failed += not ok
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
