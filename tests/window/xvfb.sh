#!/usr/bin/env bash
# Runs a command under a virtual display of its own. Xvfb picks a free display itself and tells us which
# (-displayfd), so tests that start side by side never race for one (xvfb-run -a looks for a free number and then
# starts: two starting together can pick the same, and one of them fails to open the display).
# Usage: xvfb.sh WIDTHxHEIGHT COMMAND [ARGS...]
set -euo pipefail
size="$1"
shift
dir="$(mktemp -d)"
pid=""
cleanup() {
    [[ -z "$pid" ]] || { kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; }
    rm -rf "$dir"
}
trap cleanup EXIT
mkfifo "$dir/display"
Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp -noreset 3>"$dir/display" >"$dir/xvfb.log" 2>&1 &
pid=$!
# Xvfb writes the number once it accepts connections; if it dies first, the pipe closes and read fails.
if ! read -r -t 60 number <"$dir/display"; then
    echo "xvfb.sh: Xvfb did not start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 1
fi
export DISPLAY=":$number"
status=0
"$@" || status=$?
exit "$status"
