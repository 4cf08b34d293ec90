// The sample lattice the bit-accurate engines take (hls/formatter/sample_lattice.hpp), checked
// with an error a user can act on.
#pragma once

namespace cig {

// The lattice of an N = 2^n raster with 4^t samples per pixel: 64 to 4096 samples a side;
// InputError("raster") naming the engine otherwise.
void check_lattice(int raster_log2, int side_log2, const char* engine);

}  // namespace cig
