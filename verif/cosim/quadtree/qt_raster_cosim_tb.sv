// Co-simulation wrapper of qt_raster (verification only; not part of the design): every stimulus
// input (frame start, polygon port, pixel back-pressure, configuration port) goes through a
// register, so that no logic of qt_raster depends combinationally on a top-level input except the
// read-out address. Why: Verilator evaluates the logic that depends on top-level inputs on every
// eval() call (its "input combinational" region), and the PEs, the pixel lanes and the mask
// closure all hang off `pixel_stall_i` and `poly_valid_i`; registered, the design is evaluated
// once per clock, after the rising edge, and a cycle costs about half as much.
//
// Timing seen by the testbench: the stimulus of cycle c is applied before the rising edge that
// starts cycle c; after that edge the trace outputs describe cycle c (the design's registers are
// those at the start of cycle c, its inputs the stimulus of cycle c), exactly what qt_raster's
// own ports show in cycle c when driven directly.
//
// The layout and sizes (qt_pkg) are public parameters of the Verilated model (the class
// V<prefix>_qt_raster_cosim_tb), so that the harness takes LIGHT_COVERS from the model and
// cosim.RtlLayout.* checks its C++ field table (record_bits.hpp) against them.
module qt_raster_cosim_tb #(
  parameter int N_LOG2 = qt_pkg::N_LOG2_DEFAULT,
  parameter int TREE_LEVELS = 1,
  localparam int NE /*verilator public*/ = qt_pkg::NE_DEFAULT,
  localparam int NP /*verilator public*/ = qt_pkg::NP_DEFAULT,
  localparam int EW /*verilator public*/ = qt_pkg::EW_DEFAULT,
  localparam int AW /*verilator public*/ = qt_pkg::AW_DEFAULT,
  localparam int PW /*verilator public*/ = qt_pkg::PW_DEFAULT,
  localparam int GW /*verilator public*/ = qt_pkg::GW_DEFAULT,
  localparam int G /*verilator public*/ = qt_pkg::G_DEFAULT,
  localparam int LIGHT_COVERS /*verilator public*/ = qt_pkg::LIGHT_COVERS_DEFAULT,
  localparam int WIN_W /*verilator public*/ = qt_pkg::win_w(NE, NP, EW, AW, PW, GW),
  localparam int PIX_W /*verilator public*/ = qt_pkg::pix_w(NE, NP, EW, AW, PW, GW),
  localparam int MASK_SET_W /*verilator public*/ = qt_pkg::MASK_SET_W,
  localparam int NPE /*verilator public*/ = qt_pkg::npe(N_LOG2, TREE_LEVELS),
  localparam int NPIX /*verilator public*/ = qt_pkg::npix(TREE_LEVELS),
  localparam int NSLOT = qt_pkg::nslot(N_LOG2, TREE_LEVELS)
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  input  logic                            frame_start_i,
  input  logic                            start_window_i,
  input  logic                            poly_valid_i,
  input  logic [WIN_W-1:0]                poly_i,
  output logic                            poly_ready_o,
  input  logic [NPIX-1:0]                 pixel_stall_i,
  input  logic                            cfg_valid_i,
  input  logic [qt_pkg::CFG_TARGET_W-1:0] cfg_target_i,
  input  logic [qt_pkg::CFG_ADDR_W-1:0]   cfg_addr_i,
  input  logic [qt_pkg::CFG_DATA_W-1:0]   cfg_data_i,
  output logic                            busy_o,
  output logic [NPE-1:0]                  pe_load_valid_o,
  output logic [4*NPE-1:0]                pe_load_mask_o,
  output logic [NPE-1:0]                  pe_emit_valid_o,
  output logic [2*NPE-1:0]                pe_emit_child_o,
  output logic [NPE-1:0]                  pe_emit_full_o,
  output logic [NPE*PIX_W-1:0]            pe_emit_data_o,
  output logic [NPIX-1:0]                 px_valid_o,
  output logic [NPIX*PIX_W-1:0]           px_data_o,
  output logic [16*NPIX-1:0]              px_fresh_o,
  output logic [NPIX-1:0]                 px_full_o,
  output logic [NSLOT-1:0]                mask_set_valid_o,
  output logic [NSLOT*MASK_SET_W-1:0]     mask_set_o,
  input  logic [N_LOG2-1:0]               rd_x_i,
  input  logic [N_LOG2-1:0]               rd_y_i,
  output logic [23:0]                     rd_rgb_o
);

  logic                 frame_start_q, start_window_q, poly_valid_q, cfg_valid_q;
  logic [WIN_W-1:0]     poly_q;
  logic [NPIX-1:0]      pixel_stall_q;
  logic [qt_pkg::CFG_TARGET_W-1:0] cfg_target_q;
  logic [qt_pkg::CFG_ADDR_W-1:0]   cfg_addr_q;
  logic [qt_pkg::CFG_DATA_W-1:0]   cfg_data_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      frame_start_q <= 1'b0;
      start_window_q <= 1'b0;
      poly_valid_q  <= 1'b0;
      poly_q        <= '0;
      pixel_stall_q <= '0;
      cfg_valid_q   <= 1'b0;
      cfg_target_q  <= '0;
      cfg_addr_q    <= '0;
      cfg_data_q    <= '0;
    end else begin
      frame_start_q <= frame_start_i;
      start_window_q <= start_window_i;
      poly_valid_q  <= poly_valid_i;
      poly_q        <= poly_i;
      pixel_stall_q <= pixel_stall_i;
      cfg_valid_q   <= cfg_valid_i;
      cfg_target_q  <= cfg_target_i;
      cfg_addr_q    <= cfg_addr_i;
      cfg_data_q    <= cfg_data_i;
    end
  end

  // Every port of the same name passes through (.*); the stimulus goes through the registers.
  qt_raster #(
    .N_LOG2       (N_LOG2),
    .TREE_LEVELS  (TREE_LEVELS),
    .NE(NE), .NP(NP), .EW(EW), .AW(AW), .PW(PW), .GW(GW), .G(G),
    .LIGHT_COVERS (LIGHT_COVERS)
  ) u_raster (
    .frame_start_i (frame_start_q),
    .start_window_i (start_window_q),
    .poly_valid_i  (poly_valid_q),
    .poly_i        (poly_q),
    .pixel_stall_i (pixel_stall_q),
    .cfg_valid_i   (cfg_valid_q),
    .cfg_target_i  (cfg_target_q),
    .cfg_addr_i    (cfg_addr_q),
    .cfg_data_i    (cfg_data_q),
    .*
  );

endmodule
