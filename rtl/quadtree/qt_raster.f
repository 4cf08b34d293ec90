// qt_raster.f: the quadtree raster processor (SPEC E, seed 004), top module qt_raster, for
// simulators other than the project's own Verilator flow (verif/cosim). The sources in compile
// order (the package first), paths relative to this file; the list is
// rtl/quadtree/qt_sources.cmake's CIG_RTL_SV_NAMES (ctest rtl_filelist.qt_raster checks that they
// agree and lints it). Read it with -F where the tool has it (paths relative to the list), or with
// -f from rtl/quadtree/:
//   verilator --lint-only -Wall -F rtl/quadtree/qt_raster.f --top-module qt_raster -GN_LOG2=9 -GTREE_LEVELS=2
//   vlog -sv -F rtl/quadtree/qt_raster.f; vsim qt_raster -gN_LOG2=9 -gTREE_LEVELS=2        (Questa)
//   vcs -sverilog -F rtl/quadtree/qt_raster.f -top qt_raster -pvalue+qt_raster.N_LOG2=9     (VCS)
//   cd rtl/quadtree && iverilog -g2012 -c qt_raster.f -s qt_raster -Pqt_raster.N_LOG2=9     (Icarus)
// (only Verilator is run here; a top parameter: Verilator -GNAME=V, Questa vsim -gNAME=V,
// VCS -pvalue+qt_raster.NAME=V, Icarus -Pqt_raster.NAME=V).
//
// Parameters of qt_raster (defaults: the fine format at N = 512; rtl/quadtree/README.md
// "Parameters", the limits checked at elaboration):
//   N_LOG2         9     raster of 2^N_LOG2 lines (4..10)
//   TREE_LEVELS    1     levels of the final quadtree of PEs: 1 the pipeline np (9p), 2 with
//                        N_LOG2 = 9 the pipeline-tree 7p2t (1..min(N_LOG2, 5))
//   FIFO_DEPTH     2     records per FIFO between stages (>= 1)
//   NE             8     edges per polygon piece (1..15)
//   NP             2     parameters: I and W = 1/Z (2)
//   EW             32    edge value width d (> AW)
//   AW             22    edge gradient width A, B
//   PW             53    parameter width f, F (>= G + 11)
//   GW             38    parameter gradient width D, E (<= PW)
//   G              16    fractional bits of the parameters
//   LIGHT_COVERS   4096  entries of the light-cover table (1..8191)
//   FOG_CODE_BITS  15    fog table of 2^FOG_CODE_BITS entries (15: the kernel's; fewer only for
//                        synthesis)
qt_pkg.sv
qt_e8m7_code.sv
qt_fifo.sv
qt_mask_memory.sv
qt_pe.sv
qt_pixel_lane.sv
qt_pixel_processor.sv
qt_raster.sv
qt_window_fields.sv
