// The fields of a window record (rtl/quadtree/README.md, "Records"; hls/quadtree/records.hpp
// QuadWindow), as named slices at the offsets of qt_pkg's layout (wiring only): the PE and the
// pixel processor read their fields through this module. It also checks the record widths' limits,
// since both instantiate it with their parameters.
module qt_window_fields #(
  parameter int NE = qt_pkg::NE_DEFAULT,
  parameter int NP = qt_pkg::NP_DEFAULT,
  parameter int EW = qt_pkg::EW_DEFAULT,
  parameter int AW = qt_pkg::AW_DEFAULT,
  parameter int PW = qt_pkg::PW_DEFAULT,
  parameter int GW = qt_pkg::GW_DEFAULT,
  localparam int WIN_W = qt_pkg::win_w(NE, NP, EW, AW, PW, GW),
  // The polygon's constants: everything from id up, copied unchanged from window to child.
  localparam int OFF_POLY = qt_pkg::field_lo(qt_pkg::F_POLY, NE, NP, EW, AW, PW, GW),
  localparam int POLY_W = WIN_W - OFF_POLY
) (
  input  logic [WIN_W-1:0]                window_i,
  output logic [qt_pkg::LEVEL_W-1:0]      level_o,
  output logic [qt_pkg::COORD_W-1:0]      x_o,
  output logic [qt_pkg::COORD_W-1:0]      y_o,
  output logic [NE*EW-1:0]                d_o,
  output logic [NP*PW-1:0]                f_o,
  output logic [POLY_W-1:0]               poly_o,
  output logic [qt_pkg::ID_W-1:0]         id_o,
  output logic                            opaque_o,
  output logic [qt_pkg::COLOUR_BITS-1:0]  colour_o,   // R in the low bits
  output logic [qt_pkg::EDGE_COUNT_W-1:0] edge_count_o,
  output logic [NE*AW-1:0]                a_o,
  output logic [NE*AW-1:0]                b_o,
  output logic [NP*GW-1:0]                dp_di_o,
  output logic [NP*GW-1:0]                dp_dj_o,
  output logic [qt_pkg::W_EXPONENT_W-1:0] w_exponent_o,
  output logic [qt_pkg::LEVEL_W-1:0]      start_level_o,   // the start window
  output logic [qt_pkg::COORD_W-1:0]      start_x_o,
  output logic [qt_pkg::COORD_W-1:0]      start_y_o
);

  // Field f's offset and width in this configuration.
  localparam int OFF_LEVEL = qt_pkg::field_lo(qt_pkg::F_LEVEL, NE, NP, EW, AW, PW, GW);
  localparam int OFF_X = qt_pkg::field_lo(qt_pkg::F_X, NE, NP, EW, AW, PW, GW);
  localparam int OFF_Y = qt_pkg::field_lo(qt_pkg::F_Y, NE, NP, EW, AW, PW, GW);
  localparam int OFF_D = qt_pkg::field_lo(qt_pkg::F_D, NE, NP, EW, AW, PW, GW);
  localparam int OFF_F = qt_pkg::field_lo(qt_pkg::F_F, NE, NP, EW, AW, PW, GW);
  localparam int OFF_ID = qt_pkg::field_lo(qt_pkg::F_ID, NE, NP, EW, AW, PW, GW);
  localparam int OFF_OPAQUE = qt_pkg::field_lo(qt_pkg::F_OPAQUE, NE, NP, EW, AW, PW, GW);
  localparam int OFF_COLOUR = qt_pkg::field_lo(qt_pkg::F_COLOUR, NE, NP, EW, AW, PW, GW);
  localparam int OFF_EDGES = qt_pkg::field_lo(qt_pkg::F_EDGE_COUNT, NE, NP, EW, AW, PW, GW);
  localparam int OFF_A = qt_pkg::field_lo(qt_pkg::F_A, NE, NP, EW, AW, PW, GW);
  localparam int OFF_B = qt_pkg::field_lo(qt_pkg::F_B, NE, NP, EW, AW, PW, GW);
  localparam int OFF_DI = qt_pkg::field_lo(qt_pkg::F_DP_DI, NE, NP, EW, AW, PW, GW);
  localparam int OFF_DJ = qt_pkg::field_lo(qt_pkg::F_DP_DJ, NE, NP, EW, AW, PW, GW);
  localparam int OFF_WEXP = qt_pkg::field_lo(qt_pkg::F_W_EXPONENT, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_LEVEL = qt_pkg::field_lo(qt_pkg::F_START_LEVEL, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_X = qt_pkg::field_lo(qt_pkg::F_START_X, NE, NP, EW, AW, PW, GW);
  localparam int OFF_START_Y = qt_pkg::field_lo(qt_pkg::F_START_Y, NE, NP, EW, AW, PW, GW);

  assign level_o      = window_i[OFF_LEVEL +: qt_pkg::LEVEL_W];
  assign x_o          = window_i[OFF_X +: qt_pkg::COORD_W];
  assign y_o          = window_i[OFF_Y +: qt_pkg::COORD_W];
  assign d_o          = window_i[OFF_D +: NE * EW];
  assign f_o          = window_i[OFF_F +: NP * PW];
  assign poly_o       = window_i[OFF_POLY +: POLY_W];
  assign id_o         = window_i[OFF_ID +: qt_pkg::ID_W];
  assign opaque_o     = window_i[OFF_OPAQUE];
  assign colour_o     = window_i[OFF_COLOUR +: qt_pkg::COLOUR_BITS];
  assign edge_count_o = window_i[OFF_EDGES +: qt_pkg::EDGE_COUNT_W];
  assign a_o          = window_i[OFF_A +: NE * AW];
  assign b_o          = window_i[OFF_B +: NE * AW];
  assign dp_di_o      = window_i[OFF_DI +: NP * GW];
  assign dp_dj_o      = window_i[OFF_DJ +: NP * GW];
  assign w_exponent_o = window_i[OFF_WEXP +: qt_pkg::W_EXPONENT_W];
  assign start_level_o = window_i[OFF_START_LEVEL +: qt_pkg::LEVEL_W];
  assign start_x_o    = window_i[OFF_START_X +: qt_pkg::COORD_W];
  assign start_y_o    = window_i[OFF_START_Y +: qt_pkg::COORD_W];

  // ---- Limits of the record widths (rtl/quadtree/README.md "Parameters") ------------------------
  // edge_count must count the edges; d is formed from A and B sign-extended and shifted (EW > AW);
  // f adds gradients sign-extended to PW bits (GW <= PW).
  if (NE < 1 || NE >= (1 << qt_pkg::EDGE_COUNT_W)) begin : g_bad_ne
    $error("qt_window_fields: NE must be 1..15 (edge_count is 4 bits)");
  end
  if (NP < 1) begin : g_bad_np
    $error("qt_window_fields: NP must be at least 1");
  end
  if (EW <= AW) begin : g_bad_ew
    $error("qt_window_fields: EW must exceed AW (d holds A and B shifted)");
  end
  if (GW > PW) begin : g_bad_gw
    $error("qt_window_fields: GW must not exceed PW (f adds the gradients)");
  end

endmodule
