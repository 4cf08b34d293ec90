// The double-precision twin of the quadtree raster processor's parameter arithmetic: plugged into
// the hls/quadtree kernels (setup, PE, pixel processor), it turns each of them into its twin: the
// same algorithm with no quantization of the planes, the parameter values, the fog or the colour.
// Coverage stays the kernels' exact integer arithmetic on the formatter's grid (there is nothing
// to quantize in it); the twin reads the unquantized vertex values (256 Is, Zs) of the formatter
// twin (cmodel/formatter/formatter_twin.hpp), so it also shows what the formatter's I and e8m7 Z cost.
// The plane part is the pixel stages' shared twin (cmodel/pixel/plane_double_arith.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "hls/quadtree/records.hpp"
#include "pixel/plane_double_arith.hpp"

namespace cig {

struct QuadDoubleArith : PlaneDoubleArith {
  using Accum = double;
  // f + 2^k g: the power of two is exact (0 <= k <= 13, a window side in samples), so the product
  // is ldexp(g, k) bit for bit, without a library call per child window.
  static Param step(double f, double g, int k) { return f + g * double(std::uint64_t{1} << k); }
  static Accum accumulate(double a, double s) { return a + s; }
  static hls::UInt<8> resolve(double sum, int side_log2) { return box_mean(sum, side_log2); }
};

}  // namespace cig
