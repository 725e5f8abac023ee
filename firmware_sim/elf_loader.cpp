#include "elf_loader.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <elf.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "posix/input_file.hpp"

namespace fwsim {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why);
}

template <typename T>
T read_at(const std::vector<uint8_t>& f, uint64_t off, const std::string& path) {
  if (off > f.size() || f.size() - off < sizeof(T)) fail(path, "truncated ELF file");
  T v;
  std::memcpy(&v, f.data() + off, sizeof v);
  return v;
}

void read_symbols(const std::vector<uint8_t>& f, const Elf32_Ehdr& eh, const std::string& path,
                  LoadedElf& out) {
  if (eh.e_shoff == 0 || eh.e_shentsize != sizeof(Elf32_Shdr)) return;
  std::vector<Elf32_Shdr> sh(eh.e_shnum);
  for (unsigned i = 0; i < eh.e_shnum; ++i)
    sh[i] = read_at<Elf32_Shdr>(f, eh.e_shoff + uint64_t{i} * sizeof(Elf32_Shdr), path);
  for (const Elf32_Shdr& s : sh) {
    if (s.sh_type != SHT_SYMTAB || s.sh_link >= sh.size()) continue;
    const Elf32_Shdr& strtab = sh[s.sh_link];
    if (uint64_t{strtab.sh_offset} + strtab.sh_size > f.size()) fail(path, "string table beyond end of file");
    for (uint32_t off = 0; off + sizeof(Elf32_Sym) <= s.sh_size; off += sizeof(Elf32_Sym)) {
      auto sym = read_at<Elf32_Sym>(f, uint64_t{s.sh_offset} + off, path);
      const unsigned type = ELF32_ST_TYPE(sym.st_info);
      if (sym.st_shndx == SHN_UNDEF || sym.st_shndx >= sh.size()) continue;
      if (!(sh[sym.st_shndx].sh_flags & SHF_EXECINSTR)) continue;
      // Functions, plus untyped labels from assembly such as _start.
      if (type != STT_FUNC && type != STT_NOTYPE) continue;
      if (sym.st_name >= strtab.sh_size) continue;
      const char* name = reinterpret_cast<const char*>(f.data() + strtab.sh_offset + sym.st_name);
      size_t max_len = strtab.sh_size - sym.st_name;
      std::string n(name, strnlen(name, max_len));
      if (n.empty() || n[0] == '$' || n.rfind(".L", 0) == 0) continue;  // mapping symbols, locals
      // Kept mangled: a report demangles the names it shows (symbols.hpp).
      out.symbols.add({std::move(n), sym.st_value, type == STT_FUNC ? sym.st_size : 0});
    }
  }
  out.symbols.finalize();
}

}  // namespace

LoadedElf load_elf(const std::string& path, Bus& bus) {
  // Only a regular file no larger than the RAM it is loaded into: checked
  // before reading, so /dev/zero or a directory cannot make us read forever.
  std::string why;
  const int fd = minrt::host::open_regular_file(path, why);
  if (fd < 0) fail(path, "cannot read: " + why);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    ::close(fd);
    fail(path, std::string("cannot read: ") + std::strerror(errno));
  }
  const uint64_t room = uint64_t{bus.ram_size()} + (bus.code() != bus.ram() ? bus.code_size() : 0);
  if (static_cast<uint64_t>(st.st_size) > room) {
    ::close(fd);
    fail(path, "file of " + std::to_string(st.st_size) + " bytes is larger than the " +
                   std::to_string(room) + (bus.code() != bus.ram() ? "-byte RAM and ROM" : "-byte RAM") + " it would load into");
  }
  std::string bytes;
  const bool read_ok = minrt::host::read_whole_fd(fd, bytes, why, room);
  ::close(fd);
  if (!read_ok) fail(path, "cannot read: " + why);
  const std::vector<uint8_t> f(bytes.begin(), bytes.end());
  // The magic first: a short text file is "not an ELF file", not a truncated one.
  if (f.size() < SELFMAG || std::memcmp(f.data(), ELFMAG, SELFMAG) != 0) fail(path, "not an ELF file");
  auto eh = read_at<Elf32_Ehdr>(f, 0, path);
  if (eh.e_ident[EI_CLASS] != ELFCLASS32 || eh.e_ident[EI_DATA] != ELFDATA2LSB)
    fail(path, "not a 32-bit little-endian ELF");
  if (eh.e_machine != EM_RISCV) fail(path, "not a RISC-V ELF");
  if (eh.e_type != ET_EXEC) fail(path, "not an executable ELF (ET_EXEC)");
  if (eh.e_phentsize != sizeof(Elf32_Phdr)) fail(path, "bad program header size");
  LoadedElf out;
  out.entry = eh.e_entry;
  bool have_text = false;
  for (unsigned i = 0; i < eh.e_phnum; ++i) {
    auto ph = read_at<Elf32_Phdr>(f, eh.e_phoff + uint64_t{i} * sizeof(Elf32_Phdr), path);
    if (ph.p_type != PT_LOAD || ph.p_memsz == 0) continue;
    if (ph.p_filesz > ph.p_memsz) fail(path, "segment file size exceeds memory size");
    uint8_t* const dest = bus.host_at(ph.p_paddr, ph.p_memsz);
    if (!dest) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "segment 0x%08x..0x%08x lies outside RAM 0x%08x..0x%08x%s",
                    ph.p_paddr, ph.p_paddr + ph.p_memsz, bus.ram_base(), bus.ram_base() + bus.ram_size(),
                    bus.code() != bus.ram() ? " and ROM" : " (--ram BASE:SIZE moves RAM)");
      fail(path, buf);
    }
    if (uint64_t{ph.p_offset} + ph.p_filesz > f.size()) fail(path, "segment beyond end of file");
    std::memcpy(dest, f.data() + ph.p_offset, ph.p_filesz);
    if (ph.p_flags & PF_X) {
      if (!have_text || ph.p_paddr < out.text_begin) out.text_begin = ph.p_paddr;
      if (!have_text || ph.p_paddr + ph.p_memsz > out.text_end) out.text_end = ph.p_paddr + ph.p_memsz;
      have_text = true;
    }
  }
  if (!have_text) fail(path, "no executable segment");
  if (!bus.in_code(out.entry, 4) || (out.entry & 3))
    fail(path, bus.code() != bus.ram() ? "entry point outside ROM or misaligned" : "entry point outside RAM or misaligned");
  read_symbols(f, eh, path, out);
  return out;
}

}  // namespace fwsim
