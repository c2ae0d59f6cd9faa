#!/usr/bin/env bash
# Rewrite the committed sample scenes with make-sample at its default size.
# Usage: samples/regenerate.sh [BIN]   (BIN defaults to build/bin)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bin=${1:-$here/../build/bin}
for name in flag skirt box-cover dress; do
  "$bin/make-sample" "$name" --body "$here/bodies/mean_all.obj" -o "$here/$name"
done
