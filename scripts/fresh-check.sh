#!/usr/bin/env bash
# Checks that every command the README and the pages of docs/ show works on a fresh Debian
# machine on its own: for each entry point, a clean Debian root (debootstrap, bookworm as on
# this machine) gets a copy of the repository (its committed files only) and runs that one
# command as a new user would. A script that needs a package its own deps call does not
# install fails here.
# Run on demand (it downloads Debian and builds from nothing: about an hour on 2 cores), not in
# every CI run. Needs root, debootstrap (installed if missing) and the network to Debian.
#   scripts/fresh-check.sh [ENTRY...]   ENTRY: run test-quick web report fuzz bench cli parallel
#                                       (default: all)
# Prints a table of each entry point, its time and ok / FAILED; logs in build/fresh-check/.
#   scripts/fresh-check.sh --list [PAGE...]
# The quick mode (a second, no root, no network; ctest fresh_check_list): every command line in
# the code blocks of README.md, CONTRIBUTING.md and docs/*.md (or the PAGEs) with the entry
# point that runs it, or the reason none does; exit 1 if a command is in neither, so that a
# command added to a page gets an entry point or a stated reason.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/build/fresh-check"
base="$out/base-root"
mirror=${MIRROR:-http://deb.debian.org/debian}

declare -A commands=(
  [run]="scripts/run.sh"
  [test-quick]="scripts/test.sh --quick"
  [web]="scripts/web.sh --build-only"
  [report]="scripts/report.sh --no-ensembles"
  [fuzz]="scripts/fuzz.sh 10"
  [bench]="scripts/build.sh && build/app/swarmlab bench headline"
  [cli]="scripts/build.sh && build/app/swarmlab --help && build/app/swarmlab run --help && build/app/swarmlab ensemble assets/presets/hot-wall.json --seeds 32 --out ens/hot-wall && build/app/swarmlab merge ens/hot-wall && build/app/swarmlab check-lesson assets/lessons/*.json && build/app/swarmlab run assets/presets/gravity-floor-bounce.json --plots out"
  [parallel]="scripts/build.sh && build/app/swarmlab plan assets/presets/hot-wall.json --seeds 64 --out /shared/ens && parallel --joblog /shared/ens/joblog --resume-failed -S : < /shared/ens/manifest.txt && build/app/swarmlab merge /shared/ens && build/app/swarmlab plan assets/presets/hot-wall.json --seeds 64 --out /shared/ens --slurm --at-once 16"
)
order=(run test-quick web report fuzz bench cli parallel)

# The command lines the pages show that no entry point runs, each with the reason (an
# extended regular expression over the line as --list normalises it, then the reason).
not_run=(
  '^scripts/test\.sh$'
  'the whole suite: CI runs it on a clean clone (.ci/run); the test-quick entry installs its packages from nothing'
  '^git clone \. /tmp/ci-copy && cd /tmp/ci-copy && scripts/test\.sh$'
  'the whole suite in a clone, as CI runs it (.ci/run)'
  '^scripts/web\.sh( --lan| --no-build| --port 9000)?$'
  "serves until Ctrl-C: the web entry builds what it serves, and tests/web/serve_load_test.mjs (ctest web_serve_load) loads the page from scripts/web.sh --no-build's server in 30 clients"
  '^scripts/report\.sh( --png)?$'
  'the figures and then the 32-seed ensembles, hours on 2 cores: the report entry makes the same figures with --no-ensembles'
  '^build/app/swarmlab (run assets/presets/fig5-(short|long)-equilibration\.json --out (short|long)\.json|report long\.json short\.json --plots docs/figures/fig5-overlay)$'
  'what scripts/report.sh runs (the report entry), there with its own file names'
  '^build/app/swarmlab validate my-lesson\.json$'
  "a lesson of the reader's own: the cli entry checks every shipped lesson"
  '(^| )([A-Z]+\.json|DIR|N)( |$)|\[--'
  'a synopsis with placeholders, not a command: the cli entry runs --help, which prints the same'
  '^parallel .* -S 4/node1,4/node2,: '
  'needs ssh to two more hosts sharing /shared/ens: tests/cli/ensemble_test.sh (ctest cli_ensemble) runs the plan on two stand-in hosts'
  '^sbatch '
  'needs a Slurm cluster: tests/cli/ensemble_test.sh runs array.sbatch with SLURM_ARRAY_TASK_ID set'
)

# A page's command lines: the lines of its code blocks (fenced, or indented four spaces after
# a blank line) that start with a command this project documents, comment cut off, spaces
# squeezed, and swarmlab called as the build leaves it (build/app/swarmlab).
command_lines() {
  awk '
    /^ *```/ { fenced = !fenced; next }
    fenced { print; next }
    /^    / && (blank || indented) { indented = 1; print; blank = 0; next }
    /^[ \t]*$/ { blank = 1; next }
    { indented = 0; blank = 0 }
  ' "$1" | sed -E 's/[[:space:]]+#.*$//; s/^[[:space:]]+//; s/[[:space:]]+$//; s/[[:space:]]+/ /g; s#^swarmlab( |$)#build/app/swarmlab\1#' |
    grep -E '^(scripts/[a-z-]+\.sh|build/app/swarmlab|build/bench/|bench/[a-z_]+\.sh|tests/[a-z_/]+\.(sh|mjs|py)|node |NODE_PATH=|parallel |sbatch |cmake |git |cd )' || true
}

if [ "${1:-}" = --list ]; then
  shift
  cd "$root"
  pages=("$@")
  [ ${#pages[@]} -gt 0 ] || pages=(README.md CONTRIBUTING.md docs/*.md)
  missing=0
  for page in "${pages[@]}"; do
    while IFS= read -r line; do
      how=""
      for entry in "${order[@]}"; do
        IFS=$'\n' read -r -d '' -a parts < <(printf '%s' "${commands[$entry]}" | sed 's/ && /\n/g'; printf '\0')
        for part in "${parts[@]}"; do [ "$part" = "$line" ] && how="run by entry $entry" && break 2; done
      done
      if [ -z "$how" ]; then
        for ((i = 0; i < ${#not_run[@]}; i += 2)); do
          if [[ $line =~ ${not_run[i]} ]]; then how="not run: ${not_run[i + 1]}"; break; fi
        done
      fi
      if [ -z "$how" ]; then how="NOT COVERED: add it to an entry point or to not_run"; missing=1; fi
      printf '%s: %s\n    %s\n' "$page" "$line" "$how"
    done < <(command_lines "$page")
  done
  exit $missing
fi

[ $# -gt 0 ] && order=("$@")
for entry in "${order[@]}"; do
  [ -n "${commands[$entry]:-}" ] || { echo "fresh-check: no entry point $entry (${!commands[*]})" >&2; exit 2; }
done
[ "$(id -u)" -eq 0 ] || { echo "fresh-check: needs root (debootstrap, chroot)" >&2; exit 1; }
command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >&2

mkdir -p "$out"
# The base root, made once: a minimal Debian with sudo-less root, ca-certificates and git, as
# a fresh machine or container has.
if [ ! -f "$base/.complete" ]; then
  rm -rf "$base"
  echo "[fresh-check] debootstrap bookworm into ${base#"$root"/} (a few minutes)" >&2
  debootstrap --variant=minbase --include=ca-certificates,git bookworm "$base" "$mirror" \
    >"$out/debootstrap.log" 2>&1 || { tail -20 "$out/debootstrap.log" >&2; exit 1; }
  # The same sources as this machine, deb-src off, as Debian ships them.
  cp /etc/apt/sources.list.d/debian.sources "$base/etc/apt/sources.list.d/"
  rm -f "$base/etc/apt/sources.list"
  touch "$base/.complete"
fi

results=()
failed=0
for entry in "${order[@]}"; do
  chroot_dir="$out/root-$entry"
  log="$out/$entry.log"
  rm -rf "$chroot_dir"
  cp -a "$base" "$chroot_dir"
  # Committed files only, as a clone has them.
  git -C "$root" archive --format=tar HEAD | tar -x -C "$chroot_dir/root" --one-top-level=swarmlab
  # The network trust of a machine of this kind: its extra CA certificates (an egress proxy's)
  # and npm's CA file setting, which a fresh machine here has before any script runs.
  if ls /usr/local/share/ca-certificates/*.crt >/dev/null 2>&1; then
    cp /usr/local/share/ca-certificates/*.crt "$chroot_dir/usr/local/share/ca-certificates/"
    chroot "$chroot_dir" update-ca-certificates >/dev/null 2>&1
  fi
  for npmrc in /etc/npmrc /usr/etc/npmrc; do
    [ -f "$npmrc" ] && mkdir -p "$chroot_dir$(dirname "$npmrc")" && cp "$npmrc" "$chroot_dir$npmrc"
  done
  mount -t proc proc "$chroot_dir/proc"
  mount --rbind /dev "$chroot_dir/dev"
  cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf"
  echo "[fresh-check] $entry: ${commands[$entry]}" >&2
  t0=$(date +%s)
  if chroot "$chroot_dir" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
       TERM=dumb NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt bash -c "cd /root/swarmlab && ${commands[$entry]}" >"$log" 2>&1; then
    result=ok
  else
    result="FAILED (last lines in ${log#"$root"/})"
    failed=1
  fi
  umount -R "$chroot_dir/dev" 2>/dev/null || umount -l "$chroot_dir/dev"
  umount "$chroot_dir/proc" 2>/dev/null || umount -l "$chroot_dir/proc"
  results+=("$(printf '%-12s %-52s %6ss  %s' "$entry" "${commands[$entry]}" "$(( $(date +%s) - t0 ))" "$result")")
  [ "$result" = ok ] && rm -rf "$chroot_dir"  # a failed root stays, to look into
  [ "$result" = ok ] || tail -5 "$log" >&2
done
echo
echo "== fresh check ($(date -u +%Y-%m-%d), Debian bookworm from $mirror)"
printf '%s\n' "${results[@]}"
exit $failed
