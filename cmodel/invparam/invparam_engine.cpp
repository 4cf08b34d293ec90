#include "invparam/invparam_engine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "common/timing.hpp"
#include "hls/formatter/sample_lattice.hpp"
#include "hls/invparam/visibility.hpp"
#include "invparam/face_setup.hpp"
#include "invparam/invparam_double.hpp"
#include "invparam/systolic_array.hpp"

namespace cig {

namespace {

// A word's value: code 2^-(W - 8) (word.hpp), exact in long double up to 64 significant bits.
template <int W>
double word_value(const hls::Word<W>& w) {
  const __int128 code = static_cast<__int128>((static_cast<unsigned __int128>(w.high_limb()) << 64) | w.low_limb());
  return static_cast<double>(std::ldexp(static_cast<long double>(code), -hls::word_frac_bits(W)));
}

// The bit-accurate kernel, a column at a time: the host's column values (one add of step_x per
// column), the PP chain's rows (one add of step_y per row).
template <int W>
InvparamHits fixed_hits(const ScreenFrame& frame, const InvparamLattice& lattice) {
  const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice);
  const int L = setup.size;
  InvparamHits h;
  h.size = L;
  h.face.assign(std::size_t(L) * std::size_t(L), -1);
  h.tau.assign(h.face.size(), 0.0);
  h.origin = setup.origin;
  h.saturated = setup.saturated;
  h.out_of_range = setup.out_of_range;
  h.through_eye = setup.through_eye;
  auto column = std::make_unique<hls::InvparamColumn<W>>();
  std::vector<hls::InvparamSample<W>> out(hls::kMaxSamplesPerColumn);
  hls::invparam_first_column(*setup.faces, *column);
  for (int i = 0; i < L; ++i) {
    if (i > 0) hls::invparam_next_column(*setup.faces, *column);
    hls::invparam_column(*setup.faces, *column, L, setup.eps, setup.tau_near, out.data());
    for (int j = 0; j < L; ++j) {
      if (!out[std::size_t(j)].hit) continue;
      const std::size_t idx = std::size_t(j) * std::size_t(L) + std::size_t(i);
      h.face[idx] = std::int32_t(out[std::size_t(j)].code.value());
      h.tau[idx] = word_value<W>(out[std::size_t(j)].tau);
    }
  }
  return h;
}

// W from kMinWordBits to kMaxWordBits at run time: one instantiation of the kernel per width.
using FixedHits = InvparamHits (*)(const ScreenFrame&, const InvparamLattice&);
template <int... K>
constexpr std::array<FixedHits, sizeof...(K)> fixed_table(std::integer_sequence<int, K...>) {
  return {&fixed_hits<kMinWordBits + K>...};
}
constexpr auto kFixedHits = fixed_table(std::make_integer_sequence<int, kMaxWordBits - kMinWordBits + 1>{});

InvparamHits double_hits(const ScreenFrame& frame, const InvparamLattice& lattice) {
  // RGeps as the 64-bit kernel has it: -(L + 1) LSB of 2^-56.
  const double eps = std::ldexp(double(invparam_eps_code(lattice.size())), -hls::word_frac_bits(64));
  const std::vector<InvparamSampleDouble> s = invparam_double(invparam_setup_double(frame, lattice, eps));
  InvparamHits h;
  h.size = lattice.size();
  h.face.assign(s.size(), -1);
  h.tau.assign(s.size(), 0.0);
  h.origin = invparam_face_list(frame);
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s[k].hit) {
      h.face[k] = std::int32_t(s[k].code);
      h.tau[k] = s[k].tau;
    }
  return h;
}

// The Gouraud intensity of a polygon as a plane over the screen (Newell's normal of the points
// (Xs, Ys, I)): the reference interpolates I linearly along edges and spans, which is this plane
// for a polygon whose I are planar (the fan split makes them so everywhere else).
struct IntensityPlane {
  double x0 = 0, y0 = 0, i0 = 1, di_dx = 0, di_dy = 0;
  double at(double x, double y) const { return std::clamp(i0 + di_dx * (x - x0) + di_dy * (y - y0), 0.0, 1.0); }
};

IntensityPlane intensity_plane(const ScreenPolygon& p) {
  double nx = 0, ny = 0, nz = 0, mean = 0;
  const std::size_t n = p.vertices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ScreenVertex& a = p.vertices[k];
    const ScreenVertex& b = p.vertices[(k + 1) % n];
    nx += (a.ys - b.ys) * (a.is + b.is);
    ny += (a.is - b.is) * (a.xs + b.xs);
    nz += (a.xs - b.xs) * (a.ys + b.ys);
    mean += a.is / double(n);
  }
  IntensityPlane q;
  q.x0 = p.vertices[0].xs;
  q.y0 = p.vertices[0].ys;
  q.i0 = p.vertices[0].is;
  if (std::fabs(nz) > 1e-300) {
    q.di_dx = -nx / nz;
    q.di_dy = -ny / nz;
  } else {
    q.i0 = mean;  // a polygon of no area on the screen covers no sample anyway
  }
  return q;
}

