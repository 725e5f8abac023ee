// Port-only stand-ins for the example wrappers' cores, so that the
// examples are checked by Verilator's lint (test rtl.examples_lint).
module my_wb_core (
    input  logic clk_i, rst_i,
    output logic ibus_cyc_o, ibus_stb_o, output logic [31:0] ibus_adr_o, output logic [3:0] ibus_sel_o,
    input  logic ibus_ack_i, input logic [31:0] ibus_dat_i,
    output logic dbus_cyc_o, dbus_stb_o, output logic [31:0] dbus_adr_o, output logic dbus_we_o,
    output logic [3:0] dbus_sel_o, output logic [31:0] dbus_dat_o,
    input  logic dbus_ack_i, input logic [31:0] dbus_dat_i);
  assign {ibus_cyc_o, ibus_stb_o, ibus_adr_o, ibus_sel_o} = '0;
  assign {dbus_cyc_o, dbus_stb_o, dbus_adr_o, dbus_we_o, dbus_sel_o, dbus_dat_o} = '0;
  wire unused = &{1'b0, clk_i, rst_i, ibus_ack_i, ibus_dat_i, dbus_ack_i, dbus_dat_i};
endmodule

module my_axil_core (
    input  logic aclk, aresetn,
    output logic [31:0] m_axi_awaddr, output logic m_axi_awvalid, input logic m_axi_awready,
    output logic [31:0] m_axi_wdata, output logic [3:0] m_axi_wstrb, output logic m_axi_wvalid,
    input  logic m_axi_wready,
    input  logic [1:0] m_axi_bresp, input logic m_axi_bvalid, output logic m_axi_bready,
    output logic [31:0] m_axi_araddr, output logic m_axi_arvalid, input logic m_axi_arready,
    input  logic [31:0] m_axi_rdata, input logic [1:0] m_axi_rresp, input logic m_axi_rvalid,
    output logic m_axi_rready);
  assign {m_axi_awaddr, m_axi_awvalid, m_axi_wdata, m_axi_wstrb, m_axi_wvalid, m_axi_bready} = '0;
  assign {m_axi_araddr, m_axi_arvalid, m_axi_rready} = '0;
  wire unused = &{1'b0, aclk, aresetn, m_axi_awready, m_axi_wready, m_axi_bresp, m_axi_bvalid,
                  m_axi_arready, m_axi_rdata, m_axi_rresp, m_axi_rvalid};
endmodule
