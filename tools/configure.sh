#!/usr/bin/env bash
# Configures a build directory: tools/configure.sh DIR [cmake -D options...]. A new directory gets
# the Ninja generator (a flat build graph that keeps both cores busy); an existing one keeps the
# generator it was made with. Shared by render_default.sh and test.sh. DIR must be new, empty or a
# build folder already (it holds CMakeCache.txt): cmake writes its files into DIR and would
# overwrite a user's files of the same names (Makefile, build.ninja...), so anything else is refused.
set -euo pipefail
if [ $# -lt 1 ] || [ -z "$1" ]; then
  echo "usage: tools/configure.sh DIR [cmake -D options...]" >&2
  exit 2
fi
dir=$1
shift
if [ -e "$dir" ] && [ ! -d "$dir" ]; then
  echo "tools/configure.sh: $dir: exists and is not a folder; name a new or empty folder, or a build folder" >&2
  exit 2
fi
if [ -d "$dir" ] && [ ! -f "$dir/CMakeCache.txt" ] && [ -n "$(ls -A -- "$dir")" ]; then
  echo "tools/configure.sh: $dir: is not empty and holds no CMakeCache.txt, so it is no build folder (cmake would" \
    "write over its files); name a new or empty folder, or a build folder" >&2
  exit 2
fi
generator=()
if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
cmake -S . -B "$dir" "${generator[@]}" "$@" >/dev/null
