// Progress lines (common/progress.hpp) and a run's provenance (common/provenance.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>
#include <thread>

#include "common/progress.hpp"
#include "common/provenance.hpp"

namespace cig {
namespace {

int count_lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(Progress, ALogGetsOneLinePerStep) {
  std::ostringstream os;
  {
    Progress p("cig test", 3, os, Progress::Style{false});
    p.within(10, 100, "cycles");  // within a step, before the log interval: nothing
    p.step("frame 0");
    p.step("frame 1");
    p.step("frame 2");
  }
  const std::string s = os.str();
  EXPECT_EQ(count_lines(s), 3) << s;
  EXPECT_NE(s.find("cig test: 1/3 frame 0"), std::string::npos) << s;
  EXPECT_NE(s.find("cig test: 3/3 frame 2"), std::string::npos) << s;
  EXPECT_EQ(s.find('\r'), std::string::npos) << "no carriage return in a log";
}

TEST(Progress, ALogHearsOfALongStepAtTheInterval) {
  std::ostringstream os;
  Progress::Style style{false};
  style.log_interval_s = 0;  // every call is due
  Progress p("cig test", 2, os, style);
  p.within(500, 1000, "cycles");
  EXPECT_NE(os.str().find("step 1/2: 500/1000 cycles (50 %)"), std::string::npos) << os.str();
}

TEST(Progress, AQuickRunOnATerminalPrintsNothing) {
  std::ostringstream os;
  {
    Progress p("cig test", 2, os, Progress::Style{true});  // first line only after 1 s
    p.within(1, 2, "cycles");
    p.step("a");
    p.step("b");
  }
  EXPECT_EQ(os.str(), "");
}

TEST(Progress, ATerminalLineIsRewrittenInPlaceAndEnded) {
  std::ostringstream os;
  Progress::Style style{true};
  style.first_after_s = 0;
  style.terminal_interval_s = 0;
  {
    Progress p("cig test", 2, os, style);
    p.within(3, 4, "samples");
    p.step("a");
    p.step("b");
  }
  const std::string s = os.str();
  EXPECT_EQ(s.front(), '\r');
  EXPECT_EQ(count_lines(s), 1) << "one line, ended when the run ends";
  EXPECT_NE(s.find("cig test: 2/2 b"), std::string::npos) << s;
}

// A warning between progress lines gets a line of its own: on a terminal the open line is cleared
// first, so the warning does not run on after it.
TEST(Progress, ANoteTakesALineOfItsOwn) {
  std::ostringstream os;
  Progress::Style style{true};
  style.first_after_s = 0;
  style.terminal_interval_s = 0;
  {
    Progress p("cig test", 2, os, style);
    p.step("a");
    p.note("cig: warning: frame 0: lost\n");
    p.note("");  // nothing to say: nothing printed
    p.step("b");
  }
  const std::string s = os.str();
  EXPECT_NE(s.find("\x1b[K\r\x1b[Kcig: warning: frame 0: lost\n\rcig test: 2/2 b"), std::string::npos) << s;
  EXPECT_EQ(count_lines(s), 2) << s;
}

TEST(Provenance, VersionCommitCommandLineAndDate) {
  const char* argv[] = {"build/bin/cig", "render", "scenes/a b.json", "--engine-opt", "x='1'"};
  record_command_line(5, argv);
  EXPECT_EQ(command_line(), "build/bin/cig render 'scenes/a b.json' --engine-opt 'x='\\''1'\\'''");
  const auto p = provenance_json("cig");
  EXPECT_TRUE(std::regex_match(p["version"].get<std::string>(), std::regex("[0-9]+\\.[0-9]+\\.[0-9]+")));
  // A build from a git checkout names its commit (40 hex digits, "-dirty" when files differed).
  EXPECT_TRUE(std::regex_match(p["commit"].get<std::string>(), std::regex("[0-9a-f]{40}(-dirty)?|unknown")));
  EXPECT_TRUE(std::regex_match(p["date"].get<std::string>(), std::regex("20[0-9]{2}-[0-9]{2}-[0-9]{2}T[0-9:]{8}Z")));
  EXPECT_EQ(p["command_line"], command_line());
  EXPECT_EQ(version_line("cig"), std::string("cig ") + build_version() + " (commit " + build_commit() + ")");
}

TEST(Provenance, ShellQuoteLeavesPlainWordsAlone) {
  EXPECT_EQ(shell_quote("--frames"), "--frames");
  EXPECT_EQ(shell_quote("0:119"), "0:119");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("a;b"), "'a;b'");
}

}  // namespace
}  // namespace cig
