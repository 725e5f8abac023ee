#include "profile_writers.hpp"

#include <map>
#include <vector>

namespace fwsim {

void write_callgrind(const Profiler& p, std::ostream& out, const std::string& command,
                     const std::string& elf_path) {
  struct Edge {
    uint64_t calls = 0;
    Cost inclusive;
  };
  const auto& names = p.functions();
  std::vector<Cost> self(names.size());
  std::map<std::pair<int, int>, Edge> edges;  // (caller, callee)
  Cost total;
  for (const auto& n : p.nodes()) {
    self[static_cast<size_t>(n.fn)] += n.self;
    total += n.self;
  }
  for (size_t i = 1; i < p.nodes().size(); ++i) {
    const auto& n = p.nodes()[i];
    Edge& e = edges[{p.nodes()[n.parent].fn, n.fn}];
    e.calls += n.calls;
    e.inclusive += n.inclusive;
  }
  std::vector<bool> used(names.size());
  for (const auto& n : p.nodes()) used[static_cast<size_t>(n.fn)] = true;

  out << "# callgrind format\nversion: 1\ncreator: firmware-sim\n";
  out << "cmd: " << command << "\npositions: line\nevents: Ir Cycles\n";
  out << "summary: " << total.ir << ' ' << total.cycles << "\n\n";
  out << "ob=" << elf_path << "\nfl=(1) ???\n";
  // Name compression: "(id) name" the first time, "(id)" afterwards.
  std::vector<bool> named(names.size());
  auto fn_ref = [&](int fn) {
    std::string s = "(" + std::to_string(fn + 1) + ")";
    if (!named[static_cast<size_t>(fn)]) {
      named[static_cast<size_t>(fn)] = true;
      s += " " + names[static_cast<size_t>(fn)];
    }
    return s;
  };
  for (size_t f = 0; f < names.size(); ++f) {
    if (!used[f]) continue;
    const int fn = static_cast<int>(f);
    out << "\nfn=" << fn_ref(fn) << "\n0 " << self[f].ir << ' ' << self[f].cycles << '\n';
    for (auto it = edges.lower_bound({fn, -1}); it != edges.end() && it->first.first == fn; ++it) {
      out << "cfn=" << fn_ref(it->first.second) << "\ncalls=" << it->second.calls << " 0\n0 "
          << it->second.inclusive.ir << ' ' << it->second.inclusive.cycles << '\n';
    }
  }
  out << "\ntotals: " << total.ir << ' ' << total.cycles << '\n';
}

void write_folded(const Profiler& p, std::ostream& out) {
  const auto& nodes = p.nodes();
  std::vector<uint32_t> path;
  for (const auto& n : nodes) {
    if (n.self.cycles == 0) continue;
    path.clear();
    for (uint32_t i = static_cast<uint32_t>(&n - nodes.data());; i = nodes[i].parent) {
      path.push_back(i);
      if (i == 0) break;
    }
    for (size_t k = path.size(); k-- > 0;) {
      out << p.functions()[static_cast<size_t>(nodes[path[k]].fn)] << (k ? ";" : "");
    }
    out << ' ' << n.self.cycles << '\n';
  }
}

}  // namespace fwsim
