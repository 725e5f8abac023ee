// Example wrapper (docs/rtl.md): a core with two Wishbone B4 classic
// masters (instruction and data, byte addresses, 32-bit data) behind the
// harness's CPU port. Wishbone's cycle is the port's request: cyc & stb is
// valid, ack is ready, sel the byte mask. `my_wb_core` stands for your core.
module minrt_cpu (
    input  logic        clk, rst,
    output logic        imem_valid, input logic imem_ready,
    output logic [31:0] imem_addr,  input logic [31:0] imem_rdata,
    output logic        dmem_valid, input logic dmem_ready,
    output logic [31:0] dmem_addr,
    output logic        dmem_we,
    output logic [3:0]  dmem_wstrb,
    output logic [31:0] dmem_wdata, input logic [31:0] dmem_rdata,
    output logic        rvfi_valid,
    output logic [31:0] rvfi_pc_rdata, rvfi_insn,
    output logic [4:0]  rvfi_rd_addr,
    output logic [31:0] rvfi_rd_wdata, rvfi_mem_addr,
    output logic [3:0]  rvfi_mem_rmask, rvfi_mem_wmask,
    output logic [31:0] rvfi_mem_rdata, rvfi_mem_wdata,
    output logic        uart_tx, input logic uart_rx
);
  logic ibus_cyc, ibus_stb, dbus_cyc, dbus_stb;
  logic [3:0] ibus_sel;
  my_wb_core core (
      .clk_i(clk), .rst_i(rst),
      .ibus_cyc_o(ibus_cyc), .ibus_stb_o(ibus_stb), .ibus_adr_o(imem_addr), .ibus_sel_o(ibus_sel),
      .ibus_ack_i(imem_ready), .ibus_dat_i(imem_rdata),
      .dbus_cyc_o(dbus_cyc), .dbus_stb_o(dbus_stb), .dbus_adr_o(dmem_addr), .dbus_we_o(dmem_we),
      .dbus_sel_o(dmem_wstrb), .dbus_dat_o(dmem_wdata), .dbus_ack_i(dmem_ready), .dbus_dat_i(dmem_rdata));
  assign imem_valid = ibus_cyc & ibus_stb;
  assign dmem_valid = dbus_cyc & dbus_stb;
  assign rvfi_valid = 1'b0;  // no retire port: runs work, lock-step does not
  assign {rvfi_pc_rdata, rvfi_insn, rvfi_rd_addr, rvfi_rd_wdata, rvfi_mem_addr} = '0;
  assign {rvfi_mem_rmask, rvfi_mem_wmask, rvfi_mem_rdata, rvfi_mem_wdata} = '0;
  assign uart_tx = 1'b1;
  wire unused = &{1'b0, ibus_sel, uart_rx};
endmodule
