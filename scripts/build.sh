#!/usr/bin/env bash
# Installs the dependencies, then configures and builds Contessa into build/ (Release).
# Usage: scripts/build.sh            (from the repository root or anywhere)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
jobs="${CONTESSA_BUILD_JOBS:-$(nproc)}"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE="${CMAKE_BUILD_TYPE:-Release}" >/dev/null
cmake --build "$root/build" -j "$jobs"
