// Top of the Verilator model: the CPU behind the harness's CPU port
// (module minrt_cpu: the reference core's wrapper or yours, docs/rtl.md)
// and, with --serial, the harness's 8N1 UART in front of the data port.
// Memory, the register-level UART and the halt device are the C++
// harness's (rtl/harness/harness.cpp), reached through the ports below.
module minrt_rtl_top (
    input  logic        clk,
    input  logic        rst,
    // configuration from the board file, constant during a run
    input  logic [1:0]  serial_mode,   // 0 register-level, 1 harness UART, 2 the CPU's own pins
    input  logic [31:0] uart_base,
    input  logic [31:0] uart_size,
    input  logic [15:0] cycles_per_bit,
    input  logic [31:0] uart_data_offset,
    input  logic [31:0] uart_status_offset,
    input  logic [31:0] uart_tx_ready_mask,
    input  logic [31:0] uart_rx_ready_mask,
    // the CPU's ports, as the C++ side serves them
    output logic        imem_valid,
    input  logic        imem_ready,
    output logic [31:0] imem_addr,
    input  logic [31:0] imem_rdata,
    output logic        dmem_valid,
    input  logic        dmem_ready,
    output logic [31:0] dmem_addr,
    output logic        dmem_we,
    output logic [3:0]  dmem_wstrb,
    output logic [31:0] dmem_wdata,
    input  logic [31:0] dmem_rdata,
    output logic        rvfi_valid,
    output logic [31:0] rvfi_pc_rdata,
    output logic [31:0] rvfi_insn,
    output logic [4:0]  rvfi_rd_addr,
    output logic [31:0] rvfi_rd_wdata,
    output logic [31:0] rvfi_mem_addr,
    output logic [3:0]  rvfi_mem_rmask,
    output logic [3:0]  rvfi_mem_wmask,
    output logic [31:0] rvfi_mem_rdata,
    output logic [31:0] rvfi_mem_wdata,
    // the serial line (modes 1 and 2)
    output logic        ser_tx,
    input  logic        ser_rx,
    output logic [31:0] ser_overruns,
    output logic        uart_touched   // the CPU has read the harness UART (mode 1)
);
  logic        cpu_dvalid, cpu_dready;
  logic [31:0] cpu_drdata, uart_rdata;
  logic        cpu_tx, uart_tx_line;

  minrt_cpu cpu (
      .clk, .rst,
      .imem_valid, .imem_ready, .imem_addr, .imem_rdata,
      .dmem_valid(cpu_dvalid), .dmem_ready(cpu_dready), .dmem_addr, .dmem_we,
      .dmem_wstrb, .dmem_wdata, .dmem_rdata(cpu_drdata),
      .rvfi_valid, .rvfi_pc_rdata, .rvfi_insn, .rvfi_rd_addr, .rvfi_rd_wdata,
      .rvfi_mem_addr, .rvfi_mem_rmask, .rvfi_mem_wmask, .rvfi_mem_rdata, .rvfi_mem_wdata,
      .uart_tx(cpu_tx), .uart_rx(ser_rx));

  wire uart_hit = serial_mode == 2'd1 && cpu_dvalid && dmem_addr - uart_base < uart_size;
  minrt_serial_uart uart (
      .clk, .rst, .cycles_per_bit,
      .data_offset(uart_data_offset), .status_offset(uart_status_offset),
      .tx_ready_mask(uart_tx_ready_mask), .rx_ready_mask(uart_rx_ready_mask),
      .sel(uart_hit), .we(dmem_we), .offset(dmem_addr - uart_base), .wdata(dmem_wdata),
      .rdata(uart_rdata), .overruns(ser_overruns), .tx(uart_tx_line), .rx(ser_rx));

  // The host starts sending once the firmware is up and polls its UART, as
  // a host does with a board that was reset long before.
  always_ff @(posedge clk) begin
    if (rst) uart_touched <= 1'b0;
    else if (uart_hit && !dmem_we) uart_touched <= 1'b1;
  end

  assign dmem_valid = cpu_dvalid && !uart_hit;
  assign cpu_dready = uart_hit ? 1'b1 : dmem_ready;
  assign cpu_drdata = uart_hit ? uart_rdata : dmem_rdata;
  assign ser_tx = serial_mode == 2'd2 ? cpu_tx : uart_tx_line;
endmodule
