// The PP's adder SM (seed 002, chapter 4): sum = a + b in W-bit two's complement (wrapping, no
// carry out: hls word_add), and its flags z (sum != 0) and s (sum < 0).
module ip_sm #(
  parameter int W = ip_pkg::W_DEFAULT
) (
  input  logic [W-1:0] a_i,
  input  logic [W-1:0] b_i,
  output logic [W-1:0] sum_o,
  output logic         z_o,
  output logic         s_o
);

  assign sum_o = a_i + b_i;
  assign z_o = sum_o != '0;
  assign s_o = sum_o[W-1];

endmodule
