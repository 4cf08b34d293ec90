// Golden vectors of stage A's preliminary processing unit (hls/manager/): manager_channel_setup_top
// and manager_visibility_top. The inputs are the C model's: the channels of scenes/airfield.json
// (ChannelView: the observer's eye, the rotation B, tan(fov/2), near) and its objects' and
// subobjects' bounding spheres (WorldDatabase), converted into the kernel's formats with the
// host's roundings (hls/manager/records.hpp: positions and B to nearest, radii and t up, near
// down), every visibility vector's setup made by manager_channel_setup_top; and hand-made corners
// (spheres tangent to each plane and 1 LSB, 7 LSB and 1 m beyond it, behind the eye, at the eye,
// radii and positions at the formats' ends, a B that is not a rotation, t = 0 and t at its largest).
// The writer checks that the vectors reach every plane's cull and both flags.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/manager/channel_setup.hpp"
#include "hls/manager/visibility.hpp"
#include "manager/channel_view.hpp"
#include "manager/visibility_unit.hpp"
#include "scene/scene_loader.hpp"
#include "scene/world_database.hpp"
#include "tb/manager_channel_setup_top.hpp"
#include "tb/manager_visibility_top.hpp"
#include "vector_file.hpp"

namespace cig::hls_tb {
namespace {

// The host's conversions (cmodel/manager/visibility_unit.hpp, the data path's): positions and B to
// nearest, radius and t up, near down, clamped to the formats (the corners below reach the ends).
using namespace manager_raw;  // the formats' raw ends, for the hand-made corners
hls::ManagerChannel channel_of(const ChannelView& v) { return host_manager_channel(v).channel; }
hls::ManagerObject sphere(const glm::dvec3& centre, double r) { return host_manager_object(centre, r).object; }

// A hand-made channel: eye at `eye` (raw, every axis), B = b_raw on the diagonal and off_raw off it,
// t and near raw.
hls::ManagerChannel corner_channel(std::int64_t eye, std::int64_t b_raw, std::int64_t off_raw, std::int64_t t,
                                   std::int64_t near) {
  hls::ManagerChannel ch;
  for (int i = 0; i < 3; ++i) {
    ch.eye[i] = hls::WorldCoord::from_raw_value(eye);
    for (int j = 0; j < 3; ++j) ch.b[i][j] = hls::RotationEntry::from_raw_value(i == j ? b_raw : off_raw);
  }
  ch.tan_half_fov = hls::TanHalfFov::from_raw_value(std::uint64_t(t));
  ch.near = hls::NearDistance::from_raw_value(std::uint64_t(near));
  return ch;
}

hls::ManagerChannelSetup setup_of(const hls::ManagerChannel& ch) {
  hls::ManagerChannelSetup s;
  hls::manager_channel_setup_top(ch, s);
  return s;
}

void write_channel_setup(const std::string& dir, const Scene& scene) {
  VectorFile<ManagerChannelSetupTopCase> file(
      dir, "the channels of scenes/airfield.json at frames 0, 75, 149; t = 0, 3/4 (a square), 1, the largest, random");
  ManagerChannelSetupTopCase::Input in;
  for (int frame : {0, 75, 149})
    for (int c = 0; c < int(scene.channels.size()); ++c) {
      in.in = channel_of(make_channel_view(scene, frame, c));
      file.add(in);
    }
  std::mt19937_64 rng(20261127);
  std::vector<std::int64_t> ts = {0, 1, 3 * kOne / 4, kOne, 2 * kOne, kTanMax - 1, kTanMax};
  for (int k = 0; k < 8; ++k) ts.push_back(std::int64_t(rng() % std::uint64_t(kTanMax + 1)));
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const bool low = k % 2 == 0;
    in.in = corner_channel(low ? kWorldMin : kWorldMax, low ? kRotMin : kRotMax, low ? kRotMax : kRotMin, ts[k],
                           low ? 0 : kNearMax);
    file.add(in);
  }
}

// Spheres against B = I, t = 3/4 (s = 5/4 exact), near 1 m: tangent to each plane (centre 8 m ahead,
// radius 4 m: r s = 5 m, t z = 6 m) and 0, 1 u, 7 u (past the widening) and 1 m beyond it.
std::vector<hls::ManagerObject> tangent_spheres() {
  std::vector<hls::ManagerObject> out;
  const glm::dvec3 outward[4] = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};  // left, right, top, bottom
  for (double beyond : {0.0, kU, 7 * kU, 1.0}) {
    for (const glm::dvec3& n : outward) out.push_back(sphere(glm::dvec3(0, 0, 8) + (11 + beyond) * n, 4));
    out.push_back(sphere({0, 0, -3 - beyond}, 4));  // near: z + r = near
  }
  return out;
}

