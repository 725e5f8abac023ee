#include "posix/output_file.hpp"

#include "posix/interrupt.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include <cerrno>
#include <cstring>
#include <vector>

namespace minrt::host {
namespace {

// The temporary file a signal must remove (posix/interrupt.hpp): one per
// process is all the tools need.
void register_temp(const std::string& temp) { remove_on_signal(temp.c_str()); }

void unregister_temp() { forget_removal(); }

// OUT.partial.XXXXXX beside OUT, its last component cut so that the name
// fits NAME_MAX (a 254-byte OUT is a valid name; its temporary must be too).
std::string temp_pattern(const std::string& path) {
  static constexpr char kSuffix[] = ".partial.XXXXXX";
  constexpr std::size_t kSuffixLen = sizeof kSuffix - 1;
  const std::size_t slash = path.rfind('/');
  const std::size_t base_at = slash == std::string::npos ? 0 : slash + 1;
  std::string base = path.substr(base_at);
  if (base.size() + kSuffixLen > NAME_MAX) base.resize(NAME_MAX - kSuffixLen);
  return path.substr(0, base_at) + base + kSuffix;
}

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

namespace {
// The resolved folder, with a trailing slash; empty when it cannot be resolved.
std::string resolved_folder(const std::string& folder) {
  char buf[PATH_MAX];
  if (::realpath(folder.c_str(), buf) == nullptr) return "";
  std::string out = buf;
  if (out.back() != '/') out += '/';
  return out;
}
}  // namespace

bool scene_named_output_allowed(const std::string& scene_path, const std::string& named, std::string& error) {
  if (named.empty() || named == "-") return true;
  const std::string target = resolved_folder(folder_of(named));
  if (target.empty()) return true;  // a missing folder: check_output_target says so
  std::vector<std::string> allowed{resolved_folder(".")};
  if (scene_path != "-") allowed.push_back(resolved_folder(folder_of(scene_path)));
  for (const std::string& a : allowed)
    if (!a.empty() && target.compare(0, a.size(), a) == 0) return true;
  error = "refusing to write " + named +
          ", named by the scene: it is outside the scene's folder and the working folder (-o names the output; "
          "--allow-any-output lets the scene choose)";
  return false;
}

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
  // Unnamed first (O_TMPFILE): nothing exists under any name until commit
  // links it, so even SIGKILL leaves nothing behind. File systems without
  // it get a named temporary, removed by a handler on every catchable
  // fatal signal. Either way unique per run: two runs never share a file.
  const int tmp_fd = ::open(folder_of(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (tmp_fd >= 0) {
    file_ = ::fdopen(tmp_fd, "wb");
    if (file_ == nullptr) {
      error = "cannot write next to " + path + ": " + std::strerror(errno);
      ::close(tmp_fd);
      return false;
    }
    unnamed_ = true;
    return true;
  }
  std::string temp = temp_pattern(path);
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

// The unnamed file gets a unique temporary name beside the target (linkat
// cannot replace a name), which the caller then renames over the target.
bool AtomicOutput::link_unnamed(int& err) {
  char proc[64];
  std::snprintf(proc, sizeof proc, "/proc/self/fd/%d", fileno(file_));
  const std::string pattern = temp_pattern(path_);
  static const char kChars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  unsigned long long seed = static_cast<unsigned long long>(::getpid()) * 2654435761u ^
                            static_cast<unsigned long long>(std::time(nullptr)) ^ reinterpret_cast<uintptr_t>(this);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = pattern;
    for (std::size_t i = name.size() - 6; i < name.size(); ++i) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      name[i] = kChars[(seed >> 33) % (sizeof kChars - 1)];
    }
    // Registered first: a signal between the link and the rename removes it.
    register_temp(name);
    if (::linkat(AT_FDCWD, proc, AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0 ||
        ::linkat(fileno(file_), "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH) == 0) {
      temp_ = name;
      return true;
    }
    err = errno;
    unregister_temp();
    if (err != EEXIST) return false;
  }
  return false;
}

bool AtomicOutput::commit(std::string& error) {
  if (file_ == nullptr) return false;
  bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  int err = errno;
  if (ok && !direct_ && durability_ == Durability::kSynced && ::fsync(fileno(file_)) != 0 && errno != EINVAL) {
    ok = false;
    err = errno;
  }
  if (ok && unnamed_ && !link_unnamed(err)) ok = false;
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
  if (file_ != nullptr && file_ != stdout) std::fclose(file_);  // an unnamed file vanishes with it
  file_ = nullptr;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  unregister_temp();
  temp_.clear();
}

}  // namespace minrt::host
