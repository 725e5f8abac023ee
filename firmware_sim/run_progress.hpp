// A long run on a terminal: a progress line on standard error (instructions
// retired, host MIPS, elapsed time), and Ctrl-C ending the run between two
// slices of it so that the caller can report where it stopped.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>

#include "machine.hpp"

namespace fwsim {

inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as a shell reports it

class RunProgress {
 public:
  // `show`: draw the progress line on `out` (the caller checks it is a
  // terminal). Ctrl-C is caught from here until destruction; a second one
  // ends the process at once.
  RunProgress(bool show, std::FILE* out);
  ~RunProgress();
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  // Runs `m` as Machine::run(max_instructions) does, in slices (the counts
  // are the same as one run's). After Ctrl-C it returns with cause None and
  // interrupted() true.
  StopInfo run(Machine& m, uint64_t max_instructions);
  bool interrupted() const;
  // Asked between slices: true stops the run with cause HostIo (a trace
  // whose writes fail: a full disk, a closed pipe).
  void stop_when(std::function<bool()> failed) { failed_ = std::move(failed); }

 private:
  void draw(uint64_t instructions, double seconds);
  void clear();

  bool show_;
  std::FILE* out_;
  std::function<bool()> failed_;
  bool drawn_ = false;
  double last_draw_ = 0;
};

}  // namespace fwsim
