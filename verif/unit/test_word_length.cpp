// Stage F's word-length study (cmodel/studies/word_length_study.hpp), reduced (4 views, a 64 x 64
// lattice): what follows from the derivation of the inverse parameter's bound, not tuned numbers.
//  * At the derived W (8 + log2(2 L R^2 / 1 mm)) the kernel (method a) gives no wrong face and no
//    depth error over 1 mm, at 10 km and at 100 km.
//  * The kernel needs more bits at 100 km than at 10 km (R^2: about log2(100) = 6.6 bits more).
//  * At 40 bits the kernel does go wrong at 100 km (the bound is 59: 19 bits short).
//  * The direct Z-buffer (method b) interpolates Z linearly in screen space, which is wrong for a
//    plane (1/Z is affine, Z is not): its depth error does not shrink with W. Z over a triangle is
//    convex in screen space, so the chord lies behind the plane by about (dZ)^2 / (4 Z) over a depth
//    span dZ: up to a few millimetres at 10 km on the wall (its front face's diagonal spans up to
//    ~8 m, its edge-on top and bottom ~14 m), ten times less at 100 km (the same poses), the same at
//    every W; the
//    inverse Z-buffer (c) and exact Z (d) are right at 64 bits.
#include <stdexcept>

#include <gtest/gtest.h>

#include "studies/word_length_study.hpp"

namespace cig {
namespace {

const WordLengthRow& row(const WordLengthStudy& s, double range, DepthMethod m) {
  for (const WordLengthRow& r : s.rows)
    if (r.range == range && r.method == m) return r;
  throw std::logic_error("no row");
}
const WordLengthCell& cell(const WordLengthRow& r, int bits) { return r.cells.at(std::size_t(bits - r.cells[0].bits)); }

class WordLength : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    WordLengthOptions o;
    o.views = 4;
    o.lattice = 64;
    o.min_bits = 40;
    o.max_bits = 72;
    study_ = new WordLengthStudy(run_word_length_study(o));
  }
  static void TearDownTestSuite() { delete study_; }
  static WordLengthStudy* study_;
};
WordLengthStudy* WordLength::study_ = nullptr;

TEST_F(WordLength, InverseParameterIsExactEnoughAtTheDerivedBound) {
  for (double range : {10000.0, 100000.0}) {
    const int w = word_length_bound_bits(range, 64);
    const WordLengthCell& c = cell(row(*study_, range, DepthMethod::kInverseParameter), w);
    EXPECT_EQ(c.wrong_faces, 0) << range << " m at " << w << " bits";
    EXPECT_EQ(c.depth_errors, 0) << range << " m at " << w << " bits";
    EXPECT_LT(c.max_depth_error, 1e-3) << range;
    EXPECT_LE(row(*study_, range, DepthMethod::kInverseParameter).smallest_bits(), w) << range;
  }
  EXPECT_GT(study_->samples, 0);
}

TEST_F(WordLength, InverseParameterNeedsMoreBitsFarther) {
  const int near = row(*study_, 10000, DepthMethod::kInverseParameter).smallest_bits();
  const int far = row(*study_, 100000, DepthMethod::kInverseParameter).smallest_bits();
  ASSERT_GT(near, 0);
  EXPECT_GT(far, near);
}

TEST_F(WordLength, FortyBitsGoWrongAt100Km) {
  const WordLengthCell& c = cell(row(*study_, 100000, DepthMethod::kInverseParameter), 40);
  EXPECT_GT(c.wrong_faces, 0);
  EXPECT_GT(c.depth_errors, 0);
}

TEST_F(WordLength, ZBufferInterpolationErrorDoesNotShrinkWithW) {
  const WordLengthRow& b10 = row(*study_, 10000, DepthMethod::kZBuffer);
  const WordLengthRow& b100 = row(*study_, 100000, DepthMethod::kZBuffer);
  // A floor that does not move with W: the interpolation, not the word (the kernel's error at 72
  // bits is ~1e-10 m).
  EXPECT_GT(cell(b10, 72).max_depth_error, 1e-4);
  EXPECT_NEAR(cell(b10, 48).max_depth_error, cell(b10, 72).max_depth_error, 1e-5);
  EXPECT_LT(cell(row(*study_, 10000, DepthMethod::kInverseParameter), 72).max_depth_error, 1e-8);
  // Ten times farther, the same objects in the same poses span the same depth: (dZ)^2 / (4 Z) is
  // ten times less.
  const double ratio = cell(b10, 72).max_depth_error / cell(b100, 72).max_depth_error;
  EXPECT_GT(ratio, 9);
  EXPECT_LT(ratio, 11);
  // 1/Z interpolated (c) and Z computed exactly (d) are within 1 mm at 64 bits.
  for (double range : {10000.0, 100000.0})
    for (DepthMethod m : {DepthMethod::kInverseZBuffer, DepthMethod::kExactZ}) {
      EXPECT_EQ(cell(row(*study_, range, m), 64).depth_errors, 0) << depth_method_name(m) << " " << range;
      EXPECT_EQ(cell(row(*study_, range, m), 64).wrong_faces, 0) << depth_method_name(m) << " " << range;
    }
}

TEST(WordLengthOptions, BadValuesNameTheOption) {
  WordLengthOptions o;
  o.lattice = 100;
  EXPECT_THROW(check_word_length_options(o), std::exception);
  o = WordLengthOptions{};
  o.ranges = {1e6};
  EXPECT_THROW(check_word_length_options(o), std::exception);
  EXPECT_EQ(word_length_bound_bits(10000, 2048), 57);  // the seed's figures at 512 lines, 16 spp
  EXPECT_EQ(word_length_bound_bits(100000, 2048), 64);
}

}  // namespace
}  // namespace cig
