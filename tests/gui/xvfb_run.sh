#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a command under a private Xvfb server and returns the command's exit code.
# The server picks a free display itself (-displayfd), so GUI tests running in parallel never
# race for a display number or share an authority file the way `xvfb-run -a` can.
#   DDFCAM_XVFB_SCREEN   screen geometry and depth (default 1280x800x24)
set -u
screen=${DDFCAM_XVFB_SCREEN:-1280x800x24}
out=$(mktemp) || exit 3
Xvfb -displayfd 1 -screen 0 "$screen" -nolisten tcp >"$out" 2>/dev/null &
server=$!
num=""
for _ in $(seq 1 400); do
  if [ "$(wc -l <"$out")" -ge 1 ]; then
    num=$(head -n 1 "$out")
    break
  fi
  if ! kill -0 "$server" 2>/dev/null; then
    break
  fi
  sleep 0.05
done
rm -f "$out"
if [ -z "$num" ]; then
  echo "xvfb_run.sh: Xvfb did not start (screen $screen)" >&2
  kill "$server" 2>/dev/null
  exit 3
fi
DISPLAY=":$num" "$@"
code=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit "$code"
