// A digest of kernel outputs, shared by every kernel test file: FNV-1a (64-bit) over the raw
// integer values the kernels produce. Each test file has a test named *.Digest* that recomputes
// its kernel outputs into one Digest and prints one line
//
//     DIGEST <name> <16 hex digits>
//
// The native and the SystemC-typed builds must print identical lines (ctest kernel_bits_identical,
// verif/kernels/compare_digests.cmake). The helper takes plain integers only, so it is the same in
// both type configurations.
#pragma once

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

namespace cig::kernel_test {

class Digest {
 public:
  static constexpr std::uint64_t kOffset = 14695981039346656037ull;
  static constexpr std::uint64_t kPrime = 1099511628211ull;

  // One value: its 8 bytes, least significant first (FNV-1a is defined on octets).
  void add(std::uint64_t v) {
    for (int b = 0; b < 8; ++b) { h_ = (h_ ^ ((v >> (8 * b)) & 0xFFu)) * kPrime; }
    ++count_;
  }
  void add_signed(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  void add_bool(bool b) { add(b ? 1u : 0u); }
  std::uint64_t value() const { return h_; }
  std::uint64_t count() const { return count_; }

 private:
  std::uint64_t h_ = kOffset;
  std::uint64_t count_ = 0;
};

// Prints the DIGEST line (and records it in the test's XML properties). A digest over no value at
// all is a test bug: the comparison of the builds would then be vacuous.
inline void print_digest(const char* name, const Digest& d) {
  EXPECT_GT(d.count(), 0u) << name;
  std::printf("DIGEST %s %016" PRIx64 "\n", name, d.value());
  std::fflush(stdout);
  ::testing::Test::RecordProperty(std::string("digest_") + name, std::to_string(d.value()));
}

}  // namespace cig::kernel_test
