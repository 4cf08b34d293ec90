#!/usr/bin/env bash
# Fetches the FlightGear data a region needs out of Debian's flightgear-data-base package (GPL; 1.3 GB
# .deb) into a cache outside the source tree, for `cig import flightgear` (docs/flightgear.md):
#   tools/fetch_flightgear.sh [CHUNK...]      default: w030n60 (Iceland: BIKF, BIRK)
# A CHUNK is FlightGear's 10x10-degree scenery folder (w030n60: lon -30..-20, lat 60..70). Taken:
# Airports/apt.dat.gz, Scenery/Terrain/CHUNK and Scenery/Objects/CHUNK, and of Scenery/Models only
# the folders the chunk's .stg files place (OBJECT_SHARED). Nothing else of the package is kept.
# Cache: $CIG_FLIGHTGEAR_CACHE, default ~/.cache/cig/flightgear; the data lands in CACHE/fgdata
# (what `cig import flightgear --fg-root` defaults to). A chunk already fetched is not fetched again.
# The script writes only inside the cache, and removes only what it wrote there (the .deb after use,
# the Models folders it extracted and no .stg places).
set -euo pipefail
cache=${CIG_FLIGHTGEAR_CACHE:-$HOME/.cache/cig/flightgear}
chunks=("$@")
[ ${#chunks[@]} -gt 0 ] || chunks=(w030n60)
for c in "${chunks[@]}"; do
  if ! [[ $c =~ ^[ew][01][0-9]0[ns][0-9]0$ ]]; then
    echo "fetch_flightgear: '$c': not a 10-degree scenery chunk name (like w030n60: [ew]DDD[ns]DD, multiples of 10)" >&2
    exit 2
  fi
done
root=$cache/fgdata
# The cache is this script's own folder: it removes and replaces things there, so it refuses a
# folder it did not make (one that exists, is not empty and has no marker), e.g. $HOME by mistake.
marker=$cache/.cig-flightgear-cache
if [ -e "$cache" ] && [ ! -f "$marker" ] && [ -n "$(ls -A -- "$cache" 2>/dev/null)" ]; then
  echo "fetch_flightgear: $cache: not empty and not made by this script (no .cig-flightgear-cache); name a new folder in CIG_FLIGHTGEAR_CACHE" >&2
  exit 2
fi
mkdir -p "$cache"
touch "$marker"
prefix=./usr/share/games/flightgear
todo=()
for c in "${chunks[@]}"; do
  [ -f "$cache/done/$c" ] || todo+=("$c")
done
if [ ${#todo[@]} -eq 0 ]; then
  echo "fetch_flightgear: ${chunks[*]} already in $root"
  exit 0
fi
mkdir -p "$cache/deb" "$cache/done" "$root"
need=()
command -v dpkg-deb >/dev/null || need+=(dpkg)
command -v apt-get >/dev/null || need+=(apt)
if [ ${#need[@]} -gt 0 ]; then
  echo "fetch_flightgear: needs ${need[*]} (Debian's apt-get and dpkg-deb)" >&2
  exit 2
fi
cd "$cache/deb"
start=$SECONDS
if ! ls flightgear-data-base_*.deb >/dev/null 2>&1; then
  echo "fetch_flightgear: downloading flightgear-data-base (1.3 GB) into $cache/deb" >&2
  # apt-get download runs as _apt when it can; the cache may be root's: let it fall back quietly.
  apt-get download -q flightgear-data-base 2>&1 | grep -v 'couldn.t be accessed by user' >&2 || true
fi
deb=$(ls flightgear-data-base_*.deb 2>/dev/null | head -n 1)
if [ -z "$deb" ]; then
  echo "fetch_flightgear: apt-get download flightgear-data-base failed (is Debian's archive reachable? apt-get update?)" >&2
  exit 1
fi
patterns=("$prefix/Airports/apt.dat.gz" "$prefix/Scenery/Models/*")
for c in "${todo[@]}"; do
  patterns+=("$prefix/Scenery/Terrain/$c/*" "$prefix/Scenery/Objects/$c/*")
done
echo "fetch_flightgear: extracting ${todo[*]} (about 40 s)" >&2
tmp=$cache/extract.$$
rm -rf "$tmp"
mkdir -p "$tmp"
trap 'rm -rf "$tmp"' EXIT
dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$tmp" --wildcards "${patterns[@]}"
src=$tmp/usr/share/games/flightgear
# The Models folders the chunks' objects place: OBJECT_SHARED Models/<group>/<file> -> Models/<group>.
models=$(cat "$src"/Scenery/Objects/*/*/*.stg 2>/dev/null | awk '$1 == "OBJECT_SHARED" { n = split($2, p, "/"); d = p[1]; for (i = 2; i < n; ++i) d = d "/" p[i]; print d }' | sort -u)
mkdir -p "$root/Airports" "$root/Scenery/Terrain" "$root/Scenery/Objects"
mv -f "$src/Airports/apt.dat.gz" "$root/Airports/"
for c in "${todo[@]}"; do
  rm -rf "${root:?}/Scenery/Terrain/$c" "${root:?}/Scenery/Objects/$c"
  [ -d "$src/Scenery/Terrain/$c" ] && mv "$src/Scenery/Terrain/$c" "$root/Scenery/Terrain/"
  [ -d "$src/Scenery/Objects/$c" ] && mv "$src/Scenery/Objects/$c" "$root/Scenery/Objects/"
done
kept=0
for m in $models; do
  [ -d "$src/Scenery/$m" ] || continue
  mkdir -p "$root/Scenery/$(dirname "$m")"
  rm -rf "${root:?}/Scenery/$m"
  mv "$src/Scenery/$m" "$root/Scenery/$m"
  kept=$((kept + 1))
done
for c in "${todo[@]}"; do
  date -u +%FT%TZ > "$cache/done/$c"
done
rm -f "$deb"
echo "fetch_flightgear: ${todo[*]} in $root ($kept model folders, $(du -sh "$root" | cut -f1)) in $((SECONDS - start)) s"
