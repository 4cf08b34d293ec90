// Operation counts in the units of seed 000's table (SPEC A.7): what the scene manager's counted
// model (studies/operation_counts.hpp) and the priority-tree walk (geometry/geometric_processor.hpp)
// report, so that both add up in one currency.
//
//   R  exchange with the host computer      L  memory read/write
//   C  comparison + conditional jump        A  addition (and subtraction)
//   O  logical instruction                  M  multiplication
//                                           D  division
#pragma once

#include <cstdint>
#include <sstream>
#include <string>

namespace cig {

struct OperationCounts {
  std::uint64_t R = 0, C = 0, O = 0, L = 0, A = 0, M = 0, D = 0;
  OperationCounts& operator+=(const OperationCounts& o) {
    R += o.R;
    C += o.C;
    O += o.O;
    L += o.L;
    A += o.A;
    M += o.M;
    D += o.D;
    return *this;
  }
  std::uint64_t total() const { return R + C + O + L + A + M + D; }
};

inline bool operator==(const OperationCounts& a, const OperationCounts& b) {
  return a.R == b.R && a.C == b.C && a.O == b.O && a.L == b.L && a.A == b.A && a.M == b.M && a.D == b.D;
}
inline bool operator!=(const OperationCounts& a, const OperationCounts& b) { return !(a == b); }

// "R=.. C=.. O=.. L=.. A=.. M=.. D=.."
inline std::string to_string(const OperationCounts& c) {
  std::ostringstream s;
  s << "R=" << c.R << " C=" << c.C << " O=" << c.O << " L=" << c.L << " A=" << c.A << " M=" << c.M << " D=" << c.D;
  return s.str();
}

}  // namespace cig
