// hls-subset-helper: the token codes and word fields the PP (pixel_processor.hpp) and the host's
// stream builder (cmodel/invparam/) share; no kernel of its own.
//
// The token stream of seed 002's systolic array (SPEC F; digest: notes/seed002_digest.md). The
// Input bus carries one W-bit word per clock; a token is 4 words (T_Pln, T_Obj, T_Col) or 1 word
// (the empty code). Word 1 of every token carries its 5-bit command in the word's top 5 bits
// (bits word_bits(W)-1 .. word_bits(W)-5), the rest zero:
//
//   bit   4 3   kind: 00 Empty, 01 Col, 10 Obj, 11 Pln
//         2     reserved, 0
//         1     Pln: Az (Num != 0: the PP works on tau; 0: on Den)       Col: 0
//         0     Pln: As (Num < 0)                                        Col: First (see below)
//
//   T_Pln  word 2: step_y (k_y' if Az, else k_y); word 3: tau or Den from the PP above (for the
//          first PP the host's column value start + i step_x); word 4: the colour or id code
//          (24 bits, the word's low bits).
//   T_Col  word 2: the background code for the NEXT column (low 24 bits); words 3, 4: zero.
//          First = 1 marks the frame's initialising T_Col (seed: "at the start every PP is
//          initialised by a T_Col"): it initialises like any T_Col but puts nothing on VT, since
//          there is no previous column and its VT slot would collide with column 0's when
//          N_K < N_n.
//   T_Obj  word 1 only carries meaning; words 2-4 zero.
//   Empty  one code, the all-zero word: an idle bus (every register reset to 0) reads as a stream
//          of empty codes. The seed's "empty tokens" that pad a column are groups of 4 empty codes.
//
// The Ctrl bus (seed: "synchronisation of the PPs by signals passed between PPs on Ctrl") carries
// two lines here, travelling with the word (one clock per PP): start, the word on Input is word 1
// of a token (it restarts the PP's clock-within-token counter); valid, there is a word at all. An
// invalid word (a bubble: the host had nothing to send) changes no register but the PP's delayed
// valid line, so a bubble may fall anywhere, even inside a token, and moves down the chain at one
// PP per clock like a word; the seed's stream is the case of no bubbles.
//
// Word fields are read and written only with word.hpp's operations (Word<W> may become a wider
// type): x + x is a left shift by one and the sign flag s reads the top bit, so the command field
// is 5 x (read s, double) and the code field word_bits(W) - 24 doublings then 24 x (read s, double). These
// are wiring in hardware; an HLS tool folds the chain of constant shifts.
#pragma once

#include "hls/invparam/word.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kCommandBits = 5;
constexpr int kParBits = 24;  // RGpar, RGparP: colour or id code
using Command = UInt<kCommandBits>;
using ParCode = UInt<kParBits>;

constexpr unsigned kKindEmpty = 0, kKindCol = 1, kKindObj = 2, kKindPln = 3;
constexpr unsigned kCmdEmpty = 0x00, kCmdCol = 0x08, kCmdObj = 0x10, kCmdPln = 0x18;
constexpr unsigned kCmdAz = 0x02, kCmdAs = 0x01, kCmdFirst = 0x01;

struct PpCtrl {
  bool start = false;  // word 1 of a token is on Input
  bool valid = true;   // a word is on Input (false: a bubble)
};

CIG_HLS_INLINE unsigned command_kind(const Command& c) { return unsigned(c.value() >> 3); }
CIG_HLS_INLINE bool command_az(const Command& c) { return c.bit(1); }
CIG_HLS_INLINE bool command_as(const Command& c) { return c.bit(0); }
CIG_HLS_INLINE bool command_first(const Command& c) { return c.bit(0); }

CIG_HLS_INLINE Command pln_command(bool az, bool as) {
  return Command(kCmdPln | (az ? kCmdAz : 0u) | (as ? kCmdAs : 0u));
}

// The word 0...0 (built from the largest and smallest codes: min + min wraps to 0).
template <int W>
CIG_HLS_INLINE Word<W> word_zero() {
  return word_add(word_min<W>(), word_min<W>());
}

// The word whose low `NB` bits are `code` (Horner: x = 2x + bit), the rest zero.
template <int W, int NB>
CIG_HLS_INLINE Word<W> word_of_low_bits(const UInt<NB>& code) {
  static_assert(NB < word_bits(W), "the field must leave the sign bit free");
  const Word<W> one(1);
  Word<W> x = word_zero<W>();
  for (int k = NB - 1; k >= 0; --k) {
    x = word_add(x, x);
    if (code.bit(k)) x = word_add(x, one);
  }
  return x;
}

// The top `NB` bits of w, read as the sign flag after 0 .. NB-1 doublings.
template <int NB, int W>
CIG_HLS_INLINE UInt<NB> word_top_bits(Word<W> w) {
  UInt<NB> code;
  for (int k = NB - 1; k >= 0; --k) {
    code = code.with_bit(k, word_negative(w));
    w = word_add(w, w);
  }
  return code;
}

// The low `NB` bits of w: shift them to the top (W - NB doublings), then read them.
template <int NB, int W>
CIG_HLS_INLINE UInt<NB> word_low_bits(Word<W> w) {
  constexpr int kBits = word_bits(W);
  for (int k = 0; k < kBits - NB; ++k) w = word_add(w, w);
  return word_top_bits<NB, W>(w);
}

// Word 1 of a token: the command in the top 5 bits.
template <int W>
CIG_HLS_INLINE Word<W> command_word(const Command& c) {
  constexpr int kBits = word_bits(W);
  Word<W> x = word_of_low_bits<W, kCommandBits>(c);
  for (int k = 0; k < kBits - kCommandBits; ++k) x = word_add(x, x);
  return x;
}

template <int W>
CIG_HLS_INLINE Command word_command(const Word<W>& w) {
  return word_top_bits<kCommandBits, W>(w);
}

// A colour / id code word (T_Pln word 4, T_Col word 2) and back.
template <int W>
CIG_HLS_INLINE Word<W> par_word(const ParCode& code) {
  return word_of_low_bits<W, kParBits>(code);
}
template <int W>
CIG_HLS_INLINE ParCode word_par(const Word<W>& w) {
  return word_low_bits<kParBits, W>(w);
}

CIG_HLS_END_NAMESPACE
