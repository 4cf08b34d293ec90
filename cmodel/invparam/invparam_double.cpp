#include "invparam/invparam_double.hpp"

#include <algorithm>
#include <limits>

namespace cig {

namespace {

struct ObjectRegisters {
  double tau_in, tau_out;  // RGtin, RGtout
  std::uint32_t hit_pl;    // RGparP
};

// The kernel's plane_step on doubles (T_Pln, clock 4).
void plane_step(const InvparamFaceDouble& face, double value, double eps, ObjectRegisters& r) {
  const bool s = value < 0;
  if (!face.az) {
    if (!(value > eps)) r.tau_in = 0;
  } else if (face.as) {
    if (!s && value > r.tau_out) r.tau_out = value;
  } else if (!s) {
    if (!(value > r.tau_in)) {
      r.tau_in = value;
      r.hit_pl = face.code;
    }
  } else {
    r.tau_in = 0;
  }
}

InvparamSampleDouble sample_step(const InvparamSetupDouble& s, std::vector<double>& running) {
  InvparamSampleDouble out;
  const double kMax = std::numeric_limits<double>::max();
  std::size_t base = 0;
  for (const int m : s.object_faces) {
    ObjectRegisters r{kMax, 0, 0};
    for (std::size_t f = base; f < base + static_cast<std::size_t>(m); ++f) {
      running[f] += s.faces[f].step_y;
      plane_step(s.faces[f], running[f], s.eps, r);
    }
    base += static_cast<std::size_t>(m);
    if (r.tau_in < std::min(kMax, s.tau_near) && r.tau_in > r.tau_out && r.tau_in > out.tau) {
      out.tau = r.tau_in;
      out.code = r.hit_pl;
      out.hit = true;
    }
  }
  return out;
}

}  // namespace

std::vector<InvparamSampleDouble> invparam_double(const InvparamSetupDouble& setup) {
  const int l = setup.size;
  std::vector<InvparamSampleDouble> result(static_cast<std::size_t>(l) * l);
  std::vector<double> column(setup.faces.size()), running;
  for (std::size_t f = 0; f < setup.faces.size(); ++f) column[f] = setup.faces[f].start;
  for (int i = 0; i < l; ++i) {
    if (i > 0)
      for (std::size_t f = 0; f < column.size(); ++f) column[f] += setup.faces[f].step_x;
    running = column;
    for (int j = 0; j < l; ++j) result[static_cast<std::size_t>(j) * l + i] = sample_step(setup, running);
  }
  return result;
}

}  // namespace cig
