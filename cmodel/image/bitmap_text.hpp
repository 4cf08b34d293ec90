// Text drawn into an Image with the project's own 5 x 7 bitmap font (bitmap_text.cpp: a glyph table
// written for this project, digits, letters and the punctuation that labels need), for the labels
// of the review images (review_image.hpp). No font file is read.
#pragma once

#include <cstdint>
#include <string>

#include "image/image.hpp"

namespace cig {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8& o) const { return r == o.r && g == o.g && b == o.b; }
  bool operator!=(const Rgb8& o) const { return !(*this == o); }
};

// A glyph is 5 dots wide and 7 high above the baseline, with 2 rows under it for descenders.
constexpr int kGlyphWidth = 5, kGlyphHeight = 9;
constexpr int kGlyphAdvance = kGlyphWidth + 1;  // one column between characters

// Whether the dot (row, column) of a character's glyph is inked; characters the table lacks are a
// hollow box.
bool glyph_dot(char c, int row, int column);

// Width in pixels of `text` at `scale` pixels per glyph dot (no trailing spacing).
int text_width(const std::string& text, int scale);

// Draws `text` with its top left at (x, y), each glyph dot a scale x scale square; characters
// that would cross x = clip_right (exclusive) or leave the image are not drawn.
void draw_text(Image& img, int x, int y, const std::string& text, int scale, Rgb8 colour, int clip_right);

// Fills the rectangle [x, x + w) x [y, y + h), clipped to the image.
void fill_rect(Image& img, int x, int y, int w, int h, Rgb8 colour);

}  // namespace cig
