// common/isolated_call: what the parent learns when the child's work returns, throws, crashes,
// loops or allocates without end, and that the parent's own state is untouched.
#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/isolated_call.hpp"

namespace cig {
namespace {

TEST(IsolatedCall, ReturnsTheChildsBytes) {
  std::string big(3 << 20, 'x');  // larger than a pipe's buffer: the parent reads while the child writes
  big[12345] = 'y';
  const IsolatedResult r = run_isolated([&] { return big; });
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.bytes, big);
}

TEST(IsolatedCall, AnExceptionBecomesItsMessage) {
  const IsolatedResult r = run_isolated([]() -> std::string { throw std::runtime_error("bad face 7"); });
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "threw");
  EXPECT_EQ(r.bytes, "bad face 7");
}

TEST(IsolatedCall, ACrashIsReportedNotInherited) {
  const IsolatedResult r = run_isolated([]() -> std::string {
    std::raise(SIGSEGV);
    return "unreachable";
  });
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "crashed (signal 11, SIGSEGV)");
}

TEST(IsolatedCall, ALoopIsStoppedAtTheTimeLimit) {
  IsolationLimits limits;
  limits.seconds = 0.3;
  const IsolatedResult r = run_isolated(
      []() -> std::string {
        for (volatile unsigned long i = 0;; i = i + 1) {}
      },
      limits);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, "took more than 0.3 s and was stopped");
}

// 6 GiB of address space (untouched, so it would succeed under Linux's overcommit without the
// limit) is beyond the 4 GiB the child may add.
TEST(IsolatedCall, AnAllocationBeyondTheLimitFails) {
  if (!address_space_limited()) GTEST_SKIP() << "a sanitizer build has no address-space limit";
  const IsolatedResult r = run_isolated([] {
    std::vector<char*> keep;
    keep.push_back(new char[std::size_t(6) << 30]);
    return std::string("allocated");
  });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("ran out of memory"), std::string::npos) << r.reason;
}

TEST(IsolatedCall, AResultOverTheCapIsRefused) {
  IsolationLimits limits;
  limits.max_result_bytes = 1000;
  const IsolatedResult r = run_isolated([] { return std::string(5000, 'z'); }, limits);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("larger than"), std::string::npos);
}

TEST(IsolatedCall, TheParentsStateIsUntouched) {
  int counter = 1;
  const IsolatedResult r = run_isolated([&] {
    counter = 99;
    return std::to_string(counter);
  });
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.bytes, "99");
  EXPECT_EQ(counter, 1);
}

}  // namespace
}  // namespace cig
