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
#   bench/cold_paths.sh SCENE [PATHS] [-- DRAPE-FREE OPTIONS]
#   (PATHS: 3 by default)
#
# For the benchmark skirt at a size (the scenes of bench/drape_bench.txt's notes):
#   build/bin/make-sample skirt --triangles 20000 [--mesh isotropic] --body samples/bodies/mean_all.obj -o D
#   bench/cold_paths.sh D/scene.xml
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: bench/cold_paths.sh SCENE [PATHS] [-- DRAPE-FREE OPTIONS]"
[ $# -ge 1 ] && [ "$1" != "--" ] || { echo "$usage" >&2; exit 2; }
scene=$1
shift
paths=3
if [ $# -ge 1 ] && [ "$1" != "--" ]; then
  paths=$1
  shift
fi
[ $# -ge 1 ] && [ "$1" = "--" ] && shift
[[ "$paths" =~ ^[1-9][0-9]*$ ]] || { echo "cold_paths: PATHS must be a positive whole number, not '$paths'" >&2; exit 2; }
. "$here/bench/scene_tools.sh"
bench_scene cold_paths "$scene"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# moved SRC SEED DST: SRC with every v line moved by up to 1 um per coordinate (Python's
# generator, so a seed gives the same start on every machine).
moved() {
  python3 -c 'import random, sys
random.seed(int(sys.argv[2]))
with open(sys.argv[1]) as src, open(sys.argv[3], "w") as dst:
    for line in src:
        if line.startswith("v "):
            x = [float(t) + random.uniform(-1e-6, 1e-6) for t in line.split()[1:4]]
            line = "v %.9f %.9f %.9f\n" % tuple(x)
        dst.write(line)' "$1" "$2" "$3"
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
