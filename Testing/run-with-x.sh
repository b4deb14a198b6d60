#!/usr/bin/env bash
# Runs a command under its own Xvfb. xvfb-run -a picks a display by its lock file alone, which a
# server in another container does not leave in our /tmp (CI once got "bad X server connection" on
# the display xvfb-run had picked). With -displayfd the server binds a free display itself.
set -euo pipefail
dir="$(mktemp -d)"
Xvfb -displayfd 3 -nolisten tcp -screen 0 1280x1024x24 3>"$dir/display" 2>"$dir/log" &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$dir"' EXIT
for _ in $(seq 300); do # the display number is written once the server accepts connections
  [ -s "$dir/display" ] && break
  kill -0 $server 2>/dev/null || { cat "$dir/log" >&2; echo "Xvfb failed to start" >&2; exit 1; }
  sleep 0.1
done
[ -s "$dir/display" ] || { echo "Xvfb did not start within 30 s" >&2; exit 1; }
DISPLAY=":$(head -n1 "$dir/display")" "$@"
