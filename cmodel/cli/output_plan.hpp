// What a command's run reads and writes, declared before any work, so that every collision among
// them is found before the first byte is written (issue 28): an output that would replace an input
// (the scene, the polygon list, an OBJ model), two outputs on one path, a file output that is an
// existing folder or a folder output that is an existing file, a file output on the name of an
// image an output folder receives. check() throws an InputError naming the option, the path and
// the rule; it also runs check_output_file / check_output_dir (cli_common.hpp) on every output.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace cig::cli {

class OutputPlan {
 public:
  // A file the run reads; `what` names it in messages ("the scene file this run reads").
  void input(const std::string& path, const std::string& what);
  // The scene file and every OBJ model it references.
  void scene_inputs(const Scene& scene);
  // A file the run writes, named by `option` (callers skip an optional output not given).
  void file(const std::string& path, const std::string& option);
  // --report FILE and --plot FILE.png when given ("" = not), the plot with gnuplot's presence.
  void report_and_plot(const std::string& report_file, const std::string& plot_file);
  // A folder the run writes into, named by `option`, and the names of the files it writes there
  // (those known before the work: the images of each frame and channel).
  void folder(const std::string& path, const std::string& option, std::set<std::string> names = {});
  // Throws InputError on the first collision or unwritable output.
  void check() const;

 private:
  struct Entry {
    std::string path, label;  // as given; the option or the input's description
    std::filesystem::path resolved;
    std::set<std::string> names;  // folders: the files written there
  };
  void check_folder(const Entry& f) const;
  void check_file(std::size_t k) const;
  std::vector<Entry> inputs_, files_, folders_;
};

}  // namespace cig::cli
