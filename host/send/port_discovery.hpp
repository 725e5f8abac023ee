// Finding serial ports: a walk of sysfs (/sys/class/tty/*/device) for the
// ports and the USB device each one hangs off, libusb for the USB devices
// present, /dev/serial/by-id for stable names. The sysfs and /dev roots are
// parameters so tests run on a recorded tree.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace minrt::send {

struct PortInfo {
  std::string name;     // ttyUSB0
  std::string device;   // /dev/ttyUSB0
  std::string driver;   // ftdi_sio, cdc_acm, serial8250...
  bool usb = false;
  std::uint16_t vid = 0, pid = 0;
  std::string serial, manufacturer, product;
  int interface = -1;   // bInterfaceNumber, -1 if unknown
  int busnum = -1, devnum = -1;
  std::string by_id;    // /dev/serial/by-id/... or ""
  int uart_type = -1;   // sysfs "type" of a UART port (0: no UART there), -1 if none
};

// False for the placeholder ports the 8250 driver registers without a UART.
bool port_present(const PortInfo& p);

// Ports under `sysfs_root`/class/tty with a device link, sorted by name;
// by-id names from `dev_root`/serial/by-id.
std::vector<PortInfo> list_serial_ports(const std::string& sysfs_root, const std::string& dev_root = "/dev");

struct UsbDevice {
  int bus = 0, address = 0;
  std::uint16_t vid = 0, pid = 0;
  std::string serial, manufacturer, product;  // empty when the device cannot be opened
};

// All USB devices libusb sees (empty without libusb or USB). `available`
// says whether libusb could be initialised at all.
std::vector<UsbDevice> enumerate_usb(bool& available);

struct UsbSelector {
  std::uint16_t vid = 0, pid = 0;
  std::string serial;  // empty: any
};
bool parse_usb_selector(const std::string& text, UsbSelector& sel, std::string& error);

// The tty for a usb:VID:PID[:SERIAL] selector: exactly one port must match.
bool resolve_usb_port(const std::string& text, const std::string& sysfs_root, std::string& device,
                      std::string& error, const std::string& dev_root = "/dev");

std::string format_port(const PortInfo& p);
// host-send --list: prints the ports and returns the exit status.
int list_ports_command();

}  // namespace minrt::send
