// cig_ssim_png A.png B.png: the project's SSIM (cmodel/image/ssim.hpp) of two PNG images of the same
// size, for verif/ssim/check_ssim.py to hold against scikit-image. Prints one line, the SSIM of R,
// G, B and their mean at full precision (%.17g); exit 1 with the reason on stderr when it is not
// defined (sizes differ, smaller than the window) or a file cannot be read.
#include <cstdio>
#include <exception>

#include "image/image.hpp"
#include "image/ssim.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cig_ssim_png A.png B.png\n");
    return 2;
  }
  try {
    const cig::Image a = cig::read_png(argv[1]), b = cig::read_png(argv[2]);
    const std::array<double, 3> s = cig::ssim_channels(a, b);
    std::printf("%.17g %.17g %.17g %.17g\n", s[0], s[1], s[2], cig::ssim(a, b));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cig_ssim_png: %s\n", e.what());
    return 1;
  }
}
