// The runner of the mutation test's Verilated stage F arrays (CMakeLists.txt here,
// build_models.sh): the co-simulation's IpRtlImpl (verif/cosim/invparam/ip_rtl_runner_impl.hpp)
// over the configurations of the mutated copy of rtl/invparam/ip_*.sv that this build has,
// (W, N_PP) = (64, 8), (57, 16) and / or (64, 64) (W the seed's word; the models' W is the
// register width W + 16), without FST tracing. A configuration the mutant does not name is absent:
// ip_rtl_configs() leaves it out, make_ip_rtl gives nullptr and test_ip_cosim.cpp skips it
// (CIG_COSIM_SOME_CONFIGS).

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#if __has_include("Vip_array_w64_n8.h")
#include "Vip_array_w64_n8.h"
#include "Vip_array_w64_n8_ip_array_cosim_tb.h"
#define CIG_MUTANT_W64N8 1
#endif
#if __has_include("Vip_array_w57_n16.h")
#include "Vip_array_w57_n16.h"
#include "Vip_array_w57_n16_ip_array_cosim_tb.h"
#define CIG_MUTANT_W57N16 1
#endif
#if __has_include("Vip_array_w64_n64.h")
#include "Vip_array_w64_n64.h"
#include "Vip_array_w64_n64_ip_array_cosim_tb.h"
#define CIG_MUTANT_W64N64 1
#endif
#include "invparam/ip_rtl_runner_impl.hpp"
#pragma GCC diagnostic pop

namespace cig::cosim {
namespace {

using detail::IpRtlImpl;

template <class Top, class Tb>
std::unique_ptr<IpRtl> make_config() {
  return std::make_unique<IpRtlImpl<Top, Tb, false>>();
}

// The configurations this build has, one table for both functions below; the last entry (no
// maker) keeps the table non-empty.
struct Built {
  IpRtlConfig cfg;
  std::unique_ptr<IpRtl> (*make)();
};
const Built kBuilt[] = {
#ifdef CIG_MUTANT_W64N8
    {{64, 8}, make_config<Vip_array_w64_n8, Vip_array_w64_n8_ip_array_cosim_tb>},
#endif
#ifdef CIG_MUTANT_W64N64
    {{64, 64}, make_config<Vip_array_w64_n64, Vip_array_w64_n64_ip_array_cosim_tb>},
#endif
#ifdef CIG_MUTANT_W57N16
    {{57, 16}, make_config<Vip_array_w57_n16, Vip_array_w57_n16_ip_array_cosim_tb>},
#endif
    {{0, 0}, nullptr}};

}  // namespace

std::vector<IpRtlConfig> ip_rtl_configs() {
  std::vector<IpRtlConfig> c;
  for (const Built& b : kBuilt)
    if (b.make) c.push_back(b.cfg);
  return c;
}

std::unique_ptr<IpRtl> make_ip_rtl(int w, int n_pp) {
  for (const Built& b : kBuilt)
    if (b.make && b.cfg.w == w && b.cfg.n_pp == n_pp) return b.make();
  return nullptr;
}

}  // namespace cig::cosim
