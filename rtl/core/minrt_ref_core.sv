// The project's reference RV32IM core: multi-cycle, one instruction at a
// time, written to be read. No CSRs, no traps, no interrupts: the firmware
// built for boards/rtl-reference.board (zicsr = no) needs none of them.
//
//   FETCH  ask the instruction port for the word at pc
//   EXEC   decode, read registers, compute; most instructions finish here
//   MEM    loads and stores: one access on the data port
//   DIV    divide and remainder: 32 shift-subtract steps
//
// Every port is the harness's CPU port (docs/rtl.md "The CPU port"):
// valid/ready memory requests held until ready, and the retire port, which
// pulses rvfi_valid for one cycle after each instruction completes.
//
// Test builds (MINRT_REF_FAULTS defined) read +minrt_fault=N at start and
// then behave wrongly on purpose, for the lock-step tests:
//   1  sltu/sltiu compare signed
//   2  lbu sign-extends its byte
//   3  a load's result reaches the register file one instruction late,
//      so the next instruction reads the old value (a missing load-use
//      interlock)
module minrt_ref_core #(
    parameter logic [31:0] RESET_PC = 32'h0
) (
    input  logic        clk,
    input  logic        rst,

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
    output logic [31:0] rvfi_mem_wdata
);

  typedef enum logic [1:0] { FETCH, EXEC, MEM, DIV } state_t;
  state_t state;

  logic [31:0] pc, ir;
  logic [31:0] regs [1:31];

