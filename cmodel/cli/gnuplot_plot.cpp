#include "cli/gnuplot_plot.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "cli/cli_common.hpp"
#include "common/error.hpp"

namespace cig::cli {

void check_plot_output(const std::string& plot_file, const char* option) {
  if (plot_file.empty()) return;
  check_output_file(plot_file, option);
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0)
    throw InputError("", option, "needs gnuplot (Debian package gnuplot-nox; tools/deps.sh installs it)");
}

// A new folder of its own (mkdtemp), so that the destructor removes nothing it did not create.
GnuplotJob::GnuplotJob(const std::string& tag) {
  std::string name = (std::filesystem::temp_directory_path() / ("cig-" + tag + "-XXXXXX")).string();
  if (::mkdtemp(name.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder " + name);
  dir_ = name;
}

GnuplotJob::~GnuplotJob() {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

void GnuplotJob::draw(const std::string& script, int width, int height, const std::string& plot_file,
                      const char* option) const {
  const std::string png = file("plot.png"), gp = file("plot.gp");
  std::ofstream(gp) << "set terminal png size " << width << "," << height << "\nset output '" << png << "'\n" << script;
  const int rc = std::system(("gnuplot '" + gp + "' > /dev/null 2>&1").c_str());
  if (rc != 0 || !std::filesystem::exists(png)) throw InputError("", option, "gnuplot failed to draw the plot");
  const auto parent = std::filesystem::path(plot_file).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  std::filesystem::copy_file(png, plot_file, std::filesystem::copy_options::overwrite_existing);
}

}  // namespace cig::cli
