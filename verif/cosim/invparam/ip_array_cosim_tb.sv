// Co-simulation wrapper of ip_array (verification only; not part of the design): W (the register
// width: the seed's word plus 16 guard bits, hls word_bits) and N_PP are public parameters of the
// Verilated model (the class V<prefix>_ip_array_cosim_tb), so that the harness checks them
// against its own; every stimulus input of the array's datapath goes through a register, so that
// no logic of ip_array depends combinationally on a top-level input (Verilator re-evaluates such
// logic on every eval() call) and the design is evaluated once per clock, after the rising edge.
//
// Timing seen by the testbench: the stimulus of cycle c is applied before the rising edge that
// starts cycle c; after that edge the outputs describe cycle c (the array's registers are those at
// the start of cycle c, its inputs the stimulus of cycle c), exactly what ip_array's own ports show
// in cycle c when driven directly, and the next rising edge is cycle c's clock edge. The reset is
// not registered (asynchronous, as ip_array's), nor is the configuration write (cfg_*: they feed
// only the PPs' RGeps and RGnear, no logic reads them combinationally): applied with the stimulus
// of cycle c, it lands at the edge that starts cycle c, so that RGeps and RGnear hold the new
// values from cycle c on, as when the model's registers are written between two frames.
module ip_array_cosim_tb #(
  parameter int W /*verilator public*/ = 80,
  parameter int N_PP /*verilator public*/ = 16,
  localparam int PPW = (N_PP > 1) ? $clog2(N_PP) : 1
) (
  input  logic              clk_i,
  input  logic              rst_ni,
  input  logic              cfg_valid_i,
  input  logic [W-1:0]      cfg_eps_i,
  input  logic [W-1:0]      cfg_near_i,
  input  logic              in_valid_i,
  input  logic              in_start_i,
  input  logic [W-1:0]      in_word_i,
  output logic              in_ready_o,
  input  logic              vt_ready_i,
  output logic              vt_valid_o,
  output logic [PPW-1:0]    vt_pp_o,
  output logic [23:0]       vt_par_o,
  output logic [W-1:0]      vt_obj_o,
  output logic              col_done_o,
  output logic [N_PP*W-1:0] pp_word_o,
  output logic [N_PP-1:0]   pp_start_o,
  output logic [N_PP-1:0]   pp_valid_o
);
  logic         in_valid_q, in_start_q, vt_ready_q;
  logic [W-1:0] in_word_q;

  always_ff @(posedge clk_i) begin
    in_valid_q <= in_valid_i;
    in_start_q <= in_start_i;
    in_word_q  <= in_word_i;
    vt_ready_q <= vt_ready_i;
  end

  ip_array #(.W(W), .N_PP(N_PP)) u_array (
    .clk_i,
    .rst_ni,
    .cfg_valid_i,
    .cfg_eps_i,
    .cfg_near_i,
    .in_valid_i     (in_valid_q),
    .in_start_i     (in_start_q),
    .in_word_i      (in_word_q),
    .in_ready_o,
    .vt_ready_i     (vt_ready_q),
    .vt_valid_o,
    .vt_pp_o,
    .vt_par_o,
    .vt_obj_o,
    .col_done_o,
    .pp_word_o,
    .pp_start_o,
    .pp_valid_o
  );
endmodule
