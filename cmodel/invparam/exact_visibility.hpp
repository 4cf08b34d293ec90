// The ground truth of stage F's visibility, sharing no code with the kernel, its twin or the setup:
// per sample, the nearest face the ray enters whose entry point lies inside every other face plane
// of its polyhedron (a direct point-in-polyhedron test, not the tau_in/tau_out bookkeeping) and
// beyond the frame's near plane (an entry point nearer than it is cut away: the object is not drawn
// there, what lies behind shows).
//
// Arithmetic: binary128 (__float128) from the frame's doubles. c = (Xs T, Ys T, 1) is exact (a
// double times a dyadic of <= 14 bits); every later quantity (n.c, t = d/(n.c), the residual
// r_g = t n_g.c - d_g of the entry point against plane g) takes at most 8 roundings of relative
// error 2^-113, so |error| <= 2^-100 (|t| sum_k |n_gk c_k| + |d_g|) and, for tau = n.c/d,
// <= 2^-100 (sum_k |n_k c_k|)/|d|: kFloatMargin below, far under any tolerance a W <= 72 kernel
// needs. Within those margins the answer is exact.
//
// Uncertainty. The method under test sees tau = 1/t = n.c/d (or n.c when d = 0) with an error of
// at most margins.tau (resp. margins.den: RGeps's magnitude plus the Den error). A decision it can
// get wrong within that is flagged: the residual against plane g corresponds to
// tau_g - tau_f = r_g tau_f / d_g, so an entry point within 2 margins.tau |d_g| t of plane g
// (d_g != 0), or with |n_g.c| <= margins.den (d_g = 0) is borderline; so is an entry face with
// tau <= margins.tau (near t = infinity) or within 2 margins.tau of 1/near; the sample is `uncertain` when a borderline candidate
// could be at least as near as the answer, or two valid candidates' tau lie within 2 margins.tau.
#pragma once

#include <cstdint>
#include <vector>

#include "frame/screen_frame.hpp"

namespace cig {

struct ExactMargins {
  double tau = 0;  // the tolerance on tau = n.c/d of the method compared (1/m)
  double den = 0;  // on n.c of the faces through the eye (d = 0)
};

struct ExactSample {
  bool hit = false;
  int polyhedron = -1, face = -1;  // the visible face
  std::uint32_t code = 0;          // its index in the list of every face of every polyhedron, in order
  double t = 0, tau = 0;           // its depth (eye depth Z) and 1/t
  __float128 tau_exact = 0;        // 1/t to 2^-100 (relative), for comparisons finer than a double
  bool uncertain = false;
};

// Sample column i, row j of an L x L lattice (Xs_k = Ys_k = (2k + 1)/L - 1).
ExactSample exact_visibility_sample(const ScreenFrame& frame, int size, int i, int j, const ExactMargins& margins);

}  // namespace cig
