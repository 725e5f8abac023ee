#include "port_discovery.hpp"

#include <dirent.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#ifdef MINRT_HAVE_LIBUSB
#include <libusb.h>
#endif

namespace minrt::send {

namespace {

std::string read_attr(const std::string& path) {
  std::string out;
  if (FILE* f = std::fopen(path.c_str(), "r")) {
    char buf[256];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    out.assign(buf, n);
    std::fclose(f);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' ')) out.pop_back();
  return out;
}

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

std::string real_path(const std::string& path) {
  char buf[PATH_MAX];
  return ::realpath(path.c_str(), buf) != nullptr ? std::string(buf) : std::string();
}

std::string base_name(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string parent(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos || slash == 0 ? std::string() : path.substr(0, slash);
}

std::vector<std::string> list_dir(const std::string& path) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(path.c_str())) {
    while (dirent* e = ::readdir(d))
      if (e->d_name[0] != '.') names.push_back(e->d_name);
    ::closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

bool parse_hex16(const std::string& s, std::uint16_t& v) {
  if (s.empty() || s.size() > 4) return false;
  char* end = nullptr;
  const unsigned long x = std::strtoul(s.c_str(), &end, 16);
  if (*end != 0) return false;
  v = static_cast<std::uint16_t>(x);
  return true;
}

int parse_int(const std::string& s, int base = 10) {
  if (s.empty()) return -1;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, base);
  return *end == 0 ? static_cast<int>(v) : -1;
}

// Fills the USB fields from the first ancestor of `dev_dir` (inside
// `root`) that is a USB device (has idVendor), noting the interface on the way.
void fill_usb(PortInfo& p, std::string dir, const std::string& root) {
  while (!dir.empty() && dir.size() > root.size()) {
    if (exists(dir + "/bInterfaceNumber") && p.interface < 0)
      p.interface = parse_int(read_attr(dir + "/bInterfaceNumber"), 16);
    if (exists(dir + "/idVendor") && exists(dir + "/idProduct")) {
      p.usb = parse_hex16(read_attr(dir + "/idVendor"), p.vid) && parse_hex16(read_attr(dir + "/idProduct"), p.pid);
      p.serial = read_attr(dir + "/serial");
      p.manufacturer = read_attr(dir + "/manufacturer");
      p.product = read_attr(dir + "/product");
      p.busnum = parse_int(read_attr(dir + "/busnum"));
      p.devnum = parse_int(read_attr(dir + "/devnum"));
      return;
    }
    dir = parent(dir);
  }
}

}  // namespace

std::vector<PortInfo> list_serial_ports(const std::string& sysfs_root, const std::string& dev_root) {
  std::vector<PortInfo> ports;
  const std::string root = real_path(sysfs_root);
  if (root.empty()) return ports;
  const std::string class_dir = root + "/class/tty";
  // by-id links: target basename -> link path.
  std::vector<std::pair<std::string, std::string>> by_id;
  const std::string by_id_dir = dev_root + "/serial/by-id";
  for (const auto& n : list_dir(by_id_dir)) {
    char buf[PATH_MAX];
    const ssize_t len = ::readlink((by_id_dir + "/" + n).c_str(), buf, sizeof buf - 1);
    if (len > 0) by_id.emplace_back(base_name(std::string(buf, static_cast<std::size_t>(len))), "/dev/serial/by-id/" + n);
  }
  for (const auto& name : list_dir(class_dir)) {
    const std::string entry = class_dir + "/" + name;
    if (!exists(entry + "/device")) continue;
    PortInfo p;
    p.name = name;
    p.device = "/dev/" + name;
    const std::string dev_dir = real_path(entry + "/device");
    if (dev_dir.empty()) continue;
    p.driver = base_name(real_path(dev_dir + "/driver"));
    p.uart_type = parse_int(read_attr(entry + "/type"));
    fill_usb(p, dev_dir, root);
    for (const auto& [target, link] : by_id)
      if (target == name) p.by_id = link;
    ports.push_back(std::move(p));
  }
  return ports;
}

std::vector<UsbDevice> enumerate_usb(bool& available) {
  std::vector<UsbDevice> out;
  available = false;
#ifdef MINRT_HAVE_LIBUSB
  libusb_context* ctx = nullptr;
  if (libusb_init(&ctx) != 0) return out;
  available = true;
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(ctx, &list);
  for (ssize_t i = 0; i < n; ++i) {
    libusb_device_descriptor desc{};
    if (libusb_get_device_descriptor(list[i], &desc) != 0) continue;
    UsbDevice d;
    d.bus = libusb_get_bus_number(list[i]);
    d.address = libusb_get_device_address(list[i]);
    d.vid = desc.idVendor;
    d.pid = desc.idProduct;
    libusb_device_handle* h = nullptr;
    if (libusb_open(list[i], &h) == 0) {
      unsigned char buf[256];
      auto get = [&](std::uint8_t index, std::string& s) {
        if (index != 0 && libusb_get_string_descriptor_ascii(h, index, buf, sizeof buf) > 0)
          s = reinterpret_cast<const char*>(buf);
      };
      get(desc.iSerialNumber, d.serial);
      get(desc.iManufacturer, d.manufacturer);
      get(desc.iProduct, d.product);
      libusb_close(h);
    }
    out.push_back(std::move(d));
  }
  if (n >= 0) libusb_free_device_list(list, 1);
  libusb_exit(ctx);
#endif
  return out;
}

