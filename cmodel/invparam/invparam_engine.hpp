// Stage F's engines (seed 002, the inverse-parameter visibility processor; SPEC F):
//   invparam         the bit-accurate kernel (hls/invparam/visibility.hpp) on W-bit words,
//                    --engine-opt bits=W (kMinWordBits..kMaxWordBits, default 64)
//   invparam-double  its double twin (invparam_double.hpp)
// Both take the frame's convex polyhedra (ScreenFrame::polyhedra, from stage B) rather than its
// polygons: per sample of the lattice (--engine-opt spp=1|4|16|64) the ray's visible face by
// Fig. 1, a column at a time as the systolic array computes it. The sample's owner is the face as
// drawn (EyeFace::polygon, so ids compare with the other engines'), shaded as the reference shades
// that polygon (Gouraud I, screen-affine over the polygon's vertices; fog from the kernel's own
// depth, Z = 1/tau), the pixel the box filter of its samples, its id the majority owner.
//
// What it does not draw is counted in the report's "dropped" (invparam_drop_kinds) and warned of
// by every command: the polygons of objects that are not convex polyhedra, every light point, and
// samples whose visible face stage B did not draw (clipped away whole by the near plane, or
// culled), which show the background. A polygon list (no polyhedra at all) and a scene without a
// polyhedron are refused. Not drops: setup values saturated to the word and faces whose values
// leave the word's range on the lattice (setup_values_saturated, faces_out_of_word_range in the
// report) are still drawn, with clamped words; what that costs is a wrong visible face at some
// samples, which `cig compare` and `cig wordlength` measure, as any short word's error.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "engine/engine_declaration.hpp"
#include "invparam/face_setup.hpp"

namespace cig {

constexpr int kMinWordBits = 24;
constexpr int kMaxWordBits = 80;
// t_t, the PP's clock period unless clock-ns=T says otherwise: the seed's 3 ns clock of its
// fastest estimate (`cig arch --processor invparam --clock-ns`; `cig cosim --trace` draws a cycle as
// one period of it).
constexpr double kInvparamDefaultClockNs = 3.0;

// `invparam` and (twin) `invparam-double`: the rows the registry lists (engine/engine_declaration.hpp).
const EngineDeclaration& invparam_engine_declaration(bool twin);
std::unique_ptr<RasterEngine> make_invparam_engine(const EngineOptions& options, bool twin);
std::vector<EngineOptionSpec> invparam_engine_options(bool twin);  // the twin has no bits=
const std::vector<DropKind>& invparam_drop_kinds();

// The visibility of every sample of the L x L lattice, row-major (index j L + i: column i, row j).
struct InvparamHits {
  int size = 0;
  std::vector<std::int32_t> face;          // the visible face's index in the setup's face list, -1: none
  std::vector<double> tau;                 // its tau = 1/Z (1/m), the W-bit word's value
  std::vector<InvparamFaceOrigin> origin;  // the setup's face list: where face f comes from
  int saturated = 0, out_of_range = 0, through_eye = 0;
};

// The bit-accurate kernel at W = bits (kMinWordBits..kMaxWordBits) over the frame's polyhedra, a
// column at a time as the engine runs it (the word-length study's method a).
InvparamHits invparam_kernel_hits(const ScreenFrame& frame, const InvparamLattice& lattice, int bits);

}  // namespace cig
