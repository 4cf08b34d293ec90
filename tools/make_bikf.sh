#!/usr/bin/env bash
# The Keflavik (BIKF) approach scenes of docs/flightgear.md, imported from FlightGear's data (fetched
# first if missing): an ILS approach to runway 11 on a 3-degree glide path, 3 channels, at dusk and at
# night, each as
#   OUT/bikf_TIME.json        10 NM to touchdown at 50 Hz (12858 frames; the temporal tests take
#                             250 frames of it, 5 s)
#   OUT/bikf_TIME_1hz.json    the same approach at 1 frame a second (258 frames)
# usage: tools/make_bikf.sh [OUT]   (default out/bikf; cig is build/bin/cig, or $CIG)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/bikf}
cig=${CIG:-build/bin/cig}
tools/fetch_flightgear.sh w030n60
mkdir -p "$out"
for time in dusk night; do
  "$cig" import flightgear BIKF --radius-km 20 --approach 11 --time "$time" --out "$out/bikf_$time.json" --report "$out/bikf_${time}_import.json"
  "$cig" import flightgear BIKF --radius-km 20 --approach 11 --time "$time" --rate 1 --out "$out/bikf_${time}_1hz.json" >/dev/null
done
echo "scenes in $out"
