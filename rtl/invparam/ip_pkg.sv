// The inverse-parameter processor's token coding, parameter defaults and limits (SPEC F, seed 002;
// rtl/invparam/README.md): the one SystemVerilog place they live, named as ip_pkg::NAME by
// ip_pe and ip_array. The C++ side is hls/invparam/tokens.hpp (the same codes), the contract.
//
// A token's word 1 carries its 5-bit command in the register's top bits (W-1 .. W-5): kind in
// bits 4:3 (00 Empty, 01 Col, 10 Obj, 11 Pln), bit 1 Az (Pln), bit 0 As (Pln) or First (Col: the
// frame's initialising T_Col, which puts nothing on VT). Colour / id codes (T_Pln word 4, T_Col
// word 2) are a word's low 24 bits.
package ip_pkg;

  // A package's constants serve every module, and a lint run whose top is one module uses only
  // some of them (Verilator reports the rest as unused parameters).
  /* verilator lint_off UNUSEDPARAM */

  // ---- Parameter defaults ---------------------------------------------------------------------
  // W is the register width: the seed's 64-bit word plus 16 guard bits (hls Word<64> =
  // WideInt<80>: 24 integer bits, 56 fractional; hls/invparam/word.hpp kGuardBits).
  localparam int W_DEFAULT = 80;
  localparam int N_PP_DEFAULT = 16;    // PPs in the chain (the seed: one per sample of a column)

  // ---- Limits, checked at elaboration ($error) ------------------------------------------------
  localparam int W_MIN = 26;           // the 24-bit code field below the sign bit, and a sign bit
  localparam int W_MAX = 128;          // hls WideInt's widest register (a seed word of up to 112 bits)
  localparam int N_PP_MAX = 4096;      // hls kMaxSamplesPerColumn

  // ---- Token coding (hls/invparam/tokens.hpp) --------------------------------------------------
  localparam int CMD_W = 5;            // RGI: the command
  localparam int PAR_W = 24;           // RGpar, RGparP: a colour or id code
  localparam int CLOCK_W = 3;          // the control unit's clock within a token, 0 idle, 1..4
  localparam logic [1:0] KIND_EMPTY = 2'b00;
  localparam logic [1:0] KIND_COL = 2'b01;
  localparam logic [1:0] KIND_OBJ = 2'b10;
  localparam logic [1:0] KIND_PLN = 2'b11;
  localparam int CMD_BIT_AZ = 1;       // Pln: Num != 0, the PP works on tau (0: on Den)
  localparam int CMD_BIT_AS = 0;       // Pln: Num < 0, an exit plane
  localparam int CMD_BIT_FIRST = 0;    // Col: the frame's initialising T_Col

  /* verilator lint_on UNUSEDPARAM */

endpackage
