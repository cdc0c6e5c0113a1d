#!/usr/bin/env bash
# README command 1: set up, build, and run RigMesh Studio's main job on the
# embedded example (the CLI builds the example sketch and prints its figures).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh dev
exec build/dev/app/rigmesh example
