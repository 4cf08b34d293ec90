#include "gtkw_save.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <gtkwave/fstapi.h>  // the FST reader of Verilator's runtime (compiled with verilated_fst_c.cpp)

namespace cig::cosim {

namespace {

// A variable's name as gtkwave shows it (checked against gtkwave 3.3.118's facilities of our FSTs):
// Verilator writes "data [7:0]"; gtkwave drops the space ("data[7:0]"), writes a one-bit range
// as its index ("ready [0:0]" -> "ready[0]") and drops the range of parameters and int variables.
std::string gtkwave_name(const std::string& fst_name, unsigned char type) {
  const std::size_t space = fst_name.find(" [");
  if (space == std::string::npos) return fst_name;
  const std::string base = fst_name.substr(0, space), range = fst_name.substr(space + 1);
  if (type == FST_VT_VCD_PARAMETER || type == FST_VT_VCD_INTEGER || type == FST_VT_SV_INT ||
      type == FST_VT_SV_SHORTINT || type == FST_VT_SV_LONGINT || type == FST_VT_SV_BYTE)
    return base;
  const std::size_t colon = range.find(':');
  if (colon != std::string::npos && range.substr(1, colon - 1) == range.substr(colon + 1, range.size() - colon - 2))
    return base + range.substr(0, colon) + "]";
  return base + range;
}

}  // namespace

FstContents read_fst_contents(const std::string& fst_file) {
  void* ctx = fstReaderOpen(fst_file.c_str());
  if (!ctx) throw std::runtime_error("cannot read the FST file " + fst_file);
  FstContents out;
  out.start_time = fstReaderGetStartTime(ctx);
  out.end_time = fstReaderGetEndTime(ctx);
  out.timescale_exponent = fstReaderGetTimescale(ctx);
  std::vector<std::string> scopes;
  while (const fstHier* h = fstReaderIterateHier(ctx)) {
    if (h->htyp == FST_HT_SCOPE) {
      scopes.emplace_back(h->u.scope.name, h->u.scope.name_length);
    } else if (h->htyp == FST_HT_UPSCOPE) {
      if (!scopes.empty()) scopes.pop_back();
    } else if (h->htyp == FST_HT_VAR) {
      std::string name;
      for (const std::string& s : scopes) name += s + ".";
      out.signals.push_back(name + gtkwave_name(std::string(h->u.var.name, h->u.var.name_length), h->u.var.typ));
    }
  }
  fstReaderClose(ctx);
  return out;
}

bool GtkwGroup::empty() const {
  if (!signals.empty()) return false;
  for (const GtkwGroup& g : groups)
    if (!g.empty()) return false;
  return true;
}

namespace {

// A signal's name without its range or bit index: "TOP.u.data[7:0]" -> "TOP.u.data".
std::string without_range(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::size_t bracket = name.rfind('[');
  if (bracket == std::string::npos || (dot != std::string::npos && bracket < dot) || name.back() != ']') return name;
  return name.substr(0, bracket);
}

// More than one bit: a range "[MSB:LSB]" after the name ("[0]" is one bit).
bool is_vector(const std::string& name) {
  const std::string base = without_range(name);
  return base != name && name.find(':', base.size()) != std::string::npos;
}

class Picker {
 public:
  explicit Picker(const std::vector<std::string>& signals) {
    for (const std::string& s : signals) by_base_.emplace(without_range(s), s);
  }
  // The signals `scope` + leaf present, in the order asked.
  std::vector<std::string> pick(const std::string& scope, const std::vector<const char*>& leaves) const {
    std::vector<std::string> out;
    for (const char* leaf : leaves) {
      const auto it = by_base_.find(scope + leaf);
      if (it != by_base_.end()) out.push_back(it->second);
    }
    return out;
  }
  // One group per unit k = 0, 1, ... of `scope_of(k)`, while the unit has some signal.
  template <class ScopeOf>
  GtkwGroup units(const std::string& name, const std::string& unit_name, ScopeOf scope_of,
                  const std::vector<const char*>& leaves) const {
    GtkwGroup g{name, {}, {}};
    for (int k = 0;; ++k) {
      GtkwGroup unit{unit_name + " " + std::to_string(k), pick(scope_of(k), leaves), {}};
      if (unit.empty()) break;
      g.groups.push_back(std::move(unit));
    }
    return g;
  }

