#!/usr/bin/env bash
# Configures a build directory: tools/configure.sh DIR [cmake -D options...]. A new directory gets
# the Ninja generator (a flat build graph that keeps both cores busy); an existing one keeps the
# generator it was made with. Shared by render_default.sh and test.sh.
set -euo pipefail
dir=$1
shift
generator=()
if [ ! -f "$dir/CMakeCache.txt" ] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
cmake -S . -B "$dir" "${generator[@]}" "$@" >/dev/null
