#include "cli/review_outputs.hpp"

#include <cstdio>
#include <filesystem>

#include "cli/cli_common.hpp"
#include "image/image.hpp"
#include "image/review_image.hpp"

namespace cig::cli {

namespace {

namespace fs = std::filesystem;

std::string fixed2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// The comparison's numbers as one line (the side image's caption, the gallery's).
std::string comparison_caption(const Comparison& c) {
  const ImageError& e = c.error;
  return "frame " + std::to_string(c.frame) + " channel " + std::to_string(c.channel) + ": PSNR " + fixed2(e.psnr()) +
         " dB, max |error| R " + std::to_string(e.max_abs[0]) + " G " + std::to_string(e.max_abs[1]) + " B " +
         std::to_string(e.max_abs[2]) + ", " + std::to_string(e.pixels_over_2lsb) + " px > 2 LSB, " +
         std::to_string(c.ids_differ) + " ids differ";
}

}  // namespace

std::string compare_image_file(const std::string& dir, int frame, int channel, const std::string& kind) {
  return (fs::path(dir) / (frame_name(frame) + "_ch" + std::to_string(channel) + "_" + kind + ".png")).string();
}

void write_side_image(const std::string& dir, const Comparison& c, const std::string& engine,
                      const std::string& reference, const RasterImage& got, const RasterImage& want) {
  write_png(compare_image_file(dir, c.frame, c.channel, "side"),
            review_image(got, want, {engine, reference, comparison_caption(c)}));
}

}  // namespace cig::cli
