// The fields of a window record (rtl/README.md, "Records"; hls/quadtree/records.hpp QuadWindow),
// packed LSB first in this order:
//   level 4 | x 10 | y 10 | d[NE] EW | f[NP] PW | id 16 | opaque 1 | colour[3] 8 | edge_count 4 |
//   a[NE] AW | b[NE] AW | dp_di[NP] GW | dp_dj[NP] GW | w_exponent 10
// The one place the RTL spells the layout out: the PE and the pixel processor read their fields
// through this module, and the PE packs a child as {poly_o, f, d, y, x, level}.
`include "qt_records.svh"

module qt_window_fields #(
  parameter int NE = 8,
  parameter int NP = 2,
  parameter int EW = 32,
  parameter int AW = 22,
  parameter int PW = 53,
  parameter int GW = 38,
  localparam int WIN_W = `QT_WIN_W(NE, NP, EW, AW, PW, GW),
  // The polygon's constants: everything from id up, copied unchanged from window to child.
  localparam int OFF_POLY = `QT_WIN_POLY_OFFSET(NE, NP, EW, PW),
  localparam int POLY_W = WIN_W - OFF_POLY
) (
  input  logic [WIN_W-1:0]   window_i,
  output logic [3:0]         level_o,
  output logic [9:0]         x_o,
  output logic [9:0]         y_o,
  output logic [NE*EW-1:0]   d_o,
  output logic [NP*PW-1:0]   f_o,
  output logic [POLY_W-1:0]  poly_o,
  output logic [15:0]        id_o,
  output logic               opaque_o,
  output logic [23:0]        colour_o,       // R in bits 7:0
  output logic [3:0]         edge_count_o,
  output logic [NE*AW-1:0]   a_o,
  output logic [NE*AW-1:0]   b_o,
  output logic [NP*GW-1:0]   dp_di_o,
  output logic [NP*GW-1:0]   dp_dj_o,
  output logic [9:0]         w_exponent_o
);

  localparam int OFF_D = 24;
  localparam int OFF_F = OFF_D + NE * EW;
  localparam int OFF_ID = OFF_F + NP * PW;
  localparam int OFF_OPAQUE = OFF_ID + 16;
  localparam int OFF_COLOUR = OFF_OPAQUE + 1;
  localparam int OFF_EDGES = OFF_COLOUR + 24;
  localparam int OFF_A = OFF_EDGES + 4;
  localparam int OFF_B = OFF_A + NE * AW;
  localparam int OFF_DI = OFF_B + NE * AW;
  localparam int OFF_DJ = OFF_DI + NP * GW;
  localparam int OFF_WEXP = OFF_DJ + NP * GW;

  assign level_o      = window_i[3:0];
  assign x_o          = window_i[13:4];
  assign y_o          = window_i[23:14];
  assign d_o          = window_i[OFF_D +: NE * EW];
  assign f_o          = window_i[OFF_F +: NP * PW];
  assign poly_o       = window_i[OFF_POLY +: POLY_W];
  assign id_o         = window_i[OFF_ID +: 16];
  assign opaque_o     = window_i[OFF_OPAQUE];
  assign colour_o     = window_i[OFF_COLOUR +: 24];
  assign edge_count_o = window_i[OFF_EDGES +: 4];
  assign a_o          = window_i[OFF_A +: NE * AW];
  assign b_o          = window_i[OFF_B +: NE * AW];
  assign dp_di_o      = window_i[OFF_DI +: NP * GW];
  assign dp_dj_o      = window_i[OFF_DJ +: NP * GW];
  assign w_exponent_o = window_i[OFF_WEXP +: 10];

endmodule
