#!/usr/bin/env python3
"""Runs presets with the native swarmlab and with the WebAssembly build under node and checks
that both write the same result to the last bit: the core computes its elementary functions
itself (core/src/math/portable_math.h), so no difference between glibc's and musl's libm reaches a
run. On a mismatch it reports the largest difference in the final state (per quantity,
relative to its RMS size over the particles) and the wall-hit counts.

Usage: same_final_state.py NATIVE_SWARMLAB WASM_SWARMLAB_JS PRESET..."""
import json
import math
import subprocess
import sys
import tempfile

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
            # The whole result, not only the final state: samples, stages and fits too; apart
            # from what made each (docs/command-line.md, "Provenance"): the wasm's names Emscripten and node.
            made = a.pop("provenance"), b.pop("provenance")
            ok = a == b and made[1]["compiler"].startswith("Emscripten") and made[1]["host"]["os"] == "node"
            print(f"{'ok  ' if ok else 'FAIL'} {preset}: {len(pa)} particles, "
                  f"{a['summary']['steps']} steps, wall hits {a['summary']['wall_hits']} / "
                  f"{b['summary']['wall_hits']}, {'identical results' if ok else 'DIFFERENT results'}, "
                  f"largest relative difference in the final state {worst:.2e}")
            passed += ok
            failed += not ok
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
