// Record widths of the quadtree RTL (rtl/README.md "Records"; hls/quadtree/records.hpp): the one
// place the width formulas live, so that every module and the co-simulation wrapper agree.
//   window: level 4 | x 10 | y 10 | d[NE] EW | f[NP] PW, then the polygon's constants
//           id 16 | opaque 1 | colour[3] 8 | edge_count 4 | a[NE] AW | b[NE] AW |
//           dp_di[NP] GW | dp_dj[NP] GW | w_exponent 10 (45 + 2 NE AW + 2 NP GW + 10 bits);
//   pixel record: a window and its 16 sample bits.
// The field offsets are in qt_window_fields.sv.
`ifndef QT_RECORDS_SVH
`define QT_RECORDS_SVH
`define QT_WIN_POLY_OFFSET(NE, NP, EW, PW) (24 + (NE) * (EW) + (NP) * (PW))
`define QT_WIN_W(NE, NP, EW, AW, PW, GW) (`QT_WIN_POLY_OFFSET(NE, NP, EW, PW) + 45 + 2 * (NE) * (AW) + 2 * (NP) * (GW) + 10)
`define QT_PIX_W(NE, NP, EW, AW, PW, GW) (`QT_WIN_W(NE, NP, EW, AW, PW, GW) + 16)
`endif
