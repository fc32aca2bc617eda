#!/usr/bin/env bash
# The viewer headless under a virtual X server with Mesa's software renderer:
#   run_headless.sh VIEWER SCENE OUT_PREFIX FRAMES [--set KEY=VALUE ...]
# writes OUT_PREFIX.png (the last frame) and OUT_PREFIX.json (the figures).
set -euo pipefail
viewer=$1 scene=$2 out=$3 frames=$4
shift 4
if ! command -v xvfb-run >/dev/null; then
  echo "xvfb-run not found: the headless viewer test needs it (Debian package xvfb)" >&2
  exit 1
fi
rm -f "$out.png" "$out.json"
LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x800x24" \
  "$viewer" "$scene" --screenshot "$out.png" --frames "$frames" --json "$@" > "$out.json"
cat "$out.json"
