#!/usr/bin/env bash
# Configures and builds tidepool (Release by default) into build/. Usage: scripts/build.sh [Debug]
set -euo pipefail
cd "$(dirname "$0")/.."
type=${1:-Release}
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE="$type"
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE="$type" >/dev/null
fi
cmake --build build -j "$(nproc)"
