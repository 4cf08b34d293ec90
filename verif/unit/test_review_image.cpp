// The side-by-side review image of `cig compare --out` (image/review_image.hpp): its size, its
// engine and reference panels the images themselves, the error map in the scale's colours, the id
// mark, and labels that read back as the names given.
#include <unistd.h>

#include <filesystem>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "image/review_image.hpp"

namespace cig {
namespace {

Rgb8 pixel(const Image& img, int x, int y) { return {img.at(x, y)[0], img.at(x, y)[1], img.at(x, y)[2]}; }

void set_pixel(Image& img, int x, int y, Rgb8 c) {
  img.at(x, y)[0] = c.r, img.at(x, y)[1] = c.g, img.at(x, y)[2] = c.b;
}

// Reads one line of text back from an image: each character cell of `count` characters compared with
// every printable character's glyph; '~' where no glyph matches.
std::string read_text(const Image& img, int x, int y, int count, int scale, Rgb8 ink) {
  std::string out;
  for (int k = 0; k < count; ++k, x += kGlyphAdvance * scale) {
    char found = '~';
    for (char c = ' '; c < 127 && found == '~'; ++c) {
      bool same = true;
      for (int r = 0; r < kGlyphHeight && same; ++r)
        for (int col = 0; col < kGlyphWidth && same; ++col)
          same = (pixel(img, x + col * scale, y + r * scale) == ink) == glyph_dot(c, r, col);
      if (same) found = c;
    }
    out += found;
  }
  return out;
}

TEST(ReviewImage, ErrorScaleIsLogarithmicWithADarkNeutralZero) {
  const std::tuple<int, int> cases[] = {{0, 0},  {1, 1},   {2, 2},   {3, 2},   {4, 3},  {7, 3},
                                        {8, 4},  {15, 4},  {16, 5},  {31, 5},  {32, 6}, {63, 6},
                                        {64, 7}, {127, 7}, {128, 8}, {255, 8}, {-3, 0}, {300, 8}};
  for (const auto& [error, bin] : cases) EXPECT_EQ(error_bin(error), bin) << "error " << error;
  const char* labels[kErrorBins] = {"0", "1", "2", "4", "8", "16", "32", "64", "128+"};
  std::set<std::tuple<int, int, int>> colours;
  for (int b = 0; b < kErrorBins; ++b) {
    EXPECT_EQ(error_bin_label(b), labels[b]);
    EXPECT_EQ(error_bin(error_bin_floor(b)), b);  // a bin starts at its label
    const Rgb8 c = error_bin_colour(b);
    colours.insert({c.r, c.g, c.b});
    EXPECT_NE(c, kIdDiffersColour);
    EXPECT_NE(c, kReviewBackground);
  }
  EXPECT_EQ(colours.size(), std::size_t(kErrorBins));  // every bin its own colour
  const Rgb8 zero = error_colour(0);
  EXPECT_TRUE(zero.r == zero.g && zero.g == zero.b && zero.r < 100) << "bin 0 is a dark neutral grey";
}

TEST(ReviewImage, ACorrectImageGivesAUniformErrorMap) {
  Image img(8, 4);
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = std::uint8_t(i * 7);
  const Image map = error_heat_map(img, img, nullptr, nullptr);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_EQ(pixel(map, x, y), error_colour(0));
  EXPECT_THROW(error_heat_map(img, Image(8, 5), nullptr, nullptr), std::runtime_error);
}

class ReviewImageFile : public ::testing::Test {
 protected:
  static constexpr int kW = 64, kH = 48;
  RasterImage got, want;
  Image read_back;

