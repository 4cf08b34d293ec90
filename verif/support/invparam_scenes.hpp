// Scene generators of stage F's tests (the unit tests of the systolic array and the RTL
// co-simulation): random FaceSetup words and boxes, in the array's InvparamScene form
// (cmodel/invparam/systolic_array.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>

#include "invparam/systolic_array.hpp"

namespace cig::invparam::scenes {

inline std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi) {
  return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
}

// n objects of 1..max_m faces, random words of magnitude up to 2^range_log2 (small ranges: many
// ties and zeros; large: wraps).
template <int W>
InvparamScene<W> random_scene(std::mt19937_64& rng, int n, int max_m, int range_log2) {
  InvparamScene<W> s;
  const std::int64_t r = std::int64_t(1) << range_log2;
  s.background = hls::ParCode(uniform(rng, 0, 0xffffff));
  s.eps = Word<W>(-uniform(rng, 1, std::max<std::int64_t>(1, r / 16)));
  for (int k = 0; k < n; ++k) {
    ObjectSpan o;
    o.first_face = int(s.faces.size());
    o.face_count = int(uniform(rng, 1, max_m));
    for (int f = 0; f < o.face_count; ++f) {
      FaceSetup<W> fs;
      fs.az = uniform(rng, 0, 9) != 0;
      fs.as = uniform(rng, 0, 1) != 0;
      fs.start = Word<W>(uniform(rng, -r, r));
      fs.step_x = Word<W>(uniform(rng, -r / 8, r / 8));
      fs.step_y = Word<W>(uniform(rng, -r / 8, r / 8));
      fs.colour = hls::ParCode(uniform(rng, 0, 0xffffff));
      s.faces.push_back(fs);
    }
    s.objects.push_back(o);
  }
  return s;
}

// A box at depth tau = depth over columns a..b, rows r0..r1: a front entry face, four side exit
// faces whose tau exceeds the front's outside the box, a back exit face. m = 6.
template <int W>
void add_box(InvparamScene<W>& s, int a, int b, int r0, int r1, std::int64_t depth, unsigned colour) {
  const std::int64_t k = 4 * depth, half = depth / 2;
  auto face = [&](bool as, std::int64_t start, std::int64_t sx, std::int64_t sy, unsigned c) {
    FaceSetup<W> f;
    f.az = true;
    f.as = as;
    f.start = Word<W>(start);
    f.step_x = Word<W>(sx);
    f.step_y = Word<W>(sy);
    f.colour = hls::ParCode(c);
    s.faces.push_back(f);
  };
  ObjectSpan o;
  o.first_face = int(s.faces.size());
  o.face_count = 6;
  face(false, depth, 0, 0, colour);                    // front: tau = depth
  face(true, k * a + half, -k, 0, colour + 1);         // left:  k (a - i) + depth/2
  face(true, -k * b + half, k, 0, colour + 2);         // right: k (i - b) + depth/2
  face(true, k * (r0 + 1) + half, 0, -k, colour + 3);  // top:    k (r0 - j) + depth/2
  face(true, -k * (r1 + 1) + half, 0, k, colour + 4);  // bottom: k (j - r1) + depth/2
  face(true, depth / 4, 0, 0, colour + 5);             // back
  o.first_column = a;
  o.last_column = b;
  s.objects.push_back(o);
}

// n random boxes on a columns x rows lattice.
template <int W>
InvparamScene<W> box_scene(std::mt19937_64& rng, int n, int columns, int rows) {
  InvparamScene<W> s;
  s.background = hls::ParCode(0xabcdef);
  s.eps = Word<W>(-16);
  for (int k = 0; k < n; ++k) {
    const int a = int(uniform(rng, 0, columns - 1)), b = int(uniform(rng, a, columns - 1));
    const int r0 = int(uniform(rng, 0, rows - 1)), r1 = int(uniform(rng, r0, rows - 1));
    add_box(s, a, b, r0, r1, uniform(rng, 1 << 16, 1 << 24), unsigned(16 * k + 16));
  }
  return s;
}

}  // namespace cig::invparam::scenes
