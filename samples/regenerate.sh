#!/usr/bin/env bash
# Rewrite the committed sample scenes: make-sample places each garment on an isotropic mesh
# (hinge bending is too soft on grids; tests/lib/sim/physics_test.cpp) in its sewn placement,
# nearly isometric to its patterns; then drape-free simulates it to equilibrium, and that drape is
# the committed garment.obj. The tests check the patterns and scenes byte for byte against
# make-sample, and the drapes for equilibrium (residual, penetration, pins).
# Usage: samples/regenerate.sh [BIN]   (BIN defaults to build/bin)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=${1:-$here/../build/bin}
for name in flag skirt box-cover dress; do
  "$bin/make-sample" "$name" --mesh isotropic --body "$here/bodies/mean_all.obj" -o "$here/$name"
  "$bin/drape-free" "$here/$name/scene.xml" -o "$here/$name/garment.draped.obj"
  mv "$here/$name/garment.draped.obj" "$here/$name/garment.obj"
done
