#!/usr/bin/env bash
# Install the missing Debian packages of cmake/debian-packages.txt, then configure (once) and
# build foldsketch (Release, out of source in build/). Quiet when there is nothing to do.
# Usage: cmake/ensure-built.sh [BUILD_DIR]
set -euo pipefail
top=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$top/build}

mapfile -t wanted < <(sed -e 's/#.*//' -e 's/[[:space:]]//g' "$top/cmake/debian-packages.txt" | grep -v '^$')
missing=()
for p in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "foldsketch: installing Debian packages: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq >&2
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ ! -f "$build/build.ninja" ]; then
  echo "foldsketch: configuring $build (Release)" >&2
  cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
# ninja re-runs cmake itself when a CMakeLists.txt changed; say nothing when up to date.
out=$(cmake --build "$build" 2>&1) || { echo "$out" >&2; exit 1; }
printf '%s\n' "$out" | grep -v -e '^ninja: no work to do\.$' -e '^$' >&2 || true
