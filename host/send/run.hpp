// One run of host-send, once its command line is read: the scene read and
// checked, the output checked, the link opened (a board's port, or
// firmware-sim on a pseudo-terminal), the transfer, then the image checked,
// written whole and reported.
#pragma once

#include "cli.hpp"

namespace minrt::send {

// Returns the exit status (cli.hpp); Ctrl-C ends the process with SIGINT
// after putting the port back and stopping the simulator.
int run(const Options& options);

}  // namespace minrt::send
