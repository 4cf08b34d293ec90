// The inverse-parameter pixel processor (PP) of seed 002, chapter 4 (SPEC F): one sample of a
// column; N_PP of them in a chain make the systolic array (ip_array).
//
// Arithmetic and timing = hls/invparam/pixel_processor.hpp pp_clock, one call per enabled clock,
// bit for bit (that header's comment lists the seed's clock-by-clock register transfers and the
// choices where the seed is silent). W is the register width: W-bit words are two's complement,
// the seed's word of W - 16 bits (8 integer) below 16 guard bits (hls Word<W - 16> =
// WideInt<W>, hls/invparam/word.hpp); every comparison is signed.
//
// Datapath as the seed draws it: one adder SM (Input + RGh in a T_Pln's clock 3, else Input
// passes; flags z, s of its sum), one comparator Cm (c = A > B, its operands chosen per clock),
// the registers RGres, RGh, RGtin, RGtout, RGobj, RGeps, RGnear (W bits), RGpar, RGparP (24
// bits), RGI (5 bits), the flip-flops Tz, Ts, Tc; the control unit's clock counter and the Ctrl
// flip-flops (start and valid, delayed with RGres). The seed's nine tri-state buffers are the
// multiplexers in front of Cm and of the registers. RGnear (ours, issue 29) is 1/near, the near
// plane: Obj clock 3 compares RGtin with it where the seed has its constant MAX on bus A; its reset
// value MAX is the seed's PP.
//
// Ctrl: start marks word 1 of a token (it restarts the counter), valid marks a word at all. An
// invalid word (a bubble) changes no register but the delayed Ctrl lines. en_i is the array's
// clock enable (the VT handshake holds the whole chain): with en_i low nothing changes.
module ip_pe #(
  parameter int W = ip_pkg::W_DEFAULT,
  localparam int PW = ip_pkg::PAR_W,
  localparam int CW = ip_pkg::CMD_W,
  localparam int KW = ip_pkg::CLOCK_W
) (
  input  logic          clk_i,
  input  logic          rst_ni,
  input  logic          en_i,          // the array advances this clock
  // Configuration, one write: RGeps, the tolerance of the Den test (negative), and RGnear.
  input  logic          cfg_we_i,
  input  logic [W-1:0]  eps_i,
  input  logic [W-1:0]  near_i,
  // Input and Ctrl from the PP above (or the host).
  input  logic [W-1:0]  in_word_i,
  input  logic          in_start_i,
  input  logic          in_valid_i,
  // Output and Ctrl to the PP below: the registers, one clock behind Input.
  output logic [W-1:0]  out_word_o,
  output logic          out_start_o,
  output logic          out_valid_o,
  // VT: the finished column's result, while a T_Col's clock 2 passes (combinational).
  output logic          vt_valid_o,
  output logic [PW-1:0] vt_par_o,
  output logic [W-1:0]  vt_obj_o,
  // This clock is a T_Col's clock 4 (combinational; the array's column-done of its last PP).
  output logic          col_clock4_o
);

  localparam logic [W-1:0] WORD_MAX = {1'b0, {(W - 1){1'b1}}};  // the largest code (tau = MAX)

  logic [W-1:0]  rg_res_q, rg_res_d, rg_h_q, rg_h_d, rg_tin_q, rg_tin_d;
  logic [W-1:0]  rg_tout_q, rg_tout_d, rg_obj_q, rg_obj_d, rg_eps_q, rg_near_q;
  logic [PW-1:0] rg_par_q, rg_par_d, rg_parp_q, rg_parp_d;
  logic [CW-1:0] rg_i_q, rg_i_d;
  logic          tz_q, tz_d, ts_q, ts_d, tc_q, tc_d, tctrl_q, tvalid_q;
  logic [KW-1:0] clock_q;

  // ---- Control unit: the clock within the token (pp_next_clock) ------------------------------------
  logic [1:0] kind;
  logic       cmd_az, cmd_as, cmd_first;
  assign kind = rg_i_q[CW-1 -: 2];
  assign cmd_az = rg_i_q[ip_pkg::CMD_BIT_AZ];
  assign cmd_as = rg_i_q[ip_pkg::CMD_BIT_AS];
  assign cmd_first = rg_i_q[ip_pkg::CMD_BIT_FIRST];

  logic [KW-1:0] next_clock;
  always_comb begin
    if (in_start_i) begin
      next_clock = KW'(1);
    end else if (clock_q >= KW'(1) && clock_q <= KW'(3) && kind != ip_pkg::KIND_EMPTY) begin
      next_clock = clock_q + KW'(1);
    end else begin
      next_clock = '0;
    end
  end

  // The operation of this clock (valid words only).
  logic col2, col3, pln2, pln3, pln4, obj2, obj3, obj4;
  assign col2 = in_valid_i && kind == ip_pkg::KIND_COL && next_clock == KW'(2);
  assign col3 = in_valid_i && kind == ip_pkg::KIND_COL && next_clock == KW'(3);
  assign pln2 = in_valid_i && kind == ip_pkg::KIND_PLN && next_clock == KW'(2);
  assign pln3 = in_valid_i && kind == ip_pkg::KIND_PLN && next_clock == KW'(3);
  assign pln4 = in_valid_i && kind == ip_pkg::KIND_PLN && next_clock == KW'(4);
  assign obj2 = in_valid_i && kind == ip_pkg::KIND_OBJ && next_clock == KW'(2);
  assign obj3 = in_valid_i && kind == ip_pkg::KIND_OBJ && next_clock == KW'(3);
  assign obj4 = in_valid_i && kind == ip_pkg::KIND_OBJ && next_clock == KW'(4);

  // ---- SM: Input + RGh in a T_Pln's clock 3, else Input passes ------------------------------------
  logic [W-1:0] sum;
  logic         sum_nonzero, sum_negative;
  ip_sm #(
    .W(W)
  ) u_sm (
    .a_i  (in_word_i),
    .b_i  (pln3 ? rg_h_q : '0),
    .sum_o(sum),
    .z_o  (sum_nonzero),
    .s_o  (sum_negative)
  );

  // ---- Cm: c = A > B (signed), operands by the clock (pp_pln_decide, pp_obj_clock) ---------------
  // Pln clock 4: RGres against RGeps (Az = 0), RGtout (an exit plane) or RGtin (an entry plane);
  // Obj clock 2: RGtin > RGtout; clock 3: RGnear > RGtin; clock 4: RGtin > RGobj.
  logic [W-1:0] cm_a, cm_b;
  logic         cm_enable, c;
  ip_cm #(
    .W(W)
  ) u_cm (
    .enable_i(cm_enable),
    .a_i     (cm_a),
    .b_i     (cm_b),
    .c_o     (c)
  );
  always_comb begin
    cm_a = rg_res_q;
    cm_b = rg_tin_q;
    cm_enable = 1'b0;
    if (pln4) begin
      cm_a = rg_res_q;
      cm_b = !cmd_az ? rg_eps_q : (cmd_as ? rg_tout_q : rg_tin_q);
      cm_enable = !cmd_az || !ts_q;  // Az with s: no comparison (a plane behind the eye)
    end else if (obj2) begin
      cm_a = rg_tin_q;
      cm_b = rg_tout_q;
      cm_enable = 1'b1;
    end else if (obj3) begin
      cm_a = rg_near_q;
      cm_b = rg_tin_q;
      cm_enable = tc_q;
    end else if (obj4) begin
      cm_a = rg_tin_q;
      cm_b = rg_obj_q;
      cm_enable = tc_q;
    end
  end

  // ---- Register transfers (pp_col_clock, pp_pln_clock, pp_pln_decide, pp_obj_clock) --------------
  always_comb begin
    rg_res_d = sum;
    rg_h_d = pln2 ? in_word_i : rg_h_q;
    rg_tin_d = rg_tin_q;
    rg_tout_d = rg_tout_q;
    rg_obj_d = rg_obj_q;
    rg_par_d = rg_par_q;
    rg_parp_d = rg_parp_q;
    rg_i_d = next_clock == KW'(1) ? in_word_i[W-1 -: CW] : rg_i_q;
    tz_d = pln3 ? sum_nonzero : tz_q;
    ts_d = pln3 ? sum_negative : ts_q;
    tc_d = c;
    if (col2) begin
      rg_parp_d = in_word_i[PW-1:0];
    end
    if (col3) begin
      rg_tin_d = WORD_MAX;
      rg_tout_d = '0;
      rg_obj_d = '0;
      rg_par_d = rg_parp_q;
    end
    if (pln4) begin
      if (!cmd_az) begin
        if (!c) rg_tin_d = '0;             // the eye in the plane and Den <= eps: a miss
      end else if (cmd_as) begin
        if (c) rg_tout_d = rg_res_q;       // an exit plane ahead: the nearest exit so far
      end else if (!ts_q) begin
        if (!c) begin                      // an entry plane ahead, not nearer than RGtin
          rg_tin_d = rg_res_q;
          rg_parp_d = in_word_i[PW-1:0];
        end
      end else begin
        rg_tin_d = '0;                     // the ray leaves the half-space behind the eye
      end
    end
    if (obj4) begin
      if (c) begin                         // hit, and nearer than the visible face so far
        rg_obj_d = rg_tin_q;
        rg_par_d = rg_parp_q;
      end
      rg_tin_d = WORD_MAX;
      rg_tout_d = '0;
    end
  end

  // A valid word clocks every register; a bubble only the delayed Ctrl lines.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rg_res_q <= '0;
      rg_h_q <= '0;
      rg_tin_q <= WORD_MAX;
      rg_tout_q <= '0;
      rg_obj_q <= '0;
      rg_par_q <= '0;
      rg_parp_q <= '0;
      rg_i_q <= '0;
      tz_q <= 1'b0;
      ts_q <= 1'b0;
      tc_q <= 1'b0;
      clock_q <= '0;
      tctrl_q <= 1'b0;
      tvalid_q <= 1'b0;
    end else if (en_i) begin
      if (in_valid_i) begin
        rg_res_q <= rg_res_d;
        rg_h_q <= rg_h_d;
        rg_tin_q <= rg_tin_d;
        rg_tout_q <= rg_tout_d;
        rg_obj_q <= rg_obj_d;
        rg_par_q <= rg_par_d;
        rg_parp_q <= rg_parp_d;
        rg_i_q <= rg_i_d;
        tz_q <= tz_d;
        ts_q <= ts_d;
        tc_q <= tc_d;
        clock_q <= next_clock;
      end
      tctrl_q <= in_valid_i && in_start_i;
      tvalid_q <= in_valid_i;
    end
  end

  // RGeps and RGnear: configuration registers, written together whatever en_i (the seed does not
  // say how RGeps is loaded). After the reset RGnear is MAX: no near plane, the seed's PP.
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      rg_eps_q <= '0;
      rg_near_q <= WORD_MAX;
    end else if (cfg_we_i) begin
      rg_eps_q <= eps_i;
      rg_near_q <= near_i;
    end
  end

  assign out_word_o = rg_res_q;
  assign out_start_o = tctrl_q;
  assign out_valid_o = tvalid_q;
  assign vt_valid_o = col2 && !cmd_first;
  assign vt_par_o = rg_par_q;
  assign vt_obj_o = rg_obj_q;
  assign col_clock4_o = in_valid_i && kind == ip_pkg::KIND_COL && next_clock == KW'(4);

  // Flag z is the seed's flip-flop; no rule of its clock 4 reads it (hls pixel_processor.hpp).
  logic unused_tz;
  assign unused_tz = tz_q;

  // ---- Limits (rtl/invparam/README.md) -----------------------------------------------------------
  if (W < ip_pkg::W_MIN || W > ip_pkg::W_MAX) begin : g_bad_w
    $error("ip_pe: W must be 26..128");
  end

endmodule