 private:
  std::multimap<std::string, std::string> by_base_;
};

std::string indexed(const std::string& prefix, const char* gen, int k, const char* inst) {
  return prefix + gen + "[" + std::to_string(k) + "]." + inst + ".";
}

std::vector<GtkwGroup> quadtree_groups(const Picker& p) {
  const std::string r = "TOP.qt_raster_cosim_tb.u_raster.";
  std::vector<GtkwGroup> g;
  g.push_back({"input",
               p.pick(r, {"clk_i", "rst_ni", "frame_start_i", "start_window_i", "busy_o", "poly_valid_i",
                          "poly_ready_o", "poly_i"}),
               {}});
  g.push_back(p.units("PEs", "PE", [&](int k) { return indexed(r, "g_pe", k, "u_pe"); },
                      {"in_valid_i", "in_ready_o", "busy_q", "todo_q", "win_level", "win_x", "win_y", "win_id",
                       "load_valid_o", "load_mask_o", "emit_valid_o", "emit_child_o", "emit_full_o", "out_valid_o",
                       "out_ready_i", "stall", "set_valid_o"}));
  g.push_back(p.units("FIFOs", "FIFO", [&](int k) { return indexed(r, "g_fifo", k, "u_fifo"); },
                      {"wvalid_i", "wready_o", "rvalid_o", "rready_i", "count_q"}));
  GtkwGroup pixels =
      p.units("pixel ports", "pixel processor", [&](int k) { return indexed(r, "g_pixel", k, "u_pixel"); },
              {"in_valid_i", "in_ready_o", "stall_i", "rec_id", "rec_x", "rec_y", "px_valid_o", "px_fresh_o",
               "px_full_o", "set_valid_o"});
  pixels.signals = p.pick(r, {"pixel_stall_i", "px_valid_o", "px_full_o", "mask_set_valid_o"});
  g.push_back(std::move(pixels));
  return g;
}

std::vector<GtkwGroup> invparam_groups(const Picker& p) {
  const std::string a = "TOP.ip_array_cosim_tb.u_array.";
  std::vector<GtkwGroup> g;
  g.push_back({"input",
               p.pick(a, {"clk_i", "rst_ni", "cfg_valid_i", "cfg_near_i", "in_valid_i", "in_start_i", "in_word_i",
                          "in_ready_o", "advance"}),
               {}});
  g.push_back({"VT bus", p.pick(a, {"vt_ready_i", "vt_valid_o", "vt_pp_o", "vt_par_o", "vt_obj_o", "col_done_o"}), {}});
  g.push_back(p.units("PPs", "PP", [&](int k) { return indexed(a, "g_pp", k, "u_pp"); },
                      {"en_i", "in_start_i", "in_valid_i", "out_word_o", "out_start_o", "out_valid_o", "clock_q",
                       "kind", "rg_tin_q", "rg_tout_q", "rg_obj_q", "rg_par_q", "vt_valid_o", "col_clock4_o"}));
  return g;
}

void write_group(std::ostream& os, const GtkwGroup& g, int& count, unsigned& flags) {
  if (g.empty()) return;
  auto set_flags = [&](unsigned f) {
    if (f != flags) os << "@" << std::hex << f << std::dec << "\n";
    flags = f;
  };
  set_flags(0x800200);  // grp_begin | blank
  os << "-" << g.name << "\n";
  for (const std::string& s : g.signals) {
    set_flags(is_vector(s) ? 0x22 : 0x28);  // hex | rjustify, binary | rjustify
    os << s << "\n";
    ++count;
  }
  for (const GtkwGroup& sub : g.groups) write_group(os, sub, count, flags);
  set_flags(0x1000200);  // grp_end | blank
  os << "-" << g.name << "\n";
}

}  // namespace

std::vector<GtkwGroup> design_groups(TracedDesign design, const std::vector<std::string>& signals) {
  const Picker p(signals);
  std::vector<GtkwGroup> g = design == TracedDesign::kQuadtreeRaster ? quadtree_groups(p) : invparam_groups(p);
  bool any = false;
  for (const GtkwGroup& x : g) any = any || !x.empty();
  if (!any) {  // a shallow trace (--trace-depth 1): the top's ports
    GtkwGroup top{"top ports", {}, {}};
    for (const std::string& s : signals)
      if (s.rfind("TOP.", 0) == 0 && s.find('.', 4) == std::string::npos) top.signals.push_back(s);
    g = {top};
  }
  return g;
}

int write_gtkw(const std::string& save_file, const std::string& fst_file, std::uint64_t time_start,
               const std::vector<GtkwGroup>& groups) {
  std::ofstream os(save_file);
  if (!os) throw std::runtime_error("cannot write " + save_file);
  os << "[*]\n[*] cig cosim: the co-simulation's FST trace, signals grouped (gtkwave " << fst_file << " " << save_file
     << ")\n[*]\n";
  os << "[dumpfile] \"" << std::filesystem::absolute(fst_file).string() << "\"\n";
  os << "[savefile] \"" << std::filesystem::absolute(save_file).string() << "\"\n";
  os << "[timestart] " << time_start << "\n[size] 1400 900\n[pos] -1 -1\n[sst_expanded] 1\n[signals_width] 320\n";
  int count = 0;
  unsigned flags = 0;
  for (const GtkwGroup& g : groups) write_group(os, g, count, flags);
  os << "[pattern_trace] 1\n[pattern_trace] 0\n";
  os.flush();
  if (!os) throw std::runtime_error("cannot write " + save_file);
  return count;
}

}  // namespace cig::cosim
