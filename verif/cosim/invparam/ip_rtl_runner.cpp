// The Verilated configurations of rtl/invparam/ip_array.sv inside its co-simulation wrapper
// (ip_array_cosim_tb.sv; verif/cosim/CMakeLists.txt verilates each with its own prefix, FST
// tracing compiled in) behind one interface (ip_rtl_runner_impl.hpp). Named by the seed's word w
// (64, 57); each model's W is the register width w + 16 (80, 73), which the harness checks.

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "Vip_array_w57_n16.h"
#include "Vip_array_w57_n16_ip_array_cosim_tb.h"
#include "Vip_array_w64_n64.h"
#include "Vip_array_w64_n64_ip_array_cosim_tb.h"
#include "Vip_array_w64_n8.h"
#include "Vip_array_w64_n8_ip_array_cosim_tb.h"
#include "ip_rtl_runner_impl.hpp"
#pragma GCC diagnostic pop

namespace cig::cosim {

using detail::IpRtlImpl;

std::vector<IpRtlConfig> ip_rtl_configs() { return {{64, 8}, {64, 64}, {57, 16}}; }

std::unique_ptr<IpRtl> make_ip_rtl(int w, int n_pp) {
  if (w == 64 && n_pp == 8) return std::make_unique<IpRtlImpl<Vip_array_w64_n8, Vip_array_w64_n8_ip_array_cosim_tb>>();
  if (w == 64 && n_pp == 64)
    return std::make_unique<IpRtlImpl<Vip_array_w64_n64, Vip_array_w64_n64_ip_array_cosim_tb>>();
  if (w == 57 && n_pp == 16)
    return std::make_unique<IpRtlImpl<Vip_array_w57_n16, Vip_array_w57_n16_ip_array_cosim_tb>>();
  return nullptr;
}

}  // namespace cig::cosim
