#!/usr/bin/env bash
# The paper's claims with error bars: 32 independent seeds of each preset behind a claim in
# docs/paper-reproduction.md or a finding in docs/student-projects.md, merged into means with
# 95 % intervals, each beside its dt systematic (--dt-check: the same seeds again at dt / 2), and
# the ensembles' band figures into docs/figures/ensembles/. Every report is made by one build,
# which it names (provenance.swarmlab); a folder of another build's runs is started again.
# Measured on a 2-core machine with the rest of it busy (2026-12-08, build e084a9b575e0): the
# first seven presets 26 minutes, the Fig. 4 runs of 40,000 particles 18 more; a killed run
# resumes. Fig. 5 long at 32 seeds with its dt / 2 pair is 1.02e13 particle-steps, past what
# `swarmlab ensemble` takes on one machine (8e12 with 2 jobs): it stops there, naming
# `swarmlab plan`, which has no dt / 2 check yet; its report in docs/ is an older build's.
# Usage: scripts/ensembles.sh [--seeds N] [--no-dt-check] [PRESET...]
#   (default: 32 seeds, every preset below)
# The ensembles stay in build/ensembles/PRESET (report.json, runs.csv, runs/); the reports are
# copied to docs/ensembles/PRESET.json, which the page quotes.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${SWARMLAB:-build/app/swarmlab}
[ -x "$bin" ] || scripts/build.sh >/dev/null
seeds=32
dt_check=(--dt-check)
presets=()
while [ $# -gt 0 ]; do
  case $1 in
    --seeds) seeds=$2; shift ;;
    --no-dt-check) dt_check=() ;;
    *) presets+=("$1") ;;
  esac
  shift
done
[ ${#presets[@]} -gt 0 ] || presets=(hot-wall hard-spheres-gas moving-wall-cycle fig4-equilibration
  fig2-attractive-expansion fig3-repulsive-fireball fig5-short-equilibration
  fig4-equilibration-10pi fig5-long-equilibration)
mkdir -p docs/ensembles
for preset in "${presets[@]}"; do
  echo "== $preset: $seeds seeds" >&2
  start=$(date +%s)
  # Runs of another build do not merge with this one's: start that folder again.
  dir="build/ensembles/$preset"
  if [ -f "$dir/plan.json" ] && ! grep -qF "\"swarmlab\": \"$("$bin" --version)\"" "$dir/plan.json"; then
    echo "   $dir holds runs of another build: starting it again" >&2
    rm -rf "$dir"
  fi
  "$bin" ensemble "assets/presets/$preset.json" --seeds "$seeds" --out "build/ensembles/$preset" --quiet \
    ${dt_check[@]+"${dt_check[@]}"}
  "$bin" report "build/ensembles/$preset/report.json" --plots "docs/figures/ensembles/$preset" --quiet
  cp "build/ensembles/$preset/report.json" "docs/ensembles/$preset.json"
  echo "   $(( $(date +%s) - start )) s" >&2
done
