// FIFO between quadtree PEs (and before each pixel processor): DEPTH records of WIDTH bits.
//
// Timing contract (cmodel/quadtree/arch_model.hpp, "FIFOs"): a push made in cycle t is visible to
// the consumer from cycle t + 1 (valid_o is a register: count_q > 0), and the producer sees the
// count at the start of the cycle, so a pop in the same cycle does not make room until the next
// (ready_o is a register: count_q < DEPTH). Push and pop in one cycle are allowed.
// clear_i (the frame start) empties it; the stored records are not cleared (never read while
// count_q says they are absent).
module qt_fifo #(
  parameter int WIDTH = 961,
  parameter int DEPTH = 2,
  localparam int CW = $clog2(DEPTH + 1),      // count 0..DEPTH
  localparam int PTRW = DEPTH > 1 ? $clog2(DEPTH) : 1
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             clear_i,
  // Producer: a record is pushed when wvalid_i && wready_o.
  input  logic             wvalid_i,
  input  logic [WIDTH-1:0] wdata_i,
  output logic             wready_o,
  // Consumer: the head record leaves when rvalid_o && rready_i.
  output logic             rvalid_o,
  output logic [WIDTH-1:0] rdata_o,
  input  logic             rready_i
);

  logic [WIDTH-1:0] mem_q [DEPTH];
  logic [PTRW-1:0]  head_q, head_d, tail_q, tail_d;
  logic [CW-1:0]    count_q, count_d;
  logic             push, pop;

  assign wready_o = count_q < CW'(DEPTH);
  assign rvalid_o = count_q != '0;
  assign rdata_o  = mem_q[head_q];
  assign push     = wvalid_i && wready_o;
  assign pop      = rvalid_o && rready_i;

  // Ring pointers (DEPTH need not be a power of two).
  always_comb begin
    head_d  = head_q;
    tail_d  = tail_q;
    count_d = count_q;
    if (pop) begin
      head_d = (head_q == PTRW'(DEPTH - 1)) ? '0 : head_q + 1'b1;
    end
    if (push) begin
      tail_d = (tail_q == PTRW'(DEPTH - 1)) ? '0 : tail_q + 1'b1;
    end
    unique case ({push, pop})
      2'b10:   count_d = count_q + 1'b1;
      2'b01:   count_d = count_q - 1'b1;
      default: count_d = count_q;
    endcase
    if (clear_i) begin
      head_d  = '0;
      tail_d  = '0;
      count_d = '0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      head_q  <= '0;
      tail_q  <= '0;
      count_q <= '0;
    end else begin
      head_q  <= head_d;
      tail_q  <= tail_d;
      count_q <= count_d;
    end
  end

  // Storage: no reset (only entries that count_q marks as present are ever read).
  always_ff @(posedge clk_i) begin
    if (push && !clear_i) begin
      mem_q[tail_q] <= wdata_i;
    end
  end

endmodule
