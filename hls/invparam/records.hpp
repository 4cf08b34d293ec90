// Records of stage F (seed 002, the inverse-parameter visibility processor; SPEC F).
//
// FaceSetup is what the host's preliminary computation (seed 002, Fig. 1: "tau_00, Den_00, Num,
// k_x, k_y, k_x', k_y' for each face of each object") gives the array for one face, already in
// the PP's word format (hls/invparam/word.hpp). The sample at column i (left to right), row j (top
// to bottom, 0-based) of the sample lattice sees
//     az = 1:  tau_ij = start + i step_x + (j + 1) step_y     tau = 1/t = Den/Num, step = k'
//     az = 0:  Den_ij = start + i step_x + (j + 1) step_y     the eye lies in the face's plane
// computed incrementally: the host adds step_x once per column (tau_{i,-1}), each PP of the column
// adds step_y to what the PP above passed on (RGh holds step_y).
#pragma once

#include "hls/invparam/word.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <int W>
struct FaceSetup {
  bool az = true;   // the seed's Az: Num != 0 (the PP works on tau); 0: on Den
  bool as = false;  // the seed's As: Num < 0
  Word<W> start;    // tau or Den at column 0, row -1
  Word<W> step_x;   // k_x' or k_x: one column to the right
  Word<W> step_y;   // k_y' or k_y: one row down
  UInt<24> colour;  // the face's colour or id code (RGparP, then RGpar)
};

CIG_HLS_END_NAMESPACE
