// Golden vectors of stage F (hls/invparam/, seed 002): invparam_column_top and
// invparam_pixel_processor_top at W = 64.
//
// Inputs: frames of scenes/polyhedra.json through stages A and B (ImageGenerator::geometry), their
// convex polyhedra set up as the invparam engine sets them up (invparam_setup<64>, on a small
// lattice), the column values the host computes (invparam_first_column, invparam_next_column).
// One frame also holds hand-made polyhedra for the kernel's awkward cases: a face through the eye
// (Num = 0: az = 0, the Den rule against RGeps), a face 1 mm ahead (tau up to ~1000, in the guard
// bits' range), a face 0.05 um ahead (decided as through the eye), a box around the eye (exit faces
// only) and one behind it; that frame has a near plane at 2 m (RGnear = 0.5). The pixel processor replays windows of what one PP of the systolic array
// receives (cmodel/invparam/systolic_array.hpp: the frame's token stream, with the host's input gaps
// and VT back-pressure), chosen so that the windows hold every token kind and every rule of the
// PP's clock 4. The writers check that the vectors reach these cases.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "generator/image_generator.hpp"
#include "hls/invparam/pixel_processor.hpp"
#include "hls/invparam/visibility.hpp"
#include "invparam/face_setup.hpp"
#include "invparam/systolic_array.hpp"
#include "scene/scene_loader.hpp"
#include "tb/invparam_column_top.hpp"
#include "tb/invparam_pixel_processor_top.hpp"
#include "vector_file.hpp"

