#!/bin/bash
# A chain of re-drapes, as a pattern loop makes them: the garment's patterns widen by STEP
# (a fraction of their width) COUNT times, and each re-drape starts from the one before,
# once with the accurate preset and once with the fast one (which stops each re-drape at its
# budget of 20 Newton iterations, so every fast re-drape after the first starts from a drape
# that is no equilibrium). Prints one row per step: each chain's Newton iterations and
# seconds, how far the accurate drape moved in that step, and how far the fast chain's drape
# is from the accurate one (mean and max vertex distance), all through drape-free as a user
# runs it.
#
#   bench/fast_chain.sh [SCENE] [STEP] [COUNT]
#   (defaults: samples/skirt/scene.xml, whose garment is an equilibrium; 0.025; 3)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
scene=${1:-$here/samples/skirt/scene.xml}
step=${2:-0.025}
count=${3:-3}
. "$here/bench/scene_tools.sh"
bench_scene fast_chain "$scene"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# widen SRC FACTOR DST: SRC with its patterns (vt) FACTOR times as wide (u only).
widen() {
  awk -v k="$2" '$1 == "vt" { printf "vt %.12g %s\n", $2 * k, $3; next } { print }' "$1" > "$3"
}
# drape PRESET PATTERNS INIT OUT: prints "iterations seconds".
drape() {
  "$tool" "$scene" --json --preset "$1" --patterns "$2" --init "$3" -o "$4" |
    python3 -c 'import json, sys; d = json.load(sys.stdin); print(d["newton_iterations"], "%.2f" % d["time_s"]["total"])'
}

printf '%5s %8s %18s %18s %16s %18s\n' step wider "accurate it. (s)" "fast it. (s)" "accurate moved" "fast from accurate"
accurate=$garment fast=$garment
for k in $(seq 1 "$count"); do
  wider=$(python3 -c "print(1 + $k * $step)")
  widen "$garment" "$wider" "$work/p$k.obj"
  read -r ai as < <(drape accurate "$work/p$k.obj" "$accurate" "$work/a$k.obj")
  read -r fi fs < <(drape fast "$work/p$k.obj" "$fast" "$work/f$k.obj")
  read -r mm mx < <(distance "$accurate" "$work/a$k.obj")
  read -r em ex < <(distance "$work/f$k.obj" "$work/a$k.obj")
  printf '%5d %7.1f%% %10d (%5.2f) %10d (%5.2f) %7.2f / %5.1f mm %7.2f / %5.1f mm\n' "$k" \
    "$(python3 -c "print(100 * ($wider - 1))")" "$ai" "$as" "$fi" "$fs" "$mm" "$mx" "$em" "$ex"
  accurate=$work/a$k.obj fast=$work/f$k.obj
done
