// The e8m7 code of 1/Z = v * 2^(w_exponent - G) (hls/quadtree/quadtree_arith.hpp
// QuadFixedArith::inverse_depth_code -> hls/types/zfloat_ops.hpp zfloat_from_aligned with
// e = w_exponent - G + 127 + 7 + kZGuardBits, kZGuardBits = 12), bit for bit:
//   s = min(v, 2^41 - 1), kept as a 42-bit two's complement number (the kernel's Int<42>(s),
//     which wraps: a v below -2^41 keeps only its low 42 bits);
//   s <= 0 -> code 0 (the smallest: infinitely far);
//   msb = position of the leading one of s; exponent = e + msb - (7 + 12);
//   significand = s normalised to 8 bits, rounded to nearest, ties to even (a carry to 256 gives
//     128 and exponent + 1);
//   exponent < 0 -> code 0; exponent > 255 -> 15'h7FFF; else {exponent[7:0], significand[6:0]}.
module qt_e8m7_code #(
  parameter int PW = qt_pkg::PW_DEFAULT,   // the parameter value's width (signed)
  parameter int G = qt_pkg::G_DEFAULT      // its fractional bits
) (
  input  logic [PW-1:0] value_i,        // W = 1/Z in value units, G fractional bits
  input  logic [9:0]    w_exponent_i,   // the polygon's block exponent (signed)
  output logic [14:0]   code_o
);

  // ---- s: the clamped value as Int<42> -----------------------------------------------------------
  logic [41:0] s;
  if (PW > 42) begin : g_clamp
    logic above;   // v >= 2^41
    assign above = !value_i[PW-1] && (|value_i[PW-2:41]);
    assign s = above ? {1'b0, {41{1'b1}}} : value_i[41:0];
  end else if (PW == 42) begin : g_clamp_top
    assign s = value_i;   // |v| < 2^41: the clamp never applies
  end else begin : g_extend
    assign s = 42'($signed(value_i));
  end

  logic        positive;
  logic [40:0] magnitude;
  assign positive = !s[41] && (|s[40:0]);
  assign magnitude = s[40:0];

  // ---- Leading one, normalisation, round to nearest even ------------------------------------------
  logic [5:0]  msb;
  logic [40:0] normalised;   // leading one at bit 40
  logic [7:0]  sig8;
  logic        round_bit, sticky, round_up;
  logic [8:0]  sig9;

  always_comb begin
    msb = '0;
    for (int i = 0; i < 41; i++) begin
      if (magnitude[i]) begin
        msb = 6'(i);
      end
    end
  end
  assign normalised = magnitude << (6'd40 - msb);
  assign sig8 = normalised[40:33];
  assign round_bit = normalised[32];
  assign sticky = |normalised[31:0];
  assign round_up = round_bit && (sticky || sig8[0]);
  assign sig9 = {1'b0, sig8} + {8'd0, round_up};
  // Bit 7 is the hidden one (or 0 after a carry, when bit 8 is set): not part of the code.
  logic unused_hidden_one;
  assign unused_hidden_one = sig9[7];

  // ---- Exponent: w_exponent - G + 146 + msb - 19 (+1 on a rounding carry) -------------------------
  logic signed [12:0] exponent;
  assign exponent = 13'($signed(w_exponent_i)) + 13'(msb) + 13'(127 - G) + 13'(sig9[8]);

  always_comb begin
    if (!positive || exponent < 0) begin
      code_o = 15'h0000;
    end else if (exponent > 13'sd255) begin
      code_o = 15'h7FFF;
    end else begin
      code_o = {exponent[7:0], sig9[8] ? 7'd0 : sig9[6:0]};
    end
  end

endmodule
