#include "flame_graph.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace fwsim {
namespace {

constexpr double kWidth = 1200, kMargin = 10, kRowHeight = 17, kHeaderHeight = 44, kFooterHeight = 22;
constexpr double kFontSize = 11, kCharWidth = 6.6;  // monospace at 11 px
constexpr double kMinBoxWidth = 0.3;  // narrower boxes are left out (and their callees)

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// Warm colours, fixed per name so the same function looks the same everywhere.
std::string colour_of(const std::string& name) {
  uint32_t h = 2166136261u;
  for (unsigned char c : name) h = (h ^ c) * 16777619u;
  char buf[24];
  std::snprintf(buf, sizeof buf, "rgb(%u,%u,%u)", 205 + h % 50, 90 + (h >> 8) % 120, 40 + (h >> 16) % 50);
  return buf;
}

// "Tracer::in_shadow" for "minrt::Tracer<minrt::P>::in_shadow()": template
// arguments, parameters, return type and outer namespaces dropped, for box
// labels too narrow for the full name (the tooltip keeps it).
std::string short_name(const std::string& name) {
  std::string flat;
  int depth = 0;
  for (char c : name) {
    if (c == '<' || c == '(') ++depth;
    else if ((c == '>' || c == ')') && depth > 0) --depth;
    else if (depth == 0) flat += c;
  }
  if (const size_t space = flat.find_last_of(' '); space != std::string::npos) flat.erase(0, space + 1);
  const size_t last = flat.rfind("::");
  if (last != std::string::npos && last > 0) {
    const size_t before = flat.rfind("::", last - 1);
    if (before != std::string::npos) flat.erase(0, before + 2);
  }
  return flat.empty() ? name : flat;
}

std::string with_commas(uint64_t v) {
  const std::string digits = std::to_string(v);
  std::string s;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) s += ',';
    s += digits[i];
  }
  return s;
}

}  // namespace

void write_flame_graph_svg(const Profiler& p, std::ostream& out, const std::string& title) {
  const auto& nodes = p.nodes();
  const auto& names = p.functions();
  // Inclusive cycles per call path: children always come after their parent.
  std::vector<uint64_t> total(nodes.size());
  for (size_t i = nodes.size(); i-- > 0;) {
    total[i] += nodes[i].self.cycles;
    if (i) total[nodes[i].parent] += total[i];
  }
  std::vector<unsigned> depth(nodes.size());
  unsigned max_depth = 0;
  for (size_t i = 1; i < nodes.size(); ++i) {
    depth[i] = depth[nodes[i].parent] + 1;
    if (total[i]) max_depth = std::max(max_depth, depth[i]);
  }
  const uint64_t all = nodes.empty() ? 0 : total[0];
  const double scale = all ? (kWidth - 2 * kMargin) / static_cast<double>(all) : 0;
  const double height = kHeaderHeight + (max_depth + 1) * kRowHeight + kFooterHeight;

  char num[64];
  std::snprintf(num, sizeof num, "%.0f", height);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << num
      << "\" viewBox=\"0 0 " << kWidth << ' ' << num << "\" font-family=\"monospace\" font-size=\"" << kFontSize
      << "\">\n<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"#f8f8f0\"/>\n"
      << "<text x=\"" << kWidth / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"15\">"
      << xml_escape(title) << "</text>\n"
      << "<text x=\"" << kWidth / 2 << "\" y=\"36\" text-anchor=\"middle\" fill=\"#555\">"
      << "width = cycles including callees, " << with_commas(all)
      << " in all; callers below callees; hover over a box for its name and cost</text>\n";

  // Depth-first from the root; siblings by name, as flame graphs usually are.
  struct Item {
    uint32_t node;
    double x;
  };
  std::vector<Item> work{{0, kMargin}};
  while (!work.empty() && all) {
    const Item it = work.back();
    work.pop_back();
    const auto& n = nodes[it.node];
    const double w = static_cast<double>(total[it.node]) * scale;
    if (w < kMinBoxWidth) continue;
    const double y = kHeaderHeight + (max_depth - depth[it.node]) * kRowHeight;
    const std::string& name = names[static_cast<size_t>(n.fn)];
    char pct[32];
    std::snprintf(pct, sizeof pct, "%.2f%%", 100.0 * static_cast<double>(total[it.node]) / static_cast<double>(all));
    out << "<g><title>" << xml_escape(name) << "\n" << with_commas(total[it.node]) << " cycles (" << pct
        << "), self " << with_commas(n.self.cycles) << ", calls " << with_commas(n.calls) << "</title>";
    std::snprintf(num, sizeof num, "x=\"%.2f\" y=\"%.1f\" width=\"%.2f\" height=\"%.1f\"", it.x, y, w, kRowHeight - 1);
    out << "<rect " << num << " rx=\"2\" fill=\"" << colour_of(name) << "\"/>";
    const size_t fits = static_cast<size_t>((w - 6) / kCharWidth);
    if (fits >= 3) {
      const std::string brief = short_name(name);
      std::string label = name.size() <= fits    ? name
                          : brief.size() <= fits ? brief
                                                 : brief.substr(0, fits - 2) + "..";
      std::snprintf(num, sizeof num, "x=\"%.2f\" y=\"%.1f\"", it.x + 3, y + kRowHeight - 5);
      out << "<text " << num << ">" << xml_escape(label) << "</text>";
    }
    out << "</g>\n";
    std::vector<std::pair<int, uint32_t>> kids = n.children;
    std::sort(kids.begin(), kids.end(), [&](const auto& a, const auto& b) {
      return names[static_cast<size_t>(a.first)] < names[static_cast<size_t>(b.first)];
    });
    double x = it.x;
    std::vector<Item> next;
    for (const auto& [fn, child] : kids) {
      next.push_back({child, x});
      x += static_cast<double>(total[child]) * scale;
    }
    for (size_t k = next.size(); k-- > 0;) work.push_back(next[k]);
  }
  std::snprintf(num, sizeof num, "%.0f", height - 7);
  out << "<text x=\"" << kMargin << "\" y=\"" << num << "\" fill=\"#555\">firmware-sim --flame-out</text>\n</svg>\n";
}

}  // namespace fwsim
