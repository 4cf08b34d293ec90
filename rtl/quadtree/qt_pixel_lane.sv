// One sample lane of the pixel processor: the colour of sample (di, dj) of a pixel record, bit
// for bit as hls/quadtree/pixel_processor.hpp quad_pixel_process computes it for a fresh sample
// that no light shows on (the processor picks the light's colour instead where one does):
//   vI = f[0] + dp_di[0] di + dp_dj[0] dj, vW likewise with parameter 1 (PW bits, wrapping:
//     QuadFixedArith::at_sample);
//   I = vI saturated to [0, 256 2^G] (PlaneFixedArith::intensity, UFixed<9+G, 9>: same fractional
//     bits, no rounding; 256 is full intensity);
//   code = e8m7 code of 1/Z from vW (qt_e8m7_code); the processor looks it up in the fog table
//     and returns the factor f9 (0..256; any 9-bit value is handled as the kernel would);
//   per channel (hls/pixel/sample_colour.hpp):
//     shade = min((colour I + 2^(G-1)) >> G, 65535)                     (colour x I, 8 frac bits)
//     mix   = clamp((shade (256 - f9) + (fog f9 << 8) + 128) >> 8, 0, 65535)   (fog_mix, floor)
// The sample's position is an input (tied to a constant per lane) rather than a parameter, so that
// the 16 lanes are one module (one synthesis, one row of the synthesis report).
module qt_pixel_lane #(
  parameter int PW = qt_pkg::PW_DEFAULT,
  parameter int GW = qt_pkg::GW_DEFAULT,
  parameter int G = qt_pkg::G_DEFAULT
) (
  input  logic [qt_pkg::SAMPLE_INDEX_W-1:0] sample_i,   // 4 dj + di
  input  logic [PW-1:0] f_intensity_i,     // f[0] at the pixel's top-left sample
  input  logic [PW-1:0] f_depth_i,         // f[1]
  input  logic [GW-1:0] di_intensity_i,    // dp_di[0]
  input  logic [GW-1:0] dj_intensity_i,    // dp_dj[0]
  input  logic [GW-1:0] di_depth_i,        // dp_di[1]
  input  logic [GW-1:0] dj_depth_i,        // dp_dj[1]
  input  logic [qt_pkg::W_EXPONENT_W-1:0] w_exponent_i,
  input  logic [qt_pkg::COLOUR_BITS-1:0] colour_i,      // R in the low COLOUR_W bits
  input  logic [qt_pkg::COLOUR_BITS-1:0] fog_colour_i,
  output logic [qt_pkg::FOG_CODE_W-1:0] code_o,         // e8m7 code of 1/Z: the fog table's address
  input  logic [qt_pkg::FOG_FACTOR_W-1:0] fog_factor_i, // the fog table's entry at code_o
  output logic [qt_pkg::COLOURS*qt_pkg::SAMPLE_COLOUR_W-1:0] colour_o  // three samples, R first
);

  localparam int IW = 9 + G;   // intensity: 9 integer (0..256), G fractional bits
  localparam logic [IW-1:0] IntensityFull = IW'(256) << G;

  // ---- The parameters at the sample ---------------------------------------------------------------
  logic signed [PW-1:0] v_intensity, v_depth;
  // g * k for k = 0..3 (the sample's offset): two shifted, gated copies of g.
  function automatic logic [PW-1:0] times_offset(input logic [GW-1:0] g, input logic [1:0] k);
    logic [PW-1:0] g_ext;
    g_ext = PW'($signed(g));
    times_offset = (k[0] ? g_ext : '0) + (k[1] ? (g_ext << 1) : '0);
  endfunction
  assign v_intensity = f_intensity_i + times_offset(di_intensity_i, sample_i[1:0]) +
                       times_offset(dj_intensity_i, sample_i[3:2]);
  assign v_depth = f_depth_i + times_offset(di_depth_i, sample_i[1:0]) + times_offset(dj_depth_i, sample_i[3:2]);

  // ---- Intensity: saturated to [0, 256 2^G] -------------------------------------------------------
  logic [IW-1:0] intensity;
  always_comb begin
    if (v_intensity[PW-1]) begin
      intensity = '0;
    end else if (|v_intensity[PW-2:IW] || v_intensity[IW-1:0] > IntensityFull) begin
      intensity = IntensityFull;
    end else begin
      intensity = v_intensity[IW-1:0];
    end
  end

  // ---- 1/Z -> e8m7 code (the fog table's address) ------------------------------------------------
  qt_e8m7_code #(
    .PW(PW),
    .G (G)
  ) u_code (
    .value_i      (v_depth),
    .w_exponent_i (w_exponent_i),
    .code_o       (code_o)
  );

  // ---- Colour x I, then fog ------------------------------------------------------------------------
  // Widths of hls/pixel/sample_colour.hpp's fog mix: f9 scales by 2^MixShift (256 = all fog), so
  // 256 - f9 needs FOG_FACTOR_W + 1 bits and a sign; shade (256 - f9) is SW + 1 by KeepW bits signed;
  // adding fog f9 2^MixShift and the rounding half needs two more bits; >>> MixShift leaves the rest.
  localparam int CW = qt_pkg::COLOUR_W;
  localparam int SW = qt_pkg::SAMPLE_COLOUR_W;
  localparam int MixShift = qt_pkg::FOG_FACTOR_W - 1;       // 8
  localparam int KeepW = qt_pkg::FOG_FACTOR_W + 2;          // 11
  localparam int FogTermW = CW + qt_pkg::FOG_FACTOR_W;      // 17
  localparam int KeptW = SW + 1 + KeepW;                    // 28
  localparam int MixW = KeptW + 2;                          // 30
  localparam int RoundedW = MixW - MixShift;                // 22
  logic signed [KeepW-1:0] keep;   // 256 - f9
  assign keep = KeepW'(1 << MixShift) - KeepW'($signed({2'b00, fog_factor_i}));

  for (genvar c = 0; c < qt_pkg::COLOURS; c++) begin : g_channel
    logic [IW+CW:0]          lit;        // colour x I + half an LSB of the 8-fraction-bit result
    logic [IW+CW-G:0]        shade_wide;
    logic [SW-1:0]           shade;
    logic signed [MixW-1:0]  mixed;      // shade (256 - f9) + fog f9 2^8, 16 fractional bits
    logic signed [RoundedW-1:0] rounded;
    logic [FogTermW-1:0]     fog_term;   // fog f9, 8 fractional bits
    logic [IW+CW-1:0]        product;    // colour x I: CW x IW bits
    assign product = colour_i[c*CW +: CW] * intensity;
    assign lit = (IW+CW+1)'(product) + (IW+CW+1)'(1 << (G - 1));
    assign shade_wide = (IW+CW+1-G)'(lit >> G);   // the G dropped bits: rounded half up above
    assign shade = (|shade_wide[IW+CW-G:SW]) ? '1 : shade_wide[SW-1:0];
    logic signed [KeptW-1:0] kept;       // shade (256 - f9): SW + 1 x KeepW bits signed
    assign fog_term = fog_colour_i[c*CW +: CW] * fog_factor_i;
    assign kept = $signed({1'b0, shade}) * keep;
    assign mixed = MixW'(kept) + MixW'({fog_term, {MixShift{1'b0}}});
    assign rounded = RoundedW'((mixed + MixW'(1 << (MixShift - 1))) >>> MixShift);
    always_comb begin
      if (rounded < 0) begin
        colour_o[c*SW +: SW] = '0;
      end else if (rounded > RoundedW'((1 << SW) - 1)) begin
        colour_o[c*SW +: SW] = '1;
      end else begin
        colour_o[c*SW +: SW] = rounded[SW-1:0];
      end
    end
  end

  // ---- Limits (rtl/quadtree/README.md "Parameters"): the intensity clamp reads v[PW-2:IW] -------
  if (PW < G + qt_pkg::PARAM_INT_BITS_MIN) begin : g_bad_pw
    $error("qt_pixel_lane: PW must be at least G + 11");
  end

endmodule
