// Pseudo-terminal backend for the UART: the host program (a terminal, a
// serial tool, a test) opens the slave side like a real serial port.
#pragma once
#include <string>

namespace fwsim {

// Creates a raw-mode pty, prints "WHO: uart on /dev/pts/N" on stderr
// (WHO = the program, firmware-sim by default), and blocks until a host
// opens the slave. Returns the master fd; throws std::runtime_error on
// failure.
int open_uart_pty(const char* who = "firmware-sim");

// For --real-board: the same pty, but returns at once and keeps a slave
// descriptor of its own open (in `held_slave`), so hosts can open and close
// the port as often as they like without the master seeing a hang-up; the
// master is non-blocking.
int open_uart_pty_for_board(int& held_slave);

// Waits (at most `timeout_ms`) until the host has read everything written to
// the pty, so closing the master does not discard the firmware's last output.
void drain_uart_pty(int master, int timeout_ms);

}  // namespace fwsim
