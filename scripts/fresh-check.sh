#!/usr/bin/env bash
# Checks that every command the README shows works on a fresh Debian machine on its own: for
# each entry point, a clean Debian root (debootstrap, bookworm as on this machine) gets a copy
# of the repository (its committed files only) and runs that one command as a new user would.
# A script that needs a package its own deps call does not install fails here.
# Run on demand (it downloads Debian and builds from nothing: about an hour on 2 cores), not in
# every CI run. Needs root, debootstrap (installed if missing) and the network to Debian.
#   scripts/fresh-check.sh [ENTRY...]   ENTRY: run test-quick web report fuzz bench (default: all)
# Prints a table of each entry point, its time and ok / FAILED; logs in build/fresh-check/.
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
)
order=(run test-quick web report fuzz bench)
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
