// Plots through gnuplot (Debian package gnuplot-nox), shared by `cig sweep --plot` and
// `cig wordlength --plot`: the data files and the script go to a temporary folder, gnuplot draws a
// PNG there, and only a finished PNG is copied to the output file (a failed plot leaves nothing).
#pragma once

#include <filesystem>
#include <string>

namespace cig::cli {

// --plot FILE: checked before any work (gnuplot present, the file writable). "" = no plot.
void check_plot_output(const std::string& plot_file, const char* option);

class GnuplotJob {
 public:
  explicit GnuplotJob(const std::string& tag);  // a new folder cig-TAG-XXXXXX under the temporary folder
  ~GnuplotJob();
  GnuplotJob(const GnuplotJob&) = delete;
  GnuplotJob& operator=(const GnuplotJob&) = delete;
  // A file of the folder (for the data the script plots).
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  // Runs `script` (everything after the terminal and output lines) on a PNG terminal of the size
  // given, then copies the PNG to plot_file; InputError naming `option` when gnuplot fails.
  void draw(const std::string& script, int width, int height, const std::string& plot_file, const char* option) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace cig::cli
