// A gtkwave save file (FILE.gtkw) beside a co-simulation's FST trace, so that
// `gtkwave FILE.fst FILE.gtkw` (or `gtkwave FILE.gtkw`) opens with the signals grouped: for the
// quadtree raster the input, the PEs, the FIFOs and the pixel ports; for stage F's array the
// input, the VT bus and the PPs. The signals are picked from the names the FST itself holds (read
// back with the FST reader Verilator ships), so the save file names only signals present in the
// trace, whatever its depth. The save file's syntax is gtkwave's own (its examples/des.gtkw):
// "[dumpfile]", "[savefile]", "[timestart]" lines, "@FLAGS" lines (hex: 0x22 = hex | rjustify,
// 0x28 = binary | rjustify; a group's begin 0x800200 = grp_begin | blank and end 0x1000200 =
// grp_end | blank, each followed by "-NAME"), one signal per line as "SCOPE.SCOPE.NAME[MSB:LSB]".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cig::cosim {

// The variables of an FST file, as gtkwave names them (scopes joined by '.', a vector's range
// after its name without a space: "TOP.u.data[7:0]"), in the file's order; its time span and unit
// exponent (-9: ns). std::runtime_error when the file cannot be read.
struct FstContents {
  std::vector<std::string> signals;
  std::uint64_t start_time = 0, end_time = 0;
  int timescale_exponent = 0;
};
FstContents read_fst_contents(const std::string& fst_file);

struct GtkwGroup {
  std::string name;
  std::vector<std::string> signals;
  std::vector<GtkwGroup> groups;  // nested (one per PE, FIFO, ...)
  bool empty() const;
};

// The groups of the two co-simulated designs, from the signals present.
enum class TracedDesign { kQuadtreeRaster, kInvparamArray };
std::vector<GtkwGroup> design_groups(TracedDesign design, const std::vector<std::string>& signals);

// Writes the save file: the dump file and itself by absolute path, the view starting at
// `time_start` (FST time units), the groups in order (empty ones left out). Returns the number of
// signals it names.
int write_gtkw(const std::string& save_file, const std::string& fst_file, std::uint64_t time_start,
               const std::vector<GtkwGroup>& groups);

}  // namespace cig::cosim
