// Stage A's preliminary processing unit on the model's data path (SPEC A.1-2, seed 000): the
// visual flag V[i] of every object and subobject sphere is the bit-accurate kernel's
// (hls/manager: manager_channel_setup_top once per channel, manager_visibility_top per sphere), as
// stages C-F run theirs, or its double twin (visibility_twin.hpp) by option. The kernel is
// conservative by design (hls/manager/visibility.hpp: it never culls a sphere the exact test keeps
// and keeps at most a margin M more), so the kernel's lists can hold a few more objects than the
// twin's; the geometric processor clips those away.
//
// The host side of the kernel's formats (hls/manager/records.hpp "host rounding"): positions and B
// to nearest, the radius and t up, near down. A sphere or channel the formats cannot hold (a
// coordinate beyond +-2^20 m, a radius beyond 2^21 m, fov >= 151.9 deg, near >= 8192 m) is not
// decided by the kernel: the unit keeps it visible (the conservative answer) and counts it.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "hls/manager/records.hpp"
#include "manager/channel_view.hpp"

namespace cig {

// Raw ends of the kernel's formats (hls/manager/records.hpp); u = 2^-11 m, the world's LSB.
namespace manager_raw {
constexpr double kU = 1.0 / 2048;
constexpr std::int64_t kWorldMin = -(std::int64_t{1} << 31), kWorldMax = (std::int64_t{1} << 31) - 1;
constexpr std::int64_t kRadiusMax = (std::int64_t{1} << 32) - 1;
constexpr std::int64_t kRotMin = -(std::int64_t{1} << 17), kRotMax = (std::int64_t{1} << 17) - 1;
constexpr std::int64_t kOne = std::int64_t{1} << 16;  // 1.0 in B and t
constexpr std::int64_t kTanMax = (std::int64_t{1} << 18) - 1;
constexpr std::int64_t kNearMax = (std::int64_t{1} << 24) - 1;
}  // namespace manager_raw

enum class VisibilityArith {
  kKernel,  // hls/manager's bit-accurate kernel (the default)
  kDouble,  // its double twin, unquantized
};
const char* visibility_arith_name(VisibilityArith a);  // "kernel", "double"

// The kernel's inputs from the model's doubles; `fits` false when a value was clamped to its format.
struct HostManagerChannel {
  hls::ManagerChannel channel;
  bool fits = true;
};
struct HostManagerObject {
  hls::ManagerObject object;
  bool fits = true;
};
HostManagerChannel host_manager_channel(const ChannelView& view);
HostManagerObject host_manager_object(const glm::dvec3& world_centre, double radius);

struct VisibilityUnitStats {
  std::uint64_t spheres = 0;                // spheres tested
  std::uint64_t spheres_out_of_format = 0;  // kept without a test: beyond the kernel's formats
};

class VisibilityUnit {
 public:
  VisibilityUnit(const ChannelView& view, VisibilityArith arith);
  // V[i] of the sphere (world centre, metres): false only if it is certainly outside the pyramid.
  bool visible(const glm::dvec3& world_centre, double radius, VisibilityUnitStats& stats) const;
  VisibilityArith arith() const { return arith_; }

 private:
  VisibilityArith arith_;
  // The twin's channel, in its row-major form (set once, not per sphere).
  double eye_[3], b_[3][3], tan_half_fov_, near_;
  hls::ManagerChannelSetup setup_;
  bool channel_fits_ = true;
};

}  // namespace cig
