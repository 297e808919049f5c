#!/usr/bin/env bash
# Regenerates every figure of docs/paper-reproduction.md and docs/student-projects.md into
# docs/figures/, one command per figure set, from the shipped presets (a few minutes in all;
# the Fig. 5 long run dominates).
# Then the ensembles behind the pages' error bars (scripts/ensembles.sh: 32 seeds per claim,
# each beside its dt / 2 check, hours more on this 2-core machine), unless --no-ensembles.
# Usage: scripts/report.sh [--png] [--no-ensembles]   (--png: a PNG beside each SVG; needs
# rsvg-convert)
# SWARMLAB=path/to/swarmlab picks the binary; by default build/app/swarmlab, built if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
ensembles=1
args=()
for arg in "$@"; do
  if [ "$arg" = --no-ensembles ]; then ensembles=0; else args+=("$arg"); fi
done
set -- ${args[@]+"${args[@]}"}
bin=${SWARMLAB:-build/app/swarmlab}
[ -x "$bin" ] || scripts/build.sh --target swarmlab
figures=docs/figures
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

run() {
  local preset=$1
  shift
  echo "== $preset" >&2
  "$bin" run "assets/presets/$preset.json" --plots "$figures/$preset" --quiet "$@"
}

run fig1-four-masses "$@"                # Section II: closed ellipses, one common period
run methods-vs-analytic "$@"             # Section III: Euler drifts, Euler-Cromer stays bounded
run fig2-attractive-expansion "$@"       # Fig. 2 and Appendix C, attractive
run fig3-repulsive-fireball "$@"         # Fig. 3 and Appendix C, repulsive
run fig4-equilibration-10pi "$@"         # Fig. 4: P and T at every step, normalised
run fig5-short-equilibration --out "$results/short.json" "$@"
run fig5-long-equilibration --out "$results/long.json" "$@"
echo "== fig5-overlay" >&2                # Fig. 5: long (solid) and short (dashed) overlaid
"$bin" report "$results/long.json" "$results/short.json" --plots "$figures/fig5-overlay" --quiet "$@"

# docs/student-projects.md (the paper's Appendix B): gravity, a floor, drag
run gravity-floor-bounce "$@"            # an attractive swarm bouncing on a floor under gravity
run drag-damped-swarm "$@"               # mass-proportional drag: damped oscillators about the CM
run drag-one-particle "$@"               # drag on one particle: v0 exp(-b t / m)
# Appendix B walls and contacts (docs/student-projects.md)
run moving-wall-cycle "$@"               # P-V loop of a compress-expand cycle, energy books
run hot-wall "$@"                        # a cold gas warmed by a wall at Tw
run hard-spheres-gas "$@"                # hard spheres: energy, P and T

[ $ensembles -eq 0 ] || SWARMLAB="$bin" scripts/ensembles.sh
