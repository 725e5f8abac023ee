// Writing an output file so that nothing is half-written or replaced by
// mistake: the bytes go to a unique temporary file in the target's folder,
// which is renamed over the target only when complete (and synced first
// when the caller asks for it, see Durability), and only onto a regular
// file or a new name. A FIFO, device or symbolic link is
// refused unless the caller asks to write through it; "-" is standard
// output. The temporary file has no name until it is complete (O_TMPFILE,
// linked at commit), so no signal, SIGKILL included, leaves it behind; on a
// file system without O_TMPFILE it is OUT.partial.XXXXXX (cut to fit
// NAME_MAX), removed by a handler on every catchable fatal signal.
#pragma once

#include <cstdio>
#include <string>

namespace minrt::host {

// Checks now, before any long work, that `path` can be written as above:
// false with the reason when the folder is missing or not writable, the
// target is a directory, or a special file without `write_through`.
bool check_output_target(const std::string& path, bool write_through, std::string& error);

// An output name a scene chose (CS418's png line, EASTRAY's output
// statement) must stay inside the scene's folder or the working folder: a
// scene from elsewhere must not replace ../x.png or /abs/path. False with
// one line naming the path when it leaves both (the folder it would land
// in is resolved, so `..` and symbolic links count). `scene_path` "-" (a
// scene on standard input) has only the working folder.
bool scene_named_output_allowed(const std::string& scene_path, const std::string& named, std::string& error);

// Whether commit() makes the file durable: kSynced fsyncs the file before
// the rename and its folder after it. With kRenameOnly the rename still
// gives readers, other runs and a killed process only the old or the whole
// new file; only a power cut or kernel crash soon after may lose the new
// file. Each writer chooses (minrt: kSynced only with --sync).
enum class Durability { kRenameOnly, kSynced };

// The whole of `bytes` through an AtomicOutput: `path` is either the
// complete file or untouched. False with the reason.
bool write_file_atomically(const std::string& path, const std::string& bytes, bool write_through,
                           Durability durability, std::string& error);

class AtomicOutput {
 public:
  explicit AtomicOutput(Durability durability) : durability_(durability) {}
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput() { discard(); }

  // Opens the temporary file (or the target itself when writing through,
  // or standard output for "-"). False with the reason.
  bool open(const std::string& path, bool write_through, std::string& error);
  std::FILE* file() const { return file_; }
  // Flushes, syncs (with Durability::kSynced) and renames into place. False with the reason (the
  // temporary file is then removed).
  bool commit(std::string& error);
  // Removes the temporary file; the target is left as it was.
  void discard();

 private:
  bool link_unnamed(int& err);

  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool unnamed_ = false;  // O_TMPFILE: linked to temp_ only at commit
  bool direct_ = false;  // writing to the target itself (stdout or write-through)
  Durability durability_;
};

}  // namespace minrt::host
