#!/bin/bash
# A cold drape over several paths: the scene's garment draped from its placement as it is, and
# from the placement with every vertex moved by a random amount of up to 1 um per coordinate
# (seeds 1, 2, ...). A cold drape is chaotic: 1 um moves its Newton iteration count by up to
# 2.3 times and its end by up to 13 mm mean (bench/drape_bench.txt), so a change to the solver is
# judged over paths, not on one. Prints one row per path (Newton iterations, factorisations,
# seconds, final relative residual, and the mean and max vertex distance of its drape from the
# first path's) and the medians, all through drape-free as a user runs it. Options after `--`
# go to drape-free (for example --coarse-to-fine, --straight-steps, --preset fast; with
# --coarse-to-fine the Newton and factorisation columns are the garment's own mesh's, the
# seconds those of all levels, as drape-free --json reports them).
#
#   bench/cold_paths.sh SCENE [PATHS] [--start DRAPE.obj] [--move METRES] [--normal] [-- DRAPE-FREE OPTIONS]
#   (PATHS: 3 by default; --start: the drape the paths start from, by default the scene's
#   garment, its placement; --move: the largest move per coordinate, 1e-6 m by default;
#   --normal: each vertex moved along its normal instead, by up to METRES, which stretches
#   the cloth only to second order)
#
# For the benchmark skirt at a size (the scenes of bench/drape_bench.txt's notes):
#   build/bin/make-sample skirt --triangles 20000 [--mesh isotropic] --body samples/bodies/mean_all.obj -o D
#   bench/cold_paths.sh D/scene.xml
# How far from an equilibrium a start may be and still come back to it (path 1 is the
# equilibrium itself, so the distance column is the distance from it):
#   build/bin/drape-free D/scene.xml -o D/eq.obj
#   bench/cold_paths.sh D/scene.xml 3 --start D/eq.obj --move 1e-5
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: bench/cold_paths.sh SCENE [PATHS] [--start DRAPE.obj] [--move METRES] [--normal] [-- DRAPE-FREE OPTIONS]"
[ $# -ge 1 ] && [ "$1" != "--" ] || { echo "$usage" >&2; exit 2; }
scene=$1
shift
paths=3
if [ $# -ge 1 ] && [ "$1" != "--" ] && [[ "$1" != --* ]]; then
  paths=$1
  shift
fi
start_drape=""
move=1e-6
normal=0
while [ $# -ge 1 ] && [ "$1" != "--" ]; do
  case "$1" in
    --start) [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; start_drape=$2; shift 2 ;;
    --move) [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }; move=$2; shift 2 ;;
    --normal) normal=1; shift ;;
    *) echo "cold_paths: unknown option '$1'; $usage" >&2; exit 2 ;;
  esac
done
[ $# -ge 1 ] && [ "$1" = "--" ] && shift
[[ "$paths" =~ ^[1-9][0-9]*$ ]] || { echo "cold_paths: PATHS must be a positive whole number, not '$paths'" >&2; exit 2; }
python3 -c 'import sys; m = float(sys.argv[1]); sys.exit(0 if 0 < m < 1 else 1)' "$move" 2>/dev/null ||
  { echo "cold_paths: --move must be a length in metres between 0 and 1, not '$move'" >&2; exit 2; }
. "$here/bench/scene_tools.sh"
bench_scene cold_paths "$scene"
if [ -n "$start_drape" ]; then
  [ -f "$start_drape" ] || { echo "cold_paths: $start_drape: no such file" >&2; exit 2; }
  garment=$(realpath "$start_drape")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# moved SRC SEED DST: SRC with every v line moved by up to $move per coordinate, or with
# --normal along the vertex's normal (the area-weighted sum of its faces' normals) by up to
# $move (Python's generator, so a seed gives the same start on every machine).
moved() {
  python3 -c 'import math, random, sys
random.seed(int(sys.argv[2]))
m, normal = float(sys.argv[4]), sys.argv[5] == "1"
lines = open(sys.argv[1]).read().splitlines(True)
V = [[float(t) for t in l.split()[1:4]] for l in lines if l.startswith("v ")]
N = [[0.0, 0.0, 0.0] for _ in V]
for l in lines if normal else []:
    if l.startswith("f "):
        ids = [int(t.split("/")[0]) - 1 for t in l.split()[1:4]]
        a, b, c = (V[i] for i in ids)
        u = [b[k] - a[k] for k in range(3)]
        w = [c[k] - a[k] for k in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        for i in ids:
            N[i] = [N[i][k] + n[k] for k in range(3)]
k = 0
with open(sys.argv[3], "w") as dst:
    for line in lines:
        if line.startswith("v "):
            if normal:
                length = math.sqrt(sum(x * x for x in N[k])) or 1.0
                d = random.uniform(-m, m)
                x = [V[k][j] + d * N[k][j] / length for j in range(3)]
            else:
                x = [V[k][j] + random.uniform(-m, m) for j in range(3)]
            line = "v %.9f %.9f %.9f\n" % tuple(x)
            k += 1
        dst.write(line)' "$1" "$2" "$3" "$move" "$normal"
}
printf '%4s %6s %8s %14s %10s %10s %22s\n' path seed Newton factorisations seconds residual "from path 1 (mean / max)"
rows=$work/rows
: > "$rows"
for k in $(seq 1 "$paths"); do
  seed=$((k - 1))
  start=$garment
  if [ "$seed" -gt 0 ]; then
    start=$work/start$k.obj
    moved "$garment" "$seed" "$start"
  fi
  if ! "$tool" "$scene" --init "$start" -o "$work/drape$k.obj" --json "$@" > "$work/drape$k.json" 2> "$work/drape$k.err"; then
    echo "cold_paths: drape-free failed on path $k (seed $seed); it said:" >&2
    cat "$work/drape$k.err" >&2
    exit 1
  fi
  read -r it fa s r < <(python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
print(d["newton_iterations"], d["factorizations"], "%.2f" % d["time_s"]["total"], "%.2e" % d["residual"])' "$work/drape$k.json")
  read -r dm dx < <(distance "$work/drape1.obj" "$work/drape$k.obj")
  printf '%4d %6d %8d %14d %10s %10s %12s / %6s mm\n' "$k" "$seed" "$it" "$fa" "$s" "$r" "$dm" "$dx"
  echo "$it $fa $s" >> "$rows"
done
python3 -c 'import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
col = lambda i: statistics.median(float(r[i]) for r in rows)
print("median %8g %14g %10.2f   (%d paths)" % (col(0), col(1), col(2), len(rows)))' "$rows"