  void SetUp() override {
    got.image = want.image = Image(kW, kH);
    got.ids = want.ids = IdBuffer(kW, kH);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        set_pixel(got.image, x, y, {std::uint8_t(x * 4), std::uint8_t(y * 5), std::uint8_t((x + y) * 2)});
        got.ids.id[std::size_t(y * kW + x)] = x / 16;
      }
    want = got;
    want.image.at(10, 10)[0] += 5;    // error 5: bin "4"
    want.image.at(20, 20)[1] -= 40;   // error 40: bin "32"
    want.image.at(40, 40)[2] -= 150;  // error 150 (blue 160 -> 10): bin "128+"
    want.ids.id[30 * kW + 30] = 7;    // same colour, another polygon: the id mark
    want.ids.id[31 * kW + 31] = 7;    // another polygon and a large error: still the id mark
    want.image.at(31, 31)[0] += 100;
    const std::string file =
        (std::filesystem::temp_directory_path() / ("cig_review_image_" + std::to_string(::getpid()) + ".png")).string();
    write_png(file, review_image(got, want, {"quadtree", "float-snap", "frame 0 channel 1: PSNR 40.00 dB"}));
    read_back = read_png(file);  // what a reader of the PNG sees
    std::filesystem::remove(file);
  }
};

TEST_F(ReviewImageFile, SizeIsThreePanelsWithTitleStripAndScale) {
  // At 64-pixel panels text is drawn at 1 pixel per glyph dot: margins and gaps 4, text lines 11
  // high; title strip 4 + 2 x 11 = 26 rows, scale 4 + 10 (boxes) + 2 + 9 (labels) + 4 = 29 rows under
  // the panels. The scale (10 boxes of 26, a gap of 8 and the 107-pixel "polygon id differs" under
  // the last) is wider than 3 x 64 + 2 x 4 + 2 x 4 = 208, so it sets the width: 4 + 9 x 26 + 8 + 107
  // + 4 = 357.
  EXPECT_EQ(read_back.width, 357);
  EXPECT_EQ(read_back.height, 26 + kH + 29);
  const ReviewLayout l = review_layout(kW, kH);
  EXPECT_EQ(l.width, read_back.width);
  EXPECT_EQ(l.height, read_back.height);
  // 512-pixel panels (the airfield): text doubled, the panels set the width.
  const ReviewLayout big = review_layout(512, 512);
  EXPECT_EQ(big.text_scale, 2);
  EXPECT_EQ(big.width, 2 * 8 + 3 * 512 + 2 * 8);
  EXPECT_EQ(big.height, 2 * 26 + 512 + 2 * 29);
}

TEST_F(ReviewImageFile, EngineAndReferencePanelsAreTheImages) {
  const ReviewLayout l = review_layout(kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      ASSERT_EQ(pixel(read_back, l.panel_x[0] + x, l.panel_y + y), pixel(got.image, x, y)) << x << "," << y;
      ASSERT_EQ(pixel(read_back, l.panel_x[1] + x, l.panel_y + y), pixel(want.image, x, y)) << x << "," << y;
    }
}

TEST_F(ReviewImageFile, ErrorPixelsShowTheScaleColourOfTheirError) {
  const ReviewLayout l = review_layout(kW, kH);
  // The scale's boxes as drawn in the file, read at their centres.
  auto box = [&](int k) { return pixel(read_back, l.box_x(k) + l.box_width / 2, l.scale_y + l.box_height / 2); };
  std::set<std::tuple<int, int, int>> distinct;
  for (int k = 0; k <= kErrorBins; ++k) distinct.insert({box(k).r, box(k).g, box(k).b});
  EXPECT_EQ(distinct.size(), std::size_t(kErrorBins + 1));
  auto map = [&](int x, int y) { return pixel(read_back, l.panel_x[2] + x, l.panel_y + y); };
  EXPECT_EQ(map(0, 0), box(0));             // no error
  EXPECT_EQ(map(10, 10), box(3));           // 5: the box labelled 4 (4 to 7)
  EXPECT_EQ(map(20, 20), box(6));           // 40: the box labelled 32
  EXPECT_EQ(map(40, 40), box(8));           // 150: 128+
  EXPECT_EQ(map(30, 30), box(kErrorBins));  // ids differ, colour equal: the id mark
  EXPECT_EQ(map(31, 31), box(kErrorBins));  // ids differ and an error of 100: still the id mark
  EXPECT_EQ(box(kErrorBins), kIdDiffersColour);
  // The tick labels under the boxes read back as the scale's bounds.
  EXPECT_EQ(read_text(read_back, l.box_x(8) + 1, l.labels_y, 4, 1, kReviewText), "128+");
  EXPECT_EQ(read_text(read_back, l.box_x(kErrorBins), l.labels_y, 18, 1, kReviewText), "polygon id differs");
}

TEST_F(ReviewImageFile, TitleStripNamesThePanels) {
  const ReviewLayout l = review_layout(kW, kH);
  EXPECT_EQ(read_text(read_back, l.panel_x[0], l.names_y, 8, 1, kReviewText), "quadtree");
  EXPECT_EQ(read_text(read_back, l.panel_x[1], l.names_y, 10, 1, kReviewText), "float-snap");
  // Neither "|error| LSB (max of R, G, B)" nor "|error| LSB" (65 pixels) fits 64: the shortest name.
  EXPECT_EQ(read_text(read_back, l.panel_x[2], l.names_y, 11, 1, kReviewText), "|error|    ");
  EXPECT_EQ(read_text(read_back, l.panel_x[0], l.title_y, 32, 1, kReviewText), "frame 0 channel 1: PSNR 40.00 dB");
}

TEST(ReviewImage, GlyphsAreDistinctAndClipped) {
  // Every printable character its own glyph (a label reads one way).
  std::set<std::string> shapes;
  int printable = 0;
  for (char c = ' '; c < 127; ++c) {
    std::string s;
    for (int r = 0; r < kGlyphHeight; ++r)
      for (int col = 0; col < kGlyphWidth; ++col) s += glyph_dot(c, r, col) ? '#' : '.';
    const bool boxed = c != ' ' && s == [] {
      std::string m;
      for (int r = 0; r < kGlyphHeight; ++r)
        for (int col = 0; col < kGlyphWidth; ++col) m += glyph_dot('\x01', r, col) ? '#' : '.';
      return m;
    }();
    if (!boxed) ++printable, shapes.insert(s);
  }
  EXPECT_EQ(shapes.size(), std::size_t(printable));
  EXPECT_GE(printable, 62 + 10);  // digits, both cases and the labels' punctuation
  Image img(20, 9);
  draw_text(img, 0, 0, "888", 1, {255, 255, 255}, 15);  // the third 8 would cross x = 15
  bool third = false;
  for (int y = 0; y < 9; ++y)
    for (int x = 12; x < 20; ++x) third = third || img.at(x, y)[0] != 0;
  EXPECT_FALSE(third);
  EXPECT_EQ(text_width("888", 2), 2 * (3 * kGlyphAdvance - 1));
}

}  // namespace
}  // namespace cig
