// Pixel processor of the quadtree raster processor (SPEC E, seed 004 "final computations,
// filtering"; hls/quadtree/pixel_processor.hpp quad_pixel_process / quad_pixel_resolve).
//
// One pixel record per clock from its FIFO (when valid and stall_i is low): fresh = samples &
// ~owned; every fresh sample gets its colour (16 lanes, qt_pixel_lane: I and 1/Z at the sample,
// colour x I, fog through the fog table) unless the pixel's light cover has the sample with a
// priority position <= the polygon's id, whose colour shows instead; the colours are added to the
// pixel's three sums (20 bits, wrapping: UFixed<20, 12>), owned |= fresh, and when owned becomes
// 16'hFFFF the set request (N_LOG2 - 1, x >> 1, y >> 1, {y[0], x[0]}) is raised in the same cycle.
//
// Unit unit_i of a TREE_LEVELS-level tree owns the pixels whose address bits x[T-1:1], y[T-1:1]
// are the base-4 digits of unit_i (the leaf PE m of the tree only ever emits those): digit i
// (i = 0 least significant) is {y[i+1], x[i+1]}. Its pixel state is indexed by the other bits:
// local x = {x[N-1:T], x[0]}, likewise y.
//
// Tables (the configuration port, written before the frame; each unit keeps its own copy, as the
// 16 lanes each read the fog table and the light covers):
//   target 0 fog table[code] (9 bits), 1 fog colour (addr 0..2) / background (3..5), 2 light
//   index of pixel y 2^N + x (13 bits: cover entry + 1, 0 none; only the owning unit stores it),
//   3 light cover mask[entry], 4 light cover sample[entry 16 + s] = {priority 17, R, G, B 16}.
// The frame start (clear_i) clears every pixel's owned mask and sums (valid bits).
//
// The fog table has 2^FOG_CODE_BITS entries addressed by the top FOG_CODE_BITS bits of the code:
// 15 (the default) is the kernel's table; fewer only shrink the synthesis configuration.
module qt_pixel_processor #(
  parameter int N_LOG2 = qt_pkg::N_LOG2_DEFAULT,
  parameter int TREE_LEVELS = 1,
  parameter int NE = qt_pkg::NE_DEFAULT,
  parameter int NP = qt_pkg::NP_DEFAULT,
  parameter int EW = qt_pkg::EW_DEFAULT,
  parameter int AW = qt_pkg::AW_DEFAULT,
  parameter int PW = qt_pkg::PW_DEFAULT,
  parameter int GW = qt_pkg::GW_DEFAULT,
  parameter int G = qt_pkg::G_DEFAULT,
  parameter int LIGHT_COVERS = qt_pkg::LIGHT_COVERS_DEFAULT,
  parameter int FOG_CODE_BITS = qt_pkg::FOG_CODE_W,
  localparam int WIN_W = qt_pkg::win_w(NE, NP, EW, AW, PW, GW),
  localparam int PIX_W = qt_pkg::pix_w(NE, NP, EW, AW, PW, GW),
  localparam int LVW = qt_pkg::LEVEL_W,
  localparam int CW = qt_pkg::COORD_W,
  localparam int LIW = qt_pkg::LIGHT_INDEX_W
) (
  input  logic                            clk_i,
  input  logic                            clear_i,          // frame start
  // The unit's number (a constant; a port rather than a parameter so that every unit is one
  // module: one synthesis, one row of the report).
  input  logic [2*TREE_LEVELS-1:0]        unit_i,
  // Input FIFO.
  input  logic                            in_valid_i,
  input  logic [PIX_W-1:0]                in_data_i,
  output logic                            in_ready_o,
  input  logic                            stall_i,          // verification back-pressure: take nothing
  // Configuration.
  input  logic                            cfg_valid_i,
  input  logic [qt_pkg::CFG_TARGET_W-1:0] cfg_target_i,
  input  logic [qt_pkg::CFG_ADDR_W-1:0]   cfg_addr_i,
  input  logic [qt_pkg::CFG_DATA_W-1:0]   cfg_data_i,
  // Mask set request.
  output logic                            set_valid_o,
  output qt_pkg::mask_set_t               set_o,
  // Trace: took a record, the samples it took, the pixel became full.
  output logic                            px_valid_o,
  output logic [15:0]                     px_fresh_o,
  output logic                            px_full_o,
  // Read-out of a resolved pixel this unit owns: {B, G, R}, R in bits 7:0.
  input  logic [N_LOG2-1:0]               rd_x_i,
  input  logic [N_LOG2-1:0]               rd_y_i,
  output logic [23:0]                     rd_rgb_o
);

  localparam int LW = N_LOG2 - TREE_LEVELS + 1;   // local address bits per axis
  localparam int PIXELS = 1 << (2 * LW);
  localparam int PXW = 2 * LW;                    // local pixel index
  localparam int CVW = LIGHT_COVERS > 1 ? $clog2(LIGHT_COVERS) : 1;
  localparam int CSW = CVW + 4;                   // cover sample index: entry 16 + s
  localparam int FOG_ENTRIES = 1 << FOG_CODE_BITS;

  // ---- Tables -------------------------------------------------------------------------------------
  logic [qt_pkg::FOG_FACTOR_W-1:0] fog_q [FOG_ENTRIES];
  logic [23:0]    fog_colour_q, background_q;
  logic [LIW-1:0] light_q [PIXELS];
  logic [15:0]    cover_mask_q [LIGHT_COVERS];
  logic [64:0]    cover_sample_q [LIGHT_COVERS * 16];

  // ---- Pixel state ----------------------------------------------------------------------------------
  logic [15:0]  owned_q [PIXELS];
  logic [59:0]  sum_q [PIXELS];          // three 20-bit sums, R in bits 19:0
  logic [PIXELS-1:0] valid_q;            // cleared at the frame start: owned = 0, sums = 0

  // ---- Address helpers ------------------------------------------------------------------------------
  // Local index of pixel (x, y) and its owning unit.
  function automatic logic [PXW-1:0] local_index(input logic [N_LOG2-1:0] x, input logic [N_LOG2-1:0] y);
    logic [LW-1:0] lx, ly;
    lx = LW'({x >> TREE_LEVELS, x[0]});
    ly = LW'({y >> TREE_LEVELS, y[0]});
    local_index = {ly, lx};
  endfunction

  function automatic logic [31:0] owner_unit(input logic [N_LOG2-1:0] x, input logic [N_LOG2-1:0] y);
    owner_unit = '0;
    for (int i = 0; i + 1 < TREE_LEVELS; i++) begin
      owner_unit[2*i +: 2] = {y[i+1], x[i+1]};
    end
  endfunction

  // ---- The record ---------------------------------------------------------------------------------
  localparam int OFF_POLY = qt_pkg::field_lo(qt_pkg::F_POLY, NE, NP, EW, AW, PW, GW);
  localparam int OFF_SAMPLES = qt_pkg::field_lo(qt_pkg::F_SAMPLES, NE, NP, EW, AW, PW, GW);

  logic [LVW-1:0]                  rec_level;
  logic [CW-1:0]                   rec_x, rec_y;
  logic [NE*EW-1:0]                rec_d;
  logic [NP*PW-1:0]                rec_f;
  logic [WIN_W-OFF_POLY-1:0]       rec_poly;
  logic [qt_pkg::ID_W-1:0]         rec_id;
  logic                            rec_opaque;
  logic [qt_pkg::COLOUR_BITS-1:0]  rec_colour;
  logic [qt_pkg::EDGE_COUNT_W-1:0] rec_edge_count;
  logic [NE*AW-1:0]                rec_a, rec_b;
  logic [NP*GW-1:0]                rec_dp_di, rec_dp_dj;
  logic [qt_pkg::W_EXPONENT_W-1:0] rec_w_exponent;
  logic [qt_pkg::SAMPLES_W-1:0]    rec_samples;
  logic [LVW-1:0]                  rec_start_level;
  logic [CW-1:0]                   rec_start_x, rec_start_y;

  qt_window_fields #(
    .NE(NE), .NP(NP), .EW(EW), .AW(AW), .PW(PW), .GW(GW)
  ) u_rec_fields (
    .window_i     (in_data_i[WIN_W-1:0]),
    .level_o      (rec_level),
    .x_o          (rec_x),
    .y_o          (rec_y),
    .d_o          (rec_d),
    .f_o          (rec_f),
    .poly_o       (rec_poly),
    .id_o         (rec_id),
    .opaque_o     (rec_opaque),
    .colour_o     (rec_colour),
    .edge_count_o (rec_edge_count),
    .a_o          (rec_a),
    .b_o          (rec_b),
    .dp_di_o      (rec_dp_di),
    .dp_dj_o      (rec_dp_dj),
    .w_exponent_o (rec_w_exponent),
    .start_level_o (rec_start_level),
    .start_x_o    (rec_start_x),
    .start_y_o    (rec_start_y)
  );
  assign rec_samples = in_data_i[OFF_SAMPLES +: qt_pkg::SAMPLES_W];

  logic             take;
  logic [PXW-1:0]   px;
  logic [15:0]      owned_old, owned_new, fresh;
  logic [59:0]      sum_old, sum_new;
  logic             became_full;

  assign in_ready_o = !stall_i;
  assign take = in_valid_i && !stall_i;
  assign px = local_index(rec_x[N_LOG2-1:0], rec_y[N_LOG2-1:0]);
  assign owned_old = valid_q[px] ? owned_q[px] : 16'h0000;
  assign sum_old = valid_q[px] ? sum_q[px] : 60'd0;
  assign fresh = rec_samples & ~owned_old;
  assign owned_new = owned_old | fresh;
  assign became_full = owned_new == 16'hFFFF && owned_old != 16'hFFFF;

  // ---- The pixel's light cover --------------------------------------------------------------------
  // Entry light - 1 of the cover table, or none (index 0, or beyond the table).
  logic [LIW-1:0] rec_light;
  logic           rec_has_cover;
  logic [CVW-1:0] rec_entry;
  logic [15:0]    rec_cover_mask;
  assign rec_light = light_q[px];
  assign rec_has_cover = rec_light != LIW'(0) && 32'(rec_light) <= LIGHT_COVERS;
  assign rec_entry = CVW'(rec_light - LIW'(1));
  assign rec_cover_mask = rec_has_cover ? cover_mask_q[rec_entry] : 16'h0000;

  // ---- 16 sample lanes ----------------------------------------------------------------------------
  logic [47:0] sample_colour [16];
  for (genvar s = 0; s < 16; s++) begin : g_lane
    logic [qt_pkg::FOG_CODE_W-1:0] code;
    logic [qt_pkg::FOG_FACTOR_W-1:0] fog_factor;
    logic [qt_pkg::COLOURS*qt_pkg::SAMPLE_COLOUR_W-1:0] lane_colour;
    logic [64:0] cover_entry;
    logic        light_shows;

    qt_pixel_lane #(
      .PW(PW), .GW(GW), .G(G)
    ) u_lane (
      .sample_i       (qt_pkg::SAMPLE_INDEX_W'(s)),
      .f_intensity_i  (rec_f[0 +: PW]),
      .f_depth_i      (rec_f[PW +: PW]),
      .di_intensity_i (rec_dp_di[0 +: GW]),
      .dj_intensity_i (rec_dp_dj[0 +: GW]),
      .di_depth_i     (rec_dp_di[GW +: GW]),
      .dj_depth_i     (rec_dp_dj[GW +: GW]),
      .w_exponent_i   (rec_w_exponent),
      .colour_i       (rec_colour),
      .fog_colour_i   (fog_colour_q),
      .code_o         (code),
      .fog_factor_i   (fog_factor),
      .colour_o       (lane_colour)
    );
    assign fog_factor = fog_q[code[qt_pkg::FOG_CODE_W-1 -: FOG_CODE_BITS]];

    // The light shows when it covers the sample and ranks at or before the polygon.
    assign cover_entry = cover_sample_q[{rec_entry, qt_pkg::SAMPLE_INDEX_W'(s)}];
    assign light_shows = rec_cover_mask[s] && (cover_entry[64:48] <= {1'b0, rec_id});
    // {R, G, B} of the cover entry -> R first like the lanes.
    assign sample_colour[s] = light_shows ? {cover_entry[15:0], cover_entry[31:16], cover_entry[47:32]} : lane_colour;
    if (FOG_CODE_BITS < 15) begin : g_fog_low_bits
      logic unused_code_low;
      assign unused_code_low = ^code[qt_pkg::FOG_CODE_W-1 - FOG_CODE_BITS:0];
    end
  end

  // ---- The sums: every fresh sample's colour (modulo 2^20, as UFixed<20, 12> wraps) ----------------
  always_comb begin
    sum_new = sum_old;
    for (int s = 0; s < 16; s++) begin
      if (fresh[s]) begin
        for (int c = 0; c < 3; c++) begin
          sum_new[c*20 +: 20] = sum_new[c*20 +: 20] + 20'(sample_colour[s][c*16 +: 16]);
        end
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (clear_i) begin
      valid_q <= PIXELS'(0);
    end else if (take) begin
      valid_q[px] <= 1'b1;
    end
  end
  always_ff @(posedge clk_i) begin
    if (take && !clear_i) begin
      owned_q[px] <= owned_new;
      sum_q[px] <= sum_new;
    end
  end

  assign set_valid_o = take && became_full;
  assign set_o.level = LVW'(N_LOG2 - 1);
  assign set_o.x = {1'b0, rec_x[CW-1:1]};
  assign set_o.y = {1'b0, rec_y[CW-1:1]};
  assign set_o.child = {rec_y[0], rec_x[0]};
  assign px_valid_o = take;
  assign px_fresh_o = take ? fresh : 16'h0000;
  assign px_full_o = take && became_full;

  // ---- Configuration writes -----------------------------------------------------------------------
  logic [N_LOG2-1:0] cfg_x, cfg_y;
  assign cfg_x = cfg_addr_i[N_LOG2-1:0];
  assign cfg_y = cfg_addr_i[2*N_LOG2-1:N_LOG2];

  always_ff @(posedge clk_i) begin
    if (cfg_valid_i) begin
      unique case (cfg_target_i)
        3'd0: fog_q[cfg_addr_i[qt_pkg::FOG_CODE_W-1 -: FOG_CODE_BITS]] <= cfg_data_i[qt_pkg::FOG_FACTOR_W-1:0];
        3'd1: begin
          unique case (cfg_addr_i)
            32'd0: fog_colour_q[7:0] <= cfg_data_i[7:0];
            32'd1: fog_colour_q[15:8] <= cfg_data_i[7:0];
            32'd2: fog_colour_q[23:16] <= cfg_data_i[7:0];
            32'd3: background_q[7:0] <= cfg_data_i[7:0];
            32'd4: background_q[15:8] <= cfg_data_i[7:0];
            32'd5: background_q[23:16] <= cfg_data_i[7:0];
            default: ;
          endcase
        end
        3'd2: begin
          if (owner_unit(cfg_x, cfg_y) == 32'(unit_i) && cfg_addr_i < (32'd1 << (2 * N_LOG2))) begin
            light_q[local_index(cfg_x, cfg_y)] <= cfg_data_i[LIW-1:0];
          end
        end
        3'd3: begin
          if (cfg_addr_i < 32'(LIGHT_COVERS)) begin
            cover_mask_q[cfg_addr_i[CVW-1:0]] <= cfg_data_i[15:0];
          end
        end
        3'd4: begin
          if (cfg_addr_i < 32'(LIGHT_COVERS * 16)) begin
            cover_sample_q[cfg_addr_i[CSW-1:0]] <= cfg_data_i;
          end
        end
        default: ;
      endcase
    end
  end

  // ---- Read-out: the resolved pixel (quad_pixel_resolve, resolve_box) ------------------------------
  logic [PXW-1:0] rd_px;
  logic [15:0]    rd_owned;
  logic [59:0]    rd_sum;
  logic [LIW-1:0] rd_light;
  logic           rd_has_cover;
  logic [CVW-1:0] rd_entry;
  logic [15:0]    rd_cover_mask;
  logic [59:0]    rd_total;

  assign rd_px = local_index(rd_x_i, rd_y_i);
  assign rd_owned = valid_q[rd_px] ? owned_q[rd_px] : 16'h0000;
  assign rd_sum = valid_q[rd_px] ? sum_q[rd_px] : 60'd0;
  assign rd_light = light_q[rd_px];
  assign rd_has_cover = rd_light != LIW'(0) && 32'(rd_light) <= LIGHT_COVERS;
  assign rd_entry = CVW'(rd_light - LIW'(1));
  assign rd_cover_mask = rd_has_cover ? cover_mask_q[rd_entry] : 16'h0000;

  // Samples no polygon owns show their light, or the background.
  always_comb begin
    rd_total = rd_sum;
    for (int s = 0; s < 16; s++) begin
      if (!rd_owned[s]) begin
        for (int c = 0; c < 3; c++) begin
          if (rd_cover_mask[s]) begin
            rd_total[c*20 +: 20] = rd_total[c*20 +: 20] +
                                   20'(cover_sample_q[{rd_entry, qt_pkg::SAMPLE_INDEX_W'(s)}][32 - 16 * c +: 16]);
          end else begin
            rd_total[c*20 +: 20] = rd_total[c*20 +: 20] + 20'({background_q[c*8 +: 8], 8'd0});
          end
        end
      end
    end
  end

  // The box filter's mean: (sum + 2^11) >> 12, saturated to 255.
  for (genvar c = 0; c < 3; c++) begin : g_resolve
    logic [8:0] mean;
    assign mean = 9'(({1'b0, rd_total[c*20 +: 20]} + 21'd2048) >> 12);
    assign rd_rgb_o[c*8 +: 8] = mean[8] ? 8'hFF : mean[7:0];
  end

  // Fields a pixel processor does not read.
  logic unused_fields;
  assign unused_fields = ^{rec_level, rec_d, rec_poly, rec_opaque, rec_edge_count, rec_a, rec_b,
                           rec_x, rec_y, rec_start_level, rec_start_x, rec_start_y, cfg_addr_i,
                           cfg_data_i};

  // ---- Limits (rtl/quadtree/README.md "Parameters") -----------------------------------------------
  // The lanes read parameter 0 as I and 1 as W; the light index holds a cover entry + 1.
  if (NP != 2) begin : g_bad_np
    $error("qt_pixel_processor: NP must be 2 (I and W)");
  end
  if (LIGHT_COVERS < 1 || LIGHT_COVERS > qt_pkg::LIGHT_COVERS_MAX) begin : g_bad_light_covers
    $error("qt_pixel_processor: LIGHT_COVERS must be 1..8191 (13-bit light index)");
  end
  if (FOG_CODE_BITS < 1 || FOG_CODE_BITS > qt_pkg::FOG_CODE_W) begin : g_bad_fog_code_bits
    $error("qt_pixel_processor: FOG_CODE_BITS must be 1..15");
  end

endmodule
