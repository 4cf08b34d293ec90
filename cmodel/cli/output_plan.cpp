#include "cli/output_plan.hpp"

#include "cli/gnuplot_plot.hpp"

#include "cli/cli_common.hpp"
#include "common/error.hpp"

namespace cig::cli {

namespace {

namespace fs = std::filesystem;

// The absolute path with symlinks and ".." resolved as far as it exists; "a/b/" is "a/b".
fs::path resolve(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal();
  fs::path r = fs::weakly_canonical(absolute, ec);
  if (ec) r = absolute.lexically_normal();
  while (!r.has_filename() && r != r.root_path()) r = r.parent_path();
  return r;
}

// One file or folder under two names: the same resolved path, or a hard link.
bool same(const fs::path& a, const fs::path& b) {
  if (a == b) return true;
  std::error_code ec;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

// Whether `path` is one of the files `folder` receives.
template <class Folder>
bool written_into(const fs::path& path, const Folder& folder) {
  return folder.names.count(path.filename().string()) > 0 && same(path.parent_path(), folder.resolved);
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

void OutputPlan::input(const std::string& path, const std::string& what) {
  inputs_.push_back({path, what, resolve(path), {}});
}

void OutputPlan::scene_inputs(const Scene& scene) {
  input(scene.file, "the scene file this run reads");
  std::set<std::string> models;
  for (const Object& o : scene.objects)
    for (const Subobject& s : o.subobjects)
      if (!s.model.empty()) models.insert(s.model);
  // Relative model paths resolve against the scene's folder, as the loader reads them.
  for (const std::string& m : models)
    input(fs::path(m).is_relative() ? (fs::path(scene.file).parent_path() / m).string() : m,
          "a model file the scene references");
}

void OutputPlan::file(const std::string& path, const std::string& option) {
  files_.push_back({path, option, resolve(path), {}});
}

void OutputPlan::folder(const std::string& path, const std::string& option, std::set<std::string> names) {
  folders_.push_back({path, option, resolve(path), std::move(names)});
}

void OutputPlan::check_folder(const Entry& f) const {
  for (const Entry& in : inputs_) {
    if (same(f.resolved, in.resolved))
      throw InputError("", f.label, quoted(f.path) + " is " + in.label + ", not a folder");
    if (written_into(in.resolved, f))
      throw InputError("", f.label,
                       quoted(f.path) + " would receive " + in.resolved.filename().string() + ", which is " + in.label +
                           " (" + quoted(in.path) + "); name another folder");
  }
  std::error_code ec;
  if (fs::exists(f.resolved, ec) && !fs::is_directory(f.resolved, ec))
    throw InputError("", f.label, quoted(f.path) + " is an existing file, not a folder");
  check_output_dir(f.path, f.label.c_str());
}

void OutputPlan::check_file(std::size_t k) const {
  const Entry& e = files_[k];
  if (e.path.empty()) check_output_file(e.path, e.label.c_str());  // "the output path is empty"
  for (const Entry& in : inputs_)
    if (same(e.resolved, in.resolved))
      throw InputError("", e.label,
                       quoted(e.path) + " is " + in.label + "; name another file (writing it would replace an input " +
                           "of this run)");
  for (const Entry& f : folders_) {
    if (same(e.resolved, f.resolved))
      throw InputError("", e.label, quoted(e.path) + " is the folder " + f.label + " writes into; name a file in it");
    if (written_into(e.resolved, f))
      throw InputError("", e.label,
                       quoted(e.path) + " is one of the files " + f.label + " writes (" +
                           e.resolved.filename().string() + "); name another file");
  }
  for (std::size_t j = 0; j < k; ++j)
    if (same(e.resolved, files_[j].resolved))
      throw InputError("", e.label, quoted(e.path) + " is also " + files_[j].label + "'s file; name another file");
  check_output_file(e.path, e.label.c_str());
}

void OutputPlan::check() const {
  for (const Entry& f : folders_) check_folder(f);
  for (std::size_t k = 0; k < files_.size(); ++k) check_file(k);
}

void OutputPlan::report_and_plot(const std::string& report_file, const std::string& plot_file) {
  if (!report_file.empty()) file(report_file, "--report");
  if (plot_file.empty()) return;
  file(plot_file, "--plot");
  check_plot_output(plot_file, "--plot");
}

}  // namespace cig::cli