// Whether screen point (x, y) lies in a convex polygon of either winding (its boundary included).
bool contains(const ScreenPolygon& p, double x, double y) {
  bool positive = false, negative = false;
  const std::size_t n = p.vertices.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ScreenVertex& a = p.vertices[k];
    const ScreenVertex& b = p.vertices[(k + 1) % n];
    const double c = (b.xs - a.xs) * (y - a.ys) - (b.ys - a.ys) * (x - a.xs);
    positive = positive || c > 0;
    negative = negative || c < 0;
  }
  return !(positive && negative);
}

// The polygon a sample of a face shows: the face's one drawn polygon, or of a face drawn as several
// pieces the piece that covers the sample (the first where none does: a sample on a shared edge).
std::int32_t drawn_polygon(const ScreenFrame& frame, const EyeFace& face, double x, double y) {
  if (face.pieces.size() > 1)
    for (std::int32_t p : face.pieces)
      if (contains(frame.polygons[std::size_t(p)], x, y)) return p;
  return face.polygon;
}

// Shade and resolve: a sample shows its face's polygon (colour x I, fogged by Z = 1/tau) or the
// background; a pixel is the box filter of its S x S samples, its id their majority owner.
RasterImage shade_and_resolve(const ScreenFrame& frame, const InvparamHits& h, int side, long& samples_undrawn) {
  std::vector<IntensityPlane> planes(frame.polygons.size());
  for (std::size_t p = 0; p < frame.polygons.size(); ++p) planes[p] = intensity_plane(frame.polygons[p]);
  const int n = frame.raster, L = h.size;
  RasterImage out{Image(n, n), IdBuffer(n, n)};
  std::vector<std::int32_t> owners(std::size_t(side) * std::size_t(side));
  const Fog& fog = frame.fog;
  for (int py = 0; py < n; ++py)
    for (int px = 0; px < n; ++px) {
      double sum[3] = {0, 0, 0};
      int count = 0;
      for (int sy = 0; sy < side; ++sy)
        for (int sx = 0; sx < side; ++sx, ++count) {
          const int i = px * side + sx, j = py * side + sy;
          const std::size_t idx = std::size_t(j) * std::size_t(L) + std::size_t(i);
          const double x = invparam_sample_screen(i, L), y = invparam_sample_screen(j, L);
          std::int32_t poly = -1;
          if (h.face[idx] >= 0) {
            const InvparamFaceOrigin& o = h.origin[std::size_t(h.face[idx])];
            poly = drawn_polygon(frame, frame.polyhedra[std::size_t(o.polyhedron)].faces[std::size_t(o.face)], x, y);
            if (poly < 0) ++samples_undrawn;
          }
          owners[std::size_t(count)] = poly;
          Rgb c = frame.background;
          if (poly >= 0) {
            const ScreenPolygon& p = frame.polygons[std::size_t(poly)];
            const double in = planes[std::size_t(poly)].at(x, y);
            const double z = 1.0 / h.tau[idx];
            const double f = std::clamp((z - fog.start) / (fog.end - fog.start), 0.0, 1.0);
            c = (1 - f) * in * p.colour + f * fog.colour;
          }
          sum[0] += c.r;
          sum[1] += c.g;
          sum[2] += c.b;
        }
      std::uint8_t* dst = out.image.at(px, py);
      for (int k = 0; k < 3; ++k) dst[k] = unit_to_byte(sum[k] / count);
      out.ids.id[std::size_t(py) * std::size_t(n) + std::size_t(px)] = majority_owner(owners.data(), count);
    }
  return out;
}

// The systolic array's frame time for this frame (seed 002; systolic_array.hpp): N_n = L PPs, one
// per sample of a column, P = L columns, every column's chain of T_Pln/T_Obj tokens (4 codes each)
// and its T_Col, padded as the seed pads. Full streaming sends every object to every column (the
// seed's formula, with each object's own face count); covered columns send an object only to the
// columns its drawn polygons span (a conservative range: its silhouette is the union of its drawn
// front faces, widened by one sample).
struct ArrayTime {
  std::int64_t full_clocks = 0, covered_clocks = 0;
};

