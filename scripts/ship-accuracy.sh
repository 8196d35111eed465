#!/usr/bin/env bash
# Regenerates the study data that "method": "auto" and "model": "auto" pick from (assets/accuracy/<study>.csv).
#
#   scripts/ship-accuracy.sh              run every study here and ship its rows (the GPU machine:
#                                         source .gl/prelude.sh first; no charts, it has no gnuplot)
#   scripts/ship-accuracy.sh --from-csv   ship the rows already in bench/results/ (measured
#                                         elsewhere and copied back) without running anything
#
# The list is the studies src/scene/auto/auto.cpp reads (a test checks they agree).
set -euo pipefail
cd "$(dirname "$0")/.."
studies=(swarm-orbit swarm-precision ripples-dispersion balls-restitution balls-settle fluid-density water-front)
flags=(--no-chart --ship)
if [[ "${1:-}" == "--from-csv" ]]; then
  flags+=(--from-csv)
elif [[ $# -gt 0 ]]; then
  echo "usage: $0 [--from-csv]" >&2
  exit 2
fi
for study in "${studies[@]}"; do
  build/tidepool sweep "$study" "${flags[@]}"
done
