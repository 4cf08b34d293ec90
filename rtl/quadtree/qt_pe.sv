// Quadtree processing element (SPEC E, seed 004) for one level: takes windows of level LEVEL - 1
// from its input FIFO and decides their children (level LEVEL), one child per clock.
//
// Arithmetic = hls/quadtree/pe.hpp evaluate_child, bit for bit; the child's side is 2^K samples,
// K = N_LOG2 - LEVEL + 2 (a constant: every window this PE takes has level LEVEL - 1).
//   Coverage recurrence: d' = d - 2^K |A| e_A - 2^K |B| e_B (EW bits, wrapping), e_A = !x_b for
//     A >= 0, x_b for A < 0 (likewise e_B with y_b); covered when d' >= 0 for every edge.
//   Full coverage: d' - (2^K |A| + 2^K |B|) + (|A| + |B|) >= 0 for every edge, in EW + 2 bits
//     exactly as the kernel forms it: the shifted sum wraps to EW bits first.
//   Parameter recurrence: f' = f + 2^K D x_b + 2^K E y_b (PW bits, wrapping).
//   Pixel level (LEVEL == N_LOG2): sample (di, dj) is inside when
//     d' - 3 (max(A, 0) + max(B, 0)) + A di + B dj >= 0 (EW + 2 bits) for every edge; the pixel
//     is full when all 16 are (before the screen door), a non-opaque polygon keeps the samples
//     of the screen-door checkerboard 16'hA5A5, covered = d' test passed and samples != 0.
//
// Timing = cmodel/quadtree/arch_model.hpp step_pe: busy_q, win_q, todo_q. When busy the lowest
// child q still to do is evaluated; covered and its FIFO not ready (ready is the FIFO's register:
// the count at the start of the cycle): stall; else the child is done (pushed if covered, the mask
// set request raised if full and opaque, q leaves todo). When not busy, or freed this cycle, the
// head of the input FIFO is popped, its mask word read (combinational, the memory as it was at
// the start of the cycle) and todo = ~mask; a window with all four children masked is dropped.
// Start window (start_window_i, ArchConfig::start_window): a popped window above its polygon's
// start window (record fields start_level, start_x, start_y) keeps only the child on the path to
// it, todo = ~mask & path: the other children hold no sample of the polygon.
module qt_pe #(
  parameter int N_LOG2 = qt_pkg::N_LOG2_DEFAULT,
  parameter int LEVEL = 1,                 // level of the children, 1..N_LOG2
  parameter bit ROUTE_BY_QUADRANT = 1'b0,  // tree PE: child q goes to output q
  parameter int NE = qt_pkg::NE_DEFAULT,
  parameter int NP = qt_pkg::NP_DEFAULT,
  parameter int EW = qt_pkg::EW_DEFAULT,
  parameter int AW = qt_pkg::AW_DEFAULT,
  parameter int PW = qt_pkg::PW_DEFAULT,
  parameter int GW = qt_pkg::GW_DEFAULT,
  localparam int WIN_W = qt_pkg::win_w(NE, NP, EW, AW, PW, GW),
  localparam int PIX_W = qt_pkg::pix_w(NE, NP, EW, AW, PW, GW),
  localparam int LW = qt_pkg::LEVEL_W,
  localparam int CW = qt_pkg::COORD_W,
  localparam int NOUT = ROUTE_BY_QUADRANT ? 4 : 1
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              clear_i,        // frame start
  input  logic              start_window_i, // architecture option: start at the start window
  // Input FIFO (pixel-record-wide items; the samples field is 0 above the pixel level).
  input  logic              in_valid_i,
  input  logic [PIX_W-1:0]  in_data_i,
  output logic              in_ready_o,
  // Mask read of the input FIFO's head window (level LEVEL - 1).
  output logic [LW-1:0]     mask_level_o,
  output logic [CW-1:0]     mask_x_o,
  output logic [CW-1:0]     mask_y_o,
  input  logic [3:0]        mask_word_i,
  // Output FIFO(s): a child is pushed when out_valid_o[dest] (the FIFO's ready was checked).
  input  logic [NOUT-1:0]   out_ready_i,
  output logic [NOUT-1:0]   out_valid_o,
  output logic [PIX_W-1:0]  out_data_o,
  // Mask set request.
  output logic              set_valid_o,
  output qt_pkg::mask_set_t set_o,
  // Trace.
  output logic              load_valid_o,   // popped a window this cycle
  output logic [3:0]        load_mask_o,    // its mask word
  output logic              emit_valid_o,   // pushed child emit_child_o
  output logic [1:0]        emit_child_o,
  output logic              emit_full_o,
  output logic              busy_o
);

  localparam int K = N_LOG2 - LEVEL + 2;
  localparam bit PIXEL_LEVEL = LEVEL == N_LOG2;
  localparam int OFF_LEVEL = qt_pkg::field_lo(qt_pkg::F_LEVEL, NE, NP, EW, AW, PW, GW);
  localparam int OFF_X = qt_pkg::field_lo(qt_pkg::F_X, NE, NP, EW, AW, PW, GW);
  localparam int OFF_Y = qt_pkg::field_lo(qt_pkg::F_Y, NE, NP, EW, AW, PW, GW);
  localparam int OFF_D = qt_pkg::field_lo(qt_pkg::F_D, NE, NP, EW, AW, PW, GW);
  localparam int OFF_F = qt_pkg::field_lo(qt_pkg::F_F, NE, NP, EW, AW, PW, GW);
  localparam int OFF_POLY = qt_pkg::field_lo(qt_pkg::F_POLY, NE, NP, EW, AW, PW, GW);
  localparam int OFF_SAMPLES = qt_pkg::field_lo(qt_pkg::F_SAMPLES, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_LEVEL = qt_pkg::field_lo(qt_pkg::F_START_LEVEL, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_X = qt_pkg::field_lo(qt_pkg::F_START_X, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_Y = qt_pkg::field_lo(qt_pkg::F_START_Y, NE, NP, EW, AW, PW, GW);
  localparam int POLY_W = WIN_W - OFF_POLY;
  localparam logic [15:0] SCREEN_DOOR = 16'hA5A5;  // (di + dj) even: hls kScreenDoorSamples

  // ---- State ------------------------------------------------------------------------------------
  logic             busy_q, busy_d;
  logic [3:0]       todo_q, todo_d;
  logic [WIN_W-1:0] win_q;

  // ---- The held window's fields -----------------------------------------------------------------
  logic [LW-1:0]                   win_level;
  logic [CW-1:0]                   win_x, win_y;
  logic [NE*EW-1:0]                win_d;
  logic [NP*PW-1:0]                win_f;
  logic [POLY_W-1:0]               win_poly;
  logic [qt_pkg::ID_W-1:0]         win_id;
  logic                            win_opaque;
  logic [qt_pkg::COLOUR_BITS-1:0]  win_colour;
  logic [qt_pkg::EDGE_COUNT_W-1:0] win_edge_count;
  logic [NE*AW-1:0]                win_a, win_b;
  logic [NP*GW-1:0]                win_dp_di, win_dp_dj;
  logic [qt_pkg::W_EXPONENT_W-1:0] win_w_exponent;
  logic [LW-1:0]                   win_start_level;
  logic [CW-1:0]                   win_start_x, win_start_y;

  qt_window_fields #(
    .NE(NE), .NP(NP), .EW(EW), .AW(AW), .PW(PW), .GW(GW)
  ) u_win_fields (
    .window_i     (win_q),
    .level_o      (win_level),
    .x_o          (win_x),
    .y_o          (win_y),
    .d_o          (win_d),
    .f_o          (win_f),
    .poly_o       (win_poly),
    .id_o         (win_id),
    .opaque_o     (win_opaque),
    .colour_o     (win_colour),
    .edge_count_o (win_edge_count),
    .a_o          (win_a),
    .b_o          (win_b),
    .dp_di_o      (win_dp_di),
    .dp_dj_o      (win_dp_dj),
    .w_exponent_o (win_w_exponent),
    .start_level_o (win_start_level),
    .start_x_o    (win_start_x),
    .start_y_o    (win_start_y)
  );

  // ---- The child under test: the lowest bit of todo_q --------------------------------------------
  logic [1:0] child_sel;
  logic       xb, yb;

  always_comb begin
    if (todo_q[0]) begin
      child_sel = 2'd0;
    end else if (todo_q[1]) begin
      child_sel = 2'd1;
    end else if (todo_q[2]) begin
      child_sel = 2'd2;
    end else begin
      child_sel = 2'd3;
    end
  end
  assign xb = child_sel[0];
  assign yb = child_sel[1];

  // ---- Coverage recurrence, full-coverage test, sub-pixel coverage (per edge) --------------------
  logic [NE*EW-1:0] child_d;
  logic [NE-1:0]    edge_covered;   // d' >= 0
  logic [NE-1:0]    edge_full;      // the child's minimum >= 0
  logic [15:0]      edge_samples [NE];

  for (genvar e = 0; e < NE; e++) begin : g_edge
    logic signed [AW-1:0]   a, b;
    logic signed [EW-1:0]   a_ext, b_ext, abs_a, abs_b, step_a, step_b, d, d_child;
    logic signed [EW-1:0]   sum_ab, sum_ab_shifted;
    logic signed [EW+1:0]   minimum;
    logic                   e_a, e_b;

    assign a = win_a[e*AW +: AW];
    assign b = win_b[e*AW +: AW];
    assign d = win_d[e*EW +: EW];
    assign a_ext = EW'(a);   // sign extension (signed operand)
    assign b_ext = EW'(b);
    assign abs_a = a[AW-1] ? -a_ext : a_ext;
    assign abs_b = b[AW-1] ? -b_ext : b_ext;
    // The child does not contain the parent's maximising corner along x (along y).
    assign e_a = a[AW-1] ? xb : !xb;
    assign e_b = b[AW-1] ? yb : !yb;
    assign step_a = e_a ? (abs_a <<< K) : '0;
    assign step_b = e_b ? (abs_b <<< K) : '0;
    assign d_child = d - step_a - step_b;
    assign sum_ab = abs_a + abs_b;
    assign sum_ab_shifted = sum_ab <<< K;
    assign minimum = (EW+2)'(d_child) - (EW+2)'(sum_ab_shifted) + (EW+2)'(sum_ab);
    assign edge_covered[e] = !d_child[EW-1];
    assign edge_full[e] = !minimum[EW+1];
    assign child_d[e*EW +: EW] = d_child;

    if (PIXEL_LEVEL) begin : g_samples
      // The edge at the pixel's top-left sample, then A di + B dj per sample (EW + 2 bits).
      logic signed [EW+1:0] a_wide, b_wide, pos_sum, top_left;
      assign a_wide = (EW+2)'(a);
      assign b_wide = (EW+2)'(b);
      assign pos_sum = (a[AW-1] ? '0 : a_wide) + (b[AW-1] ? '0 : b_wide);
      assign top_left = (EW+2)'(d_child) - pos_sum - (pos_sum <<< 1);
      // A di and B dj for di, dj = 0..3: 0, A, 2A, 3A (shifts and one adder).
      logic signed [EW+1:0] a_steps [4], b_steps [4];
      assign a_steps[0] = '0;
      assign a_steps[1] = a_wide;
      assign a_steps[2] = a_wide <<< 1;
      assign a_steps[3] = a_wide + (a_wide <<< 1);
      assign b_steps[0] = '0;
      assign b_steps[1] = b_wide;
      assign b_steps[2] = b_wide <<< 1;
      assign b_steps[3] = b_wide + (b_wide <<< 1);
      for (genvar s = 0; s < 16; s++) begin : g_sample
        logic signed [EW+1:0] v;
        assign v = top_left + a_steps[s % 4] + b_steps[s / 4];
        assign edge_samples[e][s] = !v[EW+1];
      end
    end else begin : g_no_samples
      assign edge_samples[e] = '0;
    end
  end

  // ---- Parameter recurrence ---------------------------------------------------------------------
  logic [NP*PW-1:0] child_f;
  for (genvar p = 0; p < NP; p++) begin : g_param
    logic signed [PW-1:0] f, step_i, step_j;
    assign f = win_f[p*PW +: PW];
    assign step_i = xb ? (PW'($signed(win_dp_di[p*GW +: GW])) <<< K) : '0;
    assign step_j = yb ? (PW'($signed(win_dp_dj[p*GW +: GW])) <<< K) : '0;
    assign child_f[p*PW +: PW] = f + step_i + step_j;
  end

  // ---- The child's verdict ----------------------------------------------------------------------
  logic        d_covered, covered, full;
  logic [15:0] samples;

  assign d_covered = &edge_covered;

  if (PIXEL_LEVEL) begin : g_pixel_verdict
    logic [15:0] sample_inside;
    always_comb begin
      sample_inside = 16'hFFFF;
      for (int e = 0; e < NE; e++) begin
        sample_inside = sample_inside & edge_samples[e];
      end
    end
    assign full = d_covered && (sample_inside == 16'hFFFF);
    assign samples = win_opaque ? sample_inside : (sample_inside & SCREEN_DOOR);
    assign covered = d_covered && (samples != '0);
    logic unused_edge_full;
    assign unused_edge_full = ^edge_full;
  end else begin : g_window_verdict
    assign full = d_covered && (&edge_full);
    assign covered = d_covered;
    assign samples = '0;
    logic [15:0] unused_edge_samples;
    always_comb begin
      unused_edge_samples = '0;
      for (int e = 0; e < NE; e++) begin
        unused_edge_samples = unused_edge_samples ^ edge_samples[e];
      end
    end
  end

  // The child record: the window's fields with a new level, address, d and f (the polygon's
  // constants unchanged), and its samples.
  always_comb begin
    out_data_o = '0;
    out_data_o[OFF_LEVEL +: LW] = LW'(LEVEL);
    out_data_o[OFF_X +: CW] = {win_x[CW-2:0], xb};
    out_data_o[OFF_Y +: CW] = {win_y[CW-2:0], yb};
    out_data_o[OFF_D +: NE*EW] = child_d;
    out_data_o[OFF_F +: NP*PW] = child_f;
    out_data_o[OFF_POLY +: POLY_W] = win_poly;
    out_data_o[OFF_SAMPLES +: qt_pkg::SAMPLES_W] = samples;
  end

  // ---- Control ----------------------------------------------------------------------------------
  logic dest_ready, stall, done, pop;
  logic [3:0] todo_left;

  if (ROUTE_BY_QUADRANT) begin : g_route
    assign dest_ready = out_ready_i[child_sel];
    assign out_valid_o = (busy_q && covered && !stall) ? (4'b0001 << child_sel) : 4'b0000;
  end else begin : g_single
    assign dest_ready = out_ready_i[0];
    assign out_valid_o = busy_q && covered && !stall;
  end

  assign stall = busy_q && covered && !dest_ready;
  assign done = busy_q && !stall;
  assign todo_left = todo_q & ~(4'b0001 << child_sel);
  // Free for a new window: idle, or the last child done this cycle.
  assign in_ready_o = !busy_q || (done && todo_left == 4'b0000);
  assign pop = in_valid_i && in_ready_o;

  // The children the popped window keeps: all four, or above its start window (level LEVEL - 1 <
  // start_level) only the one on the path, bit start_level - LEVEL of the start window's address.
  logic [LW-1:0] in_start_level, path_bit;
  logic [CW-1:0] in_start_x, in_start_y;
  logic [3:0]    path, keep;
  assign in_start_level = in_data_i[OFF_START_LEVEL +: LW];
  assign in_start_x = in_data_i[OFF_START_X +: CW];
  assign in_start_y = in_data_i[OFF_START_Y +: CW];
  assign path_bit = in_start_level - LW'(LEVEL);
  always_comb begin
    path = 4'hF;
    if (start_window_i && in_start_level >= LW'(LEVEL)) begin
      path = 4'b0001 << {in_start_y[path_bit], in_start_x[path_bit]};
    end
  end
  assign keep = ~mask_word_i & path;

  always_comb begin
    busy_d = busy_q;
    todo_d = todo_q;
    if (done) begin
      todo_d = todo_left;
      busy_d = todo_left != 4'b0000;
    end
    if (pop) begin
      todo_d = keep;
      busy_d = keep != 4'h0;
    end
    if (clear_i) begin
      todo_d = '0;
      busy_d = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q <= 1'b0;
      todo_q <= '0;
    end else begin
      busy_q <= busy_d;
      todo_q <= todo_d;
    end
  end

  // The held window: no reset (read only while busy_q).
  always_ff @(posedge clk_i) begin
    if (pop) begin
      win_q <= in_data_i[WIN_W-1:0];
    end
  end

  // ---- Mask interface and trace -----------------------------------------------------------------
  assign mask_level_o = LW'(LEVEL - 1);
  assign mask_x_o = in_data_i[OFF_X +: CW];    // the head record's x and y
  assign mask_y_o = in_data_i[OFF_Y +: CW];

  assign set_valid_o = done && full && win_opaque;
  assign set_o.level = LW'(LEVEL - 1);
  assign set_o.x = win_x;
  assign set_o.y = win_y;
  assign set_o.child = child_sel;

  assign load_valid_o = pop;
  assign load_mask_o = mask_word_i;
  assign emit_valid_o = busy_q && covered && !stall;
  assign emit_child_o = child_sel;
  assign emit_full_o = full;
  assign busy_o = busy_q;

  // Fields the PE does not read: the level (it is LEVEL - 1 by construction), the polygon's
  // identity, colour, edge count and W exponent (carried in win_poly), the input's samples (0).
  logic unused_fields;
  assign unused_fields = ^{win_level, win_id, win_colour, win_edge_count, win_w_exponent,
                           win_start_level, win_start_x, win_start_y,
                           in_data_i[OFF_SAMPLES +: qt_pkg::SAMPLES_W]};

  // ---- Limits (rtl/quadtree/README.md "Parameters") -----------------------------------------------
  if (N_LOG2 < qt_pkg::N_LOG2_MIN || N_LOG2 > qt_pkg::N_LOG2_MAX) begin : g_bad_n_log2
    $error("qt_pe: N_LOG2 must be 4..10");
  end
  if (LEVEL < 1 || LEVEL > N_LOG2) begin : g_bad_level
    $error("qt_pe: LEVEL must be 1..N_LOG2");
  end

endmodule
