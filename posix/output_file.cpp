#include "posix/output_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace minrt::host {
namespace {

// The temporary file a signal handler must remove (one per process is all
// the tools need): a fixed buffer, so the handler only calls unlink.
char g_temp[4096];
volatile sig_atomic_t g_have_temp = 0;

void remove_temp_and_die(int sig) {
  if (g_have_temp) ::unlink(g_temp);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void register_temp(const std::string& temp) {
  static bool installed = false;
  if (!installed) {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      ::sigaction(sig, nullptr, &old);
      if (old.sa_handler == SIG_DFL) ::signal(sig, remove_temp_and_die);  // leave a tool's own handler be
    }
    installed = true;
  }
  if (temp.size() < sizeof g_temp) {
    std::memcpy(g_temp, temp.c_str(), temp.size() + 1);
    g_have_temp = 1;
  }
}

void unregister_temp() { g_have_temp = 0; }

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

const char* kind_name(mode_t m) {
  if (S_ISLNK(m)) return "a symbolic link";
  if (S_ISFIFO(m)) return "a FIFO";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}

// The folder's entry made durable after a rename; file systems that cannot
// sync a folder (EINVAL) are left be, as for the file.
bool sync_folder(const std::string& path, int& err) {
  const int fd = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    err = errno;
    return false;
  }
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;
  err = errno;
  ::close(fd);
  return ok;
}

}  // namespace

bool check_output_target(const std::string& path, bool write_through, std::string& error) {
  if (path == "-") return true;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      error = "cannot write " + path + ": " + std::strerror(EISDIR);
      return false;
    }
    if (!S_ISREG(st.st_mode) && !write_through) {
      error = "refusing to replace " + path + ": it is " + kind_name(st.st_mode) +
              " (--write-through writes into it instead)";
      return false;
    }
    if (!S_ISREG(st.st_mode)) return true;
  } else if (errno != ENOENT) {
    error = "cannot write " + path + ": " + std::strerror(errno);
    return false;
  }
  const std::string folder = folder_of(path);
  if (::access(folder.c_str(), W_OK) != 0) {
    error = "cannot write " + path + ": " + folder + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

bool AtomicOutput::open(const std::string& path, bool write_through, std::string& error) {
  path_ = path;
  if (path == "-") {
    file_ = stdout;
    direct_ = true;
    return true;
  }
  if (!check_output_target(path, write_through, error)) return false;
  struct stat st {};
  if (write_through && ::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    file_ = std::fopen(path.c_str(), "wb");
    if (file_ == nullptr) {
      error = "cannot write " + path + ": " + std::strerror(errno);
      return false;
    }
    direct_ = true;
    return true;
  }
  // Unique per run: two runs writing the same target never share a file.
  std::string temp = path + ".partial.XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) {
    error = "cannot create a temporary file next to " + path + ": " + std::strerror(errno);
    return false;
  }
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    error = "cannot write " + temp + ": " + std::strerror(errno);
    ::close(fd);
    ::unlink(temp.c_str());
    return false;
  }
  temp_ = temp;
  register_temp(temp_);
  return true;
}

bool AtomicOutput::commit(std::string& error) {
  if (file_ == nullptr) return false;
  bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  int err = errno;
  if (ok && !direct_ && durability_ == Durability::kSynced && ::fsync(fileno(file_)) != 0 && errno != EINVAL) {
    ok = false;
    err = errno;
  }
  if (file_ != stdout && std::fclose(file_) != 0 && ok) {
    ok = false;
    err = errno;
  }
  file_ = nullptr;
  if (ok && !direct_ && std::rename(temp_.c_str(), path_.c_str()) != 0) {
    ok = false;
    err = errno;
  }
  if (ok && !direct_ && durability_ == Durability::kSynced && !sync_folder(path_, err)) {
    // The new file is in place and whole; only its durability is in doubt.
    error = "cannot sync the folder of " + path_ + ": " + std::strerror(err);
    unregister_temp();
    temp_.clear();
    return false;
  }
  if (!ok) {
    error = "cannot write " + path_ + ": " + std::strerror(err != 0 ? err : EIO);
    if (!temp_.empty()) ::unlink(temp_.c_str());
  }
  unregister_temp();
  temp_.clear();
  return ok;
}

bool write_file_atomically(const std::string& path, const std::string& bytes, bool write_through,
                           Durability durability, std::string& error) {
  AtomicOutput out(durability);
  if (!out.open(path, write_through, error)) return false;
  if (std::fwrite(bytes.data(), 1, bytes.size(), out.file()) != bytes.size()) {
    error = "cannot write " + path + ": " + std::strerror(errno);
    out.discard();
    return false;
  }
  return out.commit(error);
}

void AtomicOutput::discard() {
  if (file_ != nullptr && file_ != stdout) std::fclose(file_);
  file_ = nullptr;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  unregister_temp();
  temp_.clear();
}

}  // namespace minrt::host
