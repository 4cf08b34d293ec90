// Inverse-parameter visibility (seed 002, Fig. 1; SPEC F), bit-accurate: one column of samples.
//
// Per sample (i, j) and per face the PP works on one word (word.hpp, Word<W>: W + 16 bits, 24 of
// them integer with the sign, W - 8 fractional), the face's running value
//     az = 1: tau_ij = Den_ij / Num (= 1/t)      az = 0: Den_ij (Num = 0: the eye lies in the plane)
// with the seed's inward normals (Den > 0: the ray enters the face's half-space). The host gives
// each face's value at column i, row -1 (InvparamColumn: the start, plus step_x once per column,
// invparam_first_column / invparam_next_column); each row adds step_y (the PP's RGh), exactly as the
// seed's chain of PPs does, so the value at row j is start + i step_x + (j + 1) step_y on word
// codes: no rounding in the kernel, only the setup's (cmodel/invparam/face_setup.hpp states the error bound).
//
// The per-face rule is Fig. 1 as the PP computes it (seed chapter 4, token T_Pln, clock 4), on the
// sign of Num (As) and of tau (flag s) instead of the sign of Den (the same cases, Den = tau Num):
//   az = 0:               Den > RGeps (eps < 0, a tolerance)   else tau_in = 0 (the ray misses)
//   az = 1, As = 1, s = 0: exit face:   tau > tau_out          => tau_out = tau
//   az = 1, As = 0, s = 0: entry face:  tau <= tau_in          => tau_in = tau, hit_pl = face
//   az = 1, As = 0, s = 1: moving away from a face the eye is outside of: tau_in = 0 (miss)
//   az = 1, As = 1, s = 1: nothing (moving away from a face the eye is inside of)
// (Fig. 1's "tau > 0 and tau < tau_in" for an entry face differs in two corner cases only: the PP
// takes a later face of equal tau, and a zero tau (a ray parallel to a face the eye is outside of)
// sets tau_in = 0, a miss, which is right.) Per object (token T_Obj): the object is hit iff its
// last entry lies beyond the near plane (tau_in < RGnear = 1/near: an entry face was seen, and what
// the near plane cuts away is not drawn, so what lies behind shows, as in the engines that clip
// polygons; RGnear = MAX without a near plane: the seed's test tau_in < MAX), tau_in > tau_out, and
// it is nearer than the nearest so far:
// tau_in > tau_hit (RGobj); the first object wins a tie. tau_out and tau_hit start at 0 (Fig. 1:
// t = infinity), tau_in at MAX.
#pragma once

#include "hls/formatter/sample_lattice.hpp"
#include "hls/invparam/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Capacities (static loop bounds): objects per frame, faces per object (the seed's n and m), faces
// in all, samples per column (a PP per sample: the largest lattice's rows).
constexpr int kMaxObjects = 64;
constexpr int kMaxFacesPerObject = 32;
constexpr int kMaxFaces = 1024;
constexpr int kMaxSamplesPerColumn = kMaxLatticeSize;

// The host's face list: objects in order, each its faces in order (face f of the list is the
// k-th face of its object).
template <int W>
struct InvparamFaces {
  FaceSetup<W> face[kMaxFaces];
  int object_faces[kMaxObjects] = {};  // m of each object, 1..kMaxFacesPerObject
  int objects = 0;                     // n, 0..kMaxObjects
};

// Every face's value at one column, row -1 (tau_{i,-1} or Den_{i,-1}): what the host feeds the
// top PP of the column.
template <int W>
struct InvparamColumn {
  Word<W> value[kMaxFaces];
};

// One sample's result (the VT bus): the visible face's code (RGpar) and its tau (RGobj).
template <int W>
struct InvparamSample {
  bool hit = false;  // false: no object (the background)
  UInt<24> code;     // the visible face's colour or id code
  Word<W> tau;       // its tau = 1/t (0 when no hit)
};

// Column 0: every face's start value.
template <int W>
void invparam_first_column(const InvparamFaces<W>& faces, InvparamColumn<W>& column) {
  for (int f = 0; f < kMaxFaces; ++f) column.value[f] = faces.face[f].start;
}
// The next column: one W-bit add of step_x per face (the host's adder).
template <int W>
void invparam_next_column(const InvparamFaces<W>& faces, InvparamColumn<W>& column) {
  for (int f = 0; f < kMaxFaces; ++f) column.value[f] = word_add(column.value[f], faces.face[f].step_x);
}