bool port_present(const PortInfo& p) { return p.usb || p.uart_type != 0; }

bool parse_usb_selector(const std::string& text, UsbSelector& sel, std::string& error) {
  error = "bad USB port '" + text + "': expected usb:VID:PID[:SERIAL] with 4-digit hex ids";
  if (text.rfind("usb:", 0) != 0) return false;
  const std::string rest = text.substr(4);
  const std::size_t c1 = rest.find(':');
  if (c1 == std::string::npos) return false;
  const std::size_t c2 = rest.find(':', c1 + 1);
  if (!parse_hex16(rest.substr(0, c1), sel.vid)) return false;
  if (!parse_hex16(rest.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1), sel.pid))
    return false;
  sel.serial = c2 == std::string::npos ? "" : rest.substr(c2 + 1);
  error.clear();
  return true;
}

bool resolve_usb_port(const std::string& text, const std::string& sysfs_root, std::string& device,
                      std::string& error, const std::string& dev_root) {
  UsbSelector sel;
  if (!parse_usb_selector(text, sel, error)) return false;
  std::vector<PortInfo> hits;
  for (auto& p : list_serial_ports(sysfs_root, dev_root))
    if (p.usb && p.vid == sel.vid && p.pid == sel.pid && (sel.serial.empty() || p.serial == sel.serial))
      hits.push_back(p);
  if (hits.empty()) {
    error = "no serial port matches " + text + " (see host-send --list)";
    return false;
  }
  if (hits.size() > 1) {
    error = "several serial ports match " + text + ":";
    for (const auto& h : hits) error += " " + h.device + (h.serial.empty() ? "" : " (serial " + h.serial + ")");
    error += "; add :SERIAL";
    return false;
  }
  device = hits[0].device;
  return true;
}

std::string format_port(const PortInfo& p) {
  char ids[160] = "";
  if (p.usb) {
    std::snprintf(ids, sizeof ids, "  usb:%04x:%04x", p.vid, p.pid);
  }
  std::string s = p.device + ids;
  if (p.usb) {
    if (!p.serial.empty()) s += ":" + p.serial;
    if (p.interface >= 0) s += "  if" + std::to_string(p.interface);
    if (!p.manufacturer.empty() || !p.product.empty()) s += "  \"" + p.manufacturer + (p.manufacturer.empty() ? "" : " ") + p.product + "\"";
  }
  if (!p.driver.empty()) s += "  [" + p.driver + "]";
  if (!p.by_id.empty()) s += "\n    " + p.by_id;
  return s;
}

int list_ports_command() {
  std::vector<PortInfo> ports = list_serial_ports("/sys", "/dev");
  bool usb_ok = false;
  const std::vector<UsbDevice> usb = enumerate_usb(usb_ok);
  // libusb fills in strings sysfs did not have (same bus and address).
  for (auto& p : ports) {
    if (!p.usb) continue;
    for (const auto& d : usb) {
      if (d.bus != p.busnum || d.address != p.devnum) continue;
      if (p.serial.empty()) p.serial = d.serial;
      if (p.product.empty()) p.product = d.product;
      if (p.manufacturer.empty()) p.manufacturer = d.manufacturer;
    }
  }
  // USB serial adapters first; the 8250 driver's placeholder ports (no UART
  // behind them) are left out.
  std::stable_sort(ports.begin(), ports.end(), [](const PortInfo& a, const PortInfo& b) { return a.usb > b.usb; });
  int shown = 0;
  for (const auto& p : ports) {
    if (!port_present(p)) continue;
    std::printf("%s\n", format_port(p).c_str());
    ++shown;
  }
  if (shown == 0) std::printf("no serial ports found\n");
#ifdef MINRT_HAVE_LIBUSB
  if (!usb_ok) std::fprintf(stderr, "host-send: warning: libusb could not be initialised; USB strings from sysfs only\n");
#else
  std::fprintf(stderr, "host-send: note: built without libusb; USB identities from sysfs only\n");
#endif
  std::printf("(%zu USB devices seen by libusb)\n", usb.size());
  return 0;
}

}  // namespace minrt::send
