// Process hygiene: a SIGKILLed host-send leaves no simulator behind. Before
// the simulator had a parent-death signal it ran on, blocked writing to the
// pseudo-terminal nobody read any more.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "test_support.hpp"

extern char** environ;

TEST_CASE("a SIGKILLed host-send leaves no simulator running", "[e2e][process]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  // contest at 512x512, paced at 9600 baud: minutes of transfer.
  const std::string scene = hs_test::shared_dir() + "/scenes/contest.sld";
  const std::string out = dir.file("x.ppm");
  std::vector<std::string> args{HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                                "--baud", "9600", "--size", "512x512", scene, "-o", out};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t hs = 0;
  REQUIRE(posix_spawn(&hs, argv[0], &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);

  std::vector<pid_t> sims;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (sims.empty() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    sims = hs_test::children_of(hs);
  }
  REQUIRE_FALSE(sims.empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // mid-transfer
  ::kill(hs, SIGKILL);
  int st = 0;
  ::waitpid(hs, &st, 0);
  for (pid_t sim : sims) {
    bool gone = false;
    for (int i = 0; i < 100 && !gone; ++i) {
      gone = !hs_test::alive(sim);
      if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (!gone) ::kill(sim, SIGKILL);  // do not leave it behind either way
    CHECK(gone);
  }
  CHECK_FALSE(hs_test::file_exists(out));
}
