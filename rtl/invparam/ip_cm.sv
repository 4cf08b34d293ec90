// The PP's comparator Cm (seed 002, chapter 4): c = A > B, W-bit two's complement (hls
// word_greater), when the control unit enables a comparison; 0 otherwise.
module ip_cm #(
  parameter int W = ip_pkg::W_DEFAULT
) (
  input  logic         enable_i,
  input  logic [W-1:0] a_i,
  input  logic [W-1:0] b_i,
  output logic         c_o
);

  assign c_o = enable_i && ($signed(a_i) > $signed(b_i));

endmodule
