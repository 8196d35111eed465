#!/usr/bin/env bash
# Quick start, step 1: install dependencies, build (Release) and run the default scene: in a
# window when there is a display, otherwise headless, rendering a short clip of PNG frames.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh Release
exec build/tidepool run "${@:-default}"
