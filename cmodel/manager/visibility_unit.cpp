#include "manager/visibility_unit.hpp"

#include <cmath>

#include "hls/manager/channel_setup.hpp"
#include "hls/manager/visibility.hpp"
#include "manager/visibility_twin.hpp"

namespace cig {

namespace {

using namespace manager_raw;

// v (already rounded to an integer) clamped to [lo, hi]; `fits` cleared when it was not in range.
std::int64_t clamp_raw(double v, std::int64_t lo, std::int64_t hi, bool& fits) {
  if (!(v >= double(lo) && v <= double(hi))) fits = false;
  return v < double(lo) ? lo : v > double(hi) ? hi : std::int64_t(v);
}

hls::WorldCoord world_coord(double metres, bool& fits) {
  return hls::WorldCoord::from_raw_value(clamp_raw(std::nearbyint(metres / kU), kWorldMin, kWorldMax, fits));
}

}  // namespace

const char* visibility_arith_name(VisibilityArith a) { return a == VisibilityArith::kKernel ? "kernel" : "double"; }

HostManagerChannel host_manager_channel(const ChannelView& v) {
  HostManagerChannel h;
  for (int i = 0; i < 3; ++i) {
    h.channel.eye[i] = world_coord(v.eye[i], h.fits);
    // glm is column-major: row i (eye axis) of B, column j (world axis) is world_to_eye[j][i].
    for (int j = 0; j < 3; ++j)
      h.channel.b[i][j] = hls::RotationEntry::from_raw_value(
          clamp_raw(std::nearbyint(v.world_to_eye[j][i] * double(kOne)), kRotMin, kRotMax, h.fits));
  }
  h.channel.tan_half_fov = hls::TanHalfFov::from_raw_value(
      std::uint64_t(clamp_raw(std::ceil(v.tan_half_fov * double(kOne)), 0, kTanMax, h.fits)));
  h.channel.near =
      hls::NearDistance::from_raw_value(std::uint64_t(clamp_raw(std::floor(v.near / kU), 0, kNearMax, h.fits)));
  return h;
}

HostManagerObject host_manager_object(const glm::dvec3& centre, double radius) {
  HostManagerObject h;
  for (int i = 0; i < 3; ++i) h.object.centre[i] = world_coord(centre[i], h.fits);
  h.object.radius =
      hls::WorldRadius::from_raw_value(std::uint64_t(clamp_raw(std::ceil(radius / kU), 0, kRadiusMax, h.fits)));
  return h;
}

VisibilityUnit::VisibilityUnit(const ChannelView& view, VisibilityArith arith)
    : arith_(arith), tan_half_fov_(view.tan_half_fov), near_(view.near) {
  for (int i = 0; i < 3; ++i) {
    eye_[i] = view.eye[i];
    // glm is column-major: row i (eye axis) of B, column j (world axis) is world_to_eye[j][i].
    for (int j = 0; j < 3; ++j) b_[i][j] = view.world_to_eye[j][i];
  }
  const HostManagerChannel h = host_manager_channel(view);
  channel_fits_ = h.fits;
  hls::manager_channel_setup_top(h.channel, setup_);
}

bool VisibilityUnit::visible(const glm::dvec3& centre, double radius, VisibilityUnitStats& stats) const {
  ++stats.spheres;
  if (arith_ == VisibilityArith::kDouble) {
    const double c[3] = {centre.x, centre.y, centre.z};
    return manager_visibility_twin(eye_, b_, tan_half_fov_, near_, c, radius).visible;
  }
  const HostManagerObject h = host_manager_object(centre, radius);
  if (!channel_fits_ || !h.fits) {
    ++stats.spheres_out_of_format;
    return true;
  }
  hls::ManagerVisibility out;
  hls::manager_visibility_top(setup_, h.object, out);
  return out.visible;
}

}  // namespace cig
