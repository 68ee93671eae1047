#!/bin/sh
# Runs a command on a virtual X display: the viewer tests open real windows and CI has no display.
if ! command -v xvfb-run >/dev/null 2>&1; then
  if [ "${PBR_ALLOW_NO_GL:-}" = 1 ]; then
    echo "xvfb-run not found (Debian package xvfb); not run, allowed by PBR_ALLOW_NO_GL=1"
    exit 0
  fi
  echo "xvfb-run not found: install the Debian package xvfb (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
# xvfb-run's default screen is 8 bits deep, which offers no RGBA8 visual for an OpenGL window.
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
