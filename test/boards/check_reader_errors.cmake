# Malformed board files: the reader must stop with the file, the line where
# it applies and the reason.
#   cmake -DSOURCE_DIR=<repo> -DWORK=<dir> -P check_reader_errors.cmake
file(MAKE_DIRECTORY "${WORK}")
set(_good "name = t\nisa = rv32im\nreset = 0x0\nram_base = 0\nram_size = 0x1000\nuart = ns16550\nuart_base = 0x10000000\nhalt = loop\n")

# check(NAME TEXT EXPECTED-REGEX): NAME.board holding TEXT is refused with a
# message matching EXPECTED-REGEX (accepted when it is empty).
set(_failures 0)
function(check name text expected)
  set(f "${WORK}/${name}.board")
  file(WRITE "${f}" "${text}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -DBOARD=${f} -DOUT=${WORK}/${name}.h
                          -P "${SOURCE_DIR}/cmake/minrt_board.cmake"
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  string(REGEX REPLACE "[ \n]+" " " err "${err}")
  if(rc EQUAL 0 AND NOT expected STREQUAL "")
    message(SEND_ERROR "${name}: accepted, expected an error matching '${expected}'")
  elseif(NOT rc EQUAL 0 AND expected STREQUAL "")
    message(SEND_ERROR "${name}: refused: ${err}")
  elseif(NOT err MATCHES "${expected}")
    message(SEND_ERROR "${name}: error '${err}' does not match '${expected}'")
  else()
    message(STATUS "${name}: ok")
  endif()
endfunction()

check(good "${_good}" "")
check(comments "# a comment\n\n${_good}zicsr = yes # trailing\n" "")
check(unknown_key "${_good}baud = 9600\n" "unknown_key.board:9: unknown key 'baud'")
check(real_board_keys "${_good}zifencei = yes\nclock_hz = 50000000\nafter_image = halt\nwait_polls = 0x100\n" "")
check(bad_zifencei "${_good}zifencei = maybe\n" "bad_zifencei.board:9: zifencei must be yes or no, got 'maybe'")
check(bad_after_image "${_good}after_image = stop\n" "bad_after_image.board:9: after_image must be serve or halt, got 'stop'")
check(bad_clock "${_good}clock_hz = fast\n" "bad_clock.board:9: clock_hz must be a number")
check(no_equals "${_good}halt\n" "no_equals.board:9: expected 'key = value'")
check(twice "${_good}isa = rv32i\n" "twice.board:9: 'isa' given twice \\(first on line 2\\)")
string(REPLACE "uart_base = 0x10000000\n" "" _no_base "${_good}")
check(missing "${_no_base}" "missing.board: required key 'uart_base' is missing")
string(REPLACE "rv32im" "rv64gc" _bad_isa "${_good}")
check(bad_isa "${_bad_isa}" "bad_isa.board:2: isa 'rv64gc' is not one of")
string(REPLACE "rv32im" "rv32imf" _f "${_good}")
check(f_without_zicsr "${_f}zicsr = no\n" "f_without_zicsr.board:9: zicsr = no with isa 'rv32imf'")
check(bad_number "${_good}uart_divisor = 12z\n" "bad_number.board:9: uart_divisor must be a number")
check(too_big "${_good}rom_base = 0x100000000\nrom_size = 4\n" "too_big.board:9: rom_base does not fit in 32 bits")
check(reset_outside "${_good}rom_base = 0x20000000\nrom_size = 0x1000\n" "reset 0x00000000 is not inside the ROM")
string(REPLACE "ns16550" "generic" _generic "${_good}")
check(generic_no_masks "${_generic}uart_data = 0\nuart_status = 4\n" "uart = generic needs 'uart_tx_ready'")
check(generic_width "${_generic}uart_data = 0\nuart_status = 4\nuart_tx_ready = 1\nuart_rx_ready = 2\nuart_width = 2\n"
      "generic_width.board:13: uart_width must be 1 or 4")
check(generic_key_elsewhere "${_good}uart_status = 4\n" "generic_key_elsewhere.board:9: 'uart_status' is for uart = generic only")
string(REPLACE "halt = loop" "halt = finisher" _halt "${_good}")
check(bad_halt "${_halt}" "bad_halt.board:8: halt must be finisher:ADDR, ecall, store:ADDR or loop")
