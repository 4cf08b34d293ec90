// Raster-processor architectures of seed 004 (eq. 1): arch = a1 s a2 s ... b p c t, the levels
// 1..n of the subdivision divided among stacks (one PE doing several levels with a LIFO of pending
// windows), pipeline stages (one PE per level) and a final quadtree of PEs (one PE at its first
// level, four at the next, ...; each covered child routed to the PE of its quadrant).
//
// Text form: tokens <count><kind>, kind s, p or t, optionally separated by spaces; <count> may be
// "n" for "all remaining levels" (so "np", "ns", "nt" work at any raster). The counts must add
// up to n = log2(N); "t" may only come last; "p" is one stage per level. Examples for n = 9:
// "9p", "9s", "7p2t", "8s1p", "3s3s2s1t".
#pragma once

#include <string>
#include <vector>

namespace cig::quad {

struct ArchStage {
  char kind = 'p';      // 's' stack, 'p' pipeline stage (one level), 't' quadtree of PEs
  int first_level = 1;  // the levels whose windows the stage produces: first..last
  int last_level = 1;
  int levels() const { return last_level - first_level + 1; }
};

struct Architecture {
  std::string text;     // normalised, e.g. "7p2t"
  int raster_log2 = 9;  // n
  std::vector<ArchStage> stages;

  // Throws InputError naming `option` (e.g. "--arch") and the rule broken. raster_log2 = 0
  // checks the syntax only (the level count needs the raster).
  static Architecture parse(const std::string& text, int raster_log2, const std::string& option = "--arch");
  // PE count: one per stack, one per pipeline level, (4^c - 1) / 3 for a c-level tree (eq. 10).
  long long pe_count() const;
  // Pixel processors: one per leaf PE of a final tree, else one.
  long long pixel_processors() const;
};

// eq. 10 of seed 004: N_arch = i - 1 + (4^(n - i + 1) - 1) / 3 for the pipeline-tree (i-1)p(n-i+1)t.
long long seed_pe_count(int n, int i);

}  // namespace cig::quad
