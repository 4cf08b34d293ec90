// Provenance of a run: the version and git commit the binary was built from (compiled in by
// cmake/write_build_info.cmake), the command line and the date it ran. Every report carries it
// (cli/cli_common.cpp, report_text), so a number in a report can be traced to its build and rerun.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace cig {

const char* build_version();  // "0.28.0" (CMakeLists.txt, project VERSION)
const char* build_commit();   // the git commit, "-dirty" when tracked files differed; "unknown"

// Recorded once by each executable's main(): the command line as a shell would take it back
// (arguments quoted where needed) and the start time.
void record_command_line(int argc, const char* const* argv);
// The same with argv[0] replaced by `program_words` as given ("build/bin/cig cosim": cig-cosim
// records the command the user typed, not the executable cig forwarded to).
void record_command_line(const std::string& program_words, int argc, const char* const* argv);
std::string command_line();
std::string run_date();  // ISO 8601, UTC, of record_command_line (or of the first call)

// "cig 0.28.0 (commit 2ce5996...)"
std::string version_line(const std::string& program);
// {"program", "version", "commit", "command_line", "date"}
nlohmann::ordered_json provenance_json(const std::string& program = "cig");

// One argument quoted for a POSIX shell when it needs it ('...' with ' as '\'').
std::string shell_quote(const std::string& arg);

}  // namespace cig
