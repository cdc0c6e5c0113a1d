#!/usr/bin/env bash
# README command 1: set up, build, and start RigMesh Studio with the example
# document. Without a display (a server, CI) it starts the studio under Xvfb,
# saves a screenshot of its window to build/dev/studio.png and exits.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh dev
build/dev/app/rigmesh example
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    exec build/dev/app/rigmesh-studio
fi
echo "No display: starting the studio under Xvfb and saving a screenshot to build/dev/studio.png"
xvfb-run -a -s "-screen 0 1400x900x24" build/dev/app/rigmesh-studio --screenshot build/dev/studio.png
echo "Saved build/dev/studio.png"
