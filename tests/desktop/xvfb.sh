# Sourced by the desktop screenshot tests: start_xvfb FIRST LAST LOG starts Xvfb (1280x800) on
# the first free display in FIRST..LAST (no lock file and no socket), logging to LOG, stops it
# when the script exits, and sets $display. Each test takes its own range, so ctest may run
# them side by side. Needs fail() from the caller.
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
