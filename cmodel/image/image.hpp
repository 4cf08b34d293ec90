// Images (8-bit RGB) and per-pixel polygon id buffers, with their file formats.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace cig {

// A linear colour component in [0, 1] as an 8-bit code: clamped, times 255, rounded half away from
// zero (std::lround): the output's and the colour tables' one conversion.
inline std::uint8_t unit_to_byte(double unit) { return std::uint8_t(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0)); }

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // row-major, top row first, 3 bytes per pixel

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0) {}
  std::uint8_t* at(int x, int y) { return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3]; }
  const std::uint8_t* at(int x, int y) const {
    return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
  }
};

// Per-pixel index of the visible polygon in the frame's polygon list, -1 where none.
struct IdBuffer {
  int width = 0, height = 0;
  std::vector<std::int32_t> id;

  IdBuffer() = default;
  IdBuffer(int w, int h) : width(w), height(h), id(std::size_t(w) * std::size_t(h), -1) {}
};

// Places images side by side (left to right), all of the same height.
Image concatenate_horizontally(const std::vector<const Image*>& parts);

// Output files are written to a temporary name and renamed into place, so a failure never leaves a
// partial file behind. Errors throw std::runtime_error naming the file.
void write_png(const std::string& file, const Image& img);
Image read_png(const std::string& file);  // 8-bit RGB or RGBA (alpha dropped); InputError otherwise

// Id file format ("CIGIDS1"): the ASCII line "CIGIDS1 <width> <height>\n" followed by
// width*height little-endian int32 values, row-major, top row first; -1 = no polygon.
void write_ids(const std::string& file, const IdBuffer& ids);
IdBuffer read_ids(const std::string& file);

// Writes `text` to `file` atomically (temporary file + rename).
void write_text_file(const std::string& file, const std::string& text);

}  // namespace cig
