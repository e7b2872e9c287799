#!/usr/bin/env bash
# Shared helpers for scripts/run, scripts/test and scripts/bless-goldens.
# Source this file; it switches to the repository root.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Debian 12 packages needed to build and test VCT Studio.
VCT_PACKAGES=(
    build-essential cmake pkg-config
    qt6-base-dev libqt6opengl6-dev
    libglm-dev libassimp-dev libopenexr-dev
    libosmesa6-dev libegl-dev libgl1-mesa-dri libegl-mesa0
    xvfb xauth python3-glad libembree-dev qt6-charts-dev
)

# Install whichever of VCT_PACKAGES, and of the packages given as arguments, are missing (needs root or sudo).
ensure_packages() {
    local missing=() pkg status
    for pkg in "${VCT_PACKAGES[@]}" "$@"; do
        status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
        if [[ "$status" != "install ok installed" ]]; then
            missing+=("$pkg")
        fi
    done
    if ((${#missing[@]} == 0)); then
        echo "All required Debian packages are installed."
        return 0
    fi

    echo "Installing missing Debian packages: ${missing[*]}"
    local sudo=()
    if ((EUID != 0)); then
        if command -v sudo >/dev/null 2>&1; then
            sudo=(sudo)
        else
            echo "error: not running as root and sudo is not available;" \
                "install these packages as root: ${missing[*]}" >&2
            return 1
        fi
    fi
    "${sudo[@]}" apt-get update
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
        apt-get install -y --no-install-recommends "${missing[@]}"
}

# Configure (incremental) and build in ./build.
build_project() {
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j"$(nproc)"
}