ArrayTime array_time(const ScreenFrame& frame, int L) {
  std::vector<std::int64_t> full(std::size_t(L), 4), covered(std::size_t(L), 4);  // the T_Col
  for (const EyePolyhedron& p : frame.polyhedra) {
    const std::int64_t codes = 4 * (std::int64_t(p.faces.size()) + 1);  // m T_Pln + T_Obj
    double lo = 2, hi = -2;
    for (const EyeFace& f : p.faces)
      for (std::int32_t piece : f.pieces)
        for (const ScreenVertex& v : frame.polygons[std::size_t(piece)].vertices) {
          lo = std::min(lo, v.xs);
          hi = std::max(hi, v.xs);
        }
    const int first = std::max(0, int(std::floor((lo + 1) / 2 * L)) - 1);
    const int last = std::min(L - 1, int(std::ceil((hi + 1) / 2 * L)) + 1);
    for (int i = 0; i < L; ++i) {
      full[std::size_t(i)] += codes;
      if (i >= first && i <= last) covered[std::size_t(i)] += codes;
    }
  }
  return {invparam::covered_columns_clocks(full, L), invparam::covered_columns_clocks(covered, L)};
}

// The frame's polygons that are not drawn as a face of a polyhedron (EyeFace::pieces names those
// that are): objects that are not convex polyhedra.
long polygons_not_drawn(const ScreenFrame& frame) {
  std::vector<char> on_face(frame.polygons.size(), 0);
  for (const EyePolyhedron& p : frame.polyhedra)
    for (const EyeFace& f : p.faces)
      for (std::int32_t piece : f.pieces) on_face[std::size_t(piece)] = 1;
  return long(std::count(on_face.begin(), on_face.end(), 0));
}

class InvparamEngine : public RasterEngine {
 public:
  InvparamEngine(const EngineOptions& o, bool twin) : twin_(twin), name_(invparam_engine_declaration(twin).name) {
    const EngineSettings s = parse_engine_options(name_, invparam_engine_options(twin), o.params);
    if (!twin) bits_ = s.integer("bits");
    side_log2_ = s.side_log2();
    covered_ = s.is("streaming", "covered");
    clock_ns_ = s.real("clock-ns");
  }
  const char* name() const override { return name_; }
  const std::vector<DropKind>& drop_kinds() const override { return invparam_drop_kinds(); }
  void check_scene(const Scene& scene) const override {
    if (std::none_of(scene.objects.begin(), scene.objects.end(), [](const Object& o) { return o.polyhedron; }))
      throw InputError(scene.file, "objects",
                       std::string("engine '") + name_ +
                           "' draws convex polyhedra (objects with \"polyhedron\": true); this scene has none");
  }

 protected:
  void check_engine_raster(int raster) const override {
    if ((raster << side_log2_) > hls::kMaxSamplesPerColumn)
      throw InputError("", "raster",
                       std::string("engine '") + name_ + "': " + std::to_string(raster) + " lines at " +
                           std::to_string(1 << (2 * side_log2_)) + " samples per pixel need " +
                           std::to_string(raster << side_log2_) + " pixel processors a column; the array has " +
                           std::to_string(hls::kMaxSamplesPerColumn));
  }
  // A frame of a scene with polyhedra is drawn even when its channel sees none (its polygons are
  // then all counted as not drawn); a polygon list, which has none, is refused.
  void check_split_frame(const ScreenFrame& frame) const override {
    check_raster(frame.raster);
    if (frame.polyhedra.empty() && !frame.lists_polyhedra && !frame.polygons.empty())
      throw InputError("", "polygons",
                       std::string("engine '") + name_ +
                           "' draws convex polyhedra (scene objects with \"polyhedron\": "
                           "true); frame " +
                           std::to_string(frame.frame) + " channel " + std::to_string(frame.channel) + " has " +
                           std::to_string(frame.polygons.size()) +
                           " polygon(s) and no polyhedron (a polygon list has none)");
    invparam_face_list(frame);  // the kernel's capacities (InputError)
  }
  EngineRun render_frame(const ScreenFrame& frame) override {
    check_split_frame(frame);
    const auto t0 = Clock::now();
    const InvparamLattice lattice{frame.raster, side_log2_};
    const InvparamHits h =
        twin_ ? double_hits(frame, lattice) : kFixedHits[std::size_t(bits_ - kMinWordBits)](frame, lattice);
    const double visibility_ms = ms_since(t0);
    const auto t1 = Clock::now();
    long undrawn = 0;
    EngineRun run;
    run.out = shade_and_resolve(frame, h, 1 << side_log2_, undrawn);
    report(frame, h, undrawn, visibility_ms, ms_since(t1), run.report);
    return run;
  }

