#!/usr/bin/env bash
# Makes the kit gpu-figures.sh needs besides the image: the peer's imported height map and its camera circles.
# Usage (from the repository root, beside ../shared/peer): demo/dist/gpu-kit.sh [KIT_DIR]  (default demo/target/gpu-kit)
#
#   heightmap-1025.f32   the peer's 1025² spectral height map (1 m spacing, 0-150 m), made by its harness
#                        (../shared/peer/jme3/run.sh, which builds jMonkeyEngine once) unless already in $PEER_HOME
#   circle-dry.path      the peer's camera circle (radius 350 m, 120 m above the centre), water off
#   circle-sea.path      the same circle lowered with the map, for the views with water: OpenWorld's sea is at 0 and
#                        the peer's at 0.35 of the relief, so the imported heights shift down by 52.5 m
set -euo pipefail
kit=${1:-demo/target/gpu-kit}
peer=${PEER:-../shared/peer}
home=${PEER_HOME:-$HOME/.cache/openworld-peer}
map=$home/out/heightmap-1025.f32
if [ ! -f "$map" ]; then
  echo "gpu-kit: $map missing, running the peer harness once (builds jMonkeyEngine)"
  "$peer/jme3/run.sh" --frames 1 >/dev/null
fi
# The camera's height over the peer's map, as the peer prints it (compare.sh reads it the same way).
camy=$(grep -ho 'camera y=[0-9.]*' "$home"/out/*.log 2>/dev/null | tail -n 1 | cut -d= -f2)
camy=${camy:-243.3}
mkdir -p "$kit"
cp "$map" "$kit/heightmap-1025.f32"
python3 "$peer/circle_path.py" "$camy" >"$kit/circle-dry.path"
python3 "$peer/circle_path.py" "$(python3 -c "print($camy - 150 * 0.35)")" >"$kit/circle-sea.path"
echo "gpu-kit: $kit ($(du -sm "$kit" | cut -f1) MiB), camera $camy m over the map"
