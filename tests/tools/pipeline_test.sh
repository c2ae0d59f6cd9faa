#!/usr/bin/env bash
# The pipeline on the default scene: outputs appear, and a second run does nothing.
# Usage: BIN=<built tools> pipeline_test.sh <repository>
set -euo pipefail
repo=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$repo"
make --no-print-directory -f Makefile.pipeline BIN="$BIN" WORK="$work/skirt" > "$work/first.log"
for f in info.txt info.json garment.ply pieces.dxf pieces.svg pieces.png pieces.txt pipeline.done; do
  [ -s "$work/skirt/$f" ] || [ "$f" = pipeline.done ] || { echo "missing $work/skirt/$f"; exit 1; }
done
grep -q "^pipeline: read samples/skirt/scene.xml" "$work/first.log" || { echo "no summary line"; cat "$work/first.log"; exit 1; }
make --no-print-directory -f Makefile.pipeline BIN="$BIN" WORK="$work/skirt" > "$work/second.log"
grep -q "Nothing to be done" "$work/second.log" || { echo "second run did work:"; cat "$work/second.log"; exit 1; }
# A failing stage leaves no target behind (.DELETE_ON_ERROR + atomic writes).
mkdir -p "$work/bad"
printf '<scene>\n<garment file="garment.obj"/>\n<material preset="tweed"/>\n</scene>\n' > "$work/bad/scene.xml"
cp samples/flag/garment.obj "$work/bad/"
if make --no-print-directory -f Makefile.pipeline BIN="$BIN" SCENE="$work/bad" WORK="$work/bad-out" > "$work/bad.log" 2>&1; then
  echo "pipeline accepted a bad scene"; exit 1
fi
[ ! -e "$work/bad-out/info.txt" ] || { echo "bad run left info.txt"; exit 1; }
[ ! -e "$work/bad-out/pieces.txt" ] && [ ! -e "$work/bad-out/pieces.dxf" ] || { echo "bad run left cutting patterns"; exit 1; }
echo "1 passed, 0 failed"