namespace cig::hls_tb {
namespace {

constexpr int W = 64;
using Word = hls::Word<W>;

// ---- Frames -----------------------------------------------------------------------------------
EyeFace plane(double nx, double ny, double nz, double d) {
  const double n = std::sqrt(nx * nx + ny * ny + nz * nz);
  EyeFace f;
  f.nx = nx / n;
  f.ny = ny / n;
  f.nz = nz / n;
  f.d = d;
  return f;
}

// An axis-aligned box (eye coordinates), outward normals: interior n.r < d.
EyePolyhedron box(double cx, double cy, double cz, double hx, double hy, double hz) {
  EyePolyhedron p;
  p.faces = {plane(-1, 0, 0, hx - cx), plane(1, 0, 0, hx + cx),  plane(0, -1, 0, hy - cy),
             plane(0, 1, 0, hy + cy),  plane(0, 0, -1, hz - cz), plane(0, 0, 1, hz + cz)};
  return p;
}

// The awkward polyhedra (see the file's comment), for a frame of tan_half_fov t.
std::vector<EyePolyhedron> awkward_polyhedra(double t) {
  std::vector<EyePolyhedron> out;
  out.push_back(box(1.5 * t, 0, 6, 1.5 * t, t, 1));  // its face x = 0 passes through the eye
  EyePolyhedron slab = box(-0.5 * t, 0.5 * t, 0.5, 0.4 * t, 0.4 * t, 0.5);
  slab.faces[4] = plane(0.3, 0.2, -1, -0.001);  // tilted, 1 mm ahead
  out.push_back(slab);
  EyePolyhedron sliver = box(0.5 * t, -0.5 * t, 4, 0.3 * t, 0.3 * t, 1);
  sliver.faces[2] = plane(0.1, -1, 0.2, -5e-8);  // 0.05 um ahead: the Num = 0 path
  out.push_back(sliver);
  out.push_back(box(0, 0, 0, 2, 2, 2));    // around the eye
  out.push_back(box(0, 0, -10, 3, 3, 1));  // behind the eye
  return out;
}

struct Frames {
  ScreenFrame near, tele, awkward;  // polyhedra.json frame 9 wide, frame 3 tele; frame 9 + awkward
};

Frames polyhedra_frames(const std::string& scenes) {
  const Scene scene = load_scene(scenes + "/polyhedra.json");
  const ImageGenerator pipeline(scene);
  nlohmann::ordered_json report;
  Frames f;
  f.near = pipeline.geometry(9, 0, report);
  f.tele = pipeline.geometry(3, 1, report);
  f.awkward = f.near;
  for (EyePolyhedron& p : awkward_polyhedra(f.near.tan_half_fov)) f.awkward.polyhedra.push_back(std::move(p));
  f.awkward.near = 2;
  return f;
}

// ---- invparam_column_top -------------------------------------------------------------------------
struct ColumnCoverage {
  int hits = 0, misses = 0, az0_faces = 0, through_eye = 0, near_plane = 0, partial = 0, empty = 0;
  void require() const {
    if (hits == 0 || misses == 0 || az0_faces == 0 || through_eye == 0 || near_plane == 0 || partial == 0 || empty == 0)
      throw std::runtime_error("invparam_column_top vectors: a case is missing (hit, miss, az = 0, through eye, ...)");
  }
};

// Columns of one frame's setup on an L x L lattice; `rows` L unless given.
void add_columns(VectorFile<InvparamColumnTopCase>& file, const ScreenFrame& frame, const std::vector<int>& columns,
                 int rows, ColumnCoverage& coverage) {
  const InvparamLattice lattice{32, 0};
  const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice);
  auto in = std::make_unique<InvparamColumnTopCase::Input>();
  in->faces = *setup.faces;
  in->eps = setup.eps;
  in->tau_near = setup.tau_near;
  in->rows = rows > 0 ? rows : setup.size;
  if (setup.saturated != 0 || setup.out_of_range != 0)
    throw std::runtime_error("invparam_column_top vectors: a setup value left the word");
  coverage.through_eye += setup.through_eye;
  coverage.near_plane += frame.near > 0 ? 1 : 0;
  coverage.partial += in->rows < setup.size ? 1 : 0;
  coverage.empty += setup.faces->objects == 0 ? 1 : 0;
  for (int f = 0; f < int(setup.origin.size()); ++f) coverage.az0_faces += setup.faces->face[f].az ? 0 : 1;
  hls::invparam_first_column(in->faces, in->column);
  int at = 0;
  for (int c : columns) {
    for (; at < c; ++at) hls::invparam_next_column(in->faces, in->column);
    const InvparamColumnTopCase::Output& out = file.add(*in);
    for (int j = 0; j < in->rows; ++j) (out.out[j].hit ? coverage.hits : coverage.misses) += 1;
  }
}

void write_column(const std::string& dir, const Frames& f) {
  VectorFile<InvparamColumnTopCase> file(dir,
                                         "columns of scenes/polyhedra.json frames 9 (wide) and 3 (tele) on a 32 x 32 "
                                         "lattice, frame 9 with awkward polyhedra, part of a column, no polyhedra");
  ColumnCoverage coverage;
  add_columns(file, f.near, {0, 9, 16, 31}, 0, coverage);
  add_columns(file, f.tele, {0, 16, 31}, 0, coverage);
  add_columns(file, f.awkward, {0, 12, 16, 20, 31}, 0, coverage);
  add_columns(file, f.awkward, {16}, 20, coverage);
  add_columns(file, ScreenFrame{}, {0}, 0, coverage);
  coverage.require();
}

// ---- invparam_pixel_processor_top ----------------------------------------------------------------
using PpCase = InvparamPixelProcessorTopCase;

// What one PP receives in each of its clocks: the outputs of the PP above it.
struct PpInput {
  Word word;
  hls::PpCtrl ctrl;
};
struct InputRecorder {
  int above;
  std::vector<PpInput>* inputs;
  template <class Outputs>
  void on_clock(std::int64_t, int k, const Outputs& o) {
    if (k == above) inputs->push_back({o.output, o.ctrl});
  }
  void on_freeze(std::int64_t) {}
};

// The events of one PP clock, one bit each: what the windows must hold between them.
constexpr unsigned kBubble = 1u << 0;         // Ctrl valid low
constexpr unsigned kBubbleInToken = 1u << 1;  // ... inside a token
constexpr unsigned kEmpty = 1u << 2;          // clock 1 of each kind
constexpr unsigned kColFirst = 1u << 3;
constexpr unsigned kCol = 1u << 4;
constexpr unsigned kObj = 1u << 5;
constexpr unsigned kPlnDen = 1u << 6;       // az = 0
constexpr unsigned kPlnExit = 1u << 7;      // az = 1, as = 1
constexpr unsigned kPlnEntry = 1u << 8;     // az = 1, as = 0
constexpr unsigned kDenPass = 1u << 9;      // Pln clock 4, az = 0: Den > RGeps
constexpr unsigned kDenMiss = 1u << 10;     //   Den <= RGeps: RGtin = 0
constexpr unsigned kExitTaken = 1u << 11;   // as = 1, tau >= 0: tau > RGtout, RGtout = tau
constexpr unsigned kExitKept = 1u << 12;    //   tau <= RGtout
constexpr unsigned kExitBehind = 1u << 13;  //   tau < 0: nothing
constexpr unsigned kEntryTaken = 1u << 14;  // as = 0, tau >= 0: tau <= RGtin, RGtin = tau, RGparP = code
constexpr unsigned kEntryLater = 1u << 15;  //   tau > RGtin
constexpr unsigned kBehind = 1u << 16;      //   tau < 0: RGtin = 0 (a miss)
constexpr unsigned kObjHit = 1u << 17;      // Obj clock 4, the tests so far held: RGtin > RGobj
constexpr unsigned kObjNoHit = 1u << 18;    //   RGtin <= RGobj (a nearer object won)
constexpr unsigned kObjFailed = 1u << 19;   //   a test failed (no entry, exit before entry)
constexpr unsigned kVt = 1u << 20;
constexpr unsigned kEndsColumn = 1u << 21;
constexpr unsigned kAllEvents = (1u << 22) - 1;

unsigned clock_one_event(const Word& input) {
  const hls::Command c = hls::word_command<W>(input);
  switch (hls::command_kind(c)) {
    case hls::kKindEmpty:
      return kEmpty;
    case hls::kKindCol:
      return hls::command_first(c) ? kColFirst : kCol;
    case hls::kKindObj:
      return kObj;
    default:
      return !hls::command_az(c) ? kPlnDen : hls::command_as(c) ? kPlnExit : kPlnEntry;
  }
}

// Pln clock 4 (b: the state before it; pixel_processor.hpp's pp_pln_decide).
unsigned pln_decision_event(const hls::PpState<W>& b) {
  if (!hls::command_az(b.RGI)) return hls::word_greater(b.RGres, b.RGeps) ? kDenPass : kDenMiss;
  if (hls::command_as(b.RGI)) return b.Ts ? kExitBehind : hls::word_greater(b.RGres, b.RGtout) ? kExitTaken : kExitKept;
  if (b.Ts) return kBehind;
  return hls::word_greater(b.RGres, b.RGtin) ? kEntryLater : kEntryTaken;
}

unsigned pp_events(const hls::PpState<W>& b, const PpInput& in, const hls::PpOutputs<W>& o, const hls::PpState<W>& a) {
  unsigned e = (o.vt.valid ? kVt : 0u) | (o.ends_column ? kEndsColumn : 0u);
  if (!in.ctrl.valid) return e | kBubble | (b.clock.value() >= 1 && b.clock.value() <= 3 ? kBubbleInToken : 0u);
  const unsigned clock = unsigned(a.clock.value()), kind = hls::command_kind(a.RGI);
  if (clock == 1) e |= clock_one_event(in.word);
  if (clock == 4 && kind == hls::kKindPln) e |= pln_decision_event(b);
  if (clock == 4 && kind == hls::kKindObj)
    e |= !b.Tc ? kObjFailed : hls::word_greater(b.RGtin, b.RGobj) ? kObjHit : kObjNoHit;
  return e;
}

// Windows of kCalls clocks over one PP's inputs (from power-on), each taken when it holds an event
// no window before it held; returns the events covered.
unsigned add_windows(VectorFile<PpCase>& file, const std::vector<PpInput>& inputs, const Word& eps,
                     const Word& tau_near) {
  hls::PpState<W> st;
  hls::pp_reset(st, eps, tau_near);
  auto in = std::make_unique<PpCase::Input>();
  unsigned covered = 0;
  for (std::size_t first = 0; first < inputs.size(); first += PpCase::kCalls) {
    const hls::PpState<W> before = st;
    const int calls = int(std::min<std::size_t>(PpCase::kCalls, inputs.size() - first));  // the last: fewer
    unsigned events = 0;
    *in = PpCase::Input();
    for (int k = 0; k < calls; ++k) {
      const PpInput& x = inputs[first + std::size_t(k)];
      const hls::PpState<W> b = st;
      const hls::PpOutputs<W> o = hls::pp_clock(st, x.word, x.ctrl);
      events |= pp_events(b, x, o, st);
      in->input[k] = x.word;
      in->ctrl[k] = x.ctrl;
    }
    if ((events & ~covered) == 0) continue;
    covered |= events;
    in->state = before;
    in->calls = calls;
    file.add(*in);
  }
  return covered;
}

void write_pixel_processor(const std::string& dir, const Frames& f) {
  VectorFile<PpCase> file(dir,
                          "windows of what PP 8 and PP 15 of a 16-PP array receive for scenes/polyhedra.json frame 9 "
                          "with awkward polyhedra (16 x 16 lattice, input gaps, VT back-pressure), each adding an "
                          "event (token kind, clock-4 rule, bubble, VT, column end) the windows before lacked");
  const InvparamLattice lattice{16, 0};
  const InvparamSetup<W> setup = invparam_setup<W>(f.awkward, lattice);
  const int n = setup.size;
  const auto stream = invparam::build_frame_stream(invparam::scene_of_setup(setup), n, n, invparam::StreamMode::kFull);
  unsigned covered = 0;
  for (int pp : {8, n - 1}) {
    std::vector<PpInput> inputs;
    invparam::run_array_stream<W>(stream, setup.eps, setup.tau_near, n, n, invparam::ArrayPacing{29, 20, 20},
                                  InputRecorder{pp - 1, &inputs});
    covered |= add_windows(file, inputs, setup.eps, setup.tau_near);
  }
  if (covered != kAllEvents)
    throw std::runtime_error("invparam_pixel_processor_top vectors: events missing (mask " +
                             std::to_string(kAllEvents & ~covered) + ")");
}

}  // namespace

void write_invparam_vectors(const std::string& dir, const std::string& scenes) {
  const Frames f = polyhedra_frames(scenes);
  write_column(dir, f);
  write_pixel_processor(dir, f);
}

}  // namespace cig::hls_tb
