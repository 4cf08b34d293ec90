// Recursive-subdivision raster processor (SPEC E, seed 004): the pipeline-tree architecture
// `kp(n-k)t` of eq. 1 with k = PIPE_LEVELS = N_LOG2 - TREE_LEVELS pipeline PEs (levels 1..k, one
// per level) and a TREE_LEVELS-level quadtree of PEs (1, 4, 16, ... PEs; PE m of a depth routes
// child q to PE 4 m + q of the next depth), one pixel processor per leaf PE, the priority-mask
// memory, the configuration port and the trace ports of the co-simulation.
// TREE_LEVELS = 1 is the pipeline `np`; N_LOG2 = 9, TREE_LEVELS = 2 is `7p2t`.
//
// Timing: cmodel/quadtree/arch_model.hpp (rtl/quadtree/README.md "Cycle semantics"). Each PE has
// its own input FIFO (FIFO p of PE p, FIFO 0 the input port's), each pixel processor its own
// (FIFO NPE + u); FIFO ready and valid are registers, so every unit sees the state at the start of
// the cycle, and the mask memory writes the cycle's set requests and their closure at the edge.
// PE numbering (= the model's): pipeline PEs 0..PIPE_LEVELS-1 (level 1 first), then the tree by
// depth; leaf PE m feeds pixel processor m.
module qt_raster #(
  parameter int N_LOG2 = qt_pkg::N_LOG2_DEFAULT,
  parameter int TREE_LEVELS = 1,
  parameter int FIFO_DEPTH = qt_pkg::FIFO_DEPTH_DEFAULT,
  parameter int NE = qt_pkg::NE_DEFAULT,
  parameter int NP = qt_pkg::NP_DEFAULT,
  parameter int EW = qt_pkg::EW_DEFAULT,
  parameter int AW = qt_pkg::AW_DEFAULT,
  parameter int PW = qt_pkg::PW_DEFAULT,
  parameter int GW = qt_pkg::GW_DEFAULT,
  parameter int G = qt_pkg::G_DEFAULT,
  parameter int LIGHT_COVERS = qt_pkg::LIGHT_COVERS_DEFAULT,
  // Synthesis only: < 15 shrinks the fog table (not the kernel's).
  parameter int FOG_CODE_BITS = qt_pkg::FOG_CODE_W,
  localparam int WIN_W = qt_pkg::win_w(NE, NP, EW, AW, PW, GW),
  localparam int PIX_W = qt_pkg::pix_w(NE, NP, EW, AW, PW, GW),
  localparam int PIPE_LEVELS = qt_pkg::pipe_levels(N_LOG2, TREE_LEVELS),
  localparam int NPE = qt_pkg::npe(N_LOG2, TREE_LEVELS),
  localparam int NPIX = qt_pkg::npix(TREE_LEVELS),
  localparam int NSLOT = qt_pkg::nslot(N_LOG2, TREE_LEVELS),
  localparam int LW = qt_pkg::LEVEL_W,
  localparam int CW = qt_pkg::COORD_W,
  localparam int SW = qt_pkg::MASK_SET_W
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  input  logic                            frame_start_i,
  // Architecture option (static during a frame): each polygon starts at its start window.
  input  logic                            start_window_i,
  // Input: the level-0 windows of the polygon pieces, in priority order.
  input  logic                            poly_valid_i,
  input  logic [WIN_W-1:0]                poly_i,
  output logic                            poly_ready_o,
  // Verification back-pressure: pixel processor u takes nothing this cycle.
  input  logic [NPIX-1:0]                 pixel_stall_i,
  // Configuration (tables), one write per cycle.
  input  logic                            cfg_valid_i,
  input  logic [qt_pkg::CFG_TARGET_W-1:0] cfg_target_i,
  input  logic [qt_pkg::CFG_ADDR_W-1:0]   cfg_addr_i,
  input  logic [qt_pkg::CFG_DATA_W-1:0]   cfg_data_i,
  // Some FIFO holds a record or some PE holds a window (registers only).
  output logic                            busy_o,
  // Trace, per cycle.
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
  output logic [NSLOT*SW-1:0]             mask_set_o,   // qt_pkg::mask_set_t per slot
  // Read-out of a resolved pixel: {B, G, R}, R in bits 7:0.
  input  logic [N_LOG2-1:0]               rd_x_i,
  input  logic [N_LOG2-1:0]               rd_y_i,
  output logic [23:0]                     rd_rgb_o
);

  localparam int NFIFO = NPE + NPIX;
  localparam int UW = NPIX > 1 ? $clog2(NPIX) : 1;   // pixel processor number

  // ---- FIFOs --------------------------------------------------------------------------------------
  logic [NFIFO-1:0]            fifo_wvalid, fifo_wready, fifo_rvalid, fifo_rready;
  logic [NFIFO*PIX_W-1:0]      fifo_wdata, fifo_rdata;   // [i*PIX_W +: PIX_W]: FIFO i

  for (genvar i = 0; i < NFIFO; i++) begin : g_fifo
    qt_fifo #(
      .WIDTH(PIX_W),
      .DEPTH(FIFO_DEPTH)
    ) u_fifo (
      .clk_i    (clk_i),
      .rst_ni   (rst_ni),
      .clear_i  (frame_start_i),
      .wvalid_i (fifo_wvalid[i]),
      .wdata_i  (fifo_wdata[i*PIX_W +: PIX_W]),
      .wready_o (fifo_wready[i]),
      .rvalid_o (fifo_rvalid[i]),
      .rdata_o  (fifo_rdata[i*PIX_W +: PIX_W]),
      .rready_i (fifo_rready[i])
    );
  end

  // The input port writes FIFO 0 (a window: samples 0, the pixel record's last field).
  assign fifo_wvalid[0] = poly_valid_i;
  assign fifo_wdata[0 +: PIX_W] = PIX_W'(poly_i);
  assign poly_ready_o = fifo_wready[0];

  // ---- PEs ----------------------------------------------------------------------------------------
  logic [NPE-1:0]       pe_busy;
  logic [NPE*LW-1:0]    rd_level;
  logic [NPE*4-1:0]     rd_mask;
  logic [NPE*CW-1:0]    rd_x, rd_y;
  logic [NSLOT-1:0]     set_valid;
  logic [NSLOT*SW-1:0]  set;

  for (genvar p = 0; p < NPE; p++) begin : g_pe
    // Where PE p sits: pipeline stage p, or tree depth `depth`, position `m` in it.
    localparam bit IN_TREE = p >= PIPE_LEVELS;
    localparam int TP = p - PIPE_LEVELS;   // index within the tree
    localparam int DEPTH = !IN_TREE ? 0 : TP < 1 ? 0 : TP < 5 ? 1 : TP < 21 ? 2 : TP < 85 ? 3 : 4;
    localparam int M = TP - qt_pkg::tree_pes(DEPTH);
    localparam int LEVEL = IN_TREE ? PIPE_LEVELS + 1 + DEPTH : p + 1;
    localparam bit LEAF = IN_TREE && DEPTH == TREE_LEVELS - 1;
    localparam bit ROUTE = IN_TREE && !LEAF;
    localparam int NOUT = ROUTE ? 4 : 1;
    // The first FIFO PE p writes: the next stage's, child PE 4 m of the next depth's, or the pixel
    // processor's.
    localparam int DEST = !IN_TREE ? p + 1 :
                          LEAF ? NPE + M : PIPE_LEVELS + qt_pkg::tree_pes(DEPTH + 1) + 4 * M;

    logic [NOUT-1:0]  out_valid;
    logic [PIX_W-1:0] out_data;

    qt_pe #(
      .N_LOG2            (N_LOG2),
      .LEVEL             (LEVEL),
      .ROUTE_BY_QUADRANT (ROUTE),
      .NE(NE), .NP(NP), .EW(EW), .AW(AW), .PW(PW), .GW(GW)
    ) u_pe (
      .clk_i        (clk_i),
      .rst_ni       (rst_ni),
      .clear_i      (frame_start_i),
      .start_window_i (start_window_i),
      .in_valid_i   (fifo_rvalid[p]),
      .in_data_i    (fifo_rdata[p*PIX_W +: PIX_W]),
      .in_ready_o   (fifo_rready[p]),
      .mask_level_o (rd_level[p*LW +: LW]),
      .mask_x_o     (rd_x[p*CW +: CW]),
      .mask_y_o     (rd_y[p*CW +: CW]),
      .mask_word_i  (rd_mask[p*4 +: 4]),
      .out_ready_i  (fifo_wready[DEST +: NOUT]),
      .out_valid_o  (out_valid),
      .out_data_o   (out_data),
      .set_valid_o  (set_valid[p]),
      .set_o        (set[p*SW +: SW]),
      .load_valid_o (pe_load_valid_o[p]),
      .load_mask_o  (pe_load_mask_o[p*4 +: 4]),
      .emit_valid_o (pe_emit_valid_o[p]),
      .emit_child_o (pe_emit_child_o[p*2 +: 2]),
      .emit_full_o  (pe_emit_full_o[p]),
      .busy_o       (pe_busy[p])
    );

    assign fifo_wvalid[DEST +: NOUT] = out_valid;
    for (genvar q = 0; q < NOUT; q++) begin : g_out
      assign fifo_wdata[(DEST + q)*PIX_W +: PIX_W] = out_data;
    end
    assign pe_emit_data_o[p*PIX_W +: PIX_W] = out_data;
  end

  // ---- Pixel processors -----------------------------------------------------------------------------
  logic [NPIX*24-1:0] unit_rgb;   // [u*24 +: 24]: unit u's read-out

  for (genvar u = 0; u < NPIX; u++) begin : g_pixel
    qt_pixel_processor #(
      .N_LOG2        (N_LOG2),
      .TREE_LEVELS   (TREE_LEVELS),
      .NE(NE), .NP(NP), .EW(EW), .AW(AW), .PW(PW), .GW(GW), .G(G),
      .LIGHT_COVERS  (LIGHT_COVERS),
      .FOG_CODE_BITS (FOG_CODE_BITS)
    ) u_pixel (
      .clk_i        (clk_i),
      .clear_i      (frame_start_i),
      .unit_i       ((2*TREE_LEVELS)'(u)),
      .in_valid_i   (fifo_rvalid[NPE + u]),
      .in_data_i    (fifo_rdata[(NPE + u)*PIX_W +: PIX_W]),
      .in_ready_o   (fifo_rready[NPE + u]),
      .stall_i      (pixel_stall_i[u]),
      .cfg_valid_i  (cfg_valid_i),
      .cfg_target_i (cfg_target_i),
      .cfg_addr_i   (cfg_addr_i),
      .cfg_data_i   (cfg_data_i),
      .set_valid_o  (set_valid[NPE + u]),
      .set_o        (set[(NPE + u)*SW +: SW]),
      .px_valid_o   (px_valid_o[u]),
      .px_fresh_o   (px_fresh_o[u*16 +: 16]),
      .px_full_o    (px_full_o[u]),
      .rd_x_i       (rd_x_i),
      .rd_y_i       (rd_y_i),
      .rd_rgb_o     (unit_rgb[u*24 +: 24])
    );
    assign px_data_o[u*PIX_W +: PIX_W] = fifo_rdata[(NPE + u)*PIX_W +: PIX_W];
  end

  // The read-out's unit: the base-4 digits {y[i+1], x[i+1]} of the pixel's address.
  logic [UW-1:0] rd_unit;
  if (TREE_LEVELS > 1) begin : g_rd_unit
    for (genvar i = 0; i + 1 < TREE_LEVELS; i++) begin : g_digit
      assign rd_unit[2*i +: 2] = {rd_y_i[i+1], rd_x_i[i+1]};
    end
  end else begin : g_rd_single
    assign rd_unit = 1'b0;
  end
  assign rd_rgb_o = unit_rgb[32'(rd_unit)*24 +: 24];

  // ---- Mask memory --------------------------------------------------------------------------------
  qt_mask_memory #(
    .N_LOG2 (N_LOG2),
    .NRD    (NPE),
    .NSET   (NSLOT)
  ) u_masks (
    .clk_i       (clk_i),
    .clear_i     (frame_start_i),
    .rd_level_i  (rd_level),
    .rd_x_i      (rd_x),
    .rd_y_i      (rd_y),
    .rd_mask_o   (rd_mask),
    .set_valid_i (set_valid),
    .set_i       (set)
  );

  assign mask_set_valid_o = set_valid;
  assign mask_set_o = set;
  assign busy_o = (|fifo_rvalid) || (|pe_busy);

  // ---- Limits (rtl/quadtree/README.md "Parameters") -----------------------------------------------
  // The PE placement above knows tree depths 0..4; the mask memory takes a set port per unit.
  if (N_LOG2 < qt_pkg::N_LOG2_MIN || N_LOG2 > qt_pkg::N_LOG2_MAX) begin : g_bad_n_log2
    $error("qt_raster: N_LOG2 must be 4..10");
  end
  if (TREE_LEVELS < 1 || TREE_LEVELS > N_LOG2 || TREE_LEVELS > qt_pkg::TREE_LEVELS_MAX) begin : g_bad_tree
    $error("qt_raster: TREE_LEVELS must be 1..min(N_LOG2, 5)");
  end
  if (FIFO_DEPTH < 1) begin : g_bad_fifo_depth
    $error("qt_raster: FIFO_DEPTH must be at least 1");
  end

endmodule
