#include "formatter/lattice_check.hpp"

#include <string>

#include "common/error.hpp"
#include "hls/formatter/sample_lattice.hpp"

namespace cig {

void check_lattice(int raster_log2, int side_log2, const char* engine) {
  if (hls::lattice_supported(raster_log2, side_log2)) return;
  const int side = 1 << side_log2;
  throw InputError("", "raster",
                   std::string("the ") + engine +
                       " engine's sample lattice has 64 to 4096 samples a side; a raster of " +
                       std::to_string(1 << raster_log2) + " lines at " + std::to_string(side * side) +
                       (side == 1 ? " sample" : " samples") + " per pixel has " + std::to_string(side << raster_log2));
}

}  // namespace cig
