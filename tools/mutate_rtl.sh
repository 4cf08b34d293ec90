#!/usr/bin/env bash
# Mutation testing of the RTL and of the architecture model against the co-simulation
# (verif/mutation/mutate.py; rtl/README.md, "Mutation testing"): every mutant of
# verif/mutation/rtl_mutants.tsv and model_mutants.tsv applied to a copy in build/mutation, only
# the Verilated models (or the harness) rebuilt, the co-simulation tests run, a table printed.
# Options are mutate.py's (--only ID,ID  --markdown  --check  --build DIR). Configures build/
# (CIG_WITH_RTL=ON) if it has not been. Whole list: about half an hour on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
for ((k = 1; k <= $#; k++)); do
  if [ "${!k}" = "--build" ]; then j=$((k + 1)); build=${!j}; fi
done
if [ ! -d "$build/mutation" ]; then
  tools/configure.sh "$build" -DCMAKE_BUILD_TYPE=Release -DCIG_BUILD_TESTS=ON -DCIG_WITH_RTL=ON
fi
exec python3 verif/mutation/mutate.py --build "$build" "$@"
