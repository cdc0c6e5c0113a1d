#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages), then configures and builds
# RigMesh Studio with the given CMake preset (default: dev).
# Idempotent and quiet when everything is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

preset="${1:-dev}"

packages=(
    cmake ninja-build g++ ccache pkg-config git
    libcgal-dev libgmp-dev libmpfr-dev libboost-dev
    libeigen3-dev libsuitesparse-dev
    nlohmann-json3-dev libtinyxml2-dev libassimp-dev
    assimp-testmodels assimp-utils
    qt6-base-dev libqt6opengl6-dev libgl-dev libgl1-mesa-dri libqt6svg6
    qt6-tools-dev qt6-l10n-tools qt6-translations-l10n
    xvfb xauth
    libgtest-dev libgmock-dev libbenchmark-dev assimp-testmodels
    blender python3-numpy
    lintian appstream desktop-file-utils dpkg-dev file
)
# Node.js for the glTF validator: Debian's packages, unless a node and npm
# are already there (another Node.js distribution would conflict with them).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    packages+=(nodejs npm)
fi

# `grep >/dev/null`, not `grep -q`, after a pipe: under pipefail grep -q's
# early exit can kill the writer with SIGPIPE (exit 141) and fail the test
# (apt-cache policy did, so godot3 was never installed on a fresh machine).
missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep "install ok installed" >/dev/null; then
        missing+=("$package")
    fi
done

if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}"
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The package lists: apt-get needs them to install, and the test that checks
# this script against the configured build (SetupInstallsEveryBuildPackage)
# reads package dependencies from them. A fresh image may ship none.
if ! compgen -G "/var/lib/apt/lists/*_Packages*" >/dev/null; then
    echo "setup: fetching the Debian package lists (apt-get update)"
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update -qq
fi

# Godot 3 for the Godot import check (tests/external/godot): only for a build
# with tests (not the release preset), and only where Debian has it for this
# machine's architecture (read from the package lists above); elsewhere the
# check skips and says why.
if [ "$preset" != "release" ] &&
    ! dpkg-query -W -f='${Status}' godot3 2>/dev/null | grep "install ok installed" >/dev/null; then
    if apt-cache policy godot3 2>/dev/null | grep "Candidate: [0-9]" >/dev/null; then
        echo "setup: installing godot3"
        sudo=""
        if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends godot3 >/dev/null
    else
        echo "setup: Debian has no godot3 for this machine; the Godot import check will be skipped"
    fi
fi

# The glTF validator of the external export tests (tests/external), pinned by
# its package-lock.json; installed once.
if [ ! -d tests/external/node_modules ]; then
    echo "setup: installing the glTF validator (npm ci --prefix tests/external)"
    npm ci --prefix tests/external --no-audit --no-fund >/dev/null
fi

# Configure once; later runs only rebuild what changed.
if [ ! -f "build/$preset/build.ninja" ]; then
    cmake --preset "$preset" >/dev/null
fi
cmake --build --preset "$preset"