namespace invparam_detail {

// The registers one PP keeps while the tokens of one object pass.
template <int W>
struct ObjectRegisters {
  Word<W> tau_in;   // RGtin: min tau of the entry faces (the last entry, the largest t)
  Word<W> tau_out;  // RGtout: max tau of the exit faces (the first exit, the smallest t)
  UInt<24> hit_pl;  // RGparP: the code of tau_in's face
};

// T_Pln, clock 4: one face's value at this sample against the object's registers.
template <int W>
void plane_step(const FaceSetup<W>& face, const Word<W>& value, const Word<W>& eps, ObjectRegisters<W>& r) {
  const bool s = word_negative(value);
  if (!face.az) {
    if (!word_greater(value, eps)) r.tau_in = Word<W>(0);  // Den <= eps: the ray leaves the plane's inside
  } else if (face.as) {
    if (!s && word_greater(value, r.tau_out)) r.tau_out = value;  // exit face
  } else if (!s) {
    if (!word_greater(value, r.tau_in)) {  // entry face, tau <= tau_in
      r.tau_in = value;
      r.hit_pl = face.colour;
    }
  } else {
    r.tau_in = Word<W>(0);  // outside this face's half-space and moving away: a miss
  }
}

// One sample (row): every object's faces in order, the running values advanced by step_y.
template <int W>
InvparamSample<W> sample_step(const InvparamFaces<W>& faces, Word<W> running[kMaxFaces], const Word<W>& eps,
                              const Word<W>& tau_near) {
  InvparamSample<W> out;  // tau_hit = 0, no hit
  int base = 0;
  for (int o = 0; o < kMaxObjects; ++o) {
    if (o >= faces.objects) break;
    ObjectRegisters<W> r;
    r.tau_in = word_max<W>();
    r.tau_out = Word<W>(0);
    for (int k = 0; k < kMaxFacesPerObject; ++k) {
      if (k >= faces.object_faces[o]) break;
      const int f = base + k;
      running[f] = word_add(running[f], faces.face[f].step_y);  // SM: RGres = Input + RGh
      plane_step(faces.face[f], running[f], eps, r);
    }
    base += faces.object_faces[o];
    // T_Obj: the last entry beyond the near plane, the entry before the exit, nearer than the nearest so far.
    if (word_greater(tau_near, r.tau_in) && word_greater(r.tau_in, r.tau_out) && word_greater(r.tau_in, out.tau)) {
      out.tau = r.tau_in;
      out.code = r.hit_pl;
      out.hit = true;
    }
  }
  return out;
}

}  // namespace invparam_detail

// One column of `rows` samples (rows <= kMaxSamplesPerColumn), top to bottom: out[j] is sample row
// j's visible face. eps is RGeps (a negative tolerance for the az = 0 faces' Den), tau_near RGnear
// (1/near, or word_max without a near plane).
template <int W>
void invparam_column(const InvparamFaces<W>& faces, const InvparamColumn<W>& column, int rows, const Word<W>& eps,
                     const Word<W>& tau_near, InvparamSample<W> out[kMaxSamplesPerColumn]) {
  Word<W> running[kMaxFaces];  // each face's value at the row above (the token from the PP above)
  for (int f = 0; f < kMaxFaces; ++f) running[f] = column.value[f];
  for (int j = 0; j < kMaxSamplesPerColumn; ++j) {
    if (j >= rows) break;
    out[j] = invparam_detail::sample_step(faces, running, eps, tau_near);
  }
}

// The HLS top in the default word: W = 64 (the seed's "64 bits to 100 km"; an 80-bit register).
constexpr int kDefaultWordBits = 64;
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_invparam_column_top(PORT, ARRAY, RESULT)         \
  RESULT(void)                                                         \
  PORT(faces, in, ap_memory, const InvparamFaces<kDefaultWordBits>&)   \
  PORT(column, in, ap_memory, const InvparamColumn<kDefaultWordBits>&) \
  PORT(rows, in, ap_none, int)                                         \
  PORT(eps, in, ap_none, const Word<kDefaultWordBits>&)                \
  PORT(tau_near, in, ap_none, const Word<kDefaultWordBits>&)           \
  ARRAY(out, out, ap_memory, InvparamSample<kDefaultWordBits>, kMaxSamplesPerColumn)
inline CIG_HLS_TOP(invparam_column_top) { invparam_column<kDefaultWordBits>(faces, column, rows, eps, tau_near, out); }

CIG_HLS_END_NAMESPACE
