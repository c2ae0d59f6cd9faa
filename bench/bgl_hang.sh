#!/bin/bash
# Drapes every Berkeley Garment Library garment (../shared/data/bgl, the combined files whose
# vt hold the patterns) hanging from its top band, in thin cotton or MATERIAL, without a body:
# real garments not made by us, with their slivers and distorted placements, through drape-free
# as a user runs it. Prints one row per garment (OBJ faces, Newton iterations, seconds, residual, max
# strain, and the pins' most stretched edge when drape-free warns of it) and a count.
#
#   bench/bgl_hang.sh [BGL_FOLDER] [isotropic|coarse] [MATERIAL]
#   (defaults: ../shared/data/bgl, isotropic, cotton-thin; MATERIAL a preset of drape-free's scenes)
#
# The top band: drape vertices within 13.5 mm of the highest one (the hard case
# HardCases.RealGarmentHangsFromItsDistortedPlacement's choice for the skirt). Each drape may run
# for at most 3000 Newton iterations and 300 s.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bgl=${1:-$here/../shared/data/bgl}
variant=${2:-isotropic}
material=${3:-cotton-thin}
tool=$here/build/bin/drape-free
[ -x "$tool" ] || { echo "bgl_hang: build first (./foldsketch test, or cmake --build build)" >&2; exit 2; }
[ -d "$bgl/Garments" ] || { echo "bgl_hang: $bgl/Garments: no such folder" >&2; exit 2; }
bgl=$(cd "$bgl" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-45s %9s %7s %8s %10s %10s  %s\n' garment faces Newton seconds residual "strain %" note
converged=0 total=0
for f in "$bgl"/Garments/*/"$variant"/*.obj; do
  file=$(basename "$f" .obj)
  case $file in *-m | *-w) continue ;; esac  # material or world space alone: vt are texture coordinates
  name=$(basename "$(dirname "$(dirname "$f")")")/$file  # folder/file: two folders hold a dress3
  key=$work/${name//\//_}
  top=$(awk '$1 == "v" { if (!seen || $3 > top) top = $3; seen = 1 } END { printf "%.9g", top - 0.0135 }' "$f")
  cat > "$key.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<scene name="$name">
  <garment file="$f"/>
  <material preset="$material"/>
  <gravity x="0" y="-9.81" z="0"/>
  <physics body-contact="false" self-contact="false" friction="false" hemline="false"/>
  <pin box="-100 $top -100 100 100 100"/>
  <simulator mode="static" preset="accurate" time-step="0.01" max-steps="3000" tolerance="1e-06"/>
</scene>
XML
  total=$((total + 1))
  report=$(timeout 300 "$tool" --json "$key.xml" -o "$key-drape.obj" 2> "$key.err" || true)
  faces=$(grep -c '^f ' "$f" || true)
  warning=$(grep -o 'holds\? the edge [^ ]* at [^ ]* times' "$key.err" | head -1 || true)
  if [ -z "$report" ]; then
    printf '%-45s %9s %7s %8s %10s %10s  %s\n' "$name" "$faces" - - - - "$(head -c 120 "$key.err")"
    continue
  fi
  row=$(python3 -c '
import json, sys
d = json.loads(sys.argv[1])
print(d["newton_iterations"], round(d["time_s"]["total"], 1), "%.2e" % d["residual"], "%.1f" % (100 * d["max_strain"]),
      "converged" if d["converged"] else d["message"][:60])' "$report")
  read -r newton seconds residual strain note <<< "$row"
  [ "$note" = converged ] && converged=$((converged + 1))
  [ -n "$warning" ] && note="$note; pins hold the ${warning#*the }"
  printf '%-45s %9s %7s %8s %10s %10s  %s\n' "$name" "$faces" "$newton" "$seconds" "$residual" "$strain" "$note"
done
echo "$converged of $total converged"
