#!/bin/sh
# Runs a command on a virtual X display: the viewer tests open real windows and CI has no display.
# Xvfb picks a free display itself and reports it once it accepts connections (-displayfd), so no display number
# is guessed and nothing waits on a fixed delay.
if ! command -v Xvfb >/dev/null 2>&1; then
  if [ "${PBR_ALLOW_NO_GL:-}" = 1 ]; then
    echo "Xvfb not found (Debian package xvfb); not run, allowed by PBR_ALLOW_NO_GL=1"
    exit 0
  fi
  echo "Xvfb not found: install the Debian package xvfb (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
fifo_dir=$(mktemp -d) || exit 1
fifo="$fifo_dir/display"
mkfifo "$fifo" || exit 1
# The default 8-bit screen offers no RGBA8 visual for an OpenGL window. -noreset: by default the server resets
# when its last client leaves, and a window opened by the next test case during that reset fails to connect.
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$fifo" 2>"$fifo_dir/xvfb.log" &
xvfb_pid=$!
read -r display <"$fifo"
if [ -z "$display" ]; then
  echo "Xvfb did not start: $(cat "$fifo_dir/xvfb.log")" >&2
  rm -rf "$fifo_dir"
  kill "$xvfb_pid" 2>/dev/null
  exit 1
fi
rm -rf "$fifo_dir"
DISPLAY=":$display" "$@"
status=$?
kill "$xvfb_pid" 2>/dev/null
wait "$xvfb_pid" 2>/dev/null
exit $status
