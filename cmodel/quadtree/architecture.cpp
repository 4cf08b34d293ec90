#include "quadtree/architecture.hpp"

#include <cctype>

#include "common/error.hpp"

namespace cig::quad {

Architecture Architecture::parse(const std::string& text, int raster_log2, const std::string& option) {
  Architecture a;
  a.raster_log2 = raster_log2;
  // raster_log2 = 0: the syntax only (the engine's options are checked before it sees a frame).
  const bool syntax_only = raster_log2 == 0;
  const int n = syntax_only ? 64 : raster_log2;
  auto fail = [&](const std::string& rule) { throw InputError("", option, "architecture '" + text + "': " + rule); };
  int level = 1;
  std::size_t i = 0;
  bool tree_seen = false;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == '_') {
      ++i;
      continue;
    }
    int count = 0;
    if (text[i] == 'n') {
      count = syntax_only ? 1 : n - level + 1;
      ++i;
    } else if (std::isdigit(static_cast<unsigned char>(text[i]))) {
      while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) {
        count = count * 10 + (text[i] - '0');
        if (count > 64) fail("a count is larger than the number of levels");
        ++i;
      }
    } else {
      fail(std::string("expected a count (a number or n) at '") + text.substr(i) + "'");
    }
    if (i >= text.size()) fail("a count must be followed by s (stack), p (pipeline) or t (tree)");
    const char kind = text[i++];
    if (kind != 's' && kind != 'p' && kind != 't') fail(std::string("unknown stage kind '") + kind + "' (s, p or t)");
    if (count < 1) fail("every stage needs at least one level");
    if (tree_seen) fail("the quadtree of PEs (t) must be the last stage");
    if (level + count - 1 > n)
      fail("the stages cover more than the n = " + std::to_string(n) + " levels of a " + std::to_string(1 << n) +
           "-line raster");
    if (kind == 'p') {
      for (int k = 0; k < count; ++k) a.stages.push_back({'p', level + k, level + k});
    } else {
      a.stages.push_back({kind, level, level + count - 1});
      tree_seen = kind == 't';
    }
    level += count;
  }
  if (a.stages.empty()) fail("empty");
  if (syntax_only) return a;
  if (level != n + 1)
    fail("the stages cover " + std::to_string(level - 1) + " levels; a " + std::to_string(1 << n) +
         "-line raster has n = " + std::to_string(n));
  // Normalised text: consecutive pipeline stages merged into one "bp".
  std::string norm;
  for (std::size_t k = 0; k < a.stages.size(); ++k) {
    const ArchStage& s = a.stages[k];
    if (s.kind == 'p') {
      std::size_t e = k;
      while (e + 1 < a.stages.size() && a.stages[e + 1].kind == 'p') ++e;
      norm += std::to_string(e - k + 1) + "p";
      k = e;
    } else {
      norm += std::to_string(s.levels()) + s.kind;
    }
  }
  a.text = norm;
  return a;
}

long long Architecture::pe_count() const {
  long long pes = 0;
  for (const ArchStage& s : stages) pes += s.kind == 't' ? ((1LL << (2 * s.levels())) - 1) / 3 : 1;
  return pes;
}

long long Architecture::pixel_processors() const {
  const ArchStage& last = stages.back();
  return last.kind == 't' ? (1LL << (2 * (last.levels() - 1))) : 1;
}

long long seed_pe_count(int n, int i) { return i - 1 + ((1LL << (2 * (n - i + 1))) - 1) / 3; }

}  // namespace cig::quad
