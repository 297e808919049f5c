#!/usr/bin/env bash
# Ensembles on this machine (bench/RESULTS.md, "Ensembles"), all in one run so that the
# ratios share the machine's state:
#  1. 64 seeds of a preset of about 2 s (bench/ensemble-member.json) by swarmlab ensemble on
#     every core, against 64 x (one run's time on one thread) / cores; goal: within 1.15x.
#  2. swarmlab merge of 1,000 runs of 10,000 samples each (bench/ensemble-merge-member.json):
#     its time (goal: under 10 s) and peak memory, beside the same merge of 1,000 runs of
#     1,000 samples each (its memory should not grow with the samples).
# Usage: bench/ensemble_bench.sh   (SWARMLAB=path picks the binary; about 3 minutes here)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${SWARMLAB:-build/app/swarmlab}
[ -x "$bin" ] || scripts/build.sh >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cores=$(nproc)
now() { date +%s.%N; }
seconds() { python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.3f}')" "$1" "$2"; }

# 1. One run on one thread, three times (the median), then the ensemble.
times=()
for _ in 1 2 3; do
  t0=$(now)
  "$bin" run bench/ensemble-member.json --quiet --threads 1
  times+=("$(seconds "$t0" "$(now)")")
done
one=$(printf '%s\n' "${times[@]}" | sort -n | sed -n 2p)
t0=$(now)
"$bin" ensemble bench/ensemble-member.json --seeds 64 --out "$work/scaling" --quiet
ensemble=$(seconds "$t0" "$(now)")
ideal=$(python3 -c "print(f'{64 * $one / $cores:.2f}')")
ratio=$(python3 -c "print(f'{$ensemble / (64 * $one / $cores):.3f}')")

# 2. The merge, with 10,000 and with 1,000 samples a run.
"$bin" ensemble bench/ensemble-merge-member.json --seeds 1000 --out "$work/merge10k" --quiet
sed 's/"sample_every": 1}/"sample_every": 10}/; s/10,000 samples/1,000 samples/' \
  bench/ensemble-merge-member.json >"$work/member1k.json"
"$bin" ensemble "$work/member1k.json" --seeds 1000 --out "$work/merge1k" --quiet
measure_merge() {  # DIR -> "seconds peak_kB"
  /usr/bin/time -f '%e %M' -o "$work/time" "$bin" merge "$1" --quiet
  cat "$work/time"
}
read -r merge10k_s merge10k_kb <<<"$(measure_merge "$work/merge10k")"
read -r merge1k_s merge1k_kb <<<"$(measure_merge "$work/merge1k")"
record=$(du -k "$work/merge10k/runs/0.json" | cut -f1)

echo "== swarmlab ensembles, $(date -u +%Y-%m-%d), $cores cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| measurement | value | goal |"
echo "|---|---|---|"
echo "| one run, one thread (median of 3: ${times[*]} s) | $one s | |"
echo "| 64 seeds, swarmlab ensemble on $cores cores | $ensemble s (ideal $ideal s) | |"
echo "| ensemble / (64 x one run / cores) | $ratio | <= 1.15 |"
echo "| merge, 1,000 runs x 10,000 samples | $merge10k_s s, peak $((merge10k_kb / 1024)) MB | < 10 s |"
echo "| merge, 1,000 runs x 1,000 samples | $merge1k_s s, peak $((merge1k_kb / 1024)) MB | same memory |"
echo "| one run's record | $record kB | |"
