// A shared library loaded at its first use (dlopen) instead of linked, so a
// run that never needs it does not pay for loading it and its dependencies
// (SDL2 for the window, libtiff for TIFF output).
#pragma once

#include <dlfcn.h>

#include <mutex>
#include <string>

namespace minrt::host {

// Looks up a library's functions by name; the first one missing is the
// reason the library cannot be used ("LABEL has no SYMBOL").
class SymbolBinder {
 public:
  SymbolBinder(void* handle, const char* label, std::string& error)
      : handle_(handle), label_(label), error_(error) {}
  template <class F>
  void operator()(F& function, const char* symbol) {
    function = reinterpret_cast<F>(dlsym(handle_, symbol));
    if (function == nullptr && error_.empty()) error_ = std::string(label_) + " has no " + symbol;
  }

 private:
  void* handle_;
  const char* label_;
  std::string& error_;
};

// `Table` filled by bind(table, binder) from `soname` the first time; later
// calls return the same table. Null with the reason ("cannot load LABEL
// (...)" or a missing function) if the library cannot be used.
template <class Table, class Bind>
const Table* load_library_once(const char* soname, const char* label, Bind bind, std::string& why) {
  static Table table;
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [&] {
    void* handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* e = dlerror();
      error = std::string("cannot load ") + label + " (" + (e != nullptr ? e : soname) + ")";
      return;
    }
    SymbolBinder binder(handle, label, error);
    bind(table, binder);
  });
  if (!error.empty()) {
    why = error;
    return nullptr;
  }
  return &table;
}

}  // namespace minrt::host
