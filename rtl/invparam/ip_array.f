// ip_array.f: stage F's inverse-parameter systolic array (SPEC F, seed 002), top module ip_array,
// for simulators other than the project's own Verilator flow (verif/cosim). The sources in compile
// order (the package first), paths relative to this file; the list is
// rtl/invparam/ip_sources.cmake's CIG_IP_RTL_SV_NAMES (ctest rtl_filelist.ip_array checks that
// they agree and lints it). Read it with -F where the tool has it (paths relative to the list), or
// with -f from rtl/invparam/:
//   verilator --lint-only -Wall -F rtl/invparam/ip_array.f --top-module ip_array -GW=73 -GN_PP=64
//   vlog -sv -F rtl/invparam/ip_array.f; vsim ip_array -gW=73 -gN_PP=64                  (Questa)
//   vcs -sverilog -F rtl/invparam/ip_array.f -top ip_array -pvalue+ip_array.N_PP=64       (VCS)
//   cd rtl/invparam && iverilog -g2012 -c ip_array.f -s ip_array -Pip_array.N_PP=64       (Icarus)
// (only Verilator is run here; a top parameter: Verilator -GNAME=V, Questa vsim -gNAME=V,
// VCS -pvalue+ip_array.NAME=V, Icarus -Pip_array.NAME=V).
//
// Parameters of ip_array (rtl/invparam/README.md; the limits checked at elaboration):
//   W      80   register bits: the seed's 64-bit word (8 integer bits) plus 16 guard bits (26..128)
//   N_PP   16   pixel processors in the chain, one per sample of a column (1..4096)
ip_pkg.sv
ip_cm.sv
ip_pe.sv
ip_sm.sv
ip_array.sv
