#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those missing (apt-get; as root, or through
# sudo otherwise). Everything the build uses comes from these packages.
#   tools/deps.sh render   what building and running `cig` needs (Quick start, command 1)
#   tools/deps.sh          everything: also the tests, SystemC, the RTL tools (command 2)
set -euo pipefail
render_packages=(
  g++ cmake ninja-build pkg-config  # toolchain
  libglm-dev nlohmann-json3-dev libcli11-dev libpng-dev
  libassimp-dev                   # scene models in any format assimp reads (OBJ, AC3D, 3DS, PLY, STL, glTF 2, ...)
  libsimgear-dev                  # FlightGear's BTG terrain reader: `cig import flightgear` (SimGear, with zlib)
)
test_packages=(
  python3                         # layering check, scene generators
  clang libclang-rt-14-dev        # the sanitizer build and the libFuzzer targets (verif/fuzz)
  clang-format                    # the layout check (.clang-format)
  libgtest-dev libbenchmark-dev   # GoogleTest, Google Benchmark
  libsystemc-dev                  # SystemC sc_int/sc_uint: the second type-layer configuration
  assimp-testmodels               # real models of many formats: the loader tests, scenes/models.json
  verilator yosys                 # RTL: lint, Verilated tests and co-simulation, synthesis report
  gtkwave                         # fst2vcd: the co-simulation's trace test reads its FST (cosim.trace)
  gnuplot-nox                     # `cig sweep --plot`: the run-time / error frontier as a PNG
  python3-skimage                 # scikit-image: the ground truth of the SSIM check (verif/ssim)
  libosmesa6-dev                  # bench_llvmpipe (tools/bench.sh): Mesa's llvmpipe as the benchmark's peer
)
case "${1:-all}" in
  render) packages=("${render_packages[@]}") ;;
  all) packages=("${render_packages[@]}" "${test_packages[@]}") ;;
  *) echo "usage: tools/deps.sh [render|all]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "deps: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
