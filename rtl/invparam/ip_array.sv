// The inverse-parameter systolic array of seed 002 (SPEC F): N_PP pixel processors (ip_pe) in a
// chain, one per sample of a column. Tokens enter PP 0 from the host and pass one PP per clock;
// each PP puts its column result on the one VT bus while the column's T_Col passes its clock 2
// (PP k, k + 1 clocks after the T_Col entered PP 0: the stream's padding keeps this one PP at a
// time).
//
// Timing = cmodel/invparam/systolic_array.hpp run_array_frame, cycle for cycle:
//   vt_valid_o = some PP drives VT (combinational on the registers and the host's Ctrl);
//   advance    = vt_ready_i || !vt_valid_o: a result the consumer does not take holds the whole
//                chain (every PP's clock enable), anything else moves it;
//   in_ready_o = advance: the host's word, or its bubble (in_valid_i low), enters PP 0.
// col_done_o: the chain advances and the last PP does a T_Col's clock 4 (a frame of P columns
// ends at its (P + 1)-th pulse, counting the initialising T_Col).
// pp_word_o, pp_start_o, pp_valid_o: every PP's Output and Ctrl (its registers), for the
// co-simulation's token-by-token comparison.
module ip_array #(
  parameter int W = ip_pkg::W_DEFAULT,
  parameter int N_PP = ip_pkg::N_PP_DEFAULT,
  localparam int PW = ip_pkg::PAR_W,
  localparam int KW = N_PP > 1 ? $clog2(N_PP) : 1
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  // Configuration: RGeps and RGnear of every PP, one write.
  input  logic            cfg_valid_i,
  input  logic [W-1:0]    cfg_eps_i,
  input  logic [W-1:0]    cfg_near_i,
  // The host's Input and Ctrl to PP 0.
  input  logic            in_valid_i,
  input  logic            in_start_i,
  input  logic [W-1:0]    in_word_i,
  output logic            in_ready_o,
  // VT: one result per transfer (vt_valid_o && vt_ready_i).
  input  logic            vt_ready_i,
  output logic            vt_valid_o,
  output logic [KW-1:0]   vt_pp_o,
  output logic [PW-1:0]   vt_par_o,
  output logic [W-1:0]    vt_obj_o,
  output logic            col_done_o,
  // Trace: every PP's Output and Ctrl.
  output logic [N_PP*W-1:0] pp_word_o,
  output logic [N_PP-1:0] pp_start_o,
  output logic [N_PP-1:0] pp_valid_o
);

  // Chain: PP k reads stage k (stage 0 = the host), writes stage k + 1.
  logic [(N_PP+1)*W-1:0] chain_word;
  logic [N_PP:0]         chain_start, chain_valid;
  logic [N_PP-1:0]       pp_vt_valid, pp_col_clock4;
  logic [N_PP*PW-1:0]    pp_vt_par;
  logic [N_PP*W-1:0]     pp_vt_obj;
  logic                  advance;

  assign chain_word[0 +: W] = in_word_i;
  assign chain_start[0] = in_start_i;
  assign chain_valid[0] = in_valid_i;

  for (genvar k = 0; k < N_PP; k++) begin : g_pp
    ip_pe #(
      .W(W)
    ) u_pp (
      .clk_i,
      .rst_ni,
      .en_i        (advance),
      .cfg_we_i    (cfg_valid_i),
      .eps_i       (cfg_eps_i),
      .near_i      (cfg_near_i),
      .in_word_i   (chain_word[k*W +: W]),
      .in_start_i  (chain_start[k]),
      .in_valid_i  (chain_valid[k]),
      .out_word_o  (chain_word[(k+1)*W +: W]),
      .out_start_o (chain_start[k+1]),
      .out_valid_o (chain_valid[k+1]),
      .vt_valid_o  (pp_vt_valid[k]),
      .vt_par_o    (pp_vt_par[k*PW +: PW]),
      .vt_obj_o    (pp_vt_obj[k*W +: W]),
      .col_clock4_o(pp_col_clock4[k])
    );
  end

  // The VT bus: the driving PP's result (AND-OR; one driver at a time in a padded stream).
  always_comb begin
    vt_pp_o = '0;
    vt_par_o = '0;
    vt_obj_o = '0;
    for (int k = 0; k < N_PP; k++) begin
      if (pp_vt_valid[k]) begin
        vt_pp_o = vt_pp_o | KW'(k);
        vt_par_o = vt_par_o | pp_vt_par[k*PW +: PW];
        vt_obj_o = vt_obj_o | pp_vt_obj[k*W +: W];
      end
    end
  end

  assign vt_valid_o = |pp_vt_valid;
  assign advance = vt_ready_i || !vt_valid_o;
  assign in_ready_o = advance;
  assign col_done_o = advance && pp_col_clock4[N_PP-1];

  assign pp_word_o = chain_word[(N_PP+1)*W-1:W];
  assign pp_start_o = chain_start[N_PP:1];
  assign pp_valid_o = chain_valid[N_PP:1];

  // ---- Limits (rtl/invparam/README.md) -----------------------------------------------------------
  if (N_PP < 1 || N_PP > ip_pkg::N_PP_MAX) begin : g_bad_n_pp
    $error("ip_array: N_PP must be 1..4096");
  end

endmodule
