// Multilevel priority masks (SPEC E, seed 004; hls/quadtree/mask_memory.hpp): a 4-bit word per
// window of levels 0..N_LOG2-1, one bit per child (bit 2 y_b + x_b). Word (x, y) of level l is
// child {y[0], x[0]} of word (x >> 1, y >> 1) of level l - 1.
//
// Timing contract: reads (NRD combinational ports) see the words as they were at the start of the
// cycle; the cycle's set requests (NSET ports) and their upward closure (a word that becomes
// 4'hF, and was not, sets its bit in its parent) are written at the clock edge. The closure of a
// set of requests does not depend on their order (OR is commutative, "all four set" monotone), so
// every request's chain is followed level by level, each word merging every bit that any chain
// sets in it this cycle.
//
// Storage: one array per level (4^l words) plus a valid bit per word. clear_i (the frame start)
// clears the valid bits in one cycle; a word whose valid bit is clear reads as 0.
module qt_mask_memory #(
  parameter int N_LOG2 = qt_pkg::N_LOG2_DEFAULT,
  parameter int NRD = 1,
  parameter int NSET = 1,
  localparam int LW = qt_pkg::LEVEL_W,
  localparam int CW = qt_pkg::COORD_W,
  localparam int SW = qt_pkg::MASK_SET_W
) (
  input  logic               clk_i,
  input  logic               clear_i,
  // Read ports: level (0..N_LOG2-1), address -> the word.
  input  logic [NRD*LW-1:0]  rd_level_i,
  input  logic [NRD*CW-1:0]  rd_x_i,
  input  logic [NRD*CW-1:0]  rd_y_i,
  output logic [NRD*4-1:0]   rd_mask_o,
  // Set ports: a qt_pkg::mask_set_t each.
  input  logic [NSET-1:0]    set_valid_i,
  input  logic [NSET*SW-1:0] set_i
);

  // ---- Each request's chain up the levels (from the request alone) ------------------------------
  // Flat vectors indexed by k = l * NSET + s (level l, request s): reach[k]: request s is at or
  // below level l; then ax/ay[k] is the word of level l on its path and abit[k] the bit the chain
  // would set in it.
  localparam int NK = N_LOG2 * NSET;
  logic [NK-1:0]    reach;
  logic [NK-1:0]    own_level;   // l is request s's own level
  logic [NK*CW-1:0] ax, ay;
  logic [NK*2-1:0]  abit;
  // old_word[k]: that word at the start of the cycle (read by level l's block below).
  logic [NK*4-1:0]  old_word;
  // act[k]: the chain sets abit in word (ax, ay) of level l this cycle; merged[k]: that word after
  // the edge (every bit set in it this cycle).
  logic [NK-1:0]    act;
  logic [NK*4-1:0]  merged;

  // The request's address as plain vectors: yosys 0.23 builds a variable bit select of a struct
  // member as a shift of the whole struct (some 5,000 more cells here).
  qt_pkg::mask_set_t req;
  logic [CW-1:0] req_x, req_y;
  logic [LW-1:0] up;   // levels from the request to l
  always_comb begin
    reach = '0;
    ax = '0;
    ay = '0;
    abit = '0;
    own_level = '0;
    req = '0;
    req_x = '0;
    req_y = '0;
    up = '0;
    // Only a valid request has a chain (the rest stay 0: read by nothing that matters, and a
    // simulator skips them).
    for (int l = 0; l < N_LOG2; l++) begin
      for (int s = 0; s < NSET; s++) begin
        if (set_valid_i[s]) begin
          req = set_i[s*SW +: SW];
          req_x = req.x;
          req_y = req.y;
          up = req.level - LW'(l);
          reach[l*NSET+s] = req.level >= LW'(l);
          own_level[l*NSET+s] = req.level == LW'(l);
          ax[(l*NSET+s)*CW +: CW] = req_x >> up;
          ay[(l*NSET+s)*CW +: CW] = req_y >> up;
          if (up == LW'(0)) begin
            abit[(l*NSET+s)*2 +: 2] = req.child;
          end else begin
            // The word one level down is child {y[0], x[0]} of this one.
            abit[(l*NSET+s)*2 +: 2] = {req_y[up - LW'(1)], req_x[up - LW'(1)]};
          end
        end
      end
    end
  end

  // ---- The closure: level by level from the finest ----------------------------------------------
  logic [3:0] set_bits;   // the bits every active chain sets in one chain's word
  // Written so that a simulator does the work only where there is some (a cycle without a set
  // request, or a chain that stopped, skips its loops; the logic is the same): the merge of a
  // word only for an active chain (an inactive one's word is unchanged), the whole closure only
  // when some request is valid.
  always_comb begin
    act = '0;
    merged = old_word;
    set_bits = '0;
    if (|set_valid_i) begin
      for (int l = N_LOG2 - 1; l >= 0; l--) begin
        for (int s = 0; s < NSET; s++) begin
          if (reach[l*NSET+s]) begin
            if (own_level[l*NSET+s]) begin
              act[l*NSET+s] = 1'b1;   // the request itself
            end else if (l + 1 < N_LOG2) begin
              // The word one level down became full this cycle (and was not already).
              act[l*NSET+s] = act[(l+1)*NSET+s] && merged[((l+1)*NSET+s)*4 +: 4] == 4'hF &&
                              old_word[((l+1)*NSET+s)*4 +: 4] != 4'hF;
            end
          end
        end
        for (int s = 0; s < NSET; s++) begin
          if (act[l*NSET+s]) begin
            set_bits = '0;
            for (int t = 0; t < NSET; t++) begin
              if (act[l*NSET+t] && ax[(l*NSET+t)*CW +: CW] == ax[(l*NSET+s)*CW +: CW] &&
                  ay[(l*NSET+t)*CW +: CW] == ay[(l*NSET+s)*CW +: CW]) begin
                set_bits = set_bits | (4'b0001 << abit[(l*NSET+t)*2 +: 2]);
              end
            end
            merged[(l*NSET+s)*4 +: 4] = old_word[(l*NSET+s)*4 +: 4] | set_bits;
          end
        end
      end
    end
  end

  // ---- Storage, one block per level -------------------------------------------------------------
  logic [N_LOG2*NRD*4-1:0] rd_word;   // [(l * NRD + r) * 4 +: 4]: port r's address at level l

  for (genvar l = 0; l < N_LOG2; l++) begin : g_level
    if (l == 0) begin : g_root
      logic [3:0] word_q;
      for (genvar s = 0; s < NSET; s++) begin : g_old
        assign old_word[s*4 +: 4] = word_q;
      end
      for (genvar r = 0; r < NRD; r++) begin : g_rd
        assign rd_word[r*4 +: 4] = word_q;
      end
      always_ff @(posedge clk_i) begin
        if (clear_i) begin
          word_q <= '0;
        end else begin
          for (int s = 0; s < NSET; s++) begin
            if (act[s]) begin
              word_q <= merged[s*4 +: 4];
            end
          end
        end
      end
    end else begin : g_words
      localparam int WORDS = 1 << (2 * l);
      logic [3:0]       words_q [WORDS];
      logic [WORDS-1:0] valid_q;

      for (genvar s = 0; s < NSET; s++) begin : g_old
        logic [2*l-1:0] idx;
        assign idx = {ay[(l*NSET+s)*CW +: l], ax[(l*NSET+s)*CW +: l]};
        assign old_word[(l*NSET+s)*4 +: 4] = valid_q[idx] ? words_q[idx] : 4'h0;
      end
      for (genvar r = 0; r < NRD; r++) begin : g_rd
        logic [2*l-1:0] idx;
        assign idx = {rd_y_i[r*CW +: l], rd_x_i[r*CW +: l]};
        assign rd_word[(l*NRD+r)*4 +: 4] = valid_q[idx] ? words_q[idx] : 4'h0;
      end

      always_ff @(posedge clk_i) begin
        if (clear_i) begin
          valid_q <= WORDS'(0);
        end else begin
          for (int s = 0; s < NSET; s++) begin
            if (act[l*NSET+s]) begin
              valid_q[{ay[(l*NSET+s)*CW +: l], ax[(l*NSET+s)*CW +: l]}] <= 1'b1;
            end
          end
        end
      end
      always_ff @(posedge clk_i) begin
        for (int s = 0; s < NSET; s++) begin
          if (act[l*NSET+s] && !clear_i) begin
            words_q[{ay[(l*NSET+s)*CW +: l], ax[(l*NSET+s)*CW +: l]}] <= merged[(l*NSET+s)*4 +: 4];
          end
        end
      end
    end
  end

  // Address bits above level N_LOG2 - 1's width are not read.
  logic unused_rd_addr;
  assign unused_rd_addr = ^{rd_x_i, rd_y_i};

  for (genvar r = 0; r < NRD; r++) begin : g_rd_port
    logic [LW-1:0] level;
    assign level = rd_level_i[r*LW +: LW];
    assign rd_mask_o[r*4 +: 4] = (32'(level) < N_LOG2) ? rd_word[(32'(level)*NRD+r)*4 +: 4] : 4'h0;
  end

  // ---- Limits (rtl/quadtree/README.md "Parameters") -----------------------------------------------
  // The write loops over the set ports are unrolled by Verilator only up to its loop limit.
  if (NSET < 1 || NSET > qt_pkg::NSET_MAX) begin : g_bad_nset
    $error("qt_mask_memory: NSET must be 1..64 (one set port per PE and pixel processor)");
  end

endmodule
