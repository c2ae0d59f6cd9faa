# Shared by the bench scripts that drive drape-free on a scene (fast_chain.sh, cold_paths.sh);
# sourced, not run. `here` must be the repository root.

# bench_scene NAME SCENE: checks that drape-free is built and SCENE exists, and sets `tool`
# (drape-free), `scene` (SCENE, absolute) and `garment` (the scene's garment OBJ, absolute).
# NAME prefixes the error messages; any error exits with status 2.
bench_scene() {
  tool=$here/build/bin/drape-free
  [ -x "$tool" ] || { echo "$1: build first (./foldsketch test, or cmake --build build)" >&2; exit 2; }
  [ -f "$2" ] || { echo "$1: $2: no such file" >&2; exit 2; }
  scene=$(realpath "$2")
  local file
  file=$(sed -n 's/.*<garment file="\([^"]*\)".*/\1/p' "$scene" | head -1)
  [ -n "$file" ] || { echo "$1: $scene: no <garment file=...>" >&2; exit 2; }
  garment=$(cd "$(dirname "$scene")" && realpath "$file")
}

# distance A B: mean and max vertex distance between two garment OBJs [mm].
distance() {
  python3 -c 'import math, sys
def v(f): return [[float(x) for x in l.split()[1:4]] for l in open(f) if l.startswith("v ")]
d = [math.dist(a, b) for a, b in zip(v(sys.argv[1]), v(sys.argv[2]))]
print("%.3f %.2f" % (1000 * sum(d) / len(d), 1000 * max(d)))' "$1" "$2"
}
