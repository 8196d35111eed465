#!/bin/sh
# Renders the README pictures of the swarm model (docs/images/swarm-<scene>.png) headless:
# each scene at 640x360, keeping its last frame. Run from the repository root after building.
set -e
frames=${FRAMES:-90}
tmp=$(mktemp -d)
for scene in orbit sines central-attractive central-repulsive none image; do
  n=$frames
  [ "$scene" = image ] && n=15   # early, while the picture is still recognisable
  [ "$scene" = none ] && n=300   # late enough for the bounce phases to fan out
  ./build/tidepool render "assets/scenes/swarm-$scene.json" --frames "$n" --size 640x360 --out "$tmp/$scene" --quiet
  last=$(ls "$tmp/$scene" | sort | tail -n 1)
  cp "$tmp/$scene/$last" "docs/images/swarm-$scene.png"
done
rm -rf "$tmp"
python3 scripts/shrink_png.py docs/images/swarm-*.png
