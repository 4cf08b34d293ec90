// Runs a piece of third-party code that may crash, hang or exhaust memory on a hostile input
// (assimp's importers: fuzz_model_loader found a SEGV and a hang in assimp 5.2.5's PLY reader,
// verif/fuzz/model_regressions) in a child process with a time and an address-space limit. The
// child returns its result as bytes through a pipe; the parent turns a crash, a timeout or an
// exhausted limit into a failure it can report (an InputError naming the file, exit 2), so the
// project's guarantee that nothing crashes or hangs holds whatever the library does.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace cig {

struct IsolationLimits {
  double seconds = 60;                                  // wall-clock time before the child is killed
  unsigned long long extra_address_bytes = 4ull << 30;  // address space the child may add to the parent's
  std::size_t max_result_bytes = std::size_t(2) << 30;  // the largest result the parent accepts
};

// What happened to the child; ok only when it exited 0 having written its whole result.
struct IsolatedResult {
  bool ok = false;
  std::string bytes;   // the child's result when ok; its failure message when the work threw
  std::string reason;  // why not ok, in words ("crashed (signal 11, SIGSEGV)", "took more than 60 s", ...)
};

// `work` runs in the child; its return value is the result, and an exception it throws becomes a
// failure whose bytes are the exception's what() (reason "threw"). The parent's state is untouched.
// False in a sanitizer build, whose shadow memory takes terabytes of address space: there only the
// time limit and the result cap hold.
bool address_space_limited();

IsolatedResult run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits = {});

}  // namespace cig
