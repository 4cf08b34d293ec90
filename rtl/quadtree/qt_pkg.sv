// The quadtree RTL's record layout, derived unit counts, parameter defaults and limits
// (rtl/quadtree/README.md "Records", "Parameters"): the one SystemVerilog place they live. Every
// module and the co-simulation wrapper take them from here as qt_pkg::NAME; the C++ mirror is the
// field table of verif/cosim/record_bits.hpp (widths from the hls/ types), checked against the
// Verilated models by cosim.RtlLayout.* and rtl.RtlWindowFields.*. Adding a record field is an edit
// here (its number, its count and width in field_count / field_elem_w) and one there.
//
// Why functions of the parameters rather than packed struct types: the widths of d, f, a, b and
// the gradients are module parameters (the synthesis report runs the coarse format), and a package
// type cannot depend on them. Written in the subset both Debian tools read (rtl/README.md
// "Conventions"): field numbers are localparams (yosys 0.23 does not treat enum items as constants
// inside a constant function), functions assign their name (no `return`), no $bits of a type.
package qt_pkg;

  // A package's constants serve every module, and a lint run whose top is one module uses only
  // some of them (Verilator reports the rest as unused parameters).
  /* verilator lint_off UNUSEDPARAM */

  // ---- Parameter defaults: the fine format at N = 512 (hls QuadFormatFine) ----------------------
  localparam int N_LOG2_DEFAULT = 9;          // raster 2^n (hls raster_log2)
  localparam int FIFO_DEPTH_DEFAULT = 2;      // ArchConfig::fifo_depth
  localparam int NE_DEFAULT = 8;              // kQuadMaxEdges
  localparam int NP_DEFAULT = 2;              // kQuadParams: 0 I, 1 W = 1/Z
  localparam int EW_DEFAULT = 32;             // EdgeValue (d)
  localparam int AW_DEFAULT = 22;             // EdgeGradient (A, B)
  localparam int PW_DEFAULT = 53;             // Fmt::kParamWidth (f)
  localparam int GW_DEFAULT = 38;             // Fmt::kGradientWidth (D, E)
  localparam int G_DEFAULT = 16;              // Fmt::G, fractional bits of parameters
  localparam int LIGHT_COVERS_DEFAULT = 4096; // entries of the light-cover table
  localparam int FOG_CODE_W = 15;             // the e8m7 code of 1/Z: the kernel's fog table address

  // ---- Limits, checked at elaboration ($error) by the modules that take the parameters ---------
  localparam int N_LOG2_MIN = 4;
  localparam int N_LOG2_MAX = 10;             // x, y are COORD_W bits
  localparam int TREE_LEVELS_MAX = 5;         // qt_raster's tree depth (its PE placement)
  localparam int NSET_MAX = 64;               // the mask memory's write loops: the unroll limit of Verilator
  localparam int PARAM_INT_BITS_MIN = 11;     // PW >= G + 11: the pixel lane's intensity clamp
  localparam int LIGHT_INDEX_W = 13;          // light index entries: cover entry + 1
  localparam int LIGHT_COVERS_MAX = (1 << LIGHT_INDEX_W) - 1;

  // ---- Fixed field widths (hls/quadtree/records.hpp) --------------------------------------------
  localparam int LEVEL_W = 4;                 // QuadWindow::level
  localparam int COORD_W = 10;                // QuadWindow::x, y
  localparam int ID_W = 16;                   // QuadPolygon::id
  localparam int OPAQUE_W = 1;
  localparam int COLOURS = 3;                 // R, G, B
  localparam int COLOUR_W = 8;                // SampleLevel
  localparam int COLOUR_BITS = COLOURS * COLOUR_W;   // the colour field, R in the low bits
  localparam int EDGE_COUNT_W = 4;
  localparam int W_EXPONENT_W = 10;
  localparam int SAMPLES_W = 16;              // the pixel record's sample mask, bit 4 dj + di
  localparam int SAMPLE_INDEX_W = 4;          // a sample's number 4 dj + di within its pixel
  localparam int FOG_FACTOR_W = 9;            // a fog table entry f9: 0..256 (256 = all fog)
  localparam int SAMPLE_COLOUR_W = 16;        // a sample's colour channel, 8 fractional bits
  localparam int CHILD_W = 2;                 // child number q = 2 y_b + x_b

  // ---- Record fields, packed LSB first in this order --------------------------------------------
  // A window record is fields F_LEVEL .. F_W_EXPONENT; a pixel record (and every FIFO item) adds
  // F_SAMPLES. The polygon's constants are F_POLY and up, copied unchanged from window to child.
  localparam int F_LEVEL = 0;
  localparam int F_X = 1;
  localparam int F_Y = 2;
  localparam int F_D = 3;                     // [NE] EW, two's complement
  localparam int F_F = 4;                     // [NP] PW, two's complement
  localparam int F_ID = 5;
  localparam int F_OPAQUE = 6;
  localparam int F_COLOUR = 7;                // [COLOURS] COLOUR_W, R first
  localparam int F_EDGE_COUNT = 8;
  localparam int F_A = 9;                     // [NE] AW
  localparam int F_B = 10;                    // [NE] AW
  localparam int F_DP_DI = 11;                // [NP] GW
  localparam int F_DP_DJ = 12;                // [NP] GW
  localparam int F_W_EXPONENT = 13;           // two's complement
  localparam int F_START_LEVEL = 14;          // the start window (hls QuadPolygon::start_level)
  localparam int F_START_X = 15;
  localparam int F_START_Y = 16;
  localparam int F_SAMPLES = 17;
  localparam int F_COUNT = 18;
  localparam int F_POLY = F_ID;

  // Elements of field f (arrays: one per edge, parameter or channel).
  function automatic int field_count(input int f, input int ne, input int np);
    unique case (f)
      F_D, F_A, F_B: field_count = ne;
      F_F, F_DP_DI, F_DP_DJ: field_count = np;
      F_COLOUR: field_count = COLOURS;
      default: field_count = 1;
    endcase
  endfunction

  // Bits of one element of field f.
  function automatic int field_elem_w(input int f, input int ew, input int aw, input int pw,
                                      input int gw);
    unique case (f)
      F_LEVEL, F_START_LEVEL: field_elem_w = LEVEL_W;
      F_X, F_Y, F_START_X, F_START_Y: field_elem_w = COORD_W;
      F_D: field_elem_w = ew;
      F_F: field_elem_w = pw;
      F_ID: field_elem_w = ID_W;
      F_OPAQUE: field_elem_w = OPAQUE_W;
      F_COLOUR: field_elem_w = COLOUR_W;
      F_EDGE_COUNT: field_elem_w = EDGE_COUNT_W;
      F_A, F_B: field_elem_w = aw;
      F_DP_DI, F_DP_DJ: field_elem_w = gw;
      F_W_EXPONENT: field_elem_w = W_EXPONENT_W;
      F_SAMPLES: field_elem_w = SAMPLES_W;
      default: field_elem_w = 0;
    endcase
  endfunction

  // Bits of field f (all its elements).
  function automatic int field_w(input int f, input int ne, input int np, input int ew,
                                 input int aw, input int pw, input int gw);
    field_w = field_count(f, ne, np) * field_elem_w(f, ew, aw, pw, gw);
  endfunction

  // Offset of field f's lowest bit: the fields before it, in order.
  function automatic int field_lo(input int f, input int ne, input int np, input int ew,
                                  input int aw, input int pw, input int gw);
    field_lo = 0;
    for (int g = 0; g < f; g++) begin
      field_lo = field_lo + field_w(g, ne, np, ew, aw, pw, gw);
    end
  endfunction

  // A window record's width (969 for the defaults) and a pixel record's (985).
  function automatic int win_w(input int ne, input int np, input int ew, input int aw,
                               input int pw, input int gw);
    win_w = field_lo(F_SAMPLES, ne, np, ew, aw, pw, gw);
  endfunction
  function automatic int pix_w(input int ne, input int np, input int ew, input int aw,
                               input int pw, input int gw);
    pix_w = field_lo(F_COUNT, ne, np, ew, aw, pw, gw);
  endfunction

  // ---- Mask set request ---------------------------------------------------------------------------
  // Set bit `child` of the mask word (x, y) of level `level` (hls mask_memory_top's arguments).
  // LSB first: child in bits 1:0, y, x, level in the top bits.
  typedef struct packed {
    logic [LEVEL_W-1:0] level;
    logic [COORD_W-1:0] x;
    logic [COORD_W-1:0] y;
    logic [CHILD_W-1:0] child;
  } mask_set_t;
  localparam int MASK_SET_W = LEVEL_W + 2 * COORD_W + CHILD_W;   // $bits(mask_set_t): 26

  // ---- Configuration port (rtl/quadtree/README.md "Configuration port") -------------------------
  localparam int CFG_TARGET_W = 3;
  localparam int CFG_ADDR_W = 32;
  localparam int CFG_DATA_W = 65;             // a light cover sample: {priority 17, R, G, B 16}

  // ---- Units of qt_raster (`kp(n-k)t`) -------------------------------------------------------------
  // k = N_LOG2 - TREE_LEVELS pipeline PEs, then a TREE_LEVELS-level quadtree of PEs (1, 4, 16, ...)
  // with a pixel processor per leaf; one mask set port per PE and per pixel processor.
  function automatic int pipe_levels(input int n_log2, input int tree_levels);
    pipe_levels = n_log2 - tree_levels;
  endfunction
  function automatic int tree_pes(input int depths);   // PEs in the first `depths` tree depths
    tree_pes = ((1 << (2 * depths)) - 1) / 3;
  endfunction
  function automatic int npe(input int n_log2, input int tree_levels);
    npe = pipe_levels(n_log2, tree_levels) + tree_pes(tree_levels);
  endfunction
  function automatic int npix(input int tree_levels);
    npix = 1 << (2 * (tree_levels - 1));
  endfunction
  function automatic int nslot(input int n_log2, input int tree_levels);
    nslot = npe(n_log2, tree_levels) + npix(tree_levels);
  endfunction

  /* verilator lint_on UNUSEDPARAM */

endpackage
