// The double twin of the preliminary processing unit (hls/manager/visibility.hpp): the same
// algorithm with no quantization. c_eye = B (c - eye); the sphere is outside the near plane iff
// z + r < near, outside a side plane iff n . c_eye + r sqrt(1 + t^2) < 0 with n . c_eye one of
// x + t z (left), t z - x (right), t z - y (top), t z + y (bottom): the C model's cull
// (sphere_may_be_visible against ViewPyramid, manager/scene_manager.hpp) written plane by plane as
// the kernel computes it, without the kernel's floor of c_eye, its widening of r or its rounding up
// of sqrt(1 + t^2). The kernel test (verif/kernels/test_manager_kernel.cpp) compares the two.
#pragma once

#include <cmath>

namespace cig {

struct VisibilityTwinResult {
  bool visible = true;
  unsigned outside = 0;  // bit k: wholly outside plane k (near, left, right, top, bottom)
  double centre_eye[3] = {0, 0, 0};
  double plane_value[5] = {0, 0, 0, 0, 0};  // outside iff negative
};

// eye, centre: world (metres); b: world to eye, rows x right, y up, z forward; t = tan(fov / 2).
inline VisibilityTwinResult manager_visibility_twin(const double (&eye)[3], const double (&b)[3][3], double t,
                                                    double near, const double (&centre)[3], double radius) {
  VisibilityTwinResult out;
  const double d[3] = {centre[0] - eye[0], centre[1] - eye[1], centre[2] - eye[2]};
  for (int i = 0; i < 3; ++i) out.centre_eye[i] = b[i][0] * d[0] + b[i][1] * d[1] + b[i][2] * d[2];
  const double x = out.centre_eye[0], y = out.centre_eye[1], z = out.centre_eye[2];
  const double tz = t * z, rs = radius * std::sqrt(1 + t * t);
  out.plane_value[0] = z + radius - near;
  out.plane_value[1] = x + tz + rs;
  out.plane_value[2] = tz - x + rs;
  out.plane_value[3] = tz - y + rs;
  out.plane_value[4] = tz + y + rs;
  for (int k = 0; k < 5; ++k)
    if (out.plane_value[k] < 0) out.outside |= 1u << k;
  out.visible = out.outside == 0;
  return out;
}

}  // namespace cig
