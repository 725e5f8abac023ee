// Ctrl-C (SIGINT) during long work: minrt and host-send end with the
// signal's status (130 in the shell), leave no output file and no
// temporary file, and host-send leaves no simulator running.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
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

namespace {

using Clock = std::chrono::steady_clock;

// Starts argv in `dir` with its output to /dev/null and stderr to `err`.
pid_t start(const std::vector<std::string>& argv, const std::string& dir, const std::string& err) {
  return hs_test::start_program(argv, "/dev/null", err, dir);
}

// Waits for `pid` at most `seconds`, then kills it (a hang fails the test).
int wait_status(pid_t pid, int seconds) {
  int st = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(seconds);
  while (::waitpid(pid, &st, WNOHANG) == 0) {
    if (Clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &st, 0);
      FAIL("did not end within " << seconds << " s of the interrupt");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return st;
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") out.push_back(n);
    }
    ::closedir(d);
  }
  return out;
}

void check_ended_by_sigint(int st, const std::string& err_path) {
  INFO("stderr: " << hs_test::read_file(err_path));
  REQUIRE(WIFSIGNALED(st));
  CHECK(WTERMSIG(st) == SIGINT);  // the shell reports 128 + 2 = 130
}

}  // namespace

TEST_CASE("Ctrl-C during a minrt render with -o: status 130, no file, no temporary", "[interrupt]") {
  const std::string contest = hs_test::shared_dir() + "/scenes/contest.sld";
  hs_test::TempDir work, logs;
  std::ofstream(work.file("lights.rt")) << "A 0.2 255,255,255\nC 0,0,-10 0,0,1 70\nL -4,4,-6 0.7 255,255,255\n"
                                           "sp 0,0,0 4 200,40,40\npl 0,-2,0 0,1,0 90,90,90\n";
  // SLD streams its rows into the file as they are done; the other formats
  // write the whole image at the end: both are interrupted mid-render.
  const std::vector<std::vector<std::string>> runs = {
      {HS_MINRT, "--size", "2048x2048", "--threads", "1", "-o", "out.ppm", contest},
      {HS_MINRT, "--size", "4096x4096", "--threads", "1", "-o", "out.png", "lights.rt"},
  };
  for (const auto& argv : runs) {
    const std::string err = logs.file("stderr");
    const pid_t pid = start(argv, work.path, err);
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    REQUIRE(::waitpid(pid, nullptr, WNOHANG) == 0);  // still rendering
    ::kill(pid, SIGINT);
    check_ended_by_sigint(wait_status(pid, 20), err);
    CHECK(entries(work.path) == std::vector<std::string>{"lights.rt"});
  }
}

TEST_CASE("Ctrl-C during host-send's transfer: status 130, no file, no simulator left", "[interrupt][e2e]") {
  hs_test::TempDir work, logs;
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  // 128x128 P3 paced at 9600 baud: about a minute of transfer.
  const std::string err = logs.file("stderr");
  const pid_t hs = start({HS_HOST_SEND, "--sim-binary", HS_STANDIN, "--sim", HS_STANDIN, "--baud", "9600", "--size",
                          "128x128", scene, "-o", "ball.ppm"},
                         work.path, err);
  std::vector<pid_t> sims;
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  while (sims.empty() && Clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    sims = hs_test::children_of(hs);
  }
  REQUIRE(sims.size() == 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // mid-transfer
  REQUIRE(::waitpid(hs, nullptr, WNOHANG) == 0);
  ::kill(hs, SIGINT);
  check_ended_by_sigint(wait_status(hs, 20), err);
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    gone = !hs_test::alive(sims[0]);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!gone) ::kill(sims[0], SIGKILL);  // do not leave it behind either way
  CHECK(gone);
  CHECK(entries(work.path).empty());
  CHECK(hs_test::read_file(err).find("error") == std::string::npos);  // an interrupt is not reported as a failure
}

#include "posix/interrupt.hpp"

namespace {

// Runs `body` in a child process with the default signal actions (the test
// runner's own handlers are not inherited by what the tools see) and
// returns its wait status.
template <class Body>
int in_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGUSR1}) ::signal(sig, SIG_DFL);
    body();
    ::_exit(0);
  }
  int st = 0;
  ::waitpid(pid, &st, 0);
  return st;
}

}  // namespace

TEST_CASE("posix/interrupt: the temporary file is removed and the process dies of the signal", "[interrupt]") {
  hs_test::TempDir dir;
  const std::string temp = dir.file("out.ppm.partial.abc123");
  for (int sig : {SIGINT, SIGTERM, SIGUSR1}) {
    std::ofstream(temp) << "half an image";
    const int st = in_child([&] {
      minrt::host::remove_on_signal(temp.c_str());
      ::raise(sig);
      ::_exit(3);  // not reached
    });
    INFO("signal " << sig);
    REQUIRE(WIFSIGNALED(st));
    CHECK(WTERMSIG(st) == sig);
    CHECK_FALSE(hs_test::file_exists(temp));
  }
  // Forgotten once complete: the file stays.
  std::ofstream(temp) << "a whole image";
  const int st = in_child([&] {
    minrt::host::remove_on_signal(temp.c_str());
    minrt::host::forget_removal();
    ::raise(SIGINT);
  });
  CHECK(WIFSIGNALED(st));
  CHECK(hs_test::file_exists(temp));
}

TEST_CASE("posix/interrupt: held, an interrupt is only noted until the last release", "[interrupt]") {
  hs_test::TempDir dir;
  const std::string mark = dir.file("unwound");
  const int st = in_child([&] {
    minrt::host::hold_interrupts();
    minrt::host::hold_interrupts();
    if (minrt::host::interrupted()) ::_exit(4);
    ::raise(SIGINT);
    if (!minrt::host::interrupted()) ::_exit(5);
    minrt::host::release_interrupts();  // still held once
    std::ofstream(mark) << "the loop noticed and unwound";
    minrt::host::release_interrupts();  // dies here
    ::_exit(6);
  });
  REQUIRE(WIFSIGNALED(st));
  CHECK(WTERMSIG(st) == SIGINT);
  CHECK(hs_test::file_exists(mark));
}

TEST_CASE("posix/interrupt: a registered child is stopped when the process dies of a signal", "[interrupt]") {
  int fds[2];
  REQUIRE(::pipe(fds) == 0);
  const int st = in_child([&] {
    const pid_t child = ::fork();
    if (child == 0) {
      ::pause();
      ::_exit(0);
    }
    (void)!::write(fds[1], &child, sizeof child);
    minrt::host::stop_on_signal(child);
    ::raise(SIGTERM);
  });
  CHECK(WIFSIGNALED(st));
  CHECK(WTERMSIG(st) == SIGTERM);
  pid_t child = 0;
  REQUIRE(::read(fds[0], &child, sizeof child) == sizeof child);
  ::close(fds[0]);
  ::close(fds[1]);
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    gone = !hs_test::alive(child);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!gone) ::kill(child, SIGKILL);
  CHECK(gone);
}
