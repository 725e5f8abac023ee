// Function symbols from the ELF, for "function+offset" in messages and for
// per-function profiles.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace fwsim {

struct Symbol {
  std::string name;  // as in the ELF (mangled): demangle() when shown
  uint32_t addr;
  uint32_t size;  // 0 = unknown, extends to the next symbol
};

// The readable form of a C++ symbol ("minrt::Tracer<...>::init(...)"), or
// the name unchanged when it is not a mangled C++ name or when its readable
// form could be huge (a name of back-references to back-references: the
// bound is in symbols.cpp). Called only for the names a report shows.
std::string demangle(const std::string& name);

class SymbolTable {
 public:
  void add(Symbol s) { syms_.push_back(std::move(s)); }
  void finalize();  // sort, drop duplicates, close sizes
  // Index of the function containing addr, or -1.
  int find(uint32_t addr) const;
  const Symbol& at(int i) const { return syms_[static_cast<size_t>(i)]; }
  size_t size() const { return syms_.size(); }
  // "name+0x1c" (demangled) or "0x80001234" when no symbol covers addr.
  std::string describe(uint32_t addr) const;

 private:
  std::vector<Symbol> syms_;
};

}  // namespace fwsim