struct Coverage {
  int visible = 0, culled = 0, several = 0;
  unsigned planes = 0;
  void count(const hls::ManagerVisibility& v) {
    const unsigned bits = unsigned(v.outside.value());
    (v.visible ? visible : culled) += 1;
    several += (bits & (bits - 1)) != 0 ? 1 : 0;
    planes |= bits;
  }
  void require() const {
    if (visible == 0 || culled == 0 || several == 0 || planes != 0x1f)
      throw std::runtime_error("manager_visibility_top vectors: not every plane's cull, or not both flags");
  }
};

void write_scene_spheres(VectorFile<ManagerVisibilityTopCase>& file, const Scene& scene, const WorldDatabase& db,
                         Coverage& coverage) {
  ManagerVisibilityTopCase::Input in;
  struct Pick {
    int frame, channel, every;
    bool subobjects;
  };
  for (const Pick& p : {Pick{0, 0, 9, false}, Pick{0, 1, 9, false}, Pick{0, 2, 9, false}, Pick{149, 1, 11, true}}) {
    in.setup = setup_of(channel_of(make_channel_view(scene, p.frame, p.channel)));
    for (std::size_t k = std::size_t(p.channel); k < db.objects.size(); k += std::size_t(p.every)) {
      const WorldObject& o = db.objects[k];
      in.obj = sphere(o.centre, o.radius);
      coverage.count(file.add(in).out);
      if (p.subobjects && k % 2 == 0)
        for (const WorldSubobject& s : o.subobjects) {
          in.obj = sphere(s.centre, s.radius);
          coverage.count(file.add(in).out);
        }
    }
  }
}

void write_corner_spheres(VectorFile<ManagerVisibilityTopCase>& file, Coverage& coverage) {
  ManagerVisibilityTopCase::Input in;
  in.setup = setup_of(corner_channel(0, kOne, 0, 3 * kOne / 4, 2048));
  for (const hls::ManagerObject& o : tangent_spheres()) {
    in.obj = o;
    coverage.count(file.add(in).out);
  }
  const hls::ManagerObject corners[] = {sphere({0, 0, -100}, 50),      // behind the eye
                                        sphere({0, 0, 0}, 0),          // at the eye, no radius
                                        sphere({0, 0, 0}, 0.5),        // around the eye, short of near
                                        sphere({0, 0, -1000e3}, 3e6),  // the largest radius, behind
                                        sphere({5e5, -5e5, 2e5}, 1e-4)};
  for (const hls::ManagerObject& o : corners) {
    in.obj = o;
    coverage.count(file.add(in).out);
  }
  // The formats' ends: eye and centre at opposite corners of the world, B not a rotation.
  for (const std::int64_t b : {kRotMin, kRotMax}) {
    in.setup = setup_of(corner_channel(kWorldMin, b, b == kRotMin ? kRotMax : kRotMin, kTanMax, kNearMax));
    for (const std::int64_t r : {std::int64_t{0}, kRadiusMax}) {
      for (int i = 0; i < 3; ++i) in.obj.centre[i] = hls::WorldCoord::from_raw_value(kWorldMax);
      in.obj.radius = hls::WorldRadius::from_raw_value(std::uint64_t(r));
      coverage.count(file.add(in).out);
    }
  }
  // t = 0: the pyramid is the z axis.
  in.setup = setup_of(corner_channel(0, kOne, 0, 0, 2048));
  for (const double x : {0.0, 0.5, 2.0}) {
    in.obj = sphere({x, 0, 100}, 1);
    coverage.count(file.add(in).out);
  }
}

void write_visibility(const std::string& dir, const Scene& scene, const WorldDatabase& db) {
  VectorFile<ManagerVisibilityTopCase> file(dir,
                                            "objects and subobjects of scenes/airfield.json through its channels at "
                                            "frames 0 and 149, tangent spheres, the formats' ends");
  Coverage coverage;
  write_scene_spheres(file, scene, db, coverage);
  write_corner_spheres(file, coverage);
  coverage.require();
}

}  // namespace

void write_manager_vectors(const std::string& dir, const std::string& scenes) {
  const Scene scene = load_scene(scenes + "/airfield.json");
  const WorldDatabase db = build_world_database(scene);
  write_channel_setup(dir, scene);
  write_visibility(dir, scene, db);
}

}  // namespace cig::hls_tb
