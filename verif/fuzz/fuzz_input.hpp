// Shared by the libFuzzer targets (verif/fuzz/README.md): an input is run through one entry point
// of cig; an InputError is the expected answer to bad input (cig prints it and exits 2), anything
// else escaping (std::bad_alloc, a logic error, a library exception) is a finding, and so is every
// crash, hang, leak or sanitizer report, which libFuzzer catches itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"

namespace cig::fuzz {

template <class Body>
int run_input(const std::uint8_t* data, std::size_t size, Body body) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    body(text);
  } catch (const InputError&) {
    // Rejected with a message naming the file, the place and the rule: the correct outcome.
  }
  return 0;
}

// A finding that is not a crash: a property the target checks was broken.
[[noreturn]] inline void broken(const char* what) {
  __builtin_fprintf(stderr, "fuzz: property broken: %s\n", what);
  __builtin_trap();
}

}  // namespace cig::fuzz