 private:
  void report(const ScreenFrame& frame, const InvparamHits& h, long undrawn, double visibility_ms, double shade_ms,
              nlohmann::ordered_json& r) const {
    long faces = 0, hit = 0;
    for (const EyePolyhedron& p : frame.polyhedra) faces += long(p.faces.size());
    for (std::int32_t f : h.face) hit += f >= 0 ? 1 : 0;
    r["engine"] = name_;
    if (!twin_) r["word_bits"] = bits_;
    r["samples_per_pixel"] = 1 << (2 * side_log2_);
    r["objects"] = frame.polyhedra.size();
    r["faces"] = faces;
    r["samples_hit"] = hit;
    // Not drops (invparam_engine.hpp): faces drawn with clamped words, their visibility perhaps wrong.
    r["setup_values_saturated"] = h.saturated;
    r["faces_out_of_word_range"] = h.out_of_range;
    // Faces whose plane passes within 2^-20 m of the eye, decided as through it (face_setup.hpp).
    r["faces_through_eye"] = h.through_eye;
    r["dropped"] = {{"polygons_not_drawn", polygons_not_drawn(frame)},
                    {"light_points_not_drawn", frame.light_points.size()},
                    {"samples_on_undrawn_faces", undrawn}};
    const ArrayTime t = array_time(frame, h.size);
    r["array"] = {{"pixel_processors", h.size},
                  {"columns", h.size},
                  {"clock_ns", clock_ns_},
                  {"streaming", covered_ ? "covered" : "full"},
                  {"full_streaming_clocks", t.full_clocks},
                  {"covered_columns_clocks", t.covered_clocks}};
    // The modelled hardware time of the frame (cig sweep): the array's, in the chosen streaming.
    r["hardware_ms"] = double(covered_ ? t.covered_clocks : t.full_clocks) * clock_ns_ * 1e-6;
    r["visibility_ms"] = visibility_ms;
    r["shade_ms"] = shade_ms;
  }

  bool twin_;
  const char* name_;
  int bits_ = hls::kDefaultWordBits;
  int side_log2_ = hls::kDefaultSideLog2;
  bool covered_ = false;                       // streaming=covered: objects only to the columns they span
  double clock_ns_ = kInvparamDefaultClockNs;  // t_t
};

}  // namespace

InvparamHits invparam_kernel_hits(const ScreenFrame& frame, const InvparamLattice& lattice, int bits) {
  if (bits < kMinWordBits || bits > kMaxWordBits)
    throw InputError(
        "", "bits",
        std::to_string(bits) + " is not " + std::to_string(kMinWordBits) + ".." + std::to_string(kMaxWordBits));
  return kFixedHits[std::size_t(bits - kMinWordBits)](frame, lattice);
}

std::vector<EngineOptionSpec> invparam_engine_options(bool twin) {
  std::vector<EngineOptionSpec> specs;
  if (!twin)
    specs.push_back(integer_option("bits", kMinWordBits, kMaxWordBits, std::to_string(hls::kDefaultWordBits),
                                   "the pixel processor's word length"));
  specs.push_back(samples_per_pixel_option(3));
  specs.push_back(choice_option("streaming", {"full", "covered"}, "full",
                                "the array's object stream: to every column (the seed's) or to the columns an object "
                                "spans (the report's hardware_ms)"));
  specs.push_back(
      real_option("clock-ns", 0, 1e6, kInvparamDefaultClockNs, "the array's clock period in ns (the seed's 3 ns)"));
  return specs;
}

const std::vector<DropKind>& invparam_drop_kinds() {
  using Cause = DropKind::Cause;
  static const std::vector<DropKind> kinds{
      {"polygons_not_drawn", Cause::kCannotDraw,
       "polygon(s) not drawn: not a face of a convex polyhedron (stage F draws only objects with \"polyhedron\": "
       "true)"},
      {"light_points_not_drawn", Cause::kCannotDraw, "light point(s) not drawn (stage F draws no light points)"},
      {"samples_on_undrawn_faces", Cause::kCannotDraw,
       "sample(s) shown as background: their visible face was not drawn by the geometric processor (clipped away "
       "or culled)"}};
  return kinds;
}

std::unique_ptr<RasterEngine> make_invparam_engine(const EngineOptions& options, bool twin) {
  return std::make_unique<InvparamEngine>(options, twin);
}

// Both engines' rows of `cig engines` (engine/engine_declaration.hpp).
const EngineDeclaration& invparam_engine_declaration(bool twin) {
  EngineCapabilities fixed;
  fixed.bit_accurate = fixed.polyhedra = true;
  fixed.hardware_model = "rtl/invparam (ip_array)";
  static const EngineDeclaration kFixed{
      "invparam",
      "stage F: seed 002's inverse-parameter visibility processor (1/t per sample, systolic array)",
      fixed,
      [](const EngineOptions& o) { return make_invparam_engine(o, false); },
      [] { return invparam_engine_options(false); },
      invparam_drop_kinds};
  static const EngineDeclaration kTwin{"invparam-double",
                                       "stage F as `invparam`, on double arithmetic (the twin)",
                                       twin_capabilities(fixed, kFixed.name),
                                       [](const EngineOptions& o) { return make_invparam_engine(o, true); },
                                       [] { return invparam_engine_options(true); },
                                       invparam_drop_kinds};
  return twin ? kTwin : kFixed;
}

}  // namespace cig
