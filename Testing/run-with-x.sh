#!/usr/bin/env bash
# Runs a command under its own Xvfb. xvfb-run -a picks a display by its lock file alone, which a
# server in another container does not leave in our /tmp; with -displayfd the server binds a free
# display itself. CI twice saw a client fail to connect ("bad X server connection") to a server that
# had reported ready, so a run whose client could not connect is retried once on a new server, with
# that server's log shown; any other failure is the command's own. With SHRINKWRAP_X_LOG set, the
# command's output (stdout and stderr) is also kept in that file.
set -uo pipefail
dir="$(mktemp -d)"
server=
stop_server() {
  [ -n "$server" ] && kill "$server" 2>/dev/null && wait "$server" 2>/dev/null
  server=
}
trap 'stop_server; rm -rf "$dir"' EXIT

start_server() {
  : >"$dir/display"
  Xvfb -displayfd 3 -nolisten tcp -noreset -screen 0 1280x1024x24 3>"$dir/display" 2>"$dir/log" &
  server=$!
  for _ in $(seq 300); do # the display number is written once the server accepts connections
    [ -s "$dir/display" ] && return 0
    kill -0 "$server" 2>/dev/null || break
    sleep 0.1
  done
  cat "$dir/log" >&2
  echo "run-with-x: Xvfb did not start" >&2
  return 1
}

for attempt in 1 2; do
  start_server || exit 1
  DISPLAY=":$(head -n1 "$dir/display")" "$@" 2>&1 | tee "$dir/output"
  status=${PIPESTATUS[0]}
  if [ "$status" -eq 0 ] || ! grep -qiE "bad X server connection|cannot open display" "$dir/output"; then
    [ -n "${SHRINKWRAP_X_LOG:-}" ] && cp "$dir/output" "$SHRINKWRAP_X_LOG"
    exit "$status"
  fi
  echo "run-with-x: attempt $attempt could not connect to Xvfb on :$(head -n1 "$dir/display"); its log:" >&2
  cat "$dir/log" >&2
  stop_server
done
exit "$status"
