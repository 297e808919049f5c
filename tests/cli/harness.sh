# Shared by the CLI tests: sourced with SWARMLAB and PRESET_DIR as $1 and $2. Sets bin, presets,
# a scratch folder $work (removed on exit), ok/bad to count results, and finish to report them.
set -u
bin=$1
presets=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*"; }

# The summary line, and the exit status: non-zero when any check failed.
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
