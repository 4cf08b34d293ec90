#!/usr/bin/env bash
# Regenerates the golden images of verif/golden/ with the current build. Run only after a
# deliberate change of the reference's output, and say why in the commit.
set -euo pipefail
cd "$(dirname "$0")/.."
cig=build/bin/cig
g=verif/golden
$cig raster scenes/small/overlap.polys.json --out $g/overlap.png --ids $g/overlap.ids
$cig raster scenes/small/overlap.polys.json --snap --out $g/overlap_snap.png --ids $g/overlap_snap.ids
# A scratch folder of its own (removed at exit), never one that might hold someone's files.
tmp=$(mktemp -d build/golden_tmp.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
$cig render scenes/small/hut.json --frames 0:3 --ids --out "$tmp" >/dev/null 2>&1
for f in 0 3; do
  for c in 0 1; do
    base=$(printf 'frame_%04d_ch%d' $f $c)
    cp "$tmp"/${base}_*.png $g/hut_${base}.png
    cp "$tmp"/${base}_*.ids $g/hut_${base}.ids
  done
done
echo "goldens written to $g"
