// The harness's 8N1 UART (--serial): the board file's generic register
// pair (data and status at their offsets, the tx-ready and rx-ready masks)
// on one side, a serial line at `cycles_per_bit` clocks per bit on the
// other. Received bytes wait in a FIFO of 2^FIFO_BITS entries; a byte that
// arrives when it is full is dropped and counted, as a real UART's overrun.
module minrt_serial_uart #(
    parameter int FIFO_BITS = 4
) (
    input  logic        clk,
    input  logic        rst,
    input  logic [15:0] cycles_per_bit,
    input  logic [31:0] data_offset,
    input  logic [31:0] status_offset,
    input  logic [31:0] tx_ready_mask,
    input  logic [31:0] rx_ready_mask,
    // register access: one cycle, always ready
    input  logic        sel,
    input  logic        we,
    input  logic [31:0] offset,   // byte offset of the word inside the UART
    input  logic [31:0] wdata,
    output logic [31:0] rdata,
    output logic [31:0] overruns,
    output logic        tx,
    input  logic        rx
);
  // ---- Transmitter: start bit, 8 data bits LSB first, stop bit ----
  logic [9:0]  tx_shift;   // bits still to send, LSB next
  logic [3:0]  tx_left;    // bits left in tx_shift
  logic [15:0] tx_count;
  wire tx_busy = tx_left != 4'd0;

  // ---- Receiver: the start bit's edge, then the middle of each bit ----
  logic [1:0]  rx_sync;    // two flops against the asynchronous line
  logic        rx_active;
  logic [3:0]  rx_bit;     // 0 = start bit, 1..8 data, 9 stop
  logic [15:0] rx_count;
  logic [7:0]  rx_shift;
  logic [7:0]  fifo [0:(1 << FIFO_BITS) - 1];
  logic [FIFO_BITS:0] head, tail;   // one extra bit tells full from empty
  wire fifo_empty = head == tail;
  wire fifo_full  = (tail - head) == (FIFO_BITS + 1)'(1 << FIFO_BITS);
  wire rx_line = rx_sync[1];

  wire data_hit   = sel && offset == {data_offset[31:2], 2'b00};
  wire status_hit = sel && offset == {status_offset[31:2], 2'b00};
  // Byte-wide registers at an unaligned offset sit in that byte lane.
  wire [4:0] data_lane   = {data_offset[1:0], 3'b000};
  wire [4:0] status_lane = {status_offset[1:0], 3'b000};
  wire [31:0] status = (tx_busy ? 32'd0 : tx_ready_mask) | (fifo_empty ? 32'd0 : rx_ready_mask);

  always_comb begin
    rdata = 32'd0;
    if (status_hit) rdata = status << status_lane;
    else if (data_hit) rdata = {24'd0, fifo_empty ? 8'd0 : fifo[head[FIFO_BITS-1:0]]} << data_lane;
  end

  assign tx = tx_busy ? tx_shift[0] : 1'b1;

  always_ff @(posedge clk) begin
    if (rst) begin
      tx_left <= 4'd0;
      rx_sync <= 2'b11;
      rx_active <= 1'b0;
      head <= '0;
      tail <= '0;
      overruns <= 32'd0;
    end else begin
      rx_sync <= {rx_sync[0], rx};
      // transmit
      if (data_hit && we && !tx_busy) begin
        tx_shift <= {1'b1, 8'(wdata >> data_lane), 1'b0};
        tx_left  <= 4'd10;
        tx_count <= cycles_per_bit - 16'd1;
      end else if (tx_busy) begin
        if (tx_count == 16'd0) begin
          tx_shift <= tx_shift >> 1;
          tx_left  <= tx_left - 4'd1;
          tx_count <= cycles_per_bit - 16'd1;
        end else tx_count <= tx_count - 16'd1;
      end
      // receive
      if (!rx_active) begin
        if (!rx_line) begin
          rx_active <= 1'b1;
          rx_bit    <= 4'd0;
          rx_count  <= (cycles_per_bit >> 1) - 16'd1;   // to the middle of the start bit
        end
      end else if (rx_count != 16'd0) rx_count <= rx_count - 16'd1;
      else begin
        rx_count <= cycles_per_bit - 16'd1;
        rx_bit <= rx_bit + 4'd1;
        if (rx_bit == 4'd0 && rx_line) rx_active <= 1'b0;  // a glitch, not a start bit
        else if (rx_bit >= 4'd1 && rx_bit <= 4'd8) rx_shift <= {rx_line, rx_shift[7:1]};
        else if (rx_bit == 4'd9) begin
          rx_active <= 1'b0;
          if (rx_line) begin   // a good stop bit
            if (fifo_full) overruns <= overruns + 32'd1;
            else begin
              fifo[tail[FIFO_BITS-1:0]] <= rx_shift;
              tail <= tail + 1'b1;
            end
          end
        end
      end
      // a data read takes the oldest byte
      if (data_hit && !we && !fifo_empty) head <= head + 1'b1;
    end
  end
endmodule
