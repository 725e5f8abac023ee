// One AXI4-Lite master (a core's) onto one valid/ready port of the harness:
// a write (address and data both offered) or a read becomes one request,
// held until ready; the response then waits on bvalid/rvalid until the
// master takes it. Writes go first when both are offered. OKAY responses
// only: the harness reports bad addresses itself.
module minrt_axil_bridge (
    input  logic        clk, rst,
    input  logic [31:0] awaddr,  input logic awvalid, output logic awready,
    input  logic [31:0] wdata,   input logic [3:0] wstrb, input logic wvalid, output logic wready,
    output logic [1:0]  bresp,   output logic bvalid, input logic bready,
    input  logic [31:0] araddr,  input logic arvalid, output logic arready,
    output logic [31:0] rdata,   output logic [1:0] rresp, output logic rvalid, input logic rready,
    output logic        valid,   input logic ready,
    output logic [31:0] addr,
    output logic        we,
    output logic [3:0]  mask,
    output logic [31:0] wdata_o, input logic [31:0] rdata_i
);
  typedef enum logic [1:0] { IDLE, WRITE_RESP, READ_RESP } state_t;
  state_t state;
  wire write = awvalid && wvalid;
  assign valid   = state == IDLE && (write || arvalid);
  assign we      = write;
  assign addr    = write ? awaddr : araddr;
  assign mask    = write ? wstrb : 4'b1111;
  assign wdata_o = wdata;
  assign awready = state == IDLE && write && ready;
  assign wready  = awready;
  assign arready = state == IDLE && !write && arvalid && ready;
  assign bvalid  = state == WRITE_RESP;
  assign rvalid  = state == READ_RESP;
  assign bresp   = 2'b00;
  assign rresp   = 2'b00;
  always_ff @(posedge clk) begin
    if (rst) state <= IDLE;
    else case (state)
      IDLE: if (awready) state <= WRITE_RESP;
            else if (arready) begin rdata <= rdata_i; state <= READ_RESP; end
      WRITE_RESP: if (bready) state <= IDLE;
      READ_RESP:  if (rready) state <= IDLE;
      default: state <= IDLE;
    endcase
  end
endmodule