`ifdef MINRT_REF_FAULTS
  int fault = 0;
  initial begin
    if (!$value$plusargs("minrt_fault=%d", fault)) fault = 0;
  end
  // Fault 3: the late register write of the previous load.
  logic        late_pending;
  logic [4:0]  late_rd;
  logic [31:0] late_value;
`endif

  // ---- Decode (from ir, valid in EXEC, MEM and DIV) ----
  wire [6:0] opcode = ir[6:0];
  wire [4:0] rd     = ir[11:7];
  wire [2:0] funct3 = ir[14:12];
  wire [4:0] rs1    = ir[19:15];
  wire [4:0] rs2    = ir[24:20];
  wire [6:0] funct7 = ir[31:25];

  wire [31:0] imm_i = {{20{ir[31]}}, ir[31:20]};
  wire [31:0] imm_s = {{20{ir[31]}}, ir[31:25], ir[11:7]};
  wire [31:0] imm_b = {{19{ir[31]}}, ir[31], ir[7], ir[30:25], ir[11:8], 1'b0};
  wire [31:0] imm_u = {ir[31:12], 12'b0};
  wire [31:0] imm_j = {{11{ir[31]}}, ir[31], ir[19:12], ir[20], ir[30:21], 1'b0};

  localparam logic [6:0] OP_LUI    = 7'b0110111;
  localparam logic [6:0] OP_AUIPC  = 7'b0010111;
  localparam logic [6:0] OP_JAL    = 7'b1101111;
  localparam logic [6:0] OP_JALR   = 7'b1100111;
  localparam logic [6:0] OP_BRANCH = 7'b1100011;
  localparam logic [6:0] OP_LOAD   = 7'b0000011;
  localparam logic [6:0] OP_STORE  = 7'b0100011;
  localparam logic [6:0] OP_IMM    = 7'b0010011;
  localparam logic [6:0] OP_REG    = 7'b0110011;

  wire is_muldiv = opcode == OP_REG && funct7 == 7'b0000001;
  wire is_div    = is_muldiv && funct3[2];  // div, divu, rem, remu

  // Register reads; x0 reads 0.
  wire [31:0] a = rs1 == 5'd0 ? 32'd0 : regs[rs1];
  wire [31:0] b = rs2 == 5'd0 ? 32'd0 : regs[rs2];

  // ---- ALU: register-register and register-immediate forms ----
  wire        imm_form = opcode == OP_IMM;
  wire [31:0] alu_b    = imm_form ? imm_i : b;
  wire [4:0]  shamt    = alu_b[4:0];
  // sub and sra need funct7[5]; for immediates only srai has it.
  wire        alt      = funct7[5] && (!imm_form || funct3 == 3'b101);

  logic ltu_signed;  // fault 1: sltu compares as signed
  always_comb begin
    ltu_signed = 1'b0;
`ifdef MINRT_REF_FAULTS
    ltu_signed = fault == 1;
`endif
  end

  logic [31:0] alu;
  always_comb begin
    case (funct3)
      3'b000: alu = alt ? a - alu_b : a + alu_b;
      3'b001: alu = a << shamt;
      3'b010: alu = {31'd0, $signed(a) < $signed(alu_b)};
      3'b011: alu = ltu_signed ? {31'd0, $signed(a) < $signed(alu_b)} : {31'd0, a < alu_b};
      3'b100: alu = a ^ alu_b;
      3'b101: alu = alt ? 32'($signed(a) >>> shamt) : a >> shamt;
      3'b110: alu = a | alu_b;
      default: alu = a & alu_b;
    endcase
  end

  // ---- Multiply: one cycle, the upper half by sign-extending to 64 bits ----
  wire [63:0] a_s = {{32{a[31]}}, a};
  wire [63:0] b_s = {{32{b[31]}}, b};
  wire [63:0] a_u = {32'd0, a};
  wire [63:0] b_u = {32'd0, b};
  logic [31:0] mul;
  always_comb begin
    case (funct3[1:0])
      2'b00: mul = a * b;                 // mul
      2'b01: mul = 32'((a_s * b_s) >> 32); // mulh
      2'b10: mul = 32'((a_s * b_u) >> 32); // mulhsu
      default: mul = 32'((a_u * b_u) >> 32); // mulhu
    endcase
  end

  // ---- Branches ----
  logic take;
  always_comb begin
    case (funct3)
      3'b000: take = a == b;
      3'b001: take = a != b;
      3'b100: take = $signed(a) < $signed(b);
      3'b101: take = $signed(a) >= $signed(b);
      3'b110: take = a < b;
      3'b111: take = a >= b;
      default: take = 1'b0;
    endcase
  end

  // ---- Memory access: address, byte lanes, store data aligned to lanes ----
  wire [31:0] mem_addr = a + (opcode == OP_STORE ? imm_s : imm_i);
  wire [1:0]  lane     = mem_addr[1:0];
  logic [3:0]  mem_mask;
  logic [31:0] store_data;
  always_comb begin
    case (funct3[1:0])
      2'b00: begin mem_mask = 4'b0001 << lane; store_data = {4{b[7:0]}}; end
      2'b01: begin mem_mask = 4'b0011 << lane; store_data = {2{b[15:0]}}; end
      default: begin mem_mask = 4'b1111; store_data = b; end
    endcase
  end

  // Load result from the data port's word.
  wire [31:0] shifted = dmem_rdata >> {lane, 3'b000};
  logic byte_signed;
  always_comb begin
    byte_signed = !funct3[2];  // lb sign-extends, lbu does not
`ifdef MINRT_REF_FAULTS
    if (fault == 2) byte_signed = 1'b1;
`endif
  end
  logic [31:0] load_value;
  always_comb begin
    case (funct3[1:0])
      2'b00: load_value = {{24{byte_signed & shifted[7]}}, shifted[7:0]};
      2'b01: load_value = {{16{!funct3[2] & shifted[15]}}, shifted[15:0]};
      default: load_value = shifted;
    endcase
  end

  // ---- Division: restoring, one quotient bit per cycle on magnitudes ----
  logic [31:0] quot, rem_acc, divisor;
  logic [5:0]  div_step;
  logic        neg_quot, neg_rem;
  wire         div_signed = !funct3[0];
  wire [32:0]  trial = {rem_acc[31:0], quot[31]} - {1'b0, divisor};

  // Division by zero and signed overflow have fixed results (ISA spec,
  // M extension): no steps needed.
  logic [31:0] div_special;
  logic        div_is_special;
  always_comb begin
    div_is_special = 1'b1;
    if (b == 32'd0) div_special = funct3[1] ? a : 32'hffffffff;
    else if (div_signed && a == 32'h80000000 && b == 32'hffffffff) div_special = funct3[1] ? 32'd0 : a;
    else begin div_is_special = 1'b0; div_special = 32'd0; end
  end

  // ---- Next pc and the value written to rd in EXEC ----
  logic [31:0] next_pc, exec_value;
  logic        writes_rd;
  always_comb begin
    next_pc = pc + 4;
    exec_value = 32'd0;
    writes_rd = 1'b1;
    case (opcode)
      OP_LUI:   exec_value = imm_u;
      OP_AUIPC: exec_value = pc + imm_u;
      OP_JAL:   begin exec_value = pc + 4; next_pc = pc + imm_j; end
      OP_JALR:  begin exec_value = pc + 4; next_pc = (a + imm_i) & ~32'd1; end
      OP_BRANCH: begin writes_rd = 1'b0; if (take) next_pc = pc + imm_b; end
      OP_IMM:   exec_value = alu;
      OP_REG:   exec_value = is_muldiv ? mul : alu;
      default:  writes_rd = 1'b0;  // fence, ecall, ebreak: no effect here
    endcase
  end

  assign imem_valid = state == FETCH && !rst;
  assign imem_addr  = pc;
  assign dmem_valid = state == MEM;
  assign dmem_addr  = {mem_addr[31:2], 2'b00};
  assign dmem_we    = opcode == OP_STORE;
  assign dmem_wstrb = mem_mask;
  assign dmem_wdata = store_data;

  // Writes rd (never x0) and reports the instruction on the retire port.
  task automatic retire(input logic write, input logic [31:0] value, input logic [31:0] npc);
    if (write && rd != 5'd0) regs[rd] <= value;
    rvfi_valid     <= 1'b1;
    rvfi_pc_rdata  <= pc;
    rvfi_insn      <= ir;
    rvfi_rd_addr   <= write ? rd : 5'd0;
    rvfi_rd_wdata  <= write && rd != 5'd0 ? value : 32'd0;
    pc             <= npc;
    state          <= FETCH;
  endtask

  always_ff @(posedge clk) begin
    rvfi_valid <= 1'b0;
    if (rst) begin
      state <= FETCH;
      pc <= RESET_PC;
`ifdef MINRT_REF_FAULTS
      late_pending <= 1'b0;
`endif
    end else begin
`ifdef MINRT_REF_FAULTS
      // The held-back load result lands at the end of the next
      // instruction's EXEC cycle, after that instruction read its operands
      // (its own write to the same register, below, still wins).
      if (fault == 3 && late_pending && state == EXEC) begin
        if (late_rd != 5'd0) regs[late_rd] <= late_value;
        late_pending <= 1'b0;
      end
`endif
      case (state)
        FETCH: if (imem_ready) begin
          ir <= imem_rdata;
          state <= EXEC;
        end

        EXEC: begin
          rvfi_mem_rmask <= 4'd0;
          rvfi_mem_wmask <= 4'd0;
          rvfi_mem_addr  <= 32'd0;
          rvfi_mem_rdata <= 32'd0;
          rvfi_mem_wdata <= 32'd0;
          if (opcode == OP_LOAD || opcode == OP_STORE) state <= MEM;
          else if (is_div) begin
            if (div_is_special) retire(1'b1, div_special, pc + 4);
            else begin
              // Magnitudes; the signs are applied after the last step.
              quot     <= div_signed && a[31] ? -a : a;
              divisor  <= div_signed && b[31] ? -b : b;
              rem_acc  <= 32'd0;
              neg_quot <= div_signed && (a[31] ^ b[31]);
              neg_rem  <= div_signed && a[31];
              div_step <= 6'd0;
              state    <= DIV;
            end
          end else retire(writes_rd, exec_value, next_pc);
        end

        MEM: if (dmem_ready) begin
          rvfi_mem_addr <= dmem_addr;
          if (opcode == OP_LOAD) begin
            rvfi_mem_rmask <= mem_mask;
            rvfi_mem_rdata <= dmem_rdata;
`ifdef MINRT_REF_FAULTS
            if (fault == 3) begin
              // Reported as written, but held back one instruction.
              retire(1'b0, 32'd0, pc + 4);
              rvfi_rd_addr  <= rd;
              rvfi_rd_wdata <= rd != 5'd0 ? load_value : 32'd0;
              late_pending  <= 1'b1;
              late_rd       <= rd;
              late_value    <= load_value;
            end else
`endif
            retire(1'b1, load_value, pc + 4);
          end else begin
            rvfi_mem_wmask <= mem_mask;
            rvfi_mem_wdata <= store_data;
            retire(1'b0, 32'd0, pc + 4);
          end
        end

        DIV: begin
          // One step: shift the next dividend bit into the remainder and
          // subtract the divisor when it fits.
          quot <= {quot[30:0], !trial[32]};
          rem_acc <= trial[32] ? {rem_acc[30:0], quot[31]} : trial[31:0];
          div_step <= div_step + 6'd1;
          if (div_step == 6'd31) begin
            // quot and rem_acc are one step behind: finish with this step's values.
            if (funct3[1]) begin
              logic [31:0] r;
              r = trial[32] ? {rem_acc[30:0], quot[31]} : trial[31:0];
              retire(1'b1, neg_rem ? -r : r, pc + 4);
            end else begin
              logic [31:0] q;
              q = {quot[30:0], !trial[32]};
              retire(1'b1, neg_quot ? -q : q, pc + 4);
            end
          end
        end

        default: state <= FETCH;
      endcase
    end
  end

endmodule
