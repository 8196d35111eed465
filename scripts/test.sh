#!/usr/bin/env bash
# Quick start, step 2: build if needed and run the whole test suite (GPU tests on Mesa llvmpipe
# through EGL; the window test under Xvfb).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/tidepool ] || scripts/build.sh Release
cmake --build build -j "$(nproc)"
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
