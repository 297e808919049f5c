# Sourced by the desktop window tests as `. window_test_setup.sh "$@"`: reads their arguments
# [SWARMLAB_BINARY] [PRESET_DIR] [OUT_DIR] into $binary, $presets and $out (defaults: the build's
# binary, the shipped presets, a new temporary folder), sets $here and $root, defines fail
# (prints FAIL and exits 1), checks the binary and Xvfb are there and makes $out.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
binary="${1:-$root/build/app/swarmlab}"
presets="${2:-$root/assets/presets}"
out="${3:-$(mktemp -d)}"

fail() {
  echo "FAIL: $*"
  exit 1
}

[ -x "$binary" ] || fail "no swarmlab binary at $binary"
command -v Xvfb >/dev/null || fail "Xvfb is not installed (apt-get install xvfb)"
mkdir -p "$out"

# start_xvfb FIRST LAST LOG starts Xvfb (1280x800) on the first free display in FIRST..LAST (no
# lock file and no socket), logging to LOG, stops it when the script exits, and sets $display.
# Each test takes its own range, so ctest may run them side by side.
start_xvfb() {
  local first=$1 last=$2 log=$3 n
  display=""
  for n in $(seq "$first" "$last"); do
    if [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "/tmp/.X11-unix/X$n" ]; then
      display=$n
      break
    fi
  done
  [ -n "$display" ] || fail "no free X display between :$first and :$last"
  Xvfb ":$display" -screen 0 1280x800x24 -nolisten tcp >"$log" 2>&1 &
  xvfb_pid=$!
  trap 'kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null' EXIT
  for _ in $(seq 1 50); do
    [ -e "/tmp/.X11-unix/X$display" ] && return 0
    kill -0 "$xvfb_pid" 2>/dev/null || fail "Xvfb did not start: $(cat "$log")"
    sleep 0.1
  done
}
