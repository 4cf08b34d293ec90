// The command-line contract every cig executable keeps (cig, cig-cosim): an input error prints
// "PROG: error: FILE: PLACE: RULE" and exits with status 2 before any output is written; anything
// else that goes wrong prints "PROG: internal error: ..." and exits with status 1; --help exits 0.
#pragma once

#include <iostream>
#include <utility>

#include <CLI/CLI.hpp>

#include "common/error.hpp"
#include "common/provenance.hpp"

namespace cig::cli {

// Parses the command line into `app`. Returns false when it printed help or the version (the caller returns
// `status`); option errors are input errors like any other (InputError: one line, status 2).
inline bool parse_command_line(CLI::App& app, int argc, char** argv, int& status) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    status = app.exit(e);
    return false;
  } catch (const CLI::CallForAllHelp& e) {
    status = app.exit(e);
    return false;
  } catch (const CLI::CallForVersion& e) {
    status = app.exit(e);
    return false;
  } catch (const CLI::ParseError& e) { throw InputError("", "", e.what()); }
  return true;
}

// Runs `body` (returning the exit status) under the contract above, with the command line
// recorded for the reports' provenance (common/provenance.hpp).
template <class Body>
int guarded_main(const char* program, int argc, char** argv, Body&& body) {
  try {
    record_command_line(argc, argv);
    return std::forward<Body>(body)();
  } catch (const InputError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace cig::cli
